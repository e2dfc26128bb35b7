/* WGS-84 geodetic fixes to and from the local NED frame; see geodetic.h.
 *
 * The formulas (WGS-84, NIMA TR8350.2 3rd ed.: a = 6378137 m,
 * f = 1/298.257223563, e^2 = f (2 - f); N = a / w, w = sqrt(1 - e^2 sin^2 lat),
 * M = a (1 - e^2) / w^3). Write lat = lat0 + x, lon = lon0 + y, s = sin lat,
 * c = cos lat, s0, c0 those of the origin, W = N + h. Turn the ECEF axes
 * by lon0 about z, so that the origin lies in the x-z plane: the fix is
 *   P  = W (c cos y, c sin y, s) - e^2 N (0, 0, s),
 * the origin P0 = W0 (c0, 0, s0) - e^2 N0 (0, 0, s0), and the origin's
 * north, east, down axes are (-s0, 0, c0), (0, 1, 0), -(c0, 0, s0). Then,
 * with c0 s - s0 c = sin x, c0 c + s0 s = cos x and 1 - cos y = q_y (and
 * q_x = 1 - cos x), exactly:
 *   north = W (sin x + s0 c q_y) - e^2 c0 (N s - N0 s0)
 *   east  = W c sin y
 *   down  = -(N - N0) - (h - h0) + W q_x + W c0 c q_y + e^2 s0 (N s - N0 s0)
 * No term is a difference of two large numbers: the small differences are
 *   s - s0   = c0 sin x - s0 q_x,      c - c0 = -s0 sin x - c0 q_x,
 *   N - N0   = a e^2 (s - s0) (s + s0) / (w w0 (w + w0)),
 *   N s - N0 s0 = (N - N0) s + N0 (s - s0),
 * q = 1 - cos t = t^2 (1/2 - t^2/24 + ...) and t - sin t = t^3 (1/6 - ...)
 * by their Taylor series (|t| <= 10 deg; truncation below 1e-20 relative).
 *
 * Precision (float: eps = 6e-8). The angles x, y come from exact integer
 * differences of nanodegrees, times pi/180e-9 as an unevaluated sum of two
 * reals (a "double-real": hi + lo, about 2^-44 relative in float). The two
 * terms of size offset, W sin x and W c sin y, are formed as a TwoProduct
 * (p = a b, e = fma(a, b, -p): exact whatever the compiler contracts; a
 * Veltkamp/Dekker split product is not, -ffp-contract=fast fuses its
 * steps) of a (exact in float) with sin x (double-real), resp. c sin y
 * (double-real product, c = c0 + (c - c0) with c0 double-real), plus
 * (W - a) times the leading part in plain reals: the rounding of the
 * result is the only error of size eps * offset. Every other term is at
 * most offset^2 / R (785 m at 100 km) or e^2 offset and carries a few eps
 * of itself. Float: <= 0.5 ulp of the output + ~0.05 mm within 100 km
 * (north/east), i.e. <= 1 mm within 10 km, <= 4-5 mm at 100 km where the
 * output's spacing is 7.8 mm; double: ~1e-9 m.
 * The origin's sin/cos: |lat0| = D deg + r, D integer, |r| <= 0.5 deg;
 * sin/cos of D deg by angle addition from sin/cos of 1 deg (double-real
 * constants) over the binary digits of D (at most 7 additions and 6
 * doublings, each ~2^-44 relative in float), then the addition of r by its
 * Taylor series: sin/cos lat0 to ~1e-12 relative in float, far below what
 * the terms above need (1e-9).
 * Contraction. Built with -ffp-contract=fast (the Cortex-M target library)
 * the compiler may fuse any a * b + c: the only steps that need an exact
 * rounding are the TwoProducts (explicit fma), TwoSum and FastTwoSum
 * (additions only: fusing a product into an operand changes that operand
 * by a rounding, which the sum then carries exactly) and the remainders of
 * mm_to_m_dr and round64 (explicit fma, resp. an exact product); every
 * other expression is an ordinary rounded one, fused or not. The host
 * tests pass with and without contraction, with the same accuracy.
 * Integers. No int64 <-> real conversion and no 64-bit division (on
 * Cortex-M these are libgcc routines, the float -> int64 one in double):
 * an int64 of up to 40 bits goes to reals as two exact 32-bit parts
 * (int_to_dr), back from reals by two 32-bit truncations (round64), and
 * whole degrees are split off by binary long division (sincos_lat).
 *
 * Operation count of se23_geo_to_ned (the hot routine), float build: 2
 * integer-to-real angle conversions (2 uint32->real each, a FastTwoSum,
 * a TwoProduct: ~10 flops), 2 x 2 Taylor series (Horner, 6 terms),
 * 1 double-real product (~10 flops), 2 TwoProducts (2 each), 1 sqrt,
 * 1 division, ~60 further multiplications and additions: about 150 flops
 * in all, no trigonometric call, no loop.
 */
