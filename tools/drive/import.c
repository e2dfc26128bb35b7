/*
 * se23-drive-import: a recorded car drive (IMU, GNSS fixes, a reference
 * trajectory) to one harness LCM log, in time order on one timeline:
 *   SE23_IMU_INFO  once, first: the IMU's rate (median interval, measured)
 *   SE23_IMU       imu_sample, in the IMU's own axes after --axes only
 *   SE23_GNSS      gnss_fix: the antenna in NED at the origin, sigma per axis
 *                  and velocity (with its sigma) as the file gives them;
 *                  none inside an --outage
 *   SE23_GNSS_REF  gnss_fix: the reference (truth) positions, every epoch,
 *                  outages or not
 * and a sidecar text file LOG.drive (origin, the first fix's time, the
 * outages, the counters) that se23-drive (report.c) reads.
 *
 * Every latitude/longitude/height to NED goes through the library's
 * se23_geo_* (include/se23/geodetic.h), the code that flies; the text is
 * parsed exactly to 1e-9 degrees and millimetres (csv_parse_time on the
 * decimal digits, no binary floating point on the way).
 *
 * Formats (drive.h, import_read.c): --rtklib IMU_CSV TAG_FILE POS_FILE
 * (rtklibexplorer/GNSS_IMU: IMU CSV in g and deg/s with a ms tick, RTKLIB
 * time-tag file, RTKLIB .pos: SE23_GNSS gets Q=1 and Q=2 epochs, the
 * reference Q=1 only) and --ublox DIR (ublox-drives: imu.csv[.gz],
 * gnss.csv[.gz], reference_position.csv[.gz]).
 *
 * Exit status: 0 done; 1 unreadable or refused input (unit check, format),
 * nothing valid, or a write error; 2 bad usage.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <lcm/lcm.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../import/gyrocheck.h"
#include "../lcm/harness.h"
#include "drive.h"
#include "se23lcm_gnss_fix.h"
#include "se23lcm_imu_info.h"
#include "se23lcm_imu_sample.h"

#define PROG "se23-drive-import"
#define CH_REF "SE23_GNSS_REF"
#define RATE_PREFIX 10000
#define DEG (3.14159265358979323846 / 180.0)
#define REST_G_LO 0.5 /* the band of se23-import (tools/import/main.c) */
#define REST_G_HI 1.5

typedef struct {
    const char *out, *ublox, *axes, *origin, *meta;
    const char *rtk[3]; /* IMU CSV, tag file, .pos */
    int rtklib, unit_check;
    double g, imu_offset, start, duration;
    double sigma_floor[2];
    int64_t max_messages;
    int n_outages;
    double outage[DRIVE_OUTAGES_MAX][2];
} opts_t;

static void usage(FILE *f)
{
    fprintf(f,
            "usage: se23-drive-import --out file://LOG?mode=w [options]\n"
            "           --rtklib IMU_CSV TAG_FILE POS_FILE | --ublox DIR\n"
            "A recorded drive to one harness LCM log: SE23_IMU_INFO, SE23_IMU, SE23_GNSS\n"
            "(fixes in NED at the origin, antenna), SE23_GNSS_REF (the reference, every\n"
            "epoch), in time order; t_ns = 0 at the whole second of the source's time at\n"
            "or before the earliest record written. Also writes LOG.drive (origin, first\n"
            "fix time, outages, counters) for se23-drive.\n"
            "  --rtklib               rtklibexplorer/GNSS_IMU drive: IMU CSV (acc x,y,z [g],\n"
            "                         gyro x,y,z [deg/s], tick [ms]; the first and last line\n"
            "                         skipped as the source's converter does), RTKLIB time-tag\n"
            "                         file (ticks stretched linearly from the tag file's open\n"
            "                         time to its last record), RTKLIB .pos (llh in degrees;\n"
            "                         SE23_GNSS: Q=1,2 epochs, SE23_GNSS_REF: Q=1 epochs)\n"
            "  --ublox DIR            ublox-drives folder: imu.csv, gnss.csv,\n"
            "                         reference_position.csv (each also as .csv.gz)\n"
            "  --out URL              LCM URL to write, file://LOG?mode=w (required)\n"
            "  --meta FILE            the sidecar (default LOG.drive beside file://LOG)\n"
            "  --axes MAP             signed permutation applied to both sensors: body x,y,z =\n"
            "                         the IMU axes listed, e.g. -x,y,-z (x,y,z); no other\n"
            "                         rotation (mounting angles are the filter's business)\n"
            "  --imu-time-offset S    added to the IMU times, rtklib (0; the source: -0.125)\n"
            "  --g VALUE              1 g [m/s^2] for the rtklib IMU (9.80665)\n"
            "  --origin LAT,LON,H     NED origin [deg, deg, m ellipsoidal] (the first fix\n"
            "                         written)\n"
            "  --outage START,LEN     drop SE23_GNSS fixes in [START, START+LEN) s after the\n"
            "                         first fix written (repeatable, up to %d)\n"
            "  --start S              the part from S s after the file's first GNSS fix (0)\n"
            "  --duration S           ... lasting S s (0: to the end)\n"
            "  --sigma-floor P,V      SE23_GNSS sigmas at least P [m] and V [m/s] (0,0)\n"
            "  --unit-check on|off    refuse an IMU whose first rest does not read %.1f..%.1f g\n"
            "                         or whose gyro reads like the other unit (on)\n"
            "  --max-messages N       per-row messages on stderr per file, then a count (10)\n"
            "Exit status: 0 done, 1 unreadable or refused input or nothing valid, 2 usage.\n",
            DRIVE_OUTAGES_MAX, REST_G_LO, REST_G_HI);
}

