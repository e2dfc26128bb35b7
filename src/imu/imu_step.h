/**
 * @file imu_step.h
 * @brief Internal: the propagation step that also hands back the increment
 *        it used and the pieces of it (series coefficients, J, H) that the
 *        input matrix reuses, so that one filter prediction (gauss.c)
 *        evaluates the SO(3) series once per sample.
 */
#ifndef SE23_IMU_STEP_H
#define SE23_IMU_STEP_H

#include "se23/imu.h"
#include "../lie/so3_series.h"

/** What the exact increment of one sample computed on the way. */
typedef struct {
    se23_vec3_t th;       /**< w dt [rad] */
    se23_real_t t;        /**< |th| */
    se23_so3_coeffs_t c;  /**< c1..c4 at t */
    se23_mat3_t J;        /**< J_l(th) */
    se23_mat3_t H;        /**< H(th) */
    int tame;             /**< se23_sample_tame of the sample (set by
                               se23_imu_step_ups only) */
} se23_increment_parts_t;

/** SE23_ERR_NONFINITE unless the sample is finite, SE23_ERR_DT unless
 *  0 < dt <= dt_max. */
se23_status_t se23_imu_sample_check(const se23_imu_sample_t *s, se23_real_t dt_max);

/** c = s with the bias estimates added (w + b_g, f + b_a; the filter's and
 *  the factor's corrected sample). May overflow: checked by the caller. */
void se23_imu_sample_corrected(const se23_imu_sample_t *s, const se23_vec3_t *b_g,
                               const se23_vec3_t *b_a, se23_imu_sample_t *c);

/**
 * Nonzero for every sample an IMU gives: |w dt|_1 <= 8, dt <= 8 and
 * |f|_1 <= SE23_SAMPLE_F_TAME, about the square root of the largest real.
 * Then nothing the increment and its input matrix compute can overflow:
 * every series coefficient and derivative they use is at most 1 in
 * magnitude (|th| <= 8), and each intermediate is at most
 * 4 (1 + |f|_1) (1 + |w dt|_1)^3 (1 + dt)^3 < 2^23 (1 + |f|_1) (see
 * se23_input_blocks_finite). O(1); NaN is not tame.
 */
int se23_sample_tame(const se23_imu_sample_t *s);

/** The largest |f|_1 of a tame sample [m/s^2]. */
#if SE23_CFG_DOUBLE
#define SE23_SAMPLE_F_TAME SE23_R(1e154)
#else
#define SE23_SAMPLE_F_TAME SE23_R(1e19)
#endif

/** ups = the exact Upsilon of a checked sample and, if parts is not NULL,
 *  its parts. No checks. */
void se23_imu_increment_parts(const se23_imu_sample_t *s, se23_pose_t *ups,
                              se23_increment_parts_t *parts);

/**
 * se23_imu_step with the pose T trusted (not checked: a state the library
 * produced, or one the caller checked), plus ups = Upsilon(s) and, if parts
 * is not NULL, the increment's parts. The sample is checked as in
 * se23_imu_step, and SE23_ERR_NONFINITE is returned if the increment or
 * T_next would overflow. For the hot path's sake this internal step writes
 * straight into its outputs: on an error T_next, ups and parts are scratch
 * (or untouched), so callers hand in locals. T_next and ups may not alias
 * T or each other.
 */
se23_status_t se23_imu_step_ups(const se23_earth_model_t *model,
                                const se23_pose_t *T, const se23_imu_sample_t *s,
                                se23_pose_t *T_next, se23_pose_t *ups,
                                se23_increment_parts_t *parts);

#endif /* SE23_IMU_STEP_H */
