/* Unit tests of src/imu/preint.c: accumulation of the Deltas, prediction on flat
 * and rotating Earth equal to step-by-step propagation, the Proposition
 * "Preintegration with Coriolis effect" written out, and every bad-input
 * path. The comparison with an RK4 integration of the continuous equations is
 * in tests/reference/crosscheck_nav.cpp. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "se23/preint.h"
#include "se23/se23.h"
#include "se23_test.h"

#define PI 3.14159265358979323846
#define SENTINEL 0x5a
#define RATE_HZ 100
#define SECONDS 60

/* Relative agreement of two exact routes that differ only in rounding
 * order, after SECONDS * RATE_HZ samples. */
#if SE23_CFG_DOUBLE
#define ROUTE_TOL 1e-11
#else
#define ROUTE_TOL 2e-3
#endif

/* Smooth 3D motion: body rates and specific force as slow sinusoids,
 * sampled at the start of each interval (zero-order hold). */
static se23_imu_sample_t smooth_sample(int k)
{
    const double t = (double)k / RATE_HZ;
    const se23_imu_sample_t s = {
        {{(se23_real_t)(0.3 * sin(0.5 * t)), (se23_real_t)(0.2 * cos(0.3 * t + 0.4)),
          (se23_real_t)(0.1 + 0.15 * sin(0.7 * t))}},
        {{(se23_real_t)(1.0 + 0.8 * sin(0.4 * t)), (se23_real_t)(0.5 * cos(0.6 * t)),
          (se23_real_t)(-9.81 + 0.3 * sin(0.9 * t))}},
        (se23_real_t)(1.0 / RATE_HZ)};
    return s;
}

/* Initial user state: level, heading 30 deg, moving, away from the origin. */
static void initial_state(se23_pose_t *T)
{
    const double c = cos(PI / 6), s = sin(PI / 6);
    const se23_pose_t out = {{{{(se23_real_t)c, (se23_real_t)-s, 0},
                                {(se23_real_t)s, (se23_real_t)c, 0},
                                {0, 0, 1}}},
                              {{10, 2, -1}},
                              {{100, -50, 20}}};
    *T = out;
}

enum { FLAT, EARTH_45, EXAGGERATED, N_MODELS };

static void make_model(int which, se23_earth_model_t *m)
{
    const se23_vec3_t g = {{0, 0, SE23_R(9.80619777)}}, zero = {{0, 0, 0}};
    const se23_vec3_t big = {{SE23_R(0.05 * 0.6), 0, SE23_R(-0.05 * 0.8)}};
    const se23_real_t dt = SE23_R(1.0 / RATE_HZ);
    se23_status_t st = SE23_OK;
    if (which == FLAT) {
        st = se23_earth_model_init(&g, &zero, dt, dt, m);
    } else if (which == EARTH_45) {
        st = se23_earth_model_init_wgs84(SE23_FRAME_NED, (se23_real_t)(PI / 4), 0, dt, dt, m);
    } else {
        st = se23_earth_model_init(&g, &big, dt, dt, m);
    }
    assert_int_equal(st, SE23_OK);
}

static double rel_err3(const se23_vec3_t *a, const se23_vec3_t *e)
{
    double d = 0, n = 0;
    for (int i = 0; i < 3; ++i) {
        d = fmax(d, fabs((double)a->v[i] - e->v[i]));
        n = fmax(n, fabs((double)e->v[i]));
    }
    return d / n;
}

static double rot_err(const se23_mat3_t *a, const se23_mat3_t *e)
{
    double d = 0;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            d = fmax(d, fabs((double)a->m[i][j] - e->m[i][j]));
        }
    }
    return d;
}

static void test_preint_reset_is_identity(void **state)
{
    (void)state;
    se23_preint_t f, e;
    memset(&f, SENTINEL, sizeof f);
    se23_preint_reset(&f);
    se23_identity(&e.delta);
    assert_memory_equal(&f.delta, &e.delta, sizeof e.delta);
    assert_true(f.dt == 0 && f.n == 0);
}

