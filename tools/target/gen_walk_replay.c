/*
 * gen_walk_replay [--corrupt] WALK.csv > walk_replay_data.c
 *
 * The real foot-mounted walk (tools/data/xio-gait-tracking/short_walk.csv,
 * x-io NGIMU, ~400 Hz, 41.6 s) for the target's walk replay
 * (tests/target/walk_replay.c, format in walk_replay.h), and its reference
 * outputs from the filter on the host in the precision this generator is
 * built with: linked with the host float library (SE23_CFG_DOUBLE=0, the
 * M4F's arithmetic but for fused multiply-adds and libm) it writes the M4F
 * image's reference; with the host double library, the M7 image's.
 *
 * The whole walk, t = 0 to 41.6 s: the first 1 s of the 15 s rest aligns
 * the filter, ZUPT and ZARU hold it through the rest, the walk (a closed
 * loop of 23 m, 19 stance phases of 45-70 ms and more) starts at 15.1 s.
 *
 * Input, as se23-import reads the CSV with its defaults (make demo-walk):
 * the importer's own parsing code (tools/import/csv.c, row.c, hygiene.c,
 * linked in) and its main.c's steps, repeated here: one header line, whose
 * field count every row must have; blank lines skipped; the nominal
 * interval the median of the first 10000 intervals between valid rows (a
 * first pass); rows repeating the last written timestamp or earlier
 * dropped; time parsed as an exact decimal to int64 ns; deg/s * pi/180 ->
 * rad/s, g * 9.80665 -> m/s^2; the sequence numbers skip the samples lost
 * in a gap (round(interval / nominal) - 1). The samples then reach the
 * filter as se23-ins and se23-ins-float give them: the importer's doubles,
 * in the float build rounded to float by the assignment to se23_real_t.
 * The counts are checked against the importer's on this file
 * (tools/data/xio-gait-tracking/README.md).
 *
 * The filter, as `se23-ins --preset foot --imu-rate 400 --lat 51.45` sets
 * it up (tools/ins/main.c): se23_ins_preset_foot(400, 51.45 * pi/180) for
 * the configuration (nothing else of se23-ins's options survives the
 * preset), se23_ins_setup, se23_ins_align with the preset's request, then
 * every sample through se23_ins_imu (insr_drive, the driver the target
 * runs too). The host run thus reproduces se23-ins(-float)'s nav states,
 * and the loop closure is computed as se23-walk does (walk_track).
 *
 * Decisions a rounding could flip are measured and reported on stderr, not
 * avoided (real data: no margin can be imposed): the detector's SHOE test
 * on every full window (in the alignment and after it) and the filter's
 * mean-acceleration test (recomputed by insr_accel_nis, checked against every
 * rest flag the filter set); for each sample, the relative distance of the
 * deciding test from its threshold; the closest ones and how many lie
 * within 1e-4, 1e-3, 1e-2.
 *
 * --corrupt perturbs three reference values (1 m on the last checkpoint's
 * north position, one more ZUPT in a checkpoint's counters, the stance
 * flag of one sample in mid-walk): the image built from it must fail
 * exactly those 3 checks.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../import/csv.h"
#include "../import/hygiene.h"
#include "../import/row.h"
#include "gen_print.h"
#include "walk_replay.h"

#define DEG (3.14159265358979323846 / 180.0) /* as tools/ins/main.c */
#define RATE_HZ 400.0                        /* --imu-rate 400 */
#define LAT_DEG 51.45                        /* --lat 51.45 */
#define G0 9.80665                           /* se23-import --g */
#define RATE_PREFIX 10000                    /* se23-import's intervals for the nominal rate */
#define HEADER_LINES 1                       /* se23-import --header 1 */
#define N_MAX 20000
#define N_CLOSEST 6

/* The importer's counts on this file (README of the data set). */
#define EXP_ROWS 16539
#define EXP_WRITTEN 16334
#define EXP_DUP 205
#define EXP_LOST 244
#define EXP_GAPS 165

/* Checkpoints: the first sample at or after each time, and the last. The
 * rest (aligned at 1.0 s), the walk's start (15.1 s), every few steps. */
static const double check_times[] = {1.5,  5.0,  10.0, 15.0, 16.5, 18.0, 20.0,
                                     23.0, 26.0, 29.0, 32.0, 35.0, 38.0};
#define N_CHECK ((int)(sizeof check_times / sizeof check_times[0]) + 1)

static insr_imu_t imu[N_MAX];
static int n_imu;
static uint32_t stance[(N_MAX + 31) / 32];
static se23_real_t stat[N_MAX], nis[N_MAX];
static insr_check_t check[N_CHECK], got[N_CHECK];

