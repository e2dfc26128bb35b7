/**
 * @file align.h
 * @brief Static alignment: the attitude of a vehicle at rest from the mean
 *        specific force (roll and pitch) and, for good enough gyros, the
 *        mean angular rate (heading, by gyrocompassing), with the
 *        covariance of the attitude error in the library's convention.
 *
 * Attitude. R maps body to nav (types.h) and is written with yaw, pitch
 * and roll about the nav frame's own axes (earth.h: NED x north, y east,
 * z down; ENU x east, y north, z up):
 *   R = Rz(yaw) Ry(pitch) Rx(roll),
 *   Rz(a) = [[c, -s, 0], [s, c, 0], [0, 0, 1]] (c = cos a, s = sin a), etc.
 * NED: yaw is the heading of the body x axis from north, positive towards
 * east (clockwise seen from above), the usual heading of a forward-right-
 * down body. ENU: yaw is the angle of the body x axis from east, positive
 * towards north (counter-clockwise seen from above); for a body with x
 * forward, yaw = pi/2 - heading. At pitch = +-90 deg (body x vertical) roll
 * is set to 0 and yaw alone sets the rotation about the vertical.
 *
 * Levelling. At rest the specific force is f_b = R^T (-g_n), g_n = (0, 0, g)
 * in NED and (0, 0, -g) in ENU. So d = s f_b / |f_b| (s = -1 in NED,
 * +1 in ENU) is the nav z axis in body coordinates, R^T e_z, which is the
 * third row of R: d = (-sin pitch, cos pitch sin roll, cos pitch cos roll).
 * Hence sin pitch = -d_x, cos pitch = sqrt(d_y^2 + d_z^2) >= 0, and
 * (cos roll, sin roll) = (d_z, d_y) / cos pitch (the pair computed scaled,
 * so that it stays a unit vector for any pitch). No yaw information is in
 * f: the caller gives it, or se23_align_gyrocompass finds it.
 *
 * Covariance (se23_align_cov). The error is the library's: the true
 * attitude is R = Rbar exp(phi^), phi in the BODY frame (T = Tbar exp(xi),
 * xi = (phi, nu, rho)). Write the same error in the nav frame,
 * R = exp(eps^) Rbar: since Rbar exp(phi^) Rbar^T = exp((Rbar phi)^),
 * eps = Rbar phi, so P_phi = Rbar^T P_eps Rbar.
 *  - Tilt. f_mean = f_b + e, e the mean of N samples of white noise of
 *    per-axis std sigma_f: e ~ N(0, sigma_f^2 / N I). The estimate
 *    satisfies Rbar^T e_z = dbar = s f_mean / |f_mean|, the truth
 *    R^T e_z = d. To first order, R^T e_z = Rbar^T (e_z - eps x e_z), so
 *    Rbar (dbar - d) = eps x e_z = (eps_y, -eps_x, 0); and
 *    dbar - d = s (I - d d^T) e / g (|f_b| = g). The nav-frame vector
 *    Rbar e is again N(0, sigma_f^2 / N I), so eps_x and eps_y are
 *    independent with std  tilt = sigma_f / (g sqrt N), and the
 *    vertical component of the noise (along d) leaves the attitude alone.
 *  - Yaw. A heading error dpsi turns the whole attitude about the nav
 *    vertical: R = Rz(dpsi) Rbar, eps = (0, 0, dpsi). The model takes it
 *    with std sigma_yaw, independent of the tilt error.
 *  So P_eps = diag(tilt^2, tilt^2, sigma_yaw^2) (z the vertical in NED
 *  and ENU alike) and, with r = Rbar^T e_z (the third row of Rbar),
 *    P_phi = Rbar^T P_eps Rbar = tilt^2 I + (sigma_yaw^2 - tilt^2) r r^T,
 *  the form computed (symmetric by construction; from R^T R = I).
 *  Neglected first-order couplings of the vertical error with the tilt,
 *  both of size tilt x tan(angle), far below any heading source's error
 *  (tilt ~ 1e-3 rad or less) unless the angle nears 90 deg:
 *   (i) a yaw held fixed as the Euler angle of se23_align_level: a tilt
 *       error then also turns R about the vertical by -tan(pitch) eps_a,
 *       eps_a the tilt about the horizontal direction of body x
 *       (a = Rz(yaw) e_x), since d(Rz Ry Rx) = (e_z dyaw + Rz e_y dpitch +
 *       Rz Ry e_x droll)^ R and Rz Ry e_x = cos(pitch) a - sin(pitch) e_z;
 *   (ii) gyrocompassing: tan(lat) times the tilt about north (below).
 *
 * Gyrocompassing (se23_align_gyrocompass). At rest the gyro reads the Earth
 * rate, w_b = R^T w_ie_n, w_ie_n = W (cos lat, 0, -sin lat) in NED and
 * W (0, cos lat, sin lat) in ENU (earth.h, W = SE23_WGS84_OMEGA_E). Level
 * first with yaw 0, R0 = Ry(pitch) Rx(roll) = Rz(yaw)^T R; then
 * w_l = R0 w_b = Rz(yaw)^T w_ie_n, whose horizontal part is
 *   h = (w_l_x, w_l_y) = W cos(lat) (cos yaw, -sin yaw)   NED,
 *                        W cos(lat) (sin yaw,  cos yaw)   ENU,
 * so yaw = atan2(-h_y, h_x) (NED), atan2(h_x, h_y) (ENU), R = Rz(yaw) R0.
 * The gyro noise of the mean (per-axis std sigma_w / sqrt N) perpendicular
 * to h turns h by its size over |h|:
 *   sigma_yaw = sigma_w / (sqrt(N) W |cos lat|).
 * Neglected (first order, not in sigma_yaw): the tilt error moves the
 * vertical Earth rate into h, a heading error of about tilt |tan lat|,
 * correlated with the tilt about north; it is below sigma_yaw by the factor
 * (sigma_f / g) W |sin lat| / sigma_w (6e-3 for a navigation-grade IMU at
 * 100 Hz: 4.9e-3 m/s^2 and 5.8e-6 rad/s per sample). Gyro bias is not
 * noise: a bias b across h adds b / (W cos lat) of heading error, which no
 * averaging removes (0.01 deg/h gives 0.67 mrad / cos lat).
 *
 * Plausibility. At rest |f_mean| is g: alignment refuses |f_mean| outside
 * [SE23_ALIGN_F_MIN, SE23_ALIGN_F_MAX] x SE23_ALIGN_G0 (a vehicle moving,
 * or wrong units). Gyrocompassing refuses a heading std above
 * SE23_ALIGN_YAW_STD_MAX (near the poles, where cos lat -> 0, or gyros too
 * noisy), and a measured |h| outside [SE23_ALIGN_RATE_MIN,
 * SE23_ALIGN_RATE_MAX] x W |cos lat| (a gyro bias of the order of the Earth
 * rate or a turning vehicle: the reading is not the Earth rate).
 *
 * Functions index:
 *   se23_align_level        R from f_mean (roll, pitch) and a given yaw
 *   se23_align_cov          covariance of the body-frame attitude error phi
 *   se23_align_gyrocompass  R and yaw from f_mean and w_mean, with sigma_yaw
 *
 * All functions return a status and write their outputs only on SE23_OK;
 * on SE23_OK, R is in SO(3) (to a few epsilons) and P is symmetric PSD.
 */
