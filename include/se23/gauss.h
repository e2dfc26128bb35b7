/**
 * @file gauss.h
 * @brief Concentrated Gaussians on SE_2(3) and their propagation through IMU
 *        samples (paper section 3), with optional gyro and accelerometer
 *        bias states (paper section 4, DESIGN.md section 3).
 *
 * Model. T = Tbar exp(xi), xi ~ N(0, Sigma) in R^9 (paper eq. error:rep1),
 * xi = (phi, nu, rho). With bias states the error is the 15-vector
 * e = (xi, db_g, db_a), db = b - bbar (true minus estimate).
 *
 * Sensor and bias convention (the paper's, section 3.3): the IMU reads
 *   w_meas = w - b_g - eta_g,   f_meas = f - b_a - eta_a,
 * so the corrected inputs are w = w_meas + bbar_g, f = f_meas + bbar_a, and
 * the true increment is Upsilon(w + db_g + eta_g, f + db_a + eta_a).
 *
 * Propagation over one sample (paper eq. riccati, with the bias input of
 * eq. biascor):
 *   xi+ = F_k xi + B_k (db + eta),           F_k = Ad_{Upsilon_k^-1} F,
 *   F(phi, nu, rho) = (phi, nu, rho + dt nu),
 *   B_k = d/d(db) log(Upsilon_k(bbar)^-1 Upsilon_k(bbar + db)) at db = 0,
 *   db+ = db + w_b (bias random walk).
 * F_k does not depend on Gamma, so the same F_k serves flat Earth (on T) and
 * rotating Earth (on the carried T' = (R, v + Omega x p, p), imu.h); convert
 * a rotating-Earth distribution to the user's (R, v, p) with
 * se23_gauss_from_carried.
 *
 * Noise discretisation. Each sample carries the average of the white sensor
 * noise over its interval (an IMU outputs averages; the zero-order hold of
 * imu.h), i.e. eta ~ N(0, N), N = diag(sg^2/dt I3, sa^2/dt I3) with the noise
 * densities sg [rad/s/sqrt(Hz)] and sa [m/s^2/sqrt(Hz)], constant over the
 * sample. It enters through the same B_k as the bias error, so
 *   Sigma_eta = B_k N B_k^T
 * (first order in eta). With the paper's basic B_k = dt I_{9,6} this is the
 * paper's diag(sg^2 dt I3, sa^2 dt I3, 0) (section 3.3). The bias random
 * walk adds diag(qg^2 dt I3, qa^2 dt I3) to the bias block (qg [rad/s^2/
 * sqrt(Hz)], qa [m/s^3/sqrt(Hz)]); its O(dt^2) effect on xi within one
 * sample is neglected.
 *
 * Storage. Covariances of the 9- or 15-dim error live in a se23_mat15_t,
 * flat row-major with stride 15 whatever n: element (i, j) is m[15*i + j];
 * only the leading n x n block is read or written. 9x6 input matrices are
 * flat row-major: element (i, j) is m[6*i + j], columns (g, a).
 *
 * Validation. A covariance is accepted when it is finite, its diagonal
 * (the variances) is nowhere negative (exactly: no tolerance), symmetric
 * (|P_ij - P_ji| <= tol s) and positive semidefinite within tolerance
 * (P + tol s I has a Cholesky factor), s = max_i |P_ii| and
 * tol = SE23_CFG_COV_TOL; otherwise SE23_ERR_NONFINITE, SE23_ERR_NOT_SYMMETRIC
 * or SE23_ERR_NOT_PSD, and nothing is written. Singular covariances (a known
 * initial pose, Sigma = 0) are valid. A sample interval must satisfy
 * 0 < dt <= SE23_CFG_DT_MAX, else SE23_ERR_DT (a NaN dt included).
 *
 * Functions index:
 *   se23_gauss_fk_apply, se23_gauss_fk, se23_gauss_fk_mul   F_k and products
 *   se23_gauss_input_jac        B_k, exact or the paper's basic dt I_{9,6}
 *   se23_gauss_input_noise      Sigma_eta = B_k N B_k^T
 *   se23_gauss_cov_propagate    Sigma+ = F_k Sigma F_k^T + Q (9x9)
 *   se23_gauss_check            validate a se23_gauss_t
 *   se23_gauss_propagate        covariance step of a se23_gauss_t (n = 9, 15)
 *   se23_gauss_predict          full filter prediction: mean and covariance
 *   se23_gauss_predict_work     the same, with the caller's work area (work.h)
 *   se23_gauss_from_carried, se23_gauss_to_carried   (R, v', p) <-> (R, v, p)
 *
 * All functions accept outputs that alias inputs.
 */
