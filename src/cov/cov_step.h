/**
 * @file cov_step.h
 * @brief Internal: the per-sample covariance kernels of gauss.h and
 *        preint_unc.h, by 3x3 blocks in the factored form of the transition
 *        (no dense products, no callbacks). Not part of the public API.
 *
 * Factored transition (paper eq. riccati, DESIGN.md section 3). With the
 * increment U = (R, v, p) of one sample over dt, F_k = Ad_{U^-1} F splits
 * into a rotation and a shear,
 *   F_k = D G,   D = diag(R^T, R^T, R^T),
 *   G = [[I, 0, 0], [-v^, I, 0], [-p^, dt I, I]],
 * and the input matrix of gauss.h splits the same way, B_k = D Bt, since its
 * rows are R^T times the derivatives of the increment's (R, v, p) (see
 * input_jac.c). With bias states, Phi = diag(D, I6) [[G, Bt], [0, I6]]. So
 *   P+ = diag(D, I6) ( [[G, Bt], [0, I6]] P [[G, Bt], [0, I6]]^T
 *                      + diag(Bt N Bt^T, W) ) diag(D, I6)^T,
 * N = diag(qg I3, qa I3) the per-sample white noise, W = diag(wg I3, wa I3)
 * the bias random walk. The kernels evaluate this by blocks, upper triangle
 * only, and mirror it: P+ is exactly symmetric, and it is positive
 * semidefinite whenever P is, up to rounding of the congruence.
 */
#ifndef SE23_COV_STEP_H
#define SE23_COV_STEP_H

#include <float.h>

#include "../imu/imu_step.h"
#include "se23/gauss.h"
#include "se23/types.h"
#include "se23/work.h"

/** The O(n) overflow bounds of a step (se23_cov_step_fits, the factor's
 *  bound on J+ and the Deltas) keep every result and partial sum below
 *  this: 64 times below the largest real. */
#if SE23_CFG_DOUBLE
#define SE23_COV_STEP_MAX (SE23_R(DBL_MAX) / SE23_R(64))
#else
#define SE23_COV_STEP_MAX (SE23_R(FLT_MAX) / SE23_R(64))
#endif

/**
 * q = the per-sample noise of the model nz over dt (0 < dt, checked by the
 * caller).
 * @return SE23_ERR_NONFINITE (a density not finite, or a variance that
 *         overflows: a huge density or a denormal dt), SE23_ERR_DOMAIN (a
 *         negative density); q is written only on SE23_OK.
 */
se23_status_t se23_step_noise(const se23_imu_noise_t *nz, se23_real_t dt,
                              se23_step_noise_t *q);

/**
 * Nonzero if se23_cov_step with these inputs cannot overflow: |P_ij| <=
 * max_i P_ii <= d = sum_i |P_ii| for a PSD P (n a multiple of 3; the sum is
 * cheaper than the maximum), so every entry of Phi P Phi^T + Q is at most
 * 2 d r^2 + 4 q b^2 + w, with r a bound on the absolute row sums of Phi
 * and b one on those of Bt; the bound must stay 64 times below the largest
 * real. O(n).
 * @param b bound on the absolute row sums of Bt: se23_input_blocks_row_sum,
 *          or for a sample's own Bt se23_input_blocks_bound.
 */
int se23_cov_step_fits(const se23_pose_t *U, se23_real_t dt, se23_real_t b,
                       const se23_step_noise_t *q, int n, const se23_real_t *P,
                       int stride);

/** se23_cov_step_fits for a transition whose shear rows sum to at most g
 *  (G's 1 + dt + |v|_1 + |p|_1, or the time shear's 1 + dt). */
int se23_cov_fits(se23_real_t g, se23_real_t b, const se23_step_noise_t *q, int n,
                  const se23_real_t *P, int stride);

/**
 * Nonzero if every entry of Bt, built by se23_input_blocks from the parts
 * of a corrected sample, is finite; tame = se23_sample_tame of that
 * sample. O(1) for a tame sample
 * (se23_sample_tame: each intermediate of se23_input_blocks is then at most
 * 4 (1 + |f|_1) (1 + |w dt|_1)^3 (1 + dt)^3, a bound found term by term in
 * series_deriv with every coefficient at most 1), otherwise a test of each
 * entry: for huge rates or forces the products can overflow although the
 * bound of se23_input_blocks_bound, which assumes exact arithmetic, is
 * finite.
 */
int se23_input_blocks_finite(const se23_input_blocks_t *Bt, int tame);

/** The largest absolute row sum of Bt (45 entries). */
se23_real_t se23_input_blocks_row_sum(const se23_input_blocks_t *Bt);

