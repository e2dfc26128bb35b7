/*
 * Target test image of the navigation filter (se23/ins.h): runs the
 * recorded sequences of ins_replay_data.c (tools/target/gen_ins_replay.c:
 * 15 s of 200 Hz IMU samples at rest then in an accelerating turn, 5 Hz
 * GNSS fixes delivered 100 ms late, ZUPT/ZARU at rest, 15 states; one
 * sequence on flat Earth from se23_ins_init, one on rotating Earth from a
 * static alignment) through the filter in the build's precision, and
 * compares it at each checkpoint with the host's double run:
 *  - exactly: the time, the status word, every counter, the number of
 *    preintegrated factors taken and the last one's times, seq and count;
 *  - within the tolerances below: R, v, p, the biases, the diagonal of P
 *    (relative), and the last factor's Deltas, Delta t and diagonal of P
 *    (relative).
 * Then the stateless functions of ins.h, se23_ins_preset_foot,
 * se23_ins_preset_car and se23_ins_detector_threshold, on a few inputs
 * (two error cases per preset) against the host's double results: statuses
 * and integers exactly, reals (every field of the configuration and the
 * alignment request, insr_flatten) to PRESET_TOL relative.
 * Prints one line per checkpoint, one for the presets and the worst
 * deviation of each quantity over the run; exits with the number of failed
 * checkpoints and calls (capped at INSR_EXIT_MAX; 254/255 are the port's
 * assert/fault codes).
 *
 * Tolerances. Double (Cortex-M7): the same code and inputs as the host
 * double run; they differ only by fused multiply-adds (the target library
 * is built with -ffp-contract=fast) and newlib's libm against glibc's, a
 * few ulps per operation that the filter's updates keep from growing:
 * measured at most 2.8e-13 m in position, 3.7e-15 in R and 9.0e-13
 * relative in the diagonal of P, so 1e-9 (absolute in the quantity's
 * units, relative for covariances) leaves three orders of magnitude and
 * still catches any real difference of code or inputs. Float (Cortex-M4F):
 * the float build's own rounding over 15 s (the inputs are the same
 * floats), measured on these sequences and set at ~5x the worst (the table
 * below). The counters, the status and the factor bookkeeping must match
 * exactly in both: the generator guarantees that no decision (the rest
 * tests, the GNSS gate) lies within a factor 2 of its threshold, so no
 * rounding can flip one.
 */
#include <stdio.h>
#include <string.h>

#include "ins_replay.h"

#define INSR_EXIT_MAX 200

enum { G_R, G_V, G_P, G_BG, G_BA, G_PD, G_FR, G_FV, G_FX, G_FDT, G_FP, N_GROUPS };

static const char *const group_name[N_GROUPS] = {
    "R", "v [m/s]", "p [m]", "b_g [rad/s]", "b_a [m/s^2]", "diag P (rel)",
    "factor dR", "factor dV [m/s]", "factor dX [m]", "factor dt [s]", "factor diag P (rel)"};

/* Largest deviation accepted per group: absolute in the quantity's units,
 * or relative (rel[]). Float: ~5x the worst measured over this run on the
 * M4F (in brackets; the image prints them), so that a change of rounding
 * order passes and a lost digit does not. Double: the file comment. */
#if SE23_CFG_DOUBLE
static const double tol[N_GROUPS] = {1e-9, 1e-9, 1e-9, 1e-9, 1e-9, 1e-9,
                                     1e-9, 1e-9, 1e-9, 1e-9, 1e-9};
#else
static const double tol[N_GROUPS] = {
    1e-4,   /* R             [2.0e-5] */
    2.5e-4, /* v             [5.3e-5 m/s] */
    1e-2,   /* p             [1.7e-3 m, at ~130 m from the origin] */
    3e-7,   /* b_g           [6.3e-8 rad/s] */
    1.5e-4, /* b_a           [3.3e-5 m/s^2] */
    2e-2,   /* diag P        [2.3e-3 relative] */
    1.2e-6, /* factor dR     [2.4e-7] */
    8e-5,   /* factor dV     [1.7e-5 m/s] */
    2e-5,   /* factor dX     [4.1e-6 m] */
    4e-6,   /* factor dt     [7.8e-7 s, a sum of 100-200 float dt] */
    3e-5};  /* factor diag P [6.3e-6 relative] */
#endif
static const int rel[N_GROUPS] = {0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};


