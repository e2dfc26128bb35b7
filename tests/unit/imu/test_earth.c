/* Unit tests of src/imu/earth.c: WGS-84 gravity and Earth rate, Gamma', the
 * navigation model. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "se23/earth.h"
#include "se23_test.h"

#define PI 3.14159265358979323846
#define WE 7.292115e-5

/* A few operations away from exact, O(1) quantities. */
#define TOL (64.0 * SE23T_EPS)

/* Central differences in t with step h: truncation ~ h^2 |d3/dt3|, rounding
 * ~ eps / h. */
#if SE23_CFG_DOUBLE
#define FD_STEP 1e-4
#define FD_TOL 1e-7
#else
#define FD_STEP 2e-2
#define FD_TOL 2e-3
#endif

/* Byte pattern written into outputs before a call that must not write them. */
#define SENTINEL 0x5a

static void test_earth_gravity_equator_and_pole_are_wgs84_values(void **state)
{
    (void)state;
    se23_real_t g;
    assert_int_equal(se23_earth_gravity(0, 0, &g), SE23_OK);
    assert_near(g, 9.7803253359, 0, 4 * SE23T_EPS);
    assert_int_equal(se23_earth_gravity((se23_real_t)(PI / 2), 0, &g), SE23_OK);
    assert_near(g, 9.8321849378, 0, 4 * SE23T_EPS + 1e-11);
    assert_int_equal(se23_earth_gravity((se23_real_t)(-PI / 2), 0, &g), SE23_OK);
    assert_near(g, 9.8321849378, 0, 4 * SE23T_EPS + 1e-11);
}

/* GRS-80 normal gravity as Moritz's series in sin^2(lat) (Geodetic Reference
 * System 1980, eq. for gamma with coefficients to 1e-10): an independent
 * formula for the same ellipsoid up to the GRS80/WGS84 difference (~1.5e-6). */
static double grs80_series(double lat)
{
    double s2 = sin(lat) * sin(lat);
    return 9.7803267715 * (1 + s2 * (0.0052790414 +
                                     s2 * (0.0000232718 +
                                           s2 * (0.0000001262 + s2 * 0.0000000007))));
}

static void test_earth_gravity_agrees_with_grs80_series(void **state)
{
    (void)state;
    for (double deg = -90; deg <= 90; deg += 7.5) {
        se23_real_t g;
        assert_int_equal(se23_earth_gravity((se23_real_t)(deg * PI / 180), 0, &g), SE23_OK);
        assert_near(g, grs80_series(deg * PI / 180), 3e-6, 4 * SE23T_EPS);
    }
}

static void test_earth_gravity_height_gives_free_air_gradient(void **state)
{
    (void)state;
    /* The free-air gradient is -0.3086 mGal/m = -3.086e-6 s^-2 (textbook
     * value, to its 4 digits). */
    se23_real_t g0, g1, g10k;
    const se23_real_t lat = (se23_real_t)(PI / 4);
    assert_int_equal(se23_earth_gravity(lat, 0, &g0), SE23_OK);
    assert_int_equal(se23_earth_gravity(lat, 1000, &g1), SE23_OK);
    assert_near(((double)g1 - g0) / 1000, -3.086e-6, 0, SE23_CFG_DOUBLE ? 5e-4 : 0.05);
    /* The second difference isolates the h^2 term: g0 * 6 h^2 / a^2. */
    se23_real_t g20k;
    assert_int_equal(se23_earth_gravity(lat, 10000, &g10k), SE23_OK);
    assert_int_equal(se23_earth_gravity(lat, 20000, &g20k), SE23_OK);
    assert_near((double)g20k - 2.0 * g10k + g0, (double)g0 * 6e8 / (6378137.0 * 6378137.0),
                SE23_CFG_DOUBLE ? 1e-12 : 1e-5, 0);
}

