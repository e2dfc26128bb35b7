/* Unit and property tests of src/imu/imu.c: the exact increment, Forster et
 * al.'s and the paper's first-order increments, the propagation step on
 * flat and rotating Earth, the carried-state conversions, and every
 * bad-input path. The long comparisons against an RK4 integration of the
 * continuous equations are in tests/reference/crosscheck_nav.cpp. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "se23/imu.h"
#include "se23/se23.h"
#include "cov/cov_step.h"
#include "imu/imu_step.h"
#include "se23/so3.h"
#include "se23_test.h"

#define PI 3.14159265358979323846

/* A few operations away from exact, O(1) quantities. */
#define TOL (64.0 * SE23T_EPS)
#if SE23_CFG_DOUBLE
#define FD_STEP 1e-5
#define FD_TOL 1e-8
#else
#define FD_STEP 1e-2
#define FD_TOL 3e-3
#endif

#define SENTINEL 0x5a

static const double edge_angles[] = {0.0, 1e-38, 1e-8, 1e-5, 1e-3, 0.1, 1.0, 3.0, PI - 1e-6};
#define N_EDGE ((int)(sizeof edge_angles / sizeof edge_angles[0]))

/* Largest |a - b| over the entries of two poses. */
static double pose_diff(const se23_pose_t *a, const se23_pose_t *b)
{
    double d = 0;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            d = fmax(d, fabs((double)a->R.m[i][j] - b->R.m[i][j]));
        }
        d = fmax(d, fabs((double)a->v.v[i] - b->v.v[i]));
        d = fmax(d, fabs((double)a->p.v[i] - b->p.v[i]));
    }
    return d;
}

static double norm3(const se23_vec3_t *x)
{
    return sqrt((double)x->v[0] * x->v[0] + (double)x->v[1] * x->v[1] +
                (double)x->v[2] * x->v[2]);
}

static se23_imu_sample_t random_sample(se23t_rng_t *rng, double angle, double dt)
{
    se23_imu_sample_t s;
    se23t_random_axis_angle(rng, angle / dt, &s.w_ib_b);
    se23t_random_vec3(rng, 20.0, &s.f_b);
    s.dt = (se23_real_t)dt;
    return s;
}

static void test_imu_increment_without_rotation_is_constant_acceleration(void **state)
{
    (void)state;
    const se23_imu_sample_t s = {{{0, 0, 0}}, {{SE23_R(1.5), SE23_R(-2), SE23_R(9.75)}}, SE23_R(0.01)};
    se23_pose_t u;
    assert_int_equal(se23_imu_increment(&s, &u), SE23_OK);
    const se23_real_t I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    se23_real_t ev[3], ep[3];
    for (int i = 0; i < 3; ++i) {
        ev[i] = s.f_b.v[i] * s.dt;
        ep[i] = SE23_R(0.5) * s.f_b.v[i] * s.dt * s.dt;
    }
    assert_array_near(&u.R.m[0][0], I, 9, 0, 0);
    assert_array_near(u.v.v, ev, 3, 0, 2 * SE23T_EPS);
    assert_array_near(u.p.v, ep, 3, 0, 4 * SE23T_EPS);
}

static void test_imu_increment_matches_so3_series(void **state)
{
    (void)state;
    /* Upsilon = (exp(phi), dt J(phi) f, dt^2 H(phi) f), phi = w dt, with
     * exp, J, H from so3.h. */
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 31);
    for (int n = 0; n < N_EDGE; ++n) {
        const double dt = 0.02;
        se23_imu_sample_t s = random_sample(&rng, edge_angles[n], dt);
        se23_vec3_t phi;
        se23_mat3_t R, J, H;
        for (int i = 0; i < 3; ++i) {
            phi.v[i] = s.w_ib_b.v[i] * s.dt;
        }
        assert_int_equal(se23_so3_exp(&phi, &R), SE23_OK);
        assert_int_equal(se23_so3_jl(&phi, &J), SE23_OK);
        assert_int_equal(se23_so3_h(&phi, &H), SE23_OK);
        se23_pose_t u;
        assert_int_equal(se23_imu_increment(&s, &u), SE23_OK);
        assert_mat3_near(&u.R, &R, TOL);
        for (int i = 0; i < 3; ++i) {
            double v = 0, p = 0;
            for (int k = 0; k < 3; ++k) {
                v += (double)J.m[i][k] * s.f_b.v[k];
                p += (double)H.m[i][k] * s.f_b.v[k];
            }
            assert_near(u.v.v[i], v * dt, TOL * 20 * dt, 0);
            assert_near(u.p.v[i], p * dt * dt, TOL * 20 * dt * dt, 0);
        }
    }
}

static void test_imu_increment_composes_over_split_interval(void **state)
{
    (void)state;
    /* Exactness for a constant sample: Upsilon(dt) = Phi_{dt2}(Upsilon(dt1))
     * Upsilon(dt2), dt = dt1 + dt2 (the solution of eq. ODE restarted). */
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 32);
    for (int n = 0; n < 200 + N_EDGE; ++n) {
        const double angle = n < N_EDGE ? edge_angles[n] : se23t_uniform(&rng, 0, 3.0);
        const double dt = 0.1, dt1 = 0.0625;
        se23_imu_sample_t s = random_sample(&rng, angle, dt), s1 = s, s2 = s;
        s1.dt = (se23_real_t)dt1;
        s2.dt = (se23_real_t)(dt - dt1);
        se23_pose_t u, u1, u2, I, composed;
        se23_identity(&I);
        assert_int_equal(se23_imu_increment(&s, &u), SE23_OK);
        assert_int_equal(se23_imu_increment(&s1, &u1), SE23_OK);
        assert_int_equal(se23_imu_increment(&s2, &u2), SE23_OK);
        se23_imu_transition(&I, &u1, &u2, s2.dt, &composed);
        assert_true(pose_diff(&u, &composed) <= TOL * 20);
    }
}

