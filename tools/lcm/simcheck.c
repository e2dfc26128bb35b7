/*
 * se23-simcheck: checks a se23-sim log (file://) against what its GNSS
 * lever arm, GNSS latency and stationary start must produce, from the
 * messages alone (independent of the simulator's code):
 *
 *   lever     every fix at t, per axis: |p_fix - (p + R l)| <= --tol-p + 6 sigma_p
 *             and |v_fix - (v + R (w_nb_b x l))| <= --tol-v + 6 sigma_v, with
 *             (R, v, p) the truth at t, w_nb_b = omega - R^T w_ie_n from the
 *             IMU sample ending at t (exact for --imu perfect) and SIM_INFO's
 *             w_ie_n, sigma the fix's own (sharp with --gnss-sigma-p/v 1e-6);
 *   latency   every fix at t comes right after the first IMU sample at or
 *             after t + latency (the one before it is earlier than that);
 *             fixes are in seq order, none missing: the next fix, one
 *             period later, would not have been due by the last sample;
 *   rest      with --stationary S: every truth at t <= S has |v| and
 *             |p - p(0)| below --tol-rest and R = R(0) (angle below
 *             --tol-rest), and the vehicle moves after S (max |v| > 1e-3 m/s,
 *             not for the static scenario);
 *   smooth    between consecutive truths |dv| <= --max-accel * dt;
 *   misalign  with --accel-misalign RX,RY,RZ [deg] (the static scenario,
 *             --imu perfect): every accelerometer sample is M R^T (-g_n),
 *             M = exp(m^) by Rodrigues' formula written out here, within
 *             --tol-v, R the first truth and g_n SIM_INFO's;
 *   info      SIM_INFO records the lever arm, latency, rest time and
 *             accelerometer misalignment checked.
 *
 * Prints one line per check, "FAIL <check>: ..." for each failure, then
 * SIMCHECK PASSED (exit 0) or SIMCHECK FAILED (exit 1); 2: bad usage or an
 * unreadable log.
 *
 * usage: se23-simcheck [--lever X,Y,Z] [--latency S] [--stationary S]
 *                      [--accel-misalign RX,RY,RZ] [--tol-p M] [--tol-v MPS]
 *                      [--tol-rest X] [--max-accel A] LOG
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "harness.h"
#include "ldmath.h"
#include "logfile.h"
#include "se23lcm_gnss_fix.h"
#include "se23lcm_imu_sample.h"
#include "se23lcm_sim_info.h"
#include "se23lcm_truth.h"

typedef struct {
    double lever[3];
    double misalign[3]; /* [deg] */
    double latency, stationary;
    double tol_p, tol_v, tol_rest, max_accel;
} chk_opts_t;

/* A fix with the times of the two IMU samples published last before it. */
typedef struct {
    se23lcm_gnss_fix m;
    int64_t imu_last_ns, imu_prev_ns; /* -1: none */
} fix_t;

typedef struct {
    se23lcm_truth *truth;
    se23lcm_imu_sample *imu;
    fix_t *fix;
    size_t n_truth, n_imu, n_fix, cap_truth, cap_imu, cap_fix;
    se23lcm_sim_info info;
    int have_info;
    int64_t n_bad;
} chk_data_t;

static int fails;

static void fail(const char *what, const char *fmt, ...)
{
    va_list ap;
    va_start(ap, fmt);
    printf("FAIL %s: ", what);
    vprintf(fmt, ap);
    printf("\n");
    va_end(ap);
    fails++;
}

static void usage(FILE *f)
{
    fprintf(f, "usage: se23-simcheck [--lever X,Y,Z] [--latency S] [--stationary S]\n"
               "                     [--accel-misalign RX,RY,RZ] [--tol-p M] [--tol-v MPS]\n"
               "                     [--tol-rest X] [--max-accel A] LOG\n"
               "  defaults: lever 0,0,0, latency 0, stationary 0, tol-p 2e-5 m,\n"
               "  tol-v 2e-5 m/s (each plus 6 sigma of the fix), tol-rest 1e-9 (m/s, m, rad),\n"
               "  max-accel 10 m/s^2\n");
}

/* Room for one more element of size sz in *arr (n used, *cap allocated). */
static void *grow(void **arr, size_t n, size_t *cap, size_t sz)
{
    if (n == *cap) {
        size_t c = *cap ? 2 * *cap : 1024;
        void *p = realloc(*arr, c * sz);
        if (p == NULL) {
            return NULL;
        }
        *arr = p;
        *cap = c;
    }
    return (char *)*arr + n * sz;
}

