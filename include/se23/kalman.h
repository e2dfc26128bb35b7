/**
 * @file kalman.h
 * @brief Kalman update of a concentrated Gaussian in exponential coordinates
 *        (DESIGN.md section 3, "Measurement update") and ready-made
 *        measurement models: position and velocity in the navigation frame
 *        (GNSS, with lever arm), velocity in the body frame (odometer),
 *        zero velocity (ZUPT) and zero angular rate (ZARU).
 *
 * A measurement y = h(T, b) + noise, noise ~ N(0, R), is linearised at the
 * estimate in the error of gauss.h, T = Tbar exp(xi), b = bbar + db:
 *   y = h(Tbar, bbar) + H (xi, db) + O(|xi|^2) + noise.
 * The update (innovation z = y - h(Tbar, bbar), m = 1..9 rows):
 *   C = P H^T,  S = H C + R = L L^T      Cholesky, no explicit inverse
 *   K = C S^-1,  dx = K z,  nis = z^T S^-1 z
 *   X = P - C S^-1 C^T = P - U U^T, U = C L^-T
 *   P+ = X - K (H X - R K^T)
 *   Tbar+ = Tbar exp(dx_xi) (R re-orthonormalised),  bbar+ = bbar + dx_db
 * P+ equals the Joseph form (I - K H) P (I - K H)^T + K R K^T in exact
 * arithmetic (there H X = R K^T). X, the Schur complement of S (the
 * Cholesky elimination step), is positive semidefinite to rounding
 * relative to P; the second line, run when X leaves a variance below
 * 2^-10 of its prior (else P+ = X), is the Joseph form applied to X, which
 * keeps a measured state's posterior accurate however far R is below its
 * prior (up to 1/eps^2: a 1 km prior and a 1 cm fix in float). A state
 * only correlated with a measured one keeps X's error, eps times its
 * prior variance. P+ is exactly symmetric (upper triangle computed,
 * mirrored), its variances never negative (a rounding of zero is raised
 * to 0). Only the
 * 3-column blocks of H (phi, nu, rho, b_g, b_a) that hold a nonzero take
 * part: the models below touch one to three blocks, so a GNSS update
 * costs about 900 multiply-adds (1,700 with the Joseph step) instead of
 * the 9,500 of the dense Joseph form
 * (src/kalman/kalman_halves.c gives the count). P+ is the covariance of
 * the error at the old estimate; the O(|dx|) change of coordinates of the
 * retraction (a Jacobian close to I) is neglected, as usual in
 * error-state filters.
 *
 * Validation (types.h): y is the caller's and is checked on every call
 * (m, z and H finite, R symmetric PSD); the state g is trusted: only n is
 * checked (9 or 15), se23_gauss_check runs only with SE23_CFG_DEEP_CHECKS.
 * A result that would overflow is refused before anything is stored, so
 * SE23_OK always means finite outputs, R in SO(3) within
 * SE23_CFG_ROT_TOL (an R that passed the rotation test comes back
 * re-orthonormalised) and P+ symmetric PSD.
 *
 * Independent measurements may be applied one after the other. A filter
 * that carries the rotating-Earth state T' (imu.h) converts with
 * se23_gauss_from_carried, updates, and converts back with
 * se23_gauss_to_carried; position models are the same on T and T'.
 *
 * Storage: H is m x 15 row-major with stride 15, (i, j) at H[15*i + j];
 * only its first n columns are read (n of the state). R is m x m row-major
 * with stride 9, (i, j) at R[9*i + j].
 *
 * Functions index:
 *   se23_kalman_update       the update above
 *   se23_kalman_update_work  the same, with the caller's work area
 *   se23_meas_pos_nav        GNSS position (with lever arm)
 *   se23_meas_vel_nav        GNSS velocity; zero velocity (ZUPT) with v_n = 0
 *   se23_meas_vel_nav_lever  GNSS velocity of an antenna at a lever arm
 *   se23_meas_vel_body       velocity in the body frame (odometer; ZUPT too)
 *   se23_meas_zero_rate      zero angular rate (ZARU), gyro bias only
 *   se23_meas_nhc            a wheeled vehicle's non-holonomic constraint
 *
 * Zero velocity (ZUPT) needs no model of its own: at rest v = 0, so
 * se23_meas_vel_nav with v_n the zero vector (H = [0, R, 0, 0, 0]) is the
 * update; se23_meas_vel_body with v_b = 0 states the same constraint in
 * body axes (cov then in body axes; its H also couples phi through
 * (R^T vbar)^). Pair it with se23_meas_zero_rate to also observe the gyro
 * bias while standing still.
 *
 * All functions accept outputs that alias inputs. The models write m = 3,
 * z[0..2], rows 0..2 of H (all 15 columns; the bias columns a model does
 * not use are 0) and R's leading 3x3 block; the entries beyond m rows are
 * left as they were, and se23_kalman_update reads only z[0..m-1], rows
 * 0..m-1 of H and R's leading m x m block.
 */
