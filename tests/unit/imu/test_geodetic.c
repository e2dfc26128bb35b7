/* Unit tests of src/imu/geodetic.c: WGS-84 fixes to and from the local NED
 * frame, against published conversions and an independent long-double
 * route (the textbook ECEF formula, differenced and rotated: the plain
 * form, with its cancellation, which 64 significand bits absorb). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include <cmocka.h>

#include "se23/geodetic.h"
#include "se23_rng.h"
#include "se23_test.h"

#define SENTINEL 0x5a
#define DEG_E9 1000000000LL

static const long double PI_L = 3.141592653589793238462643383279502884L;
static const long double A_L = 6378137.0L;

/* Accuracy of se23_geo_to_ned against the long-double route [m]
 * (geodetic.h): within 10 km and within 100 km of the origin (the float
 * output's own spacing at 100 km is 7.8 mm). */
#if SE23_CFG_DOUBLE
#define TOL_10KM 1e-6
#define TOL_100KM 1e-6
#else
#define TOL_10KM 1e-3
#define TOL_100KM 6e-3
#endif

static long double e2_l(void)
{
    const long double f = 1.0L / 298.257223563L;
    return f * (2.0L - f);
}

static long double rad_l(int64_t e9) { return (long double)e9 * (PI_L / 180e9L); }

/* The textbook WGS-84 geodetic -> ECEF (e.g. Hofmann-Wellenhof et al.,
 * GNSS, eq. 10.29; NIMA TR8350.2 eq. 4-14), in long double. */
static void ecef_l(long double lat, long double lon, long double h, long double x[3])
{
    const long double s = sinl(lat);
    const long double n = A_L / sqrtl(1.0L - e2_l() * s * s);
    x[0] = (n + h) * cosl(lat) * cosl(lon);
    x[1] = (n + h) * cosl(lat) * sinl(lon);
    x[2] = (n * (1.0L - e2_l()) + h) * s;
}

/* R_ne of the origin applied to v (ECEF). */
static void to_ned_axes_l(const se23_geo_t *o, const long double v[3], long double p[3])
{
    const long double sp = sinl(rad_l(o->lat_e9)), cp = cosl(rad_l(o->lat_e9));
    const long double sl = sinl(rad_l(o->lon_e9)), cl = cosl(rad_l(o->lon_e9));
    p[0] = -sp * cl * v[0] - sp * sl * v[1] + cp * v[2];
    p[1] = -sl * v[0] + cl * v[1];
    p[2] = -cp * cl * v[0] - cp * sl * v[1] - sp * v[2];
}

/* Expected NED of fix in the frame at o: R_ne (x(fix) - x(o)). */
static void ned_l(const se23_geo_t *o, const se23_geo_t *fix, long double p[3])
{
    long double x0[3], x1[3], d[3];
    ecef_l(rad_l(o->lat_e9), rad_l(o->lon_e9), o->h_mm / 1000.0L, x0);
    ecef_l(rad_l(fix->lat_e9), rad_l(fix->lon_e9), fix->h_mm / 1000.0L, x1);
    for (int i = 0; i < 3; i++) {
        d[i] = x1[i] - x0[i];
    }
    to_ned_axes_l(o, d, p);
}

/* Expected down at fix, in the frame at o: minus the ellipsoid normal. */
static void down_l(const se23_geo_t *o, const se23_geo_t *fix, long double dn[3])
{
    const long double lat = rad_l(fix->lat_e9), lon = rad_l(fix->lon_e9);
    const long double u[3] = {-cosl(lat) * cosl(lon), -cosl(lat) * sinl(lon), -sinl(lat)};
    to_ned_axes_l(o, u, dn);
}

static se23_geo_t geo(double lat_deg, double lon_deg, double h_m)
{
    se23_geo_t g;
    g.lat_e9 = llround(lat_deg * 1e9);
    g.lon_e9 = llround(lon_deg * 1e9);
    g.h_mm = (int32_t)lround(h_m * 1000.0);
    return g;
}

static void frame_at(const se23_geo_t *o, se23_geo_frame_t *fr)
{
    assert_int_equal(se23_geo_origin(o, fr), SE23_OK);
}

static void assert_ned_l(const se23_vec3_t *p, const long double e[3], double tol)
{
    for (int i = 0; i < 3; i++) {
        assert_near((double)p->v[i], (double)e[i], tol, 0);
    }
}

/* Published geodetic -> ECEF pairs check the test's own long-double
 * formula (and so every expected value below). */
