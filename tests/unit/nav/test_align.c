/* Unit and statistical tests of src/nav/align.c: levelling recovers random
 * attitudes exactly from noise-free specific force (NED and ENU, pitch up to
 * +-90 deg); a Monte Carlo of noisy levelling gives the tilt std
 * sigma_f / (g sqrt N) about each horizontal axis and a NEES of the
 * body-frame error phi consistent with se23_align_cov (and shows the
 * neglected Euler-yaw coupling -tan(pitch) eps_a of align.h); the covariance
 * against a dense congruence; gyrocompassing recovers the heading exactly
 * without noise and, at a navigation-grade noise level, with the stated
 * sigma_yaw; the two frames agree; every status, nothing written on error. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "gauss_test.h"
#include "se23/align.h"
#include "se23/gauss.h"
#include "se23/so3.h"
#include "se23_test.h"

#define SENTINEL 0x5a
#define PI 3.14159265358979323846
#define WE 7.292115e-5
#define G0 9.80665

/* 99.9 % two-sided normal quantile. */
#define Z999 3.2905267314919255

typedef struct {
    double m[3][3];
} m3d_t;

/* R = Rz(yaw) Ry(pitch) Rx(roll), in double, from the elementary rotations. */
static m3d_t euler(double roll, double pitch, double yaw)
{
    const m3d_t X = {{{1, 0, 0}, {0, cos(roll), -sin(roll)}, {0, sin(roll), cos(roll)}}};
    const m3d_t Y = {{{cos(pitch), 0, sin(pitch)}, {0, 1, 0}, {-sin(pitch), 0, cos(pitch)}}};
    const m3d_t Z = {{{cos(yaw), -sin(yaw), 0}, {sin(yaw), cos(yaw), 0}, {0, 0, 1}}};
    m3d_t YX, R;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            YX.m[i][j] = 0;
            for (int k = 0; k < 3; ++k) YX.m[i][j] += Y.m[i][k] * X.m[k][j];
        }
    }
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            R.m[i][j] = 0;
            for (int k = 0; k < 3; ++k) R.m[i][j] += Z.m[i][k] * YX.m[k][j];
        }
    }
    return R;
}

/* out = R^T x */
static void tmul(const m3d_t *R, const double x[3], double out[3])
{
    for (int i = 0; i < 3; ++i) {
        out[i] = R->m[0][i] * x[0] + R->m[1][i] * x[1] + R->m[2][i] * x[2];
    }
}

static double wrap(double a)
{
    while (a > PI) a -= 2 * PI;
    while (a < -PI) a += 2 * PI;
    return a;
}

/* Gravity and Earth rate in the nav frame (earth.h). */
static void gravity_n(se23_frame_t frame, double g, double out[3])
{
    out[0] = 0;
    out[1] = 0;
    out[2] = frame == SE23_FRAME_NED ? g : -g;
}
static void rate_n(se23_frame_t frame, double lat, double out[3])
{
    if (frame == SE23_FRAME_NED) {
        out[0] = WE * cos(lat), out[1] = 0, out[2] = -WE * sin(lat);
    } else {
        out[0] = 0, out[1] = WE * cos(lat), out[2] = WE * sin(lat);
    }
}

/* f_b = R^T (-g_n) (+ noise). */
static se23_vec3_t specific_force(se23_frame_t frame, const m3d_t *R, double g)
{
    double gn[3], f[3];
    gravity_n(frame, g, gn);
    for (int i = 0; i < 3; ++i) gn[i] = -gn[i];
    tmul(R, gn, f);
    se23_vec3_t out = {{(se23_real_t)f[0], (se23_real_t)f[1], (se23_real_t)f[2]}};
    return out;
}
static se23_vec3_t earth_rate_b(se23_frame_t frame, const m3d_t *R, double lat)
{
    double wn[3], w[3];
    rate_n(frame, lat, wn);
    tmul(R, wn, w);
    se23_vec3_t out = {{(se23_real_t)w[0], (se23_real_t)w[1], (se23_real_t)w[2]}};
    return out;
}
static void add_noise(se23t_rng_t *rng, double sd, se23_vec3_t *x)
{
    for (int i = 0; i < 3; ++i) x->v[i] = (se23_real_t)((double)x->v[i] + sd * se23t_normal(rng));
}

static double max_diff(const se23_mat3_t *A, const m3d_t *B)
{
    double d = 0;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) d = fmax(d, fabs((double)A->m[i][j] - B->m[i][j]));
    }
    return d;
}

/* eps = vee of the skew part of R_true Rbar^T (the nav-frame error,
 * R_true = exp(eps^) Rbar, to third order) and phi = Rbar^T eps. */
