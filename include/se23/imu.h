/**
 * @file imu.h
 * @brief Exact propagation of an extended pose through IMU samples, on flat
 *        and on rotating Earth (paper sections 1 and 2).
 *
 * Model. An IMU sample holds the angular rate w_ib_b and the specific force
 * f_b, both in the body frame, constant over [t_k, t_k + dt) (zero-order
 * hold). Over that interval the navigation equations (paper eq. nav:eq, flat;
 * eq. nav:eq_Coriolis, rotating Earth with constant Omega) have the exact
 * solution (paper eq. discrete2)
 *   T' <- Gamma' Phi_dt(T') Upsilon,
 * where
 *   Phi_dt(R, v, p) = (R, v, p + dt v)                      (eq. phi:eq)
 *   Upsilon = (exp(w dt ^), dt J(w dt) f, dt^2 H(w dt) f)   (exact increment)
 *   Gamma'  = se23_earth_model_t.gamma                      (earth.h)
 * and T' = (R, v' = v + Omega x p, p) is the carried state of paper eq.
 * eq:trick. On flat Earth (Omega = 0) T' = T and Gamma' = (I, g dt, g dt^2/2):
 * the same step is paper eq. discrete2. J and H are the series of so3.h.
 * The step is exact for piecewise-constant inputs, whatever dt and the rates:
 * its only errors are rounding.
 *
 * Float build. Every step rounds the state's R (entries of size 1) once more;
 * over an hour at 100 Hz that walks the attitude by ~1e-4 rad and the
 * position by kilometres (tools/doc/pages/propagation.md, `make accuracy`). Feeding the samples into
 * short preintegrated factors (se23_preint_add, 0.1-0.5 s) and applying each
 * factor with se23_preint_predict_carried rounds R only once per factor and
 * loses about 100 times less; the Deltas, near the identity, keep their
 * small rotations to full relative precision.
 *
 * Carried state. The user's state is (R, v, p), v the velocity relative to
 * the Earth-fixed nav frame. Convert with se23_imu_carried_from_user before
 * propagating and se23_imu_user_from_carried to read v back. (Covariances
 * convert with M = [[I,0,0],[0,I,-(R^T Omega)^],[0,0,I]], DESIGN.md section 3.)
 *
 * Functions index:
 *   se23_imu_increment          exact Upsilon of one sample
 *   se23_imu_increment_forster  Forster et al.'s first-order Upsilon (f dt^2/2), for comparison
 *   se23_imu_increment_paper    the paper's literal Upsilon, eq. backtofuture (0), for comparison
 *   se23_imu_transition         out = Gamma Phi_t(T) Upsilon, no checks
 *   se23_imu_step               one checked propagation step of a carried state
 *   se23_imu_carried_from_user, se23_imu_user_from_carried   v' = v + Omega x p
 *
 * All functions accept outputs that alias inputs.
 */
#ifndef SE23_IMU_H
#define SE23_IMU_H

#include "se23/earth.h"
#include "se23/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** One IMU sample, held constant over [t, t + dt). */
typedef struct {
    se23_vec3_t w_ib_b; /**< angular rate of the body w.r.t. inertial space, body frame [rad/s] */
    se23_vec3_t f_b;    /**< specific force (acceleration minus gravity), body frame [m/s^2] */
    se23_real_t dt;     /**< duration of the sample [s] */
} se23_imu_sample_t;

/**
 * ups = Upsilon(w, f, dt) = (exp(w dt ^), dt J(w dt) f, dt^2 H(w dt) f),
 * the exact solution over one sample of paper eq. ODE
 * (dR/dt = R w^, dV/dt = R f, dX/dt = V from (I, 0, 0)). J = J_l, H as in so3.h.
 * Public and check-free beyond the sample, so that covariance propagation
 * (F_k = Ad_{Upsilon^-1} F) and bias Jacobians can reuse it.
 * @param s   the sample: w_ib_b [rad/s] and f_b [m/s^2] held over dt [s]
 * @param ups out: Upsilon = (R, v [m/s], p [m]) in the body frame at the
 *            sample's start (written only on SE23_OK)
 * @return SE23_ERR_NONFINITE if the sample holds NaN/Inf or the increment
 *         overflows, SE23_ERR_DT unless
 *         0 < dt <= SE23_CFG_DT_MAX.
 */
se23_status_t se23_imu_increment(const se23_imu_sample_t *s, se23_pose_t *ups);

/**
 * ups = (exp(w dt ^), dt f, dt^2 f / 2): the discrete model of Forster et
 * al., "On-manifold preintegration for real-time visual-inertial odometry",
 * IEEE T-RO 2017, the rotation exact and R held at its value at the start of
 * the sample in the velocity and position lines. It is also the paper's
 * remark after eq. discrete2 with its missing 1/2 restored (the paper prints
 * dt^2 f, DESIGN.md section 3). First order in dt: its error per sample is
 * O(|w| |f| dt^2) in velocity, so over a fixed time the error shrinks like dt.
 * Provided to measure what the exact increment gains and to run Forster et
 * al.'s pipeline as they define it (tools/doc/pages/propagation.md).
 * @param s   the sample, as for se23_imu_increment
 * @param ups out: Forster et al.'s increment (written only on SE23_OK)
 * @return as se23_imu_increment.
 */