#include "se23/geodetic.h"

#include "../base/argcheck.h"
#include "../base/linalg.h"
#include "../base/se23_math.h"

/* WGS-84: a [m] (an integer below 2^23: exact in float), e^2 = f (2 - f). */
#define GEO_A SE23_R(6378137.0)
#define GEO_E2 SE23_R(0.0066943799901413170)

/* Double-real constants hi + lo (hex literals: exact; the float pair's
 * parts are floats, the double pair's doubles; generated with mpmath at
 * 300 bits: hi = round(x), lo = round(x - hi)).
 *   K = pi / 180e9 [rad per 1e-9 deg];  S1, C1 = sin, cos of 1 deg. */
#if SE23_CFG_DOUBLE
#define GEO_K_HI SE23_R(0x1.330aa445be653p-36)
#define GEO_K_LO SE23_R(0x1.4274bf3f80ee3p-90)
#define GEO_S1_HI SE23_R(0x1.1df0b2b89dd1ep-6)
#define GEO_S1_LO SE23_R(0x1.5834d68148788p-60)
#define GEO_C1_HI SE23_R(0x1.ffec097f5af8ap-1)
#define GEO_C1_LO SE23_R(-0x1.18945ff801a15p-55)
#else
#define GEO_K_HI SE23_R(0x1.330aa4p-36)
#define GEO_K_LO SE23_R(0x1.16f994p-62)
#define GEO_S1_HI SE23_R(0x1.1df0b2p-6)
#define GEO_S1_LO SE23_R(0x1.713ba4p-31)
#define GEO_C1_HI SE23_R(0x1.ffec0ap-1)
#define GEO_C1_LO SE23_R(-0x1.014a0ep-26)
#endif

/* Whole degrees in 1e-9 deg; the latitude of the origin is split there. */
#define GEO_DEG_E9 INT64_C(1000000000)
#define GEO_HALF_DEG_E9 INT32_C(500000000)
/* Binary digits of the whole degrees of |lat0| <= 90. */
#define GEO_DEG_BITS 7
/* An integer of up to 40 bits is taken to reals as hi 2^16 + lo, hi and lo
 * 32-bit integers (exact conversions, no int64 <-> real routine). */
#define GEO_SPLIT_BITS 16
#define GEO_SPLIT_MASK UINT64_C(0xFFFF)
#define GEO_2P16 SE23_R(65536.0)
#define GEO_2M16 SE23_R(1.52587890625e-5)
/* The fused multiply-add of the build's precision, always the correctly
 * rounded libm function (one instruction on M4F/M7: VFMA.F32 / VFMA.F64;
 * a libm call on a host without FMA): the exact products below rely on it,
 * not on the contraction setting. */
#define GEO_FMA SE23_LIBM(fma)
/* Newton corrections of se23_geo_from_ned (quadratic: the first guess is
 * off by < 1 km, then < 0.2 m, < 1e-8 m; the rest absorb the rounding to
 * integers). */
#define GEO_NEWTON 5
/* A correction beyond this [1e-9 deg or mm] cannot lead to a supported fix. */
#define GEO_STEP_MAX SE23_R(1.0e11)
/* Largest |p_n - p_n(fix)| [m] of an accepted inverse: far above the
 * rounding (8 mm at 150 km in float), far below a fix outside the window. */
#define GEO_INV_TOL SE23_R(0.1)
/* (N + h) cos lat [m/rad] below which the longitude is that of a pole
 * (arbitrary): the Newton step leaves it unchanged. */
#define GEO_POLE_EAST_RAD SE23_R(1.0)

