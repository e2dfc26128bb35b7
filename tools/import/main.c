/*
 * se23-import: a CSV IMU log (one row per sample: time, 3 gyro, 3 accel
 * columns) to the harness's LCM IMU log (SE23_IMU, se23lcm_imu_sample),
 * checking what real recordings get wrong and counting each kind:
 * repeated timestamps and time going backwards (rows dropped), gaps
 * (samples lost: the sequence numbers skip them), values at the sensor's
 * range (clipping: kept), malformed rows (skipped, reported with their line
 * number). The defaults read x-io's CSV (Time (s), Gyroscope X/Y/Z (deg/s),
 * Accelerometer X/Y/Z (g), one header line).
 *
 * Two passes over the file unless --rate and --unit-check off are given:
 * the first reads the first RATE_PREFIX intervals between valid rows for
 * the nominal interval (their median) and, for the unit checks, the whole
 * file: the specific force must read about 1 g at the first rest (a file
 * in m/s^2 read as g reads 9.8 g), and the gyroscope's numbers must not be
 * those of the other unit (gyrocheck.h). The output is created at the
 * first valid row of the second pass, so an input without one, or refused
 * by the first pass, leaves no log behind.
 *
 * Exit status: 0 done; 1 the input cannot be read, holds no valid row,
 * fails a unit check, has no line end within CSV_RUNAWAY_MAX bytes, or
 * the output cannot be written; 2 bad usage (also: --out is the input).
 * Run with --help.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <lcm/lcm.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "../lcm/harness.h"
#include "csv.h"
#include "gyrocheck.h"
#include "hygiene.h"
#include "row.h"
#include "se23lcm_imu_info.h"
#include "se23lcm_imu_sample.h"

#define PROG "se23-import"
#define RATE_PREFIX 10000 /* intervals read for the nominal rate */
#define AUTO_HEADER_MAX 64 /* lines --header auto may skip */
#define DEG (3.14159265358979323846 / 180.0)
/*
 * The unit check's band for |f| at rest [g]. At rest an accelerometer
 * reads 1 g: the local gravity (9.78 to 9.83 m/s^2) within its bias and
 * scale-factor errors, a few percent for consumer MEMS. A file in m/s^2
 * read as g reads 9.8 g at rest, a file in g read as m/s^2 0.10 g: 6.5
 * times above the band and 4.9 times below it. The band's width is margin
 * for a "rest" that is steady motion instead (a vehicle in a steady turn at
 * 0.5 g lateral reads 1.1 g), not for sensor error.
 */
#define REST_G_LO 0.5
#define REST_G_HI 1.5

typedef struct {
    const char *in;
    const char *out;
    const char *header;  /* "auto" or a number of lines */
    const char *gyro_cols, *accel_cols, *axes, *accel_misalign;
    int64_t time_col, columns, max_messages;
    int time_unit, gyro_unit, accel_unit;
    int unit_check; /* 1: the accelerometer's and the gyroscope's units checked */
    double g, rate, gyro_range, accel_range;
} opts_t;

typedef struct {
    opts_t o;
    row_map_t map;
    int64_t header_lines; /* -1: auto */
    hygiene_t h;
    lcm_t *lc;
    int64_t messages;     /* per-row messages printed */
    int64_t suppressed;   /* ... and not printed (beyond --max-messages) */
    int64_t *dt;          /* pre-pass: intervals between valid rows (NULL: --rate) */
    size_t n_dt;
    int64_t prev_t;       /* pre-pass: the last valid row's time */
    int have_prev;
    hyg_rest_t rests;     /* pre-pass: the search for rests */
    hyg_run_t rest;       /* ... the first rest's first HYG_REST_NS ... */
    int rest_found;       /* ... once found */
    gyro_check_t gyro;    /* pre-pass: the gyroscope's unit check */
    int ncols;            /* fields a row must have (0: any) */
    se23lcm_imu_info info; /* the log's first message (rate_hz 0: rate unknown, none) */
} importer_t;

static const char *const time_units[] = {"s", "ms", "us", "ns"};
static const int time_exps[] = {9, 6, 3, 0};

static int find_time_unit(const char *v)
{
    int k;
    for (k = 0; k < 4; k++) {
        if (strcmp(v, time_units[k]) == 0) {
            return k;
        }
    }
    return -1;
}

static const char *const gyro_units[] = {"rad/s", "deg/s"};

static int find_gyro_unit(const char *v)
{
    return strcmp(v, gyro_units[0]) == 0 ? 0 : strcmp(v, gyro_units[1]) == 0 ? 1 : -1;
}

static const char *const accel_units[] = {"m/s2", "g"};