static void test_earth_gravity_vec_points_down(void **state)
{
    (void)state;
    se23_real_t g;
    se23_vec3_t ned, enu;
    const se23_real_t lat = SE23_R(0.7), h = SE23_R(250);
    assert_int_equal(se23_earth_gravity(lat, h, &g), SE23_OK);
    assert_int_equal(se23_earth_gravity_vec(SE23_FRAME_NED, lat, h, &ned), SE23_OK);
    assert_int_equal(se23_earth_gravity_vec(SE23_FRAME_ENU, lat, h, &enu), SE23_OK);
    const se23_real_t e_ned[3] = {0, 0, g}, e_enu[3] = {0, 0, -g};
    assert_array_near(ned.v, e_ned, 3, 0, 0);
    assert_array_near(enu.v, e_enu, 3, 0, 0);
}

static void test_earth_rate_ned_and_enu_at_45_deg(void **state)
{
    (void)state;
    se23_vec3_t ned, enu;
    const double c = WE * sqrt(0.5);
    assert_int_equal(se23_earth_rate(SE23_FRAME_NED, (se23_real_t)(PI / 4), &ned), SE23_OK);
    assert_int_equal(se23_earth_rate(SE23_FRAME_ENU, (se23_real_t)(PI / 4), &enu), SE23_OK);
    const se23_real_t e_ned[3] = {(se23_real_t)c, 0, (se23_real_t)-c};
    const se23_real_t e_enu[3] = {0, (se23_real_t)c, (se23_real_t)c};
    assert_array_near(ned.v, e_ned, 3, 0, 4 * SE23T_EPS);
    assert_array_near(enu.v, e_enu, 3, 0, 4 * SE23T_EPS);
    /* At the north pole the Earth rate points up; at the equator, north. */
    assert_int_equal(se23_earth_rate(SE23_FRAME_NED, (se23_real_t)(PI / 2), &ned), SE23_OK);
    assert_near(ned.v[2], -WE, 0, 4 * SE23T_EPS);
    assert_near(ned.v[0], 0, 1e-20 + WE * 4 * SE23T_EPS, 0);
    assert_int_equal(se23_earth_rate(SE23_FRAME_ENU, 0, &enu), SE23_OK);
    const se23_real_t e_eq[3] = {0, (se23_real_t)WE, 0};
    assert_array_near(enu.v, e_eq, 3, 0, 0);
}

static void test_earth_gravity_and_rate_reject_bad_inputs(void **state)
{
    (void)state;
    const se23_real_t big_lat = (se23_real_t)(PI / 2 + 1e-3);
    const se23_real_t bad_lat[] = {(se23_real_t)NAN, (se23_real_t)INFINITY, big_lat, -big_lat};
    const se23_status_t bad_lat_st[] = {SE23_ERR_NONFINITE, SE23_ERR_NONFINITE,
                                        SE23_ERR_DOMAIN, SE23_ERR_DOMAIN};
    for (int i = 0; i < 4; ++i) {
        se23_real_t g = SE23_R(-1);
        se23_vec3_t v, v0;
        memset(&v, SENTINEL, sizeof v);
        v0 = v;
        assert_int_equal(se23_earth_gravity(bad_lat[i], 0, &g), bad_lat_st[i]);
        assert_true(g == SE23_R(-1));
        assert_int_equal(se23_earth_gravity_vec(SE23_FRAME_ENU, bad_lat[i], 0, &v), bad_lat_st[i]);
        assert_int_equal(se23_earth_rate(SE23_FRAME_NED, bad_lat[i], &v), bad_lat_st[i]);
        assert_memory_equal(&v, &v0, sizeof v);
    }
    const se23_real_t bad_h[] = {(se23_real_t)NAN, (se23_real_t)-INFINITY,
                                 SE23_R(-1.01e4), SE23_R(1.01e5)};
    const se23_status_t bad_h_st[] = {SE23_ERR_NONFINITE, SE23_ERR_NONFINITE,
                                      SE23_ERR_DOMAIN, SE23_ERR_DOMAIN};
    for (int i = 0; i < 4; ++i) {
        se23_real_t g = SE23_R(-1);
        assert_int_equal(se23_earth_gravity(0, bad_h[i], &g), bad_h_st[i]);
        assert_true(g == SE23_R(-1));
    }
    /* The ends of the domains are accepted. */
    se23_real_t g;
    assert_int_equal(se23_earth_gravity(0, SE23_R(SE23_EARTH_H_MIN), &g), SE23_OK);
    assert_int_equal(se23_earth_gravity(0, SE23_R(SE23_EARTH_H_MAX), &g), SE23_OK);
    assert_int_equal(se23_earth_gravity((se23_real_t)(90 * (PI / 180)), 0, &g), SE23_OK);
    /* Unknown frame. */
    se23_vec3_t v, v0;
    memset(&v, SENTINEL, sizeof v);
    v0 = v;
    assert_int_equal(se23_earth_rate((se23_frame_t)7, 0, &v), SE23_ERR_DOMAIN);
    assert_int_equal(se23_earth_gravity_vec((se23_frame_t)7, 0, 0, &v), SE23_ERR_DOMAIN);
    assert_memory_equal(&v, &v0, sizeof v);
}

