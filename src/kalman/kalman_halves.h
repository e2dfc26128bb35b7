/**
 * @file kalman_halves.h
 * @brief Internal: the two halves of se23_kalman_update (kalman.h), the
 *        covariance side (the update of P from the structure of H) and the
 *        retraction of the mean, and the small symmetric matrices the
 *        first needs (measurement noise R and innovation covariance S,
 *        m x m, m <= SE23_MEAS_MMAX): validation and a packed Cholesky
 *        factor. Not part of the public API.
 *
 * A translation unit apart from kalman.c on purpose: se23_kalman_update
 * calls the two halves one after the other, and neither may be inlined
 * into its frame: the covariance's work arrays (se23_kalman_work_t: one
 * n x m matrix, one packed m x m factor) must never share the stack with
 * the retraction, whose sin/cos may take newlib's large-argument
 * reduction. se23_kalman_update_work takes them from its caller.
 *
 * Packed storage: element (i, j), j <= i, of a lower triangle at
 * L[SE23_COV_TRI(i) + j] (cov_check.h).
 */
#ifndef SE23_KALMAN_PARTS_H
#define SE23_KALMAN_PARTS_H

#include <float.h>

#include "../cov/cov_check.h"
#include "se23/kalman.h"
#include "se23/types.h"
#include "../base/se23_math.h"

/** Reals of a packed lower triangle of SE23_MEAS_MMAX rows. */
#define SE23_MEAS_TRI SE23_COV_TRI(SE23_MEAS_MMAX)

/* |dx_k| <= SE23_KALMAN_CORR_MAX: |phi|^2 <= 3 CORR_MAX^2 cannot overflow,
 * and the entries of exp(phi^) and J(phi) (at most 3 in magnitude), so
 * those of R J(phi) nu (at most 27 CORR_MAX), stay far below MEAN_MAX.
 * |mean entry| <= SE23_KALMAN_MEAN_MAX: adding such a correction cannot
 * overflow. */
#if SE23_CFG_DOUBLE
#define SE23_KALMAN_CORR_MAX SE23_R(1e150)
#define SE23_KALMAN_MEAN_MAX (SE23_R(DBL_MAX) / SE23_R(4))
#else
#define SE23_KALMAN_CORR_MAX SE23_R(1e18)
#define SE23_KALMAN_MEAN_MAX (SE23_R(FLT_MAX) / SE23_R(4))
#endif

/* An update that leaves a variance below this fraction of its prior gets
 * the Joseph step (kalman_halves.c, joseph_refine); the filter checks its
 * state after such an update (ins_aid.c). A power of two, so that
 * 1 - ratio is exact. */
#define SE23_KALMAN_PIN_RATIO (SE23_R(1) / SE23_R(1024))

/**
 * se23_cov_check (cov_check.h) of the leading m x m block of A (row stride
 * `stride`), m <= SE23_MEAS_MMAX, with a work buffer sized for m: one
 * packed 9x9 factor instead of a 15x15 one on the stack.
 * @return SE23_OK, SE23_ERR_NONFINITE, SE23_ERR_NOT_SYMMETRIC or
 *         SE23_ERR_NOT_PSD.
 */
se23_status_t se23_meas_cov_check(const se23_real_t *A, int m, int stride);

/**
 * The covariance half of se23_kalman_update for a checked g (n = 9 or 15)
 * and y (checked; bit b of mask set for each 3-column block b of H that
 * holds a nonzero, zero blocks are skipped), in the work area wk: decides
 * everything that can fail, then stores P+ = P - U U^T into Pout (may
 * alias g->P.m), the correction dx (n values) and the NIS.
 * @return SE23_OK; SE23_ERR_NOT_PSD if S is not numerically positive
 *         definite (a pivot of its Cholesky factor not above 16 eps
 *         of its diagonal entry or below the smallest normal number);
 *         SE23_ERR_NONFINITE if a result could overflow: the NIS, the bound
 *         (tr(U U^T) NIS)^(1/2) of every |dx_k| above
 *         SE23_KALMAN_CORR_MAX, or tr P or tr(U U^T) above a quarter of
 *         the largest real (which keeps P+ finite). On error Pout and nis
 *         are not written (dx and wk are scratch).
 */
se23_status_t se23_kalman_cov_work(const se23_gauss_t *g, const se23_meas_t *y,
                                   unsigned mask, se23_kalman_work_t *wk,
                                   se23_real_t *dx, se23_real_t *nis, se23_real_t *Pout);

/** se23_kalman_cov_work with the work area on this call's stack. */
se23_status_t se23_kalman_cov(const se23_gauss_t *g, const se23_meas_t *y,
                              unsigned mask, se23_real_t *dx, se23_real_t *nis,
                              se23_real_t *Pout);

/**
 * Nonzero if an update of the n x n covariance P whose factor U has
 * usq = sum_i |U_i|^2 and whose NIS is q keeps every result finite: q
 * finite, usq and tr P at most a quarter of the largest real (then P -
 * U U^T is finite), and usq q (the square of the bound on every |dx_k|) at
 * most SE23_KALMAN_CORR_MAX^2. NaN fails.
 */
int se23_kalman_fits(const se23_real_t *P, int n, se23_real_t usq, se23_real_t q);

/** Nonzero if |U_i|^2 = s leaves the variance P_ii - s below
 *  SE23_KALMAN_PIN_RATIO r of p_ii: (1 - r) (p_ii - s) < r s, the test of
 *  the general update's pinning on the prior and U (the structured rest and
 *  NHC updates). */
static inline int se23_kalman_pins(se23_real_t p_ii, se23_real_t s)
{
    const se23_real_t r = SE23_KALMAN_PIN_RATIO;
    return (((SE23_R(1) - r) * (p_ii - s)) < (r * s)) ? 1 : 0;
}

/** Nonzero if every entry of g's mean (v, p, biases) is within
 *  SE23_KALMAN_MEAN_MAX (NaN is not): the retraction cannot overflow. */
int se23_kalman_mean_in_range(const se23_gauss_t *g);

/**
 * The mean half: out's T = g's T exp(dx_xi) with R re-orthonormalised,
 * biases + dx_db (n = 15) or copied, n. Cannot fail for |dx_k| <=
 * SE23_KALMAN_CORR_MAX and mean entries within SE23_KALMAN_MEAN_MAX:
 * every value stays finite, and R exp(phi^) is within SE23_CFG_ROT_TOL + a
 * few eps of SO(3), which one Newton-Schulz step brings back to rounding
 * level. out may alias g
 * (its P is not touched).
 */
void se23_kalman_retract(const se23_gauss_t *g, const se23_real_t *dx,
                         se23_gauss_t *out);

#endif /* SE23_KALMAN_PARTS_H */