/* ---- the CSV, as se23-import reads it ------------------------------------ */

typedef struct {
    row_map_t map;
    hygiene_t h;
    int64_t malformed;
    int64_t dt[RATE_PREFIX]; /* pre-pass: intervals between valid rows */
    size_t n_dt;
    int64_t prev_t;
    int have_prev;
} import_t;

/* se23-import's default column map (x-io's CSV). */
static void import_map(row_map_t *m)
{
    memset(m, 0, sizeof *m);
    m->time_col = 0;
    for (int k = 0; k < 3; ++k) {
        m->gyro_col[k] = 1 + k;
        m->accel_col[k] = 4 + k;
        m->perm[k] = k;
        m->sign[k] = 1.0;
        m->accel_rot[4 * k] = 1.0; /* no --accel-misalign */
    }
    m->time_exp = 9;
    m->gyro_scale = DEG;
    m->accel_scale = G0;
}

/* se23-import's scan (tools/import/main.c) with --header 1: the pre-pass
 * (main_pass 0) collects intervals, the main pass writes samples. */
static int scan(import_t *im, FILE *f, int main_pass)
{
    static csv_reader_t r;
    int64_t seen = 0;
    int in_header = 1, hdr_cols = 0, ncols = 0;
    csv_reader_init(&r, f);
    while (csv_read_line(&r)) {
        row_t row;
        row_status_t st;
        if (in_header && seen < HEADER_LINES) {
            seen++;
            hdr_cols = r.too_long ? 0 : row_count_fields(r.buf);
            continue;
        }
        if (in_header) {
            in_header = 0;
            ncols = seen > 0 && hdr_cols >= row_cols_needed(&im->map) ? hdr_cols : 0;
        }
        st = r.too_long || r.has_nul ? ROW_TEXT : row_parse(&im->map, r.buf, ncols, &row, NULL);
        if (st == ROW_BLANK) {
            continue;
        }
        im->h.c.rows += main_pass;
        if (st != ROW_OK) {
            im->malformed += main_pass;
            continue;
        }
        if (!main_pass) {
            if (im->have_prev && row.t_ns > im->prev_t) {
                im->dt[im->n_dt++] = row.t_ns - im->prev_t;
            }
            if (!im->have_prev || row.t_ns > im->prev_t) {
                im->prev_t = row.t_ns;
                im->have_prev = 1;
            }
            if (im->n_dt >= RATE_PREFIX) {
                break;
            }
        } else {
            int64_t seq_no;
            if (hygiene_accept(&im->h, &row, &seq_no) == HYG_WRITE) {
                insr_imu_t *s = &imu[n_imu];
                if (n_imu == N_MAX) {
                    fprintf(stderr, "gen_walk_replay: more than %d samples\n", N_MAX);
                    return -1;
                }
                s->t_ns = row.t_ns;
                s->seq = seq_no;
                for (int k = 0; k < 3; ++k) {
                    s->w[k] = row.omega[k]; /* double -> se23_real_t, as se23-ins */
                    s->f[k] = row.accel[k];
                }
                n_imu++;
            }
        }
    }
    return ferror(f) ? -1 : 0;
}

static int import_csv(const char *path)
{
    static import_t im;
    const import_count_t *c = &im.h.c;
    double nominal;
    FILE *f = fopen(path, "rb");
    if (f == NULL) {
        fprintf(stderr, "gen_walk_replay: cannot read %s\n", path);
        return -1;
    }
    memset(&im, 0, sizeof im);
    import_map(&im.map);
    if (scan(&im, f, 0) != 0 || fseek(f, 0, SEEK_SET) != 0 || im.n_dt == 0) {
        fclose(f);
        fprintf(stderr, "gen_walk_replay: %s: no interval\n", path);
        return -1;
    }
    nominal = hygiene_median(im.dt, im.n_dt);
    hygiene_init(&im.h, nominal);
    if (scan(&im, f, 1) != 0) {
        fclose(f);
        return -1;
    }
    fclose(f);
    fprintf(stderr,
            "import: %s: %lld rows, %lld written; %lld repeated timestamps, %lld backwards, "
            "%lld malformed; %lld samples lost in %lld gaps; nominal interval %.6f ms (median "
            "of %zu); t = %.6f .. %.6f s, seq 1 .. %lld\n",
            path, (long long)c->rows, (long long)c->written, (long long)c->dup_time,
            (long long)c->backwards, (long long)im.malformed, (long long)c->lost,
            (long long)c->gaps, nominal * 1e-6, im.n_dt, (double)c->first_t_ns * 1e-9,
            (double)c->last_t_ns * 1e-9, (long long)c->seq);
    if (c->rows != EXP_ROWS || c->written != EXP_WRITTEN || c->dup_time != EXP_DUP ||
        c->lost != EXP_LOST || c->gaps != EXP_GAPS || c->backwards != 0 || im.malformed != 0) {
        fprintf(stderr, "gen_walk_replay: the counts differ from se23-import's on the x-io "
                        "walk (%d rows, %d written, %d repeated, %d lost in %d gaps)\n",
                EXP_ROWS, EXP_WRITTEN, EXP_DUP, EXP_LOST, EXP_GAPS);
        return -1;
    }
    return 0;
}

