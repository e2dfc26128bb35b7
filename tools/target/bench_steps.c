/*
 * Benchmarked operations that are not rows of tests/target/tv_list.h (see
 * bench_steps.h): one shared, realistic setup -- a 200 Hz IMU sample on the
 * rotating Earth (WGS-84, NED, latitude 0.8 rad), a moving pose, a
 * covariance with and without bias states -- and one small function per
 * operation (gauss.h so far, and the composite steps). Adding an operation: one function and one row of bench_steps[].
 * When a routine gains reference vectors (a row of tv_list.h), drop its row
 * here: the benchmark runs every tv_list.h row by itself.
 */
#include <string.h>

#include "bench_steps.h"
#include "se23/earth.h"
#include "se23/gauss.h"
#include "se23/imu.h"
#include "se23/so3.h"

static struct {
    se23_earth_model_t model;
    se23_imu_sample_t s;
    se23_imu_noise_t noise;
    se23_pose_t T, U, out;
    se23_gauss_t g9, g15, gout;
    se23_mat9x6_t B, B2;
    se23_mat9_t Q, S, F;
    se23_tangent_t x, y;
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
    (void)se23_imu_increment(&c.s, &c.U);
    (void)se23_gauss_input_jac(SE23_INPUT_JAC_EXACT, &c.s.w_ib_b, &c.s.f_b, c.s.dt, &c.B);
    (void)se23_gauss_input_noise(&c.B, &c.noise, c.s.dt, &c.Q);
    set_gauss(&c.g9, SE23_GAUSS_N_POSE);
    set_gauss(&c.g15, SE23_GAUSS_N_BIAS);
    for (i = 0; i < 9; ++i) {
        c.S.m[9 * i + i] = SE23_R(1e-2);
        c.x.v[i] = SE23_R(0.1) * (se23_real_t)(i + 1);
    }
}

/* gauss.h */
static int gauss_fk_apply(void)
{
    se23_gauss_fk_apply(&c.U, SE23_R(0.005), &c.x, &c.y);
    return 0;
}
static int gauss_fk(void)
{
    se23_gauss_fk(&c.U, SE23_R(0.005), &c.F);
    return 0;
}
static int gauss_fk_mul(void)
{
    se23_gauss_fk_mul(&c.U, SE23_R(0.005), &c.B, &c.B2);
    return 0;
}
static int gauss_input_jac(void)
{
    return (int)se23_gauss_input_jac(SE23_INPUT_JAC_EXACT, &c.s.w_ib_b, &c.s.f_b, c.s.dt, &c.B2);
}
static int gauss_input_noise(void) { return (int)se23_gauss_input_noise(&c.B, &c.noise, c.s.dt, &c.Q); }
static int gauss_cov_propagate(void)
{
    return (int)se23_gauss_cov_propagate(&c.S, &c.U, c.s.dt, &c.Q, &c.F);
}
static int gauss_check15(void) { return (int)se23_gauss_check(&c.g15); }
static int gauss_propagate15(void)
{
    return (int)se23_gauss_propagate(&c.g15, &c.U, &c.B, &c.noise, c.s.dt, &c.gout);
}
static int gauss_from_carried15(void) { return (int)se23_gauss_from_carried(&c.model, &c.g15, &c.gout); }
static int gauss_to_carried15(void) { return (int)se23_gauss_to_carried(&c.model, &c.g15, &c.gout); }
/* Composite: one full propagation step (mean + covariance), rotating Earth. */
static int step_cov9(void)
{
    return (int)se23_gauss_predict(&c.model, &c.g9, &c.s, &c.noise, SE23_INPUT_JAC_EXACT, &c.gout);
}
static int step_cov15(void)
{
    return (int)se23_gauss_predict(&c.model, &c.g15, &c.s, &c.noise, SE23_INPUT_JAC_EXACT, &c.gout);
}
static int step_cov15_basic(void)
{
    return (int)se23_gauss_predict(&c.model, &c.g15, &c.s, &c.noise, SE23_INPUT_JAC_BASIC, &c.gout);
}

const bench_step_t bench_steps[] = {
    {"se23_gauss_fk_apply", setup, gauss_fk_apply},
    {"se23_gauss_fk", setup, gauss_fk},
    {"se23_gauss_fk_mul", setup, gauss_fk_mul},
    {"se23_gauss_input_jac (exact)", setup, gauss_input_jac},
    {"se23_gauss_input_noise", setup, gauss_input_noise},
    {"se23_gauss_cov_propagate", setup, gauss_cov_propagate},
    {"se23_gauss_check (n=15)", setup, gauss_check15},
    {"se23_gauss_propagate (n=15)", setup, gauss_propagate15},
    {"se23_gauss_from_carried (n=15)", setup, gauss_from_carried15},
    {"se23_gauss_to_carried (n=15)", setup, gauss_to_carried15},
    {"STEP mean+cov n=9 (se23_gauss_predict)", setup, step_cov9},
    {"STEP mean+cov n=15 (se23_gauss_predict)", setup, step_cov15},
    {"STEP mean+cov n=15, basic B (se23_gauss_predict)", setup, step_cov15_basic},
};
const int bench_n_steps = (int)(sizeof bench_steps / sizeof bench_steps[0]);
