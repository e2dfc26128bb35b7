/* Bounded CSV line reading and field parsing; see csv.h. */
#include "csv.h"

#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define SIG_MAX 40       /* significant digits kept of a time field */
#define EXP_CLAMP 100000 /* |exponent| beyond this is out of range anyway */

void csv_reader_init(csv_reader_t *r, FILE *f)
{
    memset(r, 0, sizeof *r);
    r->f = f;
}

/* Drops a UTF-8 byte order mark from the n bytes at line; the new n. */
static size_t drop_bom(char *line, size_t n)
{
    static const char bom[3] = {'\xEF', '\xBB', '\xBF'};
    if (n < sizeof bom || memcmp(line, bom, sizeof bom) != 0) {
        return n;
    }
    memmove(line, line + sizeof bom, n - sizeof bom);
    return n - sizeof bom;
}

int csv_read_line(csv_reader_t *r)
{
    /* 4 bytes beyond CSV_LINE_MAX are kept so that a CR there (a CRLF
     * line of exactly CSV_LINE_MAX bytes) and a byte order mark can still
     * be dropped: a line overflows tmp only if it is too long anyway. */
    char tmp[CSV_LINE_MAX + 4];
    size_t n = 0;
    long total = 0;
    int c, any = 0, overflow = 0;
    r->too_long = 0;
    r->has_nul = 0;
    if (r->runaway) {
        return 0;
    }
    while ((c = getc(r->f)) != EOF) {
        any = 1;
        if (c == '\n') {
            break;
        }
        if (++total > CSV_RUNAWAY_MAX) {
            r->runaway = 1;
            r->lineno++;
            return 0;
        }
        if (c == '\0') {
            r->has_nul = 1;
            c = '?';
        }
        if (n < sizeof tmp) {
            tmp[n++] = (char)c;
        } else {
            overflow = 1;
        }
    }
    if (!any) {
        return 0;
    }
    if (r->lineno == 0) {
        n = drop_bom(tmp, n);
    }
    if (!overflow && n > 0 && tmp[n - 1] == '\r') {
        n--;
    }
    if (overflow || n > CSV_LINE_MAX) {
        r->too_long = 1;
        n = CSV_LINE_MAX;
    }
    memcpy(r->buf, tmp, n);
    r->buf[n] = '\0';
    r->len = n;
    r->lineno++;
    return 1;
}

static int is_blank(char c)
{
    return c == ' ' || c == '\t';
}

int csv_split(const char *line, csv_field_t *out, int max)
{
    const char *p = line;
    int k = 0, count = 0;
    for (;;) {
        const char *end = p;
        csv_field_t fld;
        while (*end != '\0' && *end != ',') {
            end++;
        }
        fld.p = p;
        fld.len = (size_t)(end - p);
        while (fld.len > 0 && is_blank(fld.p[0])) {
            fld.p++;
            fld.len--;
        }
        while (fld.len > 0 && is_blank(fld.p[fld.len - 1])) {
            fld.len--;
        }
        if (out != NULL && k < max) {
            out[k] = fld;
        }
        k++;
        if (fld.len > 0) {
            count = k;
        }
        if (*end == '\0') {
            return count;
        }
        p = end + 1;
    }
}

csv_num_t csv_parse_real(csv_field_t fld, double *out)
{
    char *end = NULL;
    double x;
    if (fld.len == 0) {
        return CSV_NUM_TEXT;
    }
    /* The field lies inside a NUL-terminated line and is followed by a
     * blank, a comma or the NUL, none of which strtod takes after a number. */
    errno = 0;
    x = strtod(fld.p, &end);
    if (end != fld.p + fld.len) {
        return CSV_NUM_TEXT;
    }
    if (!isfinite(x) || (errno == ERANGE && fabs(x) > 1.0)) {
        return CSV_NUM_NONFINITE;
    }
    *out = x; /* an underflow (1e-400) is 0 or subnormal: kept */
    return CSV_NUM_OK;
}

/* Decimal digits of a time field: value = digits * 10^e10. */
typedef struct {
    char d[SIG_MAX];
    int n;   /* significant digits in d (no leading zeros) */
    long e10;
    int neg;
} decimal_t;

static void dec_digit(decimal_t *v, char c, int fraction)
{
    if (v->n == 0 && c == '0') {
        v->e10 -= fraction; /* a leading zero: only the scale moves */
    } else if (v->n < SIG_MAX) {
        v->d[v->n++] = c;
        v->e10 -= fraction;
    } else if (!fraction) {
        v->e10++; /* integer digit beyond SIG_MAX: its place counts */
    }
}

/* Parses (e|E)[+-]digits at s (if there) into v->e10; the end, or NULL. */
static const char *dec_exponent(const char *s, const char *end, decimal_t *v)
{
    long e = 0;
    int eneg = 0, edigits = 0;
    if (s == end || (*s != 'e' && *s != 'E')) {
        return s;
    }
    s++;
    if (s < end && (*s == '+' || *s == '-')) {
        eneg = *s == '-';
        s++;
    }
    for (; s < end && *s >= '0' && *s <= '9'; s++, edigits++) {
        if (e < EXP_CLAMP) {
            e = 10 * e + (*s - '0');
        }
    }
    v->e10 += eneg ? -e : e;
    return edigits > 0 ? s : NULL;
}

/* Parses [+-]digits[.digits][(e|E)[+-]digits], the whole of [s, end). */
static int dec_parse(const char *s, const char *end, decimal_t *v)
{
    int mant_digits = 0, fraction = 0;
    memset(v, 0, sizeof *v);
    if (s < end && (*s == '+' || *s == '-')) {
        v->neg = *s == '-';
        s++;
    }
    for (; s < end && ((*s >= '0' && *s <= '9') || (*s == '.' && !fraction)); s++) {
        if (*s == '.') {
            fraction = 1;
        } else {
            dec_digit(v, *s, fraction);
            mant_digits++;
        }
    }
    if (mant_digits == 0) {
        return -1;
    }
    s = dec_exponent(s, end, v);
    return s == end ? 0 : -1;
}

csv_num_t csv_parse_time(csv_field_t fld, int unit_exp, int64_t *out)
{
    decimal_t v;
    long m; /* digits of the result before the decimal point */
    uint64_t acc = 0;
    long i;
    double dummy;
    if (dec_parse(fld.p, fld.p + fld.len, &v) != 0) {
        return csv_parse_real(fld, &dummy) == CSV_NUM_NONFINITE ? CSV_NUM_NONFINITE
                                                                  : CSV_NUM_TEXT;
    }
    if (v.n == 0) {
        *out = 0;
        return CSV_NUM_OK;
    }
    if (v.e10 > EXP_CLAMP || v.e10 < -EXP_CLAMP) {
        if (v.e10 > 0) {
            return CSV_NUM_NONFINITE;
        }
        *out = 0;
        return CSV_NUM_OK;
    }
    m = v.n + v.e10 + unit_exp;
    if (m > 19) {
        return CSV_NUM_NONFINITE;
    }
    for (i = 0; i < m; i++) {
        acc = 10 * acc + (uint64_t)(i < v.n ? v.d[i] - '0' : 0);
    }
    if (m >= 0 && m < v.n && v.d[m] >= '5') {
        acc++;
    }
    if (acc > (uint64_t)INT64_MAX) {
        return CSV_NUM_NONFINITE;
    }
    *out = v.neg ? -(int64_t)acc : (int64_t)acc;
    return CSV_NUM_OK;
}