static int read_log(const char *path, chk_data_t *d)
{
    logfile_t lf;
    logfile_event_t ev;
    int64_t last = -1, prev = -1;
    int oom = 0;
    if (logfile_open(&lf, path, "se23-simcheck") != 0) {
        return -1;
    }
    while (!oom && logfile_next(&lf, &ev)) {
        if (strcmp(ev.channel, HARNESS_CH_IMU) == 0) {
            se23lcm_imu_sample *s = grow((void **)&d->imu, d->n_imu, &d->cap_imu, sizeof *s);
            if (s == NULL) {
                oom = 1;
            } else if (se23lcm_imu_sample_decode(ev.data, 0, ev.datalen, s) < 0) {
                d->n_bad++;
            } else {
                prev = last;
                last = s->t_ns;
                d->n_imu++;
            }
        } else if (strcmp(ev.channel, HARNESS_CH_TRUTH) == 0) {
            se23lcm_truth *t = grow((void **)&d->truth, d->n_truth, &d->cap_truth, sizeof *t);
            if (t == NULL) {
                oom = 1;
            } else if (se23lcm_truth_decode(ev.data, 0, ev.datalen, t) < 0) {
                d->n_bad++;
            } else {
                d->n_truth++;
            }
        } else if (strcmp(ev.channel, HARNESS_CH_GNSS) == 0) {
            fix_t *f = grow((void **)&d->fix, d->n_fix, &d->cap_fix, sizeof *f);
            if (f == NULL) {
                oom = 1;
            } else if (se23lcm_gnss_fix_decode(ev.data, 0, ev.datalen, &f->m) < 0) {
                d->n_bad++;
            } else {
                f->imu_last_ns = last;
                f->imu_prev_ns = prev;
                d->n_fix++;
            }
        } else if (strcmp(ev.channel, HARNESS_CH_SIM_INFO) == 0) {
            if (se23lcm_sim_info_decode(ev.data, 0, ev.datalen, &d->info) < 0) {
                d->n_bad++;
            } else {
                d->have_info = 1;
            }
        }
    }
    if (lf.bytes_skipped > 0) {
        d->n_bad++;
    }
    logfile_close(&lf);
    if (oom) {
        fprintf(stderr, "se23-simcheck: out of memory\n");
        return -1;
    }
    return 0;
}

/* Index of the truth at t_ns == t (they are in time order), or -1. */
static long find_truth(const chk_data_t *d, int64_t t)
{
    size_t lo = 0, hi = d->n_truth;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (d->truth[mid].t_ns < t) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    return (lo < d->n_truth && d->truth[lo].t_ns == t) ? (long)lo : -1;
}

/* Index of the IMU sample ending at t (in time order), or -1. */
static long find_imu(const chk_data_t *d, int64_t t)
{
    size_t lo = 0, hi = d->n_imu;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (d->imu[mid].t_ns < t) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    return (lo < d->n_imu && d->imu[lo].t_ns == t) ? (long)lo : -1;
}