static void test_preint_predict_equals_step_by_step(void **state)
{
    (void)state;
    /* Flat Earth, the real Earth rate at 45 deg, and Omega = 0.05 rad/s:
     * one factor over 60 s at 100 Hz predicts what 6000 steps propagate. */
    for (int which = 0; which < N_MODELS; ++which) {
        se23_earth_model_t m;
        make_model(which, &m);
        se23_pose_t U0, Tc, U_steps, U_pred;
        initial_state(&U0);
        se23_imu_carried_from_user(&m, &U0, &Tc);
        se23_preint_t f;
        se23_preint_reset(&f);
        for (int k = 0; k < SECONDS * RATE_HZ; ++k) {
            const se23_imu_sample_t s = smooth_sample(k);
            assert_int_equal(se23_imu_step(&m, &Tc, &s, &Tc), SE23_OK);
            assert_int_equal(se23_preint_add(&f, &s), SE23_OK);
        }
        assert_int_equal((int)f.n, SECONDS * RATE_HZ);
        assert_near(f.dt, SECONDS, 0, SE23_CFG_DOUBLE ? 1e-12 : 1e-4);
        se23_imu_user_from_carried(&m, &Tc, &U_steps);
        assert_int_equal(se23_preint_predict(&m, &f, &U0, &U_pred), SE23_OK);
        const double e[3] = {rot_err(&U_pred.R, &U_steps.R), rel_err3(&U_pred.v, &U_steps.v),
                             rel_err3(&U_pred.p, &U_steps.p)};
        print_message("model %d: |p| %.4g m, |v| %.4g m/s; factor vs steps: R %.2g, v %.2g rel, p %.2g rel\n",
                      which, sqrt((double)U_steps.p.v[0] * U_steps.p.v[0] +
                                  (double)U_steps.p.v[1] * U_steps.p.v[1] +
                                  (double)U_steps.p.v[2] * U_steps.p.v[2]),
                      sqrt((double)U_steps.v.v[0] * U_steps.v.v[0] +
                           (double)U_steps.v.v[1] * U_steps.v.v[1] +
                           (double)U_steps.v.v[2] * U_steps.v.v[2]),
                      e[0], e[1], e[2]);
        for (int i = 0; i < 3; ++i) {
            assert_true(e[i] <= ROUTE_TOL);
        }
    }
}

/* y = A x in double. */
static void mv(const se23_mat3_t *A, const double x[3], double y[3])
{
    for (int i = 0; i < 3; ++i) {
        y[i] = (double)A->m[i][0] * x[0] + (double)A->m[i][1] * x[1] + (double)A->m[i][2] * x[2];
    }
}

static void cross(const se23_vec3_t *a, const double b[3], double c[3])
{
    c[0] = (double)a->v[1] * b[2] - (double)a->v[2] * b[1];
    c[1] = (double)a->v[2] * b[0] - (double)a->v[0] * b[2];
    c[2] = (double)a->v[0] * b[1] - (double)a->v[1] * b[0];
}

