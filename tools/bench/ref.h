/*
 * The dense Eigen reference of the benchmark's composite steps (ref_*.cpp,
 * C++17, fixed-size Eigen matrices), callable from C. Written from the
 * math (DESIGN.md section 3), not from the library: it shares only the
 * data layout of the se23 types, which it reads and writes. Compiled in
 * the precision of se23_real_t, like the library it is compared with.
 * Angles (w dt, Omega dt, the update's rotation) must stay below 1 rad:
 * the reference evaluates the SO(3) series by their Taylor sums.
 */
#ifndef SE23_BENCH_REF_H
#define SE23_BENCH_REF_H

#include "se23/earth.h"
#include "se23/gauss.h"
#include "se23/imu.h"
#include "se23/preint_unc.h"

#ifdef __cplusplus
extern "C" {
#endif

/* gamma = Gamma'(dt) = (exp(-Omega^ dt), dt J(-Omega dt) g, dt^2 K(-Omega dt) g). */
void ref_gamma(const se23_vec3_t *g_n, const se23_vec3_t *w_ie_n, se23_real_t dt,
               se23_pose_t *gamma);

/* out = g (n = 9 or 15, carried state) through the raw sample s: the mean
 * T+ = Gamma' Phi_dt(T) Upsilon with Gamma' = model->gamma, and
 * P+ = Phi P Phi^T + Q, Phi = F_k or [[F_k, B], [0, I]], dense. */
void ref_gauss_predict(const se23_earth_model_t *model, const se23_gauss_t *g,
                       const se23_imu_sample_t *s, const se23_imu_noise_t *noise,
                       se23_gauss_t *out);

/* out = fu plus the raw sample s: Deltas, P and J (not the classical
 * Jacobians, which out does not receive). */
void ref_preint_add(const se23_preint_unc_t *fu, const se23_imu_sample_t *s,
                    const se23_imu_noise_t *noise, se23_preint_unc_t *out);

/* out = g (n = 15) updated with the GNSS position fix p_n of the antenna
 * at lever_b, noise cov: dense H, S with LLT, K, Joseph form, retraction.
 * Returns 0, or 1 (out untouched) if S has no Cholesky factor. */
int ref_gnss_update(const se23_gauss_t *g, const se23_vec3_t *p_n,
                     const se23_vec3_t *lever_b, const se23_mat3_t *cov,
                     se23_gauss_t *out);

#ifdef __cplusplus
}
#endif

#endif /* SE23_BENCH_REF_H */