/* Takes the --outage options out of argv (into o) before the table parse. */
static int take_outages(int *argc, char **argv, opts_t *o)
{
    int i, w = 1;
    for (i = 1; i < *argc; i++) {
        const char *a = argv[i];
        const char *v = NULL;
        if (strcmp(a, "--outage") == 0 && i + 1 < *argc) {
            v = argv[++i];
        } else if (strncmp(a, "--outage=", 9) == 0) {
            v = a + 9;
        } else if (strcmp(a, "--outage") == 0) {
            fprintf(stderr, PROG ": --outage needs START,LEN\n");
            return -1;
        }
        if (v == NULL) {
            argv[w++] = argv[i];
            continue;
        }
        if (o->n_outages >= DRIVE_OUTAGES_MAX) {
            fprintf(stderr, PROG ": more than %d --outage\n", DRIVE_OUTAGES_MAX);
            return -1;
        }
        if (drive_parse_outage(v, o->outage[o->n_outages]) != 0) {
            fprintf(stderr, PROG ": bad value for --outage (START,LEN seconds, START >= 0, "
                            "LEN > 0): %s\n", v);
            return -1;
        }
        o->n_outages++;
    }
    *argc = w;
    return 0;
}

static int parse_args(int argc, char **argv, opts_t *o)
{
    const char **pos = calloc((size_t)argc + 1, sizeof *pos);
    const char *floor_s = "0,0";
    int n_pos = 0, rc;
    const harness_opt_t opts[] = {
        {"--out", HOPT_STR, &o->out, 0, 0, NULL},
        {"--meta", HOPT_STR, &o->meta, 0, 0, NULL},
        {"--rtklib", HOPT_FLAG, &o->rtklib, 1, 0, NULL},
        {"--ublox", HOPT_STR, &o->ublox, 0, 0, NULL},
        {"--axes", HOPT_STR, &o->axes, 0, 0, NULL},
        {"--imu-time-offset", HOPT_DOUBLE, &o->imu_offset, -10.0, 10.0, NULL},
        {"--g", HOPT_DOUBLE, &o->g, 9.7, 9.9, NULL},
        {"--origin", HOPT_STR, &o->origin, 0, 0, NULL},
        {"--start", HOPT_DOUBLE, &o->start, 0.0, 1e7, NULL},
        {"--duration", HOPT_DOUBLE, &o->duration, 0.0, 1e7, NULL},
        {"--sigma-floor", HOPT_STR, &floor_s, 0, 0, NULL},
        {"--unit-check", HOPT_CHOICE, &o->unit_check, 0, 0, harness_on_off},
        {"--max-messages", HOPT_I64, &o->max_messages, 0, 0, NULL},
    };
    if (pos == NULL) {
        return -1;
    }
    memset(o, 0, sizeof *o);
    o->axes = "x,y,z";
    o->g = 9.80665;
    o->unit_check = 1;
    o->max_messages = 10;
    if (take_outages(&argc, argv, o) != 0) {
        free(pos);
        return -1;
    }
    rc = harness_parse_opts(PROG, argc, argv, opts, (int)(sizeof opts / sizeof opts[0]), usage,
                            pos, &n_pos);
    if (rc == 0 && o->rtklib == (o->ublox != NULL)) {
        fprintf(stderr, PROG ": give one of --rtklib IMU_CSV TAG_FILE POS_FILE or --ublox DIR\n");
        rc = -1;
    }
    if (rc == 0 && o->rtklib && n_pos != 3) {
        fprintf(stderr, PROG ": --rtklib takes three files: IMU_CSV TAG_FILE POS_FILE\n");
        rc = -1;
    }
    if (rc == 0 && o->ublox != NULL && n_pos != 0) {
        fprintf(stderr, PROG ": unexpected argument %s\n", pos[0]);
        rc = -1;
    }
    if (rc == 0 && o->rtklib) {
        o->rtk[0] = pos[0];
        o->rtk[1] = pos[1];
        o->rtk[2] = pos[2];
    }
    if (rc == 0 && (o->out == NULL || strncmp(o->out, "file://", 7) != 0 ||
                    strstr(o->out, "mode=w") == NULL)) {
        fprintf(stderr, PROG ": --out file://LOG?mode=w is required\n");
        rc = -1;
    }
    if (rc == 0 && (sscanf(floor_s, "%lf,%lf", &o->sigma_floor[0], &o->sigma_floor[1]) != 2 ||
                    !(o->sigma_floor[0] >= 0 && o->sigma_floor[0] < 1e3) ||
                    !(o->sigma_floor[1] >= 0 && o->sigma_floor[1] < 1e3))) {
        fprintf(stderr, PROG ": bad value for --sigma-floor: %s\n", floor_s);
        rc = -1;
    }
    if (rc == 0 && o->max_messages < 0) {
        fprintf(stderr, PROG ": bad value for --max-messages\n");
        rc = -1;
    }
    free(pos);
    return rc;
}

