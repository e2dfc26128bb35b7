/*
 * Target test image of the navigation filter on real data: the x-io
 * foot-mounted walk (41.6 s at ~400 Hz, walk_replay_data.c from
 * tools/target/gen_walk_replay.c) through the filter configured as
 * `se23-ins --preset foot --imu-rate 400 --lat 51.45` (se23_ins_preset_foot,
 * static alignment at the first rest, ZUPT/ZARU, 15 states, no GNSS), in
 * the build's precision, against the host's run in the SAME precision (the
 * float image against the host float library, the double image against the
 * host double one):
 *  - exactly: at each checkpoint the time, the status word and every
 *    counter; after every sample the stance flag (16334 decisions of the
 *    detector and the mean-acceleration test); the loop closure's
 *    bookkeeping (the samples of the first state and of the last stance's
 *    start, the number of stance phases);
 *  - within the tolerances below: R, v, p, the biases, the diagonal of P
 *    (relative) at each checkpoint; after every sample both rest tests'
 *    statistics (the detector's SHOE statistic and the mean-acceleration
 *    NIS, recomputed by insr_accel_nis; relative to the larger of the
 *    value and the test's threshold); the loop-closure positions and the
 *    distance walked.
 * It also runs se23_ins_preset_foot(400, 51.45 deg) itself and compares
 * it with the host's configuration the replay uses (integers exactly, reals
 * to PRESET_TOL relative).
 * Prints one line per checkpoint, the stance and closure checks, the worst
 * deviation of each quantity and the closure figures; exits with the number
 * of failed checks (capped at WALK_EXIT_MAX; 254/255 are the port's
 * assert/fault codes).
 *
 * Tolerances: tol[] (the worst measured in brackets). Both sides execute
 * the same C on the same inputs in the same precision; they differ only by
 * the target library's fused multiply-adds (-ffp-contract=fast) and
 * newlib's libm against glibc's, a rounding or two per operation, which the
 * filter's updates keep from growing (in float: 1.4e-4 m in position after
 * 41.6 s and 23 m of walking).
 *
 * A real walk is not a designed sequence (gen_ins_replay keeps every
 * decision a factor 2 from its threshold; here none can be imposed): a
 * rest-test decision closer to its threshold than these roundings would
 * flip a stance flag, a ZUPT with it, and fail the exact checks. The
 * generator measures how close the host's decisions come (the closest:
 * 2.1e-3 relative, the detector's test at t = 26.1 s); the image measures
 * how far its rest statistics are from the host's and prints the closest
 * call: the largest deviation as a fraction of the host's margin over
 * every decision. Measured: 5.9 % on the M4F (t = 27.232 s), 3e-10 on the
 * M7 (the previous preset: 36 % on the M4F). A change of the float build's
 * rounding about 17x larger could flip that decision; the stance check
 * then names the first differing sample.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "walk_replay.h"
#include "walk_replay_check.h"

#define WALK_EXIT_MAX 200
#define WALK_CHECK_MAX 16

/* the state's groups (RPC_R .. RPC_PD), then the walk's */
enum { G_STAT = RPC_N_STATE, G_NIS, G_CLOSE, N_GROUPS };

static const char *const group_name[N_GROUPS] = {
    "R", "v [m/s]", "p [m]", "b_g [rad/s]", "b_a [m/s^2]", "diag P (rel)",
    "SHOE stat (rel*)", "accel NIS (rel*)", "closure p, dist [m]"};

/* Largest deviation accepted per group: absolute in the quantity's units,
 * or relative (rel[]); 5-10x the worst measured over the walk (in
 * brackets; the previous preset's run, the current one's are smaller but
 * R in double, 4.6e-14; the image prints them), so that a change of
 * rounding order passes and a lost digit does not. Float: the M4F against
 * the host float library. Double: the M7 against the host double library. */
#if SE23_CFG_DOUBLE
static const double tol[N_GROUPS] = {
    5e-13,  /* R             [7.7e-14: a preset between the two] */
    5e-13,  /* v             [4.9e-14 m/s] */
    1e-12,  /* p             [1.1e-13 m] */
    1e-14,  /* b_g           [1.1e-15 rad/s] */
    5e-13,  /* b_a           [7.8e-14 m/s^2] */
    1e-11,  /* diag P        [1.0e-12 relative] */
    3e-13,  /* SHOE stat     [4.4e-14 rel*] */
    2e-12,  /* accel NIS     [2.8e-13 rel*] */
    1e-12}; /* closure       [1.5e-13 m] */