#ifndef SE23_GAUSS_H
#define SE23_GAUSS_H

#include "se23/earth.h"
#include "se23/imu.h"
#include "se23/types.h"
#include "se23/work.h"

#ifdef __cplusplus
extern "C" {
#endif


/** Largest error dimension and its two allowed values. */
#define SE23_GAUSS_NMAX 15
#define SE23_GAUSS_N_POSE 9  /**< xi only */
#define SE23_GAUSS_N_BIAS 15 /**< xi, db_g, db_a */

/** First index of the bias blocks in the 15-dim error. */
enum {
    SE23_IDX_BG = 9, /**< gyro bias error db_g [rad/s] */
    SE23_IDX_BA = 12 /**< accelerometer bias error db_a [m/s^2] */
};

/** Up to 15x15 matrix, flat row-major with stride 15: (i, j) is m[15*i + j]. */
typedef struct {
    se23_real_t m[SE23_GAUSS_NMAX * SE23_GAUSS_NMAX]; /**< (i, j) at m[15*i + j] */
} se23_mat15_t;

/** 9x6 matrix, flat row-major: (i, j) is m[6*i + j]. */
typedef struct {
    se23_real_t m[54]; /**< (i, j) at m[6*i + j] */
} se23_mat9x6_t;

/** IMU noise model: white-noise densities and bias random walks. */
typedef struct {
    se23_real_t gyro_noise;  /**< gyro white noise density [rad/s/sqrt(Hz)] */
    se23_real_t accel_noise; /**< accel white noise density [m/s^2/sqrt(Hz)] */
    se23_real_t gyro_walk;   /**< gyro bias random walk [rad/s^2/sqrt(Hz)] */
    se23_real_t accel_walk;  /**< accel bias random walk [m/s^3/sqrt(Hz)] */
} se23_imu_noise_t;

/** Which input matrix B_k to use. */
typedef enum {
    SE23_INPUT_JAC_EXACT = 0, /**< derivative of the exact increment (default) */
    SE23_INPUT_JAC_BASIC = 1  /**< the paper's dt I_{9,6} (eq. biascor), first order in dt */
} se23_input_jac_kind_t;

/**
 * A concentrated Gaussian on SE_2(3), optionally with bias states: the
 * filter state. Caller-owned; fill every field, then validate once with
 * se23_gauss_check (every function also checks what it reads).
 */
typedef struct {
    se23_pose_t T;   /**< mean Tbar: R body -> nav, v [m/s], p [m] in nav */
    se23_vec3_t b_g; /**< gyro bias estimate bbar_g [rad/s] (added to w_meas) */
    se23_vec3_t b_a; /**< accel bias estimate bbar_a [m/s^2] (added to f_meas) */
    int n;           /**< error dimension: 9 (biases fixed) or 15 (biases estimated) */
    se23_mat15_t P;  /**< covariance of (xi, db), leading n x n block */
} se23_gauss_t;

/**
 * y = F_k x with F_k = Ad_{U^-1} F (paper eq. riccati / magic:formula):
 *   y_phi = R^T x_phi,
 *   y_nu  = R^T (x_nu - v^ x_phi),
 *   y_rho = R^T (x_rho + dt x_nu - p^ x_phi),
 * U = (R, v, p) the increment Upsilon_k. The error propagation of a
 * noise-free step is exactly xi+ = F_k xi (paper Prop. bananaprop). No checks.
 * @param U  the increment Upsilon_k = (R, v, p) of the sample
 *           (se23_imu_increment)
 * @param dt sample interval [s]
 * @param x  an error xi = (phi, nu, rho) before the sample
 * @param y  out: F_k x, the error after it (may alias x)
 */
void se23_gauss_fk_apply(const se23_pose_t *U, se23_real_t dt,
                         const se23_tangent_t *x, se23_tangent_t *y);

/**
 * F = F_k as a dense 9x9 matrix (for inspection and tests). No checks.
 * @param U  the increment Upsilon_k = (R, v, p) of the sample
 * @param dt sample interval [s]
 * @param F  out: F_k, row-major (column j is se23_gauss_fk_apply of e_j)
 */
void se23_gauss_fk(const se23_pose_t *U, se23_real_t dt, se23_mat9_t *F);

/**
 * Y = F_k X for a 9x6 X, column by column with se23_gauss_fk_apply. Serves
 * the cross-covariance of the bias states and the preintegrated bias
 * Jacobian recursion J+ = F_k J + B_k (DESIGN.md section 3). No checks.
 * @param U  the increment Upsilon_k = (R, v, p) of the sample
 * @param dt sample interval [s]
 * @param X  a 9x6 matrix, rows (phi, nu, rho)
 * @param Y  out: F_k X (may alias X)
 */
void se23_gauss_fk_mul(const se23_pose_t *U, se23_real_t dt,
                       const se23_mat9x6_t *X, se23_mat9x6_t *Y);

/**
 * B = B_k, the 9x6 input matrix of the bias errors (columns db_g, db_a) for
 * one sample with corrected inputs w = w_meas + bbar_g, f = f_meas + bbar_a:
 *   log(Upsilon(w, f)^-1 Upsilon(w + dg, f + da)) = B (dg, da) + O(|d|^2)
 * (DESIGN.md "Bias Jacobian"; sign per the sensor convention above).
 * SE23_INPUT_JAC_EXACT differentiates the exact increment of imu.h,
 * Upsilon = (R, dt J(th) f, dt^2 H(th) f), th = w dt, R = exp(th^):
 *   [[ dt Jr(th),          0             ],
 *    [ dt^2 R^T D_J(th,f), dt Jr(th)     ],
 *    [ dt^3 R^T D_H(th,f), dt^2 R^T H(th)]],
 * D_S(th, f) = d(S(th) f)/d(th) for S = a0 I + a1 W + a2 W^2, W = th^:
 *   D_S = -a1 f^ + a2 ((th.f) I + th f^T - 2 f th^T)
 *         + (a1'/t th^ f + a2'/t th^ th^ f) th^T,   t = |th|.
 * SE23_INPUT_JAC_BASIC is the paper's dt I_{9,6} (first order in dt).
 * @param kind which B_k: SE23_INPUT_JAC_EXACT or SE23_INPUT_JAC_BASIC
 * @param w_b corrected angular rate, body frame [rad/s]
 * @param f_b corrected specific force, body frame [m/s^2]
 * @param dt  sample interval [s], 0 < dt <= SE23_CFG_DT_MAX
 * @param B   out: B_k, rows (phi, nu, rho), columns (db_g, db_a)
 *            (written only on SE23_OK)
 * @return SE23_ERR_NONFINITE (NaN/Inf in, or B would overflow), SE23_ERR_DT,
 *         or SE23_ERR_DOMAIN for an unknown kind.
 */
se23_status_t se23_gauss_input_jac(se23_input_jac_kind_t kind,
                                   const se23_vec3_t *w_b,
                                   const se23_vec3_t *f_b, se23_real_t dt,
                                   se23_mat9x6_t *B);

/**
 * Q = Sigma_eta = B N B^T with N = diag(sg^2/dt I3, sa^2/dt I3) (file
 * comment: sample-averaged white noise), exactly symmetric. Only the white
 * noise densities of the noise model enter Q; the bias walks are checked
 * all the same.
 * @param B     the input matrix B_k of the sample (se23_gauss_input_jac)
 * @param noise the IMU noise model
 * @param dt    sample interval [s], 0 < dt <= SE23_CFG_DT_MAX
 * @param Q     out: Sigma_eta, the 9x9 covariance the sample's white noise
 *              adds to the error (written only on SE23_OK)
 * @return SE23_ERR_NONFINITE (NaN/Inf in B or noise, or a Q that would
 *         overflow), SE23_ERR_DT (dt <= 0 or > SE23_CFG_DT_MAX), or
 *         SE23_ERR_DOMAIN if a density or a walk is negative.
 */
se23_status_t se23_gauss_input_noise(const se23_mat9x6_t *B,
                                     const se23_imu_noise_t *noise,
                                     se23_real_t dt, se23_mat9_t *Q);

/**
 * S_next = F_k S F_k^T + Q (paper eq. riccati) for a 9x9 covariance S,
 * computed as F_k (F_k S)^T with se23_gauss_fk_apply (rotation blocks and
 * shears, no dense 9x9 product) and made exactly symmetric by mirroring the
 * upper triangle.
 * S and Q are caller input and fully checked; S_next may alias S or Q.
 * @param S      the 9x9 covariance of xi before the sample
 * @param U      the increment Upsilon_k of the sample (R in SO(3))
 * @param dt     sample interval [s], 0 < dt <= SE23_CFG_DT_MAX
 * @param Q      the 9x9 noise covariance added (se23_gauss_input_noise)
 * @param S_next out: the covariance after the sample (written only on
 *               SE23_OK)
 * @return SE23_ERR_NONFINITE, SE23_ERR_NOT_SYMMETRIC or SE23_ERR_NOT_PSD
 *         (S or Q, file comment), SE23_ERR_NOT_ROTATION (U),
 *         SE23_ERR_DT (dt <= 0 or > SE23_CFG_DT_MAX), SE23_ERR_NONFINITE
 *         if S_next would overflow (the O(n) bound of se23_gauss_predict on
 *         S's largest variance and U decides).
 */
se23_status_t se23_gauss_cov_propagate(const se23_mat9_t *S,
                                       const se23_pose_t *U, se23_real_t dt,
                                       const se23_mat9_t *Q,
                                       se23_mat9_t *S_next);

/**
 * Checks a filter state: n is 9 or 15, T finite with R in SO(3), biases
 * finite, P a valid covariance (file comment).
 * @param g the state to check
 * @return SE23_OK, SE23_ERR_NULL, SE23_ERR_DIM, SE23_ERR_NONFINITE, SE23_ERR_NOT_ROTATION,
 *         SE23_ERR_NOT_SYMMETRIC or SE23_ERR_NOT_PSD.
 */
se23_status_t se23_gauss_check(const se23_gauss_t *g);

/**
 * out = g with its covariance propagated over one sample, mean unchanged:
 *   P+ = Phi P Phi^T + diag(B N B^T, walk),  Phi = F_k (n = 9) or
 *   Phi = [[F_k, B_k], [0, I6]] (n = 15),
 * computed with se23_gauss_fk_apply (no dense products), exactly symmetric.
 * U and B must be the increment and input matrix at the corrected inputs of
 * the sample (se23_gauss_predict does all of this).
 * @param g     the state before the sample (trusted but for g->n, types.h)
 * @param U     increment Upsilon_k (se23_imu_increment)
 * @param B     input matrix B_k (se23_gauss_input_jac)
 * @param noise IMU noise model (walks used only for n = 15)
 * @param dt    sample interval [s]
 * @param out   out: g with P+ (may alias g; written only on SE23_OK)
 * @return SE23_ERR_DIM (n), SE23_ERR_NOT_ROTATION (U), SE23_ERR_NONFINITE
 *         (B, noise), SE23_ERR_DOMAIN (negative noise parameter, or B's
 *         rotation rows depend on the accelerometer, which no B_k does),
 *         SE23_ERR_DT; with SE23_CFG_DEEP_CHECKS the statuses of
 *         se23_gauss_check.
 */
se23_status_t se23_gauss_propagate(const se23_gauss_t *g, const se23_pose_t *U,
                                   const se23_mat9x6_t *B,
                                   const se23_imu_noise_t *noise,
                                   se23_real_t dt, se23_gauss_t *out);

/**
 * out = g propagated through one raw IMU sample s (sensor readings, before
 * bias correction): corrected inputs w = s.w + b_g, f = s.f + b_a; mean by
 * se23_imu_step (exact, flat or rotating Earth per model; on rotating Earth
 * g holds the carried state), covariance by se23_gauss_propagate with the
 * exact increment and the input matrix of the given kind. Biases keep their
 * estimates (random-walk model).
 * The state g is trusted (types.h, "Validation policy"): only g->n is
 * checked, unless SE23_CFG_DEEP_CHECKS.
 * @param model the Earth model (gravity, Earth rate, nominal dt; earth.h)
 * @param g     the state at the sample's start, in the model's coordinates
 * @param s     the raw sample: readings w_ib_b [rad/s], f_b [m/s^2], dt [s]
 * @param noise the IMU noise model (walks used only for n = 15)
 * @param kind  the input matrix B_k: SE23_INPUT_JAC_EXACT or
 *              SE23_INPUT_JAC_BASIC
 * @param out   out: the state at the sample's end (may alias g; written
 *              only on SE23_OK)
 * @return SE23_ERR_DIM (n), SE23_ERR_DOMAIN (kind, a negative density),
 *         the sample statuses of se23_imu_step (SE23_ERR_NONFINITE,
 *         SE23_ERR_DT), SE23_ERR_NONFINITE also when the mean or P+ would
 *         overflow (a huge density, a denormal dt, a covariance or a state
 *         near the largest real: an O(n) bound decides before anything is
 *         stored).
 */
se23_status_t se23_gauss_predict(const se23_earth_model_t *model,
                                 const se23_gauss_t *g,
                                 const se23_imu_sample_t *s,
                                 const se23_imu_noise_t *noise,
                                 se23_input_jac_kind_t kind,
                                 se23_gauss_t *out);

/**
 * se23_gauss_predict with the step's intermediate results in the caller's
 * work area w (work.h) instead of on the stack: the same statuses and the
 * same results, bit for bit. w is scratch (unspecified after the call) and
 * must not overlap another argument.
 * @param model the Earth model (earth.h)
 * @param g     the state at the sample's start, in the model's coordinates
 * @param s     the raw sample
 * @param noise the IMU noise model
 * @param kind  the input matrix B_k
 * @param w     the work area (scratch, caller-owned)
 * @param out   out: the state at the sample's end (may alias g)
 * @return the statuses of se23_gauss_predict; SE23_ERR_NULL also for a
 *         NULL w. On error out is not written.
 */
se23_status_t se23_gauss_predict_work(const se23_earth_model_t *model,
                                      const se23_gauss_t *g,
                                      const se23_imu_sample_t *s,
                                      const se23_imu_noise_t *noise,
                                      se23_input_jac_kind_t kind,
                                      se23_predict_work_t *w, se23_gauss_t *out);

/**
 * out = the distribution of the user's state (R, v, p) from that of the
 * carried state (R, v' = v + Omega x p, p), Omega = model->w_ie_n
 * (DESIGN.md section 3): mean by se23_imu_user_from_carried; errors, to
 * first order, xi = M xi' with
 *   M = [[I, 0, 0], [0, I, -(Rbar^T Omega)^], [0, 0, I]]
 * (identity on the bias block), P = M P' M^T, exactly symmetric.
 * The state g is trusted (types.h, "Validation policy"): only g->n is
 * checked, unless SE23_CFG_DEEP_CHECKS.
 * @param model the Earth model: its Earth rate Omega = w_ie_n
 * @param g     the carried state and its covariance
 * @param out   out: the user's state and its covariance (may alias g;
 *              written only on SE23_OK)
 * @return SE23_ERR_DIM (n), SE23_ERR_NONFINITE (Omega, or a mean or P
 *         that would overflow: Omega x p or M P M^T beyond the largest
 *         real); with SE23_CFG_DEEP_CHECKS the statuses of
 *         se23_gauss_check.
 */
se23_status_t se23_gauss_from_carried(const se23_earth_model_t *model,
                                      const se23_gauss_t *g,
                                      se23_gauss_t *out);

/**
 * out = the carried distribution of a user's one, the inverse of
 * se23_gauss_from_carried: v' = v + Omega x p, M^-1 = M with +(Rbar^T Omega)^.
 * @param model the Earth model: its Earth rate Omega = w_ie_n
 * @param g     the user's state and its covariance
 * @param out   out: the carried state and its covariance (may alias g;
 *              written only on SE23_OK)
 * @return as se23_gauss_from_carried.
 */
se23_status_t se23_gauss_to_carried(const se23_earth_model_t *model,
                                    const se23_gauss_t *g,
                                    se23_gauss_t *out);

#ifdef __cplusplus
}
#endif

#endif /* SE23_GAUSS_H */