static void check_lever(const chk_opts_t *o, const chk_data_t *d)
{
    ld_vec3_t l = ld_vec3_from(o->lever), w_ie = ld_vec3_from(d->info.w_ie_n);
    ld_t ep = 0.0L, ev = 0.0L, off = 0.0L, qp = 0.0L, qv = 0.0L; /* q: residual / bound */
    size_t k;
    int i;
    for (k = 0; k < d->n_fix; k++) {
        const se23lcm_gnss_fix *f = &d->fix[k].m;
        long it = find_truth(d, f->t_ns), is = find_imu(d, f->t_ns);
        if (it < 0 || is < 0) {
            fail("lever", "no truth or IMU sample at the time of fix %lld (t = %.9f s)",
                 (long long)f->seq, (double)f->t_ns * 1e-9);
            return;
        } else {
            ld_mat3_t R = ld_mat3_from(d->truth[it].R_nb);
            ld_vec3_t w = ld_vec3_from(d->imu[is].omega);
            ld_vec3_t w_ie_b = ld_tmul_v(&R, &w_ie);
            ld_vec3_t w_nb = ld_sub(&w, &w_ie_b);
            ld_vec3_t wxl = ld_cross(&w_nb, &l);
            ld_vec3_t dp = ld_mul_v(&R, &l), dv = ld_mul_v(&R, &wxl);
            for (i = 0; i < 3; i++) {
                ld_t rp = (ld_t)f->p_n[i] - ((ld_t)d->truth[it].p_n[i] + dp.v[i]);
                ld_t rv = (ld_t)f->v_n[i] - ((ld_t)d->truth[it].v_n[i] + dv.v[i]);
                ld_t o_i = (ld_t)f->p_n[i] - (ld_t)d->truth[it].p_n[i];
                ep = fmaxl(ep, fabsl(rp));
                ev = fmaxl(ev, fabsl(rv));
                qp = fmaxl(qp, fabsl(rp) / ((ld_t)o->tol_p + 6.0L * (ld_t)f->sigma_p[i]));
                qv = fmaxl(qv, fabsl(rv) / ((ld_t)o->tol_v + 6.0L * (ld_t)f->sigma_v[i]));
                off = fmaxl(off, fabsl(o_i));
            }
        }
    }
    printf("lever: %zu fixes; max |p_fix - (p + R l)| %.3g m (%.3g of its bound), "
           "max |v_fix - (v + R (w x l))| %.3g m/s (%.3g of its bound); max |p_fix - p| %.3g m\n",
           d->n_fix, (double)ep, (double)qp, (double)ev, (double)qv, (double)off);
    if (!(qp <= 1.0L)) {
        fail("lever position", "a residual %.3g times its bound (--tol-p %g m + 6 sigma)",
             (double)qp, o->tol_p);
    }
    if (!(qv <= 1.0L)) {
        fail("lever velocity", "a residual %.3g times its bound (--tol-v %g m/s + 6 sigma)",
             (double)qv, o->tol_v);
    }
}

static void check_latency(const chk_opts_t *o, const chk_data_t *d)
{
    int64_t lat = llround(o->latency * 1e9), worst = 0;
    int64_t last_imu = d->n_imu > 0 ? d->imu[d->n_imu - 1].t_ns : -1;
    size_t k, late = 0, early = 0;
    for (k = 0; k < d->n_fix; k++) {
        const fix_t *f = &d->fix[k];
        int64_t due = f->m.t_ns + lat;
        if (f->m.seq != (int64_t)k + 1 || (k > 0 && f->m.t_ns <= d->fix[k - 1].m.t_ns)) {
            fail("latency order", "fix %lld out of sequence (expected %zu)", (long long)f->m.seq,
                 k + 1);
            return;
        }
        if (f->imu_last_ns < due) {
            early++;
        } else if (f->imu_prev_ns >= due) {
            late++;
        }
        if (f->imu_last_ns - f->m.t_ns > worst) {
            worst = f->imu_last_ns - f->m.t_ns;
        }
    }
    printf("latency: %zu fixes; published after the sample at t_fix + %.6f s: %zu early, "
           "%zu late; largest delay %.6f s; last fix %.3f s, last sample %.3f s\n",
           d->n_fix, o->latency, early, late, (double)worst * 1e-9,
           d->n_fix ? (double)d->fix[d->n_fix - 1].m.t_ns * 1e-9 : 0.0,
           (double)last_imu * 1e-9);
    if (early > 0) {
        fail("latency early", "%zu fixes published before the IMU sample at t + %.6f s", early,
             o->latency);
    }
    if (late > 0) {
        fail("latency late", "%zu fixes published after a later IMU sample than t + %.6f s",
             late, o->latency);
    }
    if (d->n_fix >= 2) {
        int64_t period = d->fix[1].m.t_ns - d->fix[0].m.t_ns;
        if (d->fix[d->n_fix - 1].m.t_ns + period + lat <= last_imu) {
            fail("latency missing", "a fix at %.3f s was due by the last sample at %.3f s",
                 (double)(d->fix[d->n_fix - 1].m.t_ns + period) * 1e-9,
                 (double)last_imu * 1e-9);
        }
    }
}