static int find_accel_unit(const char *v)
{
    if (strcmp(v, accel_units[0]) == 0 || strcmp(v, "m/s^2") == 0) {
        return 0;
    }
    return strcmp(v, accel_units[1]) == 0 ? 1 : -1;
}

/* m/s^2 per unit of accel_units[unit] (1 g is --g). */
static double accel_scale(const opts_t *o, int unit)
{
    return unit == 1 ? o->g : 1.0;
}

static void usage(FILE *f)
{
    fprintf(f,
            "usage: se23-import [options] --out file://LOG?mode=w FILE.csv\n"
            "Converts a CSV IMU log to the harness's LCM IMU log (channel SE23_IMU).\n"
            "The defaults read x-io's CSV: Time (s), Gyroscope X/Y/Z (deg/s),\n"
            "Accelerometer X/Y/Z (g), one header line.\n"
            "  --out URL              LCM URL to write, e.g. file://imu.log?mode=w (required)\n"
            "  --time-col N           column of the time, from 1 (1); 0: none, row k\n"
            "                         is at k / --rate (then required)\n"
            "  --gyro-cols A,B,C      columns of gyro x,y,z (2,3,4)\n"
            "  --accel-cols A,B,C     columns of accel x,y,z, specific force (5,6,7)\n"
            "  --header N|auto        header lines to skip (1); auto: the leading lines\n"
            "                         with text in a mapped column (at most %d)\n"
            "  --columns N            fields a row must have; 0: as many as the last\n"
            "                         header line, or any with no header (0)\n"
            "  --time-unit s|ms|us|ns (s); parsed as a decimal, exact to 1 ns\n"
            "  --gyro-unit rad/s|deg/s  (deg/s)\n"
            "  --accel-unit m/s2|g    (g)\n"
            "  --g VALUE              1 g [m/s^2], 9.7..9.9 (9.80665)\n"
            "  --axes MAP             signed permutation applied to both sensors after\n"
            "                         the units: output x,y,z = the input axes listed,\n"
            "                         e.g. x,-y,-z or y,x,-z (x,y,z)\n"
            "  --accel-misalign RX,RY,RZ  rotation vector [deg] applied to the accelerometer\n"
            "                         after --axes: its triad's misalignment against the\n"
            "                         gyroscope's, from a calibration (0,0,0; at most 10)\n"
            "  --gyro-range R         |value| >= R counts as clipped, in the INPUT unit\n"
            "                         of --gyro-unit (0: no check)\n"
            "  --accel-range R        the same for the accelerometer (0: no check)\n"
            "  --rate HZ              nominal rate for gap detection (default: the median\n"
            "                         interval of the first %d intervals, a first pass)\n"
            "  --max-messages N       per-row messages on stderr, then a count (10)\n"
            "  --unit-check on|off    the first rest (|f| steady within %.0f%% for %.1f s)\n"
            "                         must read %.1f to %.1f g, and the gyroscope must not\n"
            "                         read like the other unit (beyond 4000 deg/s, or\n"
            "                         against the tilt changes between rests), else the\n"
            "                         file is refused (on)\n"
            "Rows repeating the last written timestamp, or earlier, are dropped; a\n"
            "longer interval than the nominal one loses round(interval/nominal - 1)\n"
            "samples and the sequence numbers skip them. Malformed rows (wrong field\n"
            "count, text or NaN/Inf in a mapped field, also once converted, a line\n"
            "over %d bytes) are skipped; a line over %ld bytes refuses the file.\n"
            "Exit status: 0 done, 1 unreadable or refused input, no valid row or\n"
            "write error, 2 bad usage (also: --out is the input file).\n",
            AUTO_HEADER_MAX, RATE_PREFIX, 100.0 * HYG_REST_SPREAD, HYG_REST_NS * 1e-9, REST_G_LO,
            REST_G_HI, CSV_LINE_MAX, CSV_RUNAWAY_MAX);
}

static void defaults(opts_t *o)
{
    memset(o, 0, sizeof *o);
    o->header = "1";
    o->gyro_cols = "2,3,4";
    o->accel_cols = "5,6,7";
    o->axes = "x,y,z";
    o->accel_misalign = "0,0,0";
    o->time_col = 1;
    o->max_messages = 10;
    o->time_unit = 0;
    o->gyro_unit = 1;
    o->accel_unit = 1;
    o->g = 9.80665;
    o->unit_check = 1;
}

/* Says what is wrong with the option values (then returns -1). */
static int bad(const char *what, const char *value)
{
    fprintf(stderr, PROG ": bad value for %s: %s\n", what, value);
    return -1;
}