/* ---- the run, and its decisions ------------------------------------------ */

typedef struct {
    double m; /* relative distance of the deciding test from its threshold */
    int k;
    const char *test;
} close_t;

typedef struct {
    walk_track_t track;
    se23_gauss_t prev; /* the filter's state before the current sample */
    close_t closest[N_CLOSEST];
    int n_dec, within[3]; /* decisions; within 1e-4, 1e-3, 1e-2 */
    int n_align, n_rest, n_move, bad, copy_off;
} gen_t;

static void decision(gen_t *g, int k, double m, const char *test)
{
    int i;
    g->n_dec++;
    for (i = 0; i < 3; ++i) {
        g->within[i] += m < pow(10.0, i - 4);
    }
    for (i = N_CLOSEST; i > 0 && m < g->closest[i - 1].m; --i) {
        if (i < N_CLOSEST) {
            g->closest[i] = g->closest[i - 1];
        }
    }
    if (i < N_CLOSEST) {
        g->closest[i].m = m;
        g->closest[i].k = k;
        g->closest[i].test = test;
    }
}

static void hook(void *ctx, const se23_ins_t *ins, int k, int what, int verdict)
{
    gen_t *g = ctx;
    const se23_stationary_t *d = &ins->det;
    const int full = d->count == d->cfg.window;
    const double r = (double)d->stat / (double)d->cfg.threshold;
    const int flag = (ins->status & SE23_INS_ST_STATIONARY) != 0U;
    double nv;
    if (what != 0) {
        g->bad++;
        return;
    }
    if (flag) {
        stance[k / 32] |= 1U << (k % 32);
    }
    stat[k] = d->stat;
    nis[k] = -1.0;
    if (!walk_track(&g->track, ins, k, verdict)) {
        g->bad++;
    }
    if ((ins->status & SE23_INS_ST_ALIGNING) != 0U) {
        /* an alignment sample: the detector on the raw readings */
        if (verdict != SE23_INS_EARLY) {
            fprintf(stderr, "alignment sample %d: verdict %d\n", k, verdict);
            g->bad++;
        } else if (full) {
            g->n_align++;
            decision(g, k, fabs(r - 1.0), "SHOE (alignment)");
        }
    } else if (verdict != SE23_INS_USED) {
        fprintf(stderr, "sample %d: verdict %d\n", k, verdict);
        g->bad++;
    } else if ((nv = walk_nis(ins, &g->prev, &imu[k], verdict)) >= 0.0) {
        /* a live sample with a full window: both rest tests (the second
         * one the filter evaluates only if the first passes) */
        /* without the mean-acceleration test (gravity_test_off) it always passes */
        const double n = ins->cfg.gravity_test_off != 0 ? 0.0 : nv / INSR_ACCEL_TEST_Q;
        const int shoe = d->stationary != 0;
        nis[k] = nv;
        if (flag != (shoe && n < 1.0)) {
            if (fabs(n - 1.0) > 1e-3) {
                fprintf(stderr, "sample %d: the filter's rest flag %d, the generator's copy "
                                "of its tests %d (update insr_accel_nis)\n", k, flag, !flag);
                g->bad++;
            }
            g->copy_off++; /* the copy's double against the build's rounding */
            decision(g, k, fabs(n - 1.0), "mean acceleration");
        } else if (flag) {
            g->n_rest++;
            if (1.0 - r < 1.0 - n) {
                decision(g, k, 1.0 - r, "SHOE");
            } else {
                decision(g, k, 1.0 - n, "mean acceleration");
            }
        } else {
            g->n_move++;
            if (!shoe && n >= 1.0) {
                decision(g, k, fmax(r, n) - 1.0, r > n ? "SHOE" : "mean acceleration");
            } else if (!shoe) {
                decision(g, k, r - 1.0, "SHOE");
            } else {
                decision(g, k, n - 1.0, "mean acceleration");
            }
        }
    } else if (full) {
        fprintf(stderr, "sample %d: a full live window without a state before it\n", k);
        g->bad++;
    }
    g->prev = ins->g;
}