static void test_geodetic_reference_matches_published_ecef(void **state)
{
    (void)state;
    long double x[3];
    /* pymap3d test suite (github.com/geospace-code/pymap3d,
     * tests/test_geodetic.py, also MATLAB geodetic2ecef): (42, -82, 200 m). */
    ecef_l(42.0L * PI_L / 180, -82.0L * PI_L / 180, 200.0L, x);
    assert_near((double)x[0], 660675.2518247, 1e-6, 0);
    assert_near((double)x[1], -4700948.68316, 1e-5, 0);
    assert_near((double)x[2], 4245737.66222, 1e-5, 0);
    /* qzsl6tool (github.com/yoronneko/qzsl6tool, docs/llh2ecef-en.md):
     * (34.4401061, 132.4147804, 233.362 m), printed to the millimetre. */
    ecef_l(34.4401061L * PI_L / 180, 132.4147804L * PI_L / 180, 233.362L, x);
    assert_near((double)x[0], -3551876.829, 6e-4, 0);
    assert_near((double)x[1], 3887786.860, 6e-4, 0);
    assert_near((double)x[2], 3586946.387, 6e-4, 0);
}

/* pymap3d's published local example: az 33 deg, el 70 deg, range 1000 m
 * from (42, -82, 200 m) is (42.002582, -81.997752, 1139.7018 m), its
 * degrees to 6 decimals (0.11 m). */
static void test_geodetic_to_ned_published_local_example(void **state)
{
    (void)state;
    const se23_geo_t o = geo(42, -82, 200);
    const se23_geo_t fix = geo(42.002582, -81.997752, 1139.7018);
    se23_geo_frame_t fr;
    frame_at(&o, &fr);
    se23_vec3_t p;
    assert_int_equal(se23_geo_to_ned(&fr, &fix, &p), SE23_OK);
    const double el = 70 * 3.14159265358979323846 / 180, az = 33 * 3.14159265358979323846 / 180;
    assert_near(p.v[0], 1000 * cos(el) * cos(az), 0.07, 0);
    assert_near(p.v[1], 1000 * cos(el) * sin(az), 0.07, 0);
    assert_near(p.v[2], -1000 * sin(el), 2e-3, 0);
}

static void test_geodetic_fix_at_origin_is_exactly_zero(void **state)
{
    (void)state;
    const se23_geo_t origins[] = {geo(0, 0, 0), geo(47.123456789, 8.5, 512.345),
                                  geo(-89.999, -179.5, -100), geo(90, 180, 1e5),
                                  geo(-33.9, 151.2, 20)};
    for (size_t i = 0; i < sizeof origins / sizeof origins[0]; i++) {
        se23_geo_frame_t fr;
        frame_at(&origins[i], &fr);
        se23_vec3_t p;
        assert_int_equal(se23_geo_to_ned(&fr, &origins[i], &p), SE23_OK);
        assert_true(p.v[0] == 0 && p.v[1] == 0 && p.v[2] == 0);
        se23_geo_t back;
        assert_int_equal(se23_geo_from_ned(&fr, &p, &back), SE23_OK);
        assert_true(back.lat_e9 == origins[i].lat_e9 && back.h_mm == origins[i].h_mm);
        se23_vec3_t dn;
        assert_int_equal(se23_geo_down_at(&fr, &p, &dn), SE23_OK);
        assert_near(dn.v[0], 0, 4 * SE23T_EPS, 0);
        assert_near(dn.v[1], 0, 4 * SE23T_EPS, 0);
        assert_near(dn.v[2], 1, 4 * SE23T_EPS, 0);
    }
}

/* A fix at distance dist [m] and azimuth az [rad] from o, height h_m. */
/* fix in the frame at o (made into fr) by se23_geo_to_ned into p, within tol
 * [m] of e, the long-double reference (ned_l). */
static void to_ned_checked(const se23_geo_t *o, const se23_geo_t *fix, double tol,
                           se23_geo_frame_t *fr, se23_vec3_t *p, long double e[3])
{
    frame_at(o, fr);
    assert_int_equal(se23_geo_to_ned(fr, fix, p), SE23_OK);
    ned_l(o, fix, e);
    assert_ned_l(p, e, tol);
}

