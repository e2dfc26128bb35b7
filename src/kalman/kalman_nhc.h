/**
 * @file kalman_nhc.h
 * @brief Internal: the navigation filter's non-holonomic constraint (ins.h,
 *        "Vehicles") as one structured Kalman update of its two rows. Not
 *        part of the public API.
 *
 * Measurement: se23_meas_nhc's (kalman.h) on the state T = Tbar exp(xi),
 * b = bbar + db in the coordinates the caller gives (the filter's user
 * state): with u = Rbar^T vbar and c_r the columns 1 and 2 of C_bv,
 *   H_r = [(c_r x u)^T, c_r^T, 0, 0, 0],  z_r = -c_r . u,  R = r I_2,
 * two rows nonzero only in the columns phi and nu. The update is the one
 * se23_kalman_update makes with these rows (m = 2; test_kalman_nhc
 * compares them to rounding).
 *
 * Structure. C = P H^T takes the 6 columns phi, nu of each row of P; S =
 * H C + R is 2 x 2, its Cholesky factor two pivots; U = C L^-T and dx =
 * U w follow row by row of P, and P+ = P - U U^T in one pass. Costs in
 * kalman_nhc.c.
 *
 * Scope. Only the steady state, as se23_kalman_rest (kalman_rest.h): an
 * update that would leave a variance below SE23_KALMAN_PIN_RATIO of its
 * prior needs se23_kalman_update's Joseph step and the filter's check
 * (ins_aid.c), and is refused here before anything is written
 * (SE23_ERR_DOMAIN): the caller takes that path.
 */
#ifndef SE23_KALMAN_NHC_H
#define SE23_KALMAN_NHC_H

#include "se23/kalman.h"
#include "se23/types.h"

/** The NHC's two rows (file comment). */
typedef struct {
    se23_real_t h[2][6]; /**< rows of H in the columns phi, nu: [c_r x u, c_r] */
    se23_real_t z[2];    /**< innovations -c_r . u [m/s] */
    se23_real_t r;       /**< noise variance per row [m^2/s^2], > 0 */
} se23_nhc_meas_t;

/**
 * y = the NHC rows of the state T with the mounting C_bv and 1-sigma sigma
 * (se23_meas_nhc's, without its checks: T and C_bv are trusted, the
 * filter's). 27 multiplies.
 */
void se23_nhc_rows(const se23_pose_t *T, const se23_mat3_t *C_bv, se23_real_t sigma,
                   se23_nhc_meas_t *y);

/**
 * out = g updated with the NHC rows y (file comment), the gain's factor in
 * the work area wk (scratch); *nis its NIS (2 degrees of freedom) if nis is
 * not NULL. g is trusted (the filter's state); out may alias g.
 * @return SE23_OK; SE23_ERR_DIM (n not 9 or 15); SE23_ERR_NOT_PSD (S not
 *         numerically positive definite, the pivot test of
 *         se23_kalman_update; NaN rows land here); SE23_ERR_NONFINITE (a
 *         mean entry beyond SE23_KALMAN_MEAN_MAX, or a result that could
 *         overflow: se23_kalman_fits); SE23_ERR_DOMAIN (the update would
 *         pin a variance: file comment, "Scope"); with
 *         SE23_CFG_DEEP_CHECKS also the statuses of se23_gauss_check. On
 *         error nothing is written (out, nis).
 */
se23_status_t se23_kalman_nhc(const se23_gauss_t *g, const se23_nhc_meas_t *y,
                              se23_kalman_work_t *wk, se23_gauss_t *out, se23_real_t *nis);

/**
 * The covariance half of se23_kalman_nhc (kalman_nhc.c; the mean half and
 * the state's checks are kalman.c's, shared with the rest update) for a g
 * whose mean is within range: decides everything that can fail, then
 * stores P+ into Pout (may alias g->P.m), dx (n values) and the NIS q. On
 * error Pout and q are not written (dx and wk are scratch).
 */
se23_status_t se23_kalman_nhc_cov(const se23_gauss_t *g, const se23_nhc_meas_t *y,
                                  se23_kalman_work_t *wk, se23_real_t *dx, se23_real_t *q,
                                  se23_real_t *Pout);

#endif /* SE23_KALMAN_NHC_H */
