/*
 * gen_drive_replay [--corrupt] LOG > drive_replay_data.c
 *
 * A part of the real car drive (tools/data/car/rtklibexplorer-drive-0708:
 * roof IMU at 100 Hz, RTK fixes at 4 Hz) for the target's drive replay
 * (tests/target/drive_replay.c, format in drive_replay.h), and its
 * reference outputs from the filter on the host in the precision this
 * generator is built with: linked with the host float library
 * (SE23_CFG_DOUBLE=0, the M4F's arithmetic but for fused multiply-adds and
 * libm) it writes the M4F image's reference; with the host double library,
 * the M7 image's.
 *
 * Input: the LCM log se23-drive-import writes of the part (port/target.mk
 * runs it with the installation of tools/drive/rtklibexplorer-0708.conf:
 * --axes -x,y,-z --imu-time-offset -0.125, --duration and --outage below),
 * so that the time map, the axes and the fixes in NED are the importer's:
 * SE23_IMU_INFO (the measured rate), SE23_IMU, SE23_GNSS, read in log order
 * as se23-ins reads them (tools/lcm/logfile.c, the generated decoders); a
 * fix is delivered after the last IMU sample before it in the log. The
 * IMU's first sample is at 3.73 s, the first fix at 0.5 s: the 13 fixes
 * before the first sample have none and are left out (se23-ins hands them
 * to the filter, which counts them as gnss_early). The samples and fixes
 * reach the filter as se23-ins(-float) gives them: the log's doubles, in
 * the float build rounded to float by the assignment to se23_real_t.
 *
 * The filter, as `se23-ins --preset car --lat 40.0966 --height 1601.5
 * --mount 0,6.79,-5.35 --lever 0,-0.05,0` sets it up (tools/ins/main.c,
 * build_config): se23_ins_preset_car(rate, lat) at the log's rate, then
 * height, mount_bv (the rotation vector of C_bv = Rz(yaw) Ry(pitch)
 * Rx(roll), from the angles in double), lever_b; se23_ins_setup,
 * se23_ins_align with the preset's request (2 s static alignment at the
 * start of the drive's 38 s rest, the heading from the GNSS course once the
 * car drives above the preset's course speed), then every sample and fix
 * through insr_drive, the driver the target runs too.
 *
 * --corrupt perturbs three reference values (1 m on the last checkpoint's
 * north position, one more gnss_used in a checkpoint's counters, the
 * verdict of one fix): the image built from it must fail exactly those 3
 * checks.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../lcm/harness.h"
#include "../lcm/logfile.h"
#include "drive_replay.h"
#include "gen_print.h"
#include "se23/so3.h"
#include "se23lcm_gnss_fix.h"
#include "se23lcm_imu_info.h"
#include "se23lcm_imu_sample.h"

#define DEG (3.14159265358979323846 / 180.0) /* as tools/ins/main.c */
#define LAT_DEG 40.0966                      /* --lat (rtklibexplorer-0708.conf) */
#define HEIGHT_M 1601.5                      /* --height */
static const double mount_deg[3] = {0.0, 6.79, -5.35}; /* --mount roll, pitch, yaw */
static const double lever_m[3] = {0.0, -0.05, 0.0};    /* --lever */
/* the importer's --outage (after the first fix), repeated here for the table */
#define OUTAGE_FROM_S 60.0
#define OUTAGE_LEN_S 10.0
#define N_MAX 8000
#define FIX_MAX 400

/* Checkpoints: the first sample at or after each time [s of the log], and
 * the last: after the alignment (the first 2 s of samples, from 3.73 s),
 * the rest (to ~38.5 s), the drive, the heading from the course (42.75 s),
 * the fixes to 60.5 s, the 10 s without. */
static const double check_times[] = {6.0,  10.0, 20.0, 30.0, 38.0, 40.0, 42.0, 43.0,
                                     44.0, 47.0, 50.0, 55.0, 60.4, 62.5, 65.0, 68.0};
#define N_CHECK ((int)(sizeof check_times / sizeof check_times[0]) + 1)

