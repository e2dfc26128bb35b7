/**
 * @file se23.h
 * @brief The group SE_2(3) of extended poses (Barrau & Bonnabel, ICRA 2020).
 *
 * Conventions:
 *  - T = (R, v, p): R body -> nav attitude, v [m/s] and p [m] in the nav frame;
 *    5x5 form [[R, v, p], [0, 1, 0], [0, 0, 1]].
 *  - Composition (R1, v1, p1)(R2, v2, p2) = (R1 R2, R1 v2 + v1, R1 p2 + p1).
 *  - Tangent xi = (phi, nu, rho) in R^9 (rotation, velocity, position);
 *    xi^ = [[phi^, nu, rho], [0, 0, 0], [0, 0, 0]].
 *  - Uncertainty is right-multiplied: T = Tbar exp(xi), xi ~ N(0, Sigma)
 *    (paper eq. error:rep1).
 *  - 9x9 matrices are flat row-major (se23_mat9_t).
 *
 * Functions index:
 *   se23_identity, se23_compose, se23_inverse, se23_act
 *   se23_hat, se23_vee, se23_to_mat5, se23_from_mat5
 *   se23_exp, se23_log
 *   se23_adjoint, se23_adjoint_inv
 *   se23_pose_check
 *
 * Functions that cannot fail return void; they do no finiteness or
 * orthonormality check (NaN in gives NaN out). Validate poses that come from
 * outside with se23_pose_check. All functions accept outputs that alias inputs.
 */
#ifndef SE23_SE23_H
#define SE23_SE23_H

#include "se23/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/**
 * T = identity (I, 0, 0).
 * @param T out: the identity pose
 */
void se23_identity(se23_pose_t *T);

/**
 * AB = A B (matrix product of the 5x5 forms).
 * @param A left factor
 * @param B right factor
 * @param AB out: the product; may alias A or B
 */
void se23_compose(const se23_pose_t *A, const se23_pose_t *B, se23_pose_t *AB);

/**
 * Tinv = T^-1 = (R^T, -R^T v, -R^T p).
 * @param T the pose
 * @param Tinv out: its inverse; may alias T
 */
void se23_inverse(const se23_pose_t *T, se23_pose_t *Tinv);

/**
 * y = R x + p: the action of the pose (R, p) part on a point x.
 * @param T the pose (its R and p are used)
 * @param x the point
 * @param y out: R x + p; may alias x
 */
void se23_act(const se23_pose_t *T, const se23_vec3_t *x, se23_vec3_t *y);

/**
 * X = xi^ in se_2(3) as a 5x5 matrix.
 * @param xi tangent vector (phi, nu, rho)
 * @param X out: its 5x5 Lie-algebra matrix
 */
void se23_hat(const se23_tangent_t *xi, se23_mat5_t *X);

/**
 * xi = vee(X); reads the skew part of the 3x3 block and columns 3 and 4.
 * @param X a 5x5 Lie-algebra matrix
 * @param xi out: its tangent vector (phi, nu, rho)
 */
void se23_vee(const se23_mat5_t *X, se23_tangent_t *xi);

/**
 * M = the 5x5 matrix of T.
 * @param T the pose
 * @param M out: its 5x5 matrix
 */
void se23_to_mat5(const se23_pose_t *T, se23_mat5_t *M);

/**
 * T = the pose held in a 5x5 matrix.
 * @param M a 5x5 matrix of an extended pose
 * @param T out: the pose (written only on SE23_OK)
 * @return SE23_ERR_NONFINITE, SE23_ERR_NOT_ROTATION (block), or SE23_ERR_DOMAIN
 *         if the last two rows differ from [0 0 0 1 0; 0 0 0 0 1] by more
 *         than SE23_CFG_ROT_TOL.
 */
se23_status_t se23_from_mat5(const se23_mat5_t *M, se23_pose_t *T);

/**
 * T = exp(xi) = (exp(phi^), J_l(phi) nu, J_l(phi) rho)  (paper eq. exp:map,
 * with N(omega) = J_l(phi); see DESIGN.md section 3 for the printed typo).
 * @param xi tangent vector (phi, nu, rho)
 * @param T out: exp(xi) (written only on SE23_OK)
 * @return SE23_ERR_NONFINITE if xi holds NaN/Inf or the result overflows.
 */
se23_status_t se23_exp(const se23_tangent_t *xi, se23_pose_t *T);

/**
 * xi = log(T) = (phi, J_l(phi)^-1 v, J_l(phi)^-1 p) with phi = log(R) the
 * principal rotation logarithm (|phi| <= pi).
 * @param T the pose
 * @param xi out: log(T) (written only on SE23_OK)
 * @return SE23_ERR_NONFINITE (NaN/Inf in T, or xi would overflow: v or p
 *         near the largest real), or SE23_ERR_NOT_ROTATION.
 */
se23_status_t se23_log(const se23_pose_t *T, se23_tangent_t *xi);

/**
 * Ad = Ad_T = [[R, 0, 0], [v^ R, R, 0], [p^ R, 0, R]]  (paper eq. ad:eq),
 * so that T exp(xi) T^-1 = exp(Ad_T xi).
 * @param T the pose
 * @param Ad out: Ad_T, 9x9 row-major
 */
void se23_adjoint(const se23_pose_t *T, se23_mat9_t *Ad);

/**
 * Ad = Ad_{T^-1} = [[R^T, 0, 0], [-R^T v^, R^T, 0], [-R^T p^, 0, R^T]],
 * computed directly (no inversion of T or of Ad_T).
 * @param T the pose
 * @param Ad out: Ad_{T^-1}, 9x9 row-major
 */
void se23_adjoint_inv(const se23_pose_t *T, se23_mat9_t *Ad);

/**
 * Checks that T is finite and its R is a rotation within SE23_CFG_ROT_TOL.
 * @param T the pose to check
 * @return SE23_OK, SE23_ERR_NONFINITE or SE23_ERR_NOT_ROTATION.
 */
se23_status_t se23_pose_check(const se23_pose_t *T);

#ifdef __cplusplus
}
#endif

#endif /* SE23_SE23_H */
