/**
 * @file so3.h
 * @brief The rotation group SO(3): hat/vee, exp/log, Jacobians, the series
 *        H and K used by exact IMU integration, re-orthonormalisation.
 *
 * With theta = |phi| and phi^ the skew matrix of phi (phi^ x = phi cross x):
 *   exp(phi) = I + sin(theta)/theta phi^ + (1 - cos theta)/theta^2 phi^^2
 *   J(phi)   = sum_n phi^^n / (n+1)!   left Jacobian (the paper's N(omega))
 *   H(phi)   = sum_n phi^^n / (n+2)!   (so that int_0^1 s J(s phi) ds = H(phi))
 *   K(phi)   = sum_n phi^^n / (n! (n+2))
 * Each has a closed form in theta; near theta = 0 the coefficients are
 * evaluated by their Taylor series (thresholds per precision, see
 * src/lie/so3_series.c).
 *
 * Functions index:
 *   se23_so3_hat, se23_so3_vee            skew matrix <-> vector
 *   se23_so3_exp, se23_so3_log            exponential and principal logarithm
 *   se23_so3_jl, se23_so3_jl_inv, se23_so3_jr   Jacobians
 *   se23_so3_h, se23_so3_k                integration series
 *   se23_so3_check, se23_so3_normalize    validity test, re-orthonormalisation
 *
 * All functions accept outputs that alias inputs.
 */
#ifndef SE23_SO3_H
#define SE23_SO3_H

#include "se23/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * W = phi^, the skew-symmetric matrix with W x = phi cross x.
 * @param phi rotation vector (any finite value)
 * @param W out: its skew-symmetric matrix
 */
void se23_so3_hat(const se23_vec3_t *phi, se23_mat3_t *W);

/**
 * phi = vee(W); reads the skew-symmetric part ((W - W^T)/2) of W.
 * @param W a 3x3 matrix, ideally skew-symmetric
 * @param phi out: the vector of its skew part
 */
void se23_so3_vee(const se23_mat3_t *W, se23_vec3_t *phi);

/**
 * R = exp(phi^) by Rodrigues' formula.
 * @param phi rotation vector [rad]
 * @param R out: the rotation (written only on SE23_OK)
 * @return SE23_ERR_NONFINITE if phi holds NaN/Inf or |phi|^2 overflows.
 */
se23_status_t se23_so3_exp(const se23_vec3_t *phi, se23_mat3_t *R);

/**
 * phi = log(R), the principal logarithm, |phi| in [0, pi].
 * The angle comes from atan2 (accurate at every angle); near pi the axis
 * comes from the symmetric part of R, so the result stays accurate up to pi.
 * At exactly pi either of the two opposite vectors is returned.
 * @param R a rotation matrix
 * @param phi out: its rotation vector [rad] (written only on SE23_OK)
 * @return SE23_ERR_NONFINITE, or SE23_ERR_NOT_ROTATION if R is not in SO(3)
 *         within SE23_CFG_ROT_TOL.
 */
se23_status_t se23_so3_log(const se23_mat3_t *R, se23_vec3_t *phi);

/**
 * J = J_l(phi) = sum_n phi^^n/(n+1)!, the left Jacobian:
 * exp(phi + d) = exp(J_l(phi) d) exp(phi) to first order in d.
 * @param phi rotation vector [rad]
 * @param J out: J_l(phi) (written only on SE23_OK)
 * @return SE23_ERR_NONFINITE if phi holds NaN/Inf or |phi|^2 overflows.
 */
se23_status_t se23_so3_jl(const se23_vec3_t *phi, se23_mat3_t *J);

/**
 * Jinv = J_l(phi)^-1 = I - phi^/2 + (1 - (theta/2)cot(theta/2))/theta^2 phi^^2.
 * @param phi rotation vector [rad], |phi| < 2 pi - 1e-3
 * @param Jinv out: J_l(phi)^-1 (written only on SE23_OK)
 * @return SE23_ERR_NONFINITE, or SE23_ERR_DOMAIN if |phi| >= 2 pi - 1e-3,
 *         where J_l is singular or too ill-conditioned to invert.
 */
se23_status_t se23_so3_jl_inv(const se23_vec3_t *phi, se23_mat3_t *Jinv);

/**
 * J = J_r(phi) = J_l(-phi), the right Jacobian:
 * exp(phi + d) = exp(phi) exp(J_r(phi) d) to first order in d.
 * @param phi rotation vector [rad]
 * @param J out: J_r(phi) (written only on SE23_OK)
 * @return SE23_ERR_NONFINITE if phi holds NaN/Inf or |phi|^2 overflows.
 */
se23_status_t se23_so3_jr(const se23_vec3_t *phi, se23_mat3_t *J);

/**
 * H = sum_n phi^^n/(n+2)!
 *   = I/2 + (theta - sin theta)/theta^3 phi^ + (theta^2/2 + cos theta - 1)/theta^4 phi^^2.
 * The position increment of a constant-rate IMU sample is dt^2 H(omega dt) a.
 * @param phi rotation vector [rad] (omega dt for an IMU sample)
 * @param H out: H(phi) (written only on SE23_OK)
 * @return SE23_ERR_NONFINITE if phi holds NaN/Inf or |phi|^2 overflows.
 */
se23_status_t se23_so3_h(const se23_vec3_t *phi, se23_mat3_t *H);

/**
 * K = sum_n phi^^n/(n! (n+2))
 *   = I/2 + (sin theta - theta cos theta)/theta^3 phi^
 *         + (theta^2/2 - cos theta - theta sin theta + 1)/theta^4 phi^^2.
 * Used for the rotating-Earth position term Gamma^x (DESIGN.md section 3).
 * @param phi rotation vector [rad]
 * @param K out: K(phi) (written only on SE23_OK)
 * @return SE23_ERR_NONFINITE if phi holds NaN/Inf or |phi|^2 overflows.
 */
se23_status_t se23_so3_k(const se23_vec3_t *phi, se23_mat3_t *K);

/**
 * Checks that R is a finite rotation: every entry of R^T R - I and
 * det(R) - 1 within SE23_CFG_ROT_TOL.
 * @param R the matrix to check
 * @return SE23_OK, SE23_ERR_NONFINITE or SE23_ERR_NOT_ROTATION.
 */
se23_status_t se23_so3_check(const se23_mat3_t *R);

/**
 * Rn = the orthogonal polar factor of R (the rotation nearest to R in the
 * Frobenius norm), by the Newton-Schulz iteration R <- R (3I - R^T R)/2,
 * which treats all axes alike (Gram-Schmidt would favour one) and converges
 * quadratically. Meant for R that has drifted by rounding, as after many
 * propagation steps.
 * @param R a rotation that has drifted by rounding
 * @param Rn out: the nearest rotation (written only on SE23_OK); may alias R
 * @return SE23_ERR_NONFINITE, or SE23_ERR_NOT_ROTATION if R is too far from
 *         SO(3) to be repaired (an entry of R^T R - I above 0.1, or det <= 0).
 */
se23_status_t se23_so3_normalize(const se23_mat3_t *R, se23_mat3_t *Rn);

#ifdef __cplusplus
}
#endif

#endif /* SE23_SO3_H */