static void errors(const m3d_t *Rt, const se23_mat3_t *Rb, double eps[3], double phi[3])
{
    double M[3][3];
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            M[i][j] = 0;
            for (int k = 0; k < 3; ++k) M[i][j] += Rt->m[i][k] * (double)Rb->m[j][k];
        }
    }
    eps[0] = 0.5 * (M[2][1] - M[1][2]);
    eps[1] = 0.5 * (M[0][2] - M[2][0]);
    eps[2] = 0.5 * (M[1][0] - M[0][1]);
    for (int i = 0; i < 3; ++i) {
        phi[i] = (double)Rb->m[0][i] * eps[0] + (double)Rb->m[1][i] * eps[1] +
                 (double)Rb->m[2][i] * eps[2];
    }
}

/* phi^T P^-1 phi with P from se23_align_cov. */
static double nees3(const se23_mat3_t *P, const double phi[3])
{
    double A[9], L[9];
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) A[3 * i + j] = P->m[i][j];
    }
    assert_true(gt_chol(A, 3, L));
    return gt_nees(L, 3, phi);
}

static void mean_interval(int dof, int runs, double *lo, double *hi)
{
    const double k = (double)dof * runs;
    const double a = 1.0 - 2.0 / (9.0 * k), b = sqrt(2.0 / (9.0 * k));
    *lo = k * pow(a - Z999 * b, 3) / runs;
    *hi = k * pow(a + Z999 * b, 3) / runs;
}

/* ------------------------------------------------------------ levelling */

static void test_align_level_recovers_attitude_without_noise(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 9201);
    double worst = 0;
    for (int rep = 0; rep < 2000; ++rep) {
        const se23_frame_t frame = (rep % 2) ? SE23_FRAME_ENU : SE23_FRAME_NED;
        const double roll = se23t_uniform(&rng, -PI, PI);
        const double pitch = se23t_uniform(&rng, -1.5, 1.5);
        const double yaw = se23t_uniform(&rng, -4, 4);
        const double g = se23t_uniform(&rng, 0.51 * G0, 1.49 * G0);
        const m3d_t Rt = euler(roll, pitch, yaw);
        const se23_vec3_t f = specific_force(frame, &Rt, g);
        se23_mat3_t R;
        assert_int_equal(se23_align_level(frame, &f, (se23_real_t)yaw, &R), SE23_OK);
        assert_int_equal(se23_so3_check(&R), SE23_OK);
        /* Roll is conditioned by 1 / cos(pitch). */
        const double err = max_diff(&R, &Rt) * cos(pitch) / SE23T_EPS;
        worst = fmax(worst, err);
        assert_true(err < 16);
    }
    print_message("level, noise-free: worst |R - R_true| %.1f eps / cos(pitch)\n", worst);
}

static void test_align_level_handles_vertical_body_x(void **state)
{
    (void)state;
#if SE23_CFG_DOUBLE
    const double tiny[] = {0, 1e-300, 1e-160, 1e-20, 1e-8};
#else
    const double tiny[] = {0, 1e-44, 1e-30, 1e-19, 1e-4};
#endif
    for (size_t i = 0; i < sizeof tiny / sizeof tiny[0]; ++i) {
        for (int sx = -1; sx <= 1; sx += 2) {
            for (int frame = 0; frame < 2; ++frame) {
                const se23_vec3_t f = {{(se23_real_t)(sx * G0), (se23_real_t)tiny[i],
                                        (se23_real_t)(-0.5 * tiny[i])}};
                se23_mat3_t R;
                assert_int_equal(se23_align_level((se23_frame_t)frame, &f, SE23_R(0.3), &R),
                                 SE23_OK);
                assert_int_equal(se23_so3_check(&R), SE23_OK);
                /* Third row = R^T e_z = s f / |f|. */
                const double s = frame == SE23_FRAME_NED ? -1 : 1;
                const double nf = sqrt((double)f.v[0] * f.v[0] + (double)f.v[1] * f.v[1] +
                                       (double)f.v[2] * f.v[2]);
                for (int j = 0; j < 3; ++j) {
                    assert_near(R.m[2][j], s * f.v[j] / nf, 4 * SE23T_EPS, 0);
                }
                if (tiny[i] == 0) {
                    /* Body x vertical, roll 0: yaw turns body y about it,
                     * R e_y = (-sin yaw, cos yaw, 0). */
                    assert_near(R.m[0][1], -sin(0.3), 4 * SE23T_EPS, 0);
                    assert_near(R.m[1][1], cos(0.3), 4 * SE23T_EPS, 0);
                }
            }
        }
    }
}

