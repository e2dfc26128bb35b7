/**
 * @file kalman_rest.h
 * @brief Internal: the navigation filter's rest updates (ins.h,
 *        "Zero-velocity updates") as one structured Kalman update on the
 *        state in the filter's coordinates: zero velocity (ZUPT) and, when
 *        due, zero angular rate (ZARU). Not part of the public API.
 *
 * Measurements, on the state T' = Tbar' exp(xi'), b = bbar + db of
 * gauss.h, carried (R, v' = v + Omega x p, p) on rotating Earth, the
 * user's (R, v, p) on flat Earth (Omega = 0):
 *   ZUPT  the body-frame velocity R^T v = 0 of the user's v = v' - Omega x p,
 *         z_v = -Rbar^T vbar,  H_v = [0, I, -a^, 0, 0],  noise r_v I,
 *   ZARU  the rate w_meas + b_g - a = 0 a body at rest senses less the Earth
 *         rate, z_w = -(w_meas + bbar_g - a),  H_w = [0, 0, 0, I, 0],
 *         noise r_w I (15 states only),
 * a = Rbar^T Omega the Earth rate in the body frame. v = vbar + Rbar nu to
 * first order, so H_v's nu block is I; nu = nu' - a^ rho' is gauss.h's
 * carried-to-user map M (a = 0 on flat Earth: H_v selects nu). R^T v = 0
 * with the isotropic noise r_v I carries the information of the nav-frame
 * v = 0 with the same noise (an orthogonal map of the measurement), so the
 * update, its NIS and the ZUPT of se23_meas_vel_nav agree to first order in
 * the error; the update is the one se23_kalman_update makes with these
 * rows of H (m = 3 or 6; test_kalman_rest compares them to rounding).
 *
 * Structure. With H selecting (a shear of) 3-column blocks of P, the
 * elimination of S = H P H^T + R is blockwise: the ZUPT's block S_v =
 * P_vv-sheared + r_v I (3x3), then the ZARU's Schur complement in the
 * updated P; their Cholesky factors are the two diagonal blocks of S's,
 * the columns of U = P H^T L^-T follow row by row of P, and the NIS of the
 * ZUPT rows alone, z_v^T S_v^-1 z_v, is the first block's. Costs in
 * kalman_rest.c.
 *
 * Scope. Only the steady state: an update that would leave a variance
 * below SE23_KALMAN_PIN_RATIO of its prior needs se23_kalman_update's
 * Joseph step and the filter's check (ins_aid.c), and is refused here
 * before anything is written (SE23_ERR_DOMAIN): the caller takes that
 * path.
 */
#ifndef SE23_KALMAN_REST_H
#define SE23_KALMAN_REST_H

#include "se23/kalman.h"
#include "se23/types.h"

/** The rest measurements of one stationary sample (file comment). */
typedef struct {
    se23_vec3_t a;     /**< Rbar^T Omega, the Earth rate in the body frame (0: flat) */
    se23_vec3_t z_v;   /**< ZUPT innovation -Rbar^T vbar (the user's v) [m/s] */
    se23_vec3_t z_w;   /**< ZARU innovation -(w_meas + bbar_g - a) [rad/s] */
    se23_real_t r_v;   /**< ZUPT noise variance per axis [m^2/s^2], > 0 */
    se23_real_t r_w;   /**< ZARU noise variance per axis [rad^2/s^2], > 0 */
    int zaru;          /**< nonzero: the ZARU rows too (15 states) */
} se23_rest_meas_t;

/**
 * out = g updated with the rest measurements y (file comment), the gain's
 * factor in the work area wk (scratch); *nis = the NIS of the ZUPT rows
 * alone (3 degrees of freedom). g is trusted (the filter's state); out may
 * alias g. In kalman.c: the covariance half (se23_kalman_rest_cov) returns
 * before the retraction runs, so that their frames never stack.
 * @return SE23_OK; SE23_ERR_DIM (n not 9 or 15, or ZARU with 9 states);
 *         SE23_ERR_NOT_PSD (a block of S not numerically positive
 *         definite, the pivot test of se23_kalman_update);
 *         SE23_ERR_NONFINITE (a mean entry beyond SE23_KALMAN_MEAN_MAX, or
 *         a result that could overflow: se23_kalman_fits);
 *         SE23_ERR_DOMAIN (the update would pin a variance: file comment,
 *         "Scope"); with SE23_CFG_DEEP_CHECKS also the statuses of
 *         se23_gauss_check. On error nothing is written (out, nis).
 */
se23_status_t se23_kalman_rest(const se23_gauss_t *g, const se23_rest_meas_t *y,
                               se23_kalman_work_t *wk, se23_gauss_t *out, se23_real_t *nis);

/**
 * The covariance half of se23_kalman_rest (kalman_rest.c) for a g whose
 * mean is within range: decides everything that can fail, then stores
 * P+ into Pout (may alias g->P.m), the correction dx (n values) and the
 * ZUPT's NIS. The statuses of se23_kalman_rest but for the mean's range;
 * on error Pout and nis are not written (dx and wk are scratch).
 */
se23_status_t se23_kalman_rest_cov(const se23_gauss_t *g, const se23_rest_meas_t *y,
                                   se23_kalman_work_t *wk, se23_real_t *dx, se23_real_t *nis,
                                   se23_real_t *Pout);

#endif /* SE23_KALMAN_REST_H */