static se23_geo_t fix_at(const se23_geo_t *o, double dist, double az, double h_m)
{
    const double lat = (double)rad_l(o->lat_e9);
    const double s = sin(lat);
    const double w = sqrt(1 - (double)e2_l() * s * s);
    const double m = 6378137.0 * (1 - (double)e2_l()) / (w * w * w);
    const double n = 6378137.0 / w;
    se23_geo_t g = *o;
    g.lat_e9 += llround(dist * cos(az) / m * 180e9 / 3.14159265358979323846);
    g.lon_e9 += llround(dist * sin(az) / (n * cos(lat)) * 180e9 / 3.14159265358979323846);
    if (g.lon_e9 > 180 * DEG_E9) {
        g.lon_e9 -= 360 * DEG_E9;
    } else if (g.lon_e9 < -180 * DEG_E9) {
        g.lon_e9 += 360 * DEG_E9;
    }
    g.h_mm = (int32_t)lround(h_m * 1000.0);
    return g;
}

/* Against the long-double route over origins all over the Earth (to 85 deg,
 * where 100 km are still within 10 deg of longitude), 8 azimuths, 1/10/100
 * km and heights from -500 m to 9 km; and the round trip. */
static void test_geodetic_to_ned_matches_long_double_ecef(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 35);
    const double dists[] = {1e3, 1e4, 1e5};
    const double tols[] = {TOL_10KM, TOL_10KM, TOL_100KM};
    double worst[3] = {0, 0, 0};
    double worst_ne[3] = {0, 0, 0}; /* north and east only (down carries h - h0 up to 9.5 km) */
    for (int k = 0; k < 3; k++) {
        for (int t = 0; t < 400; t++) {
            const se23_geo_t o = geo(se23t_uniform(&rng, -85, 85), se23t_uniform(&rng, -180, 180),
                                     se23t_uniform(&rng, -500, 9000));
            const se23_geo_t fix = fix_at(&o, dists[k], (t % 8) * 0.785398163397448 + 0.1,
                                          se23t_uniform(&rng, -500, 9000));
            se23_geo_frame_t fr;
            se23_vec3_t p;
            long double e[3];
            to_ned_checked(&o, &fix, tols[k], &fr, &p, e);
            for (int i = 0; i < 3; i++) {
                worst[k] = fmax(worst[k], fabs((double)((long double)p.v[i] - e[i])));
                if (i < 2) {
                    worst_ne[k] = fmax(worst_ne[k], fabs((double)((long double)p.v[i] - e[i])));
                }
            }

            /* Round trip: within one unit where the real p_n carries it
             * (double); in float within p_n's own rounding, in metres. */
            se23_geo_t back;
            assert_int_equal(se23_geo_from_ned(&fr, &p, &back), SE23_OK);
            const double m_per_e9 = 6378137.0 * 3.14159265358979323846 / 180e9;
            const double cos_lat = cos((double)rad_l(fix.lat_e9));
            const double unit = SE23_CFG_DOUBLE ? 1.0 : 1.0 + 2 * tols[k] / m_per_e9;
            assert_true(llabs(back.lat_e9 - fix.lat_e9) <= (long long)unit);
            assert_true((double)llabs(back.lon_e9 - fix.lon_e9) * cos_lat <= unit);
            assert_true(abs(back.h_mm - fix.h_mm) <= (SE23_CFG_DOUBLE ? 1 : 1 + (int)(2e3 * tols[k])));
        }
    }
    print_message("to_ned vs long double, worst [m]: 1 km %.3g, 10 km %.3g, 100 km %.3g"
                  " (north/east: %.3g, %.3g, %.3g)\n",
                  worst[0], worst[1], worst[2], worst_ne[0], worst_ne[1], worst_ne[2]);
}

/* Simpson's rule on [0, x] for f(t) = (M(lat0 + t) + h) * (cos t or sin t):
 * the tangent of the meridian at lat0 + t is tilted by t from the origin's
 * north, so a pure change of latitude at constant height is at
 * north = int (M + h) cos t dt, down = int (M + h) sin t dt (the meridian
 * arc, projected). */
static long double meridian_l(long double lat0, long double h, long double x, int sine)
{
    const int n = 2000;
    long double sum = 0;
    for (int i = 0; i <= n; i++) {
        const long double t = x * i / n;
        const long double s = sinl(lat0 + t);
        const long double w = sqrtl(1.0L - e2_l() * s * s);
        const long double m = A_L * (1.0L - e2_l()) / (w * w * w) + h;
        const long double f = m * (sine ? sinl(t) : cosl(t));
        sum += f * ((i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2));
    }
    return sum * x / (3.0L * n);
}