static void test_align_level_rejects_bad_input_untouched(void **state)
{
    (void)state;
    const se23_vec3_t ok = {{0, 0, (se23_real_t)-G0}};
    const struct {
        int frame;
        se23_vec3_t f;
        double yaw;
        se23_status_t st;
    } cases[] = {
        {0, {{NAN, 0, -9.8f}}, 0, SE23_ERR_NONFINITE},
        {1, {{0, INFINITY, -9.8f}}, 0, SE23_ERR_NONFINITE},
        {0, {{0, 0, -9.8f}}, NAN, SE23_ERR_NONFINITE},
        {1, {{0, 0, -9.8f}}, -INFINITY, SE23_ERR_NONFINITE},
        {2, {{0, 0, -9.8f}}, 0, SE23_ERR_DOMAIN},
        {-1, {{0, 0, -9.8f}}, 0, SE23_ERR_DOMAIN},
        {0, {{0, 0, (se23_real_t)(-0.499 * G0)}}, 0, SE23_ERR_DOMAIN},
        {1, {{(se23_real_t)(1.501 * G0), 0, 0}}, 0, SE23_ERR_DOMAIN},
        {0, {{0, 0, 0}}, 0, SE23_ERR_DOMAIN},
        {0, {{(se23_real_t)1e30, 0, 0}}, 0, SE23_ERR_DOMAIN},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        se23_mat3_t R, ref;
        memset(&R, SENTINEL, sizeof R);
        ref = R;
        assert_int_equal(se23_align_level((se23_frame_t)cases[i].frame, &cases[i].f,
                                          (se23_real_t)cases[i].yaw, &R),
                         cases[i].st);
        assert_memory_equal(&R, &ref, sizeof R);
    }
    /* The band edges are accepted. */
    se23_mat3_t R;
    const se23_vec3_t lo = {{0, 0, (se23_real_t)(-0.501 * G0)}};
    const se23_vec3_t hi = {{0, (se23_real_t)(1.499 * G0), 0}};
    assert_int_equal(se23_align_level(SE23_FRAME_NED, &lo, 0, &R), SE23_OK);
    assert_int_equal(se23_align_level(SE23_FRAME_ENU, &hi, 0, &R), SE23_OK);
    assert_int_equal(se23_align_level(SE23_FRAME_NED, NULL, 0, &R), SE23_ERR_NULL);
    assert_int_equal(se23_align_level(SE23_FRAME_NED, &ok, 0, NULL), SE23_ERR_NULL);
}

/* ------------------------------------------------------------ covariance */

static void test_align_cov_matches_dense_congruence(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 9202);
    for (int rep = 0; rep < 500; ++rep) {
        se23_vec3_t phi;
        se23_mat3_t R, P;
        se23t_random_axis_angle(&rng, se23t_uniform(&rng, 0, PI), &phi);
        assert_int_equal(se23_so3_exp(&phi, &R), SE23_OK);
        const double sf = se23t_uniform(&rng, 1e-4, 0.5);
        const double g = se23t_uniform(&rng, 9.7, 9.9);
        const int n = 1 + rep * 7;
        const double sy = exp(se23t_uniform(&rng, log(1e-4), log(1.0)));
        assert_int_equal(se23_align_cov(&R, (se23_real_t)sf, n, (se23_real_t)g,
                                        (se23_real_t)sy, &P),
                         SE23_OK);
        /* R^T diag(t2, t2, y2) R, dense, with the rounded R and inputs. */
        const double t = (double)(se23_real_t)sf / (double)(se23_real_t)g;
        const double d[3] = {t * t / n, t * t / n, (double)(se23_real_t)sy * (se23_real_t)sy};
        const double scale = fmax(d[0], d[2]);
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                double e = 0;
                for (int k = 0; k < 3; ++k) e += (double)R.m[k][i] * d[k] * R.m[k][j];
                assert_near(P.m[i][j], e, 16 * SE23T_EPS * scale, 0);
                assert_true(P.m[i][j] == P.m[j][i]);
            }
        }
    }
    /* R = I: diag(tilt^2, tilt^2, sigma_yaw^2). */
    se23_mat3_t I = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, P;
    assert_int_equal(se23_align_cov(&I, SE23_R(0.02), 100, SE23_R(10), SE23_R(0.1), &P),
                     SE23_OK);
    assert_near(P.m[0][0], 4e-8, 0, 8 * SE23T_EPS);
    assert_near(P.m[1][1], 4e-8, 0, 8 * SE23T_EPS);
    assert_near(P.m[2][2], 1e-2, 0, 8 * SE23T_EPS);
    assert_true(P.m[0][1] == 0 && P.m[0][2] == 0 && P.m[1][2] == 0);
}

/* Regression (fuzz_align): an R that is a rotation only to
 * SE23_CFG_ROT_TOL (its third row r a little longer than 1) and a heading
 * std far below the tilt's gave P = t2 I + (y2 - t2) r r^T a variance
 * y2 + (y2 - t2)(|r|^2 - 1) < 0 along r, so se23_gauss_check refused the
 * SE23_OK output. With r r^T / |r|^2 the variance along r is y2. */