static insr_imu_t imu[N_MAX];
static insr_fix_t fix[FIX_MAX];
static signed char verdict[FIX_MAX];
static int n_imu, n_fix, n_before;
static int64_t first_fix_ns = -1; /* the first fix in the log: the outage's origin */
static double rate_log;
static insr_check_t check[N_CHECK], got[N_CHECK];
static insr_seq_t seq;
static se23_real_t rate_hz, lat;

/* ---- the log, as se23-ins reads it ---------------------------------------- */

static int take_imu(const logfile_event_t *ev)
{
    se23lcm_imu_sample m;
    insr_imu_t *s = &imu[n_imu];
    if (se23lcm_imu_sample_decode(ev->data, 0, ev->datalen, &m) < 0 || n_imu == N_MAX) {
        fprintf(stderr, "gen_drive_replay: IMU sample %d: undecodable or beyond %d\n", n_imu,
                N_MAX);
        return -1;
    }
    s->t_ns = m.t_ns;
    s->seq = m.seq;
    for (int i = 0; i < 3; ++i) {
        s->w[i] = m.omega[i]; /* double -> se23_real_t, as se23-ins */
        s->f[i] = m.accel[i];
    }
    n_imu++;
    return 0;
}

static int take_fix(const logfile_event_t *ev)
{
    se23lcm_gnss_fix m;
    insr_fix_t *x = &fix[n_fix];
    if (se23lcm_gnss_fix_decode(ev->data, 0, ev->datalen, &m) < 0 || n_fix == FIX_MAX) {
        fprintf(stderr, "gen_drive_replay: fix %d: undecodable or beyond %d\n", n_fix, FIX_MAX);
        return -1;
    }
    if (first_fix_ns < 0) {
        first_fix_ns = m.t_ns;
    }
    if (n_imu == 0) {
        n_before++; /* nothing to deliver it after */
        return 0;
    }
    x->at = n_imu - 1;
    x->t_ns = m.t_ns;
    for (int i = 0; i < 3; ++i) {
        x->p[i] = m.p_n[i];
        x->sp[i] = m.sigma_p[i];
        x->v[i] = m.v_n[i];
        x->sv[i] = m.sigma_v[i];
    }
    x->has_vel = m.has_vel != 0;
    n_fix++;
    return 0;
}

static int read_log(const char *path)
{
    logfile_t lf;
    logfile_event_t ev;
    int bad = 0;
    if (logfile_open(&lf, path, "gen_drive_replay") != 0) {
        return -1;
    }
    while (bad == 0 && logfile_next(&lf, &ev)) {
        if (strcmp(ev.channel, HARNESS_CH_IMU) == 0) {
            bad = take_imu(&ev);
        } else if (strcmp(ev.channel, HARNESS_CH_GNSS) == 0) {
            bad = take_fix(&ev);
        } else if (strcmp(ev.channel, HARNESS_CH_IMU_INFO) == 0) {
            se23lcm_imu_info m;
            bad = se23lcm_imu_info_decode(ev.data, 0, ev.datalen, &m) < 0;
            rate_log = m.rate_hz;
        }
    }
    bad |= lf.corrupt_spans != 0;
    logfile_close(&lf);
    fprintf(stderr,
            "log: %s: rate %.6f Hz, %d IMU samples (t = %.3f .. %.3f s), %d fixes (%d before "
            "the first sample, left out)\n",
            path, rate_log, n_imu, n_imu ? (double)imu[0].t_ns * 1e-9 : 0.0,
            n_imu ? (double)imu[n_imu - 1].t_ns * 1e-9 : 0.0, n_fix, n_before);
    if (bad != 0 || n_imu < 100 || n_fix == 0 || !(rate_log > 0.0)) {
        fprintf(stderr, "gen_drive_replay: %s: not a drive's log\n", path);
        return -1;
    }
    return 0;
}

/* ---- the filter ------------------------------------------------------------ */

/* The rotation vector of C_bv = Rz(yaw) Ry(pitch) Rx(roll) (se23-ins
 * --mount: the product in double, its log in the build's precision). */