static void test_preint_predict_is_the_coriolis_proposition(void **state)
{
    (void)state;
    /* The Proposition written out on user states, with v'_0 = v_0 + Omega x p_0:
     *   X_t = G^x + G^R R_0 X^u + t G^R v'_0 + G^R p_0,
     *   V_t = G^v + G^R R_0 V^u + G^R v'_0 - Omega x X_t,
     *   R_t = G^R R_0 R^u. */
    se23_earth_model_t m;
    make_model(EXAGGERATED, &m);
    se23_preint_t f;
    se23_preint_reset(&f);
    for (int k = 0; k < 500; ++k) {
        const se23_imu_sample_t s = smooth_sample(k);
        assert_int_equal(se23_preint_add(&f, &s), SE23_OK);
    }
    se23_pose_t U0, G, U;
    initial_state(&U0);
    assert_int_equal(se23_earth_gamma(&m.g_n, &m.w_ie_n, f.dt, &G), SE23_OK);
    assert_int_equal(se23_preint_predict(&m, &f, &U0, &U), SE23_OK);
    const double t = f.dt;
    double p0[3], v0[3], wxp[3], v0c[3], RX[3], RV[3], GRX[3], GRV[3], GRv[3], GRp[3];
    double X[3], V[3], wxX[3];
    for (int i = 0; i < 3; ++i) {
        p0[i] = U0.p.v[i];
        v0[i] = U0.v.v[i];
    }
    cross(&m.w_ie_n, p0, wxp);
    for (int i = 0; i < 3; ++i) {
        v0c[i] = v0[i] + wxp[i];
    }
    const double dX[3] = {f.delta.p.v[0], f.delta.p.v[1], f.delta.p.v[2]};
    const double dV[3] = {f.delta.v.v[0], f.delta.v.v[1], f.delta.v.v[2]};
    mv(&U0.R, dX, RX);
    mv(&U0.R, dV, RV);
    mv(&G.R, RX, GRX);
    mv(&G.R, RV, GRV);
    mv(&G.R, v0c, GRv);
    mv(&G.R, p0, GRp);
    for (int i = 0; i < 3; ++i) {
        X[i] = G.p.v[i] + GRX[i] + t * GRv[i] + GRp[i];
    }
    cross(&m.w_ie_n, X, wxX);
    for (int i = 0; i < 3; ++i) {
        V[i] = G.v.v[i] + GRV[i] + GRv[i] - wxX[i];
    }
    se23_pose_t E;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double r = 0;
            for (int k = 0; k < 3; ++k) {
                double gr = 0;
                for (int l = 0; l < 3; ++l) {
                    gr += (double)G.R.m[i][l] * U0.R.m[l][k];
                }
                r += gr * f.delta.R.m[k][j];
            }
            E.R.m[i][j] = (se23_real_t)r;
        }
        E.v.v[i] = (se23_real_t)V[i];
        E.p.v[i] = (se23_real_t)X[i];
    }
    const double tol = SE23_CFG_DOUBLE ? 1e-13 : 1e-5;
    assert_true(rot_err(&U.R, &E.R) <= tol);
    assert_true(rel_err3(&U.v, &E.v) <= tol);
    assert_true(rel_err3(&U.p, &E.p) <= tol);
}

static void test_preint_factors_chain(void **state)
{
    (void)state;
    /* Predicting through A then B equals predicting through the factor of
     * the concatenated samples. */
    se23_earth_model_t m;
    make_model(EARTH_45, &m);
    se23_preint_t a, b, ab;
    se23_preint_reset(&a);
    se23_preint_reset(&b);
    se23_preint_reset(&ab);
    for (int k = 0; k < 700; ++k) {
        const se23_imu_sample_t s = smooth_sample(k);
        assert_int_equal(se23_preint_add(k < 300 ? &a : &b, &s), SE23_OK);
        assert_int_equal(se23_preint_add(&ab, &s), SE23_OK);
    }
    se23_pose_t U0, mid, end2, end1;
    initial_state(&U0);
    assert_int_equal(se23_preint_predict(&m, &a, &U0, &mid), SE23_OK);
    assert_int_equal(se23_preint_predict(&m, &b, &mid, &end2), SE23_OK);
    assert_int_equal(se23_preint_predict(&m, &ab, &U0, &end1), SE23_OK);
    const double tol = SE23_CFG_DOUBLE ? 1e-13 : 5e-4;
    assert_true(rot_err(&end1.R, &end2.R) <= tol);
    assert_true(rel_err3(&end1.v, &end2.v) <= tol);
    assert_true(rel_err3(&end1.p, &end2.p) <= tol);
}