static insr_seq_t seq;
static se23_real_t rate_hz, lat;

/* The filter as se23-ins --preset foot --imu-rate 400 --lat 51.45 sets it
 * up; the checkpoints. */
static int setup(void)
{
    memset(&seq, 0, sizeof seq);
    rate_hz = RATE_HZ;
    lat = LAT_DEG * DEG; /* se23-ins: lat_deg * DEG, rounded to se23_real_t at the call */
    if (se23_ins_preset_foot(rate_hz, lat, &seq.cfg, &seq.start.a) != SE23_OK) {
        fprintf(stderr, "gen_walk_replay: se23_ins_preset_foot failed\n");
        return -1;
    }
    seq.name = "walk";
    seq.start.align = 1;
    seq.imu = imu;
    seq.n_imu = n_imu;
    seq.fix = NULL;
    seq.n_fix = 0;
    seq.check = check;
    seq.n_check = N_CHECK;
    memset(check, 0, sizeof check);
    if (gen_checkpoints(imu, n_imu, check_times, check, N_CHECK) != 0) {
        fprintf(stderr, "gen_walk_replay: checkpoints out of order\n");
        return -1;
    }
    return 0;
}

static int run(gen_t *g)
{
    static se23_ins_t ins; /* large: static */
    int bad, j;
    memset(g, 0, sizeof *g);
    walk_track_init(&g->track);
    for (j = 0; j < N_CLOSEST; ++j) {
        g->closest[j].m = HUGE_VAL;
        g->closest[j].k = -1;
        g->closest[j].test = "-";
    }
    bad = insr_drive(&seq, &ins, got, hook, g);
    for (j = 0; j < N_CHECK; ++j) {
        const insr_check_t *o = &got[j];
        fprintf(stderr,
                "check %2d: sample %5d t = %7.3f s  status 0x%03x  p = (%9.5f, %9.5f, %9.5f) m  "
                "|v| %.4f m/s  zupt %5u zaru %5u missing %3u\n",
                j, o->at, (double)o->t_ns * 1e-9, (unsigned)o->status, (double)o->p[0],
                (double)o->p[1], (double)o->p[2],
                sqrt((double)o->v[0] * o->v[0] + (double)o->v[1] * o->v[1] +
                     (double)o->v[2] * o->v[2]),
                (unsigned)o->c[INSR_CIDX(zupt_used)], (unsigned)o->c[INSR_CIDX(zaru_used)],
                (unsigned)o->c[INSR_CIDX(imu_missing)]);
    }
    {
        const walk_closure_t *c = &g->track.c;
        const insr_check_t *e = &got[N_CHECK - 1];
        fprintf(stderr,
                "walk: %d stance phases, distance %.6f m, closure %.6f m 3D (%.6f horizontal, "
                "%.6f vertical), read at t = %.6f s (sample %d; first state sample %d, "
                "t = %.6f s)\n",
                c->phases, c->dist, walk_closure_err(c, 0), walk_closure_err(c, 1),
                walk_closure_err(c, 2), (double)c->t_last_ns * 1e-9, c->last_at, c->first_at,
                (double)c->t_first_ns * 1e-9);
        fprintf(stderr,
                "counters at the end: used %u align %u missing %u zupt %u zaru %u errors %u; "
                "status 0x%03x\n",
                (unsigned)e->c[INSR_CIDX(imu_used)], (unsigned)e->c[INSR_CIDX(imu_align)],
                (unsigned)e->c[INSR_CIDX(imu_missing)], (unsigned)e->c[INSR_CIDX(zupt_used)],
                (unsigned)e->c[INSR_CIDX(zaru_used)], (unsigned)e->c[INSR_CIDX(filter_errors)],
                (unsigned)e->status);
    }
    fprintf(stderr,
            "decisions: %d (%d alignment windows, %d stationary and %d moving live windows); "
            "deciding test within 1e-4 of its threshold: %d, 1e-3: %d, 1e-2: %d; the copy of "
            "the mean-acceleration test off the filter's flag %d times\n",
            g->n_dec, g->n_align, g->n_rest, g->n_move, g->within[0], g->within[1],
            g->within[2], g->copy_off);
    for (j = 0; j < N_CLOSEST && g->closest[j].k >= 0; ++j) {
        const close_t *c = &g->closest[j];
        fprintf(stderr, "  closest %d: %.3e relative, sample %d (t = %.4f s), %s, flag %d\n",
                j + 1, c->m, c->k, (double)imu[c->k].t_ns * 1e-9, c->test,
                (int)((stance[c->k / 32] >> (c->k % 32)) & 1U));
    }
    if (bad != 0 || g->bad != 0 || ins.c.filter_errors != 0 || g->track.c.phases == 0) {
        fprintf(stderr, "gen_walk_replay: %d failed calls, %d unexpected verdicts, %u filter "
                        "errors, %d stance phases\n",
                bad, g->bad, (unsigned)ins.c.filter_errors, g->track.c.phases);
        return -1;
    }
    return 0;
}

