/**
 * @file se23_rng.h
 * @brief Seeded random inputs for the tests and the paper tools: a
 *        splitmix64 generator and random vectors, rotations and poses.
 *        Plain C, no test framework, no call into the library.
 */
#ifndef SE23_RNG_H
#define SE23_RNG_H

#include <stdint.h>

#include "se23/types.h"

/** Seeded generator (splitmix64): the same seed gives the same sequence. */
typedef struct {
    uint64_t state;
} se23t_rng_t;

void se23t_rng_seed(se23t_rng_t *rng, uint64_t seed);
/** Uniform in [lo, hi). */
double se23t_uniform(se23t_rng_t *rng, double lo, double hi);
/** Standard normal (Box-Muller). */
double se23t_normal(se23t_rng_t *rng);
/** Vector with entries uniform in [-scale, scale). */
void se23t_random_vec3(se23t_rng_t *rng, double scale, se23_vec3_t *out);
/** Rotation vector with uniform direction and angle exactly `angle`. */
void se23t_random_axis_angle(se23t_rng_t *rng, double angle, se23_vec3_t *out);
/** Tangent with rotation angle uniform in [0, max_angle) and nu, rho uniform in [-scale, scale). */
void se23t_random_tangent(se23t_rng_t *rng, double max_angle, double scale,
                          se23_tangent_t *out);
/** Pose: rotation from a random axis-angle below pi, v and p in [-scale, scale). */
void se23t_random_pose(se23t_rng_t *rng, double scale, se23_pose_t *out);

#endif /* SE23_RNG_H */
