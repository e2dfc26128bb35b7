/*
 * The routines the target images test against reference vectors: one row
 * per public function (X-macro list; no include guard on purpose). Read by
 * tests/target/tv.h and tv_runner.c on the target and by
 * tools/target/gen_vectors.cpp on the host, which must have a generator of
 * the same name (it refuses to run otherwise). Adding a routine:
 *   1. one row here, of the kind matching its signature;
 *   2. one entry in the generator table of tools/target/gen_vectors.cpp
 *      (inputs + expected outputs from the Eigen reference).
 * Kinds (A, B inputs, O output; all structs of se23_real_t):
 *   TV_V0(fn, O, tol)          void fn(O *)
 *   TV_V1(fn, A, O, tol)       void fn(const A *, O *)
 *   TV_S1(fn, A, O, tol)       se23_status_t fn(const A *, O *)
 *   TV_V2(fn, A, B, O, tol)    void fn(const A *, const B *, O *)
 *   TV_S2(fn, A, B, O, tol)    se23_status_t fn(const A *, const B *, O *)
 *   TV_C1(fn, A, tol)          se23_status_t fn(const A *)  (a check)
 *   TV_CUSTOM(fn, n_in, n_out, tol)  anything else: write tv_call_<fn> in
 *                              tests/target/tv_custom.c
 * tol: outputs must satisfy |got - expected| <= tol * eps * scale (eps of
 * the build's precision; scale per output real from the generator: the
 * magnitude of its block, see tools/target/gen_common.hpp).
 * Routines tested on the target without vectors (names up to the first full
 * stop; tools/target/se23_api.py reads them): se23_status_str (by
 * tv_runner), the work-area calls se23_gauss_predict_work,
 * se23_preint_unc_add_work and se23_kalman_update_work (the plain calls'
 * vectors run them, each plain call being its work-area call with the
 * work area on its stack; the filter calls them in ins_replay), and the
 * navigation filter's se23_ins_setup, se23_ins_init,
 * se23_ins_align, se23_ins_imu, se23_ins_gnss, se23_ins_state,
 * se23_ins_take_factor, se23_ins_preset_foot, se23_ins_preset_car and
 * se23_ins_detector_threshold (by the image ins_replay of tests/target,
 * which runs recorded sequences through the filter and compares with the
 * host's double run at checkpoints, and compares the presets and the
 * threshold with the host's on a few inputs, every field of the
 * configuration; sequences and reference from tools/target/gen_ins_replay).
 */
#include "se23/earth.h"
#include "se23/gauss.h"
#include "se23/imu.h"
#include "se23/kalman.h"
#include "se23/preint.h"
#include "se23/preint_unc.h"
#include "se23/se23.h"
#include "se23/so3.h"

/* so3.h */
TV_V1(se23_so3_hat, se23_vec3_t, se23_mat3_t, 1)
TV_V1(se23_so3_vee, se23_mat3_t, se23_vec3_t, 1)
TV_S1(se23_so3_exp, se23_vec3_t, se23_mat3_t, 8)
TV_S1(se23_so3_log, se23_mat3_t, se23_vec3_t, 16)
TV_S1(se23_so3_jl, se23_vec3_t, se23_mat3_t, 8)
TV_S1(se23_so3_jl_inv, se23_vec3_t, se23_mat3_t, 16)
TV_S1(se23_so3_jr, se23_vec3_t, se23_mat3_t, 8)
TV_S1(se23_so3_h, se23_vec3_t, se23_mat3_t, 8)
TV_S1(se23_so3_k, se23_vec3_t, se23_mat3_t, 8)
TV_C1(se23_so3_check, se23_mat3_t, 0)
TV_S1(se23_so3_normalize, se23_mat3_t, se23_mat3_t, 8)

/* se23.h */
TV_V0(se23_identity, se23_pose_t, 0)
TV_V2(se23_compose, se23_pose_t, se23_pose_t, se23_pose_t, 8)
TV_V1(se23_inverse, se23_pose_t, se23_pose_t, 8)
TV_V2(se23_act, se23_pose_t, se23_vec3_t, se23_vec3_t, 8)
TV_V1(se23_hat, se23_tangent_t, se23_mat5_t, 1)
TV_V1(se23_vee, se23_mat5_t, se23_tangent_t, 1)
TV_V1(se23_to_mat5, se23_pose_t, se23_mat5_t, 0)
TV_S1(se23_from_mat5, se23_mat5_t, se23_pose_t, 0)
TV_S1(se23_exp, se23_tangent_t, se23_pose_t, 16)
TV_S1(se23_log, se23_pose_t, se23_tangent_t, 16)
TV_V1(se23_adjoint, se23_pose_t, se23_mat9_t, 8)
TV_V1(se23_adjoint_inv, se23_pose_t, se23_mat9_t, 8)
TV_C1(se23_pose_check, se23_pose_t, 0)

