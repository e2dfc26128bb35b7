/**
 * @file imu_step.h
 * @brief Internal: the checked propagation step that also hands back the
 *        increment it used, so that covariance propagation (gauss.c)
 *        does not compute Upsilon a second time per sample.
 */
#ifndef SE23_IMU_STEP_H
#define SE23_IMU_STEP_H

#include "se23/imu.h"

/**
 * se23_imu_step, plus ups = Upsilon(s) (se23_imu_increment) on success.
 * Same checks and statuses as se23_imu_step; nothing written on error.
 */
se23_status_t se23_imu_step_ups(const se23_earth_model_t *model,
                                const se23_pose_t *T, const se23_imu_sample_t *s,
                                se23_pose_t *T_next, se23_pose_t *ups);

#endif /* SE23_IMU_STEP_H */