static void test_geodetic_north_follows_meridian_arc(void **state)
{
    (void)state;
    const double lats[] = {0, 30, 45.5, -60.25, 80};
    const int64_t dlats[] = {9 * DEG_E9 / 1000, 9 * DEG_E9 / 100, 9 * DEG_E9 / 10};
    const double tols[] = {TOL_10KM, TOL_10KM, TOL_100KM};
    for (size_t i = 0; i < sizeof lats / sizeof lats[0]; i++) {
        for (int k = 0; k < 3; k++) {
            const se23_geo_t o = geo(lats[i], 10, 250);
            se23_geo_t fix = o;
            fix.lat_e9 += dlats[k];
            se23_geo_frame_t fr;
            frame_at(&o, &fr);
            se23_vec3_t p;
            assert_int_equal(se23_geo_to_ned(&fr, &fix, &p), SE23_OK);
            const long double lat0 = rad_l(o.lat_e9), x = rad_l(dlats[k]);
            assert_near(p.v[0], (double)meridian_l(lat0, 250, x, 0), tols[k], 0);
            assert_near(p.v[1], 0, tols[k], 0);
            assert_near(p.v[2], (double)meridian_l(lat0, 250, x, 1), tols[k], 0);
            /* The arc itself, to its chord correction (x^3 R / 6). */
            const double arc = (double)(meridian_l(lat0, 250, x, 0) / 1);
            assert_near(p.v[0], arc, 6.4e6 * pow((double)x, 3) / 6 + tols[k], 0);
        }
    }
}

/* se23_geo_down_at at fix, in the frame at o, into dn: exactly the ellipsoid
 * normal there (down_l). */
static void assert_down_at_normal(const se23_geo_t *o, const se23_geo_t *fix, se23_vec3_t *dn)
{
    se23_geo_frame_t fr;
    se23_vec3_t p;
    long double e[3];
    frame_at(o, &fr);
    assert_int_equal(se23_geo_to_ned(&fr, fix, &p), SE23_OK);
    assert_int_equal(se23_geo_down_at(&fr, &p, dn), SE23_OK);
    down_l(o, fix, e);
    for (int j = 0; j < 3; j++) {
        assert_near(dn->v[j], (double)e[j], SE23_CFG_DOUBLE ? 1e-12 : 4e-7, 0);
    }
}

/* East along the parallel: the down vector tilts east by offset / (N + h). */
static void test_geodetic_down_tilts_by_offset_over_radius(void **state)
{
    (void)state;
    const double lats[] = {0, 45, -70};
    const int64_t dlons[] = {DEG_E9 / 100, DEG_E9 / 10, DEG_E9 / 2};
    for (size_t i = 0; i < sizeof lats / sizeof lats[0]; i++) {
        for (int k = 0; k < 3; k++) {
            const se23_geo_t o = geo(lats[i], -120, 100);
            se23_geo_t fix = o;
            fix.lon_e9 += dlons[k];
            se23_vec3_t dn;
            assert_down_at_normal(&o, &fix, &dn); /* exact: the ellipsoid normal at the fix */
            const double lat = (double)rad_l(o.lat_e9);
            const double n = 6378137.0 / sqrt(1 - (double)e2_l() * sin(lat) * sin(lat));
            const double east = (n + 100) * cos(lat) * (double)rad_l(dlons[k]); /* along the parallel */
            const double tilt = east / (n + 100);
            /* First order: dn_east = -sin(tilt) (cos dlon ~ 1), second order in tilt elsewhere. */
            assert_near(dn.v[1], -tilt, tilt * tilt + 8 * SE23T_EPS, 0);
            assert_near(sqrt(dn.v[0] * dn.v[0] + dn.v[1] * dn.v[1]), fabs(tilt),
                        tilt * tilt + 8 * SE23T_EPS, 0);
        }
    }
}

static void test_geodetic_down_at_matches_normal_everywhere(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 36);
    for (int t = 0; t < 300; t++) {
        const se23_geo_t o = geo(se23t_uniform(&rng, -85, 85), se23t_uniform(&rng, -180, 180),
                                 se23t_uniform(&rng, 0, 2000));
        const se23_geo_t fix = fix_at(&o, se23t_uniform(&rng, 0, 1e5),
                                      se23t_uniform(&rng, 0, 6.283185307), se23t_uniform(&rng, 0, 2000));
        se23_vec3_t dn;
        assert_down_at_normal(&o, &fix, &dn);
    }
}