static void test_imu_increment_solves_ode_in_dt(void **state)
{
    (void)state;
    /* d/dt Upsilon = (R w^, R f, V)  (paper eq. ODE), by central differences. */
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 33);
    for (int n = 0; n < 20; ++n) {
        se23_imu_sample_t s = random_sample(&rng, se23t_uniform(&rng, 0.1, 1.0), 0.5);
        se23_imu_sample_t sp = s, sm = s;
        sp.dt = (se23_real_t)(0.5 + FD_STEP);
        sm.dt = (se23_real_t)(0.5 - FD_STEP);
        se23_pose_t u, up, um;
        assert_int_equal(se23_imu_increment(&s, &u), SE23_OK);
        assert_int_equal(se23_imu_increment(&sp, &up), SE23_OK);
        assert_int_equal(se23_imu_increment(&sm, &um), SE23_OK);
        const double h2 = (double)sp.dt - sm.dt;
        se23_mat3_t W;
        se23_so3_hat(&s.w_ib_b, &W);
        for (int i = 0; i < 3; ++i) {
            double dv = 0;
            for (int j = 0; j < 3; ++j) {
                double dR = 0;
                for (int k = 0; k < 3; ++k) {
                    dR += (double)u.R.m[i][k] * W.m[k][j];
                }
                assert_near(((double)up.R.m[i][j] - um.R.m[i][j]) / h2, dR, FD_TOL * 10, FD_TOL);
                dv += (double)u.R.m[i][j] * s.f_b.v[j];
            }
            assert_near(((double)up.v.v[i] - um.v.v[i]) / h2, dv, FD_TOL * 100, FD_TOL);
            assert_near(((double)up.p.v[i] - um.p.v[i]) / h2, u.v.v[i], FD_TOL * 100, FD_TOL);
        }
    }
}

typedef se23_status_t (*increment_fn)(const se23_imu_sample_t *, se23_pose_t *);

/* Largest entry error, against the exact increment u of s, of m sub-steps
 * of s by the increment inc composed with se23_imu_transition (Gamma = I). */
static double substeps_error(increment_fn inc, const se23_imu_sample_t *s, int m,
                             const se23_pose_t *u)
{
    se23_imu_sample_t sub = *s;
    sub.dt = (se23_real_t)(s->dt / m);
    se23_pose_t acc, step, I;
    se23_identity(&acc);
    se23_identity(&I);
    assert_int_equal(inc(&sub, &step), SE23_OK);
    for (int k = 0; k < m; ++k) {
        se23_imu_transition(&I, &acc, &step, sub.dt, &acc);
    }
    return pose_diff(&acc, u);
}

/* Composing m sub-steps of inc converges to the exact increment of s at
 * first order: doubling m halves the error. */
static void assert_first_order(increment_fn inc, const se23_imu_sample_t *s)
{
    se23_pose_t u;
    assert_int_equal(se23_imu_increment(s, &u), SE23_OK);
    const double e64 = substeps_error(inc, s, 64, &u), e128 = substeps_error(inc, s, 128, &u);
    assert_true(e64 > 1e-4); /* ~ dt^2 |w| |f| / (2 m): far above rounding */
    assert_near(e64 / e128, 2.0, 0.1, 0);
}

static void test_imu_increment_forster_is_first_order(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 34);
    se23_imu_sample_t s = random_sample(&rng, 0.5, 0.1);
    se23_pose_t u, e;
    assert_int_equal(se23_imu_increment(&s, &u), SE23_OK);
    assert_int_equal(se23_imu_increment_forster(&s, &e), SE23_OK);
    /* Same rotation; velocity dt f and position dt^2 f / 2 (Forster et
     * al.'s model; the paper's remark prints dt^2 f, missing the 1/2). */
    assert_mat3_near(&e.R, &u.R, 0);
    for (int i = 0; i < 3; ++i) {
        assert_near(e.v.v[i], (double)s.f_b.v[i] * s.dt, 0, 2 * SE23T_EPS);
        assert_near(e.p.v[i], 0.5 * s.f_b.v[i] * s.dt * s.dt, 0, 4 * SE23T_EPS);
    }
    assert_first_order(se23_imu_increment_forster, &s);
    /* With w parallel to f both agree: J(phi) f = f and H(phi) f = f/2. */
    for (int i = 0; i < 3; ++i) {
        s.f_b.v[i] = SE23_R(3) * s.w_ib_b.v[i];
    }
    assert_int_equal(se23_imu_increment(&s, &u), SE23_OK);
    assert_int_equal(se23_imu_increment_forster(&s, &e), SE23_OK);
    assert_true(pose_diff(&u, &e) <= TOL);
}

