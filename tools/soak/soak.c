/*
 * se23-soak: a long run of the library's filter (se23/ins.h, 15 states,
 * rotating Earth, 200 Hz) on a bounded random motion, to show that its
 * state stays valid by construction over millions of steps: it reports the
 * worst |R^T R - I| (largest entry), the smallest eigenvalue of P (Jacobi,
 * in double, relative to the largest), every non-finite value, the
 * library's filter_errors, and a hash of the final state for the
 * determinism check (two runs of the same seed must print the same hash).
 *
 *   se23-soak [--steps N] [--aided on|off] [--seed S] [--check-every K]
 *
 * Aided: a GNSS position fix (1-sigma 1 m) at the filter's own position
 * (plus noise) every second keeps P bounded; unaided: P grows for the
 * whole run. Built twice, se23-soak (double) and se23-soak-float. Exit
 * status 1 if a value went non-finite, P lost positive semidefiniteness
 * beyond rounding (smallest eigenvalue below -1e-6 of the largest), R left
 * SO(3) beyond SE23_CFG_ROT_TOL, or a library step failed.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../lcm/harness.h"
#include "se23/ins.h"

#define RATE 200.0
#define DT_NS 5000000LL

typedef struct {
    uint64_t s;
} rng_t;

/* xorshift64*: uniform in [-1, 1) */
static double uni(rng_t *r)
{
    r->s ^= r->s >> 12;
    r->s ^= r->s << 25;
    r->s ^= r->s >> 27;
    return (double)((r->s * 2685821657736338717ULL) >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

/* Smallest and largest eigenvalue of the n x n symmetric A (row stride 15),
 * cyclic Jacobi in double. */
static void eig_range(const se23_real_t *P, int n, double *lo, double *hi)
{
    double A[15][15];
    int i, j, k, sweep;
    for (i = 0; i < n; i++) {
        for (j = 0; j < n; j++) {
            A[i][j] = (double)P[15 * i + j];
        }
    }
    for (sweep = 0; sweep < 50; sweep++) {
        double off = 0.0;
        for (i = 0; i < n; i++) {
            for (j = i + 1; j < n; j++) {
                off += A[i][j] * A[i][j];
            }
        }
        if (off < 1e-300) {
            break;
        }
        for (i = 0; i < n; i++) {
            for (j = i + 1; j < n; j++) {
                double th, t, c, s;
                if (fabs(A[i][j]) < 1e-300) {
                    continue;
                }
                th = (A[j][j] - A[i][i]) / (2.0 * A[i][j]);
                t = (th >= 0 ? 1.0 : -1.0) / (fabs(th) + sqrt(th * th + 1.0));
                c = 1.0 / sqrt(t * t + 1.0);
                s = t * c;
                for (k = 0; k < n; k++) {
                    const double aki = A[k][i], akj = A[k][j];
                    A[k][i] = c * aki - s * akj;
                    A[k][j] = s * aki + c * akj;
                }
                for (k = 0; k < n; k++) {
                    const double aik = A[i][k], ajk = A[j][k];
                    A[i][k] = c * aik - s * ajk;
                    A[j][k] = s * aik + c * ajk;
                }
            }
        }
    }
    *lo = *hi = A[0][0];
    for (i = 1; i < n; i++) {
        *lo = fmin(*lo, A[i][i]);
        *hi = fmax(*hi, A[i][i]);
    }
}

static double rot_err(const se23_mat3_t *R)
{
    double worst = 0.0;
    int i, j, k;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            double s = (i == j) ? -1.0 : 0.0;
            for (k = 0; k < 3; k++) {
                s += (double)R->m[k][i] * (double)R->m[k][j];
            }
            worst = fmax(worst, fabs(s));
        }
    }
    return worst;
}