static void test_preint_empty_factor_predicts_initial_state(void **state)
{
    (void)state;
    se23_earth_model_t m;
    make_model(EXAGGERATED, &m);
    se23_preint_t f;
    se23_preint_reset(&f);
    se23_pose_t U0, U;
    initial_state(&U0);
    assert_int_equal(se23_preint_predict(&m, &f, &U0, &U), SE23_OK);
    assert_pose_near(&U, &U0, 4 * SE23T_EPS * 100);
}

static void test_preint_one_sample_equals_one_step(void **state)
{
    (void)state;
    se23_earth_model_t m;
    make_model(EXAGGERATED, &m);
    const se23_imu_sample_t s = smooth_sample(17);
    se23_preint_t f, g;
    se23_preint_reset(&f);
    assert_int_equal(se23_preint_add(&f, &s), SE23_OK);
    /* add_increment with the caller's increment is the same accumulation. */
    se23_pose_t u;
    se23_preint_reset(&g);
    assert_int_equal(se23_imu_increment(&s, &u), SE23_OK);
    se23_preint_add_increment(&g, &u, s.dt);
    assert_memory_equal(&f.delta, &g.delta, sizeof f.delta);
    assert_true(f.dt == g.dt && f.n == 1 && g.n == 1);
    se23_pose_t Tc, step, pred;
    initial_state(&Tc);
    assert_int_equal(se23_imu_step(&m, &Tc, &s, &step), SE23_OK);
    assert_int_equal(se23_preint_predict_carried(&m, &f, &Tc, &pred), SE23_OK);
    assert_pose_near(&pred, &step, 16 * SE23T_EPS * 200);
}

static void test_preint_add_rejects_bad_samples(void **state)
{
    (void)state;
    se23_preint_t f, f0;
    memset(&f, 0, sizeof f); /* defined padding for memory comparisons */
    se23_preint_reset(&f);
    assert_int_equal(se23_preint_add(&f, &(se23_imu_sample_t){{{0, 0, SE23_R(0.1)}}, {{0, 0, -10}}, SE23_R(0.01)}), SE23_OK);
    f0 = f;
    const se23_real_t nonfinite[] = {(se23_real_t)NAN, (se23_real_t)INFINITY};
    for (int k = 0; k < 2; ++k) {
        for (int i = 0; i < 7; ++i) {
            se23_imu_sample_t s = smooth_sample(3);
            if (i < 3) {
                s.w_ib_b.v[i] = nonfinite[k];
            } else if (i < 6) {
                s.f_b.v[i - 3] = nonfinite[k];
            } else {
                s.dt = nonfinite[k];
            }
            assert_int_equal(se23_preint_add(&f, &s), SE23_ERR_NONFINITE);
        }
    }
    const double bad_dt[] = {0.0, -1e-3, SE23_CFG_DT_MAX * 1.001};
    for (int i = 0; i < 3; ++i) {
        se23_imu_sample_t s = smooth_sample(3);
        s.dt = (se23_real_t)bad_dt[i];
        assert_int_equal(se23_preint_add(&f, &s), SE23_ERR_DT);
    }
    assert_memory_equal(&f, &f0, sizeof f);
}

