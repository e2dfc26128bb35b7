/**
 * @file ekf.h
 * @brief The standard ("multiplicative") EKF that the paper's Figure on
 *        Monte Carlo clouds contrasts with exponential coordinates: its
 *        error is e = (dtheta, dv, dp) with R = Rbar exp(dtheta^) and the
 *        velocity and position additive, v = vbar + dv, p = pbar + dp.
 *
 * Textbook discretisation of the linearised navigation equations (paper
 * eq. nav:eq, flat Earth) over one sample of corrected inputs (w, f):
 *   d/dt e = A e + G eta,
 *   A = [[-w^, 0, 0], [-Rbar f^, 0, 0], [0, I, 0]],  G = [[I, 0], [0, Rbar], [0, 0]],
 *   P+ = Phi P Phi^T + G diag(qg, qa) G^T dt,  Phi = I + A dt,
 * with the white-noise densities squared qg [rad^2/s] (per axis) and qa
 * [m^2/s^3]. Dense 9x9 products in double: this is the comparison, not the
 * library.
 */
#ifndef PAPER_EKF_H
#define PAPER_EKF_H

/** P = covariance of (dtheta, dv, dp), 9x9 row-major. */
typedef struct {
    double P[81];
} ekf_t;

/**
 * One step of the EKF covariance from the mean attitude R (body -> nav)
 * at the start of the sample (read only; not const for C99 pedantic
 * 2-D array passing).
 * @param w  corrected angular rate, body [rad/s]
 * @param f  corrected specific force, body [m/s^2]
 * @param qg gyro white-noise density squared per axis [rad^2/s]
 * @param qa accel white-noise density squared [m^2/s^3]
 */
void ekf_propagate(ekf_t *e, double R[3][3], const double w[3],
                   const double f[3], double dt, const double qg[3], double qa);

#endif /* PAPER_EKF_H */