#ifndef SE23_KALMAN_H
#define SE23_KALMAN_H

#include "se23/gauss.h"
#include "se23/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Most rows of one measurement. */
#define SE23_MEAS_MMAX 9

/** One linearised measurement: innovation, Jacobian, noise covariance. */
typedef struct {
    int m;                                           /**< rows, 1..9 */
    se23_real_t z[SE23_MEAS_MMAX];                   /**< innovation y - h(Tbar, bbar) */
    se23_real_t H[SE23_MEAS_MMAX * SE23_GAUSS_NMAX]; /**< dh/d(xi, db), (i, j) at H[15*i + j] */
    se23_real_t R[SE23_MEAS_MMAX * SE23_MEAS_MMAX];  /**< noise covariance, (i, j) at R[9*i + j] */
} se23_meas_t;

/** Work area of se23_kalman_update_work (work.h, "Contents"): the factors
 *  of one update's gain, the largest part of se23_kalman_update's stack. */
typedef struct {
    se23_real_t U[SE23_GAUSS_NMAX * SE23_MEAS_MMAX];          /**< C L^-T */
    se23_real_t L[SE23_MEAS_MMAX * (SE23_MEAS_MMAX + 1) / 2]; /**< S = L L^T, packed */
    se23_real_t w[SE23_MEAS_MMAX];                            /**< L^-1 z */
} se23_kalman_work_t;

/**
 * out = g updated with the measurement y (file comment).
 * @param g   the state, trusted (produced by the library or checked once
 *            with se23_gauss_check); only g->n is checked.
 * @param y   the measurement model (a se23_meas_* result)
 * @param out out: the updated state (written only on SE23_OK); may alias g
 * @param nis if not NULL, receives the normalised innovation squared
 *            z^T S^-1 z (chi^2 with m degrees of freedom for a consistent
 *            filter; use it to gate outliers).
 * @return SE23_ERR_NULL; SE23_ERR_DIM unless g->n is 9 or 15 and
 *         1 <= y->m <= 9; SE23_ERR_NONFINITE if z or the first n columns
 *         of H hold NaN or Inf; for R the covariance statuses of gauss.h
 *         (SE23_ERR_NONFINITE, SE23_ERR_NOT_SYMMETRIC, SE23_ERR_NOT_PSD);
 *         SE23_ERR_NOT_PSD if S is not numerically positive definite (a
 *         pivot of its Cholesky factor not above 16 eps times its diagonal
 *         entry, or below the smallest normal number of the precision,
 *         e.g. P = 0 with a denormal R); SE23_ERR_NONFINITE if a result
 *         could overflow: the NIS; a correction, when the bound
 *         (tr(K S K^T) NIS)^(1/2) of every |dx_k| is above 1e18 (float) /
 *         1e150 (double); an entry of P+, when tr P or tr(K S K^T) is
 *         above a quarter of the largest finite value; or a mean entry of
 *         g above that quarter (or NaN). With
 *         SE23_CFG_DEEP_CHECKS also the statuses of se23_gauss_check.
 *         On error nothing is written (out, nis).
 */
se23_status_t se23_kalman_update(const se23_gauss_t *g, const se23_meas_t *y,
                                 se23_gauss_t *out, se23_real_t *nis);

/**
 * se23_kalman_update with the gain's factors in the caller's work area w
 * instead of on the stack: the same statuses and the same results, bit
 * for bit. w is scratch (unspecified after the call) and must not overlap
 * another argument.
 * @param g   the state, as in se23_kalman_update
 * @param y   the measurement model
 * @param w   the work area (scratch)
 * @param out out: the updated state (written only on SE23_OK); may alias g
 * @param nis if not NULL, receives the NIS
 * @return the statuses of se23_kalman_update; SE23_ERR_NULL also for a
 *         NULL w. On error nothing is written (out, nis).
 */