static void test_geodetic_across_antimeridian(void **state)
{
    (void)state;
    const se23_geo_t o = geo(10, 179.9995, 0);
    const se23_geo_t fix = geo(10, -179.9995, 0);
    se23_geo_frame_t fr;
    se23_vec3_t p;
    long double e[3];
    to_ned_checked(&o, &fix, TOL_10KM, &fr, &p, e);
    assert_true(p.v[1] > 100 && p.v[1] < 120);
    se23_geo_t back;
    assert_int_equal(se23_geo_from_ned(&fr, &p, &back), SE23_OK);
    assert_true(llabs(back.lon_e9 - fix.lon_e9) <= (SE23_CFG_DOUBLE ? 1 : 8));
    /* West across it, and the longitude comes back in (-180, 180]. */
    const se23_geo_t o2 = geo(-5, -180, 0);
    frame_at(&o2, &fr);
    se23_vec3_t w = {{0, -1000, 0}};
    assert_int_equal(se23_geo_from_ned(&fr, &w, &back), SE23_OK);
    assert_true(back.lon_e9 < 180 * DEG_E9 && back.lon_e9 > 179 * DEG_E9);
}

static void test_geodetic_origin_rejects_bad_inputs(void **state)
{
    (void)state;
    const se23_geo_t bad[] = {
        {90 * DEG_E9 + 1, 0, 0},  {-90 * DEG_E9 - 1, 0, 0},  {0, 180 * DEG_E9 + 1, 0},
        {0, -180 * DEG_E9 - 1, 0}, {0, 0, SE23_GEO_H_MAX_MM + 1}, {0, 0, -SE23_GEO_H_MAX_MM - 1},
        {INT64_MIN, 0, 0},         {0, INT64_MAX, 0},
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        se23_geo_frame_t fr, fr0;
        memset(&fr, SENTINEL, sizeof fr);
        fr0 = fr;
        assert_int_equal(se23_geo_origin(&bad[i], &fr), SE23_ERR_DOMAIN);
        assert_memory_equal(&fr, &fr0, sizeof fr);
    }
    const se23_geo_t edge[] = {{90 * DEG_E9, 180 * DEG_E9, SE23_GEO_H_MAX_MM},
                               {-90 * DEG_E9, -180 * DEG_E9, -SE23_GEO_H_MAX_MM}};
    for (size_t i = 0; i < 2; i++) {
        se23_geo_frame_t fr;
        assert_int_equal(se23_geo_origin(&edge[i], &fr), SE23_OK);
    }
}

static void test_geodetic_to_ned_rejects_bad_fixes(void **state)
{
    (void)state;
    const se23_geo_t o = geo(45, 7, 300);
    se23_geo_frame_t fr;
    frame_at(&o, &fr);
    se23_geo_t bad[] = {
        {90 * DEG_E9 + 1, o.lon_e9, 0},
        {o.lat_e9, 180 * DEG_E9 + 1, 0},
        {o.lat_e9, o.lon_e9, SE23_GEO_H_MAX_MM + 1},
        {o.lat_e9 + SE23_GEO_DLAT_MAX_E9 + 1, o.lon_e9, 0},
        {o.lat_e9, o.lon_e9 + 3 * DEG_E9, 0},        /* 236 km east: beyond the range */
        {o.lat_e9 - 14 * DEG_E9 / 10, o.lon_e9, 0},  /* 155 km south */
        {o.lat_e9, o.lon_e9 - 11 * DEG_E9, 0},       /* beyond 10 deg */
    };
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        se23_vec3_t p, p0;
        memset(&p, SENTINEL, sizeof p);
        p0 = p;
        assert_int_equal(se23_geo_to_ned(&fr, &bad[i], &p), SE23_ERR_DOMAIN);
        assert_memory_equal(&p, &p0, sizeof p);
    }
    /* Near the pole the 10 deg of longitude is the limit, not the range. */
    const se23_geo_t polar = geo(88, 0, 0);
    frame_at(&polar, &fr);
    const se23_geo_t far_lon = geo(88, 10.5, 0);
    se23_vec3_t p;
    assert_int_equal(se23_geo_to_ned(&fr, &far_lon, &p), SE23_ERR_DOMAIN);
    const se23_geo_t near_lon = geo(88, 9.5, 0);
    assert_int_equal(se23_geo_to_ned(&fr, &near_lon, &p), SE23_OK);
}