static void test_align_cov_psd_at_the_rotation_tolerance(void **state)
{
    (void)state;
    const double a = 1.0 / sqrt(2.0), b = 1.0 / sqrt(6.0), c = 1.0 / sqrt(3.0);
    const double k = 1.0 + 0.9 * SE23_CFG_ROT_TOL; /* |r|^2 = 1 + 1.8 tol */
    const se23_mat3_t R = {{{(se23_real_t)a, (se23_real_t)-a, 0},
                            {(se23_real_t)b, (se23_real_t)b, (se23_real_t)(-2.0 * b)},
                            {(se23_real_t)(k * c), (se23_real_t)(k * c), (se23_real_t)(k * c)}}};
    se23_mat3_t P;
    se23_gauss_t g;
    assert_int_equal(se23_so3_check(&R), SE23_OK);
    /* tilt^2 = 1, sigma_yaw^2 = 1e-12 */
    assert_int_equal(se23_align_cov(&R, SE23_R(1), 1, SE23_R(1), (se23_real_t)1e-6, &P), SE23_OK);
    memset(&g, 0, sizeof g);
    g.n = 9;
    for (int i = 0; i < 3; ++i) {
        g.T.R.m[i][i] = SE23_R(1);
        for (int j = 0; j < 3; ++j) {
            g.P.m[15 * i + j] = P.m[i][j];
        }
    }
    assert_int_equal(se23_gauss_check(&g), SE23_OK);
    /* the variance along r is sigma_yaw^2, to rounding of tilt^2 */
    double q = 0;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            q += c * (double)P.m[i][j] * c;
        }
    }
    assert_near(q, 1e-12, 8 * SE23T_EPS, 0);
}

/* Regression (fuzz_align, both precisions): a vertical third row a few
 * epsilons short of unit length and a tilt variance beyond y2 / eps gave
 * the variance along r as t2 + (y2 - t2) r_z^2 / |r|^2, which rounded to
 * about -eps t2: a negative variance, refused by se23_gauss_check. Formed
 * as (t2 (r_x^2 + r_y^2) + y2 r_z^2) / |r|^2 it is y2. */
static void test_align_cov_no_negative_variance_for_a_vast_tilt(void **state)
{
    (void)state;
    const double ca = cos(0.9), sa = sin(0.9);
    const se23_mat3_t R = {{{(se23_real_t)ca, (se23_real_t)-sa, 0},
                            {(se23_real_t)sa, (se23_real_t)ca, 0},
                            {0, 0, (se23_real_t)(1.0 - 2.0 * SE23T_EPS)}}};
    se23_mat3_t P;
    se23_gauss_t g;
    assert_int_equal(se23_so3_check(&R), SE23_OK);
    /* tilt^2 = 1e20 rad^2 (sigma_f / g = 1e10), sigma_yaw^2 = 1e-4 */
    assert_int_equal(se23_align_cov(&R, (se23_real_t)1e10, 1, SE23_R(1), (se23_real_t)1e-2, &P),
                     SE23_OK);
    for (int i = 0; i < 3; ++i) {
        assert_true(P.m[i][i] >= 0);
    }
    assert_near(P.m[2][2], 1e-4, 0, 8 * SE23T_EPS);
    memset(&g, 0, sizeof g);
    g.n = 9;
    for (int i = 0; i < 3; ++i) {
        g.T.R.m[i][i] = SE23_R(1);
        for (int j = 0; j < 3; ++j) {
            g.P.m[15 * i + j] = P.m[i][j];
        }
    }
    assert_int_equal(se23_gauss_check(&g), SE23_OK);
}

static void test_align_cov_rejects_bad_input_untouched(void **state)
{
    (void)state;
#if SE23_CFG_DOUBLE
    const double huge = 1e200;
#else
    const double huge = 1e30;
#endif
    const se23_mat3_t I = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    se23_mat3_t nanR = I, bigR = I;
    nanR.m[1][2] = NAN;
    for (int i = 0; i < 3; ++i) bigR.m[i][i] = SE23_R(1.01);
    const struct {
        const se23_mat3_t *R;
        double sf;
        int n;
        double g, sy;
        se23_status_t st;
    } cases[] = {
        {&nanR, 0.01, 10, 9.8, 0.1, SE23_ERR_NONFINITE},
        {&I, NAN, 10, 9.8, 0.1, SE23_ERR_NONFINITE},
        {&I, 0.01, 10, INFINITY, 0.1, SE23_ERR_NONFINITE},
        {&I, 0.01, 10, 9.8, -INFINITY, SE23_ERR_NONFINITE},
        {&I, 0.01, 0, 9.8, 0.1, SE23_ERR_DIM},
        {&I, 0.01, -5, 9.8, 0.1, SE23_ERR_DIM},
        {&I, 0, 10, 9.8, 0.1, SE23_ERR_DOMAIN},
        {&I, -0.01, 10, 9.8, 0.1, SE23_ERR_DOMAIN},
        {&I, 0.01, 10, 0, 0.1, SE23_ERR_DOMAIN},
        {&I, 0.01, 10, 9.8, 0, SE23_ERR_DOMAIN},
        {&bigR, 0.01, 10, 9.8, 0.1, SE23_ERR_NOT_ROTATION},
        {&I, huge, 1, 1e-10, 0.1, SE23_ERR_NONFINITE},
        {&I, 0.01, 1, 9.8, huge, SE23_ERR_NONFINITE},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        se23_mat3_t P, ref;
        memset(&P, SENTINEL, sizeof P);
        ref = P;
        assert_int_equal(se23_align_cov(cases[i].R, (se23_real_t)cases[i].sf, cases[i].n,
                                        (se23_real_t)cases[i].g, (se23_real_t)cases[i].sy, &P),
                         cases[i].st);
        assert_memory_equal(&P, &ref, sizeof P);
    }
    se23_mat3_t P;
    assert_int_equal(se23_align_cov(NULL, SE23_R(0.1), 1, SE23_R(9.8), SE23_R(0.1), &P),
                     SE23_ERR_NULL);
    assert_int_equal(se23_align_cov(&I, SE23_R(0.1), 1, SE23_R(9.8), SE23_R(0.1), NULL),
                     SE23_ERR_NULL);
}