/* An unevaluated sum hi + lo. */
typedef struct {
    se23_real_t hi;
    se23_real_t lo;
} dreal_t;

/* s + e = a + b exactly (Knuth's TwoSum). */
static dreal_t two_sum(se23_real_t a, se23_real_t b)
{
    const se23_real_t s = a + b;
    const se23_real_t bb = s - a;
    const se23_real_t e = (a - (s - bb)) + (b - bb);
    const dreal_t r = {s, e};
    return r;
}

/* s + e = a + b exactly, for |a| >= |b| or a = 0 (Dekker's FastTwoSum). */
static dreal_t fast_two_sum(se23_real_t a, se23_real_t b)
{
    const se23_real_t s = a + b;
    const se23_real_t e = b - (s - a);
    const dreal_t r = {s, e};
    return r;
}

static dreal_t dr_neg(dreal_t x)
{
    const dreal_t r = {-x.hi, -x.lo};
    return r;
}

/* p + e = a b exactly (TwoProduct by a fused multiply-add: e = a b - p
 * with one rounding is exact, no underflow here). Unlike Dekker's split
 * product it holds whatever the compiler contracts: p is a lone product,
 * and the fma is explicit. */
static dreal_t two_prod(se23_real_t a, se23_real_t b)
{
    const se23_real_t p = a * b;
    const se23_real_t e = GEO_FMA(a, b, -p);
    const dreal_t r = {p, e};
    return r;
}

/* x y in double-real (relative error a few eps^2 plus |x.lo/x.hi| eps). */
static dreal_t dr_mul(dreal_t x, dreal_t y)
{
    const dreal_t p = two_prod(x.hi, y.hi);
    return fast_two_sum(p.hi, p.lo + (x.hi * y.lo + x.lo * y.hi));
}

/* x + y in double-real (no cancellation where it is used). */
static dreal_t dr_add(dreal_t x, dreal_t y)
{
    const dreal_t s = two_sum(x.hi, y.hi);
    return fast_two_sum(s.hi, s.lo + (x.lo + y.lo));
}

/* d = dh + dl exactly in reals, dh = d rounded, |dl| <= half its spacing
 * (|d| < 2^40: |d| = u1 2^16 + u0, u1 < 2^24 and u0 < 2^16 exact in float,
 * u1 2^16 exact, their sum by FastTwoSum). */
static dreal_t int_to_dr(int64_t d)
{
    const uint64_t u = (d < 0) ? (uint64_t)0 - (uint64_t)d : (uint64_t)d;
    const uint32_t u1 = (uint32_t)(u >> GEO_SPLIT_BITS);
    const uint32_t u0 = (uint32_t)(u & GEO_SPLIT_MASK);
    const dreal_t r = fast_two_sum((se23_real_t)u1 * GEO_2P16, (se23_real_t)u0);
    return (d < 0) ? dr_neg(r) : r;
}

/* The angle of d nanodegrees [rad], double-real: d = dh + dl exactly in
 * reals (|d| <= 1e11 < 2^37: dh is an integer, |dl| <= 2^13), times K. */
static dreal_t angle(int64_t d)
{
    const dreal_t dd = int_to_dr(d);
    const se23_real_t dh = dd.hi;
    const se23_real_t dl = dd.lo;
    const dreal_t p = two_prod(GEO_K_HI, dh);
    return fast_two_sum(p.hi, p.lo + (GEO_K_HI * dl + GEO_K_LO * dh));
}

/* t - sin t, |t| <= 0.2 (Taylor, six terms: truncation < 1e-20 relative). */
static se23_real_t sin_rem(se23_real_t t)
{
    const se23_real_t t2 = t * t;
    const se23_real_t c =
        SE23_R(1.0 / 6.0) -
        t2 * (SE23_R(1.0 / 120.0) -
              t2 * (SE23_R(1.0 / 5040.0) -
                    t2 * (SE23_R(1.0 / 362880.0) -
                          t2 * (SE23_R(1.0 / 39916800.0) - t2 * SE23_R(1.0 / 6227020800.0)))));
    return t * t2 * c;
}

