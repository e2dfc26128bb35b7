/* One CSV row to one IMU sample; see row.h. */
#include "row.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../lcm/ldmath.h"

static void set_why(row_why_t *why, int nfields, int col, const csv_field_t *fld)
{
    if (why != NULL) {
        why->nfields = nfields;
        why->bad_col = col;
        if (fld != NULL) {
            why->bad = *fld;
        } else {
            why->bad.p = "";
            why->bad.len = 0;
        }
    }
}

int row_cols_needed(const row_map_t *m)
{
    int k, c = m->time_col;
    for (k = 0; k < 3; k++) {
        c = m->gyro_col[k] > c ? m->gyro_col[k] : c;
        c = m->accel_col[k] > c ? m->accel_col[k] : c;
    }
    return c + 1;
}

/* The three values of cols into v; the first failure's column in *bad. */
static csv_num_t parse3(const csv_field_t *f, const int col[3], double v[3], int *bad)
{
    int k;
    for (k = 0; k < 3; k++) {
        csv_num_t r = csv_parse_real(f[col[k]], &v[k]);
        if (r != CSV_NUM_OK) {
            *bad = col[k];
            return r;
        }
    }
    return CSV_NUM_OK;
}

static row_status_t num_status(csv_num_t r)
{
    return r == CSV_NUM_TEXT ? ROW_TEXT : ROW_NONFINITE;
}

static int clipped(const double v[3], double range)
{
    return range > 0.0 && (fabs(v[0]) >= range || fabs(v[1]) >= range || fabs(v[2]) >= range);
}

static int finite3(const double v[3])
{
    return isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2]);
}

/* The column of the largest |raw| value of a triad (the one that overflows
 * first when scaled). */
static int largest_col(const double raw[3], const int col[3])
{
    int k, best = 0;
    for (k = 1; k < 3; k++) {
        best = fabs(raw[k]) > fabs(raw[best]) ? k : best;
    }
    return col[best];
}

/* Unit conversion, then the axis map. */
static void convert(const row_map_t *m, const double raw[3], double scale, double out[3])
{
    int k;
    for (k = 0; k < 3; k++) {
        out[k] = m->sign[k] * (raw[m->perm[k]] * scale);
    }
}

/* The raw values of out converted (units, axes, misalignment) and their
 * clipping flags; ROW_OVERFLOW (the column to blame in *bad) if a value
 * finite in the file is not once converted (1e308 g, or rotated): the row
 * is then as unusable as one with a NaN in the file. */
static row_status_t convert_row(const row_map_t *m, row_t *out, int *bad)
{
    double a[3];
    int k;
    convert(m, out->raw_gyro, m->gyro_scale, out->omega);
    convert(m, out->raw_accel, m->accel_scale, a);
    for (k = 0; k < 3; k++) {
        out->accel[k] = m->accel_rot[3 * k] * a[0] + m->accel_rot[3 * k + 1] * a[1] +
                        m->accel_rot[3 * k + 2] * a[2];
    }
    out->gyro_clipped = clipped(out->raw_gyro, m->gyro_range);
    out->accel_clipped = clipped(out->raw_accel, m->accel_range);
    if (finite3(out->omega) && finite3(out->accel)) {
        return ROW_OK;
    }
    *bad = finite3(out->omega) ? largest_col(out->raw_accel, m->accel_col)
                               : largest_col(out->raw_gyro, m->gyro_col);
    return ROW_OVERFLOW;
}

row_status_t row_parse(const row_map_t *m, const char *line, int ncols, row_t *out,
                       row_why_t *why)
{
    csv_field_t f[ROW_COLS_MAX];
    const char *p = line;
    int nf, bad = -1;
    csv_num_t r;
    row_status_t st;
    while (*p == ' ' || *p == '\t') {
        p++;
    }
    if (*p == '\0') {
        return ROW_BLANK;
    }
    nf = csv_split(line, f, ROW_COLS_MAX);
    if ((ncols > 0 && nf != ncols) || row_cols_needed(m) > nf) {
        set_why(why, nf, -1, NULL);
        return ROW_COLUMNS;
    }
    out->t_ns = 0;
    r = m->time_col < 0 ? CSV_NUM_OK : csv_parse_time(f[m->time_col], m->time_exp, &out->t_ns);
    if (r != CSV_NUM_OK) {
        set_why(why, nf, m->time_col, &f[m->time_col]);
        return num_status(r);
    }
    r = parse3(f, m->gyro_col, out->raw_gyro, &bad);
    if (r == CSV_NUM_OK) {
        r = parse3(f, m->accel_col, out->raw_accel, &bad);
    }
    if (r != CSV_NUM_OK) {
        set_why(why, nf, bad, &f[bad]);
        return num_status(r);
    }
    st = convert_row(m, out, &bad);
    if (st != ROW_OK) {
        set_why(why, nf, bad, &f[bad]);
    }
    return st;
}