se23_status_t se23_kalman_update_work(const se23_gauss_t *g, const se23_meas_t *y,
                                      se23_kalman_work_t *w, se23_gauss_t *out,
                                      se23_real_t *nis);

/**
 * y = the position of a GNSS antenna at lever arm l_b (body frame) measured
 * in the nav frame: h(T) = p + R l_b, so
 *   H = [-R l_b^, 0, R, 0] (columns phi, nu, rho, db).
 * @param T      estimate Tbar
 * @param p_n    measured position, nav frame [m]
 * @param lever_b antenna position in the body frame [m] (zero vector if none)
 * @param cov    measurement noise covariance [m^2]
 * @param y      out: the measurement model (written only on SE23_OK)
 * @return SE23_ERR_NONFINITE (an input holds NaN or Inf, or the residual
 *         or an entry of H would overflow), SE23_ERR_NOT_ROTATION (T), or
 *         the covariance statuses of gauss.h for cov. On error y is not
 *         written.
 */
se23_status_t se23_meas_pos_nav(const se23_pose_t *T, const se23_vec3_t *p_n,
                                const se23_vec3_t *lever_b,
                                const se23_mat3_t *cov, se23_meas_t *y);

/**
 * y = the velocity measured in the nav frame: h(T) = v, H = [0, R, 0, 0].
 * @param T   estimate Tbar
 * @param v_n measured velocity, nav frame [m/s]
 * @param cov measurement noise covariance [m^2/s^2]
 * @param y   out: the measurement model (written only on SE23_OK)
 * @return as se23_meas_pos_nav.
 */
se23_status_t se23_meas_vel_nav(const se23_pose_t *T, const se23_vec3_t *v_n,
                                const se23_mat3_t *cov, se23_meas_t *y);

/**
 * y = the velocity of a GNSS antenna at lever arm l_b (body frame) measured
 * in the nav frame. The antenna moves with v + R (w x l_b), w the true body
 * angular rate in body axes. The gyro measures the rate relative to inertial
 * space, while the antenna's velocity relative to the Earth follows the
 * rate relative to the nav frame; the difference, the Earth rate, adds
 * |w_ie| |l_b| = 7.3e-5 m/s per metre of lever and is neglected. With the
 * gyro bias convention of gauss.h (w = w_meas + b_g), the caller passes
 * the bias-corrected rate w_b = w_meas + bbar_g and
 *   h(T, b) = v + R (w x l_b),  w = w_b + db_g.
 * Linearised at Tbar, bbar with R = Rbar exp(phi^),
 * v = vbar + Rbar nu + O(|xi|^2), u = w_b x l_b and a^ b = a x b:
 *   phi:  Rbar phi^ u = -Rbar u^ phi                        -> -R u^
 *   nu:   Rbar nu                                           ->  R
 *   b_g:  Rbar (db_g x l_b) = -Rbar l_b^ db_g               -> -R l_b^
 * so H = [-R (w_b x l_b)^, R, 0, -R l_b^, 0] (columns phi, nu, rho, b_g,
 * b_a) and z = v_n - vbar - Rbar (w_b x l_b). The b_g columns (9..11) are
 * used by a 15-state filter; se23_kalman_update with a 9-state g reads only
 * the first 9 columns of H (file comment) and ignores the rest, so there
 * the gyro bias is taken as known (its error not modelled). With l_b = 0
 * this is se23_meas_vel_nav.
 * @param T       estimate Tbar
 * @param w_b     bias-corrected body angular rate w_meas + bbar_g [rad/s],
 *                e.g. of the IMU sample at the time of the fix
 * @param lever_b antenna position in the body frame [m]
 * @param v_n     measured antenna velocity, nav frame [m/s]
 * @param cov     measurement noise covariance [m^2/s^2] (include the gyro
 *                noise mapped through the lever, |l_b|^2 sigma_w^2, if it
 *                matters)
 * @param y       out: the measurement model (written only on SE23_OK)
 * @return as se23_meas_pos_nav.
 */
se23_status_t se23_meas_vel_nav_lever(const se23_pose_t *T,
                                      const se23_vec3_t *w_b,
                                      const se23_vec3_t *lever_b,
                                      const se23_vec3_t *v_n,
                                      const se23_mat3_t *cov, se23_meas_t *y);