static void check_rest(const chk_opts_t *o, const chk_data_t *d)
{
    int64_t rest = llround(o->stationary * 1e9);
    ld_mat3_t R0 = ld_mat3_from(d->truth[0].R_nb);
    ld_t vmax = 0.0L, pmax = 0.0L, amax = 0.0L, vafter = 0.0L;
    size_t k, n_rest = 0;
    int i;
    for (k = 0; k < d->n_truth; k++) {
        const se23lcm_truth *t = &d->truth[k];
        ld_t v = 0.0L, p = 0.0L;
        for (i = 0; i < 3; i++) {
            v = fmaxl(v, fabsl((ld_t)t->v_n[i]));
            p = fmaxl(p, fabsl((ld_t)t->p_n[i] - (ld_t)d->truth[0].p_n[i]));
        }
        if (t->t_ns <= rest) {
            ld_mat3_t R = ld_mat3_from(t->R_nb);
            ld_mat3_t E = ld_mul_tn(&R0, &R);
            ld_vec3_t e = ld_log(&E);
            n_rest++;
            vmax = fmaxl(vmax, v);
            pmax = fmaxl(pmax, p);
            amax = fmaxl(amax, ld_norm(&e));
        } else {
            vafter = fmaxl(vafter, v);
        }
    }
    printf("rest: %zu truths at t <= %.3f s: max |v| %.3g m/s, max |p - p0| %.3g m, "
           "max angle to R0 %.3g rad (tol %.3g); max |v| after: %.3g m/s\n",
           n_rest, o->stationary, (double)vmax, (double)pmax, (double)amax, o->tol_rest,
           (double)vafter);
    if (n_rest < 2) {
        fail("rest", "%zu truth messages in the rest phase of %.3f s", n_rest, o->stationary);
    }
    if (!(vmax <= (ld_t)o->tol_rest) || !(pmax <= (ld_t)o->tol_rest) ||
        !(amax <= (ld_t)o->tol_rest)) {
        fail("rest moving", "max |v| %.3g m/s, |p - p0| %.3g m, angle %.3g rad: not all below %.3g",
             (double)vmax, (double)pmax, (double)amax, o->tol_rest);
    }
    if (d->info.scenario != 0 && !(vafter > 1e-3L)) {
        fail("rest never ends", "max |v| %.3g m/s after %.3f s", (double)vafter, o->stationary);
    }
}

static void check_smooth(const chk_opts_t *o, const chk_data_t *d)
{
    ld_t worst = 0.0L;
    size_t k;
    int i;
    for (k = 1; k < d->n_truth; k++) {
        ld_t dt = (ld_t)(d->truth[k].t_ns - d->truth[k - 1].t_ns) * 1e-9L;
        for (i = 0; i < 3; i++) {
            ld_t a = fabsl((ld_t)d->truth[k].v_n[i] - (ld_t)d->truth[k - 1].v_n[i]) / dt;
            worst = fmaxl(worst, a);
        }
    }
    printf("smooth: largest |dv/dt| between truths %.3f m/s^2 (max %.3f)\n", (double)worst,
           o->max_accel);
    if (!(worst <= (ld_t)o->max_accel)) {
        fail("smooth", "|dv/dt| %.3f m/s^2 above %.3f", (double)worst, o->max_accel);
    }
}

/* The rotation vector of --accel-misalign in radians. */
static void misalign_rad(const chk_opts_t *o, double rv[3])
{
    int i;
    for (i = 0; i < 3; i++) {
        rv[i] = o->misalign[i] * (3.14159265358979323846 / 180.0);
    }
}

static void check_misalign(const chk_opts_t *o, const chk_data_t *d)
{
    /* M = I + sin(t)/t m^ + (1 - cos(t))/t^2 m^2, t = |m| (Rodrigues) */
    double m[3], M[3][3], u[3], e = 0.0;
    const double *Rt = d->truth[0].R_nb, *g = d->info.g_n;
    double t, a, b;
    size_t k;
    int i, j;
    misalign_rad(o, m);
    t = sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    a = t > 0.0 ? sin(t) / t : 1.0;
    b = t > 0.0 ? (1.0 - cos(t)) / (t * t) : 0.5;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            M[i][j] = (i == j ? 1.0 - b * (t * t) : 0.0) + b * m[i] * m[j];
        }
    }
    M[0][1] -= a * m[2];
    M[0][2] += a * m[1];
    M[1][0] += a * m[2];
    M[1][2] -= a * m[0];
    M[2][0] -= a * m[1];
    M[2][1] += a * m[0];
    for (i = 0; i < 3; i++) { /* u = M R^T (-g) */
        u[i] = 0.0;
        for (j = 0; j < 3; j++) {
            u[i] -= (M[i][0] * Rt[3 * j] + M[i][1] * Rt[3 * j + 1] + M[i][2] * Rt[3 * j + 2]) * g[j];
        }
    }
    for (k = 0; k < d->n_imu; k++) {
        for (i = 0; i < 3; i++) {
            e = fmax(e, fabs(d->imu[k].accel[i] - u[i]));
        }
    }
    printf("misalign: %zu samples, max |f - M R^T (-g)| %.3g m/s^2 (tol %.3g)\n", d->n_imu, e,
           o->tol_v);
    if (d->info.scenario != 0 || d->info.imu_profile != 0) {
        fail("misalign", "needs the static scenario and --imu perfect");
    } else if (!(e <= o->tol_v)) {
        fail("misalign", "the accelerometer is not the rotated gravity");
    }
}

