/**
 * @file harness.h
 * @brief Shared definitions of the se23 LCM harness (host tools only):
 *        channel names, IMU error profiles, small command-line helpers.
 *
 * Frames: navigation frame NED (local Earth-fixed tangent frame, origin at
 * the start point), body frame FRD. Times are int64 nanoseconds.
 */
#ifndef SE23_HARNESS_H
#define SE23_HARNESS_H

#include <stdint.h>

#define HARNESS_CH_IMU "SE23_IMU"           /**< se23lcm_imu_sample_t */
#define HARNESS_CH_TRUTH "SE23_TRUTH"       /**< se23lcm_truth_t */
#define HARNESS_CH_GNSS "SE23_GNSS"         /**< se23lcm_gnss_fix_t */
#define HARNESS_CH_INIT "SE23_INIT"         /**< se23lcm_nav_state_t, initial estimate */
#define HARNESS_CH_NAV "SE23_NAV"           /**< se23lcm_nav_state_t, INS output */
#define HARNESS_CH_PREINT "SE23_PREINT"     /**< se23lcm_preint_factor_t */
#define HARNESS_CH_SIM_INFO "SE23_SIM_INFO" /**< se23lcm_sim_info_t, at start */
#define HARNESS_CH_SIM_END "SE23_SIM_END"   /**< se23lcm_sim_info_t, at the end */

/** Default live transport (needs the private network namespace, live.sh). */
#define HARNESS_LIVE_URL "udpm://239.255.76.67:7667?ttl=0"

/**
 * IMU error model ("datasheet") shared by the simulator, which draws the
 * errors, and the INS, which models them.
 * measured = true - b - white noise (the paper's sign convention, as in
 * se23/gauss.h); b = b0 + random walk.
 */
typedef struct {
    const char *name;
    double gyro_noise;   /**< gyro white noise density [rad/s/sqrt(Hz)] */
    double accel_noise;  /**< accel white noise density [m/s^2/sqrt(Hz)] */
    double gyro_bias0;   /**< 1-sigma constant gyro bias [rad/s] */
    double accel_bias0;  /**< 1-sigma constant accel bias [m/s^2] */
    double gyro_bias_rw; /**< gyro bias random walk [rad/s/sqrt(s)] */
    double accel_bias_rw; /**< accel bias random walk [m/s^2/sqrt(s)] */
    double gyro_range;   /**< sensor range, |omega| above is invalid [rad/s] */
    double accel_range;  /**< sensor range, |accel| above is invalid [m/s^2] */
} harness_imu_profile_t;

enum { HARNESS_IMU_PERFECT = 0, HARNESS_IMU_MEMS, HARNESS_IMU_TACTICAL, HARNESS_IMU_NAV, HARNESS_IMU_COUNT };

/** Profile by index (0..HARNESS_IMU_COUNT-1), or NULL. */
const harness_imu_profile_t *harness_imu_profile(int index);

/** Index of the profile called name, or -1. */
int harness_imu_profile_find(const char *name);

/** Parses a whole decimal/float number; returns 0 on success. */
int harness_parse_double(const char *s, double *out);

/** Parses a whole integer; returns 0 on success. */
int harness_parse_i64(const char *s, int64_t *out);

/** Parses "x,y,z"; returns 0 on success. */
int harness_parse_vec3(const char *s, double out[3]);

/** Monotonic wall clock [ns]. */
int64_t harness_now_ns(void);

/** Sleeps until the monotonic clock reaches t_ns. */
void harness_sleep_until_ns(int64_t t_ns);

#endif /* SE23_HARNESS_H */