static void test_geodetic_from_ned_and_down_reject_bad_points(void **state)
{
    (void)state;
    const se23_geo_t o = geo(-30, 20, 0);
    se23_geo_frame_t fr;
    frame_at(&o, &fr);
    const struct {
        se23_vec3_t p;
        se23_status_t st;
    } cases[] = {
        {{{(se23_real_t)NAN, 0, 0}}, SE23_ERR_NONFINITE},
        {{{0, (se23_real_t)INFINITY, 0}}, SE23_ERR_NONFINITE},
        {{{0, 0, (se23_real_t)-INFINITY}}, SE23_ERR_NONFINITE},
        {{{SE23_R(150001), 0, 0}}, SE23_ERR_DOMAIN},
        {{{0, SE23_R(-150001), 0}}, SE23_ERR_DOMAIN},
        {{{0, 0, SE23_R(210001)}}, SE23_ERR_DOMAIN},
        {{{0, 0, SE23_R(-100001)}}, SE23_ERR_DOMAIN}, /* h beyond 100 km */
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; i++) {
        se23_geo_t g, g0;
        memset(&g, SENTINEL, sizeof g);
        g0 = g;
        assert_int_equal(se23_geo_from_ned(&fr, &cases[i].p, &g), cases[i].st);
        assert_memory_equal(&g, &g0, sizeof g);
        se23_vec3_t dn, dn0;
        memset(&dn, SENTINEL, sizeof dn);
        dn0 = dn;
        assert_int_equal(se23_geo_down_at(&fr, &cases[i].p, &dn), cases[i].st);
        assert_memory_equal(&dn, &dn0, sizeof dn);
    }
    /* Across the pole: 100 km north of 89.5 deg. */
    const se23_geo_t polar = geo(89.5, 0, 0);
    frame_at(&polar, &fr);
    const se23_vec3_t over = {{100000, 0, 0}};
    se23_geo_t g, g0;
    memset(&g, SENTINEL, sizeof g);
    g0 = g;
    assert_int_equal(se23_geo_from_ned(&fr, &over, &g), SE23_ERR_DOMAIN);
    assert_memory_equal(&g, &g0, sizeof g);
    se23_vec3_t dn, dn0;
    memset(&dn, SENTINEL, sizeof dn);
    dn0 = dn;
    assert_int_equal(se23_geo_down_at(&fr, &over, &dn), SE23_ERR_DOMAIN);
    assert_memory_equal(&dn, &dn0, sizeof dn);
}

static void test_geodetic_null_arguments_return_err_null(void **state)
{
    (void)state;
#if SE23_CFG_ARG_CHECKS
    const se23_geo_t o = geo(1, 2, 3);
    se23_geo_frame_t fr;
    frame_at(&o, &fr);
    se23_vec3_t p = {{0, 0, 0}};
    se23_geo_t g;
    assert_int_equal(se23_geo_origin(NULL, &fr), SE23_ERR_NULL);
    assert_int_equal(se23_geo_origin(&o, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_geo_to_ned(NULL, &o, &p), SE23_ERR_NULL);
    assert_int_equal(se23_geo_to_ned(&fr, NULL, &p), SE23_ERR_NULL);
    assert_int_equal(se23_geo_to_ned(&fr, &o, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_geo_from_ned(NULL, &p, &g), SE23_ERR_NULL);
    assert_int_equal(se23_geo_from_ned(&fr, NULL, &g), SE23_ERR_NULL);
    assert_int_equal(se23_geo_from_ned(&fr, &p, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_geo_down_at(NULL, &p, &p), SE23_ERR_NULL);
    assert_int_equal(se23_geo_down_at(&fr, NULL, &p), SE23_ERR_NULL);
    assert_int_equal(se23_geo_down_at(&fr, &p, NULL), SE23_ERR_NULL);
#else
    skip();
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_geodetic_reference_matches_published_ecef),
        cmocka_unit_test(test_geodetic_to_ned_published_local_example),
        cmocka_unit_test(test_geodetic_fix_at_origin_is_exactly_zero),
        cmocka_unit_test(test_geodetic_to_ned_matches_long_double_ecef),
        cmocka_unit_test(test_geodetic_north_follows_meridian_arc),
        cmocka_unit_test(test_geodetic_down_tilts_by_offset_over_radius),
        cmocka_unit_test(test_geodetic_down_at_matches_normal_everywhere),
        cmocka_unit_test(test_geodetic_across_antimeridian),
        cmocka_unit_test(test_geodetic_origin_rejects_bad_inputs),
        cmocka_unit_test(test_geodetic_to_ned_rejects_bad_fixes),
        cmocka_unit_test(test_geodetic_from_ned_and_down_reject_bad_points),
        cmocka_unit_test(test_geodetic_null_arguments_return_err_null),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