static void test_imu_increment_paper_is_forster_without_position(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 35);
    se23_imu_sample_t s = random_sample(&rng, 0.5, 0.1);
    se23_pose_t e, q;
    assert_int_equal(se23_imu_increment_forster(&s, &e), SE23_OK);
    assert_int_equal(se23_imu_increment_paper(&s, &q), SE23_OK);
    /* The same rotation and velocity to the bit; the position is zero
     * (eq. backtofuture), Forster's minus f dt^2 / 2. */
    assert_memory_equal(&q.R, &e.R, sizeof q.R);
    assert_memory_equal(&q.v, &e.v, sizeof q.v);
    for (int i = 0; i < 3; ++i) {
        assert_true(q.p.v[i] == SE23_R(0));
        assert_near((double)e.p.v[i] - q.p.v[i], 0.5 * s.f_b.v[i] * s.dt * s.dt, 0,
                    4 * SE23T_EPS);
    }
    assert_first_order(se23_imu_increment_paper, &s);
    /* Without rotation, m sub-steps miss exactly f dt^2 / (2 m) in position
     * (the sum of their v dt / m is f dt^2 (m - 1) / (2 m)) and nothing
     * else; Forster's sub-steps are exact there. */
    se23_imu_sample_t still = s;
    still.w_ib_b = (se23_vec3_t){{0, 0, 0}};
    se23_pose_t u;
    assert_int_equal(se23_imu_increment(&still, &u), SE23_OK);
    double f_max = 0;
    for (int i = 0; i < 3; ++i) {
        f_max = fmax(f_max, fabs((double)s.f_b.v[i]));
    }
    const double miss = f_max * s.dt * s.dt / (2.0 * 10);
    assert_near(substeps_error(se23_imu_increment_paper, &still, 10, &u), miss, TOL, TOL);
    assert_true(substeps_error(se23_imu_increment_forster, &still, 10, &u) <= TOL);
}

/* Yaw rotation by angle a. */
static void rot_z(double a, se23_mat3_t *R)
{
    const se23_mat3_t out = {{{(se23_real_t)cos(a), (se23_real_t)-sin(a), 0},
                              {(se23_real_t)sin(a), (se23_real_t)cos(a), 0},
                              {0, 0, 1}}};
    *R = out;
}

static void test_imu_step_flat_circle_is_exact(void **state)
{
    (void)state;
    /* Level circle at speed V and yaw rate w in ENU: the body's specific
     * force is constant, (0, w V, g), so zero-order hold is exact and the
     * truth is closed-form: R = Rz(w t), v = R (V, 0, 0),
     * p = V/w (sin w t, 1 - cos w t, 0). 60 s at 100 Hz. */
    const double V = 12.0, w = 0.2, g = 9.80665, dt = 0.01;
    const se23_vec3_t g_n = {{0, 0, (se23_real_t)-g}}, zero = {{0, 0, 0}};
    se23_earth_model_t m;
    assert_int_equal(se23_earth_model_init(&g_n, &zero, (se23_real_t)dt, SE23_R(0.02), &m), SE23_OK);
    const se23_imu_sample_t s = {{{0, 0, (se23_real_t)w}}, {{0, (se23_real_t)(w * V), (se23_real_t)g}}, (se23_real_t)dt};
    se23_pose_t T;
    se23_identity(&T);
    T.v.v[0] = (se23_real_t)V;
    const int steps = 6000;
    for (int k = 0; k < steps; ++k) {
        assert_int_equal(se23_imu_step(&m, &T, &s, &T), SE23_OK);
    }
    const double t = steps * (double)s.dt, a = w * t;
    se23_pose_t E;
    rot_z(a, &E.R);
    const se23_real_t ev[3] = {(se23_real_t)(V * cos(a)), (se23_real_t)(V * sin(a)), 0};
    const se23_real_t ep[3] = {(se23_real_t)(V / w * sin(a)), (se23_real_t)(V / w * (1 - cos(a))), 0};
    /* Rounding only: double ~1e-12 over 6000 steps; float ~1e-3. */
    const double tol = SE23_CFG_DOUBLE ? 1e-9 : 2e-2;
    assert_mat3_near(&T.R, &E.R, tol / 10);
    assert_array_near(T.v.v, ev, 3, tol, 0);
    assert_array_near(T.p.v, ep, 3, tol * 10, 0);
}

/* Sample that keeps a body at rest at p0 in the rotating nav frame with
 * attitude R: the gyro sees the Earth rate, R^T Omega; the accelerometer
 * cancels gravity and the residual centrifugal term: f = R^T (Omega^ Omega^ p0 - g). */
static se23_imu_sample_t at_rest_sample(const se23_earth_model_t *m, const se23_pose_t *T)
{
    se23_imu_sample_t s;
    double wxp[3], wwxp[3], f_n[3];
    const se23_real_t *w = m->w_ie_n.v, *p = T->p.v;
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        wxp[i] = (double)w[j] * p[k] - (double)w[k] * p[j];
    }
    for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3, k = (i + 2) % 3;
        wwxp[i] = (double)w[j] * wxp[k] - (double)w[k] * wxp[j];
        f_n[i] = wwxp[i] - (double)m->g_n.v[i];
    }
    for (int i = 0; i < 3; ++i) {
        double wb = 0, fb = 0;
        for (int k = 0; k < 3; ++k) {
            wb += (double)T->R.m[k][i] * w[k];
            fb += (double)T->R.m[k][i] * f_n[k];
        }
        s.w_ib_b.v[i] = (se23_real_t)wb;
        s.f_b.v[i] = (se23_real_t)fb;
    }
    s.dt = m->dt;
    return s;
}