/* ---- output ------------------------------------------------------------- */

static void print_closure(const walk_closure_t *c)
{
    printf("  {.first_at = %d, .last_at = %d, .t_first_ns = %lldLL, .t_last_ns = %lldLL,\n   ",
           c->first_at, c->last_at, (long long)c->t_first_ns, (long long)c->t_last_ns);
    gen_reals("p_first", c->p_first, 3);
    gen_reals("p_last", c->p_last, 3);
    printf("\n   .phases = %d, .dist = %.17g},\n", c->phases, c->dist);
}

static void output(const gen_t *g, int corrupt)
{
    int k, j;
    printf("/* Generated by tools/target/gen_walk_replay%s from\n"
           " * tools/data/xio-gait-tracking/short_walk.csv and the host's %s build of\n"
           " * the filter; do not edit. */\n#include \"walk_replay.h\"\n",
           corrupt ? " --corrupt (three reference values perturbed)" : "",
           SE23_CFG_DOUBLE ? "double" : "float");
    gen_print_imu(imu, n_imu);
    printf("\nstatic const insr_check_t check[%d] = {\n", N_CHECK);
    for (j = 0; j < N_CHECK; ++j) {
        gen_print_check(&got[j]);
    }
    printf("};\n\n/* the stance flag after every sample: bit k %% 32 of word k / 32 */\n");
    printf("static const uint32_t stance[%d] = {", (n_imu + 31) / 32);
    for (k = 0; k < (n_imu + 31) / 32; ++k) {
        printf("%s0x%08xU,", k % 8 == 0 ? "\n " : " ", (unsigned)stance[k]);
    }
    printf("\n};\n\n/* the detector's statistic after every sample */\n");
    printf("static const se23_real_t stat[%d] = {", n_imu);
    for (k = 0; k < n_imu; ++k) {
        fputs(k % 6 == 0 ? "\n " : " ", stdout);
        gen_real(stat[k]);
        putchar(',');
    }
    printf("\n};\n\n/* the mean-acceleration test's NIS after every sample (-1: not decided) */\n");
    printf("static const se23_real_t nis[%d] = {", n_imu);
    for (k = 0; k < n_imu; ++k) {
        fputs(k % 6 == 0 ? "\n " : " ", stdout);
        gen_real(nis[k]);
        putchar(',');
    }
    printf("\n};\n\nconst walk_ref_t walk_ref = {\n {\"walk\",\n");
    gen_print_config(&seq.cfg);
    gen_print_start(&seq.start);
    printf("  imu, %d, NULL, 0, check, %d},\n ", n_imu, N_CHECK);
    gen_real(rate_hz);
    fputs(", ", stdout);
    gen_real(lat);
    printf(", stance, stat, nis,\n");
    print_closure(&g->track.c);
    printf("  %.17g, %d, \"%s\"\n};\n", g->closest[0].m, g->closest[0].k, g->closest[0].test);
}

int main(int argc, char **argv)
{
    static gen_t g;
    int corrupt = 0;
    if (argc == 3 && strcmp(argv[1], "--corrupt") == 0) {
        corrupt = 1;
    } else if (argc != 2) {
        fprintf(stderr, "usage: gen_walk_replay [--corrupt] WALK.csv > walk_replay_data.c\n");
        return 2;
    }
    fprintf(stderr, "gen_walk_replay: the host's %s build\n", SE23_CFG_DOUBLE ? "double" : "float");
    if (import_csv(argv[argc - 1]) != 0 || setup() != 0 || run(&g) != 0) {
        return 1;
    }
    if (corrupt) {
        const int k = n_imu / 2;
        got[N_CHECK - 1].p[0] += 1.0F; /* 1 m: beyond any tolerance */
        got[N_CHECK / 2].c[INSR_CIDX(zupt_used)] += 1U;
        stance[k / 32] ^= 1U << (k % 32);
    }
    output(&g, corrupt);
    return 0;
}