/**
 * y = the velocity measured in the body frame (zero-velocity update with
 * v_b = 0, or an odometer): h(T) = R^T v, H = [(R^T v)^, I, 0, 0].
 * @param T   estimate Tbar
 * @param v_b measured velocity, body frame [m/s]
 * @param cov measurement noise covariance [m^2/s^2]
 * @param y   out: the measurement model (written only on SE23_OK)
 * @return as se23_meas_pos_nav.
 */
se23_status_t se23_meas_vel_body(const se23_pose_t *T, const se23_vec3_t *v_b,
                                 const se23_mat3_t *cov, se23_meas_t *y);

/**
 * y = zero angular rate (ZARU): the vehicle is known to be at rest, so the
 * true body rate w = w_meas + b_g (gauss.h's bias convention) is taken as
 * 0: the pseudo-measurement y = 0 of
 *   h(b) = w_meas + b_g,  H = [0, 0, 0, I, 0] (columns phi, nu, rho, b_g,
 *   b_a),  z = -(w_meas + bbar_g),
 * which pulls bbar_g toward -w_meas.
 * The Earth rate is neglected: at rest the true rate is R^T w_ie, up to
 * 7.29e-5 rad/s (15 deg/h), and this model leaves it in the bias estimate.
 * That is below the bias uncertainty of MEMS gyros, which the model is
 * for; cov should cover it (a standard deviation of about 7.3e-5 rad/s per
 * axis at least, plus the gyro noise over the averaging window). A
 * navigation-grade gyro needs the expected rate R^T w_ie, which depends
 * on the attitude (an H_phi block (R^T w_ie)^, the gyrocompassing signal):
 * a constant expected rate would be inconsistent there, so none is taken.
 * Only meaningful for a 15-state filter (n = 15): the first 9 columns of H
 * are zero, so with n = 9 se23_kalman_update leaves the state unchanged.
 * @param w_meas the raw gyro measurement [rad/s] (or its mean over the
 *               rest interval; then scale cov accordingly)
 * @param b_g    the gyro bias estimate bbar_g [rad/s] (g->b_g)
 * @param cov    noise covariance of the rate [rad^2/s^2]
 * @param y      out: the measurement model (written only on SE23_OK)
 * @return SE23_ERR_NONFINITE (an input holds NaN or Inf, or w_meas + b_g
 *         would overflow), or the covariance statuses of gauss.h for cov.
 *         On error y is not written.
 */
se23_status_t se23_meas_zero_rate(const se23_vec3_t *w_meas,
                                  const se23_vec3_t *b_g,
                                  const se23_mat3_t *cov, se23_meas_t *y);

/** Largest 1-sigma se23_meas_nhc takes [m/s]. */
#define SE23_MEAS_NHC_SIGMA_MAX SE23_R(1e3)

/**
 * y = the non-holonomic constraint of a wheeled vehicle: it neither slides
 * sideways nor leaves the road, so its velocity has no lateral and no
 * vertical component in the vehicle frame v (forward, right, down). The
 * IMU is mounted with x_b = C_bv x_v. The pseudo-measurement 0 of the two
 * rows
 *   h(T) = [e_2, e_3]^T C_bv^T R^T v,
 * linearised as se23_meas_vel_body (R^T v = u + u^ phi + nu, u = Rbar^T
 * vbar): with c_r the columns 2 and 3 of C_bv (the vehicle's right and
 * down axes in the body frame),
 *   H_r = [(c_r x u)^T, c_r^T, 0, 0, 0],  z_r = -c_r . u,  R = sigma^2 I_2.
 * The constraint holds at the vehicle's reference point (the rear axle's
 * middle); an IMU away from it also moves with w x l, which sigma covers
 * (the caller's choice, see the car preset in ins.h).
 * @param T     estimate Tbar
 * @param C_bv  the mounting rotation, vehicle to body frame
 * @param sigma 1-sigma of each velocity component [m/s], in (0,
 *              SE23_MEAS_NHC_SIGMA_MAX]
 * @param y     out: the measurement model, m = 2 (written only on SE23_OK)
 * @return SE23_ERR_NOT_ROTATION (T's R or C_bv), SE23_ERR_NONFINITE (T, or
 *         a residual or entry of H that would overflow), SE23_ERR_DOMAIN
 *         (sigma not in its range, NaN included). On error y is not
 *         written.
 */
se23_status_t se23_meas_nhc(const se23_pose_t *T, const se23_mat3_t *C_bv, se23_real_t sigma,
                            se23_meas_t *y);

#ifdef __cplusplus
}
#endif

#endif /* SE23_KALMAN_H */
