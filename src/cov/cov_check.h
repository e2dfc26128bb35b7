/**
 * @file cov_check.h
 * @brief Internal: validation and Cholesky factorisation of small symmetric
 *        matrices (covariances up to 15x15, measurement noise and
 *        innovation covariances up to 9x9). Not part of the public API.
 *
 * Matrices are flat row-major with an explicit row stride: element (i, j)
 * of the leading n x n block of A is A[stride*i + j]. Factors are packed
 * lower triangles: row i starts at L[i (i + 1) / 2].
 */
#ifndef SE23_COV_H
#define SE23_COV_H

#include <float.h>

#include "cov_chol.h"
#include "se23/gauss.h"
#include "se23/types.h"

/** The absolute part of the checks' PSD tolerance (se23_cov_check_work):
 *  twice the smallest normal float, in both precisions. A step that
 *  multiplies a checked covariance by a large factor multiplies this
 *  slack too (se23_cov_step_fits). */
#define SE23_COV_ABS_TOL (SE23_R(2) * SE23_R(FLT_MIN))

/**
 * Raises every negative diagonal entry of the leading n x n block of P to
 * 0. A covariance the library computes is PSD in exact arithmetic, so a
 * negative variance it produces is the rounding of a zero one (the
 * denormal noise of a step from P = 0, the Joseph form of a state pinned
 * to R = 0); raising it adds a PSD term, so the result stays within the
 * checks' tolerance and meets their exact rule (no negative variance).
 * n compares.
 */
static inline void se23_cov_clamp_variances(se23_real_t *P, int n, int stride)
{
    for (int i = 0; i < n; ++i) {
        if (P[(stride + 1) * i] < SE23_R(0)) {
            P[(stride + 1) * i] = SE23_R(0);
        }
    }
}

/** Reals of a packed lower triangle of n rows. */
#define SE23_COV_TRI(n) ((n) * ((n) + 1) / 2)


/**
 * Checks the leading n x n block of A: finite, no negative diagonal entry
 * (a variance; no tolerance), symmetric
 * (|A_ij - A_ji| <= tol s) and positive semidefinite within tolerance
 * (A + (tol s + FLT_MIN) I has a Cholesky factor by se23_cov_chol_packed),
 * s = max_i |A_ii|, tol = SE23_CFG_COV_TOL. work: SE23_COV_TRI(n) reals
 * (the caller sizes the stack it spends).
 * @return SE23_OK, SE23_ERR_NONFINITE, SE23_ERR_NOT_SYMMETRIC or
 *         SE23_ERR_NOT_PSD.
 */
se23_status_t se23_cov_check_work(const se23_real_t *A, int n, int stride,
                                  se23_real_t *work);

/** se23_cov_check_work with a work buffer for n <= SE23_GAUSS_NMAX. */
se23_status_t se23_cov_check(const se23_real_t *A, int n, int stride);

#endif /* SE23_COV_H */
