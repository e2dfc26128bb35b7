/**
 * @file metrics.h
 * @brief Errors of a navigation estimate against the truth, their 1-sigma
 *        from the estimate's covariance, and the NEES, independent of the
 *        library under test (long double arithmetic of ldmath.h).
 *
 * With T = That exp(xi) (paper eq. error:rep1), xi = log(That^-1 T) =
 * (phi, J(phi)^-1 Rhat^T dv, J(phi)^-1 Rhat^T dp) exactly; the NEES is
 * e^T P^-1 e with e = (xi, b - bhat) (15) or xi alone (9). The errors shown
 * are in the nav frame (dp = p - phat, dv = v - vhat, dth = log(R Rhat^T)),
 * with sigmas from Rhat P_block Rhat^T (first order).
 */
#ifndef REPORT_METRICS_H
#define REPORT_METRICS_H

#include "se23lcm_nav_state.h"
#include "se23lcm_truth.h"

typedef struct {
    double t;
    double p_true[3], p_est[3];
    double dp[3], sp[3];   /**< position error and sigma, NED [m] */
    double dv[3], sv[3];   /**< velocity error and sigma, NED [m/s] */
    double dth[3], sth[3]; /**< attitude error and sigma, NED [rad] */
    double bg_true[3], bg_est[3], sbg[3]; /**< gyro bias [rad/s] */
    double ba_true[3], ba_est[3], sba[3]; /**< accel bias [m/s^2] */
    double nees9;  /**< NEES of xi (NaN if P_xi is singular) */
    double nees15; /**< NEES of (xi, db) (NaN without bias covariance) */
    int status;
} epoch_t;

/** e^T P^-1 e for the leading n x n block (n <= 15) of P, row stride
 *  `stride`, by its Cholesky factor in long double; NaN if that block is
 *  not positive definite. */
double metrics_nees(const double *P, int stride, const double *e, int n);

/** C = R P_blk R^T, the nav-frame covariance of the error block at b
 *  (0 attitude, 3 velocity, 6 position) of the 15x15 P, R_nb row-major;
 *  computed in long double. */
void metrics_nav_cov(const double R_nb[9], const double *P, int b, double C[3][3]);

/** Fills e from a truth and an estimate at the same time. */
void metrics_epoch(const se23lcm_truth *tr, const se23lcm_nav_state *nav, epoch_t *e);

#endif /* REPORT_METRICS_H */