/* 1 - cos t, |t| <= 0.2 (Taylor, six terms). */
static se23_real_t one_minus_cos(se23_real_t t)
{
    const se23_real_t t2 = t * t;
    const se23_real_t c =
        SE23_R(0.5) -
        t2 * (SE23_R(1.0 / 24.0) -
              t2 * (SE23_R(1.0 / 720.0) -
                    t2 * (SE23_R(1.0 / 40320.0) -
                          t2 * (SE23_R(1.0 / 3628800.0) - t2 * SE23_R(1.0 / 479001600.0)))));
    return t2 * c;
}

/* sin t as double-real, t double-real with |t| <= 0.2. */
static dreal_t sin_small(dreal_t t)
{
    return fast_two_sum(t.hi, t.lo - sin_rem(t.hi));
}

/* (s, c) = (sin, cos)(A + B) by angle addition, in double-real. */
static void rotate(dreal_t *s, dreal_t *c, dreal_t sb, dreal_t cb)
{
    const dreal_t sa = *s;
    const dreal_t ca = *c;
    *s = dr_add(dr_mul(sa, cb), dr_mul(ca, sb));
    *c = dr_add(dr_mul(ca, cb), dr_neg(dr_mul(sa, sb)));
}

/* sin, cos of |lat| [1e-9 deg] <= 90 deg, double-real (file comment). */
static void sincos_lat(int64_t lat_abs, dreal_t *s, dreal_t *c)
{
    /* deg = lat_abs / 1e9 by binary long division (no 64-bit division
     * routine), then r = lat_abs - deg 1e9 in [-0.5, 0.5] deg. */
    int32_t deg = 0;
    int64_t rem = lat_abs;
    for (int k = GEO_DEG_BITS - 1; k >= 0; k--) {
        const int64_t unit = GEO_DEG_E9 * (INT64_C(1) << k);
        if (rem >= unit) {
            rem -= unit;
            deg += INT32_C(1) << k;
        }
    }
    int32_t r = (int32_t)rem; /* < 1e9 */
    if (r > GEO_HALF_DEG_E9) {
        deg += 1;
        r -= (int32_t)GEO_DEG_E9;
    }
    dreal_t s_acc = {SE23_R(0), SE23_R(0)};
    dreal_t c_acc = {SE23_R(1), SE23_R(0)};
    dreal_t s_step = {GEO_S1_HI, GEO_S1_LO};
    dreal_t c_step = {GEO_C1_HI, GEO_C1_LO};
    for (int k = 0; k < GEO_DEG_BITS; k++) {
        if ((deg % 2) != 0) {
            rotate(&s_acc, &c_acc, s_step, c_step);
        }
        deg /= 2;
        if (deg > 0) {
            rotate(&s_step, &c_step, s_step, c_step);
        }
    }
    const dreal_t rho = angle(r);
    const dreal_t s_r = sin_small(rho);
    const dreal_t c_r = fast_two_sum(SE23_R(1), -one_minus_cos(rho.hi));
    rotate(&s_acc, &c_acc, s_r, c_r);
    *s = s_acc;
    *c = c_acc;
}

static int64_t abs64(int64_t x) { return (x < 0) ? -x : x; }

/* Valid latitude, longitude, height (no arithmetic on unchecked integers). */
static int geo_valid(const se23_geo_t *g)
{
    return (g->lat_e9 >= -SE23_GEO_LAT_MAX_E9) && (g->lat_e9 <= SE23_GEO_LAT_MAX_E9) &&
           (g->lon_e9 >= -SE23_GEO_LON_MAX_E9) && (g->lon_e9 <= SE23_GEO_LON_MAX_E9) &&
           (g->h_mm >= -SE23_GEO_H_MAX_MM) && (g->h_mm <= SE23_GEO_H_MAX_MM);
}

/* mm -> m; mm is a height or a height difference, |mm| <= 2e8 (checked
 * by the callers): q exact in double, one rounding in float (2e8 < 2^28,
 * spacing <= 16 mm, relative 6e-8), then the division's. */
static se23_real_t mm_to_m(int32_t mm)
{
    const se23_real_t q = (se23_real_t)mm;
    return q / SE23_R(1000);
}

/* mm -> m as double-real hi + lo (exact for |mm| < 2^24 in float): the
 * remainder q - 1000 hi of a correctly rounded quotient is a real, and the
 * fused multiply-add forms it exactly. */