/* Noisy levelling: 2000 trials, random attitudes (|pitch| < 1 rad), a
 * yaw with noise sigma_yaw >> tilt, the mean of N samples of accelerometer
 * noise sigma_f. */
static void test_align_level_monte_carlo_matches_tilt_std_and_cov(void **state)
{
    (void)state;
    enum { TRIALS = 2000, N = 100 };
    const double sf = 0.05, g = 9.81, sy = 0.02;
    const double tilt = sf / (g * sqrt((double)N));
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 9203);
    double s2[3] = {0, 0, 0}, sxy = 0, nees = 0;
    for (int rep = 0; rep < TRIALS; ++rep) {
        const se23_frame_t frame = (rep % 2) ? SE23_FRAME_ENU : SE23_FRAME_NED;
        const double yaw = se23t_uniform(&rng, -PI, PI);
        const m3d_t Rt = euler(se23t_uniform(&rng, -PI, PI), se23t_uniform(&rng, -1, 1), yaw);
        se23_vec3_t f = specific_force(frame, &Rt, g);
        add_noise(&rng, sf / sqrt((double)N), &f);
        se23_mat3_t R, P;
        const double yaw_est = yaw + sy * se23t_normal(&rng);
        assert_int_equal(se23_align_level(frame, &f, (se23_real_t)yaw_est, &R), SE23_OK);
        assert_int_equal(se23_align_cov(&R, (se23_real_t)sf, N, (se23_real_t)g,
                                        (se23_real_t)sy, &P),
                         SE23_OK);
        double eps[3], phi[3];
        errors(&Rt, &R, eps, phi);
        for (int i = 0; i < 3; ++i) s2[i] += eps[i] * eps[i] / TRIALS;
        sxy += eps[0] * eps[1] / TRIALS;
        nees += nees3(&P, phi) / TRIALS;
    }
    double lo, hi;
    mean_interval(3, TRIALS, &lo, &hi);
    print_message("level, %d trials: tilt std %.4g %.4g (formula %.4g), yaw %.4g (%.4g), "
                  "corr %.3f, mean NEES %.3f in [%.3f, %.3f]\n",
                  TRIALS, sqrt(s2[0]), sqrt(s2[1]), tilt, sqrt(s2[2]), sy,
                  sxy / sqrt(s2[0] * s2[1]), nees, lo, hi);
    for (int i = 0; i < 2; ++i) assert_near(sqrt(s2[i]), tilt, 0, 0.10);
    assert_near(sqrt(s2[2]), sy, 0, 0.10);
    assert_true(fabs(sxy / sqrt(s2[0] * s2[1])) < 0.1);
    assert_true(nees > lo && nees < hi);
}

/* The coupling align.h neglects: with the Euler yaw exact, a tilt error
 * also turns R about the vertical by -tan(pitch) eps_a, eps_a the tilt about
 * a = Rz(yaw) e_x. At pitch 60 deg it is as large as the tilt itself. */
static void test_align_level_euler_yaw_couples_tilt_into_vertical(void **state)
{
    (void)state;
    enum { TRIALS = 2000, N = 100 };
    const double sf = 0.05, g = 9.81, pitch = PI / 3;
    const double tilt = sf / (g * sqrt((double)N));
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 9204);
    double s2z = 0, worst = 0;
    for (int rep = 0; rep < TRIALS; ++rep) {
        const se23_frame_t frame = (rep % 2) ? SE23_FRAME_ENU : SE23_FRAME_NED;
        const double yaw = se23t_uniform(&rng, -PI, PI);
        const m3d_t Rt = euler(se23t_uniform(&rng, -PI, PI), pitch, yaw);
        se23_vec3_t f = specific_force(frame, &Rt, g);
        add_noise(&rng, sf / sqrt((double)N), &f);
        se23_mat3_t R;
        assert_int_equal(se23_align_level(frame, &f, (se23_real_t)yaw, &R), SE23_OK);
        double eps[3], phi[3];
        errors(&Rt, &R, eps, phi);
        const double ea = cos(yaw) * eps[0] + sin(yaw) * eps[1];
        worst = fmax(worst, fabs(eps[2] + tan(pitch) * ea));
        s2z += eps[2] * eps[2] / TRIALS;
    }
    print_message("level at pitch 60 deg, yaw exact: vertical std %.4g (tilt tan(pitch) "
                  "%.4g), worst |eps_z + tan(pitch) eps_a| %.2g\n",
                  sqrt(s2z), tilt * tan(pitch), worst);
    assert_near(sqrt(s2z), tilt * tan(pitch), 0, 0.10);
    assert_true(worst < 0.02 * tilt);
}