/* A valid factor made invalid in one of several ways, and its status. */
static se23_status_t corrupt_factor(int which, se23_preint_t *f)
{
    memset(f, 0, sizeof *f); /* defined padding for memory comparisons */
    se23_preint_reset(f);
    for (int k = 0; k < 10; ++k) {
        const se23_imu_sample_t s = smooth_sample(k);
        assert_int_equal(se23_preint_add(f, &s), SE23_OK);
    }
    switch (which) {
    case 0:
        f->delta.R.m[1][2] = (se23_real_t)NAN;
        return SE23_ERR_NONFINITE;
    case 1:
        f->delta.v.v[0] = (se23_real_t)INFINITY;
        return SE23_ERR_NONFINITE;
    case 2:
        f->delta.p.v[2] = (se23_real_t)NAN;
        return SE23_ERR_NONFINITE;
    case 3:
        f->dt = (se23_real_t)NAN;
        return SE23_ERR_NONFINITE;
    case 4:
        f->dt = SE23_R(-0.5);
        return SE23_ERR_DT;
    case 5:
        f->delta.R.m[0][0] *= (se23_real_t)(1 + 100 * SE23_CFG_ROT_TOL);
        return SE23_ERR_NOT_ROTATION;
    default:
        for (int i = 0; i < 3; ++i) {
            f->delta.R.m[i][0] = -f->delta.R.m[i][0]; /* det = -1 */
        }
        return SE23_ERR_NOT_ROTATION;
    }
}
#define N_CORRUPT 7

static void test_preint_add_rejects_bad_factor(void **state)
{
    (void)state;
    for (int which = 0; which < N_CORRUPT; ++which) {
        se23_preint_t f, f0;
        const se23_status_t expect = corrupt_factor(which, &f);
        f0 = f;
        const se23_imu_sample_t s = smooth_sample(11);
        assert_int_equal(se23_preint_add(&f, &s), expect);
        assert_memory_equal(&f, &f0, sizeof f);
    }
}

static void test_preint_predict_rejects_bad_inputs(void **state)
{
    (void)state;
    se23_earth_model_t m;
    make_model(EARTH_45, &m);
    se23_pose_t U0, out, out0;
    initial_state(&U0);
    memset(&out, SENTINEL, sizeof out);
    out0 = out;
    for (int which = 0; which < N_CORRUPT; ++which) {
        se23_preint_t f, f0;
        const se23_status_t expect = corrupt_factor(which, &f);
        f0 = f;
        assert_int_equal(se23_preint_predict(&m, &f, &U0, &out), expect);
        assert_int_equal(se23_preint_predict_carried(&m, &f, &U0, &out), expect);
        assert_memory_equal(&f, &f0, sizeof f);
    }
    se23_preint_t f;
    se23_preint_reset(&f);
    for (int n = 0; n < 3; ++n) {
        se23_pose_t T = U0, T0;
        se23_status_t expect = SE23_ERR_NONFINITE;
        if (n == 0) {
            T.p.v[1] = (se23_real_t)NAN;
        } else if (n == 1) {
            T.v.v[2] = (se23_real_t)-INFINITY;
        } else {
            T.R.m[2][2] = SE23_R(0.9);
            expect = SE23_ERR_NOT_ROTATION;
        }
        T0 = T;
        assert_int_equal(se23_preint_predict(&m, &f, &T, &out), expect);
        assert_int_equal(se23_preint_predict_carried(&m, &f, &T, &out), expect);
        /* In place, the state is left as it was. */
        assert_int_equal(se23_preint_predict(&m, &f, &T, &T), expect);
        assert_memory_equal(&T, &T0, sizeof T);
    }
    se23_earth_model_t bad = m;
    bad.g_n.v[0] = (se23_real_t)NAN;
    assert_int_equal(se23_preint_predict(&bad, &f, &U0, &out), SE23_ERR_NONFINITE);
    bad = m;
    bad.w_ie_n.v[1] = (se23_real_t)INFINITY;
    assert_int_equal(se23_preint_predict_carried(&bad, &f, &U0, &out), SE23_ERR_NONFINITE);
    assert_memory_equal(&out, &out0, sizeof out);
}

/* Regression (fuzz_preint): finite Deltas, states or Delta t near the
 * largest real overflowed in se23_preint_add and the predictions, which
 * returned Inf with SE23_OK. Now refused, nothing written. */
