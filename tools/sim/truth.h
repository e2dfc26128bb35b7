/**
 * @file truth.h
 * @brief Ground truth of the simulator: the navigation equations with
 *        rotating Earth (paper eq. nav:eq_Coriolis),
 *          dR/dt = -W R + R w^,
 *          dv/dt = g + R a - 2 W v - W W p,      W = Omega^,
 *          dp/dt = v,
 *        integrated in long double by classical RK4 with the IMU inputs
 *        (w, a) held constant over each sample interval (zero-order hold,
 *        the library's assumption). Omega = 0 gives the flat-Earth equations
 *        (paper eq. nav:eq). Independent of the library under test.
 */
#ifndef SIM_TRUTH_H
#define SIM_TRUTH_H

#include "../lcm/ldmath.h"

typedef struct {
    ld_mat3_t R; /**< body -> nav */
    ld_vec3_t v; /**< velocity w.r.t. the Earth, nav [m/s] */
    ld_vec3_t p; /**< position, nav [m] */
} truth_state_t;

typedef struct {
    ld_vec3_t g_n;    /**< gravity (incl. centrifugal at the origin), nav [m/s^2] */
    ld_vec3_t w_ie_n; /**< Earth rate, nav [rad/s] (0: flat Earth) */
} truth_env_t;

/**
 * Advances x over dt [s] with constant body rate w_ib_b [rad/s] and specific
 * force f_b [m/s^2], in nsub RK4 steps, then re-orthonormalises R.
 */
void truth_step(truth_state_t *x, const truth_env_t *env, const ld_vec3_t *w_ib_b,
                const ld_vec3_t *f_b, ld_t dt, int nsub);

/**
 * Environment of a local NED frame at geodetic latitude lat [rad]:
 * WGS-84 normal gravity (Somigliana) at the ellipsoid, and the Earth rate
 * 7.292115e-5 rad/s * (cos lat, 0, -sin lat) if earth_rotation, else 0.
 */
truth_env_t truth_env_ned(ld_t lat, int earth_rotation);

#endif /* SIM_TRUTH_H */