/* earth.h (se23_frame_t travels as a real) */
TV_CUSTOM(se23_earth_gravity, 2, 1, 8)
TV_CUSTOM(se23_earth_gravity_vec, 3, 3, 8)
TV_CUSTOM(se23_earth_rate, 2, 3, 8)
TV_CUSTOM(se23_earth_gamma, 2 * TV_REALS(se23_vec3_t) + 1, TV_REALS(se23_pose_t), 16)
TV_CUSTOM(se23_earth_model_init, 2 * TV_REALS(se23_vec3_t) + 2, TV_REALS(se23_earth_model_t), 16)
TV_CUSTOM(se23_earth_model_init_wgs84, 5, TV_REALS(se23_earth_model_t), 16)

/* imu.h */
TV_S1(se23_imu_increment, se23_imu_sample_t, se23_pose_t, 16)
TV_S1(se23_imu_increment_forster, se23_imu_sample_t, se23_pose_t, 16)
TV_S1(se23_imu_increment_paper, se23_imu_sample_t, se23_pose_t, 16)
TV_CUSTOM(se23_imu_transition, 3 * TV_REALS(se23_pose_t) + 1, TV_REALS(se23_pose_t), 16)
TV_CUSTOM(se23_imu_step,
          TV_REALS(se23_earth_model_t) + TV_REALS(se23_pose_t) + TV_REALS(se23_imu_sample_t),
          TV_REALS(se23_pose_t), 16)
TV_V2(se23_imu_carried_from_user, se23_earth_model_t, se23_pose_t, se23_pose_t, 8)
TV_V2(se23_imu_user_from_carried, se23_earth_model_t, se23_pose_t, se23_pose_t, 8)

/* preint.h (se23_preint_t travels as delta, dt, n: 17 reals) */
TV_CUSTOM(se23_preint_reset, 0, TV_PREINT_REALS, 0)
TV_CUSTOM(se23_preint_add, TV_PREINT_REALS + TV_REALS(se23_imu_sample_t), TV_PREINT_REALS, 16)
TV_CUSTOM(se23_preint_add_increment, TV_PREINT_REALS + TV_REALS(se23_pose_t) + 1,
          TV_PREINT_REALS, 16)
TV_CUSTOM(se23_preint_predict,
          TV_REALS(se23_earth_model_t) + TV_PREINT_REALS + TV_REALS(se23_pose_t),
          TV_REALS(se23_pose_t), 16)
TV_CUSTOM(se23_preint_predict_carried,
          TV_REALS(se23_earth_model_t) + TV_PREINT_REALS + TV_REALS(se23_pose_t),
          TV_REALS(se23_pose_t), 16)

/* gauss.h (se23_gauss_t travels as T, b_g, b_a, n, P: TV_GAUSS_REALS reals;
 * enums as reals) */
#define TV_FK_IN (TV_REALS(se23_pose_t) + 1)
TV_CUSTOM(se23_gauss_fk_apply, TV_FK_IN + 9, 9, 16)
TV_CUSTOM(se23_gauss_fk, TV_FK_IN, 81, 16)
TV_CUSTOM(se23_gauss_fk_mul, TV_FK_IN + 54, 54, 16)
TV_CUSTOM(se23_gauss_input_jac, 8, 54, 16)
TV_CUSTOM(se23_gauss_input_noise, 54 + TV_REALS(se23_imu_noise_t) + 1, 81, 16)
TV_CUSTOM(se23_gauss_cov_propagate, 81 + TV_REALS(se23_pose_t) + 1 + 81, 81, 16)
TV_CUSTOM(se23_gauss_check, TV_GAUSS_REALS, 0, 0)
TV_CUSTOM(se23_gauss_propagate,
          TV_GAUSS_REALS + TV_REALS(se23_pose_t) + 54 + TV_REALS(se23_imu_noise_t) + 1,
          TV_GAUSS_REALS, 16)
TV_CUSTOM(se23_gauss_predict,
          TV_REALS(se23_earth_model_t) + TV_GAUSS_REALS + TV_REALS(se23_imu_sample_t) +
              TV_REALS(se23_imu_noise_t) + 1,
          TV_GAUSS_REALS, 16)
TV_CUSTOM(se23_gauss_from_carried, TV_REALS(se23_earth_model_t) + TV_GAUSS_REALS,
          TV_GAUSS_REALS, 16)
TV_CUSTOM(se23_gauss_to_carried, TV_REALS(se23_earth_model_t) + TV_GAUSS_REALS,
          TV_GAUSS_REALS, 16)
#undef TV_FK_IN