static se23_ins_t ins;                 /* large: static */
static insr_check_t got[16];
static double worst_run[N_GROUPS];     /* worst deviation per group, whole run */

/* Worst deviation (as a fraction of tol) of n reals of group gr; updates
 * the run's worst and *where. */
static double compare(int gr, const se23_real_t *a, const se23_real_t *b, int n, double worst,
                      const char **where)
{
    int i;
    for (i = 0; i < n; ++i) {
        const double ref = (double)b[i];
        double d = (double)a[i] - ref;
        d = d < 0.0 ? -d : d;
        if (rel[gr] != 0) {
            d = ref != 0.0 ? d / (ref < 0.0 ? -ref : ref) : (d != 0.0 ? 1e30 : 0.0);
        }
        if (!(d == d)) {
            d = 1e30; /* NaN */
        }
        if (d > worst_run[gr]) {
            worst_run[gr] = d;
        }
        if (d / tol[gr] > worst) {
            worst = d / tol[gr];
            *where = group_name[gr];
        }
    }
    return worst;
}

/* The checks of one checkpoint; returns 1 if it failed. */
static int check(const insr_seq_t *s, const insr_check_t *o, const insr_check_t *ref)
{
    const char *where = "-";
    double w = 0.0;
    int fails = 0, i;
    if (o->t_ns != ref->t_ns || o->status != ref->status || o->factors != ref->factors) {
        printf("FAIL %s sample %d: t %lld ns, status 0x%03x, %d factors; expected %lld, "
               "0x%03x, %d\n",
               s->name, ref->at, (long long)o->t_ns, (unsigned)o->status, o->factors,
               (long long)ref->t_ns, (unsigned)ref->status, ref->factors);
        ++fails;
    }
    for (i = 0; i < INSR_N_COUNTERS; ++i) {
        if (o->c[i] != ref->c[i]) {
            printf("FAIL %s sample %d: counter %s = %u, expected %u\n", s->name, ref->at,
                   insr_counter_name[i], (unsigned)o->c[i], (unsigned)ref->c[i]);
            ++fails;
        }
    }
    w = compare(G_R, o->R, ref->R, 9, w, &where);
    w = compare(G_V, o->v, ref->v, 3, w, &where);
    w = compare(G_P, o->p, ref->p, 3, w, &where);
    w = compare(G_BG, o->bg, ref->bg, 3, w, &where);
    w = compare(G_BA, o->ba, ref->ba, 3, w, &where);
    w = compare(G_PD, o->P, ref->P, 15, w, &where);
    if (ref->factors > 0) {
        const insr_factor_t *f = &o->fac, *g = &ref->fac;
        if (f->t0_ns != g->t0_ns || f->t1_ns != g->t1_ns || f->seq0 != g->seq0 || f->n != g->n) {
            printf("FAIL %s sample %d: factor %lld..%lld ns, seq0 %lld, %u samples; expected "
                   "%lld..%lld, %lld, %u\n",
                   s->name, ref->at, (long long)f->t0_ns, (long long)f->t1_ns,
                   (long long)f->seq0, (unsigned)f->n, (long long)g->t0_ns, (long long)g->t1_ns,
                   (long long)g->seq0, (unsigned)g->n);
            ++fails;
        }
        w = compare(G_FR, f->dR, g->dR, 9, w, &where);
        w = compare(G_FV, f->dV, g->dV, 3, w, &where);
        w = compare(G_FX, f->dX, g->dX, 3, w, &where);
        w = compare(G_FDT, &f->dt, &g->dt, 1, w, &where);
        w = compare(G_FP, f->P, g->P, 9, w, &where);
    }
    if (!(w <= 1.0)) {
        printf("FAIL %s sample %d: %s beyond its tolerance (%.3g x tol)\n", s->name, ref->at,
               where, w);
        ++fails;
    }
    w = w < 99.99 ? w : 99.99;
    printf("%-9s t = %6.3f s  %2u fixes (%2u late) %3u ZUPT  worst %5.1f%% of tol (%s)  %s\n",
           s->name, (double)ref->t_ns * 1e-9, (unsigned)ref->c[INSR_CIDX(gnss_used)],
           (unsigned)ref->c[INSR_CIDX(gnss_delayed)], (unsigned)ref->c[INSR_CIDX(zupt_used)], w * 100.0, where, fails != 0 ? "FAIL" : "ok");
    return fails != 0;
}