/* The mapped columns (6, and the time's if there is one) are distinct. */
static int distinct_cols(const row_map_t *m)
{
    int c[7], i, j;
    const int n = m->time_col >= 0 ? 7 : 6;
    for (i = 0; i < 3; i++) {
        c[i] = m->gyro_col[i];
        c[3 + i] = m->accel_col[i];
    }
    c[6] = m->time_col;
    for (i = 0; i < n; i++) {
        for (j = i + 1; j < n; j++) {
            if (c[i] == c[j]) {
                return 0;
            }
        }
    }
    return 1;
}

/* Option values into im->map and im->header_lines; -1 if one is bad. */
static int setup(importer_t *im)
{
    const opts_t *o = &im->o;
    row_map_t *m = &im->map;
    char *end = NULL;
    if (o->time_col < 0 || o->time_col > ROW_COLS_MAX) {
        return bad("--time-col", "(from 1 to 1024, or 0: no time column)");
    }
    if (o->time_col == 0 && o->rate <= 0.0) {
        fprintf(stderr, PROG ": --time-col 0 (no time column) needs --rate HZ: row k is at "
                        "k / HZ\n");
        return -1;
    }
    m->time_col = (int)o->time_col - 1; /* -1: none */
    if (row_parse_cols(o->gyro_cols, m->gyro_col) != 0) {
        return bad("--gyro-cols", o->gyro_cols);
    }
    if (row_parse_cols(o->accel_cols, m->accel_col) != 0) {
        return bad("--accel-cols", o->accel_cols);
    }
    if (!distinct_cols(m)) {
        fprintf(stderr, PROG ": the time, gyro and accel columns must all differ\n");
        return -1;
    }
    if (row_parse_axes(o->axes, m->perm, m->sign) != 0) {
        return bad("--axes (a signed permutation of x,y,z)", o->axes);
    }
    if (row_parse_misalign(o->accel_misalign, m->accel_rot) != 0) {
        return bad("--accel-misalign (rx,ry,rz in degrees, at most 10 in all)",
                   o->accel_misalign);
    }
    if (o->columns < 0 || o->columns > ROW_COLS_MAX || o->max_messages < 0) {
        return bad("--columns or --max-messages", "(negative or too large)");
    }
    if (strcmp(o->header, "auto") == 0) {
        im->header_lines = -1;
    } else {
        errno = 0;
        im->header_lines = strtoll(o->header, &end, 10);
        if (errno != 0 || end == o->header || *end != '\0' || im->header_lines < 0) {
            return bad("--header", o->header);
        }
    }
    if (o->out == NULL || o->in == NULL) {
        fprintf(stderr, PROG ": %s\n", o->in == NULL ? "no input file" : "--out is required");
        return -1;
    }
    if (strstr(o->out, "://") == NULL) {
        return bad("--out (an LCM URL, e.g. file://imu.log?mode=w)", o->out);
    }
    if (strncmp(o->out, "file://", 7) == 0 && strstr(o->out, "mode=w") == NULL &&
        strstr(o->out, "mode=a") == NULL) {
        return bad("--out (a file:// URL needs ?mode=w)", o->out);
    }
    m->time_exp = time_exps[o->time_unit];
    m->gyro_scale = o->gyro_unit == 1 ? DEG : 1.0;
    m->accel_scale = accel_scale(o, o->accel_unit);
    m->gyro_range = o->gyro_range;
    m->accel_range = o->accel_range;
    return 0;
}

/*
 * -1 (after saying so) if --out, a file:// URL, names the input file itself,
 * also through a hard or symbolic link (the same device and inode): LCM
 * would replace the CSV with the log. An output that does not exist yet
 * cannot be the input.
 */
static int out_not_in(const opts_t *o)
{
    const char *p = o->out + 7; /* file://PATH?PARAMS: LCM's path is PATH */
    struct stat si, so;
    char *path;
    int same;
    if (strncmp(o->out, "file://", 7) != 0) {
        return 0;
    }
    path = strndup(p, strcspn(p, "?"));
    if (path == NULL) {
        fprintf(stderr, PROG ": out of memory\n");
        return -1;
    }
    same = stat(path, &so) == 0 && stat(o->in, &si) == 0 && si.st_dev == so.st_dev &&
           si.st_ino == so.st_ino;
    if (same) {
        fprintf(stderr, PROG ": --out %s is the input file %s: refused, nothing written\n",
                path, o->in);
    }
    free(path);
    return same ? -1 : 0;
}

