/**
 * @file trig.c
 * @brief sin and cos of one argument from one argument reduction.
 *
 * Why the library's own: newlib's sinf/cosf reduce large arguments with
 * __kernel_rem_pio2f, a 416 B frame on Cortex-M4F that a static stack
 * analysis charges to every per-sample path (IMU angles are tiny, but the
 * series' large-angle branches reach sin); and sin(theta), sin(theta/2)
 * taken separately are reduced with independent errors, so that exp of a
 * large angle is not a rotation. Here both values come from one reduced
 * angle.
 *
 * Reduction (Cody and Waite): x = k pi/2 + r, |r| <= pi/4 (to rounding),
 * with pi/2 = C1 + C2 + C3. C1 and C2 carry few enough significant bits
 * that k C1 and k C2 are exact for |x| <= SE23_TRIG_EXACT_MAX (k below
 * 2^8 in float, 2^20 in double), so x - k C1 - k C2 is exact and r is off
 * by k times C1 + C2 + C3 - pi/2, below 1e-18 (float) and 1e-31 (double).
 * Beyond that range x is first replaced by fmod(x, 2 pi) with 2 pi
 * rounded: exact, but of an angle off by up to |x| eps.
 *
 * Kernels on |r| <= pi/4: Taylor polynomials in z = r^2, the first omitted
 * term below 3e-9 (float) or 3e-18 (double) relative. 36 (float) or 50
 * (double) multiplies and adds, the 13 of the reduction included; no
 * division. Measured: within 0.66 eps (double), 0.63 eps (float) of
 * sinl/cosl (tests/unit/test_trig.c).
 */
#include "trig.h"

#include "se23_math.h"

#if SE23_CFG_DOUBLE
#define PIO2_C1 SE23_R(0x1.921fb544p+0)
#define PIO2_C2 SE23_R(0x1.0b4611a6p-34)
#define PIO2_C3 SE23_R(0x1.3198a2e037073p-69)
#define SIN_TERMS 8 /* r^3 .. r^17 */
#define COS_TERMS 8 /* r^2 .. r^16 */
#else
#define PIO2_C1 SE23_R(0x1.922p+0)
#define PIO2_C2 SE23_R(-0x1.2aeep-18)
#define PIO2_C3 SE23_R(-0x1.e973dcp-35)
#define SIN_TERMS 4 /* r^3 .. r^9 */
#define COS_TERMS 5 /* r^2 .. r^10 */
#endif
#define TWO_OVER_PI SE23_R(0.63661977236758134307553505349005744813783858)
#define TWO_PI SE23_R(6.28318530717958647692528676655900576839433880)

/* (-1)^(k+1) / (2k+1)!, k = 1.. */
static const se23_real_t sin_coef[8] = {
    SE23_R(-1.0 / 6.0),
    SE23_R(1.0 / 120.0),
    SE23_R(-1.0 / 5040.0),
    SE23_R(1.0 / 362880.0),
    SE23_R(-1.0 / 39916800.0),
    SE23_R(1.0 / 6227020800.0),
    SE23_R(-1.0 / 1307674368000.0),
    SE23_R(1.0 / 355687428096000.0),
};

/* (-1)^k / (2k)!, k = 1.. */
static const se23_real_t cos_coef[8] = {
    SE23_R(-1.0 / 2.0),
    SE23_R(1.0 / 24.0),
    SE23_R(-1.0 / 720.0),
    SE23_R(1.0 / 40320.0),
    SE23_R(-1.0 / 3628800.0),
    SE23_R(1.0 / 479001600.0),
    SE23_R(-1.0 / 87178291200.0),
    SE23_R(1.0 / 20922789888000.0),
};

/* sum_{k < terms} coef[k] z^k; a constant term count, written out. */
static inline se23_real_t poly(const se23_real_t *coef, int terms, se23_real_t z)
{
    se23_real_t acc = coef[terms - 1];
    for (int k = terms - 2; k >= 0; --k) {
        acc = coef[k] + z * acc;
    }
    return acc;
}

void se23_sincos(se23_real_t x, se23_real_t *s, se23_real_t *c)
{
    se23_real_t xr = x;
    if (!(se23_fabs(x) <= SE23_TRIG_EXACT_MAX)) {
        if (!se23_is_finite(x)) {
            *s = x - x; /* NaN */
            *c = x - x;
            return;
        }
        xr = se23_fmod(x, TWO_PI);
    }
    const se23_real_t kr = xr * TWO_OVER_PI;
    const long k = (long)(kr + ((kr < SE23_R(0)) ? SE23_R(-0.5) : SE23_R(0.5)));
    const se23_real_t kf = (se23_real_t)k;
    /* r + rt = x - k pi/2: a exact, a - w with its rounding error carried
     * in rt (|a| >= |w|: w is the small middle part), then the tail. */
    const se23_real_t a = xr - kf * PIO2_C1;
    const se23_real_t w = kf * PIO2_C2;
    const se23_real_t r1 = a - w;
    const se23_real_t t = ((a - r1) - w) - kf * PIO2_C3;
    const se23_real_t r = r1 + t;
    const se23_real_t rt = (r1 - r) + t;
    /* sin(r + rt) = sin r + rt, cos(r + rt) = cos r - r rt to rounding. */
    const se23_real_t z = r * r;
    const se23_real_t sr = r + (((r * z) * poly(sin_coef, SIN_TERMS, z)) + rt);
    const se23_real_t cr = SE23_R(1) + ((z * poly(cos_coef, COS_TERMS, z)) - (r * rt));
    /* sin and cos of r + k pi/2 by the quadrant k mod 4 (a negative k
     * converts to unsigned modulo 2^n, so the low bits still give it). */
    switch ((unsigned long)k & 3UL) {
    case 0:
        *s = sr;
        *c = cr;
        break;
    case 1:
        *s = cr;
        *c = -sr;
        break;
    case 2:
        *s = -sr;
        *c = -cr;
        break;
    default:
        *s = -cr;
        *c = sr;
        break;
    }
}