/* Propagates a body at rest for 60 s at 100 Hz; returns the largest
 * attitude [rad], velocity [m/s] and position [m] errors. */
static void at_rest_errors(const se23_earth_model_t *m, double err[3])
{
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 35);
    se23_pose_t U0;
    se23t_random_pose(&rng, 300.0, &U0);
    memset(&U0.v, 0, sizeof U0.v);
    const se23_imu_sample_t s = at_rest_sample(m, &U0);
    se23_pose_t Tc, U;
    se23_imu_carried_from_user(m, &U0, &Tc);
    for (int k = 0; k < 6000; ++k) {
        assert_int_equal(se23_imu_step(m, &Tc, &s, &Tc), SE23_OK);
    }
    se23_imu_user_from_carried(m, &Tc, &U);
    err[0] = err[1] = err[2] = 0;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            err[0] = fmax(err[0], fabs((double)U.R.m[i][j] - U0.R.m[i][j]));
        }
        err[1] = fmax(err[1], fabs((double)U.v.v[i] - U0.v.v[i]));
        err[2] = fmax(err[2], fabs((double)U.p.v[i] - U0.p.v[i]));
    }
    print_message("at rest, |Omega| = %.3g rad/s: errors R %.3g, v %.3g m/s, p %.3g m\n",
                  norm3(&m->w_ie_n), err[0], err[1], err[2]);
}

static void test_imu_step_rotating_earth_keeps_body_at_rest(void **state)
{
    (void)state;
    /* 60 s at 100 Hz with the real Earth rate at 45 deg and with an
     * exaggerated Omega = 0.05 rad/s: Coriolis (zero here), centrifugal
     * (-Omega^ Omega^ p, 0.0025 * 300 m) and the attitude's Earth-rate term
     * must cancel exactly; what remains is rounding, mostly through the
     * attitude (g times the attitude error). In float the Earth rate over one
     * sample (5e-7 rad) is a few epsilons: tools/accuracy measures what that
     * costs (tools/doc/pages/propagation.md). */
    const double tol_d[3] = {1e-12, 1e-9, 1e-8};
    const double tol_f[3] = {3e-4, 0.1, 2.0};
    const double *tol = SE23_CFG_DOUBLE ? tol_d : tol_f;
    double err[3];
    se23_earth_model_t m;
    assert_int_equal(se23_earth_model_init_wgs84(SE23_FRAME_NED, (se23_real_t)(PI / 4), 0,
                                                 SE23_R(0.01), SE23_R(0.01), &m), SE23_OK);
    at_rest_errors(&m, err);
    for (int i = 0; i < 3; ++i) {
        assert_true(err[i] <= tol[i]);
    }
    const se23_vec3_t big = {{SE23_R(0.03), SE23_R(0.0), SE23_R(-0.04)}};
    assert_int_equal(se23_earth_model_init(&m.g_n, &big, SE23_R(0.01), SE23_R(0.01), &m), SE23_OK);
    at_rest_errors(&m, err);
    for (int i = 0; i < 3; ++i) {
        assert_true(err[i] <= tol[i]);
    }
}

/* gamma = NULL is Gamma = I (preintegration), without the product. */
static void test_imu_transition_null_gamma_is_identity(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 78);
    se23_pose_t I, T, U, with, without;
    se23_identity(&I);
    for (int n = 0; n < 20; ++n) {
        se23t_random_pose(&rng, 10.0, &T);
        se23t_random_pose(&rng, 1.0, &U);
        se23_imu_transition(&I, &T, &U, SE23_R(0.01), &with);
        se23_imu_transition(NULL, &T, &U, SE23_R(0.01), &without);
        assert_memory_equal(&with, &without, sizeof with);
    }
}

static void test_imu_step_keeps_rotation_orthonormal(void **state)
{
    (void)state;
    /* A repeated sample repeats its rounding error: without
     * re-orthonormalisation R leaves SO(3) linearly (float: past
     * SE23_CFG_ROT_TOL within ~100 steps). 20000 steps with Earth rate. */
    const se23_vec3_t g = {{0, 0, SE23_R(9.8)}}, w = {{SE23_R(0.03), 0, SE23_R(-0.04)}};
    se23_earth_model_t m;
    assert_int_equal(se23_earth_model_init(&g, &w, SE23_R(0.01), SE23_R(0.01), &m), SE23_OK);
    const se23_imu_sample_t s = {{{SE23_R(0.01), SE23_R(0.02), SE23_R(0.3)}},
                                 {{0, 0, SE23_R(-9.8)}}, SE23_R(0.01)};
    se23_pose_t T;
    se23_identity(&T);
    rot_z(0.7, &T.R);
    for (int k = 0; k < 20000; ++k) {
        assert_int_equal(se23_imu_step(&m, &T, &s, &T), SE23_OK);
    }
    se23_mat3_t RtR;
    const se23_real_t I[9] = {1, 0, 0, 0, 1, 0, 0, 0, 1};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double d = 0;
            for (int k = 0; k < 3; ++k) {
                d += (double)T.R.m[k][i] * T.R.m[k][j];
            }
            RtR.m[i][j] = (se23_real_t)d;
        }
    }
    assert_array_near(&RtR.m[0][0], I, 9, 8 * SE23T_EPS, 0);
}