static void test_preint_rejects_overflow(void **state)
{
    (void)state;
    const se23_real_t big = (se23_real_t)(0.75 * SE23T_REAL_MAX);
    se23_earth_model_t m;
    make_model(FLAT, &m);
    se23_preint_t f, f0;
    memset(&f, 0, sizeof f); /* defined padding for memory comparisons */
    se23_preint_reset(&f);
    f.delta.v.v[0] = big;
    f0 = f;
    /* the sample's own increment is finite: dt J f = f */
    const se23_imu_sample_t s = {{{0, 0, 0}}, {{big, 0, 0}}, SE23_R(1)};
    se23_pose_t U;
    assert_int_equal(se23_imu_increment(&s, &U), SE23_OK);
    assert_int_equal(se23_preint_add(&f, &s), SE23_ERR_NONFINITE);
    assert_memory_equal(&f, &f0, sizeof f);
    /* v_j = v_i + R dV + g t: 1.5 x the largest real */
    se23_pose_t Ti, out, out0;
    initial_state(&Ti);
    Ti.v.v[0] = big;
    memset(&out, SENTINEL, sizeof out);
    out0 = out;
    f.dt = SE23_R(1);
    assert_int_equal(se23_preint_predict(&m, &f, &Ti, &out), SE23_ERR_NONFINITE);
    assert_int_equal(se23_preint_predict_carried(&m, &f, &Ti, &out), SE23_ERR_NONFINITE);
    assert_memory_equal(&out, &out0, sizeof out);
    /* p_j = p_i + R dX + ...: 1.5 x the largest real */
    f = f0;
    f.delta.v.v[0] = SE23_R(0);
    f.delta.p.v[2] = big;
    f.dt = SE23_R(1);
    Ti.v.v[0] = SE23_R(0);
    Ti.p.v[2] = big;
    assert_int_equal(se23_preint_predict_carried(&m, &f, &Ti, &out), SE23_ERR_NONFINITE);
    assert_memory_equal(&out, &out0, sizeof out);
}

static void test_preint_null_arguments_return_err_null(void **state)
{
    (void)state;
#if SE23_CFG_ARG_CHECKS
    se23_earth_model_t m;
    make_model(FLAT, &m);
    se23_preint_t f;
    se23_preint_reset(&f);
    se23_pose_t T;
    se23_identity(&T);
    const se23_imu_sample_t s = smooth_sample(0);
    assert_int_equal(se23_preint_add(NULL, &s), SE23_ERR_NULL);
    assert_int_equal(se23_preint_add(&f, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_preint_predict(NULL, &f, &T, &T), SE23_ERR_NULL);
    assert_int_equal(se23_preint_predict(&m, NULL, &T, &T), SE23_ERR_NULL);
    assert_int_equal(se23_preint_predict(&m, &f, NULL, &T), SE23_ERR_NULL);
    assert_int_equal(se23_preint_predict(&m, &f, &T, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_preint_predict_carried(NULL, &f, &T, &T), SE23_ERR_NULL);
    assert_int_equal(se23_preint_predict_carried(&m, NULL, &T, &T), SE23_ERR_NULL);
    assert_int_equal(se23_preint_predict_carried(&m, &f, NULL, &T), SE23_ERR_NULL);
    assert_int_equal(se23_preint_predict_carried(&m, &f, &T, NULL), SE23_ERR_NULL);
#else
    skip();
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_preint_reset_is_identity),
        cmocka_unit_test(test_preint_predict_equals_step_by_step),
        cmocka_unit_test(test_preint_predict_is_the_coriolis_proposition),
        cmocka_unit_test(test_preint_factors_chain),
        cmocka_unit_test(test_preint_empty_factor_predicts_initial_state),
        cmocka_unit_test(test_preint_one_sample_equals_one_step),
        cmocka_unit_test(test_preint_add_rejects_bad_samples),
        cmocka_unit_test(test_preint_add_rejects_bad_factor),
        cmocka_unit_test(test_preint_predict_rejects_bad_inputs),
        cmocka_unit_test(test_preint_rejects_overflow),
        cmocka_unit_test(test_preint_null_arguments_return_err_null),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
