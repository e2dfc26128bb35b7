/**
 * @file preint_unc.h
 * @brief A preintegrated IMU factor with its uncertainty and its bias
 *        Jacobians: the 9x9 covariance of the Deltas (paper section 3), the
 *        9x6 bias Jacobian in exponential coordinates (paper section 4,
 *        eq. biascor) and first-order bias correction without
 *        re-integration, with the classical correction of Forster et al.
 *        (T-RO 2017) alongside for comparison.
 *
 * Sensor and bias convention (gauss.h, the paper's section 3.3): the IMU
 * reads w_meas = w - b_g - eta_g, f_meas = f - b_a - eta_a. The factor is
 * integrated at a bias estimate bbar, i.e. from the corrected inputs
 * w = w_meas + bbar_g, f = f_meas + bbar_a (body frame, rad/s and m/s^2).
 *
 * Uncertainty (paper eq. error:rep1, eq. riccati). The true Deltas are
 * Delta_true = Delta exp(xi), xi ~ N(0, P), xi = (phi, nu, rho) in the body
 * frame at t_i. Preintegration is the flat-Earth step with Gamma = I
 * (preint.h), so xi propagates like a state error (gauss.h):
 *   xi+ = F_k xi + B_k eta,  P+ = F_k P F_k^T + B_k N B_k^T,
 *   F_k = Ad_{Upsilon_k^-1} F,  P_0 = 0,
 * the model of se23_gauss_input_jac, se23_gauss_input_noise and
 * se23_gauss_cov_propagate (the same B_k and noise as the filter's; the
 * factor evaluates the recursion in its left form, below). A state
 * distribution predicted through the factor
 * is Sigma_j = F_D Sigma_i F_D^T + P with F_D = Ad_{Delta^-1} F_{Delta t}
 * (se23_gauss_fk_apply with U = Delta, dt = Delta t), the same as
 * propagating Sigma_i sample by sample.
 *
 * Bias Jacobian in exponential coordinates (paper eq. bias:discrep,
 * eq. biascor; DESIGN.md "Bias Jacobian"). For a new estimate
 * bhat = bbar + db, Delta(bhat) = Delta(bbar) exp(d) with d = J db + O(db^2),
 *   J_{k+1} = F_k J_k + B_k,  J_0 = 0   (9x6, columns (db_g, db_a), [s]),
 * B_k the exact input matrix (SE23_INPUT_JAC_EXACT: J is the derivative of
 * log(Delta(bbar)^-1 Delta(bbar + db)) at db = 0, to rounding) or the
 * paper's basic dt I_{9,6} (SE23_INPUT_JAC_BASIC: J is first order in dt).
 * The kind chosen at reset also weights the noise, B_k N B_k^T.
 * Bias correction without re-integration:
 *   Delta(bhat) ~ Delta(bbar) exp(J (bhat - bbar)).
 *
 * Storage: the left form. The factor keeps P and J as the left error's,
 *   Delta_true = exp(zeta) Delta, zeta = Ad_Delta xi ~ N(0, P_left),
 *   Delta(bbar + db) = exp(J_left db + O(db^2)) Delta(bbar),
 * P_left = Ad_Delta P Ad_Delta^T, J_left = Ad_Delta J. Their recursion
 * (src/cov/cov_step.h, "The left form") has the constant sparse transition
 *   F = [[I, 0, 0], [0, I, 0], [0, dt I, I]]
 * and moves the rotation by R^T from the covariance to the input matrix:
 * half the arithmetic of the right form per sample. se23_preint_unc_cov
 * returns the paper's P and J, once per factor.
 *
 * Classical first-order correction (Forster et al., IEEE T-RO 2017: the
 * first-order bias update of the preintegrated measurements and the
 * incremental Jacobians of its appendix), with this library's sign of the
 * bias (theirs is subtracted from the corrected reading, so every Jacobian
 * changes sign), accumulated over the same samples; right-hand sides hold
 * the values before sample k:
 *   dR/dbg+ = DR_k^T dR/dbg + Jr(w dt) dt       (DR_k = exp(w dt ^))
 *   dV/dbg+ = dV/dbg - DeltaR f^ dR/dbg dt,     dV/dba+ = dV/dba + DeltaR dt
 *   dX/dbg+ = dX/dbg + dV/dbg dt - DeltaR f^ dR/dbg dt^2/2
 *   dX/dba+ = dX/dba + dV/dba dt + DeltaR dt^2/2
 * and the correction
 *   DeltaR(bhat) ~ DeltaR exp(dR/dbg db_g),
 *   DeltaV(bhat) ~ DeltaV + dV/dbg db_g + dV/dba db_a,  DeltaX likewise.
 * These are the Jacobians of Euler-integrated Deltas; applied to the exact
 * Deltas of this library they stay first-order accurate.
 *
 * Functions index:
 *   se23_preint_unc_reset           empty factor at a bias estimate
 *   se23_preint_unc_reset_classic   the same, also accumulating Forster's Jacobians
 *   se23_preint_unc_add             one raw sample: Deltas, P, J (, classical)
 *   se23_preint_unc_add_work        the same, with the caller's work area (work.h)
 *   se23_preint_unc_check           validate a factor
 *   se23_preint_unc_cov             P and J of the paper's (right) form
 *   se23_preint_unc_correct         Delta(bbar) exp(J db), paper eq. biascor
 *   se23_preint_unc_correct_classic Forster et al.'s first-order correction
 *
 * Every function returns a status and writes its outputs (or changes the
 * factor) only on SE23_OK.
 */