/* FNV-1a over bytes, continuing from h. */
static uint64_t fnv(uint64_t h, const void *p, size_t n)
{
    const unsigned char *b = p;
    size_t i;
    for (i = 0; i < n; i++) {
        h = (h ^ b[i]) * 1099511628211ULL;
    }
    return h;
}

/* Hash of the state's values (no padding bytes). */
static uint64_t state_hash(const se23_gauss_t *g)
{
    uint64_t h = 1469598103934665603ULL;
    h = fnv(h, &g->T, sizeof g->T);
    h = fnv(h, &g->b_g, sizeof g->b_g);
    h = fnv(h, &g->b_a, sizeof g->b_a);
    return fnv(h, g->P.m, sizeof g->P.m);
}

static int all_finite(const se23_gauss_t *g)
{
    int i;
    for (i = 0; i < 225; i++) {
        if (!isfinite((double)g->P.m[i])) {
            return 0;
        }
    }
    for (i = 0; i < 3; i++) {
        if (!isfinite((double)g->T.v.v[i]) || !isfinite((double)g->T.p.v[i]) ||
            !isfinite((double)g->b_g.v[i]) || !isfinite((double)g->b_a.v[i]) ||
            !isfinite((double)g->T.R.m[i][0]) || !isfinite((double)g->T.R.m[i][1]) ||
            !isfinite((double)g->T.R.m[i][2])) {
            return 0;
        }
    }
    return 1;
}

static void usage(FILE *f)
{
    fprintf(f, "usage: se23-soak [--steps N] [--aided on|off] [--seed S] [--check-every K]\n");
}