static void test_imu_step_recomputes_gamma_for_other_dt(void **state)
{
    (void)state;
    const se23_vec3_t g = {{0, 0, SE23_R(9.8)}}, w = {{SE23_R(0.02), SE23_R(0.01), SE23_R(-0.03)}};
    se23_earth_model_t m100, m80;
    assert_int_equal(se23_earth_model_init(&g, &w, SE23_R(0.01), SE23_R(0.05), &m100), SE23_OK);
    assert_int_equal(se23_earth_model_init(&g, &w, SE23_R(0.0125), SE23_R(0.05), &m80), SE23_OK);
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 36);
    se23_pose_t T, a, b;
    se23t_random_pose(&rng, 50.0, &T);
    se23_imu_sample_t s = random_sample(&rng, 0.01, 0.0125);
    assert_int_equal(se23_imu_step(&m100, &T, &s, &a), SE23_OK);
    assert_int_equal(se23_imu_step(&m80, &T, &s, &b), SE23_OK);
    assert_memory_equal(&a, &b, sizeof a);
    /* A sample interval within rounding of the nominal one uses the cache. */
    s.dt = SE23_R(0.01);
    se23_pose_t c, d;
    assert_int_equal(se23_imu_step(&m100, &T, &s, &c), SE23_OK);
    se23_pose_t u;
    assert_int_equal(se23_imu_increment(&s, &u), SE23_OK);
    se23_imu_transition(&m100.gamma, &T, &u, s.dt, &d);
    assert_memory_equal(&c, &d, sizeof c);
}

static void test_imu_step_flat_is_paper_discrete2(void **state)
{
    (void)state;
    /* T+ = Gamma Phi(T) Upsilon with Gamma = (I, g dt, g dt^2/2), written
     * out: R+ = R dR, v+ = v + R dV + g dt, p+ = p + v dt + R dX + g dt^2/2. */
    const se23_vec3_t g = {{SE23_R(0.1), SE23_R(0.2), SE23_R(-9.8)}}, zero = {{0, 0, 0}};
    se23_earth_model_t m;
    assert_int_equal(se23_earth_model_init(&g, &zero, SE23_R(0.005), SE23_R(0.01), &m), SE23_OK);
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 37);
    for (int n = 0; n < 50; ++n) {
        se23_pose_t T, out, u;
        se23t_random_pose(&rng, 100.0, &T);
        se23_imu_sample_t s = random_sample(&rng, se23t_uniform(&rng, 0, 0.05), 0.005);
        assert_int_equal(se23_imu_step(&m, &T, &s, &out), SE23_OK);
        assert_int_equal(se23_imu_increment(&s, &u), SE23_OK);
        const double dt = s.dt;
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                double r = 0;
                for (int k = 0; k < 3; ++k) {
                    r += (double)T.R.m[i][k] * u.R.m[k][j];
                }
                assert_near(out.R.m[i][j], r, TOL, 0);
            }
            double Rv = 0, Rp = 0;
            for (int k = 0; k < 3; ++k) {
                Rv += (double)T.R.m[i][k] * u.v.v[k];
                Rp += (double)T.R.m[i][k] * u.p.v[k];
            }
            assert_near(out.v.v[i], T.v.v[i] + Rv + g.v[i] * dt, TOL * 100, 0);
            assert_near(out.p.v[i], T.p.v[i] + T.v.v[i] * dt + Rp + 0.5 * g.v[i] * dt * dt,
                        TOL * 100, 0);
        }
    }
}

static void test_imu_carried_conversions_invert(void **state)
{
    (void)state;
    const se23_vec3_t g = {{0, 0, SE23_R(9.8)}}, w = {{SE23_R(1e-4), SE23_R(-2e-4), SE23_R(3e-4)}};
    se23_earth_model_t m;
    assert_int_equal(se23_earth_model_init(&g, &w, SE23_R(0.01), SE23_R(0.01), &m), SE23_OK);
    se23_pose_t T, Tc, back;
    se23_identity(&T);
    T.v = (se23_vec3_t){{1, 2, 3}};
    T.p = (se23_vec3_t){{100, -200, 50}};
    se23_imu_carried_from_user(&m, &T, &Tc);
    /* v' = v + Omega x p. */
    const se23_real_t e[3] = {
        SE23_R(1) + (SE23_R(-2e-4) * SE23_R(50) - SE23_R(3e-4) * SE23_R(-200)),
        SE23_R(2) + (SE23_R(3e-4) * SE23_R(100) - SE23_R(1e-4) * SE23_R(50)),
        SE23_R(3) + (SE23_R(1e-4) * SE23_R(-200) - SE23_R(-2e-4) * SE23_R(100))};
    assert_array_near(Tc.v.v, e, 3, 0, 4 * SE23T_EPS);
    assert_memory_equal(&Tc.R, &T.R, sizeof T.R);
    assert_memory_equal(&Tc.p, &T.p, sizeof T.p);
    se23_imu_user_from_carried(&m, &Tc, &back);
    assert_array_near(back.v.v, T.v.v, 3, 0, 4 * SE23T_EPS);
    /* In place. */
    se23_imu_carried_from_user(&m, &T, &T);
    assert_memory_equal(&T, &Tc, sizeof T);
}

/* Every bad sample, for a function f(sample) -> status that must not write. */
typedef se23_status_t (*sample_fn)(const se23_imu_sample_t *s, void *out);

