/*
 * Target test image of the navigation filter on a real car drive: the
 * first 70 s of the rtklibexplorer drive 0708 (roof IMU at 100 Hz, RTK
 * fixes at 4 Hz; drive_replay_data.c from tools/target/gen_drive_replay.c
 * out of se23-drive-import's log) through the filter configured as
 * `se23-ins --preset car --lat 40.0966 --height 1601.5 --mount
 * 0,6.79,-5.35 --lever 0,-0.05,0` (se23_ins_preset_car at the log's
 * measured 99.97 Hz: 2 s static alignment at the start of the 35 s rest,
 * ZUPT at rest, the heading from the GNSS course once the car drives above
 * the preset's course speed (42.75 s), the fixes and the non-holonomic
 * constraint to 60.5 s, then 10 s and 90 m without fixes), in the build's
 * precision, against the host's run in the SAME precision (the float image
 * against the host float library, the double image against the host double
 * one):
 *  - exactly: at each checkpoint the time, the status word and every
 *    counter; the verdict of se23_ins_gnss on each of the 227 fixes;
 *  - within the tolerances below: R, v, p, the biases, the diagonal of P
 *    (relative) at each checkpoint.
 * It also runs se23_ins_preset_car itself, sets the installation as
 * se23-ins does (lever arm, mounting, height: the replay's), and compares
 * it with the host's configuration (integers exactly, reals to PRESET_TOL
 * relative).
 * Prints one line per checkpoint, the verdict check and the worst deviation
 * of each quantity; exits with the number of failed checks (capped at
 * DRIVE_EXIT_MAX; 254/255 are the port's assert/fault codes).
 *
 * Tolerances: tol[] (the worst measured in brackets), as the walk replay's
 * (walk_replay.c): both sides execute the same C on the same inputs in the
 * same precision and differ only by the target library's fused
 * multiply-adds and newlib's libm against glibc's. Unlike the walk's, this
 * run's decisions (ZUPT at rest, the fixes' gate and delay, the course
 * heading) are not measured against their thresholds: a rounding that
 * flipped one would fail the exact checks, naming the checkpoint or fix.
 */
#include <stdio.h>
#include <string.h>

#include "drive_replay.h"
#include "walk_replay_check.h"

#define DRIVE_EXIT_MAX 200
#define DRIVE_CHECK_MAX 24

static const char *const group_name[RPC_N_STATE] = {"R", "v [m/s]", "p [m]", "b_g [rad/s]",
                                                    "b_a [m/s^2]", "diag P (rel)"};

/* Largest deviation accepted per group: absolute in the quantity's units,
 * or relative (rel[]); 5-10x the worst measured over the drive (in
 * brackets). Float: the M4F against the host float library. Double: the
 * M7 against the host double library. */
#if SE23_CFG_DOUBLE
static const double tol[RPC_N_STATE] = {
    1e-12,   /* R             [1.1e-13] */
    5e-13,   /* v             [5.0e-14 m/s] */
    2e-12,   /* p             [2.1e-13 m] */
    1.5e-15, /* b_g           [1.8e-16 rad/s] */
    4e-14,   /* b_a           [4.3e-15 m/s^2] */
    3e-11};  /* diag P        [3.7e-12 relative] */
#else
static const double tol[RPC_N_STATE] = {
    5e-5,    /* R             [7.8e-6] */
    3e-4,    /* v             [4.1e-5 m/s] */
    1e-3,    /* p             [1.7e-4 m, at the end of the 10 s without fixes] */
    1e-6,    /* b_g           [1.0e-7 rad/s] */
    3e-5,    /* b_a           [4.0e-6 m/s^2] */
    1e-2};   /* diag P        [1.1e-3 relative] */
#endif
static const int rel[RPC_N_STATE] = {0, 0, 0, 0, 0, 1};

/* se23_ins_preset_car on the target against the host's configuration. */
#if SE23_CFG_DOUBLE
#define PRESET_TOL 1e-12
#else
#define PRESET_TOL 1e-6
#endif

static se23_ins_t ins; /* large: static */
static insr_check_t got[DRIVE_CHECK_MAX];
static double worst_run[RPC_N_STATE];
static int worst_at[RPC_N_STATE];
static const rpc_groups_t groups = {RPC_N_STATE, group_name, tol, rel, worst_run, worst_at};

typedef struct {
    int n, bad, first_bad, first_got;
} verdicts_t;