/* "LAT,LON,H" exactly (1e-9 deg, mm); 0 if ok. */
static int parse_origin(const char *s, se23_geo_t *g)
{
    csv_field_t f[4];
    int64_t a, b, c;
    if (csv_split(s, f, 4) != 3 || csv_parse_time(f[0], 9, &a) != CSV_NUM_OK ||
        csv_parse_time(f[1], 9, &b) != CSV_NUM_OK || csv_parse_time(f[2], 3, &c) != CSV_NUM_OK ||
        a < -90000000000LL || a > 90000000000LL || b < -180000000000LL || b > 180000000000LL ||
        c < -100000000LL || c > 100000000LL) {
        return -1;
    }
    g->lat_e9 = a;
    g->lon_e9 = b;
    g->h_mm = (int32_t)c;
    return 0;
}

/* The sidecar's path: --meta, else PATH.drive for --out file://PATH?... */
static char *meta_path(const opts_t *o)
{
    const char *p = o->out + 7;
    const size_t n = strcspn(p, "?");
    char *s;
    if (o->meta != NULL) {
        return strdup(o->meta);
    }
    s = malloc(n + 7);
    if (s != NULL) {
        memcpy(s, p, n);
        strcpy(s + n, ".drive");
    }
    return s;
}

static int cmp_i64(const void *a, const void *b)
{
    const int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

typedef struct {
    opts_t o;
    row_map_t map;
    drive_msgs_t msgs;
    drive_imu_t imu;
    drive_fixes_t gnss, ref;
    hygiene_t h;
    int64_t *seq;      /* per IMU row: its sequence number, 0: dropped */
    double nominal_ns;
    int64_t n_dt;
    hyg_run_t rest;
    int rest_found;
    gyro_check_t gyro;
} drive_t;

/* The unit checks of se23-import (first rest ~1 g, gyrocheck.h) on the IMU
 * rows in time order; -1 (after saying so) if the file is refused. */
static int unit_checks(drive_t *d, const char *path)
{
    hyg_rest_t rests;
    size_t i;
    int64_t prev = 0;
    int have_prev = 0;
    gyro_unit_t u;
    const int is_deg = d->map.gyro_scale != 1.0;
    char why[400];
    memset(&rests, 0, sizeof rests);
    gyro_check_init(&d->gyro, d->map.gyro_scale);
    for (i = 0; i < d->imu.n; i++) {
        const row_t *r = &d->imu.row[i];
        hyg_rest_event_t ev;
        if (have_prev && r->t_ns <= prev) {
            continue;
        }
        prev = r->t_ns;
        have_prev = 1;
        ev = hygiene_rest(&rests, r);
        if (ev == HYG_REST_BEGINS && !d->rest_found) {
            d->rest = rests.run;
            d->rest_found = 1;
        }
        gyro_check_add(&d->gyro, r, ev, &rests);
    }
    if (!d->o.unit_check) {
        printf(PROG ": unit check off\n");
        return 0;
    }
    if (d->rest_found) {
        const double g = d->rest.sum / (double)d->rest.n / 9.80665;
        if (g < REST_G_LO || g > REST_G_HI) {
            fprintf(stderr, PROG ": %s: the accelerometer reads %.3g g at rest (1 g expected, "
                            "%.1f to %.1f accepted): the file is not in %s; nothing written\n",
                    path, g, REST_G_LO, REST_G_HI, d->o.rtklib ? "g" : "m/s^2");
            return -1;
        }
        printf(PROG ": unit check: |f| = %.3f g at rest\n", g);
    } else {
        printf(PROG ": unit check: no rest found, the accelerometer's unit not checked\n");
    }
    u = gyro_check_verdict(&d->gyro);
    gyro_check_describe(&d->gyro, why, sizeof why);
    if ((u == GYRO_IS_RAD && is_deg) || (u == GYRO_IS_DEG && !is_deg)) {
        fprintf(stderr, PROG ": %s: the gyroscope's numbers are %s, not %s (%s); nothing "
                        "written\n",
                path, is_deg ? "rad/s" : "deg/s", is_deg ? "deg/s" : "rad/s", why);
        return -1;
    }
    printf(PROG ": gyro unit check: %s (%s)\n",
           u == GYRO_IS_RAD || u == GYRO_IS_DEG ? "confirmed" : "undecided", why);
    return 0;
}

/* se23-import's time checks on the IMU rows: nominal interval (median of
 * the first RATE_PREFIX intervals), repeated/backward rows dropped, gaps
 * counted and skipped in the sequence numbers. */
static int imu_hygiene(drive_t *d)
{
    int64_t *dt = malloc(RATE_PREFIX * sizeof *dt);
    size_t i, n = 0;
    int64_t prev = 0;
    int have = 0;
    d->seq = calloc(d->imu.n + 1, sizeof *d->seq);
    if (dt == NULL || d->seq == NULL) {
        free(dt);
        return -1;
    }
    for (i = 0; i < d->imu.n && n < RATE_PREFIX; i++) {
        const int64_t t = d->imu.row[i].t_ns;
        if (have && t > prev) {
            dt[n++] = t - prev;
        }
        if (!have || t > prev) {
            prev = t;
            have = 1;
        }
    }
    d->n_dt = (int64_t)n;
    d->nominal_ns = n > 0 ? hygiene_median(dt, n) : 0.0;
    free(dt);
    hygiene_init(&d->h, d->nominal_ns);
    for (i = 0; i < d->imu.n; i++) {
        int64_t seq = 0;
        char a[32], b[32];
        const hyg_action_t act = hygiene_accept(&d->h, &d->imu.row[i], &seq);
        if (act == HYG_WRITE) {
            d->seq[i] = d->h.c.seq;
        } else if (act == HYG_BACK) {
            drive_msg(&d->msgs, "imu", d->imu.lineno[i], "time %s s before the previous row's "
                      "%s s, dropped", drive_fmt_s(d->imu.row[i].t_ns, a, sizeof a),
                      drive_fmt_s(d->h.last.t_ns, b, sizeof b));
        }
    }
    return 0;
}

static void print_counts(const char *what, const import_count_t *c, int64_t extra_n,
                         const char *extra_name)
{
    char gap[32];
    printf(PROG ": %s: %lld rows, %lld written; dropped %lld repeated timestamps (%lld with "
                "repeated values), %lld going backwards, %lld malformed (%lld columns, %lld "
                "number, %lld non-finite, %lld long); %lld lost in %lld gaps (longest %s s)",
           what, (long long)c->rows, (long long)c->written, (long long)c->dup_time,
           (long long)c->dup_same, (long long)c->backwards, (long long)import_malformed(c),
           (long long)c->bad_columns, (long long)c->bad_number, (long long)c->bad_nonfinite,
           (long long)c->bad_long, (long long)c->lost, (long long)c->gaps,
           drive_fmt_s(c->longest_gap_ns, gap, sizeof gap));
    if (extra_name != NULL) {
        printf("; %s %lld", extra_name, (long long)extra_n);
    }
    printf("\n");
}

/* Writes one fix on ch as number *n_written + 1 and counts it there, or in
 * *n_bad_geo if se23_geo_to_ned refuses it; -1 on a write error. */
static int put_fix(lcm_t *lc, const char *ch, const se23_geo_frame_t *frame, const drive_fix_t *x,
                   int64_t t_ns, const double floor[2], int64_t *n_written, int64_t *n_bad_geo)
{
    se23lcm_gnss_fix m;
    se23_vec3_t p;
    int k;
    if (se23_geo_to_ned(frame, &x->geo, &p) != SE23_OK) {
        (*n_bad_geo)++;
        return 0;
    }
    memset(&m, 0, sizeof m);
    m.t_ns = t_ns;
    m.seq = *n_written + 1;
    for (k = 0; k < 3; k++) {
        m.p_n[k] = (double)p.v[k];
        m.v_n[k] = x->v[k];
        m.sigma_p[k] = x->sp[k] > floor[0] ? x->sp[k] : floor[0];
        m.sigma_v[k] = x->sv[k] > floor[1] ? x->sv[k] : floor[1];
    }
    m.has_vel = (int8_t)(x->has_vel && m.sigma_v[0] > 0 && m.sigma_v[1] > 0 && m.sigma_v[2] > 0);
    if (se23lcm_gnss_fix_publish(lc, ch, &m) != 0) {
        return -1;
    }
    (*n_written)++;
    return 0;
}

static int in_outage(const opts_t *o, int64_t t_rel_ns)
{
    int k;
    for (k = 0; k < o->n_outages; k++) {
        const double t = (double)t_rel_ns * 1e-9;
        if (t >= o->outage[k][0] && t < o->outage[k][0] + o->outage[k][1]) {
            return 1;
        }
    }
    return 0;
}

static int64_t floor_s(int64_t t_ns)
{
    int64_t q = t_ns / 1000000000;
    if (t_ns % 1000000000 != 0 && t_ns < 0) {
        q--;
    }
    return q * 1000000000;
}

/* Writes the log and the sidecar; 0, or 1 (nothing valid / write error). */
static int write_out(drive_t *d)
{
    const opts_t *o = &d->o;
    int64_t lo, hi, t0 = INT64_MAX, first_fix;
    size_t i = 0, j = 0, k = 0, i_end, j_end, k_end, i0, j0, k0;
    int64_t n_imu = 0, n_gnss = 0, n_ref = 0, n_out = 0, n_bad_geo = 0, n_nosig = 0;
    se23_geo_t origin;
    se23_geo_frame_t frame;
    se23lcm_imu_info info;
    lcm_t *lc;
    char *mp;
    FILE *mf;
    char a[32], b[32], c[32];
    if (d->gnss.n == 0) {
        fprintf(stderr, PROG ": no valid GNSS fix: nothing written\n");
        return 1;
    }
    /* no --start: from the file's first record, also IMU before the first fix */
    lo = d->gnss.fix[0].t_ns + llround(o->start * 1e9);
    hi = o->duration > 0.0 ? lo + llround(o->duration * 1e9) : INT64_MAX;
    if (o->start <= 0.0) {
        lo = INT64_MIN;
    }
    /* the cut: [lo, hi) of each stream */
    for (i0 = 0; i0 < d->imu.n && (d->seq[i0] == 0 || d->imu.row[i0].t_ns < lo); i0++) {
    }
    for (i_end = i0; i_end < d->imu.n && d->imu.row[i_end].t_ns < hi; i_end++) {
    }
    for (j0 = 0; j0 < d->gnss.n && d->gnss.fix[j0].t_ns < lo; j0++) {
    }
    for (j_end = j0; j_end < d->gnss.n && d->gnss.fix[j_end].t_ns < hi; j_end++) {
    }
    for (k0 = 0; k0 < d->ref.n && d->ref.fix[k0].t_ns < lo; k0++) {
    }
    for (k_end = k0; k_end < d->ref.n && d->ref.fix[k_end].t_ns < hi; k_end++) {
    }
    if (j0 == j_end || i0 == i_end) {
        fprintf(stderr, PROG ": no %s in the part [%s, %s) s: nothing written\n",
                j0 == j_end ? "GNSS fix" : "IMU sample",
                lo == INT64_MIN ? "start" : drive_fmt_s(lo, a, sizeof a),
                hi == INT64_MAX ? "end" : drive_fmt_s(hi, b, sizeof b));
        return 1;
    }
    first_fix = d->gnss.fix[j0].t_ns;
    origin = d->gnss.fix[j0].geo;
    if (o->origin != NULL && parse_origin(o->origin, &origin) != 0) {
        fprintf(stderr, PROG ": bad value for --origin (LAT,LON,H in deg, deg, m): %s\n",
                o->origin);
        return 2;
    }
    if (se23_geo_origin(&origin, &frame) != SE23_OK) {
        fprintf(stderr, PROG ": se23_geo_origin refused the origin\n");
        return 1;
    }
    t0 = d->imu.row[i0].t_ns < first_fix ? d->imu.row[i0].t_ns : first_fix;
    if (k0 < k_end && d->ref.fix[k0].t_ns < t0) {
        t0 = d->ref.fix[k0].t_ns;
    }
    t0 = floor_s(t0);
    lc = lcm_create(o->out);
    if (lc == NULL) {
        fprintf(stderr, PROG ": cannot open LCM URL %s\n", o->out);
        return 1;
    }
    memset(&info, 0, sizeof info);
    info.rate_hz = d->nominal_ns > 0 ? 1e9 / d->nominal_ns : 0.0;
    info.rate_source = SE23LCM_IMU_INFO_RATE_MEASURED;
    info.n_intervals = d->n_dt;
    if (info.rate_hz > 0 && se23lcm_imu_info_publish(lc, HARNESS_CH_IMU_INFO, &info) != 0) {
        goto write_error;
    }
    i = i0;
    j = j0;
    k = k0;
    for (;;) {
        int64_t ti, tj, tk;
        while (i < i_end && d->seq[i] == 0) {
            i++;
        }
        ti = i < i_end ? d->imu.row[i].t_ns : INT64_MAX;
        tj = j < j_end ? d->gnss.fix[j].t_ns : INT64_MAX;
        tk = k < k_end ? d->ref.fix[k].t_ns : INT64_MAX;
        if (ti == INT64_MAX && tj == INT64_MAX && tk == INT64_MAX) {
            break;
        }
        if (ti <= tj && ti <= tk) { /* IMU first at a tie: the fix applies after it */
            se23lcm_imu_sample s;
            memset(&s, 0, sizeof s);
            s.t_ns = ti - t0;
            s.seq = d->seq[i];
            memcpy(s.omega, d->imu.row[i].omega, sizeof s.omega);
            memcpy(s.accel, d->imu.row[i].accel, sizeof s.accel);
            if (se23lcm_imu_sample_publish(lc, HARNESS_CH_IMU, &s) != 0) {
                goto write_error;
            }
            n_imu++;
            i++;
        } else if (tj <= tk) {
            const drive_fix_t *x = &d->gnss.fix[j];
            j++;
            if (in_outage(o, tj - first_fix)) {
                n_out++;
                continue;
            }
            if (o->sigma_floor[0] <= 0 && !(x->sp[0] > 0 && x->sp[1] > 0 && x->sp[2] > 0)) {
                n_nosig++;
                continue;
            }
            if (put_fix(lc, HARNESS_CH_GNSS, &frame, x, tj - t0, o->sigma_floor, &n_gnss,
                        &n_bad_geo) != 0) {
                goto write_error;
            }
        } else {
            static const double no_floor[2] = {0.0, 0.0};
            if (put_fix(lc, CH_REF, &frame, &d->ref.fix[k], tk - t0, no_floor, &n_ref,
                        &n_bad_geo) != 0) {
                goto write_error;
            }
            k++;
        }
    }
    lcm_destroy(lc);
    printf(PROG ": origin lat %s deg, lon %s deg, h %.3f m (%s)\n",
           drive_fmt_e9(origin.lat_e9, a, sizeof a), drive_fmt_e9(origin.lon_e9, b, sizeof b),
           origin.h_mm * 1e-3, o->origin != NULL ? "--origin" : "the first fix written");
    printf(PROG ": wrote %lld IMU samples, %lld GNSS fixes (%lld dropped in %d outage(s), %lld "
           "without sigma), %lld reference epochs (%lld refused by se23_geo_to_ned); first fix "
           "at t = %s s of the log (t = 0 is %s s of the source); span %s s\n",
           (long long)n_imu, (long long)n_gnss, (long long)n_out, o->n_outages,
           (long long)n_nosig, (long long)n_ref, (long long)n_bad_geo,
           drive_fmt_s(first_fix - t0, a, sizeof a), drive_fmt_s(t0, b, sizeof b),
           drive_fmt_s(d->imu.row[i_end - 1].t_ns - t0, c, sizeof c));
    mp = meta_path(o);
    mf = mp != NULL ? fopen(mp, "w") : NULL;
    if (mf == NULL) {
        fprintf(stderr, PROG ": cannot write the sidecar %s\n", mp != NULL ? mp : "?");
        free(mp);
        return 1;
    }
    fprintf(mf, "# se23-drive-import sidecar: what se23-drive needs beside the log\n");
    fprintf(mf, "format %s\n", o->rtklib ? "rtklib" : "ublox");
    fprintf(mf, "source %s\n", o->rtklib ? o->rtk[2] : o->ublox);
    fprintf(mf, "origin_lat_deg %s\n", drive_fmt_e9(origin.lat_e9, a, sizeof a));
    fprintf(mf, "origin_lon_deg %s\n", drive_fmt_e9(origin.lon_e9, a, sizeof a));
    fprintf(mf, "origin_h_m %.3f\n", origin.h_mm * 1e-3);
    fprintf(mf, "t0_source_s %s\n", drive_fmt_s(t0, a, sizeof a));
    fprintf(mf, "first_fix_s %s\n", drive_fmt_s(first_fix - t0, a, sizeof a));
    fprintf(mf, "axes %s\n", o->axes);
    fprintf(mf, "imu_time_offset_s %.6f\n", o->imu_offset);
    fprintf(mf, "imu_rate_hz %.6f\n", info.rate_hz);
    fprintf(mf, "imu_written %lld\ngnss_written %lld\nref_written %lld\ngnss_in_outages %lld\n",
            (long long)n_imu, (long long)n_gnss, (long long)n_ref, (long long)n_out);
    for (k = 0; k < (size_t)o->n_outages; k++) {
        fprintf(mf, "outage %.6f %.6f\n", o->outage[k][0], o->outage[k][1]);
    }
    fclose(mf);
    printf(PROG ": sidecar %s\n", mp);
    free(mp);
    return n_imu > 0 && n_gnss + n_out > 0 ? 0 : 1;
write_error:
    lcm_destroy(lc);
    fprintf(stderr, PROG ": cannot write to %s\n", o->out);
    return 1;
}

/* Reads the drive's files into d; 0, or 1 (unreadable or refused). */
static int read_drive(drive_t *d)
{
    opts_t *o = &d->o;
    char path[3][4096];
    const char *imu_path = o->rtk[0];
    int k;
    if (row_parse_axes(o->axes, d->map.perm, d->map.sign) != 0) {
        fprintf(stderr, PROG ": bad value for --axes (a signed permutation of x,y,z): %s\n",
                o->axes);
        return 2;
    }
    row_parse_misalign("0,0,0", d->map.accel_rot);
    if (o->rtklib) {
        d->map.time_col = 6;
        for (k = 0; k < 3; k++) {
            d->map.accel_col[k] = k;
            d->map.gyro_col[k] = 3 + k;
        }
        d->map.time_exp = 6;
        d->map.gyro_scale = DEG;
        d->map.accel_scale = o->g;
        if (drive_read_rtk_imu(o->rtk[0], &d->map, &d->imu, &d->msgs) != 0 ||
            drive_map_tag(o->rtk[1], &d->imu, llround(o->imu_offset * 1e9)) != 0 ||
            drive_read_pos(o->rtk[2], &d->gnss, &d->ref, &d->msgs) != 0) {
            return 1;
        }
    } else {
        static const char *const base[3] = {"imu", "gnss", "reference_position"};
        drive_fixes_t *dst[3] = {NULL, &d->gnss, &d->ref};
        for (k = 0; k < 3; k++) {
            FILE *f;
            snprintf(path[k], sizeof path[k], "%s/%s.csv", o->ublox, base[k]);
            if ((f = fopen(path[k], "rb")) == NULL) {
                snprintf(path[k], sizeof path[k], "%s/%s.csv.gz", o->ublox, base[k]);
            } else {
                fclose(f);
            }
        }
        d->map.time_col = 0;
        for (k = 0; k < 3; k++) {
            d->map.gyro_col[k] = 1 + k;
            d->map.accel_col[k] = 4 + k;
        }
        d->map.time_exp = 9;
        d->map.gyro_scale = 1.0;
        d->map.accel_scale = 1.0;
        imu_path = path[0];
        if (drive_read_ublox_imu(path[0], &d->map, &d->imu, &d->msgs) != 0) {
            return 1;
        }
        for (k = 1; k < 3; k++) {
            if (drive_read_ublox_fixes(path[k], dst[k], &d->msgs) != 0) {
                return 1;
            }
        }
    }
    if (d->imu.n == 0) {
        fprintf(stderr, PROG ": %s: no valid IMU row; nothing written\n", imu_path);
        return 1;
    }
    if (unit_checks(d, imu_path) != 0 || imu_hygiene(d) != 0) {
        return 1;
    }
    drive_fix_hygiene(&d->gnss, &d->msgs);
    drive_fix_hygiene(&d->ref, &d->msgs);
    {
        import_count_t c = d->h.c;
        c.rows = d->imu.c.rows;
        c.bad_columns = d->imu.c.bad_columns;
        c.bad_number = d->imu.c.bad_number;
        c.bad_nonfinite = d->imu.c.bad_nonfinite;
        c.bad_long = d->imu.c.bad_long;
        print_counts("imu", &c, d->imu.skipped_ends, o->rtklib ? "first/last line skipped" : NULL);
        printf(PROG ": imu: nominal interval %.6f ms (%.3f Hz; median of the first %lld "
               "intervals)\n", d->nominal_ns * 1e-6, d->nominal_ns > 0 ? 1e9 / d->nominal_ns : 0.0,
               (long long)d->n_dt);
        print_counts("gnss", &d->gnss.c, d->gnss.skipped_q,
                     o->rtklib ? "other quality than Q=1,2 skipped" : NULL);
        print_counts("reference", &d->ref.c, 0, NULL);
        printf(PROG ": counters\n");
        printf("  imu_rows %lld\n  imu_written %lld\n  imu_dup_time %lld\n  imu_backwards %lld\n"
               "  imu_gaps %lld\n  imu_lost %lld\n  imu_malformed %lld\n  imu_nonfinite %lld\n",
               (long long)c.rows, (long long)c.written, (long long)c.dup_time,
               (long long)c.backwards, (long long)c.gaps, (long long)c.lost,
               (long long)import_malformed(&c), (long long)c.bad_nonfinite);
        printf("  gnss_rows %lld\n  gnss_valid %lld\n  gnss_dup_time %lld\n  gnss_backwards %lld\n"
               "  gnss_gaps %lld\n  gnss_malformed %lld\n  gnss_nonfinite %lld\n",
               (long long)d->gnss.c.rows, (long long)d->gnss.c.written,
               (long long)d->gnss.c.dup_time, (long long)d->gnss.c.backwards,
               (long long)d->gnss.c.gaps, (long long)import_malformed(&d->gnss.c),
               (long long)d->gnss.c.bad_nonfinite);
        printf("  ref_valid %lld\n  ref_dup_time %lld\n  ref_backwards %lld\n  ref_malformed "
               "%lld\n", (long long)d->ref.c.written, (long long)d->ref.c.dup_time,
               (long long)d->ref.c.backwards,
               (long long)(o->rtklib ? 0 : import_malformed(&d->ref.c)));
    }
    if (d->msgs.suppressed > 0) {
        fprintf(stderr, PROG ": %lld more row messages not shown (--max-messages %lld)\n",
                (long long)d->msgs.suppressed, (long long)d->msgs.max);
    }
    (void)cmp_i64;
    return 0;
}

int main(int argc, char **argv)
{
    drive_t *d = calloc(1, sizeof *d);
    char **av = drive_split_eq(&argc, argv);
    int rc;
    if (d == NULL || av == NULL) {
        return 1;
    }
    if (parse_args(argc, av, &d->o) != 0) {
        usage(stderr);
        return 2;
    }
    d->msgs.max = d->o.max_messages;
    d->gnss.name = "gnss";
    d->ref.name = "reference";
    rc = read_drive(d);
    if (rc == 0) {
        rc = write_out(d);
    }
    free(d->imu.row);
    free(d->imu.lineno);
    free(d->gnss.fix);
    free(d->ref.fix);
    free(d->seq);
    free(d);
    free(av);
    return rc;
}