static void check_bad_samples(sample_fn fn, void *out, size_t size, double dt_max)
{
    const se23_imu_sample_t good = {{{SE23_R(0.1), SE23_R(0.2), SE23_R(0.3)}},
                                    {{SE23_R(1), SE23_R(2), SE23_R(-9.8)}},
                                    SE23_R(0.01)};
    unsigned char before[sizeof(se23_pose_t)];
    assert_true(size <= sizeof before);
    memset(out, SENTINEL, size);
    memcpy(before, out, size);
    const se23_real_t nonfinite[] = {(se23_real_t)NAN, (se23_real_t)INFINITY, (se23_real_t)-INFINITY};
    for (int k = 0; k < 3; ++k) {
        for (int i = 0; i < 3; ++i) {
            se23_imu_sample_t s = good;
            s.w_ib_b.v[i] = nonfinite[k];
            assert_int_equal(fn(&s, out), SE23_ERR_NONFINITE);
            s = good;
            s.f_b.v[i] = nonfinite[k];
            assert_int_equal(fn(&s, out), SE23_ERR_NONFINITE);
        }
        se23_imu_sample_t s = good;
        s.dt = nonfinite[k];
        assert_int_equal(fn(&s, out), SE23_ERR_NONFINITE);
    }
    const double bad_dt[] = {0.0, -0.0, -0.01, dt_max * 1.001, 1e30};
    for (size_t i = 0; i < sizeof bad_dt / sizeof bad_dt[0]; ++i) {
        se23_imu_sample_t s = good;
        s.dt = (se23_real_t)bad_dt[i];
        assert_int_equal(fn(&s, out), SE23_ERR_DT);
    }
    assert_memory_equal(out, before, size);
    /* dt_max itself is accepted. */
    se23_imu_sample_t s = good;
    s.dt = (se23_real_t)dt_max;
    assert_int_equal(fn(&s, out), SE23_OK);
}

static se23_status_t call_increment(const se23_imu_sample_t *s, void *out)
{
    return se23_imu_increment(s, out);
}

static se23_status_t call_increment_forster(const se23_imu_sample_t *s, void *out)
{
    return se23_imu_increment_forster(s, out);
}

static se23_status_t call_increment_paper(const se23_imu_sample_t *s, void *out)
{
    return se23_imu_increment_paper(s, out);
}

static se23_earth_model_t step_model;
static se23_pose_t step_state;

static se23_status_t call_step(const se23_imu_sample_t *s, void *out)
{
    return se23_imu_step(&step_model, &step_state, s, out);
}

static void test_imu_increment_rejects_bad_samples(void **state)
{
    (void)state;
    se23_pose_t u;
    check_bad_samples(call_increment, &u, sizeof u, SE23_CFG_DT_MAX);
    check_bad_samples(call_increment_forster, &u, sizeof u, SE23_CFG_DT_MAX);
    check_bad_samples(call_increment_paper, &u, sizeof u, SE23_CFG_DT_MAX);
}

/* The internal step used by covariance propagation returns the same state
 * as se23_imu_step and the same increment as se23_imu_increment; on error
 * it writes neither. */
static void test_imu_step_ups_matches_step_and_increment(void **state)
{
    (void)state;
    se23_earth_model_t m;
    const se23_vec3_t g = {{0, 0, (se23_real_t)9.8}};
    const se23_vec3_t w = {{(se23_real_t)5e-5, 0, (se23_real_t)-5e-5}};
    assert_int_equal(se23_earth_model_init(&g, &w, SE23_R(0.01), SE23_R(0.03), &m), SE23_OK);
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 77);
    for (int n = 0; n < 20; ++n) {
        se23_pose_t T, by_step, by_ups, ups, ups_ref;
        se23_imu_sample_t s;
        se23t_random_pose(&rng, 100.0, &T);
        se23t_random_vec3(&rng, 2.0, &s.w_ib_b);
        se23t_random_vec3(&rng, 20.0, &s.f_b);
        s.dt = (se23_real_t)(n % 2 ? 0.01 : 0.02); /* cached and recomputed Gamma' */
        assert_int_equal(se23_imu_step(&m, &T, &s, &by_step), SE23_OK);
        se23_increment_parts_t parts;
        assert_int_equal(se23_imu_step_ups(&m, &T, &s, &by_ups, &ups, &parts), SE23_OK);
        assert_int_equal(se23_imu_increment(&s, &ups_ref), SE23_OK);
        assert_pose_near(&by_ups, &by_step, 0);
        assert_pose_near(&ups, &ups_ref, 0);
        /* The parts are the series the increment was built from. */
        se23_mat3_t Jl, Hs;
        se23_vec3_t th;
        for (int k = 0; k < 3; ++k) {
            th.v[k] = s.dt * s.w_ib_b.v[k];
        }
        assert_int_equal(se23_so3_jl(&th, &Jl), SE23_OK);
        assert_int_equal(se23_so3_h(&th, &Hs), SE23_OK);
        assert_mat3_near(&parts.J, &Jl, 0);
        assert_mat3_near(&parts.H, &Hs, 0);
    }
    se23_pose_t T, out, ups, before;
    se23_imu_sample_t bad = {{{0, 0, 0}}, {{0, 0, 0}}, SE23_R(0.5)}; /* dt > dt_max */
    se23_identity(&T);
    se23_identity(&out);
    out.p.v[0] = 42;
    ups = out;
    before = out;
    assert_int_equal(se23_imu_step_ups(&m, &T, &bad, &out, &ups, NULL), SE23_ERR_DT);
    assert_pose_near(&out, &before, 0);
    assert_pose_near(&ups, &before, 0);