static void check_info(const chk_opts_t *o, const chk_data_t *d)
{
    const se23lcm_sim_info *m = &d->info;
    int i, ok = m->gnss_latency_s == o->latency && m->stationary_s == o->stationary;
    double rv[3];
    misalign_rad(o, rv);
    for (i = 0; i < 3; i++) {
        ok = ok && m->lever_b[i] == o->lever[i];
        ok = ok && fabs(m->accel_misalign_b[i] - rv[i]) <= 1e-15;
    }
    printf("info: lever %g,%g,%g m, latency %g s, stationary %g s, ramp %g s, "
           "accelerometer rotation %g,%g,%g rad\n",
           m->lever_b[0], m->lever_b[1], m->lever_b[2], m->gnss_latency_s, m->stationary_s,
           m->ramp_s, m->accel_misalign_b[0], m->accel_misalign_b[1], m->accel_misalign_b[2]);
    if (!ok) {
        fail("info", "SIM_INFO does not record the options checked");
    }
}

int main(int argc, char **argv)
{
    const double inf = HUGE_VAL;
    chk_opts_t o;
    chk_data_t d;
    const char **pos = calloc((size_t)argc, sizeof *pos);
    int n_pos = 0, rc;
    const harness_opt_t opts[] = {
        {"--lever", HOPT_VEC3, o.lever, -inf, inf, NULL},
        {"--latency", HOPT_DOUBLE, &o.latency, 0.0, inf, NULL},
        {"--stationary", HOPT_DOUBLE, &o.stationary, 0.0, inf, NULL},
        {"--accel-misalign", HOPT_VEC3, o.misalign, -inf, inf, NULL},
        {"--tol-p", HOPT_DOUBLE, &o.tol_p, 0.0, inf, NULL},
        {"--tol-v", HOPT_DOUBLE, &o.tol_v, 0.0, inf, NULL},
        {"--tol-rest", HOPT_DOUBLE, &o.tol_rest, 0.0, inf, NULL},
        {"--max-accel", HOPT_DOUBLE, &o.max_accel, 0.0, inf, NULL},
    };
    memset(&o, 0, sizeof o);
    memset(&d, 0, sizeof d);
    o.tol_p = 2e-5;
    o.tol_v = 2e-5;
    o.tol_rest = 1e-9;
    o.max_accel = 10.0;
    if (pos == NULL ||
        harness_parse_opts("se23-simcheck", argc, argv, opts, (int)(sizeof opts / sizeof opts[0]),
                           usage, pos, &n_pos) != 0 ||
        n_pos != 1) {
        usage(stderr);
        free(pos);
        return 2;
    }
    rc = read_log(pos[0], &d);
    free(pos);
    if (rc != 0) {
        free(d.truth);
        free(d.imu);
        free(d.fix);
        return 2;
    }
    if (!d.have_info || d.n_truth == 0 || d.n_imu == 0 || d.n_bad > 0) {
        printf("FAIL log: SIM_INFO %s, %zu truths, %zu IMU samples, %lld bad messages\n",
               d.have_info ? "present" : "missing", d.n_truth, d.n_imu, (long long)d.n_bad);
        fails++;
    } else {
        check_info(&o, &d);
        check_lever(&o, &d);
        check_latency(&o, &d);
        if (o.stationary > 0.0) {
            check_rest(&o, &d);
        }
        check_smooth(&o, &d);
        if (o.misalign[0] != 0.0 || o.misalign[1] != 0.0 || o.misalign[2] != 0.0) {
            check_misalign(&o, &d);
        }
    }
    free(d.truth);
    free(d.imu);
    free(d.fix);
    printf(fails ? "SIMCHECK FAILED\n" : "SIMCHECK PASSED\n");
    return fails ? 1 : 0;
}