/* ------------------------------------------------------------ gyrocompass */

static void test_align_gyrocompass_recovers_heading_without_noise(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 9205);
    double worst = 0;
    for (int rep = 0; rep < 2000; ++rep) {
        const se23_frame_t frame = (rep % 2) ? SE23_FRAME_ENU : SE23_FRAME_NED;
        const double pitch = se23t_uniform(&rng, -1.3, 1.3);
        const double yaw = se23t_uniform(&rng, -PI, PI);
        const double lat = se23t_uniform(&rng, -1.3, 1.3);
        const m3d_t Rt = euler(se23t_uniform(&rng, -PI, PI), pitch, yaw);
        const se23_vec3_t f = specific_force(frame, &Rt, 9.81);
        const se23_vec3_t w = earth_rate_b(frame, &Rt, lat);
        se23_mat3_t R;
        se23_real_t y, sy;
        assert_int_equal(se23_align_gyrocompass(frame, (se23_real_t)lat, &f, &w,
                                                SE23_R(1e-6), 100, &R, &y, &sy),
                         SE23_OK);
        assert_int_equal(se23_so3_check(&R), SE23_OK);
        const double err = max_diff(&R, &Rt) * cos(pitch) * cos(lat) / SE23T_EPS;
        worst = fmax(worst, err);
        assert_true(err < 64);
        assert_near(wrap((double)y - yaw), 0, 64 * SE23T_EPS / cos(lat), 0);
        assert_near(sy, 1e-6 / (10 * WE * cos(lat)), 0, 32 * SE23T_EPS);
    }
    print_message("gyrocompass, noise-free: worst |R - R_true| %.1f eps / (cos(pitch) "
                  "cos(lat))\n", worst);
}

/* Navigation grade at 100 Hz: ARW 0.002 deg/sqrt(h) (5.8e-6 rad/s per
 * sample), VRW 50 ug/sqrt(Hz) (4.9e-3 m/s^2 per sample), 60 s averaged. */
static void test_align_gyrocompass_monte_carlo_nav_grade(void **state)
{
    (void)state;
    enum { TRIALS = 2000, N = 6000 };
    const double sw = 0.002 * PI / 180 / 60 * 10, sf = 50e-6 * 9.81 * 10, g = 9.81;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 9206);
    for (int k = 0; k < 2; ++k) {
        const double lat = k == 0 ? PI / 4 : -1.2;
        double s1 = 0, s2 = 0, nees = 0, sy_ret = 0;
        for (int rep = 0; rep < TRIALS; ++rep) {
            const se23_frame_t frame = (rep % 2) ? SE23_FRAME_ENU : SE23_FRAME_NED;
            const double yaw = se23t_uniform(&rng, -PI, PI);
            const m3d_t Rt = euler(se23t_uniform(&rng, -0.3, 0.3), se23t_uniform(&rng, -0.3, 0.3),
                                   yaw);
            se23_vec3_t f = specific_force(frame, &Rt, g);
            se23_vec3_t w = earth_rate_b(frame, &Rt, lat);
            add_noise(&rng, sf / sqrt((double)N), &f);
            add_noise(&rng, sw / sqrt((double)N), &w);
            se23_mat3_t R, P;
            se23_real_t y, sy;
            assert_int_equal(se23_align_gyrocompass(frame, (se23_real_t)lat, &f, &w,
                                                    (se23_real_t)sw, N, &R, &y, &sy),
                             SE23_OK);
            assert_int_equal(se23_align_cov(&R, (se23_real_t)sf, N, (se23_real_t)g, sy, &P),
                             SE23_OK);
            const double e = wrap((double)y - yaw);
            s1 += e / TRIALS;
            s2 += e * e / TRIALS;
            sy_ret = sy;
            double eps[3], phi[3];
            errors(&Rt, &R, eps, phi);
            nees += nees3(&P, phi) / TRIALS;
        }
        const double formula = sw / (sqrt((double)N) * WE * cos(lat));
        double lo, hi;
        mean_interval(3, TRIALS, &lo, &hi);
        print_message("gyrocompass, lat %.1f deg, %d trials: yaw error mean %.3g, std %.4g "
                      "rad (sigma_yaw %.4g, formula %.4g), mean NEES %.3f in [%.3f, %.3f]\n",
                      lat * 180 / PI, TRIALS, s1, sqrt(s2), (double)sy_ret, formula, nees, lo,
                      hi);
        assert_near(sy_ret, formula, 0, 1e-5);
        assert_near(sqrt(s2), formula, 0, 0.10);
        assert_true(fabs(s1) < Z999 * formula / sqrt((double)TRIALS));
        assert_true(nees > lo && nees < hi);
    }
}