/* Relative deviation of the presets' and the threshold's reals from the
 * host's double values: a handful of operations each (products with
 * pi/180, a square root, a cube), so a few ulps of the build's precision
 * (measured 2.4e-7 in float, 6.5e-16 in double). */
#if SE23_CFG_DOUBLE
#define PRESET_TOL 1e-12
#else
#define PRESET_TOL 1e-6
#endif

/* se23_ins_preset_foot, se23_ins_preset_car and se23_ins_detector_threshold
 * against the host; returns the number of failed calls. */
static int check_presets(void)
{
    static se23_ins_config_t cfg; /* static: kept off the stack */
    se23_ins_align_t al;
    double worst = 0.0;
    int fails = 0, same = 1, n_car = 0, k;
    for (k = 0; k < insr_n_presets; ++k) {
        const insr_preset_t *p = &insr_presets[k];
        const char *name = p->car != 0 ? "se23_ins_preset_car" : "se23_ins_preset_foot";
        int bad, st;
        memset(&cfg, 0, sizeof cfg);
        memset(&al, 0, sizeof al);
        if (p->car != 0) {
            st = (int)se23_ins_preset_car(p->rate_hz, p->lat, &cfg, &al);
            ++n_car;
        } else {
            st = (int)se23_ins_preset_foot(p->rate_hz, p->lat, &cfg, &al);
        }
        if (st != p->status) {
            printf("FAIL %s(%g, %g): status %d, expected %d\n", name, (double)p->rate_hz,
                   (double)p->lat, st, p->status);
            ++fails;
            continue;
        }
        if (st != SE23_OK) {
            continue;
        }
        bad = insr_config_diff(&cfg, &al, &p->cfg, &p->align, PRESET_TOL, &worst, &same);
        if (bad != 0) {
            printf("FAIL %s(%g, %g): %d field(s) differ\n", name, (double)p->rate_hz,
                   (double)p->lat, bad);
            ++fails;
        }
    }
    for (k = 0; k < insr_n_thresholds; ++k) {
        const insr_threshold_t *t = &insr_thresholds[k];
        const se23_real_t thr = se23_ins_detector_threshold(t->window, t->z);
        const double d = insr_rel_dev(thr, t->threshold);
        worst = d > worst ? d : worst;
        if (!(d <= PRESET_TOL)) {
            printf("FAIL se23_ins_detector_threshold(%d, %g) = %.9g, expected %.17g\n",
                   t->window, (double)t->z, (double)thr, (double)t->threshold);
            ++fails;
        }
    }
    printf("presets   %d se23_ins_preset_foot, %d se23_ins_preset_car, %d "
           "se23_ins_detector_threshold calls  worst %.2e relative (tol %.0e)  %s\n",
           insr_n_presets - n_car, n_car, insr_n_thresholds, worst, PRESET_TOL,
           fails != 0 ? "FAIL" : "ok");
    return fails;
}

int main(void)
{
    int fails = 0, s, j;
    printf("se23 navigation filter replay, %s build, against the host's double run\n",
           SE23_CFG_DOUBLE ? "double" : "float");
    for (s = 0; s < insr_n_seqs; ++s) {
        const insr_seq_t *q = &insr_seqs[s];
        int bad;
        if (q->n_check > (int)(sizeof got / sizeof got[0])) {
            printf("FAIL %s: %d checkpoints, room for %d\n", q->name, q->n_check,
                   (int)(sizeof got / sizeof got[0]));
            ++fails;
            continue;
        }
        bad = insr_drive(q, &ins, got, NULL, NULL);
        if (bad != 0) {
            printf("FAIL %s: %d calls failed (setup, init/align, state)\n", q->name, bad);
            ++fails;
        }
        for (j = 0; j < q->n_check; ++j) {
            fails += check(q, &got[j], &q->check[j]);
        }
    }
    fails += check_presets();
    printf("worst deviation over the run (tolerance):\n");
    for (j = 0; j < N_GROUPS; ++j) {
        printf("  %-20s %9.2e  (tol %.1e%s: %5.1f%%)\n", group_name[j], worst_run[j], tol[j],
               rel[j] != 0 ? ", relative" : "", 100.0 * worst_run[j] / tol[j]);
    }
    printf("%d failure(s)\n", fails);
    return fails > INSR_EXIT_MAX ? INSR_EXIT_MAX : fails;
}
