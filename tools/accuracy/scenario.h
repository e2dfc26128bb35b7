/**
 * @file scenario.h
 * @brief The two test scenarios of the accuracy program: a designed motion in
 *        a local NED frame at 45 deg latitude with the Earth rate, and the
 *        IMU samples a sensor of the given grade would output along it
 *        (kinematic rate and specific force at the middle of each interval,
 *        plus constant bias and white noise). All in long double; nothing
 *        here depends on the library or its precision.
 *
 * The rotating-Earth equations (paper eq. nav:eq_Coriolis) give the specific
 * force along a motion (R, v, p): R f = dv/dt - g + 2 Omega x v + Omega x (Omega x p),
 * and the gyro reads w_ib_b = w_nb_b + R^T Omega.
 */
#ifndef ACC_SCENARIO_H
#define ACC_SCENARIO_H

#include <stdint.h>

typedef long double ld;

/** A designed motion: a horizontal circle with heave, heading along the
 *  circle plus a yaw oscillation, roll and pitch oscillations. */
typedef struct {
    ld radius;   /**< circle radius [m] */
    ld rate;     /**< angular rate on the circle [rad/s] */
    ld z0;       /**< mean down coordinate [m] */
    ld heave[2]; /**< amplitude [m], angular frequency [rad/s] */
    ld yaw[2];   /**< yaw oscillation amplitude [rad], frequency [rad/s] */
    ld roll[2];
    ld pitch[2];
} acc_motion_t;

/** Sensor grade, sample rate and vehicle. */
typedef struct {
    const char *name;
    ld rate_hz;
    ld gyro_bias;  /**< constant bias magnitude per axis [rad/s] */
    ld gyro_arw;   /**< angle random walk [rad/s/sqrt(Hz)] */
    ld accel_bias; /**< constant bias magnitude per axis [m/s^2] */
    ld accel_vrw;  /**< velocity random walk [m/s^2/sqrt(Hz)] */
    acc_motion_t motion;
} acc_grade_t;

/** [0]: MEMS-grade drone at 200 Hz; [1]: navigation-grade ship at 100 Hz. */
extern const acc_grade_t acc_grades[2];

/** Gravity (WGS-84 normal gravity at 45 deg, h = 0) and Earth rate, NED at 45 deg. */
void acc_earth(ld g[3], ld omega[3]);

/** The designed state at time t [s]: R (body to NED, row-major), v, p. */
void acc_motion_state(const acc_motion_t *m, ld t, ld R[3][3], ld v[3], ld p[3]);

/** Sample generator with seeded noise (reproducible). */
typedef struct {
    const acc_grade_t *grade;
    uint64_t rng;
    ld bias_g[3];
    ld bias_a[3];
} acc_sensor_t;

void acc_sensor_init(acc_sensor_t *s, const acc_grade_t *grade, uint64_t seed);

/**
 * Sample k, for the interval [k dt, (k+1) dt): the exact w_ib_b [rad/s] and
 * f_b [m/s^2] of the motion at the middle of the interval (w, f), and what
 * the sensor outputs, with its bias and noise (w_meas, f_meas).
 */
void acc_sample(acc_sensor_t *s, long k, ld w[3], ld f[3], ld w_meas[3], ld f_meas[3]);

#endif /* ACC_SCENARIO_H */
