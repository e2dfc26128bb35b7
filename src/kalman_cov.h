/**
 * @file kalman_cov.h
 * @brief Internal: the covariance side of the measurement update
 *        (kalman.h): the update of P from the structure of H, and the
 *        small symmetric matrices it needs (measurement noise R and
 *        innovation covariance S, m x m, m <= SE23_MEAS_MMAX): validation
 *        and a packed Cholesky factor. Not part of the public API.
 *
 * A translation unit of its own on purpose: its work arrays (one n x m
 * matrix and one packed m x m factor) must not share a stack frame with
 * the retraction of kalman.c, whose sin/cos may take newlib's
 * large-argument reduction (see the stack table of the README).
 *
 * Packed storage: element (i, j), j <= i, of a lower triangle at
 * L[se23_tri(i) + j].
 */
#ifndef SE23_KALMAN_COV_H
#define SE23_KALMAN_COV_H

#include "se23/kalman.h"
#include "se23/types.h"

/** Reals of a packed lower triangle of SE23_MEAS_MMAX rows. */
#define SE23_MEAS_TRI (SE23_MEAS_MMAX * (SE23_MEAS_MMAX + 1) / 2)

/** 3-column blocks of the 15-dim error (phi, nu, rho, b_g, b_a). */
#define SE23_KALMAN_NBLK (SE23_GAUSS_NMAX / 3)

/** Offset of row i of a packed lower triangle, 0 <= i < SE23_MEAS_MMAX. */
static inline int se23_tri(int i)
{
    static const int offset[SE23_MEAS_MMAX] = {0, 1, 3, 6, 10, 15, 21, 28, 36};
    return offset[i];
}

/**
 * In place: L holds the packed lower triangle of a symmetric m x m A on
 * entry, its lower Cholesky factor on exit, except that the diagonal holds
 * the reciprocals 1 / L_jj (what the solves need). Refused (returns 0, L
 * then unspecified) unless every pivot is finite, exceeds 16 eps A_jj (the
 * rule of cov.h) and is at least the smallest normal number of the
 * precision (so that 1 / L_jj is finite and accurate); NaN is refused.
 * m^3/6 multiply-adds, m square roots and divisions.
 */
int se23_meas_chol(se23_real_t *L, int m);

/**
 * Checks the leading m x m block of A (row stride `stride`) as gauss.h
 * checks a covariance, with the same result as se23_cov_check (cov.h):
 * finite, symmetric (|A_ij - A_ji| <= tol s), A + (tol s + FLT_MIN) I
 * factors by se23_meas_chol, s = max_i |A_ii|, tol = SE23_CFG_COV_TOL.
 * Stack: one packed 9x9 factor instead of cov.h's 15x15 one.
 * @return SE23_OK, SE23_ERR_NONFINITE, SE23_ERR_NOT_SYMMETRIC or
 *         SE23_ERR_NOT_PSD.
 */
se23_status_t se23_meas_cov_check(const se23_real_t *A, int m, int stride);

/**
 * The covariance part of se23_kalman_update for a checked g (n = 9 or 15)
 * and y (checked, blk[0..nb-1] its active blocks, ascending): decides
 * everything that can fail, then stores P+ = P - U U^T into Pout (may
 * alias g->P.m), the correction dx (n values) and the NIS.
 * @return SE23_OK; SE23_ERR_NOT_PSD if S is not numerically positive
 *         definite (se23_meas_chol); SE23_ERR_NONFINITE if a result would
 *         overflow (|dx_k| > corr_max, the NIS, or an entry of P+).
 *         On error Pout and nis are not written (dx is scratch).
 */
se23_status_t se23_kalman_cov(const se23_gauss_t *g, const se23_meas_t *y,
                              const int *blk, int nb, se23_real_t corr_max,
                              se23_real_t *dx, se23_real_t *nis,
                              se23_real_t *Pout);

#endif /* SE23_KALMAN_COV_H */