static int mount_rotation(se23_vec3_t *rv)
{
    double C[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    se23_mat3_t M;
    for (int r = 2; r >= 0; --r) { /* C = ((I Rz) Ry) Rx */
        const double c = cos(mount_deg[r] * DEG), s = sin(mount_deg[r] * DEG);
        const int a = (r + 1) % 3, b = (r + 2) % 3; /* the plane the axis r turns */
        for (int i = 0; i < 3; ++i) {
            const double ca = C[i][a], cb = C[i][b];
            C[i][a] = ca * c + cb * s;
            C[i][b] = cb * c - ca * s;
        }
    }
    for (int i = 0; i < 9; ++i) {
        M.m[i / 3][i % 3] = C[i / 3][i % 3];
    }
    return se23_so3_log(&M, rv) != SE23_OK;
}

static int setup(void)
{
    memset(&seq, 0, sizeof seq);
    rate_hz = rate_log;
    lat = LAT_DEG * DEG;
    if (se23_ins_preset_car(rate_hz, lat, &seq.cfg, &seq.start.a) != SE23_OK ||
        mount_rotation(&seq.cfg.mount_bv) != 0) {
        fprintf(stderr, "gen_drive_replay: se23_ins_preset_car or the mounting refused\n");
        return -1;
    }
    seq.cfg.height = HEIGHT_M;
    for (int i = 0; i < 3; ++i) {
        seq.cfg.lever_b.v[i] = lever_m[i];
    }
    seq.name = "drive";
    seq.start.align = 1;
    seq.imu = imu;
    seq.n_imu = n_imu;
    seq.fix = fix;
    seq.n_fix = n_fix;
    seq.check = check;
    seq.n_check = N_CHECK;
    memset(check, 0, sizeof check);
    if (gen_checkpoints(imu, n_imu, check_times, check, N_CHECK) != 0) {
        fprintf(stderr, "gen_drive_replay: checkpoints out of order\n");
        return -1;
    }
    return 0;
}

typedef struct {
    int next_fix, heading_at, bad;
} gen_t;

static void hook(void *ctx, const se23_ins_t *ins, int k, int what, int v)
{
    gen_t *g = ctx;
    if (what == 1) {
        verdict[g->next_fix++] = (signed char)v;
    } else if (v != SE23_INS_USED && v != SE23_INS_EARLY) {
        fprintf(stderr, "sample %d: verdict %d\n", k, v);
        g->bad++;
    }
    if (g->heading_at < 0 && ins->c.course_headings != 0U) {
        g->heading_at = k;
    }
}

static int run(void)
{
    static se23_ins_t ins; /* large: static */
    gen_t g = {0, -1, 0};
    int bad, j, hist[SE23_INS_FAILED + 1] = {0};
    bad = insr_drive(&seq, &ins, got, hook, &g);
    for (j = 0; j < N_CHECK; ++j) {
        const insr_check_t *o = &got[j];
        fprintf(stderr,
                "check %2d: sample %4d t = %7.3f s  status 0x%03x  p = (%9.3f, %9.3f, %8.3f) m  "
                "|v| %6.3f m/s  gnss %3u gated %2u early %2u  zupt %4u nhc %4u\n",
                j, o->at, (double)o->t_ns * 1e-9, (unsigned)o->status, (double)o->p[0],
                (double)o->p[1], (double)o->p[2],
                sqrt((double)o->v[0] * o->v[0] + (double)o->v[1] * o->v[1] +
                     (double)o->v[2] * o->v[2]),
                (unsigned)o->c[INSR_CIDX(gnss_used)], (unsigned)o->c[INSR_CIDX(gnss_gated)],
                (unsigned)o->c[INSR_CIDX(gnss_early)], (unsigned)o->c[INSR_CIDX(zupt_used)],
                (unsigned)o->c[INSR_CIDX(nhc_used)]);
    }
    for (j = 0; j < n_fix; ++j) {
        hist[verdict[j] >= 0 && verdict[j] <= SE23_INS_FAILED ? verdict[j] : 0]++;
    }
    fprintf(stderr, "fixes: %d delivered, verdicts used %d, early %d, pending %d, gated %d; "
                    "the heading from the course at sample %d (t = %.3f s); filter errors %u\n",
            g.next_fix, hist[SE23_INS_USED], hist[SE23_INS_EARLY], hist[SE23_INS_PENDING],
            hist[SE23_INS_GATED], g.heading_at,
            g.heading_at >= 0 ? (double)imu[g.heading_at].t_ns * 1e-9 : -1.0,
            (unsigned)ins.c.filter_errors);
    if (bad != 0 || g.bad != 0 || g.next_fix != n_fix || g.heading_at < 0 ||
        ins.c.filter_errors != 0) {
        fprintf(stderr, "gen_drive_replay: %d failed calls, %d unexpected verdicts, %u filter "
                        "errors, no heading from the course or fixes undelivered\n",
                bad, g.bad, (unsigned)ins.c.filter_errors);
        return -1;
    }
    return 0;
}

/* ---- output ---------------------------------------------------------------- */

static void output(int corrupt)
{
    int j;
    printf("/* Generated by tools/target/gen_drive_replay%s from the\n"
           " * rtklibexplorer drive 0708 as se23-drive-import writes it and the host's %s\n"
           " * build of the filter; do not edit. */\n#include \"drive_replay.h\"\n",
           corrupt ? " --corrupt (three reference values perturbed)" : "",
           SE23_CFG_DOUBLE ? "double" : "float");
    gen_print_imu(imu, n_imu);
    printf("\n/* %d fixes: after sample at, t_ns, p_n, sigma_p, v_n, sigma_v [m, m/s] */\n", n_fix);
    printf("static const insr_fix_t fix[%d] = {\n", n_fix);
    for (j = 0; j < n_fix; ++j) {
        const insr_fix_t *x = &fix[j];
        printf(" {%d, %lldLL, ", x->at, (long long)x->t_ns);
        gen_real3(x->p);
        fputs(", ", stdout);
        gen_real3(x->sp);
        fputs(",\n  ", stdout);
        gen_real3(x->v);
        fputs(", ", stdout);
        gen_real3(x->sv);
        printf(", %d},\n", x->has_vel);
    }
    printf("};\n\nstatic const insr_check_t check[%d] = {\n", N_CHECK);
    for (j = 0; j < N_CHECK; ++j) {
        gen_print_check(&got[j]);
    }
    printf("};\n\n/* se23_ins_gnss's verdict on every fix */\n");
    printf("static const signed char verdict[%d] = {", n_fix);
    for (j = 0; j < n_fix; ++j) {
        printf("%s%d,", j % 24 == 0 ? "\n " : " ", verdict[j]);
    }
    printf("\n};\n\nconst drive_ref_t drive_ref = {\n {\"drive\",\n");
    gen_print_config(&seq.cfg);
    gen_print_start(&seq.start);
    printf("  imu, %d, fix, %d, check, %d},\n ", n_imu, n_fix, N_CHECK);
    gen_real(rate_hz);
    fputs(", ", stdout);
    gen_real(lat);
    printf(", verdict, {%.17g, %.17g}\n};\n", (double)first_fix_ns * 1e-9 + OUTAGE_FROM_S,
           OUTAGE_LEN_S);
}

int main(int argc, char **argv)
{
    int corrupt = 0;
    if (argc == 3 && strcmp(argv[1], "--corrupt") == 0) {
        corrupt = 1;
    } else if (argc != 2) {
        fprintf(stderr, "usage: gen_drive_replay [--corrupt] LOG > drive_replay_data.c\n");
        return 2;
    }
    fprintf(stderr, "gen_drive_replay: the host's %s build\n",
            SE23_CFG_DOUBLE ? "double" : "float");
    if (read_log(argv[argc - 1]) != 0 || setup() != 0 || run() != 0) {
        return 1;
    }
    if (corrupt) {
        got[N_CHECK - 1].p[0] += 1.0F; /* 1 m: beyond any tolerance */
        got[N_CHECK / 2].c[INSR_CIDX(gnss_used)] += 1U;
        verdict[n_fix / 2] = (signed char)(verdict[n_fix / 2] ^ 1);
    }
    output(corrupt);
    return 0;
}