#if SE23_CFG_ARG_CHECKS
    assert_int_equal(se23_imu_step_ups(&m, &T, &bad, &out, NULL, NULL), SE23_ERR_NULL);
#endif
}

/* Regression (issue 12, D3): a finite rate whose |w dt|^2 overflows gave
 * NaN increments with SE23_OK; now SE23_ERR_NONFINITE, nothing written. */
static void test_imu_increments_refuse_overflow(void **state)
{
    (void)state;
#if SE23_CFG_DOUBLE
    const se23_real_t w = 1e157;
#else
    const se23_real_t w = 1e22f;
#endif
    const se23_imu_sample_t s = {{{w, 0, 0}}, {{0, 0, SE23_R(9.8)}}, SE23_R(0.01)};
    se23_pose_t out, out0;
    memset(&out, 0x5a, sizeof out);
    out0 = out;
    assert_int_equal(se23_imu_increment(&s, &out), SE23_ERR_NONFINITE);
    assert_int_equal(se23_imu_increment_forster(&s, &out), SE23_ERR_NONFINITE);
    assert_int_equal(se23_imu_increment_paper(&s, &out), SE23_ERR_NONFINITE);
    assert_memory_equal(&out, &out0, sizeof out);
}

/* se23_sample_tame's promise (imu_step.h): the increment and the input
 * matrix of a tame sample are finite, with no test of their entries.
 * Checked at the corners of the tame set (|w dt|_1 = 8 and |f|_1 at its
 * limit, random directions, three dt), and both sides of every limit. */
static int all_finite(const se23_real_t *x, int n)
{
    for (int i = 0; i < n; ++i) {
        if (!isfinite(x[i])) {
            return 0;
        }
    }
    return 1;
}

static void l1_scale(se23_vec3_t *v, double target)
{
    const double l1 = fabs((double)v->v[0]) + fabs((double)v->v[1]) + fabs((double)v->v[2]);
    for (int i = 0; i < 3; ++i) {
        v->v[i] = (se23_real_t)((double)v->v[i] * (target / l1));
    }
}

static void test_sample_tame_corners_are_finite(void **state)
{
    (void)state;
    const double shrink = 1.0 - 1e-5; /* inside, after the rounding of the scaling */
    const se23_real_t dts[3] = {SE23_R(1e-4), SE23_R(0.01), SE23_R(SE23_CFG_DT_MAX)};
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 91);
    for (int n = 0; n < 300; ++n) {
        se23_imu_sample_t s;
        s.dt = dts[n % 3];
        se23t_random_vec3(&rng, 1.0, &s.w_ib_b);
        se23t_random_vec3(&rng, 1.0, &s.f_b);
        l1_scale(&s.w_ib_b, 8.0 / (double)s.dt * shrink);
        l1_scale(&s.f_b, (double)SE23_SAMPLE_F_TAME * shrink);
        assert_true(se23_sample_tame(&s));
        se23_pose_t U;
        se23_increment_parts_t parts;
        se23_input_blocks_t Bt;
        se23_imu_increment_parts(&s, &U, &parts);
        se23_input_blocks(SE23_INPUT_JAC_EXACT, &parts, &U.R, &s.f_b, s.dt, &Bt);
        assert_true(all_finite(&U.R.m[0][0], 9) && all_finite(U.v.v, 3) && all_finite(U.p.v, 3));
        for (int i = 0; i < 3; ++i) {
            for (int k = 0; k < 2; ++k) {
                assert_true(all_finite(&Bt.blk[i][k].m[0][0], 9));
            }
        }
    }
    /* each limit, from inside and from outside */
    se23_imu_sample_t s = {{{SE23_R(1), 0, 0}}, {{0, 0, SE23_R(9.8)}}, SE23_R(0.01)};
    assert_true(se23_sample_tame(&s));
    se23_imu_sample_t t = s;
    t.w_ib_b.v[0] = SE23_R(8) / t.dt;
    assert_true(se23_sample_tame(&t));
    t.w_ib_b.v[0] = SE23_R(8.01) / t.dt;
    assert_false(se23_sample_tame(&t));
    t = s;
    t.f_b.v[2] = SE23_SAMPLE_F_TAME;
    assert_true(se23_sample_tame(&t));
    t.f_b.v[2] = SE23_SAMPLE_F_TAME * SE23_R(1.01);
    assert_false(se23_sample_tame(&t));
    t = s;
    t.dt = SE23_R(8);
    t.w_ib_b.v[0] = SE23_R(0.5);
    assert_true(se23_sample_tame(&t));
    t.dt = SE23_R(8.01);
    assert_false(se23_sample_tame(&t));
    t = s;
    t.f_b.v[1] = (se23_real_t)NAN;
    assert_false(se23_sample_tame(&t));
    t = s;
    t.w_ib_b.v[2] = (se23_real_t)INFINITY;
    assert_false(se23_sample_tame(&t));
}

static void test_imu_step_rejects_bad_samples(void **state)
{
    (void)state;
    const se23_vec3_t g = {{0, 0, SE23_R(9.8)}}, w = {{SE23_R(0.01), 0, 0}};
    assert_int_equal(se23_earth_model_init(&g, &w, SE23_R(0.01), SE23_R(0.03), &step_model), SE23_OK);
    se23_identity(&step_state);
    se23_pose_t out;
    check_bad_samples(call_step, &out, sizeof out, 0.03);
}

