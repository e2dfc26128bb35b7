/*
 * se23-bench: runs one library routine N times on varied inputs, for
 * instruction counting with valgrind --tool=callgrind (tools/bench/run.sh).
 * Only the function run_kernel is collected (--toggle-collect), so input
 * generation and start-up do not count; counts are deterministic.
 *
 *   se23-bench NAME [N]   run kernel NAME N times (default 1000)
 *   se23-bench --list     print the kernel names
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "se23/earth.h"
#include "se23/gauss.h"
#include "se23/imu.h"
#include "se23/kalman.h"
#include "se23/preint_unc.h"
#include "se23/se23.h"
#include "se23/so3.h"

#define N_INPUTS 64

/* Varied inputs, prepared before the collected loop. */
static se23_vec3_t phis[N_INPUTS];
static se23_mat3_t rots[N_INPUTS];
static se23_tangent_t xis[N_INPUTS];
static se23_pose_t poses[N_INPUTS];
static se23_imu_sample_t samples[N_INPUTS];
static se23_earth_model_t model;
static se23_gauss_t filters[2]; /* n = 9 and n = 15 */
static se23_imu_noise_t noise;
static se23_meas_t gnss;
static se23_preint_unc_t factor;

/* Results are written here so the compiler cannot drop the calls. */
static volatile se23_real_t sink;

static double lcg(unsigned *state)
{
    *state = *state * 1103515245u + 12345u;
    return (double)((*state >> 8) & 0xFFFF) / 65535.0 - 0.5;
}

static void prepare(void)
{
    unsigned st = 1;
    for (int i = 0; i < N_INPUTS; ++i) {
        for (int k = 0; k < 3; ++k) {
            phis[i].v[k] = (se23_real_t)(4.0 * lcg(&st));
        }
        for (int k = 0; k < 9; ++k) {
            xis[i].v[k] = (se23_real_t)(4.0 * lcg(&st));
        }
        (void)se23_so3_exp(&phis[i], &rots[i]);
        (void)se23_exp(&xis[i], &poses[i]);
        for (int k = 0; k < 3; ++k) {
            samples[i].w_ib_b.v[k] = (se23_real_t)lcg(&st);
            samples[i].f_b.v[k] = (se23_real_t)(20.0 * lcg(&st));
        }
        samples[i].dt = (se23_real_t)0.005;
    }
    se23_vec3_t g = {{0, 0, (se23_real_t)9.81}};
    se23_vec3_t w = {{(se23_real_t)5.2e-5, 0, (se23_real_t)-5.2e-5}};
    (void)se23_earth_model_init(&g, &w, (se23_real_t)0.005, (se23_real_t)0.1, &model);

    noise.gyro_noise = (se23_real_t)1e-4;
    noise.accel_noise = (se23_real_t)1e-3;
    noise.gyro_walk = (se23_real_t)1e-6;
    noise.accel_walk = (se23_real_t)1e-5;
    for (int f = 0; f < 2; ++f) {
        se23_gauss_t *gs = &filters[f];
        memset(gs, 0, sizeof *gs);
        gs->T = poses[0];
        gs->n = f == 0 ? 9 : 15;
        for (int k = 0; k < gs->n; ++k) {
            gs->P.m[k * SE23_GAUSS_NMAX + k] = (se23_real_t)(k < 9 ? 1e-2 : 1e-6);
        }
    }
    se23_vec3_t p_meas = filters[1].T.p, lever = {{0, 0, 0}};
    se23_mat3_t cov = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    p_meas.v[0] = (se23_real_t)(p_meas.v[0] + 0.5);
    (void)se23_meas_pos_nav(&filters[1].T, &p_meas, &lever, &cov, &gnss);
    se23_vec3_t zero = {{0, 0, 0}};
    (void)se23_preint_unc_reset(&zero, &zero, SE23_INPUT_JAC_EXACT, &factor);
}