static dreal_t mm_to_m_dr(int32_t mm)
{
    const se23_real_t q = (se23_real_t)mm;
    const se23_real_t hi = q / SE23_R(1000);
    const se23_real_t rest = GEO_FMA(-hi, SE23_R(1000), q);
    const dreal_t r = {hi, rest / SE23_R(1000)};
    return r;
}

/* The fix's latitude and longitude relative to the origin. */
typedef struct {
    dreal_t sx;         /* sin x, x = lat - lat0 */
    se23_real_t qx;     /* 1 - cos x */
    dreal_t sy;         /* sin y, y = lon - lon0 */
    se23_real_t qy;     /* 1 - cos y */
    se23_real_t ds;     /* sin lat - sin lat0 */
    se23_real_t s;      /* sin lat */
    dreal_t c;          /* cos lat */
} geo_angles_t;

static void geo_angles(const se23_geo_frame_t *fr, int64_t dlat, int64_t dlon,
                       geo_angles_t *g)
{
    const dreal_t x = angle(dlat);
    const dreal_t y = angle(dlon);
    const se23_real_t s0 = fr->sin_hi;
    const se23_real_t c0 = fr->cos_hi;
    g->sx = sin_small(x);
    g->qx = one_minus_cos(x.hi);
    g->sy = sin_small(y);
    g->qy = one_minus_cos(y.hi);
    g->ds = c0 * g->sx.hi - s0 * g->qx;
    g->s = s0 + g->ds;
    const se23_real_t dc = -s0 * g->sx.hi - c0 * g->qx;
    const dreal_t c = two_sum(fr->cos_hi, dc);
    g->c = fast_two_sum(c.hi, c.lo + fr->cos_lo);
}

/* The fix in the frame (file comment), and N + h and w at the fix. */
typedef struct {
    se23_vec3_t p_n;
    se23_real_t nh; /* N + h [m] */
    se23_real_t w;  /* sqrt(1 - e^2 sin^2 lat) */
} geo_point_t;

static void geo_offset(const se23_geo_frame_t *fr, const geo_angles_t *g, int32_t dh_mm,
                       geo_point_t *pt)
{
    const se23_real_t a = GEO_A;
    const se23_real_t s0 = fr->sin_hi;
    const se23_real_t c0 = fr->cos_hi;
    const se23_real_t w = se23_sqrt(SE23_R(1) - GEO_E2 * g->s * g->s);
    const se23_real_t dn = a * GEO_E2 * g->ds * (SE23_R(2) * s0 + g->ds) /
                           (w * fr->w0 * (w + fr->w0));
    const se23_real_t h = mm_to_m(fr->origin.h_mm + dh_mm);
    const se23_real_t b = fr->dn0 + dn + h; /* N + h - a */
    const se23_real_t nh = a + b;
    const se23_real_t nsd = dn * g->s + (a + fr->dn0) * g->ds; /* N s - N0 s0 */
    const se23_real_t c = g->c.hi;

    const dreal_t xe = dr_mul(g->c, g->sy);
    const dreal_t pe = two_prod(a, xe.hi);
    pt->p_n.v[1] = pe.hi + ((pe.lo + a * xe.lo) + b * xe.hi);

    const dreal_t pn = two_prod(a, g->sx.hi);
    pt->p_n.v[0] = pn.hi + ((pn.lo + a * g->sx.lo) + b * g->sx.hi +
                            nh * s0 * c * g->qy - GEO_E2 * c0 * nsd);

    const dreal_t dh = mm_to_m_dr(dh_mm);
    pt->p_n.v[2] = ((nh * g->qx + nh * c0 * c * g->qy + GEO_E2 * s0 * nsd - dn) - dh.lo) -
                   dh.hi;
    pt->nh = nh;
    pt->w = w;
}

/* Rows: the fix's north, east and down axes in the frame's axes. */
static void geo_axes(const se23_geo_frame_t *fr, const geo_angles_t *g, se23_mat3_t *ax)
{
    const se23_real_t s0 = fr->sin_hi;
    const se23_real_t c0 = fr->cos_hi;
    const se23_real_t sx = g->sx.hi;
    const se23_real_t sy = g->sy.hi;
    const se23_real_t cx = SE23_R(1) - g->qx;
    const se23_real_t s = g->s;
    const se23_real_t c = g->c.hi;
    ax->m[0][0] = cx - s0 * s * g->qy;
    ax->m[0][1] = -s * sy;
    ax->m[0][2] = sx - c0 * s * g->qy;
    ax->m[1][0] = s0 * sy;
    ax->m[1][1] = SE23_R(1) - g->qy;
    ax->m[1][2] = c0 * sy;
    ax->m[2][0] = -(sx + s0 * c * g->qy);
    ax->m[2][1] = -c * sy;
    ax->m[2][2] = cx - c0 * c * g->qy;
}

