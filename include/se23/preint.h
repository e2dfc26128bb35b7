/**
 * @file preint.h
 * @brief Preintegrated IMU factor between two instants t_i and t_j: the
 *        Deltas accumulated sample by sample with the exact increment, and
 *        the exact prediction of the state at t_j from any state at t_i, on
 *        flat and on rotating Earth (paper sections 1 and 2).
 *
 * Accumulation. The Deltas Upsilon_{i->j} = (Delta R, Delta V, Delta X) solve
 * paper eq. ODE from (I, 0, 0) (its third initial condition is
 * X_0 = 0, DESIGN.md section 3); with piecewise-constant samples this is,
 * per sample k of duration dt_k,
 *   Upsilon <- Phi_{dt_k}(Upsilon) Upsilon_k,   Upsilon_k = se23_imu_increment,
 * exactly. The Deltas depend on the IMU samples only, not on the state, g or
 * Omega.
 *
 * Prediction over Delta t = sum dt_k (paper eq. discrete and Proposition
 * "Preintegration with Coriolis effect"):
 *   T'_j = Gamma'(Delta t) Phi_{Delta t}(T'_i) Upsilon_{i->j}
 * on carried states T' = (R, v + Omega x p, p), with Gamma' from
 * se23_earth_gamma. Written out for the user's states this is the
 * Proposition: R_j = G^R R_i dR, p_j = G^x + G^R (R_i dX + Delta t v'_i + p_i),
 * v_j = G^v + G^R (R_i dV + v'_i) - Omega x p_j, v'_i = v_i + Omega x p_i.
 * Prediction from a factor equals step-by-step propagation (se23_imu_step)
 * up to rounding. Delta V and Delta X grow as g t and g t^2/2 and cancel
 * against Gamma' in the prediction: in the float build keep factors short
 * (a 60 s factor loses ~2e-4 relative, crosscheck_nav; 0.1-0.5 s factors are
 * the most accurate way to propagate in float, tools/doc/pages/propagation.md).
 *
 * Extension. The covariance (9x9) and the bias Jacobian (9x6) of the Deltas
 * are meant to live in a wrapper that embeds se23_preint_t as its first
 * member; such code computes Upsilon_k itself (se23_imu_increment, it needs it
 * for F_k = Ad_{Upsilon_k^-1} F) and accumulates it with
 * se23_preint_add_increment, so that both use one increment.
 *
 * Functions index:
 *   se23_preint_reset           empty factor
 *   se23_preint_add             one checked sample
 *   se23_preint_add_increment   one precomputed increment, no checks
 *   se23_preint_predict         user state at t_j from user state at t_i
 *   se23_preint_predict_carried carried state at t_j from carried state at t_i
 */
#ifndef SE23_PREINT_H
#define SE23_PREINT_H

#include <stdint.h>

#include "se23/earth.h"
#include "se23/imu.h"
#include "se23/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** A preintegrated factor. Start with se23_preint_reset. */
typedef struct {
    se23_pose_t delta; /**< Upsilon_{i->j} = (Delta R, Delta V [m/s], Delta X [m]), body frame at t_i */
    se23_real_t dt;    /**< Delta t = t_j - t_i, the sum of the samples' dt [s] */
    uint32_t n;        /**< number of samples accumulated */
} se23_preint_t;

/**
 * f = the empty factor: Deltas (I, 0, 0), Delta t = 0, no samples.
 * @param f out: the factor to (re)start
 */
void se23_preint_reset(se23_preint_t *f);

/**
 * Adds one sample: f.delta <- Phi_dt(f.delta) Upsilon(s), f.dt += s.dt,
 * f.n += 1 (exact for a zero-order-hold sample).
 * @param f the factor, changed in place (only on SE23_OK)
 * @param s the sample: w_ib_b [rad/s], f_b [m/s^2] (already corrected by
 *          any bias estimate the caller applies), dt [s]
 * @return SE23_ERR_NONFINITE (NaN/Inf in s or f, or Deltas that would
 *         overflow), SE23_ERR_DT unless
 *         0 < s.dt <= SE23_CFG_DT_MAX (or f.dt < 0), SE23_ERR_NOT_ROTATION
 *         (f.delta.R not in SO(3) within SE23_CFG_ROT_TOL); f is unchanged
 *         on error.
 */
se23_status_t se23_preint_add(se23_preint_t *f, const se23_imu_sample_t *s);

/**
 * Adds one increment ups of duration dt [s] computed by the caller
 * (se23_imu_increment): f.delta <- Phi_dt(f.delta) ups, f.dt += dt, f.n += 1.
 * No checks.
 * @param f   the factor, changed in place
 * @param ups the sample's increment Upsilon_k
 * @param dt  the sample's duration [s]
 */
void se23_preint_add_increment(se23_preint_t *f, const se23_pose_t *ups,
                               se23_real_t dt);

/**
 * T_j = the user's state (R, v, p) at t_j predicted exactly from the user's
 * state T_i at t_i through the factor f, with the model's g and Omega
 * (Proposition "Preintegration with Coriolis effect"; flat Earth, paper
 * eq. discrete, when model->w_ie_n = 0). model->dt is not used.
 * @param model the Earth model: gravity g_n and Earth rate w_ie_n (earth.h)
 * @param f     the factor from t_i to t_j
 * @param T_i   the user's state (R, v, p) at t_i
 * @param T_j   out: the user's state at t_j (may alias T_i)
 * @return SE23_ERR_NONFINITE (NaN/Inf in T_i, f or the model, or a T_j
 *         that would overflow),
 *         SE23_ERR_NOT_ROTATION (T_i.R or f.delta.R), SE23_ERR_DT (f.dt < 0);
 *         T_j is unchanged on error.
 */
se23_status_t se23_preint_predict(const se23_earth_model_t *model,
                                  const se23_preint_t *f, const se23_pose_t *T_i,
                                  se23_pose_t *T_j);

/**
 * Tc_j = Gamma'(f.dt) Phi_{f.dt}(Tc_i) f.delta: the same prediction on carried
 * states Tc = (R, v + Omega x p, p), as se23_imu_step propagates them.
 * @param model the Earth model: gravity g_n and Earth rate w_ie_n (earth.h)
 * @param f     the factor from t_i to t_j
 * @param Tc_i  the carried state at t_i
 * @param Tc_j  out: the carried state at t_j (may alias Tc_i)
 * @return as se23_preint_predict.
 */
se23_status_t se23_preint_predict_carried(const se23_earth_model_t *model,
                                          const se23_preint_t *f,
                                          const se23_pose_t *Tc_i,
                                          se23_pose_t *Tc_j);

#ifdef __cplusplus
}
#endif

#endif /* SE23_PREINT_H */
