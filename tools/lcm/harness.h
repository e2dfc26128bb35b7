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
#include <stdio.h>

#define HARNESS_CH_IMU "SE23_IMU"           /**< se23lcm_imu_sample_t */
#define HARNESS_CH_TRUTH "SE23_TRUTH"       /**< se23lcm_truth_t */
#define HARNESS_CH_GNSS "SE23_GNSS"         /**< se23lcm_gnss_fix_t */
#define HARNESS_CH_INIT "SE23_INIT"         /**< se23lcm_nav_state_t, initial estimate */
#define HARNESS_CH_NAV "SE23_NAV"           /**< se23lcm_nav_state_t, INS output */
#define HARNESS_CH_PREINT "SE23_PREINT"     /**< se23lcm_preint_factor_t */
#define HARNESS_CH_SIM_INFO "SE23_SIM_INFO" /**< se23lcm_sim_info_t, at start */
#define HARNESS_CH_SIM_END "SE23_SIM_END"   /**< se23lcm_sim_info_t, at the end */
#define HARNESS_CH_IMU_INFO "SE23_IMU_INFO" /**< se23lcm_imu_info_t, before the first sample */

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

/** Kinds of command-line options (harness_parse_opts). */
typedef enum {
    HOPT_FLAG,   /**< no value; stores (int)lo into *(int *)dst */
    HOPT_DOUBLE, /**< number in [lo, hi] into *(double *)dst */
    HOPT_I64,    /**< integer into *(int64_t *)dst */
    HOPT_STR,    /**< the string into *(const char **)dst */
    HOPT_VEC3,   /**< "x,y,z", each in [lo, hi], into (double *)dst */
    HOPT_CHOICE  /**< find(value) >= 0 into *(int *)dst */
} harness_opt_kind_t;

/** One command-line option: "--name VALUE" (or "--name" for a flag). */
typedef struct {
    const char *name;
    harness_opt_kind_t kind;
    void *dst;
    double lo, hi;
    int (*find)(const char *value); /**< HOPT_CHOICE: index of value, or -1 */
} harness_opt_t;

/**
 * Parses argv against the table opt[0..n-1]. "--help"/"-h" prints usage to
 * stdout and exits 0. Arguments not starting with '-' go to pos (up to
 * argc entries; *n_pos counts them) if pos is not NULL, else are errors.
 * Returns 0, or -1 after printing what is wrong (prefixed with prog).
 */
int harness_parse_opts(const char *prog, int argc, char **argv, const harness_opt_t *opt, int n,
                       void (*usage)(FILE *), const char **pos, int *n_pos);

/** 1 for "on", 0 for "off", -1 otherwise (a HOPT_CHOICE finder). */
int harness_on_off(const char *value);

/** Parses a whole decimal/float number; returns 0 on success. */
int harness_parse_double(const char *s, double *out);

/** Parses a whole integer; returns 0 on success. */
int harness_parse_i64(const char *s, int64_t *out);

/** Parses "x,y,z"; returns 0 on success. */
int harness_parse_vec3(const char *s, double out[3]);

/** SIGINT and SIGTERM then only set a flag (graceful stop of a loop). */
void harness_catch_stop_signals(void);

/** Nonzero once SIGINT or SIGTERM arrived (after harness_catch_stop_signals). */
int harness_stop_requested(void);

/** Monotonic wall clock [ns]. */
int64_t harness_now_ns(void);

/** Sleeps until the monotonic clock reaches t_ns. */
void harness_sleep_until_ns(int64_t t_ns);

/** A progress line on stderr (see harness_progress). */
typedef struct {
    int tty;         /**< stderr is a terminal */
    int64_t last_ns; /**< when the last line was printed */
} harness_progress_t;

/** p = a progress line that has printed nothing yet. */
void harness_progress_init(harness_progress_t *p);

/**
 * Prints the progress line fmt, ... on stderr. On a terminal it is redrawn
 * in place ("\r") at most every 0.2 s; otherwise (a log) it is a plain line
 * at most every 10 s. A final line is always printed and ends the line.
 */
void harness_progress(harness_progress_t *p, int final, const char *fmt, ...);

#endif /* SE23_HARNESS_H */
