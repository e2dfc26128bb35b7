/* SO(3) series coefficients; see so3_series.h.
 *
 * Thresholds. The closed forms lose about eps * 12/theta^2 (relative) to
 * cancellation; the Taylor series with SERIES_TERMS terms truncates at about
 * theta^18/19!. Double: Taylor below theta = 1 (truncation < 1e-17; just
 * above it the closed forms are within 16 eps, 15.6 eps measured for c4 at
 * theta = 1.09, far inside the 1e-12 the double build promises). Float: Taylor below theta = 2, where
 * the closed forms are within a few FLT_EPSILON.
 */
#include "so3_series.h"

#include "../base/linalg.h"
#include "../base/se23_math.h"
#include "../base/trig.h"

#define SERIES_TERMS 9

#if SE23_CFG_DOUBLE
#define TAYLOR_MAX SE23_R(1.0)
#else
#define TAYLOR_MAX SE23_R(2.0)
#endif

/* 1/n!, n = 0..20 */
static const se23_real_t inv_fact[21] = {
    SE23_R(1.0 / 1.0),
    SE23_R(1.0 / 1.0),
    SE23_R(1.0 / 2.0),
    SE23_R(1.0 / 6.0),
    SE23_R(1.0 / 24.0),
    SE23_R(1.0 / 120.0),
    SE23_R(1.0 / 720.0),
    SE23_R(1.0 / 5040.0),
    SE23_R(1.0 / 40320.0),
    SE23_R(1.0 / 362880.0),
    SE23_R(1.0 / 3628800.0),
    SE23_R(1.0 / 39916800.0),
    SE23_R(1.0 / 479001600.0),
    SE23_R(1.0 / 6227020800.0),
    SE23_R(1.0 / 87178291200.0),
    SE23_R(1.0 / 1307674368000.0),
    SE23_R(1.0 / 20922789888000.0),
    SE23_R(1.0 / 355687428096000.0),
    SE23_R(1.0 / 6402373705728000.0),
    SE23_R(1.0 / 121645100408832000.0),
    SE23_R(1.0 / 2432902008176640000.0),
};
/* |k1 Taylor coefficients|: 1/((2k+1)! (2k+3)) */
static const se23_real_t k1_taylor[SERIES_TERMS] = {
    SE23_R(1.0 / 3.0),
    SE23_R(1.0 / 30.0),
    SE23_R(1.0 / 840.0),
    SE23_R(1.0 / 45360.0),
    SE23_R(1.0 / 3991680.0),
    SE23_R(1.0 / 518918400.0),
    SE23_R(1.0 / 93405312000.0),
    SE23_R(1.0 / 22230464256000.0),
    SE23_R(1.0 / 6758061133824000.0),
};
static const se23_real_t k2_taylor[SERIES_TERMS] = {
    SE23_R(1.0 / 8.0),
    SE23_R(1.0 / 144.0),
    SE23_R(1.0 / 5760.0),
    SE23_R(1.0 / 403200.0),
    SE23_R(1.0 / 43545600.0),
    SE23_R(1.0 / 6706022400.0),
    SE23_R(1.0 / 1394852659200.0),
    SE23_R(1.0 / 376610217984000.0),
    SE23_R(1.0 / 128047474114560000.0),
};

/* sum_{k < terms} coef[k * stride] * x^k, by Horner. */
static se23_real_t horner_n(const se23_real_t *coef, int stride, int terms,
                            se23_real_t x)
{
    se23_real_t acc = coef[(terms - 1) * stride];
    for (int k = terms - 2; k >= 0; --k) {
        acc = coef[k * stride] + x * acc;
    }
    return acc;
}

static se23_real_t horner(const se23_real_t *coef, int stride, se23_real_t x)
{
    return horner_n(coef, stride, SERIES_TERMS, x);
}

/* sin theta and 1 - cos theta. Within the exact range of se23_sincos one
 * reduction gives both, and 1 - cos theta is taken directly where cos
 * theta <= 1/2 (no cancellation: the error is that of cos, below 1 eps of
 * the result); nearer theta = 0 mod 2 pi it is 2 sin^2(theta/2). Beyond
 * the range each reduction is off by up to |theta| eps, differently, so
 * both come from theta/2 alone (sin theta = 2 sin cos of it): c1 and c2
 * are then of one angle, and exp is a rotation. */