static const se23_vec3_t g_ned = {{0, 0, SE23_R(9.81)}};
static const se23_vec3_t omega_big = {{SE23_R(0.03), SE23_R(-0.02), SE23_R(0.035)}};

static void test_earth_gamma_at_zero_time_is_identity(void **state)
{
    (void)state;
    se23_pose_t G;
    assert_int_equal(se23_earth_gamma(&g_ned, &omega_big, 0, &G), SE23_OK);
    const se23_real_t I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1}, z[3] = {0, 0, 0};
    assert_array_near(&G.R.m[0][0], I, 9, 0, 0);
    assert_array_near(G.v.v, z, 3, 0, 0);
    assert_array_near(G.p.v, z, 3, 0, 0);
}

static void test_earth_gamma_without_rotation_is_flat_gamma(void **state)
{
    (void)state;
    /* Paper eq. phi2:eq: Gamma_t = (I, g t, g t^2/2). */
    const se23_vec3_t zero = {{0, 0, 0}}, g = {{SE23_R(0.1), SE23_R(-0.2), SE23_R(9.8)}};
    const se23_real_t t = SE23_R(0.37);
    se23_pose_t G;
    assert_int_equal(se23_earth_gamma(&g, &zero, t, &G), SE23_OK);
    const se23_real_t I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    se23_real_t ev[3], ep[3];
    for (int i = 0; i < 3; ++i) {
        ev[i] = g.v[i] * t;
        ep[i] = SE23_R(0.5) * g.v[i] * t * t;
    }
    assert_array_near(&G.R.m[0][0], I, 9, 0, 0);
    assert_array_near(G.v.v, ev, 3, 0, 2 * SE23T_EPS);
    assert_array_near(G.p.v, ep, 3, 0, 4 * SE23T_EPS);
}

/* d/dt Gamma' by central differences in double. */
static void gamma_derivative(const se23_vec3_t *g, const se23_vec3_t *w, double t,
                             double dR[3][3], double dv[3], double dp[3])
{
    se23_pose_t Gp, Gm;
    assert_int_equal(se23_earth_gamma(g, w, (se23_real_t)(t + FD_STEP), &Gp), SE23_OK);
    assert_int_equal(se23_earth_gamma(g, w, (se23_real_t)(t - FD_STEP), &Gm), SE23_OK);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            dR[i][j] = ((double)Gp.R.m[i][j] - Gm.R.m[i][j]) / (2 * FD_STEP);
        }
        dv[i] = ((double)Gp.v.v[i] - Gm.v.v[i]) / (2 * FD_STEP);
        dp[i] = ((double)Gp.p.v[i] - Gm.p.v[i]) / (2 * FD_STEP);
    }
}

/* (Omega x y)_i in double. */
static double cross_i(const se23_vec3_t *w, const double y[3], int i)
{
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    return (double)w->v[j] * y[k] - (double)w->v[k] * y[j];
}

