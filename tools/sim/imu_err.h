/**
 * @file imu_err.h
 * @brief IMU error model of the simulator and its random numbers:
 *        measured = M true - b - n (the paper's signs, as in se23/gauss.h), n white with the profile's density
 *        (per sample sigma = density / sqrt(dt), the mean of white noise
 *        over the interval), b = b0 + random walk (b0 ~ N(0, bias0^2)),
 *        M the accelerometer triad's rotation against the gyroscope's
 *        (identity unless imu_err_misalign_accel sets it; I for the gyro).
 */
#ifndef SIM_IMU_ERR_H
#define SIM_IMU_ERR_H

#include <stdint.h>

#include "../lcm/harness.h"
#include "../lcm/ldmath.h"

/** xoshiro256** generator with a cached Gaussian. */
typedef struct {
    uint64_t s[4];
    int has_spare;
    double spare;
} rng_t;

void rng_seed(rng_t *r, uint64_t seed);
double rng_uniform(rng_t *r); /* in (0, 1) */
double rng_normal(rng_t *r);  /* N(0, 1) */

typedef struct {
    harness_imu_profile_t prof;
    rng_t rng;
    double b_g[3]; /**< current gyro bias [rad/s] */
    double b_a[3]; /**< current accel bias [m/s^2] */
    ld_mat3_t accel_rot; /**< M of the accelerometer */
} imu_err_t;

/** Draws the constant biases from the profile with the given seed. */
void imu_err_init(imu_err_t *e, const harness_imu_profile_t *prof, uint64_t seed);

/** M = exp(rotvec^) for the accelerometer, rotvec in radians. */
void imu_err_misalign_accel(imu_err_t *e, const double rotvec[3]);

/**
 * Measured sample over an interval dt [s] from the true inputs, with the
 * bias in force over the interval; then advances the bias random walk.
 */
void imu_err_apply(imu_err_t *e, const double w_true[3], const double f_true[3], double dt,
                   double w_meas[3], double f_meas[3]);

#endif /* SIM_IMU_ERR_H */
