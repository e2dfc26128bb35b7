/* The library's routines one by one; see routines.h. */
#include "routines.h"

#include "ring.h"
#include "se23/earth.h"
#include "se23/imu.h"
#include "se23/se23.h"
#include "se23/so3.h"
#include "se23_rng.h"

static se23_vec3_t phis[BENCH_RING];
static se23_mat3_t rots[BENCH_RING];
static se23_tangent_t xis[BENCH_RING];
static se23_pose_t poses[BENCH_RING];
static se23_imu_sample_t samples[BENCH_RING];
static se23_earth_model_t model;

/* Results are written here so the compiler cannot drop the calls. */
static volatile se23_real_t sink;

int bench_routines_prepare(void)
{
    se23t_rng_t rng;
    int bad = 0;
    se23t_rng_seed(&rng, 1);
    for (int i = 0; i < BENCH_RING; ++i) {
        se23t_random_vec3(&rng, 2.0, &phis[i]);
        se23t_random_tangent(&rng, 3.0, 2.0, &xis[i]);
        bad |= (int)se23_so3_exp(&phis[i], &rots[i]);
        bad |= (int)se23_exp(&xis[i], &poses[i]);
        se23t_random_vec3(&rng, 0.5, &samples[i].w_ib_b);
        se23t_random_vec3(&rng, 10.0, &samples[i].f_b);
        samples[i].dt = SE23_R(0.005);
    }
    const se23_vec3_t g = {{0, 0, SE23_R(9.81)}};
    const se23_vec3_t w = {{SE23_R(5.2e-5), 0, SE23_R(-5.2e-5)}};
    bad |= (int)se23_earth_model_init(&g, &w, SE23_R(0.005), SE23_R(0.1), &model);
    return bad;
}

static int k_so3_exp(int i)
{
    se23_mat3_t R;
    const se23_status_t st = se23_so3_exp(&phis[i], &R);
    sink = R.m[0][1];
    return (int)st;
}
static int k_so3_log(int i)
{
    se23_vec3_t phi;
    const se23_status_t st = se23_so3_log(&rots[i], &phi);
    sink = phi.v[0];
    return (int)st;
}
static int k_so3_jl(int i)
{
    se23_mat3_t J;
    const se23_status_t st = se23_so3_jl(&phis[i], &J);
    sink = J.m[0][1];
    return (int)st;
}
static int k_so3_jl_inv(int i)
{
    se23_mat3_t J;
    const se23_status_t st = se23_so3_jl_inv(&phis[i], &J);
    sink = J.m[0][1];
    return (int)st;
}
static int k_so3_normalize(int i)
{
    se23_mat3_t R;
    const se23_status_t st = se23_so3_normalize(&rots[i], &R);
    sink = R.m[0][1];
    return (int)st;
}
static int k_se23_exp(int i)
{
    se23_pose_t T;
    const se23_status_t st = se23_exp(&xis[i], &T);
    sink = T.p.v[0];
    return (int)st;
}
static int k_se23_log(int i)
{
    se23_tangent_t xi;
    const se23_status_t st = se23_log(&poses[i], &xi);
    sink = xi.v[8];
    return (int)st;
}
static int k_se23_compose(int i)
{
    se23_pose_t T;
    se23_compose(&poses[i], &poses[(i + 1) % BENCH_RING], &T);
    sink = T.p.v[0];
    return 0;
}
static int k_se23_inverse(int i)
{
    se23_pose_t T;
    se23_inverse(&poses[i], &T);
    sink = T.p.v[0];
    return 0;
}
static int k_se23_adjoint(int i)
{
    se23_mat9_t Ad;
    se23_adjoint(&poses[i], &Ad);
    sink = Ad.m[10];
    return 0;
}
static int k_se23_adjoint_inv(int i)
{
    se23_mat9_t Ad;
    se23_adjoint_inv(&poses[i], &Ad);
    sink = Ad.m[10];
    return 0;
}
static int k_imu_increment(int i)
{
    se23_pose_t U;
    const se23_status_t st = se23_imu_increment(&samples[i], &U);
    sink = U.p.v[0];
    return (int)st;
}
static int k_imu_step(int i)
{
    se23_pose_t T;
    const se23_status_t st = se23_imu_step(&model, &poses[i], &samples[i], &T);
    sink = T.p.v[0];
    return (int)st;
}

const bench_routine_t bench_routines[] = {
    {"so3_exp", k_so3_exp},           {"so3_log", k_so3_log},
    {"so3_jl", k_so3_jl},             {"so3_jl_inv", k_so3_jl_inv},
    {"so3_normalize", k_so3_normalize}, {"se23_exp", k_se23_exp},
    {"se23_log", k_se23_log},         {"se23_compose", k_se23_compose},
    {"se23_inverse", k_se23_inverse}, {"se23_adjoint", k_se23_adjoint},
    {"se23_adjoint_inv", k_se23_adjoint_inv},
    {"imu_increment", k_imu_increment}, {"imu_step", k_imu_step},
};
const int bench_n_routines = (int)(sizeof bench_routines / sizeof bench_routines[0]);
