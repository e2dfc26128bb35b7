/* Seeded random inputs: see se23_rng.h. Written without calling the
 * library, so the inputs do not depend on the code under test. */
#include "se23_rng.h"

#include <math.h>

void se23t_rng_seed(se23t_rng_t *rng, uint64_t seed)
{
    rng->state = seed;
}

static uint64_t next_u64(se23t_rng_t *rng)
{
    uint64_t z = (rng->state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

double se23t_uniform(se23t_rng_t *rng, double lo, double hi)
{
    double u = (double)(next_u64(rng) >> 11) * 0x1.0p-53;
    return lo + (hi - lo) * u;
}

double se23t_normal(se23t_rng_t *rng)
{
    double u1 = se23t_uniform(rng, 0.0, 1.0);
    double u2 = se23t_uniform(rng, 0.0, 1.0);
    if (u1 < 1e-300) {
        u1 = 1e-300;
    }
    return sqrt(-2.0 * log(u1)) * cos(2.0 * 3.14159265358979323846 * u2);
}

void se23t_random_vec3(se23t_rng_t *rng, double scale, se23_vec3_t *out)
{
    for (int i = 0; i < 3; ++i) {
        out->v[i] = (se23_real_t)se23t_uniform(rng, -scale, scale);
    }
}

void se23t_random_axis_angle(se23t_rng_t *rng, double angle, se23_vec3_t *out)
{
    double n[3];
    double norm2;
    do {
        for (int i = 0; i < 3; ++i) {
            n[i] = se23t_normal(rng);
        }
        norm2 = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    } while (norm2 < 1e-6);
    double s = angle / sqrt(norm2);
    for (int i = 0; i < 3; ++i) {
        out->v[i] = (se23_real_t)(n[i] * s);
    }
}

void se23t_random_tangent(se23t_rng_t *rng, double max_angle, double scale,
                          se23_tangent_t *out)
{
    se23_vec3_t phi;
    se23t_random_axis_angle(rng, se23t_uniform(rng, 0.0, max_angle), &phi);
    for (int i = 0; i < 3; ++i) {
        out->v[SE23_IDX_PHI + i] = phi.v[i];
        out->v[SE23_IDX_NU + i] = (se23_real_t)se23t_uniform(rng, -scale, scale);
        out->v[SE23_IDX_RHO + i] = (se23_real_t)se23t_uniform(rng, -scale, scale);
    }
}

/* Rotation from a random unit quaternion (uniform on SO(3)), computed in
 * double and rounded once, so it is orthonormal to the build's precision. */
void se23t_random_pose(se23t_rng_t *rng, double scale, se23_pose_t *out)
{
    double q[4];
    double norm2;
    do {
        for (int i = 0; i < 4; ++i) {
            q[i] = se23t_normal(rng);
        }
        norm2 = q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
    } while (norm2 < 1e-6);
    double s = 1.0 / sqrt(norm2);
    double w = q[0] * s, x = q[1] * s, y = q[2] * s, z = q[3] * s;
    double R[3][3] = {
        {1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
        {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
        {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)},
    };
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            out->R.m[i][j] = (se23_real_t)R[i][j];
        }
    }
    se23t_random_vec3(rng, scale, &out->v);
    se23t_random_vec3(rng, scale, &out->p);
}