/**
 * A bound on the absolute row sums of the Bt of se23_input_blocks from the
 * sample alone, O(1): ||J||_2 <= 1, ||H||_2 <= 1/2 (normal matrices with
 * eigenvalues (e^{i t} - 1)/(i t) and (e^{i t} - 1 - i t)/(i t)^2),
 * ||D_J||_2 <= |f|/2 and ||D_H||_2 <= |f|/6 (J f and H f are averages of
 * exp(s th^) f over s with weights 1 and 1 - s), and an entry is at most
 * the spectral norm: a row of Bt sums to at most
 * 3 dt (2 + dt |f| (1/2 + dt/6 + 1/2)) <= 6 dt (1 + dt |f| (1 + dt)).
 * |f| is bounded by |f|_1.
 */
se23_real_t se23_input_blocks_bound(const se23_vec3_t *f, se23_real_t dt);

/**
 * out = Phi P Phi^T + diag(B_k N B_k^T, W) on the leading n x n blocks
 * (n = 9 or 15, row stride `stride`; for 15 states the stride must be
 * SE23_GAUSS_NMAX, which the bias stages have built in), reading only P's
 * upper triangle and writing both triangles of out (file comment). out may
 * alias P. No checks; cannot fail.
 */
void se23_cov_step(const se23_pose_t *U, se23_real_t dt,
                   const se23_input_blocks_t *Bt, const se23_step_noise_t *q,
                   int n, const se23_real_t *P, se23_real_t *out, int stride);

/** out = F_k P F_k^T = D G P G^T D^T on the pose blocks (9x9, no input,
 *  no noise): se23_cov_step's shear and rotation stages from a zero
 *  scratch. out may alias P. No checks. */
void se23_cov_fk_congruence(const se23_pose_t *U, se23_real_t dt, const se23_real_t *P,
                            se23_real_t *out, int stride);

/** The pose blocks (i, j), i <= j, of S = G X G^T + E before the rotation,
 *  packed: the blocks in the order (0,0), (0,1), (0,2), (1,1), (1,2),
 *  (2,2), a diagonal block as its upper triangle by rows (6 entries), the
 *  others by rows (9); 45 entries, the 81 of nine full blocks less what
 *  symmetry repeats (the scratch is on the stack under every step). */
typedef struct {
    se23_real_t e[45];
} se23_cov_pose_t;

/** The stages of se23_cov_step (file comment of cov_step.c), each a
 *  function of its own so that none holds another's values in registers:
 *  S = E, for 9 states Bt N Bt^T, for 15 with the cross blocks of out of
 *  the gyro bias, then those of the accel bias (from Y = G C and
 *  Zq = Y + Bt Bb + Bt N, a bias column at a time), then the bias block
 *  Bb + W; then S += G X G^T; last, out's pose blocks R^T S R.
 *  Straight-line code generated by tools/gen/gen_cov_step.py into
 *  cov_step_kernel.c. */
void se23_cov_step9_noise(const se23_input_blocks_t *Bt, const se23_step_noise_t *q,
                          se23_cov_pose_t *S);
void se23_cov_step15_gyro(const se23_pose_t *U, se23_real_t dt, const se23_input_blocks_t *Bt,
                          const se23_step_noise_t *q, const se23_real_t *P, se23_real_t *out,
                          se23_cov_pose_t *S);
void se23_cov_step15_accel(const se23_pose_t *U, se23_real_t dt, const se23_input_blocks_t *Bt,
                           const se23_step_noise_t *q, const se23_real_t *P, se23_real_t *out,
                           se23_cov_pose_t *S);
void se23_cov_step15_bias(const se23_step_noise_t *q, const se23_real_t *P, se23_real_t *out);
void se23_cov_shear_pose(const se23_pose_t *U, se23_real_t dt, const se23_real_t *P, int stride,
                         se23_cov_pose_t *S);
void se23_cov_rotate_pose(const se23_pose_t *U, const se23_cov_pose_t *S, se23_real_t *out,
                          int stride);

/** Nonzero if every entry of se23_cov_nu_shear's result stays finite:
 *  with d = sum_i |P_ii| (P PSD, so |P_ij| <= d) each entry of M P M^T is
 *  at most d (1 + |a|_1)^2, which must stay 64 times below the largest
 *  real. O(n). */
int se23_cov_nu_shear_fits(const se23_vec3_t *a, int n, const se23_real_t *P, int stride);

/**
 * out = M P M^T, M = I + [[0, 0, 0], [0, 0, a^], [0, 0, 0]] (identity on
 * the bias blocks): the carried <-> user change of error coordinates of
 * gauss.h with a = -+ Rbar^T Omega. Only row and column nu change: about
 * 20 n multiply-adds. out may alias P. No checks.
 */