static int parse_args(int argc, char **argv, importer_t *im)
{
    const double inf = HUGE_VAL;
    opts_t *o = &im->o;
    const char **pos = calloc((size_t)argc, sizeof *pos);
    int n_pos = 0, rc;
    const harness_opt_t opts[] = {
        {"--out", HOPT_STR, &o->out, 0, 0, NULL},
        {"--time-col", HOPT_I64, &o->time_col, 0, 0, NULL},
        {"--gyro-cols", HOPT_STR, &o->gyro_cols, 0, 0, NULL},
        {"--accel-cols", HOPT_STR, &o->accel_cols, 0, 0, NULL},
        {"--header", HOPT_STR, &o->header, 0, 0, NULL},
        {"--columns", HOPT_I64, &o->columns, 0, 0, NULL},
        {"--time-unit", HOPT_CHOICE, &o->time_unit, 0, 0, find_time_unit},
        {"--gyro-unit", HOPT_CHOICE, &o->gyro_unit, 0, 0, find_gyro_unit},
        {"--accel-unit", HOPT_CHOICE, &o->accel_unit, 0, 0, find_accel_unit},
        {"--g", HOPT_DOUBLE, &o->g, 9.7, 9.9, NULL},
        {"--axes", HOPT_STR, &o->axes, 0, 0, NULL},
        {"--accel-misalign", HOPT_STR, &o->accel_misalign, 0, 0, NULL},
        {"--gyro-range", HOPT_DOUBLE, &o->gyro_range, 0.0, inf, NULL},
        {"--accel-range", HOPT_DOUBLE, &o->accel_range, 0.0, inf, NULL},
        {"--rate", HOPT_DOUBLE, &o->rate, 1e-3, 1e9, NULL},
        {"--max-messages", HOPT_I64, &o->max_messages, 0, 0, NULL},
        {"--unit-check", HOPT_CHOICE, &o->unit_check, 0, 0, harness_on_off},
    };
    defaults(o);
    if (pos == NULL) {
        return -1;
    }
    rc = harness_parse_opts(PROG, argc, argv, opts, (int)(sizeof opts / sizeof opts[0]), usage,
                            pos, &n_pos);
    if (rc == 0 && n_pos > 1) {
        fprintf(stderr, PROG ": one input file only\n");
        rc = -1;
    }
    o->in = n_pos == 1 ? pos[0] : NULL;
    free(pos);
    if (rc == 0) {
        rc = setup(im);
    }
    return rc == 0 ? out_not_in(o) : -1;
}

/* The time t_ns as seconds, into buf. */
static const char *fmt_s(int64_t t_ns, char *buf, size_t n)
{
    uint64_t a = t_ns < 0 ? (uint64_t)0 - (uint64_t)t_ns : (uint64_t)t_ns;
    snprintf(buf, n, "%s%llu.%09llu", t_ns < 0 ? "-" : "",
             (unsigned long long)(a / 1000000000u), (unsigned long long)(a % 1000000000u));
    return buf;
}

/* A message about line lineno, within the --max-messages budget. */
static void row_msg(importer_t *im, int64_t lineno, const char *fmt, ...)
{
    va_list ap;
    if (im->messages >= im->o.max_messages) {
        im->suppressed++;
        return;
    }
    im->messages++;
    fprintf(stderr, PROG ": %s:%lld: ", im->o.in, (long long)lineno);
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    fputc('\n', stderr);
}

/* A field, quoted for a message into buf[n] (n > 6): unprintables as '?',
 * cut to n - 6 bytes ("..." after the closing quote). */
static const char *quote(csv_field_t fld, char *buf, size_t n)
{
    const size_t max = n - 6;
    size_t i, k = 0;
    buf[k++] = '"';
    for (i = 0; i < fld.len && i < max; i++) {
        unsigned char c = (unsigned char)fld.p[i];
        buf[k++] = (c >= 0x20 && c < 0x7f) ? fld.p[i] : '?';
    }
    buf[k++] = '"';
    if (fld.len > max) {
        memcpy(buf + k, "...", 3);
        k += 3;
    }
    buf[k] = '\0';
    return buf;
}