static void k_so3_exp(int i)
{
    se23_mat3_t R;
    (void)se23_so3_exp(&phis[i], &R);
    sink = R.m[0][1];
}
static void k_so3_log(int i)
{
    se23_vec3_t phi;
    (void)se23_so3_log(&rots[i], &phi);
    sink = phi.v[0];
}
static void k_so3_jl(int i)
{
    se23_mat3_t J;
    (void)se23_so3_jl(&phis[i], &J);
    sink = J.m[0][1];
}
static void k_so3_jl_inv(int i)
{
    se23_mat3_t J;
    (void)se23_so3_jl_inv(&phis[i], &J);
    sink = J.m[0][1];
}
static void k_so3_normalize(int i)
{
    se23_mat3_t R;
    (void)se23_so3_normalize(&rots[i], &R);
    sink = R.m[0][1];
}
static void k_se23_exp(int i)
{
    se23_pose_t T;
    (void)se23_exp(&xis[i], &T);
    sink = T.p.v[0];
}
static void k_se23_log(int i)
{
    se23_tangent_t xi;
    (void)se23_log(&poses[i], &xi);
    sink = xi.v[8];
}
static void k_se23_compose(int i)
{
    se23_pose_t T;
    se23_compose(&poses[i], &poses[(i + 1) % N_INPUTS], &T);
    sink = T.p.v[0];
}
static void k_se23_inverse(int i)
{
    se23_pose_t T;
    se23_inverse(&poses[i], &T);
    sink = T.p.v[0];
}
static void k_se23_adjoint(int i)
{
    se23_mat9_t Ad;
    se23_adjoint(&poses[i], &Ad);
    sink = Ad.m[10];
}
static void k_se23_adjoint_inv(int i)
{
    se23_mat9_t Ad;
    se23_adjoint_inv(&poses[i], &Ad);
    sink = Ad.m[10];
}
static void k_imu_increment(int i)
{
    se23_pose_t U;
    (void)se23_imu_increment(&samples[i], &U);
    sink = U.p.v[0];
}
static void k_imu_step(int i)
{
    se23_pose_t T;
    (void)se23_imu_step(&model, &poses[i], &samples[i], &T);
    sink = T.p.v[0];
}

static void k_gauss_predict_9(int i)
{
    se23_gauss_t out;
    (void)se23_gauss_predict(&model, &filters[0], &samples[i], &noise,
                             SE23_INPUT_JAC_EXACT, &out);
    sink = out.P.m[0];
}
static void k_gauss_predict_15(int i)
{
    se23_gauss_t out;
    (void)se23_gauss_predict(&model, &filters[1], &samples[i], &noise,
                             SE23_INPUT_JAC_EXACT, &out);
    sink = out.P.m[0];
}
static void k_kalman_update_gnss_pos_15(int i)
{
    se23_gauss_t out;
    (void)i;
    (void)se23_kalman_update(&filters[1], &gnss, &out, NULL);
    sink = out.P.m[0];
}
static void k_preint_unc_add(int i)
{
    se23_preint_unc_t f = factor;
    (void)se23_preint_unc_add(&f, &samples[i], &noise);
    sink = f.f.delta.p.v[0];
}

typedef struct {
    const char *name;
    void (*fn)(int);
} kernel_t;

static const kernel_t kernels[] = {
    {"so3_exp", k_so3_exp},           {"so3_log", k_so3_log},
    {"so3_jl", k_so3_jl},             {"so3_jl_inv", k_so3_jl_inv},
    {"so3_normalize", k_so3_normalize}, {"se23_exp", k_se23_exp},
    {"se23_log", k_se23_log},         {"se23_compose", k_se23_compose},
    {"se23_inverse", k_se23_inverse}, {"se23_adjoint", k_se23_adjoint},
    {"se23_adjoint_inv", k_se23_adjoint_inv},
    {"imu_increment", k_imu_increment}, {"imu_step", k_imu_step},
    {"gauss_predict_n9", k_gauss_predict_9},
    {"gauss_predict_n15", k_gauss_predict_15},
    {"kalman_update_gnss_n15", k_kalman_update_gnss_pos_15},
    {"preint_unc_add", k_preint_unc_add},
};
#define N_KERNELS (sizeof kernels / sizeof kernels[0])

/* The only collected function: n calls of one kernel. */
void run_kernel(void (*fn)(int), int n);
void run_kernel(void (*fn)(int), int n)
{
    for (int k = 0; k < n; ++k) {
        fn(k % N_INPUTS);
    }
}

int main(int argc, char **argv)
{
    if (argc >= 2 && strcmp(argv[1], "--list") == 0) {
        for (size_t k = 0; k < N_KERNELS; ++k) {
            puts(kernels[k].name);
        }
        return 0;
    }
    if (argc < 2) {
        fprintf(stderr, "usage: se23-bench NAME [N] | --list\n");
        return 2;
    }
    int n = argc >= 3 ? atoi(argv[2]) : 1000;
    prepare();
    for (size_t k = 0; k < N_KERNELS; ++k) {
        if (strcmp(argv[1], kernels[k].name) == 0) {
            run_kernel(kernels[k].fn, n);
            return 0;
        }
    }
    fprintf(stderr, "se23-bench: unknown kernel '%s'\n", argv[1]);
    return 2;
}
