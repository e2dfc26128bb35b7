/**
 * @file preint_check.h
 * @brief Checks published preintegrated factors against the truth: the
 *        truth at t0 predicted through each factor must match the truth at
 *        t1. The prediction is the paper's exact one (Proposition
 *        "Preintegration with Coriolis effect"), on carried states
 *        T' = (R, v + Omega x p, p):
 *          T'_1 = Gamma'(dt) Phi_dt(T'_0) Delta,
 *          Gamma' = (exp(-Omega^ dt), dt J(-Omega dt) g, dt^2 K(-Omega dt) g),
 *        with g and Omega from SE23_SIM_INFO, in long double (ldmath.h),
 *        independent of the library. Meaningful for noise-free, bias-free
 *        data (--imu perfect): then the residual is rounding only.
 */
#ifndef REPORT_PREINT_CHECK_H
#define REPORT_PREINT_CHECK_H

#include "logread.h"

typedef struct {
    long n_checked;     /**< factors with truth at both ends */
    double max_pos_err; /**< largest |p_pred - p_true| [m] */
    double max_vel_err; /**< largest |v_pred - v_true| [m/s] */
    double max_att_err; /**< largest |log(R_pred^T R_true)| [rad] */
} preint_check_t;

/** Fills r from the factors and truth of d (needs d->have_info). */
void preint_check(const log_data_t *d, preint_check_t *r);

#endif /* REPORT_PREINT_CHECK_H */