void se23_cov_nu_shear(const se23_vec3_t *a, int n, const se23_real_t *P,
                       se23_real_t *out, int stride);

/*
 * The left form of a preintegrated factor (preint_unc.h): the error
 * zeta = Ad_Delta xi of Delta_true = exp(zeta) Delta, frame of t_i. With
 * Delta+ = Phi_dt(Delta) U and Phi_dt(exp(zeta)) = exp(F zeta) (Phi_dt the
 * time shear (R, v, p) -> (R, v, p + dt v), an automorphism),
 *   zeta+ = F zeta + Ad_{Delta+} B_k n,   F = [[I, 0, 0], [0, I, 0], [0, dt I, I]],
 * and Ad_{Delta+} D = [[R, 0, 0], [v+^ R, R, 0], [p+^ R, 0, R]] with R the
 * rotation of Delta before the step (R+ R_U^T = R): F is constant and
 * sparse, and the rotation moves from the covariance (R^T S R, two-sided)
 * to the input matrix (one-sided).
 */

/** Bt <- Bl = Ad_{Delta+} D Bt in place: R the rotation of Delta before
 *  the step, v and p the velocity and position of Delta after it.
 *  blk[0][1] stays zero and unread. No checks. */
void se23_input_blocks_left(const se23_mat3_t *R, const se23_vec3_t *v, const se23_vec3_t *p,
                            se23_input_blocks_t *Bt);

/** Q <- F Q F^T + Bl N Bl^T in place (9x9, row stride 9, upper triangle
 *  read, both written: exactly symmetric), Bt holding Bl: the covariance
 *  step of the left form. No checks. */
void se23_cov_left_step(se23_real_t dt, const se23_input_blocks_t *Bt,
                        const se23_step_noise_t *q, se23_real_t *Q);

/** J <- F J + Bl in place (9x6), Bt holding Bl: the bias-Jacobian step of
 *  the left form. No checks.
 *  The three are generated straight-line code (cov_step_kernel.c): per
 *  sample 469 multiplies and 423 adds, against 1,008 and 855 for the
 *  right form's D (G P G^T + Bt N Bt^T) D^T and D (G J + Bt). */
void se23_cov_left_jac_step(se23_real_t dt, const se23_input_blocks_t *Bt, se23_mat9x6_t *J);

/**
 * Bt of one sample from the parts of its exact increment U (kind EXACT or
 * BASIC, already checked), f the corrected specific force:
 *   EXACT: [[dt J, 0], [dt^2 D_J, dt J], [dt^3 D_H, dt^2 H]] (input_jac.c),
 *   BASIC: diag(R, R, R) dt I_{9,6} = [[dt R, 0], [0, dt R], [0, 0]].
 */
void se23_input_blocks(se23_input_jac_kind_t kind,
                       const se23_increment_parts_t *q, const se23_mat3_t *R,
                       const se23_vec3_t *f, se23_real_t dt,
                       se23_input_blocks_t *Bt);

/**
 * The mean and input half of one filter prediction (se23_gauss_predict):
 * se23_imu_step_ups from the trusted pose T and the corrected sample
 * w->in.c into w->T_next and w->in.U, the step noise w->in.q of c.dt, and
 * w->in.Bt of the given kind, checked finite (SE23_ERR_NONFINITE
 * otherwise). A call of its own so that the increment's parts, used only
 * to build Bt, are not on the stack under the covariance kernels. Its
 * outputs are scratch on error.
 */
se23_status_t se23_predict_inputs(const se23_earth_model_t *model, const se23_pose_t *T,
                                  const se23_imu_noise_t *noise, se23_input_jac_kind_t kind,
                                  se23_predict_work_t *w);

/**
 * The increment U of the corrected sample c (se23_imu_increment_parts) and
 * its Bt of the given kind: the input half of a preintegration step
 * (se23_preint_unc_add). A call of its own, as se23_predict_inputs, so
 * that the increment's parts are not on the stack under the covariance
 * kernels. No checks (the caller tests U and Bt for overflow).
 */
void se23_sample_inputs(se23_input_jac_kind_t kind, const se23_imu_sample_t *c,
                        se23_pose_t *U, se23_input_blocks_t *Bt);

/** B = D Bt, the public form of the input matrix (gauss.h). */
void se23_input_blocks_rotate(const se23_mat3_t *R,
                              const se23_input_blocks_t *Bt, se23_mat9x6_t *B);

/** Bt = D^-1 B = diag(R, R, R) B, the blocks of a public input matrix.
 *  @return 0 (Bt unwritten) if B's rotation rows have accel columns. */
int se23_input_blocks_from(const se23_mat3_t *R, const se23_mat9x6_t *B,
                           se23_input_blocks_t *Bt);

#endif /* SE23_COV_STEP_H */