se23_status_t se23_imu_increment_forster(const se23_imu_sample_t *s,
                                         se23_pose_t *ups);

/**
 * ups = (exp(w dt ^), dt f, 0): the paper's increment exactly as printed in
 * eq. backtofuture ("to the first order in dt"), the one its noise model
 * (eq. discrete3) and its bias correction (eq. approx2:eq) start from. It
 * differs from se23_imu_increment_forster only in the position, by
 * dt^2 f / 2, so over a fixed time its position error also shrinks like dt,
 * with a larger constant (the whole f dt^2 / 2 of every sample is lost).
 * Provided to run the paper's comparisons with its own increment (tools/doc/pages/paper.md).
 * @param s   the sample, as for se23_imu_increment
 * @param ups out: the paper's increment (written only on SE23_OK)
 * @return as se23_imu_increment.
 */
se23_status_t se23_imu_increment_paper(const se23_imu_sample_t *s, se23_pose_t *ups);

/**
 * out = Gamma Phi_t(T) Upsilon  (paper eq. discrete), Phi_t(R, v, p) =
 * (R, v, p + t v). The building block of se23_imu_step (Gamma = Gamma'(dt),
 * one sample), of preintegration (Gamma = I, accumulating Deltas: pass
 * gamma = NULL, which skips the product) and of prediction (Gamma =
 * Gamma'(Delta t), one factor). out.R is re-orthonormalised (one
 * Newton-Schulz step once |R^T R - I| passes 4 eps), so that rounding drift
 * never accumulates. No checks: NaN in gives NaN out.
 * @param gamma Gamma, applied on the left; NULL for the identity
 * @param T     the pose at the interval's start
 * @param ups   the increment Upsilon over the interval, on the right
 * @param t     the interval's length [s] (Phi_t)
 * @param out   out: Gamma Phi_t(T) Upsilon (may alias any input)
 */
void se23_imu_transition(const se23_pose_t *gamma, const se23_pose_t *T,
                         const se23_pose_t *ups, se23_real_t t,
                         se23_pose_t *out);

/**
 * T_next = Gamma' Phi_dt(T) Upsilon(s): one exact propagation step of the
 * carried state T = (R, v + Omega x p, p) over the sample s (paper eq.
 * discrete2; with model->w_ie_n = 0, T is the plain (R, v, p), flat Earth).
 * Gamma' is model->gamma when s->dt equals model->dt to within 4 ulp, and
 * is recomputed for s->dt otherwise (timing jitter costs one more
 * se23_earth_gamma, not accuracy).
 * R_next is kept orthonormal to rounding (se23_imu_transition), so a long
 * run never drifts out of the SO(3) check.
 * @param model  the Earth model (gravity, Earth rate, dt, dt_max, Gamma';
 *               earth.h)
 * @param T      the carried state at the sample's start
 * @param s      the sample, used as it is (no bias correction here)
 * @param T_next out: the carried state at its end (may alias T)
 * @return SE23_ERR_NONFINITE (NaN/Inf in s or T, or a T_next that would
 *         overflow), SE23_ERR_DT unless
 *         0 < s->dt <= model->dt_max, SE23_ERR_NOT_ROTATION (T.R not in
 *         SO(3) within SE23_CFG_ROT_TOL), the statuses of se23_earth_gamma
 *         when Gamma' is recomputed; T_next is untouched on error.
 */
se23_status_t se23_imu_step(const se23_earth_model_t *model,
                            const se23_pose_t *T, const se23_imu_sample_t *s,
                            se23_pose_t *T_next);

/**
 * Tc = (R, v + Omega x p, p): the carried state of the user's T = (R, v, p)
 * (paper eq. eq:trick), Omega = model->w_ie_n. No checks.
 * @param model the Earth model: its Earth rate Omega = w_ie_n [rad/s]
 * @param T     the user's state, v relative to the Earth-fixed nav frame
 * @param Tc    out: the carried state (may alias T)
 */
void se23_imu_carried_from_user(const se23_earth_model_t *model,
                                const se23_pose_t *T, se23_pose_t *Tc);

/**
 * T = (R, v' - Omega x p, p): the user's state of a carried Tc = (R, v', p).
 * No checks.
 * @param model the Earth model: its Earth rate Omega = w_ie_n [rad/s]
 * @param Tc    the carried state
 * @param T     out: the user's state (may alias Tc)
 */
void se23_imu_user_from_carried(const se23_earth_model_t *model,
                                const se23_pose_t *Tc, se23_pose_t *T);

#ifdef __cplusplus
}
#endif

#endif /* SE23_IMU_H */
