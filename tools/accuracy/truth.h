/**
 * @file truth.h
 * @brief Long-double ground truth for the accuracy program: exact
 *        propagation of zero-order-hold IMU samples on rotating Earth,
 *        T' <- Gamma' Phi_dt(T') Upsilon (paper eq. discrete2 on the carried
 *        state v' = v + Omega x p), with Upsilon and Gamma' taken from generic
 *        matrix exponentials (Taylor series with scaling and squaring) of the
 *        augmented matrices of tests/reference/ref_nav.hpp -- not from the
 *        library's closed forms. That this discrete propagation solves the
 *        continuous equations is checked against RK4 by crosscheck_nav.
 */
#ifndef ACC_TRUTH_H
#define ACC_TRUTH_H

/** (R, v, p) in long double; v is the carried v' when used as a state. */
typedef struct {
    long double R[3][3];
    long double v[3];
    long double p[3];
} acc_pose_t;

/** G = Gamma'(dt) for gravity g and Earth rate omega (nav frame). */
void acc_truth_gamma(const long double g[3], const long double omega[3], long double dt, acc_pose_t *G);

/** T <- G Phi_dt(T) Upsilon(w, f, dt). */
void acc_truth_step(const acc_pose_t *G, const long double w[3], const long double f[3], long double dt, acc_pose_t *T);

/** v <- v + sign Omega x p (user <-> carried state). */
void acc_truth_shift(const long double omega[3], long double sign, acc_pose_t *T);

#endif /* ACC_TRUTH_H */
