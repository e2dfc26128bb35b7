/**
 * @file so3_series.h
 * @brief Internal: the scalar coefficients of the SO(3) series, accurate at
 *        every angle. Below a per-precision threshold each coefficient is
 *        its Taylor series in theta^2 (Horner, enough terms that truncation
 *        is below the precision's epsilon); above, its closed form, where the
 *        cancellation is then mild.
 *
 * With c_m(theta) = sum_k (-1)^k theta^(2k) / (2k+m)!:
 *   c1 = sin(theta)/theta           exp:  I + c1 W + c2 W^2
 *   c2 = (1 - cos theta)/theta^2    J_l:  I + c2 W + c3 W^2
 *   c3 = (theta - sin theta)/theta^3   H: I/2 + c3 W + c4 W^2
 *   c4 = (theta^2/2 + cos theta - 1)/theta^4
 * and for K = I/2 + k1 W + k2 W^2 (DESIGN.md section 3):
 *   k1 = (sin theta - theta cos theta)/theta^3
 *   k2 = (theta^2/2 - cos theta - theta sin theta + 1)/theta^4
 * and for J_l^-1 = I - W/2 + e W^2:
 *   e = (1 - (theta/2) cot(theta/2))/theta^2   (singular at 2 pi)
 */
#ifndef SE23_SO3_SERIES_H
#define SE23_SO3_SERIES_H

#include "se23/types.h"

/** Below this angle (IMU samples: |w| dt is rarely above 0.05 rad) every
 *  series of the library is summed with SE23_SERIES_SMALL_TERMS terms: the
 *  first omitted term is then below 3e-17 (double, 5 terms) or 3e-9 (float,
 *  3 terms) relative, and the Horner sum costs about half. */
#define SE23_SERIES_SMALL_THETA SE23_R(0.1)
#if SE23_CFG_DOUBLE
#define SE23_SERIES_SMALL_TERMS 5
#else
#define SE23_SERIES_SMALL_TERMS 3
#endif

/** The four sin/cos coefficients at one angle. */
typedef struct {
    se23_real_t c1;
    se23_real_t c2;
    se23_real_t c3;
    se23_real_t c4;
} se23_so3_coeffs_t;

/** c1..c4 at theta >= 0. */
void se23_so3_coeffs(se23_real_t theta, se23_so3_coeffs_t *c);

/** k1, k2 (coefficients of K) at theta >= 0. */
void se23_so3_k_coeffs(se23_real_t theta, se23_real_t *k1, se23_real_t *k2);

/**
 * Gamma_t of paper eq. (discrete) for a constant Earth rate (earth.h):
 * R = exp(phi) = I + c1 W + c2 W^2, v = t J_l(phi) g, p = t^2 K(phi) g,
 * W = phi^, from c and k1, k2 at |phi|. A call of its own, made after the
 * coefficients, so that its pose and matrix are not on the stack under the
 * sine of the coefficients.
 * @return 1, or 0 (gamma unwritten) if an entry overflowed.
 */
int se23_so3_gamma_series(const se23_vec3_t *phi, const se23_so3_coeffs_t *c,
                          se23_real_t k1, se23_real_t k2, se23_real_t t,
                          const se23_vec3_t *g, se23_pose_t *gamma);

/** e (coefficient of J_l^-1) at 0 <= theta < 2 pi. */
se23_real_t se23_so3_jl_inv_coeff(se23_real_t theta);

#endif /* SE23_SO3_SERIES_H */