#ifndef SE23_ALIGN_H
#define SE23_ALIGN_H

#include "se23/earth.h"
#include "se23/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/* Plain double literals: wrap in SE23_R() where used. */
#define SE23_ALIGN_G0 9.80665        /**< nominal gravity of the |f_mean| band [m/s^2] */
#define SE23_ALIGN_F_MIN 0.5         /**< smallest |f_mean| accepted, x SE23_ALIGN_G0 */
#define SE23_ALIGN_F_MAX 1.5         /**< largest |f_mean| accepted, x SE23_ALIGN_G0 */
#define SE23_ALIGN_YAW_STD_MAX 0.1   /**< largest gyrocompass sigma_yaw accepted [rad] */
#define SE23_ALIGN_RATE_MIN 0.5      /**< smallest horizontal rate accepted, x W |cos lat| */
#define SE23_ALIGN_RATE_MAX 1.5      /**< largest horizontal rate accepted, x W |cos lat| */

/**
 * R = Rz(yaw) Ry(pitch) Rx(roll) with roll and pitch from the mean specific
 * force at rest (file comment).
 * @param frame  SE23_FRAME_NED or SE23_FRAME_ENU
 * @param f_mean mean specific force at rest [m/s^2], body frame
 * @param yaw    yaw [rad] as defined in the file comment (any finite value)
 * @param R      attitude, body -> nav
 * @return SE23_ERR_NULL; SE23_ERR_NONFINITE (f_mean, yaw); SE23_ERR_DOMAIN
 *         for an unknown frame or |f_mean| outside [SE23_ALIGN_F_MIN,
 *         SE23_ALIGN_F_MAX] x SE23_ALIGN_G0. Checked in this order.
 */