/* Offsets within SE23_GEO_DLAT_MAX_E9, SE23_GEO_DLON_MAX_E9, heights within
 * the limit. */
static int offsets_ok(const se23_geo_frame_t *fr, int64_t dlat, int64_t dlon, int64_t dh_mm)
{
    const int64_t h = (int64_t)fr->origin.h_mm + dh_mm;
    return (abs64(dlat) <= SE23_GEO_DLAT_MAX_E9) && (abs64(dlon) <= SE23_GEO_DLON_MAX_E9) &&
           (abs64(h) <= (int64_t)SE23_GEO_H_MAX_MM);
}

static int ned_in_range(const se23_vec3_t *p)
{
    return (se23_fabs(p->v[0]) <= SE23_R(SE23_GEO_RANGE_M)) &&
           (se23_fabs(p->v[1]) <= SE23_R(SE23_GEO_RANGE_M)) &&
           (se23_fabs(p->v[2]) <= SE23_R(SE23_GEO_DOWN_MAX_M));
}

se23_status_t se23_geo_origin(const se23_geo_t *origin, se23_geo_frame_t *frame)
{
    SE23_CHECK_NOT_NULL(origin);
    SE23_CHECK_NOT_NULL(frame);
    if (geo_valid(origin) == 0) {
        return SE23_ERR_DOMAIN;
    }
    dreal_t s0;
    dreal_t c0;
    sincos_lat(abs64(origin->lat_e9), &s0, &c0);
    if (origin->lat_e9 < 0) {
        s0 = dr_neg(s0);
    }
    if (c0.hi < SE23_R(0)) { /* cos 90 deg, computed: a rounding below 0 */
        c0.hi = SE23_R(0);
        c0.lo = SE23_R(0);
    }
    const se23_real_t a = GEO_A;
    const se23_real_t s2 = s0.hi * s0.hi;
    const se23_real_t w0 = se23_sqrt(SE23_R(1) - GEO_E2 * s2);
    const se23_real_t dn0 = a * GEO_E2 * s2 / (w0 * (SE23_R(1) + w0));
    const se23_real_t h0 = mm_to_m(origin->h_mm);
    frame->origin = *origin;
    frame->sin_hi = s0.hi;
    frame->sin_lo = s0.lo;
    frame->cos_hi = c0.hi;
    frame->cos_lo = c0.lo;
    frame->w0 = w0;
    frame->dn0 = dn0;
    frame->h0 = h0;
    frame->north_rad = a * (SE23_R(1) - GEO_E2) / (w0 * w0 * w0) + h0;
    frame->east_rad = (a + dn0 + h0) * c0.hi;
    return SE23_OK;
}

/* lon - lon0 in (-180, 180] deg [1e-9 deg]. */
static int64_t lon_diff(int64_t lon, int64_t lon0)
{
    int64_t d = lon - lon0;
    if (d > SE23_GEO_LON_MAX_E9) {
        d -= 2 * SE23_GEO_LON_MAX_E9;
    } else if (d <= -SE23_GEO_LON_MAX_E9) {
        d += 2 * SE23_GEO_LON_MAX_E9;
    } else {
        /* within the half turn already */
    }
    return d;
}

