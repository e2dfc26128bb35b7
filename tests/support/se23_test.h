/**
 * @file se23_test.h
 * @brief Test helpers shared by the CMocka tests: comparisons in double with
 *        absolute + relative tolerance (CMocka 1.1.5 has none), a seeded
 *        random generator, and random group elements.
 *
 * Include after <setjmp.h>, <stdarg.h>, <stddef.h> and <cmocka.h>.
 */
#ifndef SE23_TEST_H
#define SE23_TEST_H

#include <float.h>
#include <stdint.h>

#include "se23/types.h"

/** Machine epsilon of the build's precision. */
#if SE23_CFG_DOUBLE
#define SE23T_EPS DBL_EPSILON
#else
#define SE23T_EPS ((double)FLT_EPSILON)
#endif

/**
 * Nonzero when |actual - expected| <= abs_tol + rel_tol * |expected|
 * (and both are finite, or both are the same infinity/NaN never).
 */
int se23t_near(double actual, double expected, double abs_tol, double rel_tol);

/** Fails the current test with a message naming the operands. */
void se23t_assert_near(double actual, double expected, double abs_tol,
                       double rel_tol, const char *what, const char *file,
                       int line);
void se23t_assert_array_near(const se23_real_t *actual,
                             const se23_real_t *expected, int n,
                             double abs_tol, double rel_tol, const char *what,
                             const char *file, int line);

#define assert_near(a, e, abs_tol, rel_tol)                                    \
    se23t_assert_near((double)(a), (double)(e), (abs_tol), (rel_tol), #a,      \
                      __FILE__, __LINE__)
/** Compares n reals; use with .v, .m or &x.m[0][0] of the se23 types. */
#define assert_array_near(a, e, n, abs_tol, rel_tol)                           \
    se23t_assert_array_near((a), (e), (n), (abs_tol), (rel_tol), #a,          \
                            __FILE__, __LINE__)
#define assert_mat3_near(a, e, abs_tol)                                        \
    assert_array_near(&(a)->m[0][0], &(e)->m[0][0], 9, (abs_tol), 0.0)
#define assert_pose_near(a, e, abs_tol)                                        \
    do {                                                                       \
        assert_mat3_near(&(a)->R, &(e)->R, (abs_tol));                         \
        assert_array_near((a)->v.v, (e)->v.v, 3, (abs_tol), 0.0);              \
        assert_array_near((a)->p.v, (e)->p.v, 3, (abs_tol), 0.0);              \
    } while (0)

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

#endif /* SE23_TEST_H */