/* The same physical attitude in NED and ENU: R_enu = C R_ned with
 * C = [[0,1,0],[1,0,0],[0,0,-1]], and yaw_enu = pi/2 - yaw_ned. */
static void test_align_frames_agree(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 9207);
    for (int rep = 0; rep < 200; ++rep) {
        const m3d_t Rn = euler(se23t_uniform(&rng, -1, 1), se23t_uniform(&rng, -1, 1),
                               se23t_uniform(&rng, -PI, PI));
        m3d_t Re;
        for (int j = 0; j < 3; ++j) {
            Re.m[0][j] = Rn.m[1][j];
            Re.m[1][j] = Rn.m[0][j];
            Re.m[2][j] = -Rn.m[2][j];
        }
        const double lat = se23t_uniform(&rng, -1, 1);
        const se23_vec3_t fn = specific_force(SE23_FRAME_NED, &Rn, 9.81);
        const se23_vec3_t fe = specific_force(SE23_FRAME_ENU, &Re, 9.81);
        const se23_vec3_t wn = earth_rate_b(SE23_FRAME_NED, &Rn, lat);
        const se23_vec3_t we = earth_rate_b(SE23_FRAME_ENU, &Re, lat);
        assert_array_near(fn.v, fe.v, 3, 8 * SE23T_EPS * 9.81, 0);
        assert_array_near(wn.v, we.v, 3, 8 * SE23T_EPS * WE, 0);
        se23_mat3_t A, B;
        se23_real_t ya, yb, sa, sb;
        assert_int_equal(se23_align_gyrocompass(SE23_FRAME_NED, (se23_real_t)lat, &fn, &wn,
                                                SE23_R(1e-6), 1000, &A, &ya, &sa),
                         SE23_OK);
        assert_int_equal(se23_align_gyrocompass(SE23_FRAME_ENU, (se23_real_t)lat, &fn, &wn,
                                                SE23_R(1e-6), 1000, &B, &yb, &sb),
                         SE23_OK);
        for (int j = 0; j < 3; ++j) {
            assert_near(B.m[0][j], A.m[1][j], 64 * SE23T_EPS, 0);
            assert_near(B.m[1][j], A.m[0][j], 64 * SE23T_EPS, 0);
            assert_near(B.m[2][j], -A.m[2][j], 64 * SE23T_EPS, 0);
        }
        assert_near(wrap((double)yb - (PI / 2 - (double)ya)), 0, 64 * SE23T_EPS, 0);
        assert_true(sa == sb);
        /* Levelling with the corresponding yaws gives the same pair. */
        assert_int_equal(se23_align_level(SE23_FRAME_NED, &fn, ya, &A), SE23_OK);
        assert_int_equal(se23_align_level(SE23_FRAME_ENU, &fn, yb, &B), SE23_OK);
        for (int j = 0; j < 3; ++j) {
            assert_near(B.m[0][j], A.m[1][j], 64 * SE23T_EPS, 0);
            assert_near(B.m[2][j], -A.m[2][j], 64 * SE23T_EPS, 0);
        }
    }
}

