/* Readers of se23-drive-import: RTKLIB and ublox-drives files; see drive.h. */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "drive.h"

#define PROG "se23-drive-import"
#define FIELDS_MAX 40

void drive_msg(drive_msgs_t *m, const char *file, int64_t lineno, const char *fmt, ...)
{
    va_list ap;
    if (m->shown >= m->max) {
        m->suppressed++;
        return;
    }
    m->shown++;
    fprintf(stderr, PROG ": %s:%lld: ", file, (long long)lineno);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

void *drive_push(void **arr, size_t *n, size_t *cap, size_t sz)
{
    if (*n == *cap) {
        const size_t nc = *cap ? 2 * *cap : 4096;
        void *p = realloc(*arr, nc * sz);
        if (p == NULL) {
            return NULL;
        }
        *arr = p;
        *cap = nc;
    }
    return (char *)*arr + (*n)++ * sz;
}

static int ends_with(const char *s, const char *suffix)
{
    const size_t a = strlen(s), b = strlen(suffix);
    return a >= b && strcmp(s + a - b, suffix) == 0;
}

FILE *drive_open(const char *path, int *is_pipe)
{
    FILE *f = fopen(path, "rb");
    char *cmd;
    size_t i, k = 0;
    *is_pipe = 0;
    if (f == NULL) {
        fprintf(stderr, PROG ": cannot read %s: %s\n", path, strerror(errno));
        return NULL;
    }
    if (!ends_with(path, ".gz")) {
        return f;
    }
    fclose(f);
    /* gzip -dc 'path', the path single-quoted ('\'' for a quote) */
    cmd = malloc(4 * strlen(path) + 32);
    if (cmd == NULL) {
        return NULL;
    }
    k = (size_t)sprintf(cmd, "gzip -dc -- '");
    for (i = 0; path[i] != '\0'; i++) {
        if (path[i] == '\'') {
            memcpy(cmd + k, "'\\''", 4);
            k += 4;
        } else {
            cmd[k++] = path[i];
        }
    }
    strcpy(cmd + k, "'");
    f = popen(cmd, "r");
    free(cmd);
    if (f == NULL) {
        fprintf(stderr, PROG ": cannot run gzip for %s: %s\n", path, strerror(errno));
        return NULL;
    }
    *is_pipe = 1;
    return f;
}

int drive_close(FILE *f, int is_pipe)
{
    if (!is_pipe) {
        return fclose(f) == 0 ? 0 : -1;
    }
    return pclose(f) == 0 ? 0 : -1;
}

int64_t drive_days_from_civil(int64_t y, int m, int d)
{
    /* H. Hinnant's days_from_civil */
    const int64_t yy = y - (m <= 2);
    const int64_t era = (yy >= 0 ? yy : yy - 399) / 400;
    const int64_t yoe = yy - era * 400;
    const int64_t doy = (153 * (m + (m > 2 ? -3 : 9)) + 2) / 5 + d - 1;
    const int64_t doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
    return era * 146097 + doe - 719468;
}

const char *drive_fmt_e9(int64_t v, char *buf, size_t n)
{
    const uint64_t a = v < 0 ? (uint64_t)0 - (uint64_t)v : (uint64_t)v;
    snprintf(buf, n, "%s%llu.%09llu", v < 0 ? "-" : "", (unsigned long long)(a / 1000000000u),
             (unsigned long long)(a % 1000000000u));
    return buf;
}

const char *drive_fmt_s(int64_t t_ns, char *buf, size_t n)
{
    return drive_fmt_e9(t_ns, buf, n);
}

/* Counts a malformed row of st (row.h) and says so. */
static void count_bad(import_count_t *c, drive_msgs_t *msgs, const char *path,
                      const csv_reader_t *r, row_status_t st, const char *what)
{
    if (r->too_long) {
        c->bad_long++;
        drive_msg(msgs, path, r->lineno, "line longer than %d bytes, skipped", CSV_LINE_MAX);
    } else if (st == ROW_COLUMNS) {
        c->bad_columns++;
        drive_msg(msgs, path, r->lineno, "%s: wrong number of fields, skipped", what);
    } else if (st == ROW_NONFINITE || st == ROW_OVERFLOW) {
        c->bad_nonfinite++;
        drive_msg(msgs, path, r->lineno, "%s: a value is not finite, skipped", what);
    } else {
        c->bad_number++;
        drive_msg(msgs, path, r->lineno, "%s: a field is not a number, skipped", what);
    }
}

/* A reader on path opened by drive_open (its FILE in r->f); NULL if either
 * fails (nothing left open). */
static csv_reader_t *reader_open(const char *path, int *is_pipe)
{
    FILE *f = drive_open(path, is_pipe);
    csv_reader_t *r = malloc(sizeof *r);
    if (f == NULL || r == NULL) {
        free(r);
        if (f != NULL) {
            drive_close(f, *is_pipe);
        }
        return NULL;
    }
    csv_reader_init(r, f);
    return r;
}

/* Closes what reader_open opened: -1 if the close failed (a gzip that
 * failed), which say says on stderr. */
static int reader_close(const char *path, csv_reader_t *r, int is_pipe, int say)
{
    const int rc = drive_close(r->f, is_pipe);
    free(r);
    if (rc != 0 && say) {
        fprintf(stderr, PROG ": %s: gzip failed (not a gzip file, or truncated)\n", path);
    }
    return rc;
}

/* -1 (and says so) if r met a line with no end: the file is not text. */
static int refuse_runaway(const char *path, const csv_reader_t *r)
{
    if (!r->runaway) {
        return 0;
    }
    fprintf(stderr, PROG ": %s: no line end within %ld bytes: not a text file, refused\n", path,
            CSV_RUNAWAY_MAX);
    return -1;
}

/* ---- IMU ------------------------------------------------------------- */

static int imu_push(drive_imu_t *imu, const row_t *row, int64_t lineno)
{
    size_t n = imu->n, cap = imu->cap;
    row_t *slot = drive_push((void **)&imu->row, &imu->n, &imu->cap, sizeof *slot);
    if (slot == NULL) {
        return -1;
    }
    *slot = *row;
    if (imu->cap != cap || imu->lineno == NULL) {
        int64_t *p = realloc(imu->lineno, imu->cap * sizeof *p);
        if (p == NULL) {
            return -1;
        }
        imu->lineno = p;
    }
    imu->lineno[n] = lineno;
    return 0;
}

/* Reads the IMU CSV at path: header lines (header < 0: the first line if it
 * is text in a mapped column), rows by map; ncols fields per row. With
 * skip_ends the first and the last data line are dropped. */
static int read_imu(const char *path, const row_map_t *map, int ncols, int header, int skip_ends,
                    drive_imu_t *imu, drive_msgs_t *msgs)
{
    int is_pipe, rc = 0;
    csv_reader_t *r = reader_open(path, &is_pipe);
    int64_t data_lines = 0;
    int last_was_valid = 0;
    if (r == NULL) {
        return -1;
    }
    while (csv_read_line(r)) {
        row_t row;
        row_why_t why;
        row_status_t st;
        if (r->lineno == 1 && (header > 0 || (header < 0 && !r->too_long &&
                                              row_is_header(map, r->buf)))) {
            imu->c.header++;
            continue;
        }
        st = r->too_long || r->has_nul ? ROW_TEXT : row_parse(map, r->buf, ncols, &row, &why);
        if (st == ROW_BLANK) {
            imu->c.blank++;
            continue;
        }
        data_lines++;
        if (skip_ends && data_lines == 1) {
            imu->skipped_ends++;
            continue;
        }
        imu->c.rows++;
        last_was_valid = st == ROW_OK;
        if (st != ROW_OK) {
            count_bad(&imu->c, msgs, path, r, st, "IMU row");
            continue;
        }
        if (imu_push(imu, &row, r->lineno) != 0) {
            fprintf(stderr, PROG ": out of memory\n");
            rc = -1;
            break;
        }
    }
    if (r->runaway) {
        fprintf(stderr, PROG ": %s:%lld: no line end within %ld bytes: not a CSV text file, "
                        "refused\n", path, (long long)r->lineno, CSV_RUNAWAY_MAX);
        rc = -1;
    }
    if (ferror(r->f)) {
        fprintf(stderr, PROG ": cannot read %s\n", path);
        rc = -1;
    }
    if (reader_close(path, r, is_pipe, 1) != 0) {
        rc = -1;
    }
    if (rc == 0 && skip_ends && data_lines >= 2 && last_was_valid) {
        /* the last data line too, as the source's converter (skip_footer=1);
         * a malformed last line stays counted as malformed */
        imu->skipped_ends++;
        imu->c.rows--;
        imu->n--;
    }
    return rc;
}

int drive_read_rtk_imu(const char *path, const row_map_t *map, drive_imu_t *imu,
                       drive_msgs_t *msgs)
{
    return read_imu(path, map, 7, -1, 1, imu, msgs);
}

int drive_read_ublox_imu(const char *path, const row_map_t *map, drive_imu_t *imu,
                         drive_msgs_t *msgs)
{
    return read_imu(path, map, 7, 1, 0, imu, msgs);
}

static uint32_t le32(const unsigned char *p)
{
    return (uint32_t)p[0] | (uint32_t)p[1] << 8 | (uint32_t)p[2] << 16 | (uint32_t)p[3] << 24;
}

int drive_map_tag(const char *tag_path, drive_imu_t *imu, int64_t offset_ns)
{
    FILE *f = fopen(tag_path, "rb");
    unsigned char head[76], rec[8];
    long size;
    double sec;
    uint64_t bits = 0;
    int64_t start_ns, end_ns, tick0, tick1, n_rec;
    uint32_t last_tick;
    size_t i;
    int k;
    if (f == NULL) {
        fprintf(stderr, PROG ": cannot read %s: %s\n", tag_path, strerror(errno));
        return -1;
    }
    if (fseek(f, 0, SEEK_END) != 0 || (size = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0 ||
        fread(head, 1, sizeof head, f) != sizeof head ||
        strncmp((const char *)head, "TIMETAG RTKLIB", 14) != 0 || (size - 76) % 8 != 0 ||
        size < 84) {
        fprintf(stderr, PROG ": %s: not an RTKLIB time-tag file (a 76-byte header starting "
                        "\"TIMETAG RTKLIB\", then 8-byte records)\n", tag_path);
        fclose(f);
        return -1;
    }
    n_rec = (size - 76) / 8;
    if (fseek(f, size - 8, SEEK_SET) != 0 || fread(rec, 1, 8, f) != 8) {
        fprintf(stderr, PROG ": cannot read %s\n", tag_path);
        fclose(f);
        return -1;
    }
    fclose(f);
    for (k = 7; k >= 0; k--) {
        bits = bits << 8 | head[68 + k];
    }
    memcpy(&sec, &bits, sizeof sec);
    last_tick = le32(rec);
    if (!(sec >= 0.0 && sec < 1.0) || last_tick == 0) {
        fprintf(stderr, PROG ": %s: fraction of a second %g or last tick %u out of range\n",
                tag_path, sec, (unsigned)last_tick);
        return -1;
    }
    start_ns = (int64_t)le32(head + 64) * 1000000000 + llround(sec * 1e9);
    end_ns = start_ns + (int64_t)last_tick * 1000000;
    if (imu->n < 2) {
        fprintf(stderr, PROG ": fewer than 2 valid IMU rows: no time map\n");
        return -1;
    }
    tick0 = imu->row[0].t_ns;
    tick1 = imu->row[imu->n - 1].t_ns;
    if (tick1 <= tick0) {
        fprintf(stderr, PROG ": the IMU's last tick is not after its first: no time map\n");
        return -1;
    }
    printf(PROG ": time tags %s: %lld records, GPST %lld.%03lld s + %.1f s (ticks %lld to %lld "
           "ms stretched by %.6f) %+.3f s IMU time offset\n",
           tag_path, (long long)n_rec, (long long)(start_ns / 1000000000),
           (long long)(start_ns % 1000000000 / 1000000), last_tick * 1e-3,
           (long long)(tick0 / 1000000), (long long)(tick1 / 1000000),
           (double)(end_ns - start_ns) / (double)(tick1 - tick0), offset_ns * 1e-9);
    for (i = 0; i < imu->n; i++) {
        /* exact integer arithmetic: (tick - tick0) [ns] * span / ticks, long double */
        const long double u = (long double)(imu->row[i].t_ns - tick0) *
                              (long double)(end_ns - start_ns) / (long double)(tick1 - tick0);
        imu->row[i].t_ns = start_ns + (int64_t)llroundl(u) + offset_ns;
    }
    return 0;
}

/* ---- fixes ----------------------------------------------------------- */

static int fix_push(drive_fixes_t *s, const drive_fix_t *x)
{
    drive_fix_t *slot = drive_push((void **)&s->fix, &s->n, &s->cap, sizeof *slot);
    if (slot == NULL) {
        return -1;
    }
    *slot = *x;
    return 0;
}

/* Splits line at blanks into fields (at most max); returns the count. */
static int split_ws(const char *line, csv_field_t *out, int max)
{
    int n = 0;
    const char *p = line;
    for (;;) {
        const char *q;
        while (*p == ' ' || *p == '\t') {
            p++;
        }
        if (*p == '\0') {
            return n;
        }
        q = p;
        while (*q != '\0' && *q != ' ' && *q != '\t') {
            q++;
        }
        if (n < max) {
            out[n].p = p;
            out[n].len = (size_t)(q - p);
        }
        n++;
        p = q;
    }
}

/* Worst of two parse results. */
static csv_num_t worst(csv_num_t a, csv_num_t b)
{
    return a == CSV_NUM_NONFINITE || b == CSV_NUM_NONFINITE ? CSV_NUM_NONFINITE
           : a != CSV_NUM_OK                                 ? a
                                                             : b;
}

/* lat, lon (exact to 1e-9 deg) and height (to mm) from their fields. */
static csv_num_t parse_llh(csv_field_t lat, csv_field_t lon, csv_field_t h, se23_geo_t *g)
{
    int64_t a = 0, b = 0, c = 0;
    csv_num_t st = worst(worst(csv_parse_time(lat, 9, &a), csv_parse_time(lon, 9, &b)),
                         csv_parse_time(h, 3, &c));
    if (st != CSV_NUM_OK) {
        return st;
    }
    if (a < -90000000000LL || a > 90000000000LL || b < -180000000000LL || b > 180000000000LL ||
        c < -100000000LL || c > 100000000LL) {
        return CSV_NUM_NONFINITE; /* out of range: as good as not finite */
    }
    g->lat_e9 = a;
    g->lon_e9 = b;
    g->h_mm = (int32_t)c;
    return CSV_NUM_OK;
}

/* "yyyy/mm/dd" "hh:mm:ss.sss" (GPST) to ns since 1970-01-01. */
static csv_num_t parse_gpst(csv_field_t date, csv_field_t tod, int64_t *t_ns)
{
    int y, mo, d, hh, mm, n = 0;
    char buf[32];
    csv_field_t sec;
    int64_t s_ns;
    csv_num_t st;
    if (date.len >= sizeof buf || tod.len >= sizeof buf || tod.len < 7) {
        return CSV_NUM_TEXT;
    }
    memcpy(buf, date.p, date.len);
    buf[date.len] = '\0';
    if (sscanf(buf, "%4d/%2d/%2d%n", &y, &mo, &d, &n) != 3 || (size_t)n != date.len || mo < 1 ||
        mo > 12 || d < 1 || d > 31) {
        return CSV_NUM_TEXT;
    }
    memcpy(buf, tod.p, tod.len);
    buf[tod.len] = '\0';
    if (sscanf(buf, "%2d:%2d:%n", &hh, &mm, &n) != 2 || n != 6 || hh > 23 || mm > 59) {
        return CSV_NUM_TEXT;
    }
    sec.p = tod.p + 6;
    sec.len = tod.len - 6;
    st = csv_parse_time(sec, 9, &s_ns);
    if (st != CSV_NUM_OK) {
        return st;
    }
    if (s_ns < 0 || s_ns >= 61000000000LL) {
        return CSV_NUM_TEXT;
    }
    *t_ns = ((drive_days_from_civil(y, mo, d) * 24 + hh) * 60 + mm) * 60000000000LL + s_ns;
    return CSV_NUM_OK;
}

static row_status_t st_of(csv_num_t n)
{
    return n == CSV_NUM_OK ? ROW_OK : n == CSV_NUM_TEXT ? ROW_TEXT : ROW_NONFINITE;
}

/* The fields of r's line into fl by split (csv_split or split_ws), counted
 * in c: 0 for a blank line, -1 for a line that is not text (a bad row, what
 * names it), else how many (a row). */
static int fix_fields(const csv_reader_t *r, int (*split)(const char *, csv_field_t *, int),
                      csv_field_t *fl, import_count_t *c, drive_msgs_t *msgs, const char *path,
                      const char *what)
{
    int n;
    if (r->too_long || r->has_nul) {
        c->rows++;
        count_bad(c, msgs, path, r, ROW_TEXT, what);
        return -1;
    }
    n = split(r->buf, fl, FIELDS_MAX);
    if (n == 0) {
        c->blank++;
    } else {
        c->rows++;
    }
    return n;
}

int drive_read_pos(const char *path, drive_fixes_t *gnss, drive_fixes_t *ref,
                   drive_msgs_t *msgs)
{
    int is_pipe, rc = 0, saw_header = 0;
    csv_reader_t *r = reader_open(path, &is_pipe);
    if (r == NULL) {
        return -1;
    }
    while (csv_read_line(r)) {
        csv_field_t fl[FIELDS_MAX];
        drive_fix_t x;
        int n, k;
        csv_num_t st;
        if (r->buf[0] == '%') {
            gnss->c.header++;
            if (strstr(r->buf, "latitude(deg)") != NULL) {
                saw_header = 1;
            } else if (strstr(r->buf, "x-ecef") != NULL || strstr(r->buf, "latitude(d'\"") ||
                       strstr(r->buf, "e-baseline") != NULL) {
                fprintf(stderr, PROG ": %s:%lld: not a latitude/longitude in degrees solution "
                                "(RTKLIB's output format must be llh in degrees), refused\n",
                        path, (long long)r->lineno);
                rc = -1;
                break;
            }
            continue;
        }
        n = fix_fields(r, split_ws, fl, &gnss->c, msgs, path, "solution row");
        if (n <= 0) {
            continue;
        }
        memset(&x, 0, sizeof x);
        if (n != 15 && n != 24) {
            count_bad(&gnss->c, msgs, path, r, ROW_COLUMNS, "solution row (15 or 24 fields)");
            continue;
        }
        st = worst(parse_gpst(fl[0], fl[1], &x.t_ns), parse_llh(fl[2], fl[3], fl[4], &x.geo));
        {
            double q = 0.0, v[13];
            st = worst(st, csv_parse_real(fl[5], &q));
            for (k = 0; k < 3; k++) {
                st = worst(st, csv_parse_real(fl[7 + k], &x.sp[k]));
            }
            if (n == 24) {
                for (k = 0; k < 6; k++) {
                    st = worst(st, csv_parse_real(fl[15 + k], &v[k]));
                }
                x.v[0] = v[0];
                x.v[1] = v[1];
                x.v[2] = -v[2]; /* up -> down */
                x.sv[0] = v[3];
                x.sv[1] = v[4];
                x.sv[2] = v[5];
                x.has_vel = 1;
            }
            x.q = (int)q;
            if (st == CSV_NUM_OK && (q != (double)x.q || x.sp[0] < 0 || x.sp[1] < 0 ||
                                     x.sp[2] < 0 || x.sv[0] < 0 || x.sv[1] < 0 || x.sv[2] < 0)) {
                st = CSV_NUM_TEXT;
            }
        }
        if (st != CSV_NUM_OK) {
            count_bad(&gnss->c, msgs, path, r, st_of(st), "solution row");
            continue;
        }
        if (x.q != 1 && x.q != 2) {
            gnss->skipped_q++;
            continue;
        }
        if (fix_push(gnss, &x) != 0 || (x.q == 1 && fix_push(ref, &x) != 0)) {
            fprintf(stderr, PROG ": out of memory\n");
            rc = -1;
            break;
        }
    }
    if (rc == 0 && !saw_header) {
        fprintf(stderr, PROG ": %s: no RTKLIB header line with latitude(deg): not an RTKLIB "
                        ".pos solution in degrees, refused\n", path);
        rc = -1;
    }
    if (refuse_runaway(path, r) != 0) {
        rc = -1;
    }
    reader_close(path, r, is_pipe, 0);
    ref->c.rows = gnss->c.rows;
    return rc;
}

/* Index of the header field called name, or -1. */
static int col_of(const csv_field_t *hdr, int n, const char *name)
{
    int k;
    for (k = 0; k < n && k < FIELDS_MAX; k++) {
        if (hdr[k].len == strlen(name) && memcmp(hdr[k].p, name, hdr[k].len) == 0) {
            return k;
        }
    }
    return -1;
}

int drive_read_ublox_fixes(const char *path, drive_fixes_t *out, drive_msgs_t *msgs)
{
    static const char *const names[] = {"t_s",         "lat_deg",     "lon_deg",     "height_m",
                                        "vn_mps",      "ve_mps",      "vd_mps",      "pos_std_n_m",
                                        "pos_std_e_m", "pos_std_d_m", "vel_std_n_mps",
                                        "vel_std_e_mps", "vel_std_d_mps"};
    int col[13], ncols = 0, is_pipe, rc = 0, k, n;
    csv_reader_t *r = reader_open(path, &is_pipe);
    if (r == NULL) {
        return -1;
    }
    while (csv_read_line(r)) {
        drive_fix_t x;
        csv_field_t fl[FIELDS_MAX];
        csv_num_t st;
        if (r->lineno == 1) {
            char hdr[CSV_LINE_MAX + 1];
            memcpy(hdr, r->buf, r->len + 1);
            ncols = csv_split(hdr, fl, FIELDS_MAX);
            for (k = 0; k < 13; k++) {
                col[k] = col_of(fl, ncols, names[k]);
            }
            out->c.header = 1;
            if (col[0] < 0 || col[1] < 0 || col[2] < 0 || col[3] < 0) {
                fprintf(stderr, PROG ": %s:1: the header names no t_s, lat_deg, lon_deg, "
                                "height_m: not a ublox-drives %s file, refused\n",
                        path, out->name);
                rc = -1;
                break;
            }
            continue;
        }
        n = fix_fields(r, csv_split, fl, &out->c, msgs, path, out->name);
        if (n <= 0) {
            continue;
        }
        if (n != ncols) {
            count_bad(&out->c, msgs, path, r, ROW_COLUMNS, out->name);
            continue;
        }
        memset(&x, 0, sizeof x);
        st = worst(csv_parse_time(fl[col[0]], 9, &x.t_ns),
                   parse_llh(fl[col[1]], fl[col[2]], fl[col[3]], &x.geo));
        x.has_vel = col[4] >= 0 && col[5] >= 0 && col[6] >= 0;
        for (k = 0; k < 3; k++) {
            if (x.has_vel) {
                st = worst(st, csv_parse_real(fl[col[4 + k]], &x.v[k]));
            }
            if (col[7 + k] >= 0) {
                st = worst(st, csv_parse_real(fl[col[7 + k]], &x.sp[k]));
            }
            if (col[10 + k] >= 0) {
                st = worst(st, csv_parse_real(fl[col[10 + k]], &x.sv[k]));
            }
        }
        if (st == CSV_NUM_OK && (x.sp[0] < 0 || x.sp[1] < 0 || x.sp[2] < 0 || x.sv[0] < 0 ||
                                 x.sv[1] < 0 || x.sv[2] < 0)) {
            st = CSV_NUM_TEXT;
        }
        if (st != CSV_NUM_OK) {
            count_bad(&out->c, msgs, path, r, st_of(st), out->name);
            continue;
        }
        if (fix_push(out, &x) != 0) {
            fprintf(stderr, PROG ": out of memory\n");
            rc = -1;
            break;
        }
    }
    if (rc == 0 && out->c.header == 0) {
        fprintf(stderr, PROG ": %s: empty file, refused\n", path);
        rc = -1;
    }
    if (refuse_runaway(path, r) != 0) {
        rc = -1;
    }
    if (reader_close(path, r, is_pipe, rc == 0) != 0) {
        rc = -1;
    }
    return rc;
}

static int cmp_i64(const void *a, const void *b)
{
    const int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

void drive_fix_hygiene(drive_fixes_t *s, drive_msgs_t *msgs)
{
    size_t i, w = 0;
    int64_t *dt;
    double med = 0.0;
    char a[32], b[32];
    (void)msgs;
    for (i = 0; i < s->n; i++) {
        if (w > 0 && s->fix[i].t_ns == s->fix[w - 1].t_ns) {
            s->c.dup_time++;
            s->c.dup_same += memcmp(&s->fix[i].geo, &s->fix[w - 1].geo, sizeof(se23_geo_t)) == 0;
            continue;
        }
        if (w > 0 && s->fix[i].t_ns < s->fix[w - 1].t_ns) {
            s->c.backwards++;
            fprintf(stderr, PROG ": %s: time %s s before the previous fix's %s s, dropped\n",
                    s->name, drive_fmt_s(s->fix[i].t_ns, a, sizeof a),
                    drive_fmt_s(s->fix[w - 1].t_ns, b, sizeof b));
            continue;
        }
        s->fix[w++] = s->fix[i];
    }
    s->n = w;
    s->c.written = (int64_t)w;
    if (w >= 2 && (dt = malloc((w - 1) * sizeof *dt)) != NULL) {
        for (i = 1; i < w; i++) {
            dt[i - 1] = s->fix[i].t_ns - s->fix[i - 1].t_ns;
        }
        qsort(dt, w - 1, sizeof *dt, cmp_i64);
        med = (double)dt[(w - 1) / 2];
        free(dt);
        for (i = 1; i < w; i++) {
            const int64_t d = s->fix[i].t_ns - s->fix[i - 1].t_ns;
            if ((double)d > 1.5 * med) {
                s->c.gaps++;
                s->c.lost += llround((double)d / med) - 1;
                s->c.longest_gap_ns = d > s->c.longest_gap_ns ? d : s->c.longest_gap_ns;
            }
        }
    }
    if (w > 0) {
        s->c.first_t_ns = s->fix[0].t_ns;
        s->c.last_t_ns = s->fix[w - 1].t_ns;
    }
}

int drive_parse_outage(const char *s, double out[2])
{
    char *end;
    errno = 0;
    out[0] = strtod(s, &end);
    if (errno != 0 || end == s || *end != ',') {
        return -1;
    }
    s = end + 1;
    out[1] = strtod(s, &end);
    if (errno != 0 || end == s || *end != '\0') {
        return -1;
    }
    return isfinite(out[0]) && isfinite(out[1]) && out[0] >= 0.0 && out[1] > 0.0 &&
                   out[0] < 1e7 && out[1] < 1e7
               ? 0
               : -1;
}

int drive_meta_read(const char *path, drive_meta_t *m)
{
    FILE *f = fopen(path, "r");
    char line[512];
    int have_first = 0;
    memset(m, 0, sizeof *m);
    if (f == NULL) {
        fprintf(stderr, "se23-drive: cannot read %s: %s\n", path, strerror(errno));
        return -1;
    }
    while (fgets(line, sizeof line, f) != NULL) {
        double a, b;
        if (sscanf(line, "first_fix_s %lf", &a) == 1) {
            m->first_fix_s = a;
            have_first = 1;
        } else if (sscanf(line, "outage %lf %lf", &a, &b) == 2 &&
                   m->n_outages < DRIVE_OUTAGES_MAX) {
            m->outage[m->n_outages][0] = a;
            m->outage[m->n_outages][1] = b;
            m->n_outages++;
        }
    }
    fclose(f);
    if (!have_first) {
        fprintf(stderr, "se23-drive: %s: no first_fix_s line: not a se23-drive-import sidecar\n",
                path);
        return -1;
    }
    return 0;
}

char **drive_split_eq(int *argc, char **argv)
{
    char **v = calloc(2 * (size_t)*argc + 1, sizeof *v);
    int i, n = 0;
    if (v == NULL) {
        return NULL;
    }
    for (i = 0; i < *argc; i++) {
        char *eq = strncmp(argv[i], "--", 2) == 0 ? strchr(argv[i], '=') : NULL;
        if (i > 0 && eq != NULL) {
            *eq = '\0';
            v[n++] = argv[i];
            v[n++] = eq + 1;
        } else {
            v[n++] = argv[i];
        }
    }
    *argc = n;
    return v;
}
