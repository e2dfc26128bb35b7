/**
 * @file cov.h
 * @brief Internal: validation and Cholesky factorisation of small symmetric
 *        matrices (covariances up to 15x15, innovation covariances up to
 *        9x9), and the congruence A P A^T of a linear map given as a
 *        function. Not part of the public API.
 *
 * Matrices are flat row-major with an explicit row stride: element (i, j)
 * of the leading n x n block of A is A[stride*i + j].
 */
#ifndef SE23_COV_H
#define SE23_COV_H

#include "se23/gauss.h"
#include "se23/types.h"

/** Largest size handled. */
#define SE23_COV_NMAX SE23_GAUSS_NMAX

/**
 * Checks the leading n x n block of A: finite, symmetric
 * (|A_ij - A_ji| <= tol s) and positive semidefinite within tolerance
 * (A + tol s I has a Cholesky factor), s = max_i |A_ii|,
 * tol = SE23_CFG_COV_TOL.
 * @return SE23_OK, SE23_ERR_NONFINITE, SE23_ERR_NOT_SYMMETRIC or
 *         SE23_ERR_NOT_PSD.
 */
se23_status_t se23_cov_check(const se23_real_t *A, int n, int stride);

/**
 * L = the lower Cholesky factor of the leading n x n block of A + shift I,
 * reading A's lower triangle only; L is n x n row-major with stride n, its
 * upper triangle zero. A pivot must exceed 16 eps (A_jj + shift) (eps of the
 * build's precision), so a numerically singular matrix is refused.
 * @return nonzero on success, 0 if A + shift I is not (numerically)
 *         positive definite or holds NaN; L is then unspecified.
 */
int se23_cov_chol(const se23_real_t *A, int n, int stride, se23_real_t shift,
                  se23_real_t *L);

/** x = (L L^T)^-1 x by forward and back substitution; L from se23_cov_chol. */
void se23_cov_chol_solve(const se23_real_t *L, int n, se23_real_t *x);

/** A linear map y = A x of R^n (n <= SE23_COV_NMAX); y never aliases x. */
typedef void (*se23_cov_map_fn)(const void *ctx, const se23_real_t *x,
                                se23_real_t *y);

/**
 * out = A P A^T for the map A, computed as A (A P)^T (P symmetric): n
 * applications of the map to the columns of P, n to the rows of A P. The
 * upper triangle is kept and mirrored, so out is exactly symmetric. P and
 * out have stride SE23_COV_NMAX and may alias.
 */
void se23_cov_congruence(se23_cov_map_fn map, const void *ctx, int n,
                         const se23_real_t *P, se23_real_t *out);

#endif /* SE23_COV_H */
