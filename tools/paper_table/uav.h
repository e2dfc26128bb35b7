/**
 * @file uav.h
 * @brief The smooth 3D UAV trajectory of the paper's Table "Higher-order
 *        errors for a low-cost IMU" (section 4.2) and its error-free IMU
 *        samples, in double.
 *
 * Flat Earth, NED navigation frame, g = (0, 0, 9.81) m/s^2. Position: a
 * figure of eight 120 m x 60 m flown in 80 s at 50 m height +- 10 m,
 *   p(t) = (60 sin(a t), 30 sin(2 a t), -50 - 10 sin(b t)),
 *   a = 2 pi / 80 s, b = 2 pi / 50 s  (speed 3.1 to 6.8 m/s, body rates
 * up to 0.26 rad/s).
 * Attitude R = Rz(yaw) Ry(pitch) Rx(roll): the yaw follows the horizontal
 * velocity, roll 0.15 sin(0.4 t) and pitch 0.1 sin(0.3 t + 1) rad add a
 * wobble, so that every body axis turns. Body rates from the ZYX Euler
 * kinematics, specific force f_b = R^T (dv/dt - g), both analytic.
 */
#ifndef PAPER_UAV_H
#define PAPER_UAV_H

#define UAV_G 9.81 /**< gravity [m/s^2], down */

/** The trajectory at one instant. */
typedef struct {
    double p[3];    /**< position, NED [m] */
    double v[3];    /**< velocity, NED [m/s] */
    double R[3][3]; /**< attitude, body -> NED */
    double w_b[3];  /**< angular rate, body [rad/s] */
    double f_b[3];  /**< specific force, body [m/s^2] */
} uav_state_t;

/** s = the trajectory at time t [s]. */
void uav_state(double t, uav_state_t *s);

/**
 * w_b, f_b = the IMU sample k at rate hz [Hz]: the trajectory's rate and
 * specific force at the middle of [k / hz, (k + 1) / hz) (a zero-order hold
 * that is second-order accurate in 1 / hz).
 */
void uav_sample(long k, double hz, double w_b[3], double f_b[3]);

#endif /* PAPER_UAV_H */