#else
static const double tol[N_GROUPS] = {
    5e-5,   /* R             [7.3e-6] */
    5e-4,   /* v             [6.7e-5 m/s] */
    1e-3,   /* p             [1.4e-4 m] */
    1e-5,   /* b_g           [1.1e-6 rad/s] */
    5e-4,   /* b_a           [7.8e-5 m/s^2] */
    1e-2,   /* diag P        [1.1e-3 relative] */
    2e-4,   /* SHOE stat     [3.2e-5 rel*] */
    2.5e-3, /* accel NIS     [3.7e-4 rel*] */
    1e-3};  /* closure       [1.4e-4 m: p_first, p_last, distance] */
#endif
/* 1: relative; 2 (rel*): relative to the larger of the reference and the
 * test's threshold, the deviation that matters for the decision */
static const int rel[N_GROUPS] = {0, 0, 0, 0, 0, 1, 2, 2, 0};

/* se23_ins_preset_foot on the target against the host's configuration:
 * a few operations per real (products with pi/180, a square root, a cube). */
#if SE23_CFG_DOUBLE
#define PRESET_TOL 1e-12
#else
#define PRESET_TOL 1e-6
#endif


static se23_ins_t ins;              /* large: static */
static insr_check_t got[WALK_CHECK_MAX];
static double worst_run[N_GROUPS];  /* worst deviation per group, whole run */
static int worst_at[N_GROUPS];      /* ... at this sample (stat) or checkpoint */

static const rpc_groups_t groups = {N_GROUPS, group_name, tol, rel, worst_run, worst_at};

/* ---- after every sample ------------------------------------------------- */

typedef struct {
    walk_track_t track;
    se23_gauss_t prev; /* the filter's state before the current sample */
    int flags_bad, first_bad, track_bad, nis_bad;
    double call;       /* the closest call: deviation / margin, its largest */
    int call_at;
} walk_ctx_t;

/* x / m, m > 0 (else a huge ratio). */
static double ratio(double x, double m)
{
    return m > 0.0 ? x / m : 1e30;
}

/*
 * How close the target's rest tests at sample k came to flipping the
 * host's stance decision: the deviation of each test's statistic as a
 * fraction of its distance from the threshold (both relative to the
 * threshold; margins the host's), combined as the decision combines the
 * tests: at rest either test crossing flips it, in motion every failing
 * one must cross; in the alignment only SHOE decides. Below 1 at every
 * sample: no rounding of this size can have flipped a flag.
 */
static void closest_call(walk_ctx_t *w, const se23_ins_t *in, int k, double nis)
{
    const double thr = (double)walk_ref.seq.cfg.detector.threshold;
    const double r1 = (double)walk_ref.stat[k] / thr, nr = (double)walk_ref.nis[k];
    const double x1 = ratio(fabs((double)in->det.stat / thr - r1), fabs(r1 - 1.0));
    double x;
    if (nr < 0.0) {
        if (in->det.count != in->det.cfg.window || (in->status & SE23_INS_ST_ALIGNING) == 0U) {
            return; /* no decision */
        }
        x = x1;
    } else {
        const double r2 = nr / INSR_ACCEL_TEST_Q;
        const double x2 = ratio(fabs(nis / INSR_ACCEL_TEST_Q - r2), fabs(r2 - 1.0));
        const int flag = (int)((walk_ref.stance[k / 32] >> (k % 32)) & 1U);
        if (flag != 0) {
            x = x1 > x2 ? x1 : x2;
        } else if (r1 >= 1.0 && r2 >= 1.0) {
            x = x1 < x2 ? x1 : x2;
        } else {
            x = r1 >= 1.0 ? x1 : x2;
        }
    }
    if (x > w->call) {
        w->call = x;
        w->call_at = k;
    }
}