static void test_align_gyrocompass_rejects_bad_input_untouched(void **state)
{
    (void)state;
    const m3d_t Rt = euler(0.1, -0.2, 0.7);
    const double lat = 0.8, sw = 5.8e-6;
    const se23_vec3_t f = specific_force(SE23_FRAME_NED, &Rt, 9.81);
    const se23_vec3_t w = earth_rate_b(SE23_FRAME_NED, &Rt, lat);
    const se23_vec3_t fnan = {{f.v[0], NAN, f.v[2]}};
    const se23_vec3_t winf = {{w.v[0], w.v[1], INFINITY}};
    const se23_vec3_t flow = {{0, 0, (se23_real_t)(-0.45 * G0)}};
    const se23_vec3_t zero = {{0, 0, 0}};
    se23_vec3_t w10 = w, wturn = w;
    for (int i = 0; i < 3; ++i) {
        w10.v[i] *= 10; /* a bias of 10 Earth rates, or a turning vehicle */
        wturn.v[i] += (se23_real_t)(i == 0 ? 1e-3 : 0);
    }
    const struct {
        int frame;
        double lat;
        const se23_vec3_t *f, *w;
        double sw;
        int n;
        se23_status_t st;
    } cases[] = {
        {0, NAN, &f, &w, sw, 100, SE23_ERR_NONFINITE},
        {0, lat, &fnan, &w, sw, 100, SE23_ERR_NONFINITE},
        {0, lat, &f, &winf, sw, 100, SE23_ERR_NONFINITE},
        {0, lat, &f, &w, INFINITY, 100, SE23_ERR_NONFINITE},
        {0, lat, &f, &w, sw, 0, SE23_ERR_DIM},
        {2, lat, &f, &w, sw, 100, SE23_ERR_DOMAIN},
        {0, lat, &f, &w, 0, 100, SE23_ERR_DOMAIN},
        {0, lat, &f, &w, -sw, 100, SE23_ERR_DOMAIN},
        {0, PI / 2 + 1e-3, &f, &w, sw, 100, SE23_ERR_DOMAIN},
        {0, lat, &flow, &w, sw, 100, SE23_ERR_DOMAIN},
        /* sigma_yaw too large: the poles, a MEMS gyro, too few samples. */
        {0, PI / 2, &f, &w, sw, 100, SE23_ERR_DOMAIN},
        {1, -89.9 * PI / 180, &f, &w, sw, 100, SE23_ERR_DOMAIN},
        {0, lat, &f, &w, 1e-2, 100, SE23_ERR_DOMAIN},
        {0, lat, &f, &w, sw, 1, SE23_ERR_DOMAIN},
        /* The reading is not the Earth rate. */
        {0, lat, &f, &zero, sw, 100, SE23_ERR_DOMAIN},
        {0, lat, &f, &w10, sw, 100, SE23_ERR_DOMAIN},
        {0, lat, &f, &wturn, sw, 100, SE23_ERR_DOMAIN},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        se23_mat3_t R, R0;
        se23_real_t y, sy, y0, sy0;
        memset(&R, SENTINEL, sizeof R);
        memset(&y, SENTINEL, sizeof y);
        memset(&sy, SENTINEL, sizeof sy);
        R0 = R, y0 = y, sy0 = sy;
        assert_int_equal(se23_align_gyrocompass((se23_frame_t)cases[i].frame,
                                                (se23_real_t)cases[i].lat, cases[i].f, cases[i].w,
                                                (se23_real_t)cases[i].sw, cases[i].n, &R, &y, &sy),
                         cases[i].st);
        assert_memory_equal(&R, &R0, sizeof R);
        assert_memory_equal(&y, &y0, sizeof y);
        assert_memory_equal(&sy, &sy0, sizeof sy);
    }
    /* The bound itself: sigma_yaw just below SE23_ALIGN_YAW_STD_MAX is accepted. */
    se23_mat3_t R;
    se23_real_t y, sy;
    const double n1 = sw / (0.099 * WE * cos(lat));
    assert_int_equal(se23_align_gyrocompass(SE23_FRAME_NED, (se23_real_t)lat, &f, &w,
                                            (se23_real_t)sw, (int)ceil(n1 * n1), &R, &y, &sy),
                     SE23_OK);
    assert_true(sy < SE23_R(SE23_ALIGN_YAW_STD_MAX));
    assert_int_equal(se23_align_gyrocompass(SE23_FRAME_NED, SE23_R(0.8), NULL, &w, SE23_R(1e-6),
                                            1, &R, &y, &sy),
                     SE23_ERR_NULL);
    assert_int_equal(se23_align_gyrocompass(SE23_FRAME_NED, SE23_R(0.8), &f, NULL, SE23_R(1e-6),
                                            1, &R, &y, &sy),
                     SE23_ERR_NULL);
    assert_int_equal(se23_align_gyrocompass(SE23_FRAME_NED, SE23_R(0.8), &f, &w, SE23_R(1e-6), 1,
                                            NULL, &y, &sy),
                     SE23_ERR_NULL);
    assert_int_equal(se23_align_gyrocompass(SE23_FRAME_NED, SE23_R(0.8), &f, &w, SE23_R(1e-6), 1,
                                            &R, NULL, &sy),
                     SE23_ERR_NULL);
    assert_int_equal(se23_align_gyrocompass(SE23_FRAME_NED, SE23_R(0.8), &f, &w, SE23_R(1e-6), 1,
                                            &R, &y, NULL),
                     SE23_ERR_NULL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_align_level_recovers_attitude_without_noise),
        cmocka_unit_test(test_align_level_handles_vertical_body_x),
        cmocka_unit_test(test_align_level_rejects_bad_input_untouched),
        cmocka_unit_test(test_align_cov_matches_dense_congruence),
        cmocka_unit_test(test_align_cov_psd_at_the_rotation_tolerance),
        cmocka_unit_test(test_align_cov_rejects_bad_input_untouched),
        cmocka_unit_test(test_align_level_monte_carlo_matches_tilt_std_and_cov),
        cmocka_unit_test(test_align_level_euler_yaw_couples_tilt_into_vertical),
        cmocka_unit_test(test_align_gyrocompass_recovers_heading_without_noise),
        cmocka_unit_test(test_align_gyrocompass_monte_carlo_nav_grade),
        cmocka_unit_test(test_align_frames_agree),
        cmocka_unit_test(test_align_cov_no_negative_variance_for_a_vast_tilt),
        cmocka_unit_test(test_align_gyrocompass_rejects_bad_input_untouched),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