se23_status_t se23_geo_to_ned(const se23_geo_frame_t *frame, const se23_geo_t *fix,
                              se23_vec3_t *p_n)
{
    SE23_CHECK_NOT_NULL(frame);
    SE23_CHECK_NOT_NULL(fix);
    SE23_CHECK_NOT_NULL(p_n);
    if (geo_valid(fix) == 0) {
        return SE23_ERR_DOMAIN;
    }
    const int64_t dlat = fix->lat_e9 - frame->origin.lat_e9;
    const int64_t dlon = lon_diff(fix->lon_e9, frame->origin.lon_e9);
    const int64_t dh_mm = (int64_t)fix->h_mm - (int64_t)frame->origin.h_mm;
    if (offsets_ok(frame, dlat, dlon, dh_mm) == 0) {
        return SE23_ERR_DOMAIN;
    }
    geo_angles_t g;
    geo_angles(frame, dlat, dlon, &g);
    geo_point_t pt;
    geo_offset(frame, &g, (int32_t)dh_mm, &pt); /* |dh_mm| <= 2e8: checked */
    if (ned_in_range(&pt.p_n) == 0) {
        return SE23_ERR_DOMAIN;
    }
    *p_n = pt.p_n;
    return SE23_OK;
}

/* round(x) as an integer, |x| <= GEO_STEP_MAX < 2^37 checked by the
 * caller, without a real -> int64 routine (libgcc's float one works in
 * double): xr = x + 1/2 away from 0, truncated as t1 2^16 + t0, t1 the
 * truncation of xr 2^-16 (exact scaling, |t1| < 2^22), then xr - t1 2^16
 * (exact: the low bits of xr, of its sign, below 2^16) truncated. */
static int64_t round64(se23_real_t x)
{
    const se23_real_t half = (x < SE23_R(0)) ? SE23_R(-0.5) : SE23_R(0.5);
    const se23_real_t xr = x + half;
    const int32_t t1 = (int32_t)(xr * GEO_2M16);
    const se23_real_t low = xr - (se23_real_t)t1 * GEO_2P16;
    const int32_t t0 = (int32_t)low;
    return (int64_t)t1 * (INT64_C(1) << GEO_SPLIT_BITS) + (int64_t)t0;
}

/* x clamped to [-lim, lim]. */
static int64_t clamp64(int64_t x, int64_t lim)
{
    return (x > lim) ? lim : ((x < -lim) ? -lim : x);
}

/* dd += round(step), |step| <= GEO_STEP_MAX (else 0: refused), each
 * offset clamped into the supported window. */
static int step_clamped(const se23_geo_frame_t *fr, const se23_real_t step[3], int64_t dd[3])
{
    for (int i = 0; i < 3; i++) {
        if (!(se23_fabs(step[i]) <= GEO_STEP_MAX)) {
            return 0;
        }
        dd[i] += round64(step[i]);
    }
    const int64_t h0 = (int64_t)fr->origin.h_mm;
    const int64_t h_max = (int64_t)SE23_GEO_H_MAX_MM;
    dd[0] = clamp64(dd[0], SE23_GEO_DLAT_MAX_E9);
    dd[1] = clamp64(dd[1], SE23_GEO_DLON_MAX_E9);
    dd[2] = clamp64(h0 + dd[2], h_max) - h0;
    return 1;
}

/* The fix of p_n relative to the origin: dlat, dlon [1e-9 deg], dh [mm],
 * and its angles; SE23_OK or a refusal (geodetic.h). Newton's method from
 * a first guess, every iterate inside the supported window; the result is
 * accepted if it maps back onto p_n to GEO_INV_TOL (a point whose fix is
 * outside the window does not). */