#ifndef SE23_PREINT_UNC_H
#define SE23_PREINT_UNC_H

#include "se23/gauss.h"
#include "se23/imu.h"
#include "se23/preint.h"
#include "se23/types.h"
#include "se23/work.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Bias Jacobians of the classical (Forster et al. 2017) correction. */
typedef struct {
    se23_mat3_t dR_dbg; /**< right-perturbation of Delta R per gyro bias [s] */
    se23_mat3_t dV_dbg; /**< Delta V per gyro bias [m/s per rad/s] */
    se23_mat3_t dV_dba; /**< Delta V per accel bias [s] */
    se23_mat3_t dX_dbg; /**< Delta X per gyro bias [m per rad/s] */
    se23_mat3_t dX_dba; /**< Delta X per accel bias [s^2] */
} se23_preint_classic_t;

/**
 * A preintegrated factor with uncertainty. se23_preint_t comes first, so a
 * pointer to this struct's f serves every function of preint.h (prediction).
 * Start with se23_preint_unc_reset; change only through this header.
 */
typedef struct {
    se23_preint_t f;            /**< Deltas at the bias estimate, Delta t, sample count */
    se23_vec3_t b_g;            /**< gyro bias estimate bbar_g [rad/s] (added to w_meas) */
    se23_vec3_t b_a;            /**< accel bias estimate bbar_a [m/s^2] (added to f_meas) */
    se23_input_jac_kind_t kind; /**< input matrix of J and of the noise */
    int classic;                /**< nonzero: cl is accumulated (se23_preint_unc_reset_classic) */
    se23_mat9_t P_left;         /**< covariance of zeta, Delta_true = exp(zeta) Delta
                                 *   (file comment; se23_preint_unc_cov for P) */
    se23_mat9x6_t J_left;       /**< bias Jacobian of the left form [s]
                                 *   (se23_preint_unc_cov for J) */
    se23_preint_classic_t cl;   /**< classical Jacobians, for comparison (zero unless classic) */
} se23_preint_unc_t;