/* kalman.h (se23_meas_t travels as m, z, H, R: TV_MEAS_REALS reals) */
TV_CUSTOM(se23_meas_pos_nav, TV_REALS(se23_pose_t) + 6 + 9, TV_MEAS_REALS, 16)
TV_CUSTOM(se23_meas_vel_nav, TV_REALS(se23_pose_t) + 3 + 9, TV_MEAS_REALS, 16)
TV_CUSTOM(se23_meas_vel_body, TV_REALS(se23_pose_t) + 3 + 9, TV_MEAS_REALS, 16)
TV_CUSTOM(se23_meas_vel_nav_lever, TV_REALS(se23_pose_t) + 9 + 9, TV_MEAS_REALS, 16)
TV_CUSTOM(se23_meas_zero_rate, 6 + 9, TV_MEAS_REALS, 16)
/* se23_meas_nhc's output, m = 2 only: m, z[0..1], rows 0..1 of H, R's
 * leading 2 x 2 (the rows beyond m are the library's to leave; a quarter
 * of TV_MEAS_REALS keeps the M7 image's double tables within its flash) */
#define TV_NHC_REALS (1 + 2 + 2 * SE23_GAUSS_NMAX + 4)
TV_CUSTOM(se23_meas_nhc, TV_REALS(se23_pose_t) + 9 + 1, TV_NHC_REALS, 16)
TV_CUSTOM(se23_kalman_update, TV_GAUSS_REALS + TV_MEAS_REALS, TV_GAUSS_REALS + 1, 32)

/* preint_unc.h (se23_preint_unc_t travels as TV_PREINT_UNC_REALS reals) */
TV_CUSTOM(se23_preint_unc_reset, 7, TV_PREINT_UNC_REALS, 0)
TV_CUSTOM(se23_preint_unc_reset_classic, 7, TV_PREINT_UNC_REALS, 0)
TV_CUSTOM(se23_preint_unc_add,
          TV_PREINT_UNC_REALS + TV_REALS(se23_imu_sample_t) + TV_REALS(se23_imu_noise_t),
          TV_PREINT_UNC_REALS, 16)
TV_CUSTOM(se23_preint_unc_check, TV_PREINT_UNC_REALS, 0, 0)
TV_CUSTOM(se23_preint_unc_correct, TV_PREINT_UNC_REALS + 6, TV_PREINT_REALS, 16)
TV_CUSTOM(se23_preint_unc_correct_classic, TV_PREINT_UNC_REALS + 6, TV_PREINT_REALS, 16)
TV_CUSTOM(se23_preint_unc_cov, TV_PREINT_UNC_REALS, 81 + 54, 16)

/* stationary.h (se23_stationary_t travels as its configuration, window
 * first as a real, then k and TV_ST_SAMPLES samples (w, f); load runs init
 * and the first adds, the j-th with sample j mod TV_ST_SAMPLES, see
 * tests/target/tv_custom.c) */
#include "se23/stationary.h"
#define TV_ST_SAMPLES 7
#define TV_ST_CFG 5
#define TV_ST_IN (TV_ST_CFG + 1 + 6 * TV_ST_SAMPLES)
#define TV_ST_STATE (TV_ST_CFG + 4)
TV_CUSTOM(se23_stationary_init, TV_ST_CFG, TV_ST_STATE, 0)
TV_CUSTOM(se23_stationary_add, TV_ST_IN, 5, 32)
TV_CUSTOM(se23_stationary_reset, TV_ST_CFG + 1 + 6, TV_ST_STATE, 0)
TV_CUSTOM(se23_stationary_mean, TV_ST_IN, 6, 16)
TV_CUSTOM(se23_stationary_var, TV_ST_IN, 6, 16)

/* align.h (se23_frame_t and counts travel as reals) */
#include "se23/align.h"
TV_CUSTOM(se23_align_level, 5, 9, 8)
TV_CUSTOM(se23_align_cov, 13, 9, 8)
TV_CUSTOM(se23_align_gyrocompass, 10, 11, 16)

/* geodetic.h (an integer travels as two reals hi = floor(x / 2^20) and
 * lo = x - 2^20 hi, exact in float; se23_geo_t as lat, lon, h: 6 reals; a
 * frame as its origin, built by se23_geo_origin in the loader; tol 1: the
 * bounds are the generator's scales, tools/target/gen_geo.cpp) */
#include "se23/geodetic.h"
#define TV_GEO_REALS 6
TV_CUSTOM(se23_geo_origin, TV_GEO_REALS, TV_GEO_REALS + 9, 1)
TV_CUSTOM(se23_geo_to_ned, 2 * TV_GEO_REALS, 3, 1)
TV_CUSTOM(se23_geo_from_ned, TV_GEO_REALS + 3, TV_GEO_REALS, 1)
TV_CUSTOM(se23_geo_down_at, TV_GEO_REALS + 3, 3, 1)