se23_status_t se23_align_level(se23_frame_t frame, const se23_vec3_t *f_mean,
                               se23_real_t yaw, se23_mat3_t *R);

/**
 * P = the covariance of the body-frame attitude error phi (R = Rbar
 * exp(phi^)) of an alignment: tilt^2 I + (sigma_yaw^2 - tilt^2) r r^T,
 * tilt = sigma_f / (g sqrt n), r = R^T e_z (file comment), computed with
 * r r^T / |r|^2 (R is a rotation only to SE23_CFG_ROT_TOL; so P stays PSD
 * however small sigma_yaw is against tilt).
 * @param R         the aligned attitude Rbar, body -> nav
 * @param sigma_f   accelerometer noise std of one sample, per axis [m/s^2]
 *                  (sqrt of se23_stationary_var's f_var at rest, or sigma_a)
 * @param n         number of samples averaged into f_mean, n >= 1
 * @param g         gravity magnitude [m/s^2]
 * @param sigma_yaw heading std [rad] (from se23_align_gyrocompass, or the
 *                  caller's heading source; for an unknown heading a large
 *                  value, but the first-order model then says little)
 * @param P         3x3 covariance [rad^2], symmetric PSD
 * @return SE23_ERR_NULL; SE23_ERR_NONFINITE (R, sigma_f, g, sigma_yaw);
 *         SE23_ERR_DIM if n < 1; SE23_ERR_DOMAIN unless sigma_f > 0,
 *         g > 0 and sigma_yaw > 0; SE23_ERR_NOT_ROTATION if R is not in
 *         SO(3) within SE23_CFG_ROT_TOL; SE23_ERR_NONFINITE if an entry of
 *         P overflows. Checked in this order.
 */
se23_status_t se23_align_cov(const se23_mat3_t *R, se23_real_t sigma_f, int n,
                             se23_real_t g, se23_real_t sigma_yaw,
                             se23_mat3_t *P);

/**
 * R, yaw = the attitude at rest from the mean specific force (roll, pitch)
 * and the mean gyro reading (heading from the horizontal Earth rate), and
 * sigma_yaw = sigma_w / (sqrt(n) W |cos lat|), the std of yaw due to gyro
 * noise (file comment). Pair with se23_align_cov(R, sigma_f, n, g,
 * sigma_yaw, P) for the covariance.
 * @param frame     SE23_FRAME_NED or SE23_FRAME_ENU
 * @param lat       geodetic latitude [rad], |lat| <= pi/2 (+ SE23_EARTH_LAT_SLACK)
 * @param f_mean    mean specific force at rest [m/s^2], body frame
 * @param w_mean    mean angular rate at rest [rad/s], body frame (bias
 *                  removed if known)
 * @param sigma_w   gyro noise std of one sample, per axis [rad/s]
 * @param n         number of samples averaged into w_mean, n >= 1
 * @param R         attitude, body -> nav
 * @param yaw       yaw [rad] in [-pi, pi], as se23_align_level defines it
 * @param sigma_yaw std of yaw [rad]
 * @return SE23_ERR_NULL; SE23_ERR_NONFINITE (lat, f_mean, w_mean,
 *         sigma_w); SE23_ERR_DIM if n < 1; SE23_ERR_DOMAIN for an unknown
 *         frame, sigma_w <= 0, |lat| > pi/2 + SE23_EARTH_LAT_SLACK,
 *         |f_mean| outside the band of se23_align_level, sigma_yaw above
 *         SE23_ALIGN_YAW_STD_MAX, or the measured horizontal rate |h|
 *         outside [SE23_ALIGN_RATE_MIN, SE23_ALIGN_RATE_MAX] x W |cos lat|.
 *         Checked in this order. On error nothing is written (R, yaw,
 *         sigma_yaw).
 */
se23_status_t se23_align_gyrocompass(se23_frame_t frame, se23_real_t lat,
                                     const se23_vec3_t *f_mean,
                                     const se23_vec3_t *w_mean,
                                     se23_real_t sigma_w, int n, se23_mat3_t *R,
                                     se23_real_t *yaw, se23_real_t *sigma_yaw);

#ifdef __cplusplus
}
#endif

#endif /* SE23_ALIGN_H */
