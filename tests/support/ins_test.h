/**
 * @file ins_test.h
 * @brief Helpers of the navigation-filter tests (test_ins*.c), header-only:
 *        a configuration, an initial state, and the samples and fixes of a
 *        body at rest on flat Earth (any attitude, optional true biases),
 *        noise-free or with white noise: a truth that needs no integrator.
 */
#ifndef SE23_INS_TEST_H
#define SE23_INS_TEST_H

#include <math.h>
#include <string.h>

#include "se23/earth.h"
#include "se23/ins.h"
#include "se23_rng.h"

#define IT_RATE 200.0               /* IMU rate [Hz] */
#define IT_DT_NS 5000000LL          /* its interval [ns] */
#define IT_G 9.80665                /* flat-Earth gravity of the tests [m/s^2] */
#define IT_SG 1e-3                  /* gyro noise std of one sample [rad/s] */
#define IT_SA 1e-2                  /* accel noise std of one sample [m/s^2] */

/* Gravity the filter's model uses at latitude 0 (NED, height 0). */
static inline double it_gravity(void)
{
    se23_real_t g;
    (void)se23_earth_gravity(SE23_R(0), SE23_R(0), &g);
    return (double)g;
}

/** A flat-Earth configuration: noise of IT_SG/IT_SA per sample, detector on. */
static inline void it_config(se23_ins_config_t *c, int bias_states)
{
    memset(c, 0, sizeof *c);
    c->noise.gyro_noise = (se23_real_t)(IT_SG / sqrt(IT_RATE));
    c->noise.accel_noise = (se23_real_t)(IT_SA / sqrt(IT_RATE));
    c->noise.gyro_walk = (se23_real_t)1e-6;
    c->noise.accel_walk = (se23_real_t)1e-5;
    c->gyro_range = (se23_real_t)30.0;
    c->accel_range = (se23_real_t)150.0;
    c->lat = SE23_R(0);
    c->earth_rotation = 0;
    c->bias_states = bias_states;
    c->dt_nominal = (se23_real_t)(1.0 / IT_RATE);
    c->max_gap = (se23_real_t)0.125;
    c->max_outage = SE23_R(10);
    c->outage_accel = SE23_R(1);
    c->outage_rate = (se23_real_t)0.05;
    c->gnss_gate = SE23_R(30);
    c->gate_recover = 5;
    c->delay_horizon = (se23_real_t)0.25;
    c->zupt = 1;
    c->detector.window = 20;
    c->detector.sigma_a = (se23_real_t)IT_SA;
    c->detector.sigma_g = (se23_real_t)IT_SG;
    c->detector.gravity = (se23_real_t)it_gravity();
    c->detector.threshold = SE23_R(12);
    c->zupt_sigma_v = (se23_real_t)0.01;
    c->zaru_sigma_w = (se23_real_t)1e-3;
}

/** Level at the origin, at rest; P diagonal with the given 1-sigmas. */
static inline void it_initial(int n, double s_att, double s_v, double s_p, se23_gauss_t *g)
{
    memset(g, 0, sizeof *g);
    g->n = n;
    for (int i = 0; i < 3; ++i) {
        g->T.R.m[i][i] = SE23_R(1);
    }
    for (int i = 0; i < 3; ++i) {
        g->P.m[16 * i] = (se23_real_t)(s_att * s_att);
        g->P.m[16 * (3 + i)] = (se23_real_t)(s_v * s_v);
        g->P.m[16 * (6 + i)] = (se23_real_t)(s_p * s_p);
        if (n == 15) {
            g->P.m[16 * (9 + i)] = (se23_real_t)1e-6;
            g->P.m[16 * (12 + i)] = (se23_real_t)1e-3;
        }
    }
}

/** Samples of a body at rest on flat Earth with attitude R (NULL: level):
 *  f = R^T (0, 0, -g), w = 0, minus the true biases b_g, b_a (measured =
 *  true - bias, gauss.h; NULL: none), plus white noise of IT_SG, IT_SA if
 *  rng is not NULL. */
static inline void it_rest_sample(se23t_rng_t *rng, const se23_mat3_t *R, const double b_g[3],
                                  const double b_a[3], se23_vec3_t *w, se23_vec3_t *f)
{
    const double g = it_gravity();
    for (int i = 0; i < 3; ++i) {
        const double nw = rng != NULL ? IT_SG * se23t_normal(rng) : 0.0;
        const double na = rng != NULL ? IT_SA * se23t_normal(rng) : 0.0;
        const double up = R != NULL ? -g * (double)R->m[2][i] : (i == 2 ? -g : 0.0);
        w->v[i] = (se23_real_t)(nw - (b_g != NULL ? b_g[i] : 0.0));
        f->v[i] = (se23_real_t)(up + na - (b_a != NULL ? b_a[i] : 0.0));
    }
}

/** Runs n level samples at rest from time t0 (seq from seq0) through the
 *  filter; returns the number integrated. */
static inline int it_run_rest(se23_ins_t *ins, se23t_rng_t *rng, const double b_a[3],
                              long long t0, long long seq0, int n)
{
    int used = 0;
    for (int k = 1; k <= n; ++k) {
        se23_vec3_t w, f;
        it_rest_sample(rng, NULL, NULL, b_a, &w, &f);
        used += se23_ins_imu(ins, t0 + k * IT_DT_NS, seq0 + k, &w, &f) == SE23_INS_USED;
    }
    return used;
}

/** A position fix at p (m) with 1-sigma s, at t. */
static inline void it_fix(long long t, const double p[3], double s, se23_ins_gnss_t *fix)
{
    memset(fix, 0, sizeof *fix);
    fix->t_ns = t;
    for (int i = 0; i < 3; ++i) {
        fix->p_n.v[i] = (se23_real_t)p[i];
        fix->sigma_p.v[i] = (se23_real_t)s;
    }
}

#endif /* SE23_INS_TEST_H */
