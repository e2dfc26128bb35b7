/**
 * @file se23_test.h
 * @brief Test helpers shared by the CMocka tests: comparisons in double with
 *        absolute + relative tolerance (CMocka 1.1.5 has none); with
 *        se23_rng.h, the seeded generator of random inputs.
 *
 * Include after <setjmp.h>, <stdarg.h>, <stddef.h> and <cmocka.h>.
 */
#ifndef SE23_TEST_H
#define SE23_TEST_H

#include <float.h>

#include "se23/types.h"
#include "se23_rng.h"

/** Machine epsilon of the build's precision. */
#if SE23_CFG_DOUBLE
#define SE23T_EPS DBL_EPSILON
#else
#define SE23T_EPS ((double)FLT_EPSILON)
#endif

/** Largest finite real of the build's precision. */
#if SE23_CFG_DOUBLE
#define SE23T_REAL_MAX DBL_MAX
#else
#define SE23T_REAL_MAX FLT_MAX
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

#endif /* SE23_TEST_H */