int main(int argc, char **argv)
{
    static se23_ins_t ins;
    static se23_gauss_t g, out;
    int64_t steps = 10000000, seed = 1, every = 100000, k;
    int aided = 1;
    const harness_opt_t opts[] = {
        {"--steps", HOPT_I64, &steps, 0, 0, NULL},
        {"--aided", HOPT_CHOICE, &aided, 0, 0, harness_on_off},
        {"--seed", HOPT_I64, &seed, 0, 0, NULL},
        {"--check-every", HOPT_I64, &every, 0, 0, NULL},
    };
    se23_ins_config_t c;
    rng_t r;
    double w[3] = {0.0, 0.0, 0.0}, a[3] = {0.0, 0.0, 0.0};
    double worst_rot = 0.0, min_eig = HUGE_VAL, lo, hi;
    int64_t nonfinite = 0, checks = 0;
    harness_progress_t pr;
    int i, bad;
    if (harness_parse_opts("se23-soak", argc, argv, opts, (int)(sizeof opts / sizeof opts[0]),
                           usage, NULL, NULL) != 0 ||
        steps < 1 || every < 1) {
        usage(stderr);
        return 2;
    }
    r.s = 0x9e3779b97f4a7c15ULL ^ (uint64_t)seed;
    memset(&c, 0, sizeof c);
    c.noise.gyro_noise = (se23_real_t)8.7e-5;
    c.noise.accel_noise = (se23_real_t)1.7e-3;
    c.noise.gyro_walk = (se23_real_t)2e-5;
    c.noise.accel_walk = (se23_real_t)2e-4;
    c.gyro_range = (se23_real_t)30.0;
    c.accel_range = (se23_real_t)150.0;
    c.lat = (se23_real_t)0.785;
    c.earth_rotation = 1;
    c.bias_states = 1;
    c.dt_nominal = (se23_real_t)(1.0 / RATE);
    c.max_gap = (se23_real_t)0.125;
    c.max_outage = (se23_real_t)10.0;
    c.outage_accel = (se23_real_t)1.0;
    c.outage_rate = (se23_real_t)0.05;
    c.gnss_gate = (se23_real_t)0.0; /* every fix fused: the run must survive them all */
    c.delay_horizon = (se23_real_t)0.0;
    memset(&g, 0, sizeof g);
    g.n = 15;
    for (i = 0; i < 3; i++) {
        g.T.R.m[i][i] = (se23_real_t)1.0;
    }
    for (i = 0; i < 15; i++) {
        g.P.m[16 * i] = (se23_real_t)(i < 3 ? 1e-4 : i < 9 ? 1.0 : i < 12 ? 1e-6 : 1e-3);
    }
    if (se23_ins_setup(&c, &ins) != SE23_OK || se23_ins_init(&ins, 0, &g) != SE23_OK) {
        fprintf(stderr, "se23-soak: setup failed\n");
        return 2;
    }
    harness_progress_init(&pr);
    for (k = 1; k <= steps; k++) {
        se23_vec3_t wv, fv;
        int64_t t;
        /* bounded random motion: rate and acceleration random walks, clipped */
        for (i = 0; i < 3; i++) {
            w[i] = fmax(-2.0, fmin(2.0, w[i] + 0.02 * uni(&r)));
            a[i] = fmax(-3.0, fmin(3.0, a[i] + 0.05 * uni(&r)));
        }
        (void)se23_ins_state(&ins, &out, &t);
        for (i = 0; i < 3; i++) { /* f = R^T (a - g_n) with the filter's attitude */
            double s = 0.0;
            int j;
            for (j = 0; j < 3; j++) {
                s += (double)out.T.R.m[j][i] * (a[j] - (double)ins.model.g_n.v[j]);
            }
            fv.v[i] = (se23_real_t)(s + 0.01 * uni(&r));
            wv.v[i] = (se23_real_t)(w[i] + 0.001 * uni(&r));
        }
        (void)se23_ins_imu(&ins, k * DT_NS, k, &wv, &fv);
        if (aided && k % 200 == 0) {
            se23_ins_gnss_t fix;
            memset(&fix, 0, sizeof fix);
            fix.t_ns = k * DT_NS;
            (void)se23_ins_state(&ins, &out, &t);
            for (i = 0; i < 3; i++) {
                fix.p_n.v[i] = (se23_real_t)((double)out.T.p.v[i] + uni(&r));
                fix.sigma_p.v[i] = (se23_real_t)1.0;
            }
            (void)se23_ins_gnss(&ins, &fix);
        }
        if (k % every == 0 || k == steps) {
            (void)se23_ins_state(&ins, &out, &t);
            if (!all_finite(&out)) {
                nonfinite++;
            } else {
                worst_rot = fmax(worst_rot, rot_err(&out.T.R));
                eig_range(out.P.m, 15, &lo, &hi);
                min_eig = fmin(min_eig, lo / hi);
            }
            checks++;
            harness_progress(&pr, k == steps, "se23-soak: %lld / %lld steps", (long long)k,
                             (long long)steps);
        }
    }
    bad = nonfinite > 0 || ins.c.filter_errors > 0 || worst_rot > (double)SE23_CFG_ROT_TOL ||
          min_eig < -1e-6;
    printf("se23-soak: %s, %s, %lld steps (%.0f s at %.0f Hz), seed %lld\n",
           SE23_CFG_DOUBLE ? "double" : "float", aided ? "aided (GNSS 1 Hz)" : "unaided",
           (long long)steps, (double)steps / RATE, RATE, (long long)seed);
    printf("  checks                %lld (every %lld steps and at the end)\n", (long long)checks,
           (long long)every);
    printf("  worst |R^T R - I|     %.3g (tolerance %.3g)\n", worst_rot,
           (double)SE23_CFG_ROT_TOL);
    printf("  smallest eig(P)/max   %.3g\n", min_eig);
    printf("  non-finite states     %lld\n", (long long)nonfinite);
    printf("  filter_errors         %lu\n", (unsigned long)ins.c.filter_errors);
    printf("  imu_used              %lu\n", (unsigned long)ins.c.imu_used);
    printf("  final state hash      %016llx\n", (unsigned long long)state_hash(&ins.g));
    printf("  %s\n", bad ? "SOAK FAILED" : "ok");
    return bad ? 1 : 0;
}
