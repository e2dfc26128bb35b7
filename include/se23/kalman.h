/**
 * @file kalman.h
 * @brief Kalman update of a concentrated Gaussian in exponential coordinates
 *        (DESIGN.md section 3, "Measurement update") and ready-made
 *        measurement models: position and velocity in the navigation frame
 *        (GNSS), velocity in the body frame (zero velocity, odometer).
 *
 * A measurement y = h(T, b) + noise, noise ~ N(0, R), is linearised at the
 * estimate in the error of gauss.h, T = Tbar exp(xi), b = bbar + db:
 *   y = h(Tbar, bbar) + H (xi, db) + O(|xi|^2) + noise.
 * The update (innovation z = y - h(Tbar, bbar), m = 1..9 rows):
 *   C = P H^T,  S = H C + R = L L^T      Cholesky, no explicit inverse
 *   K = C S^-1,  dx = K z,  nis = z^T S^-1 z
 *   P+ = P - C S^-1 C^T = P - U U^T, U = C L^-T
 *   Tbar+ = Tbar exp(dx_xi) (R re-orthonormalised),  bbar+ = bbar + dx_db
 * P+ equals the Joseph form (I - K H) P (I - K H)^T + K R K^T in exact
 * arithmetic; computed as the Schur complement of S (the Cholesky
 * elimination step) it is positive semidefinite to rounding whatever R,
 * and exactly symmetric (upper triangle computed, mirrored). Only the
 * 3-column blocks of H (phi, nu, rho, b_g, b_a) that hold a nonzero take
 * part: the models below touch two blocks, so a GNSS update costs about
 * 800 multiply-adds instead of the 9,500 of the dense Joseph form
 * (src/kalman_parts.c gives the count). P+ is the covariance of the error
 * at the old estimate; the O(|dx|) change of coordinates of the
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
 *   se23_kalman_update    the update above
 *   se23_meas_pos_nav     GNSS position (with lever arm)
 *   se23_meas_vel_nav     GNSS velocity
 *   se23_meas_vel_body    velocity in the body frame (zero velocity / odometer)
 *
 * All functions accept outputs that alias inputs. The models write every
 * element of their output (rows beyond m and the bias columns 0).
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

/**
 * out = g updated with the measurement y (file comment).
 * @param g   the state, trusted (produced by the library or checked once
 *            with se23_gauss_check); only g->n is checked.
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
 *         would overflow: the NIS, an entry of P+, a correction |dx_k|
 *         above 1e18 (float) / 1e150 (double), or a mean entry of g above
 *         a quarter of the largest finite value (or NaN). With
 *         SE23_CFG_DEEP_CHECKS also the statuses of se23_gauss_check.
 *         On error nothing is written (out, nis).
 */
se23_status_t se23_kalman_update(const se23_gauss_t *g, const se23_meas_t *y,
                                 se23_gauss_t *out, se23_real_t *nis);

/**
 * y = the position of a GNSS antenna at lever arm l_b (body frame) measured
 * in the nav frame: h(T) = p + R l_b, so
 *   H = [-R l_b^, 0, R, 0] (columns phi, nu, rho, db).
 * @param T      estimate Tbar
 * @param p_n    measured position, nav frame [m]
 * @param lever_b antenna position in the body frame [m] (zero vector if none)
 * @param cov    measurement noise covariance [m^2]
 * @return SE23_ERR_NONFINITE, SE23_ERR_NOT_ROTATION (T), or the covariance
 *         statuses of gauss.h for cov.
 */
se23_status_t se23_meas_pos_nav(const se23_pose_t *T, const se23_vec3_t *p_n,
                                const se23_vec3_t *lever_b,
                                const se23_mat3_t *cov, se23_meas_t *y);

/**
 * y = the velocity measured in the nav frame: h(T) = v, H = [0, R, 0, 0].
 * @param v_n measured velocity, nav frame [m/s]
 * @param cov measurement noise covariance [m^2/s^2]
 * @return as se23_meas_pos_nav.
 */
se23_status_t se23_meas_vel_nav(const se23_pose_t *T, const se23_vec3_t *v_n,
                                const se23_mat3_t *cov, se23_meas_t *y);

/**
 * y = the velocity measured in the body frame (zero-velocity update with
 * v_b = 0, or an odometer): h(T) = R^T v, H = [(R^T v)^, I, 0, 0].
 * @param v_b measured velocity, body frame [m/s]
 * @param cov measurement noise covariance [m^2/s^2]
 * @return as se23_meas_pos_nav.
 */
se23_status_t se23_meas_vel_body(const se23_pose_t *T, const se23_vec3_t *v_b,
                                 const se23_mat3_t *cov, se23_meas_t *y);

#ifdef __cplusplus
}
#endif

#endif /* SE23_KALMAN_H */
