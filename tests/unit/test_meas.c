/* Unit tests of src/meas.c: the ready-made measurement models (GNSS
 * position with lever arm, velocity in the nav frame, velocity in the body
 * frame): residuals, H against central differences of h(Tbar exp(xi)) in
 * the double reference, zero bias columns, noise copied, bad input. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "gauss_test.h"
#include "se23/kalman.h"
#include "se23/se23.h"
#include "se23_test.h"

enum { S = SE23_GAUSS_NMAX, M = SE23_MEAS_MMAX };

#define SENTINEL 0x5a
#define TOL (64.0 * SE23T_EPS)
#define FD_H 1e-6

typedef enum { POS_NAV, VEL_NAV, VEL_BODY } model_t;

/* h(T) in double from the 5x5 form. */
static void reference_h(model_t which, const gt_m5_t *T, const double l[3],
                        double h[3])
{
    for (int i = 0; i < 3; ++i) {
        double s = 0;
        for (int k = 0; k < 3; ++k) {
            switch (which) {
            case POS_NAV:
                s += T->m[i][k] * l[k];
                break;
            case VEL_BODY:
                s += T->m[k][i] * T->m[k][3];
                break;
            default:
                break;
            }
        }
        if (which == POS_NAV) {
            s += T->m[i][4];
        } else if (which == VEL_NAV) {
            s = T->m[i][3];
        }
        h[i] = s;
    }
}

static se23_status_t call_model(model_t which, const se23_pose_t *T,
                                const se23_vec3_t *y, const se23_vec3_t *l,
                                const se23_mat3_t *cov, se23_meas_t *out)
{
    switch (which) {
    case POS_NAV:
        return se23_meas_pos_nav(T, y, l, cov, out);
    case VEL_NAV:
        return se23_meas_vel_nav(T, y, cov, out);
    default:
        return se23_meas_vel_body(T, y, cov, out);
    }
}

static void test_meas_models_match_central_differences(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 701);
    for (int which = POS_NAV; which <= VEL_BODY; ++which) {
        for (int rep = 0; rep < 30; ++rep) {
            se23_pose_t T;
            se23_vec3_t y, l;
            se23_mat3_t cov;
            se23_meas_t out;
            se23t_random_pose(&rng, 20.0, &T);
            se23t_random_vec3(&rng, 20.0, &y);
            se23t_random_vec3(&rng, (which == POS_NAV) ? 2.0 : 0.0, &l);
            gt_random_cov(&rng, 3, 3, 3, 1.0, 0.1, &cov.m[0][0]);
            memset(&out, SENTINEL, sizeof out);
            assert_int_equal(call_model((model_t)which, &T, &y, &l, &cov, &out), SE23_OK);
            assert_int_equal(out.m, 3);
            gt_m5_t Td;
            gt_from_pose(&T, &Td);
            const double ld[3] = {l.v[0], l.v[1], l.v[2]};
            double h0[3];
            reference_h((model_t)which, &Td, ld, h0);
            for (int i = 0; i < 3; ++i) {
                assert_near(out.z[i], (double)y.v[i] - h0[i], 2 * TOL * 40, 0.0);
                for (int j = 0; j < 3; ++j) {
                    assert_true(out.R[M * i + j] == cov.m[i][j]);
                }
                for (int j = 9; j < S; ++j) {
                    assert_true(out.H[S * i + j] == SE23_R(0));
                }
            }
            for (int j = 0; j < 9; ++j) {
                double hp[3], hm[3];
                for (int sgn = -1; sgn <= 1; sgn += 2) {
                    double e[9] = {0};
                    e[j] = sgn * FD_H;
                    gt_m5_t E, Tp;
                    gt_exp(e, &E);
                    gt_m5_mul(&Td, &E, &Tp);
                    reference_h((model_t)which, &Tp, ld, sgn > 0 ? hp : hm);
                }
                for (int i = 0; i < 3; ++i) {
                    const double cd = (hp[i] - hm[i]) / (2 * FD_H);
                    /* CD: rounding ~ 40 eps / 1e-6 = 1e-8 (double). */
                    assert_near(out.H[S * i + j], cd, 1e-7 + TOL * 40, 0.0);
                }
            }
        }
    }
}