int row_count_fields(const char *line)
{
    return csv_split(line, NULL, 0);
}

int row_is_header(const row_map_t *m, const char *line)
{
    csv_field_t f[ROW_COLS_MAX];
    const int *cols[2] = {m->gyro_col, m->accel_col};
    double x;
    int nf = csv_split(line, f, ROW_COLS_MAX), s, k;
    if (row_cols_needed(m) > nf) {
        return 1;
    }
    if (m->time_col >= 0 && csv_parse_real(f[m->time_col], &x) == CSV_NUM_TEXT) {
        return 1;
    }
    for (s = 0; s < 2; s++) {
        for (k = 0; k < 3; k++) {
            if (csv_parse_real(f[cols[s][k]], &x) == CSV_NUM_TEXT) {
                return 1;
            }
        }
    }
    return 0;
}

/* The next comma-separated item of *s into item (at most n - 1 chars). */
static int next_item(const char **s, char *item, size_t n)
{
    const char *comma = strchr(*s, ',');
    size_t len = comma != NULL ? (size_t)(comma - *s) : strlen(*s);
    if (len >= n) {
        return -1;
    }
    memcpy(item, *s, len);
    item[len] = '\0';
    *s = comma != NULL ? comma + 1 : NULL;
    return 0;
}

int row_parse_cols(const char *s, int col[3])
{
    char item[16];
    int k, tmp[3];
    for (k = 0; k < 3; k++) {
        char *end = NULL;
        long v;
        if (s == NULL || next_item(&s, item, sizeof item) != 0) {
            return -1;
        }
        v = strtol(item, &end, 10);
        if (end == item || *end != '\0' || v < 1 || v > ROW_COLS_MAX) {
            return -1;
        }
        tmp[k] = (int)v - 1;
    }
    if (s != NULL) {
        return -1;
    }
    memcpy(col, tmp, sizeof tmp);
    return 0;
}

int row_parse_axes(const char *s, int perm[3], double sign[3])
{
    char item[4];
    int k, used[3] = {0, 0, 0}, p[3];
    double sg[3];
    for (k = 0; k < 3; k++) {
        const char *a = item;
        if (s == NULL || next_item(&s, item, sizeof item) != 0) {
            return -1;
        }
        sg[k] = 1.0;
        if (*a == '+' || *a == '-') {
            sg[k] = *a == '-' ? -1.0 : 1.0;
            a++;
        }
        if (a[0] < 'x' || a[0] > 'z' || a[1] != '\0' || used[a[0] - 'x']) {
            return -1;
        }
        p[k] = a[0] - 'x';
        used[p[k]] = 1;
    }
    if (s != NULL) {
        return -1;
    }
    memcpy(perm, p, sizeof p);
    memcpy(sign, sg, sizeof sg);
    return 0;
}

int row_parse_misalign(const char *s, double R[9])
{
    const double deg = 3.14159265358979323846 / 180.0;
    char item[32];
    double r[3];
    ld_vec3_t phi;
    ld_mat3_t E;
    int k;
    for (k = 0; k < 3; k++) {
        char *end = NULL;
        if (s == NULL || next_item(&s, item, sizeof item) != 0) {
            return -1;
        }
        r[k] = strtod(item, &end);
        if (end == item || *end != '\0' || !isfinite(r[k])) {
            return -1;
        }
    }
    if (s != NULL || !(sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]) <= ROW_MISALIGN_MAX_DEG)) {
        return -1;
    }
    for (k = 0; k < 3; k++) {
        r[k] *= deg;
    }
    phi = ld_vec3_from(r);
    E = ld_exp(&phi);
    ld_mat3_to(&E, R);
    return 0;
}