/* Counts and reports the malformed row of status st in r. */
static void malformed(importer_t *im, const csv_reader_t *r, row_status_t st,
                      const row_why_t *why)
{
    import_count_t *c = &im->h.c;
    char q[46]; /* a field shown up to 40 bytes */
    if (r->too_long) {
        c->bad_long++;
        row_msg(im, r->lineno, "line longer than %d bytes, skipped", CSV_LINE_MAX);
    } else if (r->has_nul) {
        c->bad_number++;
        row_msg(im, r->lineno, "NUL byte in the line, skipped");
    } else if (st == ROW_NONFINITE && why->bad_col < 0) {
        c->bad_nonfinite++;
        row_msg(im, r->lineno, "time from the row index (k / --rate) beyond int64 nanoseconds, "
                               "skipped");
    } else if (st == ROW_COLUMNS) {
        c->bad_columns++;
        row_msg(im, r->lineno, "%d field(s), expected %s%d, skipped", why->nfields,
                im->ncols > 0 ? "" : "at least ",
                im->ncols > 0 ? im->ncols : row_cols_needed(&im->map));
    } else {
        static const char *const what[] = {"not a number", "not finite (NaN, Inf or out of range)",
                                           "not finite once converted to rad/s, m/s^2"};
        if (st == ROW_TEXT) {
            c->bad_number++;
        } else {
            c->bad_nonfinite++; /* ROW_NONFINITE, ROW_OVERFLOW */
        }
        row_msg(im, r->lineno, "column %d: %s: %s, skipped", why->bad_col + 1,
                what[st == ROW_TEXT ? 0 : st == ROW_NONFINITE ? 1 : 2],
                quote(why->bad, q, sizeof q));
    }
}

/* Opens the output and writes the log's first message, how its samples are
 * timed (if the rate is known); -1 on failure. */
static int open_out(importer_t *im)
{
    im->lc = lcm_create(im->o.out);
    if (im->lc == NULL) {
        fprintf(stderr, PROG ": cannot open LCM URL %s\n", im->o.out);
        return -1;
    }
    if (im->info.rate_hz > 0.0 &&
        se23lcm_imu_info_publish(im->lc, HARNESS_CH_IMU_INFO, &im->info) != 0) {
        fprintf(stderr, PROG ": cannot write to %s\n", im->o.out);
        return -1;
    }
    return 0;
}

/* Writes the sample of r with sequence number seq; -1 on failure. */
static int publish(importer_t *im, const row_t *r, int64_t seq)
{
    se23lcm_imu_sample s;
    if (im->lc == NULL && open_out(im) != 0) {
        return -1;
    }
    memset(&s, 0, sizeof s);
    s.t_ns = r->t_ns;
    s.seq = seq;
    memcpy(s.omega, r->omega, sizeof s.omega);
    memcpy(s.accel, r->accel, sizeof s.accel);
    if (se23lcm_imu_sample_publish(im->lc, HARNESS_CH_IMU, &s) != 0) {
        fprintf(stderr, PROG ": cannot write to %s\n", im->o.out);
        return -1;
    }
    return 0;
}

/* Main pass: a valid row; 0 to go on, -1 on a write error. */
static int take_row(importer_t *im, const row_t *r, int64_t lineno)
{
    int64_t seq = 0;
    char a[32], b[32];
    switch (hygiene_accept(&im->h, r, &seq)) {
    case HYG_WRITE:
        return publish(im, r, seq);
    case HYG_BACK:
        row_msg(im, lineno, "time %s s before the previous row's %s s, dropped",
                fmt_s(r->t_ns, a, sizeof a), fmt_s(im->h.last.t_ns, b, sizeof b));
        return 0;
    case HYG_DUP:
    default:
        return 0;
    }
}

/*
 * Pre-pass: a valid row. On the rows in time order, collects the intervals
 * (unless --rate) and feeds the unit checks (unless --unit-check off: then
 * 1 once RATE_PREFIX intervals are in; they read every row).
 */
static int take_first(importer_t *im, const row_t *r)
{
    if (im->have_prev && r->t_ns <= im->prev_t) {
        return 0;
    }
    if (im->have_prev && im->dt != NULL && im->n_dt < RATE_PREFIX) {
        im->dt[im->n_dt++] = hygiene_interval(im->prev_t, r->t_ns);
    }
    im->prev_t = r->t_ns;
    im->have_prev = 1;
    if (im->o.unit_check) {
        const hyg_rest_event_t ev = hygiene_rest(&im->rests, r);
        if (ev == HYG_REST_BEGINS && !im->rest_found) {
            im->rest = im->rests.run;
            im->rest_found = 1;
        }
        gyro_check_add(&im->gyro, r, ev, &im->rests);
    }
    return (im->dt == NULL || im->n_dt >= RATE_PREFIX) && !im->o.unit_check;
}

/*
 * Without a time column (--time-col 0), data row k (from 0, malformed rows
 * counted: each is a sample) is at k / --rate, into row->t_ns; -1 if that
 * is beyond int64 nanoseconds (292 years).
 */
static int time_from_index(const importer_t *im, int64_t k, row_t *row)
{
    const double t_ns = (double)k * 1e9 / im->o.rate;
    if (!(t_ns < 9.2e18)) {
        return -1;
    }
    row->t_ns = llround(t_ns);
    return 0;
}