static void hook(void *ctx, const se23_ins_t *in, int k, int what, int verdict)
{
    walk_ctx_t *w = ctx;
    const int flag = (in->status & SE23_INS_ST_STATIONARY) != 0U;
    const int ref = (int)((walk_ref.stance[k / 32] >> (k % 32)) & 1U);
    double nis;
    if (what != 0) {
        return;
    }
    if (flag != ref) {
        if (w->flags_bad == 0) {
            w->first_bad = k;
        }
        ++w->flags_bad;
    }
    rpc_note(&groups, G_STAT,
             rpc_dev(&groups, G_STAT, (double)in->det.stat, (double)walk_ref.stat[k],
                     (double)in->det.cfg.threshold),
             k);
    nis = walk_nis(in, &w->prev, &walk_ref.seq.imu[k], verdict);
    if ((nis < 0.0) != (walk_ref.nis[k] < 0)) {
        ++w->nis_bad; /* evaluated on one side only */
    } else {
        if (nis >= 0.0) {
            rpc_note(&groups, G_NIS,
                     rpc_dev(&groups, G_NIS, nis, (double)walk_ref.nis[k], INSR_ACCEL_TEST_Q), k);
        }
        closest_call(w, in, k, nis);
    }
    w->track_bad += walk_track(&w->track, in, k, verdict) == 0;
    w->prev = in->g;
}

/* ---- the checks ---------------------------------------------------------- */

/* The checks of one checkpoint; returns 1 if it failed. */
static int check(int j, const insr_check_t *o, const insr_check_t *ref)
{
    const char *where;
    double w;
    const int fails = rpc_check_state(&groups, j, o, ref, &w, &where);
    printf("walk t = %6.3f s  %s  p = (%7.3f, %7.3f, %7.3f) m  %4u ZUPT %4u ZARU  worst %5.1f%% "
           "of tol (%s)  %s\n",
           (double)ref->t_ns * 1e-9,
           (ref->status & SE23_INS_ST_STATIONARY) != 0U ? "stance" : "swing ", (double)ref->p[0],
           (double)ref->p[1], (double)ref->p[2], (unsigned)ref->c[INSR_CIDX(zupt_used)],
           (unsigned)ref->c[INSR_CIDX(zaru_used)], w * 100.0, where, fails != 0 ? "FAIL" : "ok");
    return fails != 0;
}

/* The stance flags and the rest tests' statistics after every sample. */
static int check_detector(const walk_ctx_t *w)
{
    const int n = walk_ref.seq.n_imu;
    int fails = 0, gr;
    if (w->flags_bad != 0) {
        printf("FAIL stance flags: %d of %d samples differ, the first at sample %d (t = %.4f s: "
               "%d, expected %d)\n",
               w->flags_bad, n, w->first_bad,
               (double)walk_ref.seq.imu[w->first_bad].t_ns * 1e-9,
               1 - (int)((walk_ref.stance[w->first_bad / 32] >> (w->first_bad % 32)) & 1U),
               (int)((walk_ref.stance[w->first_bad / 32] >> (w->first_bad % 32)) & 1U));
        fails = 1;
    }
    if (w->nis_bad != 0) {
        printf("FAIL mean-acceleration test: decided on one side only at %d samples\n",
               w->nis_bad);
        fails = 1;
    }
    for (gr = G_STAT; gr <= G_NIS; ++gr) {
        if (!(worst_run[gr] <= tol[gr])) {
            printf("FAIL %s: %.3g at sample %d, beyond %.1e\n", group_name[gr], worst_run[gr],
                   worst_at[gr], tol[gr]);
            fails = 1;
        }
    }
    printf("stance    %d samples: flags %s  %s\n"
           "          rest tests' worst deviation %.2e (SHOE, t = %.3f s), %.2e (mean "
           "acceleration, t = %.3f s) of max(value, threshold)\n"
           "          the host's closest decision %.2e from its threshold (%s, t = %.3f s); "
           "closest call: a deviation %.3g%% of its margin (t = %.3f s)\n",
           n, w->flags_bad != 0 ? "differ" : "identical", fails != 0 ? "FAIL" : "ok",
           worst_run[G_STAT], (double)walk_ref.seq.imu[worst_at[G_STAT]].t_ns * 1e-9,
           worst_run[G_NIS], (double)walk_ref.seq.imu[worst_at[G_NIS]].t_ns * 1e-9,
           walk_ref.margin, walk_ref.margin_test,
           (double)walk_ref.seq.imu[walk_ref.margin_at].t_ns * 1e-9, 100.0 * w->call,
           (double)walk_ref.seq.imu[w->call_at].t_ns * 1e-9);
    return fails;
}