static void sin_one_minus_cos(se23_real_t theta, se23_real_t *s, se23_real_t *omc)
{
    se23_real_t hs, hc;
    if (theta <= SE23_TRIG_EXACT_MAX) {
        se23_real_t c;
        se23_sincos(theta, s, &c);
        if (c <= SE23_R(0.5)) {
            *omc = SE23_R(1) - c;
            return;
        }
        se23_sincos(SE23_R(0.5) * theta, &hs, &hc);
    } else {
        se23_sincos(SE23_R(0.5) * theta, &hs, &hc);
        *s = SE23_R(2) * hs * hc;
    }
    *omc = SE23_R(2) * hs * hs;
}

/* c_m = sum_{k < terms} inv_fact[2k + m] (-t)^k, m = 1..4. Inline, so a
 * constant term count lets the compiler write the Horner sums out. */
static inline void taylor_coeffs(se23_real_t t, int terms,
                                 se23_so3_coeffs_t *c)
{
    c->c1 = horner_n(&inv_fact[1], 2, terms, -t);
    c->c2 = horner_n(&inv_fact[2], 2, terms, -t);
    c->c3 = horner_n(&inv_fact[3], 2, terms, -t);
    c->c4 = horner_n(&inv_fact[4], 2, terms, -t);
}

void se23_so3_coeffs(se23_real_t theta, se23_so3_coeffs_t *c)
{
    const se23_real_t t = theta * theta;
    /* The IMU's branch: 12 or 20 multiply-adds, no loop. */
    if (theta < SE23_SERIES_SMALL_THETA) {
        taylor_coeffs(t, SE23_SERIES_SMALL_TERMS, c);
        return;
    }
    if (theta < TAYLOR_MAX) {
        taylor_coeffs(t, SERIES_TERMS, c);
        return;
    }
    se23_real_t s, one_minus_cos;
    sin_one_minus_cos(theta, &s, &one_minus_cos);
    c->c1 = s / theta;
    c->c2 = one_minus_cos / t;
    c->c3 = (theta - s) / (t * theta);
    c->c4 = (SE23_R(0.5) * t - one_minus_cos) / (t * t);
}

void se23_so3_k_coeffs(se23_real_t theta, se23_real_t *k1, se23_real_t *k2)
{
    const se23_real_t t = theta * theta;
    if (theta < TAYLOR_MAX) {
        *k1 = horner(k1_taylor, 1, -t);
        *k2 = horner(k2_taylor, 1, -t);
        return;
    }
    se23_real_t s, one_minus_cos;
    sin_one_minus_cos(theta, &s, &one_minus_cos);
    const se23_real_t cos_theta = SE23_R(1) - one_minus_cos;
    *k1 = (s - theta * cos_theta) / (t * theta);
    *k2 = (SE23_R(0.5) * t + one_minus_cos - theta * s) / (t * t);
}

int se23_so3_gamma_series(const se23_vec3_t *phi, const se23_so3_coeffs_t *c,
                          se23_real_t k1, se23_real_t k2, se23_real_t t,
                          const se23_vec3_t *g, se23_pose_t *gamma)
{
    se23_pose_t out;
    se23_mat3_t M;
    se23_m3_series(SE23_R(1), c->c1, c->c2, phi, &out.R);
    se23_m3_series(SE23_R(1), c->c2, c->c3, phi, &M);
    se23_m3_mul_v3(&M, g, &out.v);
    se23_v3_scale(&out.v, t, &out.v);
    se23_m3_series(SE23_R(0.5), k1, k2, phi, &M);
    se23_m3_mul_v3(&M, g, &out.p);
    se23_v3_scale(&out.p, t * t, &out.p);
    if (!se23_pose_finite(&out)) {
        return 0;
    }
    *gamma = out;
    return 1;
}

/* With x = theta/2: 1 - x cot x = (sin x - x cos x)/sin x = x^2 k1(x)/c1(x),
 * so e = k1(x) / (4 c1(x)): no cancellation at any angle, and the only
 * singularity is c1(x) = 0 at theta = 2 pi. */
se23_real_t se23_so3_jl_inv_coeff(se23_real_t theta)
{
    const se23_real_t x = SE23_R(0.5) * theta;
    const se23_real_t t = x * x;
    if (x < TAYLOR_MAX) {
        return horner(k1_taylor, 1, -t) / (SE23_R(4) * horner(&inv_fact[1], 2, -t));
    }
    se23_real_t s, c;
    se23_sincos(x, &s, &c);
    return (s - x * c) / (SE23_R(4) * t * s);
}