static void test_meas_vel_body_is_zero_velocity_update(void **state)
{
    (void)state;
    /* At rest with a zero measurement the residual is -R^T v. */
    se23_pose_t T;
    se23_identity(&T);
    T.v.v[0] = SE23_R(0.5);
    const se23_vec3_t zero = {{0}};
    const se23_mat3_t cov = {{{SE23_R(1e-4), 0, 0}, {0, SE23_R(1e-4), 0}, {0, 0, SE23_R(1e-4)}}};
    se23_meas_t y;
    assert_int_equal(se23_meas_vel_body(&T, &zero, &cov, &y), SE23_OK);
    assert_true(y.z[0] == SE23_R(-0.5) && y.z[1] == SE23_R(0) && y.z[2] == SE23_R(0));
}

static void test_meas_models_reject_bad_input_untouched(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 702);
    se23_pose_t T, badT;
    se23_vec3_t y, l = {{SE23_R(0.1), 0, 0}}, bad;
    se23_mat3_t cov, badc;
    se23_meas_t out, out0;
    se23t_random_pose(&rng, 5.0, &T);
    se23t_random_vec3(&rng, 5.0, &y);
    gt_random_cov(&rng, 3, 3, 3, 1.0, 0.1, &cov.m[0][0]);
    memset(&out, SENTINEL, sizeof out);
    out0 = out;
    for (int which = POS_NAV; which <= VEL_BODY; ++which) {
        const model_t w = (model_t)which;
        bad = y;
        bad.v[1] = (se23_real_t)NAN;
        assert_int_equal(call_model(w, &T, &bad, &l, &cov, &out), SE23_ERR_NONFINITE);
        badT = T;
        badT.R.m[0][1] += SE23_R(0.01);
        assert_int_equal(call_model(w, &badT, &y, &l, &cov, &out), SE23_ERR_NOT_ROTATION);
        badT = T;
        badT.v.v[2] = (se23_real_t)INFINITY;
        assert_int_equal(call_model(w, &badT, &y, &l, &cov, &out), SE23_ERR_NONFINITE);
        badc = cov;
        badc.m[0][2] += SE23_R(0.5);
        assert_int_equal(call_model(w, &T, &y, &l, &badc, &out), SE23_ERR_NOT_SYMMETRIC);
        badc = cov;
        badc.m[1][1] = -badc.m[1][1];
        assert_int_equal(call_model(w, &T, &y, &l, &badc, &out), SE23_ERR_NOT_PSD);
        badc.m[1][1] = (se23_real_t)NAN;
        assert_int_equal(call_model(w, &T, &y, &l, &badc, &out), SE23_ERR_NONFINITE);
    }
    bad = l;
    bad.v[0] = (se23_real_t)NAN;
    assert_int_equal(se23_meas_pos_nav(&T, &y, &bad, &cov, &out), SE23_ERR_NONFINITE);
    assert_memory_equal(&out, &out0, sizeof out);
}

/* Every element of the output is written: rows beyond m = 3 and the bias
 * columns are zero whatever the buffer held. */
