/**
 * @file cov_chol.h
 * @brief Internal: the packed Cholesky factor of small symmetric matrices
 *        (cov_check.h), as inline functions: the caller's frame holds it, so a
 *        factorisation does not stack a frame of its own on top of the
 *        work arrays of its caller (se23_kalman_update's covariance half).
 *        Not part of the public API.
 */
#ifndef SE23_COV_CHOL_H
#define SE23_COV_CHOL_H

#include <float.h>

#include "se23/types.h"
#include "../base/se23_math.h"

/* A pivot must exceed SE23_CHOL_PIVOT_EPS A_jj ... */
#define SE23_CHOL_PIVOT_EPS (SE23_R(16) * SE23_EPSILON)
/* ... and be at least the smallest normal number: below it the pivot has
 * lost relative precision and 1 / sqrt(pivot) may overflow. */
#if SE23_CFG_DOUBLE
#define SE23_CHOL_PIVOT_MIN DBL_MIN
#else
#define SE23_CHOL_PIVOT_MIN FLT_MIN
#endif

/* A pivot d of the factorisation is usable against its diagonal entry a. */
static inline int se23_chol_pivot_ok(se23_real_t d, se23_real_t a)
{
    return (d > (SE23_CHOL_PIVOT_EPS * a)) && (d >= SE23_CHOL_PIVOT_MIN) && se23_is_finite(d);
}

/* se23_cov_chol_packed for n = 3, the shape of every measurement model's
 * noise and innovation covariance: the loops below unrolled, the same
 * operations in the same order (bit-identical results; test_cov checks
 * it against the leading block of a 4 x 4 factor). 3 multiply-adds,
 * 3 multiplies, 3 square roots and divisions. */
static inline int se23_chol3(se23_real_t *L)
{
    /* The caller has written the triangle; when it is the Kalman update's
     * work area, uninitialised on se23_kalman_cov's stack and filled by
     * innovation_cov's blocks, the analyzer loses track (kalman_halves.c). */
    const se23_real_t d0 = L[0]; // NOLINT(clang-analyzer-core.uninitialized.Assign)
    if (!se23_chol_pivot_ok(d0, L[0])) {
        return 0;
    }
    const se23_real_t i0 = SE23_R(1) / se23_sqrt(d0);
    const se23_real_t l10 = L[1] * i0, l20 = L[3] * i0;
    const se23_real_t d1 = se23_fma(-l10, l10, L[2]);
    if (!se23_chol_pivot_ok(d1, L[2])) {
        return 0;
    }
    const se23_real_t i1 = SE23_R(1) / se23_sqrt(d1);
    const se23_real_t l21 = se23_fma(-l20, l10, L[4]) * i1;
    const se23_real_t d2 = se23_fma(-l21, l21, se23_fma(-l20, l20, L[5]));
    if (!se23_chol_pivot_ok(d2, L[5])) {
        return 0;
    }
    L[0] = i0;
    L[1] = l10;
    L[2] = i1;
    L[3] = l20;
    L[4] = l21;
    L[5] = SE23_R(1) / se23_sqrt(d2);
    return 1;
}

/* se23_cov_chol_packed for any n. */
static inline int se23_chol_loop(se23_real_t *L, int n)
{
    se23_real_t *lj = L; /* row j; row j + 1 starts j + 1 entries later */
    for (int j = 0; j < n; ++j) {
        se23_real_t d = lj[j]; // NOLINT(clang-analyzer-core.uninitialized.Assign): as in se23_chol3
        for (int k = 0; k < j; ++k) {
            d = se23_fma(-lj[k], lj[k], d);
        }
        if (!se23_chol_pivot_ok(d, lj[j])) {
            return 0;
        }
        const se23_real_t inv = SE23_R(1) / se23_sqrt(d);
        lj[j] = inv;
        se23_real_t *li = &lj[j + 1];
        for (int i = j + 1; i < n; ++i) {
            se23_real_t s = li[j];
            for (int k = 0; k < j; ++k) {
                s = se23_fma(-li[k], lj[k], s);
            }
            li[j] = s * inv;
            li = &li[i + 1];
        }
        lj = &lj[j + 1];
    }
    return 1;
}

/**
 * In place: L holds the packed lower triangle of a symmetric n x n A on
 * entry, its lower Cholesky factor on exit, except that the diagonal holds
 * the reciprocals 1 / L_jj (what the solves need). Refused (returns 0, L
 * then unspecified) unless every pivot is finite, exceeds 16 eps A_jj and
 * is at least the smallest normal number of the precision (so that 1/L_jj
 * is finite and accurate); NaN is refused. n^3/6 multiply-adds, n square
 * roots and divisions.
 */
static inline int se23_cov_chol_packed(se23_real_t *L, int n)
{
    return (n == 3) ? se23_chol3(L) : se23_chol_loop(L, n);
}

#endif /* SE23_COV_CHOL_H */