/* Whether the line in r, after seen header lines, is one more. */
static int is_header(const importer_t *im, const csv_reader_t *r, int64_t seen)
{
    if (im->header_lines >= 0) {
        return seen < im->header_lines;
    }
    return seen < AUTO_HEADER_MAX && (r->too_long || row_is_header(&im->map, r->buf));
}

/*
 * Reads f from the start: header, then every row. main_pass: count, report,
 * write (take_row); otherwise the pre-pass (take_first). Returns 0, or -1
 * on a read or write error or a runaway line (no line end: the file is
 * refused).
 */
static int scan(importer_t *im, FILE *f, int main_pass)
{
    csv_reader_t *r = malloc(sizeof *r);
    import_count_t *c = &im->h.c;
    int64_t seen = 0, data_rows = 0;
    int in_header = 1, rc = 0, hdr_cols = 0;
    if (r == NULL) {
        return -1;
    }
    csv_reader_init(r, f);
    while (rc == 0 && csv_read_line(r)) {
        row_t row;
        row_why_t why;
        row_status_t st;
        if (in_header && is_header(im, r, seen)) {
            seen++;
            hdr_cols = r->too_long ? 0 : row_count_fields(r->buf);
            continue;
        }
        if (in_header) {
            /* the row width: --columns, else the last header line's if it
             * covers the mapped columns, else any */
            in_header = 0;
            im->ncols = (int)im->o.columns;
            if (im->ncols == 0 && seen > 0 && hdr_cols >= row_cols_needed(&im->map)) {
                im->ncols = hdr_cols;
            }
        }
        st = r->too_long || r->has_nul ? ROW_TEXT
                                       : row_parse(&im->map, r->buf, im->ncols, &row, &why);
        if (st == ROW_BLANK) {
            c->blank += main_pass;
            continue;
        }
        c->rows += main_pass;
        if (st == ROW_OK && im->map.time_col < 0 && time_from_index(im, data_rows, &row) != 0) {
            st = ROW_NONFINITE;
            why.bad_col = -1; /* no column: the time from the row index */
        }
        data_rows++;
        if (st != ROW_OK) {
            if (main_pass) {
                malformed(im, r, st, &why);
            }
            continue;
        }
        rc = main_pass ? take_row(im, &row, r->lineno) : take_first(im, &row);
    }
    if (r->runaway) {
        fprintf(stderr, PROG ": %s:%lld: no line end within %ld bytes: not a CSV text file, "
                        "refused\n", im->o.in, (long long)r->lineno, CSV_RUNAWAY_MAX);
        rc = -1;
    }
    if (main_pass) {
        c->header = seen;
    }
    if (ferror(f)) {
        fprintf(stderr, PROG ": cannot read %s: %s\n", im->o.in, strerror(errno));
        rc = -1;
    }
    free(r);
    return rc < 0 ? -1 : 0;
}

/*
 * The first pass over f, then f is rewound: the intervals for the nominal
 * interval (unless --rate) and the unit checks (unless --unit-check off);
 * none with both options. Returns 0, or -1 after saying what failed.
 */
static int first_pass(importer_t *im, FILE *f)
{
    int rc;
    if (im->o.rate > 0.0 && !im->o.unit_check) {
        return 0;
    }
    if (im->o.rate <= 0.0) {
        im->dt = malloc(RATE_PREFIX * sizeof *im->dt);
        if (im->dt == NULL) {
            fprintf(stderr, PROG ": out of memory\n");
            return -1;
        }
    }
    gyro_check_init(&im->gyro, im->map.gyro_scale);
    rc = scan(im, f, 0);
    if (rc == 0 && fseek(f, 0, SEEK_SET) != 0) {
        fprintf(stderr, PROG ": cannot rewind %s (give --rate and --unit-check off): %s\n",
                im->o.in, strerror(errno));
        rc = -1;
    }
    return rc;
}

/*
 * The nominal interval [ns] (0: unknown, no gap detection), and how it was
 * found, into how and im->info (the log's first message): --rate (for the
 * row index without a time column), or the median of the first RATE_PREFIX
 * intervals between valid rows (the first pass).
 */
static double nominal(importer_t *im, char *how, size_t n)
{
    double nom = 0.0;
    memset(&im->info, 0, sizeof im->info);
    if (im->o.rate > 0.0) {
        const int by_index = im->map.time_col < 0;
        snprintf(how, n, "%s--rate %g Hz", by_index ? "row index, " : "", im->o.rate);
        im->info.rate_source = by_index ? SE23LCM_IMU_INFO_RATE_ROW_INDEX
                                        : SE23LCM_IMU_INFO_RATE_GIVEN;
        nom = 1e9 / im->o.rate;
    } else if (im->n_dt == 0) {
        snprintf(how, n, "unknown: no interval, no gap detection");
    } else {
        snprintf(how, n, "median of the first %zu intervals", im->n_dt);
        im->info.rate_source = SE23LCM_IMU_INFO_RATE_MEASURED;
        im->info.n_intervals = (int64_t)im->n_dt;
        nom = hygiene_median(im->dt, im->n_dt);
    }
    im->info.rate_hz = nom > 0.0 ? 1e9 / nom : 0.0;
    return nom;
}

