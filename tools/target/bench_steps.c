/*
 * Benchmarked operations that are not rows of tests/target/tv_list.h (see
 * bench_steps.h), i.e. composite steps: one shared, realistic setup -- a 200 Hz IMU sample on the
 * rotating Earth (WGS-84, NED, latitude 0.8 rad), a moving pose, a
 * covariance with and without bias states, a GNSS fix -- and one small
 * function per operation. Adding an operation: one function and one row of bench_steps[].
 * When a routine gains reference vectors (a row of tv_list.h), drop its row
 * here: the benchmark runs every tv_list.h row by itself.
 */
#include <string.h>

#include "bench_steps.h"
#include "se23/earth.h"
#include "se23/gauss.h"
#include "se23/imu.h"
#include "se23/kalman.h"
#include "se23/preint_unc.h"
#include "se23/so3.h"

static struct {
    se23_earth_model_t model;
    se23_imu_sample_t s;
    se23_imu_noise_t noise;
    se23_pose_t T;
    se23_gauss_t g9, g15, gout;
    se23_preint_unc_t factor;
    se23_meas_t y;
    se23_vec3_t p_gnss, lever;
    se23_mat3_t cov;
} c;

static void set_gauss(se23_gauss_t *g, int n)
{
    int i;
    memset(g, 0, sizeof *g);
    g->T = c.T;
    g->b_g.v[0] = SE23_R(1e-4);
    g->b_a.v[2] = SE23_R(-2e-2);
    g->n = n;
    for (i = 0; i < n; ++i) {
        g->P.m[SE23_GAUSS_NMAX * i + i] = (i < 3) ? SE23_R(1e-4) : SE23_R(1e-2);
    }
    g->P.m[SE23_GAUSS_NMAX * 0 + 4] = SE23_R(1e-6);
    g->P.m[SE23_GAUSS_NMAX * 4 + 0] = SE23_R(1e-6);
}

static void setup(void)
{
    const se23_vec3_t phi = {{SE23_R(0.3), SE23_R(0.2), SE23_R(-0.5)}};
    int i;
    memset(&c, 0, sizeof c);
    (void)se23_earth_model_init_wgs84(SE23_FRAME_NED, SE23_R(0.8), SE23_R(100), SE23_R(0.005),
                                      SE23_R(0.02), &c.model);
    c.s.w_ib_b.v[0] = SE23_R(0.1);
    c.s.w_ib_b.v[1] = SE23_R(-0.2);
    c.s.w_ib_b.v[2] = SE23_R(0.3);
    c.s.f_b.v[0] = SE23_R(0.3);
    c.s.f_b.v[1] = SE23_R(-0.2);
    c.s.f_b.v[2] = SE23_R(-9.8);
    c.s.dt = SE23_R(0.005);
    c.noise.gyro_noise = SE23_R(1e-4);
    c.noise.accel_noise = SE23_R(1e-3);
    c.noise.gyro_walk = SE23_R(1e-6);
    c.noise.accel_walk = SE23_R(1e-5);
    (void)se23_so3_exp(&phi, &c.T.R);
    c.T.v.v[0] = SE23_R(10);
    c.T.v.v[1] = SE23_R(1);
    c.T.p.v[0] = SE23_R(100);
    c.T.p.v[2] = SE23_R(-20);
    set_gauss(&c.g9, SE23_GAUSS_N_POSE);
    set_gauss(&c.g15, SE23_GAUSS_N_BIAS);
    for (i = 0; i < 3; ++i) {
        c.p_gnss.v[i] = c.T.p.v[i] + SE23_R(0.5);
        c.lever.v[i] = SE23_R(0.1) * (se23_real_t)(i + 1);
        c.cov.m[i][i] = SE23_R(4.0);
    }
    (void)se23_preint_unc_reset(&c.g15.b_g, &c.g15.b_a, SE23_INPUT_JAC_EXACT, &c.factor);
    for (i = 0; i < 20; ++i) {
        (void)se23_preint_unc_add(&c.factor, &c.s, &c.noise);
    }
}

/* Composite: one full propagation step (mean + covariance), rotating Earth. */
static int step_cov9(void)
{
    return (int)se23_gauss_predict(&c.model, &c.g9, &c.s, &c.noise, SE23_INPUT_JAC_EXACT, &c.gout);
}
static int step_cov15(void)
{
    return (int)se23_gauss_predict(&c.model, &c.g15, &c.s, &c.noise, SE23_INPUT_JAC_EXACT, &c.gout);
}
/* Composite: one GNSS position update (model + Kalman update), n = 15. */
static int update_gnss15(void)
{
    se23_status_t st = se23_meas_pos_nav(&c.g15.T, &c.p_gnss, &c.lever, &c.cov, &c.y);
    return st != SE23_OK ? (int)st : (int)se23_kalman_update(&c.g15, &c.y, &c.gout, NULL);
}
/* Composite: one sample into a preintegrated factor (Deltas, P, J; no
 * classical Jacobians), 20 samples in. */
static int step_preint(void)
{
    return (int)se23_preint_unc_add(&c.factor, &c.s, &c.noise);
}
static int step_cov15_basic(void)
{
    return (int)se23_gauss_predict(&c.model, &c.g15, &c.s, &c.noise, SE23_INPUT_JAC_BASIC, &c.gout);
}

const bench_step_t bench_steps[] = {
    {"STEP mean+cov n=9 (se23_gauss_predict)", setup, step_cov9},
    {"STEP mean+cov n=15 (se23_gauss_predict)", setup, step_cov15},
    {"STEP mean+cov n=15, basic B (se23_gauss_predict)", setup, step_cov15_basic},
    {"STEP preintegration (se23_preint_unc_add, exact B, no classical Jacobians)", setup, step_preint},
    {"UPDATE GNSS position n=15 (se23_meas_pos_nav + se23_kalman_update)", setup, update_gnss15},
};
const int bench_n_steps = (int)(sizeof bench_steps / sizeof bench_steps[0]);
