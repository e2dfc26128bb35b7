/* The benchmark's input ring; see ring.h. The filter is run with the
 * library itself for 1 s before the ring starts, so that the covariances
 * are those of a running filter (correlated, after GNSS updates). */
#include "ring.h"

#include <math.h>
#include <string.h>

#include "se23/kalman.h"
#include "se23/se23.h"
#include "se23/so3.h"
#include "se23_rng.h"

#define RATE_HZ 200
#define WARMUP (RATE_HZ * 1) /* samples before the ring starts */
#define GNSS_EVERY 40        /* 5 Hz */

/* A manoeuvring UAV: raw gyro and accelerometer readings at time t [s],
 * with the white noise of the MEMS densities of models() at 200 Hz. */
static void sample_at(double t, se23t_rng_t *rng, se23_imu_sample_t *s)
{
    const double w[3] = {0.3 * sin(1.1 * t), 0.2 * cos(0.7 * t), 0.25 + 0.1 * sin(0.3 * t)};
    const double f[3] = {0.8 * sin(0.9 * t), 0.4 * cos(1.3 * t), -9.81 + 0.5 * sin(2.0 * t)};
    for (int k = 0; k < 3; ++k) {
        s->w_ib_b.v[k] = (se23_real_t)(w[k] + 7e-3 * se23t_normal(rng));
        s->f_b.v[k] = (se23_real_t)(f[k] + 3e-2 * se23t_normal(rng));
    }
    s->dt = SE23_R(1.0 / RATE_HZ);
}

/* The filter at t = 0: level flight heading 23 deg at 12 m/s, 120 m up,
 * bias estimates set, diagonal covariance; carried state. */
static se23_status_t initial_state(const se23_earth_model_t *m, se23_gauss_t *g)
{
    static const double sd[15] = {0.01, 0.01, 0.03, 0.2, 0.2, 0.3, 2, 2, 3,
                                  3e-4, 3e-4, 3e-4, 0.03, 0.03, 0.03};
    const se23_vec3_t phi = {{SE23_R(0.02), SE23_R(-0.01), SE23_R(0.4)}};
    se23_pose_t T;
    memset(g, 0, sizeof *g);
    se23_status_t st = se23_so3_exp(&phi, &T.R);
    const se23_vec3_t v = {{SE23_R(12), SE23_R(3), SE23_R(-0.5)}};
    const se23_vec3_t p = {{SE23_R(50), SE23_R(-20), SE23_R(-120)}};
    T.v = v;
    T.p = p;
    se23_imu_carried_from_user(m, &T, &g->T);
    const se23_vec3_t bg = {{SE23_R(1e-3), SE23_R(-2e-3), SE23_R(5e-4)}};
    const se23_vec3_t ba = {{SE23_R(0.02), SE23_R(-0.01), SE23_R(0.03)}};
    g->b_g = bg;
    g->b_a = ba;
    g->n = SE23_GAUSS_N_BIAS;
    for (int k = 0; k < 15; ++k) {
        g->P.m[15 * k + k] = (se23_real_t)(sd[k] * sd[k]);
    }
    return st;
}

/* A GNSS fix near the antenna of state g: h(T) = p + R l plus noise of 1 m. */
static void gnss_fix(const bench_ring_t *r, const se23_gauss_t *g, se23t_rng_t *rng,
                     se23_vec3_t *p_n)
{
    se23_act(&g->T, &r->lever_b, p_n);
    for (int k = 0; k < 3; ++k) {
        p_n->v[k] += (se23_real_t)se23t_normal(rng);
    }
}

static void models(bench_ring_t *r)
{
    r->noise.gyro_noise = SE23_R(5e-4);
    r->noise.accel_noise = SE23_R(2e-3);
    r->noise.gyro_walk = SE23_R(1e-5);
    r->noise.accel_walk = SE23_R(1e-4);
    const se23_vec3_t lever = {{SE23_R(0.1), SE23_R(0.05), SE23_R(-0.2)}};
    r->lever_b = lever;
    const se23_mat3_t cov = {{{SE23_R(2.25), 0, 0}, {0, SE23_R(2.25), 0}, {0, 0, SE23_R(9)}}};
    r->gnss_cov = cov;
}

int bench_ring_fill(bench_ring_t *r)
{
    se23t_rng_t rng;
    se23_gauss_t g;
    se23_preint_unc_t fu;
    memset(r, 0, sizeof *r);
    se23t_rng_seed(&rng, 7);
    models(r);
    se23_status_t st = se23_earth_model_init_wgs84(SE23_FRAME_NED, SE23_R(0.785), SE23_R(120),
                                                   SE23_R(1.0 / RATE_HZ), SE23_R(0.02), &r->model);
    if (st == SE23_OK) {
        st = initial_state(&r->model, &g);
    }
    for (int k = 0; st == SE23_OK && k < WARMUP + BENCH_RING; ++k) {
        se23_imu_sample_t s;
        sample_at((double)k / RATE_HZ, &rng, &s);
        if (k % BENCH_FACTOR_LEN == 0) {
            st = se23_preint_unc_reset(&g.b_g, &g.b_a, SE23_INPUT_JAC_EXACT, &fu);
        }
        const int i = k - WARMUP;
        if (i >= 0) {
            r->s[i] = s;
            r->g15[i] = g;
            r->g9[i] = g;
            r->g9[i].n = SE23_GAUSS_N_POSE;
            gnss_fix(r, &g, &rng, &r->gnss_p[i]);
            r->fu[i] = fu;
        }
        if (st == SE23_OK) {
            st = se23_preint_unc_add(&fu, &s, &r->noise);
        }
        if (st == SE23_OK) {
            st = se23_gauss_predict(&r->model, &g, &s, &r->noise, SE23_INPUT_JAC_EXACT, &g);
        }
        if (st == SE23_OK && k % GNSS_EVERY == GNSS_EVERY - 1) {
            se23_vec3_t p_n;
            se23_meas_t y;
            gnss_fix(r, &g, &rng, &p_n);
            st = se23_meas_pos_nav(&g.T, &p_n, &r->lever_b, &r->gnss_cov, &y);
            if (st == SE23_OK) {
                st = se23_kalman_update(&g, &y, &g, NULL);
            }
        }
    }
    return (int)st;
}