/* The loop closure against the host's (se23-walk's figures). */
static int check_closure(const walk_ctx_t *w)
{
    const walk_closure_t *c = &w->track.c, *r = &walk_ref.closure;
    double worst = 0.0;
    int fails = 0, i;
    if (w->track_bad != 0 || c->first_at != r->first_at || c->last_at != r->last_at ||
        c->phases != r->phases) {
        printf("FAIL closure: first state at sample %d, last stance from %d, %d phases (%d "
               "failed states); expected %d, %d, %d\n",
               c->first_at, c->last_at, c->phases, w->track_bad, r->first_at, r->last_at,
               r->phases);
        fails = 1;
    }
    for (i = 0; i < 3; ++i) {
        const double a =
            rpc_dev(&groups, G_CLOSE, (double)c->p_first[i], (double)r->p_first[i], 0.0);
        const double b =
            rpc_dev(&groups, G_CLOSE, (double)c->p_last[i], (double)r->p_last[i], 0.0);
        worst = a > worst ? a : worst;
        worst = b > worst ? b : worst;
    }
    {
        const double d = rpc_dev(&groups, G_CLOSE, c->dist, r->dist, 0.0);
        worst = d > worst ? d : worst;
    }
    worst_run[G_CLOSE] = worst;
    if (!(worst <= tol[G_CLOSE])) {
        printf("FAIL closure: positions or distance %.3g m off, beyond %.1e m\n", worst,
               tol[G_CLOSE]);
        fails = 1;
    }
    printf("closure   %d stance phases, %.4f m walked; closure error %.6f m 3D (%.6f "
           "horizontal, %.6f vertical) at t = %.3f s; host %.6f m  %s\n",
           c->phases, c->dist, walk_closure_err(c, 0), walk_closure_err(c, 1),
           walk_closure_err(c, 2), (double)c->t_last_ns * 1e-9, walk_closure_err(r, 0),
           fails != 0 ? "FAIL" : "ok");
    return fails;
}

/* se23_ins_preset_foot on the target against the configuration replayed. */
static int check_preset(void)
{
    static se23_ins_config_t cfg; /* static: kept off the stack */
    se23_ins_align_t al;
    se23_status_t st;
    memset(&cfg, 0, sizeof cfg);
    memset(&al, 0, sizeof al);
    st = se23_ins_preset_foot(walk_ref.rate_hz, walk_ref.lat, &cfg, &al);
    return rpc_check_preset("se23_ins_preset_foot", walk_ref.rate_hz, walk_ref.lat, st, &cfg, &al,
                            &walk_ref.seq.cfg, &walk_ref.seq.start.a, PRESET_TOL);
}

int main(void)
{
    static walk_ctx_t ctx;
    const insr_seq_t *q = &walk_ref.seq;
    int fails = 0, bad, j;
    printf("se23 walk replay (x-io foot-mounted walk, %d samples, %.1f s), %s build, against "
           "the host's %s run\n",
           q->n_imu, (double)q->imu[q->n_imu - 1].t_ns * 1e-9,
           SE23_CFG_DOUBLE ? "double" : "float", SE23_CFG_DOUBLE ? "double" : "float");
    fails += check_preset();
    if (q->n_check > WALK_CHECK_MAX) {
        printf("FAIL %d checkpoints, room for %d\n", q->n_check, WALK_CHECK_MAX);
        return 1;
    }
    walk_track_init(&ctx.track);
    bad = insr_drive(q, &ins, got, hook, &ctx);
    if (bad != 0) {
        printf("FAIL %d calls failed (setup, align, state)\n", bad);
        ++fails;
    }
    for (j = 0; j < q->n_check; ++j) {
        fails += check(j, &got[j], &q->check[j]);
    }
    fails += check_detector(&ctx);
    fails += check_closure(&ctx);
    rpc_print_worst(&groups);
    printf("%d failure(s)\n", fails);
    return fails > WALK_EXIT_MAX ? WALK_EXIT_MAX : fails;
}
