/**
 * @file ref_nav.hpp
 * @brief Independent ground truth for IMU propagation, written from the
 *        continuous equations, not from the C code (nor from its closed forms):
 *
 *  - nav_rk4: the navigation equations with rotating Earth (paper eq.
 *    nav:eq_Coriolis; Omega = 0 gives eq. nav:eq) on the user's state
 *    (R, v, p), integrated by classical RK4 over one zero-order-hold sample
 *    with n equal sub-steps, in long double:
 *        dR/dt = -Omega^ R + R w^,
 *        dv/dt = g + R f - 2 Omega^ v - Omega^ Omega^ p,
 *        dp/dt = v.
 *    RK4's global error is O(h^4); the crosscheck uses h = dt/8, which keeps it
 *    below 1e-14 (relative) over 60 s of the test trajectories.
 *  - upsilon_expm: the exact increment as the generic matrix exponential of
 *    an augmented 5x5 matrix: for constant w, f,
 *        expm(dt [[w^, f, 0], [0, 0, 1], [0, 0, 0]]) = [[dR, dV, dX], [0, 1, dt], [0, 0, 1]],
 *    since Z' = Z A gives dR' = dR w^, dV' = dR f, dX' = dV (paper eq. ODE).
 *  - gamma_expm: Gamma'(t) from the generic exponential of a 7x7 matrix:
 *    with y = (G^v, G^x, 1), paper eq. ODE21 (typos fixed, DESIGN.md section 3)
 *    is the linear system y' = [[-Omega^, 0, g], [I, -Omega^, 0], [0, 0, 0]] y,
 *    whose exponential's top-left block is also G^R = exp(-Omega^ t).
 *
 * Poses are 5x5 matrices [[R, v, p], [0, 1, 0], [0, 0, 1]] as in reference.hpp.
 */
#ifndef SE23_REF_NAV_HPP
#define SE23_REF_NAV_HPP

#include "reference.hpp"

namespace se23ref {

/** The user's state (R, v, p) after integrating eq. nav:eq_Coriolis from T
 *  over dt with constant w (body rate, rad/s) and f (specific force, m/s^2),
 *  gravity g and Earth rate Omega (nav frame), by RK4 with n sub-steps. */
Mat5L nav_rk4(const Mat5L &T, const Vec3L &w, const Vec3L &f, const Vec3L &g,
              const Vec3L &Omega, LD dt, int n);

/** Upsilon(w, f, dt) = (dR, dV, dX) from the augmented 5x5 exponential. */
Mat5L upsilon_expm(const Vec3L &w, const Vec3L &f, LD dt);

/** Gamma'(t) = (G^R, G^v, G^x) from the augmented 7x7 exponential. */
Mat5L gamma_expm(const Vec3L &g, const Vec3L &Omega, LD t);

} // namespace se23ref

#endif // SE23_REF_NAV_HPP