static void test_meas_models_define_every_element(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 703);
    se23_pose_t T;
    se23_vec3_t y, l = {{SE23_R(0.1), SE23_R(-0.2), SE23_R(0.3)}};
    se23_mat3_t cov;
    se23t_random_pose(&rng, 5.0, &T);
    se23t_random_vec3(&rng, 5.0, &y);
    gt_random_cov(&rng, 3, 3, 3, 1.0, 0.1, &cov.m[0][0]);
    for (int which = POS_NAV; which <= VEL_BODY; ++which) {
        se23_meas_t out;
        memset(&out, SENTINEL, sizeof out);
        assert_int_equal(call_model((model_t)which, &T, &y, &l, &cov, &out), SE23_OK);
        for (int i = 0; i < M; ++i) {
            if (i >= 3) {
                assert_true(out.z[i] == SE23_R(0));
            }
            for (int j = 0; j < S; ++j) {
                if (i >= 3 || j >= 9) {
                    assert_true(out.H[S * i + j] == SE23_R(0));
                }
            }
            for (int j = 0; j < M; ++j) {
                if (i >= 3 || j >= 3) {
                    assert_true(out.R[M * i + j] == SE23_R(0));
                }
            }
        }
    }
}

/* The noise check is that of gauss.h, both sides of each tolerance:
 * asymmetry and a negative eigenvalue of 0.5 tol s pass, 2 tol s fail. */
static void test_meas_cov_check_tolerance_boundaries(void **state)
{
    (void)state;
    se23_pose_t T;
    se23_identity(&T);
    const se23_vec3_t y = {{0}}, l = {{0}};
    const double tol = (double)SE23_CFG_COV_TOL;
    se23_meas_t out;
    for (int side = 0; side < 2; ++side) {
        const double k = side ? 2.0 : 0.5;
        se23_mat3_t cov = {{{SE23_R(1), 0, 0}, {0, SE23_R(1), 0}, {0, 0, SE23_R(1)}}};
        cov.m[0][2] = (se23_real_t)(k * tol);
        assert_int_equal(se23_meas_pos_nav(&T, &y, &l, &cov, &out),
                         side ? SE23_ERR_NOT_SYMMETRIC : SE23_OK);
        /* diag(1, 1, -k tol): smallest eigenvalue -k tol s, s = 1. */
        se23_mat3_t neg = {{{SE23_R(1), 0, 0}, {0, SE23_R(1), 0}, {0, 0, (se23_real_t)(-k * tol)}}};
        assert_int_equal(se23_meas_pos_nav(&T, &y, &l, &neg, &out),
                         side ? SE23_ERR_NOT_PSD : SE23_OK);
    }
    /* The zero matrix (an exact measurement) is valid. */
    const se23_mat3_t zero = {{{0}}};
    assert_int_equal(se23_meas_pos_nav(&T, &y, &l, &zero, &out), SE23_OK);
}

static void test_meas_null_arguments_return_err_null(void **state)
{
    (void)state;
#if SE23_CFG_ARG_CHECKS
    se23_pose_t T;
    se23_vec3_t y = {{0}};
    se23_mat3_t cov = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    se23_meas_t out;
    se23_identity(&T);
    assert_int_equal(se23_meas_pos_nav(NULL, &y, &y, &cov, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_pos_nav(&T, NULL, &y, &cov, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_pos_nav(&T, &y, NULL, &cov, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_pos_nav(&T, &y, &y, NULL, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_pos_nav(&T, &y, &y, &cov, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_meas_vel_nav(NULL, &y, &cov, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_vel_nav(&T, NULL, &cov, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_vel_nav(&T, &y, NULL, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_vel_nav(&T, &y, &cov, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_meas_vel_body(NULL, &y, &cov, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_vel_body(&T, NULL, &cov, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_vel_body(&T, &y, NULL, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_vel_body(&T, &y, &cov, NULL), SE23_ERR_NULL);
#else
    skip();
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_meas_models_match_central_differences),
        cmocka_unit_test(test_meas_vel_body_is_zero_velocity_update),
        cmocka_unit_test(test_meas_models_reject_bad_input_untouched),
        cmocka_unit_test(test_meas_models_define_every_element),
        cmocka_unit_test(test_meas_cov_check_tolerance_boundaries),
        cmocka_unit_test(test_meas_null_arguments_return_err_null),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