/**
 * fu = the empty factor at the bias estimate (b_g, b_a): Deltas (I, 0, 0),
 * Delta t = 0, P = 0, J = 0 (J_0 = 0, DESIGN.md; their left forms too),
 * classical Jacobians 0 and not accumulated
 * (se23_preint_unc_reset_classic for those). A factor
 * starts valid here and stays valid through se23_preint_unc_add, which
 * does not re-check it (types.h, "Validation policy").
 * @param b_g  gyro bias estimate [rad/s]
 * @param b_a  accel bias estimate [m/s^2]
 * @param kind input matrix for J and the noise (gauss.h)
 * @param fu   out: the empty factor (written only on SE23_OK)
 * @return SE23_ERR_NONFINITE (bias), SE23_ERR_DOMAIN (unknown kind).
 */
se23_status_t se23_preint_unc_reset(const se23_vec3_t *b_g,
                                    const se23_vec3_t *b_a,
                                    se23_input_jac_kind_t kind,
                                    se23_preint_unc_t *fu);

/**
 * As se23_preint_unc_reset, for a factor that also accumulates the
 * classical Jacobians of Forster et al. (file comment), for comparison:
 * about 300 more multiply-adds per sample. Only such a factor can be
 * corrected with se23_preint_unc_correct_classic.
 * @param b_g  gyro bias estimate [rad/s]
 * @param b_a  accel bias estimate [m/s^2]
 * @param kind input matrix for J and the noise (gauss.h)
 * @param fu   out: the empty factor, classic set (written only on SE23_OK)
 * @return as se23_preint_unc_reset.
 */
se23_status_t se23_preint_unc_reset_classic(const se23_vec3_t *b_g,
                                            const se23_vec3_t *b_a,
                                            se23_input_jac_kind_t kind,
                                            se23_preint_unc_t *fu);

/**
 * Adds one raw sample s (sensor readings; corrected with the factor's bias
 * estimate): the Deltas by se23_preint_add_increment with the exact
 * increment of the corrected sample; P+ = F_k P F_k^T + B_k N B_k^T
 * (paper eq. riccati, gauss.h noise model, bias walks unused) and J+ =
 * F_k J + B_k (paper eq. biascor), in the left form (file comment):
 * P_left+ = F P_left F^T + Bl N Bl^T, J_left+ = F J_left + Bl,
 * Bl = Ad_{Delta+} B_k; the classical Jacobians if the factor was reset with
 * se23_preint_unc_reset_classic (file comment). The sample and the noise
 * are checked; the factor is trusted (it comes from reset and add), and
 * re-checked with se23_preint_unc_check only if SE23_CFG_DEEP_CHECKS.
 * @param fu    the factor, changed in place (only on SE23_OK)
 * @param s     the raw sample: readings w_ib_b [rad/s], f_b [m/s^2]
 *              before bias correction, dt [s]
 * @param noise white-noise densities of the IMU (gauss.h)
 * @return SE23_ERR_NONFINITE (s, noise, or an increment, P+, J+, the
 *         classical Jacobians or the Deltas that would overflow: a huge
 *         density, a denormal dt, a force near the largest real),
 *         SE23_ERR_DT (s->dt
 *         outside (0, SE23_CFG_DT_MAX]), SE23_ERR_DOMAIN (negative density); with
 *         SE23_CFG_DEEP_CHECKS also the statuses of se23_preint_unc_check;
 *         fu is unchanged on error.
 */
se23_status_t se23_preint_unc_add(se23_preint_unc_t *fu,
                                  const se23_imu_sample_t *s,
                                  const se23_imu_noise_t *noise);

/**
 * se23_preint_unc_add with the step's intermediate results in the caller's
 * work area w (work.h) instead of on the stack: the same statuses and the
 * same results, bit for bit. w is scratch (unspecified after the call) and
 * must not overlap another argument.
 * @param fu    the factor, changed in place (only on SE23_OK)
 * @param s     the raw sample, as for se23_preint_unc_add
 * @param noise white-noise densities of the IMU (gauss.h)
 * @param w     the work area (scratch, caller-owned)
 * @return the statuses of se23_preint_unc_add; SE23_ERR_NULL also for a
 *         NULL w. fu is unchanged on error.
 */
