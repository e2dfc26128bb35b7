/* Sine and cosine with a bounded frame (trig.h). */
#include "trig.h"

#include <stdint.h>

#include "se23_math.h"

/* pi/2 = PIO2_1 + PIO2_2 + PIO2_3 + d (Cody & Waite). PIO2_1 and PIO2_2
 * carry at most 32 (double) / 16 (float) significant bits, so k PIO2_1
 * and k PIO2_2 are exact for |k| < 2^21 / 2^8, i.e. for every
 * |x| <= SE23_TRIG_REDUCE_MAX; |d| is 1.0e-37 / 1.2e-18. The digits are
 * pi/2 rounded to those widths, computed with mpmath at 400 bits. */
#if SE23_CFG_DOUBLE
#define PIO2_1 0x1.921fb544p+0
#define PIO2_2 0x1.0b4611a6p-34
#define PIO2_3 0x1.3198a2e037073p-69
#define TWO_OVER_PI 0x1.45f306dc9c883p-1
#define TWO_PI 0x1.921fb54442d18p+2
#define PIO4 0x1.921fb54442d18p-1
#else
#define PIO2_1 0x1.922p+0f
#define PIO2_2 (-0x1.2aeep-18f)
#define PIO2_3 (-0x1.e973dcp-35f)
#define TWO_OVER_PI 0x1.45f306p-1f
#define TWO_PI 0x1.921fb6p+2f
#define PIO4 0x1.921fb6p-1f
#endif

/* Reduced argument r = hi + lo: lo is the rounding error of hi. */
typedef struct {
    se23_real_t hi;
    se23_real_t lo;
} reduced_t;

/* x = k pi/2 + r with |r| <= pi/4 (to rounding); returns k mod 4.
 * 5 multiplies, 6 additions and a conversion each way. */
static uint32_t reduce(se23_real_t x, reduced_t *r)
{
    se23_real_t a = x;
    if (se23_fabs(a) <= PIO4) {
        r->hi = a; /* k = 0: the angles of IMU samples and latitudes */
        r->lo = SE23_R(0);
        return 0u;
    }
    if (!(se23_fabs(a) <= SE23_TRIG_REDUCE_MAX)) {
        if (!se23_is_finite(a)) {
            r->hi = a - a; /* NaN, as C99 sin(inf) */
            r->lo = SE23_R(0);
            return 0u;
        }
        a = SE23_LIBM(fmod)(a, TWO_PI); /* exact remainder, |a| < 2 pi */
    }
    const se23_real_t y = a * TWO_OVER_PI;
    const int32_t k = (int32_t)(y + ((y < SE23_R(0)) ? SE23_R(-0.5) : SE23_R(0.5)));
    const se23_real_t kr = (se23_real_t)k;
    /* a - k PIO2_1 is exact (Sterbenz); the two small parts are summed
     * first (to about 2^-p of their size), so hi is rounded once and lo
     * recovers that rounding exactly */
    const se23_real_t head = a - kr * PIO2_1;
    const se23_real_t tail = kr * PIO2_2 + kr * PIO2_3;
    r->hi = head - tail;
    r->lo = (head - r->hi) - tail;
    return (uint32_t)k & 3u; /* conversion is modulo 2^32: k mod 4 for k < 0 too */
}

/* sin r, r = hi + lo, |r| <= pi/4: Taylor series to r^17 (double) / r^9
 * (float); the first omitted term is below 1.2e-19 / 2.5e-9 relative at
 * pi/4. Horner in z = r^2: 7 / 3 multiply-adds, then 4 multiplies and 3
 * additions. */
static se23_real_t sin_kernel(const reduced_t *a)
{
    const se23_real_t r = a->hi;
    const se23_real_t z = r * r;
#if SE23_CFG_DOUBLE
    se23_real_t p = SE23_R(1) / SE23_R(355687428096000.0); /* 1/17! */
    p = p * z - SE23_R(1) / SE23_R(1307674368000.0);
    p = p * z + SE23_R(1) / SE23_R(6227020800.0);
    p = p * z - SE23_R(1) / SE23_R(39916800.0);
    p = p * z + SE23_R(1) / SE23_R(362880.0);
#else
    se23_real_t p = SE23_R(1) / SE23_R(362880.0); /* 1/9! */
#endif
    p = p * z - SE23_R(1) / SE23_R(5040.0);
    p = p * z + SE23_R(1) / SE23_R(120.0);
    p = p * z - SE23_R(1) / SE23_R(6.0);
    /* sin(r + lo) = sin r + lo cos r; cos r = 1 - z/2 to lo z^2/24 */
    return r + (r * z * p + a->lo * (SE23_R(1) - SE23_R(0.5) * z));
}

/* cos r, r = hi + lo, |r| <= pi/4: Taylor series to r^16 (double) / r^10
 * (float); the first omitted term is below 3e-18 / 1.6e-10 relative at
 * pi/4. Horner in z = r^2: 6 / 3 multiply-adds, then 5 multiplies and 6
 * additions. */
static se23_real_t cos_kernel(const reduced_t *a)
{
    const se23_real_t r = a->hi;
    const se23_real_t z = r * r;
#if SE23_CFG_DOUBLE
    se23_real_t p = SE23_R(1) / SE23_R(20922789888000.0); /* 1/16! */
    p = p * z - SE23_R(1) / SE23_R(87178291200.0);
    p = p * z + SE23_R(1) / SE23_R(479001600.0);
    p = p * z - SE23_R(1) / SE23_R(3628800.0);
#else
    se23_real_t p = -SE23_R(1) / SE23_R(3628800.0); /* -1/10! */
#endif
    p = p * z + SE23_R(1) / SE23_R(40320.0);
    p = p * z - SE23_R(1) / SE23_R(720.0);
    p = p * z + SE23_R(1) / SE23_R(24.0);
    /* 1 - z/2 rounds once more than the rest: its rounding error
     * (1 - w) - z/2 is exact and carried into the small part, with
     * cos(r + lo) - cos r = -lo sin r = -lo r to lo r^3/6 */
    const se23_real_t half_z = SE23_R(0.5) * z;
    const se23_real_t w = SE23_R(1) - half_z;
    return w + ((((SE23_R(1) - w) - half_z) + z * z * p) - r * a->lo);
}

/* sin(k pi/2 + r) from k mod 4: sin r, cos r, -sin r, -cos r. */
static se23_real_t sin_of_quadrant(uint32_t q, const reduced_t *r)
{
    const se23_real_t v = ((q & 1u) != 0u) ? cos_kernel(r) : sin_kernel(r);
    return ((q & 2u) != 0u) ? -v : v;
}

se23_real_t se23_trig_sin(se23_real_t x)
{
    reduced_t r;
    const uint32_t q = reduce(x, &r);
    return sin_of_quadrant(q, &r);
}

/* cos x = sin(x + pi/2): one quadrant on. */
se23_real_t se23_trig_cos(se23_real_t x)
{
    reduced_t r;
    const uint32_t q = reduce(x, &r);
    return sin_of_quadrant(q + 1u, &r);
}