/* After every fix: its verdict against the host's. */
static void hook(void *ctx, const se23_ins_t *in, int k, int what, int verdict)
{
    verdicts_t *v = ctx;
    (void)in;
    (void)k;
    if (what == 0) {
        return;
    }
    if (v->n < drive_ref.seq.n_fix && verdict != drive_ref.verdict[v->n]) {
        if (v->bad++ == 0) {
            v->first_bad = v->n;
            v->first_got = verdict;
        }
    }
    ++v->n;
}

/* The checks of one checkpoint; returns 1 if it failed. */
static int check(int j, const insr_check_t *o, const insr_check_t *ref)
{
    const char *where;
    double w;
    const int fails = rpc_check_state(&groups, j, o, ref, &w, &where);
    printf("drive t = %6.3f s  p = (%8.3f, %8.3f, %6.3f) m  %4u fixes %4u ZUPT %3u NHC  worst "
           "%5.1f%% of tol (%s)  %s\n",
           (double)ref->t_ns * 1e-9, (double)ref->p[0], (double)ref->p[1], (double)ref->p[2],
           (unsigned)ref->c[INSR_CIDX(gnss_used)], (unsigned)ref->c[INSR_CIDX(zupt_used)],
           (unsigned)ref->c[INSR_CIDX(nhc_used)], w * 100.0, where, fails != 0 ? "FAIL" : "ok");
    return fails;
}

/* The fixes' verdicts. */
static int check_verdicts(const verdicts_t *v)
{
    const int n = drive_ref.seq.n_fix;
    if (v->bad != 0 || v->n != n) {
        printf("FAIL fixes: %d delivered of %d, %d verdicts differ, the first of fix %d (t = "
               "%.3f s: %d, expected %d)\n",
               v->n, n, v->bad, v->first_bad,
               (double)drive_ref.seq.fix[v->first_bad].t_ns * 1e-9, v->first_got,
               (int)drive_ref.verdict[v->first_bad]);
        return 1;
    }
    printf("fixes     %d verdicts identical (none from %.1f s for %.0f s)  ok\n", n,
           drive_ref.outage_s[0], drive_ref.outage_s[1]);
    return 0;
}

/* se23_ins_preset_car and the installation on the target against the
 * configuration replayed. */
static int check_preset(void)
{
    static se23_ins_config_t cfg; /* static: kept off the stack */
    se23_ins_align_t al;
    se23_status_t st;
    memset(&cfg, 0, sizeof cfg);
    memset(&al, 0, sizeof al);
    st = se23_ins_preset_car(drive_ref.rate_hz, drive_ref.lat, &cfg, &al);
    cfg.height = drive_ref.seq.cfg.height; /* as se23-ins sets the installation */
    cfg.mount_bv = drive_ref.seq.cfg.mount_bv;
    cfg.lever_b = drive_ref.seq.cfg.lever_b;
    return rpc_check_preset("se23_ins_preset_car", drive_ref.rate_hz, drive_ref.lat, st, &cfg,
                            &al, &drive_ref.seq.cfg, &drive_ref.seq.start.a, PRESET_TOL);
}

int main(void)
{
    static verdicts_t v;
    const insr_seq_t *q = &drive_ref.seq;
    int fails = 0, bad, j;
    printf("se23 drive replay (rtklibexplorer drive 0708, %d samples, %d fixes, %.1f s), %s "
           "build, against the host's %s run\n",
           q->n_imu, q->n_fix, (double)q->imu[q->n_imu - 1].t_ns * 1e-9,
           SE23_CFG_DOUBLE ? "double" : "float", SE23_CFG_DOUBLE ? "double" : "float");
    fails += check_preset();
    if (q->n_check > DRIVE_CHECK_MAX) {
        printf("FAIL %d checkpoints, room for %d\n", q->n_check, DRIVE_CHECK_MAX);
        return 1;
    }
    bad = insr_drive(q, &ins, got, hook, &v);
    if (bad != 0) {
        printf("FAIL %d calls failed (setup, align, state)\n", bad);
        ++fails;
    }
    for (j = 0; j < q->n_check; ++j) {
        fails += check(j, &got[j], &q->check[j]);
    }
    fails += check_verdicts(&v);
    rpc_print_worst(&groups);
    printf("%d failure(s)\n", fails);
    return fails > DRIVE_EXIT_MAX ? DRIVE_EXIT_MAX : fails;
}