static void test_imu_step_rejects_bad_states(void **state)
{
    (void)state;
    const se23_vec3_t g = {{0, 0, SE23_R(9.8)}}, w = {{SE23_R(0.01), 0, 0}};
    se23_earth_model_t m;
    assert_int_equal(se23_earth_model_init(&g, &w, SE23_R(0.01), SE23_R(0.03), &m), SE23_OK);
    const se23_imu_sample_t s = {{{0, 0, SE23_R(0.1)}}, {{0, 0, SE23_R(-9.8)}}, SE23_R(0.01)};
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 38);
    se23_pose_t good;
    se23t_random_pose(&rng, 10.0, &good);
    for (int n = 0; n < 15 + 4; ++n) {
        se23_pose_t T = good, T0, out, out0;
        se23_status_t expect = SE23_ERR_NONFINITE;
        se23_real_t *x = &T.R.m[0][0];
        if (n < 9) {
            x[n] = (se23_real_t)NAN;
        } else if (n < 12) {
            T.v.v[n - 9] = (se23_real_t)INFINITY;
        } else if (n < 15) {
            T.p.v[n - 12] = (se23_real_t)NAN;
        } else {
            /* Not rotations: scaled, sheared, reflected, far off. */
            const double f[4] = {1 + 100 * SE23_CFG_ROT_TOL, 0, -1, 0};
            for (int i = 0; i < 9; ++i) {
                x[i] = (se23_real_t)(n == 18 ? 0.5 : f[n - 15] * x[i]);
            }
            if (n == 16) {
                T.R = good.R;
                T.R.m[0][1] += (se23_real_t)(100 * SE23_CFG_ROT_TOL);
            }
            expect = SE23_ERR_NOT_ROTATION;
        }
        T0 = T;
        memset(&out, SENTINEL, sizeof out);
        out0 = out;
        assert_int_equal(se23_imu_step(&m, &T, &s, &out), expect);
        assert_memory_equal(&out, &out0, sizeof out);
        assert_memory_equal(&T, &T0, sizeof T);
        /* In place: the state itself is left as it was. */
        assert_int_equal(se23_imu_step(&m, &T, &s, &T), expect);
        assert_memory_equal(&T, &T0, sizeof T);
    }
}

static void test_imu_null_arguments_return_err_null(void **state)
{
    (void)state;
#if SE23_CFG_ARG_CHECKS
    se23_imu_sample_t s = {{{0, 0, 0}}, {{0, 0, 0}}, SE23_R(0.01)};
    se23_pose_t T;
    se23_earth_model_t m;
    se23_identity(&T);
    const se23_vec3_t g = {{0, 0, SE23_R(9.8)}};
    assert_int_equal(se23_earth_model_init(&g, &g, SE23_R(0.01), SE23_R(0.01), &m), SE23_OK);
    assert_int_equal(se23_imu_increment(NULL, &T), SE23_ERR_NULL);
    assert_int_equal(se23_imu_increment(&s, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_imu_increment_forster(NULL, &T), SE23_ERR_NULL);
    assert_int_equal(se23_imu_increment_forster(&s, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_imu_increment_paper(NULL, &T), SE23_ERR_NULL);
    assert_int_equal(se23_imu_increment_paper(&s, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_imu_step(NULL, &T, &s, &T), SE23_ERR_NULL);
    assert_int_equal(se23_imu_step(&m, NULL, &s, &T), SE23_ERR_NULL);
    assert_int_equal(se23_imu_step(&m, &T, NULL, &T), SE23_ERR_NULL);
    assert_int_equal(se23_imu_step(&m, &T, &s, NULL), SE23_ERR_NULL);
#else
    skip();
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_imu_increment_without_rotation_is_constant_acceleration),
        cmocka_unit_test(test_imu_increment_matches_so3_series),
        cmocka_unit_test(test_imu_increment_composes_over_split_interval),
        cmocka_unit_test(test_imu_increment_solves_ode_in_dt),
        cmocka_unit_test(test_imu_increment_forster_is_first_order),
        cmocka_unit_test(test_imu_increment_paper_is_forster_without_position),
        cmocka_unit_test(test_imu_step_flat_circle_is_exact),
        cmocka_unit_test(test_imu_step_rotating_earth_keeps_body_at_rest),
        cmocka_unit_test(test_imu_transition_null_gamma_is_identity),
        cmocka_unit_test(test_imu_step_keeps_rotation_orthonormal),
        cmocka_unit_test(test_imu_step_recomputes_gamma_for_other_dt),
        cmocka_unit_test(test_imu_step_flat_is_paper_discrete2),
        cmocka_unit_test(test_imu_carried_conversions_invert),
        cmocka_unit_test(test_imu_increment_rejects_bad_samples),
        cmocka_unit_test(test_imu_step_ups_matches_step_and_increment),
        cmocka_unit_test(test_imu_increments_refuse_overflow),
        cmocka_unit_test(test_sample_tame_corners_are_finite),
        cmocka_unit_test(test_imu_step_rejects_bad_samples),
        cmocka_unit_test(test_imu_step_rejects_bad_states),
        cmocka_unit_test(test_imu_null_arguments_return_err_null),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