/* The first rest's mean |f| in g (of --g). */
static double rest_g(const importer_t *im)
{
    return im->rest.sum / (double)im->rest.n / im->o.g;
}

/*
 * The accelerometer's unit check on the first pass's rest: 0 if it reads
 * REST_G_LO to REST_G_HI g (or --unit-check off, or no rest found), else
 * -1 after saying which --accel-unit would.
 */
static int accel_verdict(const importer_t *im)
{
    double g, raw;
    char t0[32], t1[32];
    int k, fit = -1;
    if (!im->o.unit_check || !im->rest_found) {
        return 0;
    }
    g = rest_g(im);
    if (g >= REST_G_LO && g <= REST_G_HI) {
        return 0;
    }
    raw = g * im->o.g / im->map.accel_scale; /* |f| at rest in the file's numbers */
    for (k = 0; k < 2; k++) {
        const double gk = raw * accel_scale(&im->o, k) / im->o.g;
        fit = k != im->o.accel_unit && gk >= REST_G_LO && gk <= REST_G_HI ? k : fit;
    }
    fprintf(stderr, PROG ": %s: the accelerometer reads %.3g g at rest (t = %s to %s s; 1 g "
                    "expected, %.1f to %.1f accepted): ", im->o.in, g,
            fmt_s(im->rest.t0_ns, t0, sizeof t0), fmt_s(im->rest.t1_ns, t1, sizeof t1),
            REST_G_LO, REST_G_HI);
    if (fit >= 0) {
        fprintf(stderr, "is the file in %s? use --accel-unit %s", accel_units[fit],
                accel_units[fit]);
    } else {
        fprintf(stderr, "no --accel-unit fits: check --accel-cols and the file's unit");
    }
    fprintf(stderr, " (--unit-check off if that is no rest at 1 g); nothing written\n");
    return -1;
}

/*
 * The gyroscope's unit check on the first pass's evidence (gyrocheck.h): 0
 * unless it says the file is in the other unit than --gyro-unit, else -1
 * after saying so.
 */
static int gyro_verdict(const importer_t *im)
{
    const gyro_unit_t u = gyro_check_verdict(&im->gyro);
    const int fit = u == GYRO_IS_RAD ? 0 : u == GYRO_IS_DEG ? 1 : -1;
    char why[400];
    if (!im->o.unit_check || fit < 0 || fit == im->o.gyro_unit) {
        return 0;
    }
    gyro_check_describe(&im->gyro, why, sizeof why);
    fprintf(stderr, PROG ": %s: the gyroscope's numbers are %s, not %s (%s): is the file in %s? "
                    "use --gyro-unit %s (--unit-check off to import it as told); nothing written\n",
            im->o.in, gyro_units[fit], gyro_units[im->o.gyro_unit], why, gyro_units[fit],
            gyro_units[fit]);
    return -1;
}

/* The gyroscope's unit check's line of the summary (unless off). */
static void gyro_note(const importer_t *im)
{
    const gyro_unit_t u = gyro_check_verdict(&im->gyro);
    char why[400];
    gyro_check_describe(&im->gyro, why, sizeof why);
    if (u == GYRO_IS_RAD || u == GYRO_IS_DEG) {
        printf(PROG ": gyro unit check: %s confirmed (%s)\n", gyro_units[im->o.gyro_unit], why);
    } else {
        printf(PROG ": gyro unit check: undecided%s, the gyroscope's unit not checked (%s)\n",
               u == GYRO_CONFLICT ? " (evidence both ways)" : "", why);
    }
}

/* The unit checks' lines of the summary. */
static void unit_note(const importer_t *im)
{
    char t0[32], t1[32];
    if (!im->o.unit_check) {
        printf(PROG ": unit check off\n");
        return;
    }
    if (!im->rest_found) {
        printf(PROG ": unit check: no rest (|f| steady within %.0f %% for %.1f s), the "
                    "accelerometer's unit not checked\n",
               100.0 * HYG_REST_SPREAD, HYG_REST_NS * 1e-9);
    } else {
        printf(PROG ": unit check: |f| = %.3f g at rest (t = %s to %s s)\n", rest_g(im),
               fmt_s(im->rest.t0_ns, t0, sizeof t0), fmt_s(im->rest.t1_ns, t1, sizeof t1));
    }
    gyro_note(im);
}