static void test_earth_gamma_solves_ode21_with_typos_fixed(void **state)
{
    (void)state;
    /* Paper eq. ODE21 as corrected in DESIGN.md section 3:
     *   d/dt G^R = -Omega^ G^R, d/dt G^v = g - Omega^ G^v,
     *   d/dt G^x = G^v - Omega^ G^x. */
    const double times[] = {0.5, 3.0, 20.0};
    for (int n = 0; n < 3; ++n) {
        double dR[3][3], dv[3], dp[3];
        gamma_derivative(&g_ned, &omega_big, times[n], dR, dv, dp);
        se23_pose_t G;
        assert_int_equal(se23_earth_gamma(&g_ned, &omega_big, (se23_real_t)times[n], &G), SE23_OK);
        double v[3], p[3];
        for (int i = 0; i < 3; ++i) {
            v[i] = G.v.v[i];
            p[i] = G.p.v[i];
        }
        for (int j = 0; j < 3; ++j) {
            double col[3] = {G.R.m[0][j], G.R.m[1][j], G.R.m[2][j]};
            for (int i = 0; i < 3; ++i) {
                assert_near(dR[i][j], -cross_i(&omega_big, col, i), FD_TOL, 0);
            }
        }
        for (int i = 0; i < 3; ++i) {
            assert_near(dv[i], (double)g_ned.v[i] - cross_i(&omega_big, v, i), 10 * FD_TOL, FD_TOL);
            assert_near(dp[i], v[i] - cross_i(&omega_big, p, i), 10 * FD_TOL, FD_TOL);
        }
    }
}

static void test_earth_gamma_rejects_bad_inputs(void **state)
{
    (void)state;
    se23_pose_t G, G0;
    memset(&G, SENTINEL, sizeof G);
    G0 = G;
    se23_vec3_t bad = g_ned;
    bad.v[1] = (se23_real_t)NAN;
    assert_int_equal(se23_earth_gamma(&bad, &omega_big, 1, &G), SE23_ERR_NONFINITE);
    assert_int_equal(se23_earth_gamma(&g_ned, &bad, 1, &G), SE23_ERR_NONFINITE);
    assert_int_equal(se23_earth_gamma(&g_ned, &omega_big, (se23_real_t)INFINITY, &G), SE23_ERR_NONFINITE);
    assert_int_equal(se23_earth_gamma(&g_ned, &omega_big, SE23_R(-1e-3), &G), SE23_ERR_DT);
    assert_memory_equal(&G, &G0, sizeof G);
}

static void test_earth_model_init_precomputes_gamma(void **state)
{
    (void)state;
    se23_earth_model_t m;
    assert_int_equal(se23_earth_model_init(&g_ned, &omega_big, SE23_R(0.01), SE23_R(0.05), &m), SE23_OK);
    se23_pose_t G;
    assert_int_equal(se23_earth_gamma(&g_ned, &omega_big, SE23_R(0.01), &G), SE23_OK);
    assert_memory_equal(&m.gamma, &G, sizeof G);
    assert_memory_equal(&m.g_n, &g_ned, sizeof g_ned);
    assert_memory_equal(&m.w_ie_n, &omega_big, sizeof omega_big);
    assert_true(m.dt == SE23_R(0.01) && m.dt_max == SE23_R(0.05));
    /* dt = dt_max = SE23_CFG_DT_MAX is accepted. */
    const se23_real_t dmax = SE23_R(SE23_CFG_DT_MAX);
    assert_int_equal(se23_earth_model_init(&g_ned, &omega_big, dmax, dmax, &m), SE23_OK);
}

static void test_earth_model_init_wgs84_matches_parts(void **state)
{
    (void)state;
    const se23_real_t lat = (se23_real_t)(PI / 4), h = SE23_R(120);
    se23_earth_model_t m, e;
    se23_vec3_t g, w;
    assert_int_equal(se23_earth_model_init_wgs84(SE23_FRAME_NED, lat, h, SE23_R(0.005), SE23_R(0.02), &m), SE23_OK);
    assert_int_equal(se23_earth_gravity_vec(SE23_FRAME_NED, lat, h, &g), SE23_OK);
    assert_int_equal(se23_earth_rate(SE23_FRAME_NED, lat, &w), SE23_OK);
    assert_int_equal(se23_earth_model_init(&g, &w, SE23_R(0.005), SE23_R(0.02), &e), SE23_OK);
    assert_memory_equal(&m, &e, sizeof m);
    /* Earth rate over one sample is a tiny rotation: Gamma^R = I - Omega^ dt. */
    assert_near(m.gamma.R.m[0][1], (double)w.v[2] * 0.005, 1e-20, 1e-6);
    memset(&m, SENTINEL, sizeof m);
    e = m;
    assert_int_equal(se23_earth_model_init_wgs84(SE23_FRAME_NED, SE23_R(2), h, SE23_R(0.005), SE23_R(0.02), &m), SE23_ERR_DOMAIN);
    assert_int_equal(se23_earth_model_init_wgs84(SE23_FRAME_ENU, lat, h, SE23_R(0.005), SE23_R(0.001), &m), SE23_ERR_DT);
    assert_memory_equal(&m, &e, sizeof m);
}