se23_status_t se23_preint_unc_add_work(se23_preint_unc_t *fu,
                                       const se23_imu_sample_t *s,
                                       const se23_imu_noise_t *noise,
                                       se23_preint_work_t *w);

/**
 * Checks a factor (the deep check, for callers who want it): kind known,
 * classic 0 or 1, biases, J and the classical Jacobians
 * finite, Deltas an extended pose (finite, Delta R in SO(3)), Delta t finite
 * and >= 0, P_left a valid covariance (gauss.h, "Validation").
 * @param fu the factor to check
 * @return SE23_OK, SE23_ERR_NULL, SE23_ERR_DOMAIN, SE23_ERR_NONFINITE,
 *         SE23_ERR_NOT_ROTATION, SE23_ERR_DT, SE23_ERR_NOT_SYMMETRIC or
 *         SE23_ERR_NOT_PSD.
 */
se23_status_t se23_preint_unc_check(const se23_preint_unc_t *fu);

/**
 * P and J of the paper's form (file comment) from the factor's left form:
 * P = Ad_{Delta^-1} P_left Ad_{Delta^-1}^T, J = Ad_{Delta^-1} J_left, by
 * the covariance kernels of gauss.h (F_k with U = Delta, dt = 0). The
 * factor is checked (se23_preint_unc_check) first.
 * @param fu the factor
 * @param P out: the covariance of xi, Delta_true = Delta exp(xi) (exactly
 *          symmetric)
 * @param J out: the bias Jacobian: d = J db [s]; NULL if not wanted
 * @return the statuses of se23_preint_unc_check, SE23_ERR_NONFINITE (P or J
 *         would overflow: Deltas near the largest real); P and J are written
 *         only on SE23_OK.
 */
se23_status_t se23_preint_unc_cov(const se23_preint_unc_t *fu, se23_mat9_t *P,
                                  se23_mat9x6_t *J);

/**
 * out = the factor corrected to the new bias estimate bhat = (b_g, b_a)
 * without re-integration, in exponential coordinates (paper eq.
 * bias:discrep, eq. biascor):
 *   out.delta = fu.f.delta exp(J (bhat - bbar))
 *             = exp(J_left (bhat - bbar)) fu.f.delta,
 * out.dt and out.n copied. Error O(|bhat - bbar|^2).
 * @param fu  the factor, integrated at bbar
 * @param b_g new gyro bias estimate [rad/s]
 * @param b_a new accel bias estimate [m/s^2]
 * @param out out: the corrected factor (written only on SE23_OK)
 * @return the statuses of se23_preint_unc_check, SE23_ERR_NONFINITE (bias,
 *         or corrected Deltas that would overflow).
 */
se23_status_t se23_preint_unc_correct(const se23_preint_unc_t *fu,
                                      const se23_vec3_t *b_g,
                                      const se23_vec3_t *b_a,
                                      se23_preint_t *out);

/**
 * out = the classical first-order correction of Forster et al. 2017
 * (file comment) to the new bias estimate (b_g, b_a):
 * Delta R exp(dR/dbg db_g), Delta V + dV/dbg db_g + dV/dba db_a,
 * Delta X + dX/dbg db_g + dX/dba db_a; out.dt and out.n copied.
 * @param fu  the factor, from se23_preint_unc_reset_classic
 * @param b_g new gyro bias estimate [rad/s]
 * @param b_a new accel bias estimate [m/s^2]
 * @param out out: the corrected factor (written only on SE23_OK)
 * @return as se23_preint_unc_correct, and SE23_ERR_DOMAIN if fu does not
 *         accumulate the classical Jacobians (se23_preint_unc_reset_classic).
 */
se23_status_t se23_preint_unc_correct_classic(const se23_preint_unc_t *fu,
                                              const se23_vec3_t *b_g,
                                              const se23_vec3_t *b_a,
                                              se23_preint_t *out);

#ifdef __cplusplus
}
#endif

#endif /* SE23_PREINT_UNC_H */