static void summary(const importer_t *im, double nom, const char *how)
{
    const import_count_t *c = &im->h.c;
    char gap[32], t0[32], t1[32], ns[32];
    const struct {
        const char *name;
        int64_t n;
    } rows[] = {
        {"header_lines", c->header},
        {"blank_lines", c->blank},
        {"rows", c->rows},
        {"rows_written", c->written},
        {"dup_time", c->dup_time},
        {"dup_time_same", c->dup_same},
        {"backwards", c->backwards},
        {"gaps", c->gaps},
        {"lost_samples", c->lost},
        {"gyro_clipped", c->gyro_clipped},
        {"accel_clipped", c->accel_clipped},
        {"malformed", import_malformed(c)},
        {"malformed_columns", c->bad_columns},
        {"malformed_number", c->bad_number},
        {"malformed_nonfinite", c->bad_nonfinite},
        {"malformed_long", c->bad_long},
        {"last_seq", c->seq},
    };
    size_t k;
    fmt_s(c->longest_gap_ns, gap, sizeof gap);
    printf(PROG ": %s: %lld rows, %lld written; dropped %lld repeated timestamps (%lld with "
                "repeated values), %lld going backwards, %lld malformed; %lld samples lost in "
                "%lld gaps (longest %s s); clipped %lld gyro, %lld accel\n",
           im->o.in, (long long)c->rows, (long long)c->written, (long long)c->dup_time,
           (long long)c->dup_same, (long long)c->backwards, (long long)import_malformed(c),
           (long long)c->lost, (long long)c->gaps, gap, (long long)c->gyro_clipped,
           (long long)c->accel_clipped);
    printf(PROG ": nominal interval %.6f ms (%.3f Hz; %s); samples from t = %s to %s s\n",
           nom * 1e-6, nom > 0.0 ? 1e9 / nom : 0.0, how,
           fmt_s(c->first_t_ns, t0, sizeof t0), fmt_s(c->last_t_ns, t1, sizeof t1));
    unit_note(im);
    printf(PROG ": counters\n");
    for (k = 0; k < sizeof rows / sizeof rows[0]; k++) {
        printf("  %-20s %lld\n", rows[k].name, (long long)rows[k].n);
    }
    printf("  %-20s %s\n", "longest_gap_s", gap);
    printf("  %-20s %s\n", "nominal_interval_s", fmt_s(llround(nom), ns, sizeof ns));
}

/* Why nothing was written (no valid row), on stderr. */
static void no_valid_row(const importer_t *im)
{
    const import_count_t *c = &im->h.c;
    fprintf(stderr, PROG ": %s: no valid row found (", im->o.in);
    if (c->header + c->blank + c->rows == 0) {
        fprintf(stderr, "the file is empty");
    } else if (c->rows == 0) {
        fprintf(stderr, "no data row after %lld header line(s)", (long long)c->header);
    } else {
        fprintf(stderr, "%lld data rows, %lld malformed", (long long)c->rows,
                (long long)import_malformed(c));
    }
    fprintf(stderr, "); nothing written\n");
}

int main(int argc, char **argv)
{
    importer_t im;
    FILE *f;
    double nom = 0.0;
    char how[64];
    int rc;
    memset(&im, 0, sizeof im);
    if (parse_args(argc, argv, &im) != 0) {
        usage(stderr);
        return 2;
    }
    f = fopen(im.o.in, "rb");
    if (f == NULL) {
        fprintf(stderr, PROG ": cannot read %s: %s\n", im.o.in, strerror(errno));
        return 1;
    }
    rc = first_pass(&im, f);
    if (rc == 0) {
        rc = accel_verdict(&im) != 0 ? -1 : gyro_verdict(&im);
    }
    if (rc == 0) {
        nom = nominal(&im, how, sizeof how);
        hygiene_init(&im.h, nom);
        rc = scan(&im, f, 1);
    }
    fclose(f);
    free(im.dt);
    if (im.lc != NULL) {
        lcm_destroy(im.lc);
        if (rc != 0) {
            fprintf(stderr, PROG ": %s: stopped early; %s holds the %lld samples written before\n",
                    im.o.in, im.o.out, (long long)im.h.c.written);
        }
    }
    if (rc != 0) {
        return 1;
    }
    if (im.suppressed > 0) {
        fprintf(stderr, PROG ": %s: %lld more row messages not shown (--max-messages %lld)\n",
                im.o.in, (long long)im.suppressed, (long long)im.o.max_messages);
    }
    summary(&im, nom, how);
    if (im.h.c.written == 0) {
        no_valid_row(&im);
        return 1;
    }
    return 0;
}