static void test_earth_model_init_rejects_bad_intervals(void **state)
{
    (void)state;
    struct {
        double dt, dt_max;
        se23_status_t st;
    } cases[] = {
        {0.0, 0.1, SE23_ERR_DT},         {-0.01, 0.1, SE23_ERR_DT},
        {0.2, 0.1, SE23_ERR_DT},         {0.01, SE23_CFG_DT_MAX * 1.01, SE23_ERR_DT},
        {NAN, 0.1, SE23_ERR_NONFINITE},  {0.01, INFINITY, SE23_ERR_NONFINITE},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        se23_earth_model_t m, m0;
        memset(&m, SENTINEL, sizeof m);
        m0 = m;
        assert_int_equal(se23_earth_model_init(&g_ned, &omega_big, (se23_real_t)cases[i].dt,
                                               (se23_real_t)cases[i].dt_max, &m),
                         cases[i].st);
        assert_memory_equal(&m, &m0, sizeof m);
    }
    se23_earth_model_t m, m0;
    memset(&m, SENTINEL, sizeof m);
    m0 = m;
    se23_vec3_t bad = omega_big;
    bad.v[2] = (se23_real_t)INFINITY;
    assert_int_equal(se23_earth_model_init(&g_ned, &bad, SE23_R(0.01), SE23_R(0.1), &m), SE23_ERR_NONFINITE);
    assert_memory_equal(&m, &m0, sizeof m);
}

static void test_earth_null_arguments_return_err_null(void **state)
{
    (void)state;
#if SE23_CFG_ARG_CHECKS
    se23_vec3_t v;
    se23_pose_t G;
    se23_earth_model_t m;
    assert_int_equal(se23_earth_gravity(0, 0, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_earth_gravity_vec(SE23_FRAME_NED, 0, 0, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_earth_rate(SE23_FRAME_NED, 0, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_earth_gamma(NULL, &v, 1, &G), SE23_ERR_NULL);
    assert_int_equal(se23_earth_gamma(&v, NULL, 1, &G), SE23_ERR_NULL);
    assert_int_equal(se23_earth_gamma(&g_ned, &g_ned, 1, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_earth_model_init(NULL, &v, SE23_R(0.1), 1, &m), SE23_ERR_NULL);
    assert_int_equal(se23_earth_model_init(&v, NULL, SE23_R(0.1), 1, &m), SE23_ERR_NULL);
    assert_int_equal(se23_earth_model_init(&g_ned, &g_ned, SE23_R(0.1), 1, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_earth_model_init_wgs84(SE23_FRAME_NED, 0, 0, SE23_R(0.1), 1, NULL), SE23_ERR_NULL);
#else
    skip();
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_earth_gravity_equator_and_pole_are_wgs84_values),
        cmocka_unit_test(test_earth_gravity_agrees_with_grs80_series),
        cmocka_unit_test(test_earth_gravity_height_gives_free_air_gradient),
        cmocka_unit_test(test_earth_gravity_vec_points_down),
        cmocka_unit_test(test_earth_rate_ned_and_enu_at_45_deg),
        cmocka_unit_test(test_earth_gravity_and_rate_reject_bad_inputs),
        cmocka_unit_test(test_earth_gamma_at_zero_time_is_identity),
        cmocka_unit_test(test_earth_gamma_without_rotation_is_flat_gamma),
        cmocka_unit_test(test_earth_gamma_solves_ode21_with_typos_fixed),
        cmocka_unit_test(test_earth_gamma_rejects_bad_inputs),
        cmocka_unit_test(test_earth_model_init_precomputes_gamma),
        cmocka_unit_test(test_earth_model_init_wgs84_matches_parts),
        cmocka_unit_test(test_earth_model_init_rejects_bad_intervals),
        cmocka_unit_test(test_earth_null_arguments_return_err_null),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
