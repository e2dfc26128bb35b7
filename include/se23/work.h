/**
 * @file work.h
 * @brief Work areas of the per-sample kernels (se23_gauss_predict_work,
 *        se23_preint_unc_add_work) and the intermediate results of one IMU
 *        step they hold.
 *
 * Why. se23_gauss_predict and se23_preint_unc_add keep the intermediate
 * results of a step (the corrected sample, the increment, the input matrix
 * blocks) on the stack: most of their frame. A caller with a small task
 * stack, such as the navigation filter (ins.h), passes a work area of its own
 * to the _work variant instead, in memory it owns (a static object, or a
 * member of its state, as the filter does), and the call's stack drops by
 * the size of the work area (tools/doc/pages/embedding.md). The
 * results are the same bit for bit: the plain functions are the _work ones
 * with a work area on their stack. Each holds only what is live across
 * the call's covariance step (the pieces of the increment that the input
 * matrix reuses are on the stack of a callee that returns before it). The
 * Kalman update's work area is se23_kalman_work_t (kalman.h).
 *
 * Contents. Scratch: every call writes it before reading it, nothing is
 * carried from one call to the next, and its contents after a call (OK or
 * not) are unspecified. The members are the library's intermediate
 * results; their layout may change between versions: only the type's size
 * is part of the interface.
 */
#ifndef SE23_WORK_H
#define SE23_WORK_H

#include "se23/imu.h"
#include "se23/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Bt, the 9x6 input matrix before the rotation D: blk[i][k] is block row i
 *  (phi, nu, rho) and block column k (0: gyro, 1: accel). blk[0][1] is
 *  zero and never read: the rotation of an increment does not depend on
 *  the accelerometer. */
typedef struct {
    se23_mat3_t blk[3][2]; /**< blk[i][k]: block row i (0: phi, 1: nu, 2: rho),
                            *   block column k (0: gyro, 1: accel); the rotation
                            *   D = diag(R^T, R^T, R^T) of the increment's R
                            *   turns it into B_k = D Bt (gauss.h) */
} se23_input_blocks_t;

/** Noise of one sample: white-noise variances of the sample averages,
 *  qg = sg^2/dt, qa = sa^2/dt, and bias random walk, wg = qg_w^2 dt,
 *  wa = qa_w^2 dt (gauss.h, "Noise discretisation"). */
typedef struct {
    /** @var se23_step_noise_t::qg
     *  Variance of each axis of the gyro's white noise averaged over the
     *  sample, gyro_noise^2 / dt [(rad/s)^2]. */
    /** @var se23_step_noise_t::qa
     *  Variance of each axis of the accelerometer's white noise averaged
     *  over the sample, accel_noise^2 / dt [(m/s^2)^2]. */
    /** @var se23_step_noise_t::wg
     *  Variance of each axis of the gyro bias's random-walk step over the
     *  sample, gyro_walk^2 dt [(rad/s)^2]. */
    /** @var se23_step_noise_t::wa
     *  Variance of each axis of the accelerometer bias's random-walk step
     *  over the sample, accel_walk^2 dt [(m/s^2)^2]. */
    se23_real_t qg, qa, wg, wa;
} se23_step_noise_t;

/** What one IMU step computes for its covariance step. */
typedef struct {
    se23_imu_sample_t c;          /**< the sample, bias-corrected */
    se23_pose_t U;                /**< its increment Upsilon */
    se23_step_noise_t q;          /**< the sample's noise */
    se23_input_blocks_t Bt;       /**< its input matrix, before the rotation */
} se23_step_inputs_t;

/** Work area of se23_gauss_predict_work (file comment). */
typedef struct {
    se23_step_inputs_t in;        /**< the step's corrected sample, increment,
                                   *   noise and input matrix */
    se23_pose_t T_next;           /**< the predicted mean */
} se23_predict_work_t;

/** Work area of se23_preint_unc_add_work (file comment). */
typedef struct {
    se23_step_inputs_t in;        /**< the step's corrected sample, increment,
                                   *   noise and input matrix */
} se23_preint_work_t;

#ifdef __cplusplus
}
#endif

#endif /* SE23_WORK_H */