static se23_status_t geo_invert(const se23_geo_frame_t *fr, const se23_vec3_t *p_n,
                                int64_t d[3], geo_angles_t *g)
{
    for (int i = 0; i < 3; i++) {
        if (!se23_is_finite(p_n->v[i])) {
            return SE23_ERR_NONFINITE;
        }
    }
    if (ned_in_range(p_n) == 0) {
        return SE23_ERR_DOMAIN;
    }
    const se23_real_t n = p_n->v[0];
    const se23_real_t e = p_n->v[1];
    /* First guess: the arcs along the origin's meridian and parallel, the
     * height above the sphere of radius a + h0 tangent at the origin. */
    se23_real_t step[3];
    step[0] = n / fr->north_rad / GEO_K_HI;
    step[1] = (fr->east_rad > GEO_POLE_EAST_RAD) ? (e / fr->east_rad / GEO_K_HI) : SE23_R(0);
    step[1] = (step[1] > GEO_STEP_MAX) ? GEO_STEP_MAX
                                       : ((step[1] < -GEO_STEP_MAX) ? -GEO_STEP_MAX : step[1]);
    step[2] = SE23_R(1000) * ((n * n + e * e) / (SE23_R(2) * (GEO_A + fr->h0)) - p_n->v[2]);
    int64_t dd[3] = {0, 0, 0};
    if (step_clamped(fr, step, dd) == 0) {
        return SE23_ERR_DOMAIN;
    }
    se23_vec3_t r;
    for (int k = 0; k <= GEO_NEWTON; k++) {
        geo_angles(fr, dd[0], dd[1], g);
        geo_point_t pt;
        geo_offset(fr, g, (int32_t)dd[2], &pt); /* clamped: |dd[2]| <= 2e8 */
        se23_v3_axpy(p_n, SE23_R(-1), &pt.p_n, &r);
        if (k == GEO_NEWTON) {
            break;
        }
        /* Newton: the Jacobian of p_n in (lat, lon, h) has the fix's north,
         * east and down axes as columns, scaled by M + h, (N + h) cos lat, -1. */
        se23_mat3_t ax;
        geo_axes(fr, g, &ax);
        se23_vec3_t loc;
        se23_m3_mul_v3(&ax, &r, &loc);
        const se23_real_t h = mm_to_m(fr->origin.h_mm + (int32_t)dd[2]);
        const se23_real_t m_h =
            GEO_A * (SE23_R(1) - GEO_E2) / (pt.w * pt.w * pt.w) + h;
        const se23_real_t e_rad = pt.nh * g->c.hi;
        step[0] = loc.v[0] / m_h / GEO_K_HI;
        step[1] = (e_rad > GEO_POLE_EAST_RAD) ? (loc.v[1] / e_rad / GEO_K_HI) : SE23_R(0);
        step[2] = SE23_R(-1000) * loc.v[2];
        if (step_clamped(fr, step, dd) == 0) {
            return SE23_ERR_DOMAIN;
        }
    }
    if (!((se23_fabs(r.v[0]) <= GEO_INV_TOL) && (se23_fabs(r.v[1]) <= GEO_INV_TOL) &&
          (se23_fabs(r.v[2]) <= GEO_INV_TOL))) {
        return SE23_ERR_DOMAIN;
    }
    d[0] = dd[0];
    d[1] = dd[1];
    d[2] = dd[2];
    return SE23_OK;
}

se23_status_t se23_geo_from_ned(const se23_geo_frame_t *frame, const se23_vec3_t *p_n,
                                se23_geo_t *fix)
{
    SE23_CHECK_NOT_NULL(frame);
    SE23_CHECK_NOT_NULL(p_n);
    SE23_CHECK_NOT_NULL(fix);
    int64_t d[3];
    geo_angles_t g;
    const se23_status_t st = geo_invert(frame, p_n, d, &g);
    if (st != SE23_OK) {
        return st;
    }
    const int64_t lat = frame->origin.lat_e9 + d[0];
    if (abs64(lat) > SE23_GEO_LAT_MAX_E9) {
        return SE23_ERR_DOMAIN; /* across a pole */
    }
    const int64_t lon = frame->origin.lon_e9 + d[1];
    fix->lat_e9 = lat;
    fix->lon_e9 = lon_diff(lon, 0);
    fix->h_mm = (int32_t)((int64_t)frame->origin.h_mm + d[2]);
    return SE23_OK;
}

se23_status_t se23_geo_down_at(const se23_geo_frame_t *frame, const se23_vec3_t *p_n,
                               se23_vec3_t *down_n)
{
    SE23_CHECK_NOT_NULL(frame);
    SE23_CHECK_NOT_NULL(p_n);
    SE23_CHECK_NOT_NULL(down_n);
    int64_t d[3];
    geo_angles_t g;
    const se23_status_t st = geo_invert(frame, p_n, d, &g);
    if (st != SE23_OK) {
        return st;
    }
    if (abs64(frame->origin.lat_e9 + d[0]) > SE23_GEO_LAT_MAX_E9) {
        return SE23_ERR_DOMAIN;
    }
    se23_mat3_t ax;
    geo_axes(frame, &g, &ax);
    const se23_vec3_t dn = {{ax.m[2][0], ax.m[2][1], ax.m[2][2]}};
    const se23_real_t inv = SE23_R(1) / se23_sqrt(se23_v3_dot(&dn, &dn));
    se23_v3_scale(&dn, inv, down_n);
    return SE23_OK;
}
