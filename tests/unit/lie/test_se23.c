/* Unit and property tests of src/lie/se23.c. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "se23/se23.h"
#include "se23/so3.h"
#include "se23_test.h"

#define N_RANDOM 200
#define PI 3.14159265358979323846
#define TOL (256.0 * SE23T_EPS)

/* 9x9 products in double, for the property checks. */
static void mat9_mul(const se23_mat9_t *A, const se23_mat9_t *B, se23_mat9_t *C)
{
    for (int i = 0; i < 9; ++i) {
        for (int j = 0; j < 9; ++j) {
            double s = 0;
            for (int k = 0; k < 9; ++k) {
                s += (double)A->m[9 * i + k] * (double)B->m[9 * k + j];
            }
            C->m[9 * i + j] = (se23_real_t)s;
        }
    }
}

static void mat9_apply(const se23_mat9_t *A, const se23_tangent_t *x, se23_tangent_t *y)
{
    for (int i = 0; i < 9; ++i) {
        double s = 0;
        for (int k = 0; k < 9; ++k) {
            s += (double)A->m[9 * i + k] * (double)x->v[k];
        }
        y->v[i] = (se23_real_t)s;
    }
}

static void test_se23_compose_inverse_is_identity(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 11);
    se23_pose_t I;
    se23_identity(&I);
    for (int n = 0; n < N_RANDOM; ++n) {
        se23_pose_t T, Ti, P;
        se23t_random_pose(&rng, 10.0, &T);
        se23_inverse(&T, &Ti);
        se23_compose(&T, &Ti, &P);
        assert_pose_near(&P, &I, 10 * TOL);
        se23_compose(&Ti, &T, &P);
        assert_pose_near(&P, &I, 10 * TOL);
    }
}

static void test_se23_compose_matches_5x5_product_and_aliases(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 12);
    se23_pose_t A, B, AB;
    se23t_random_pose(&rng, 3.0, &A);
    se23t_random_pose(&rng, 3.0, &B);
    se23_compose(&A, &B, &AB);
    se23_mat5_t MA, MB, MAB;
    se23_to_mat5(&A, &MA);
    se23_to_mat5(&B, &MB);
    se23_to_mat5(&AB, &MAB);
    for (int i = 0; i < 5; ++i) {
        for (int j = 0; j < 5; ++j) {
            double s = 0;
            for (int k = 0; k < 5; ++k) {
                s += (double)MA.m[i][k] * MB.m[k][j];
            }
            assert_near(MAB.m[i][j], s, TOL, 0);
        }
    }
    se23_compose(&A, &B, &A); /* output aliases the first input */
    assert_pose_near(&A, &AB, 0);
}

static void test_se23_act_is_rotation_plus_translation(void **state)
{
    (void)state;
    se23_pose_t T;
    se23_identity(&T);
    T.R.m[0][0] = 0;
    T.R.m[0][1] = -1;
    T.R.m[1][0] = 1;
    T.R.m[1][1] = 0; /* +90 deg about z */
    T.p.v[0] = 1;
    T.p.v[1] = 2;
    T.p.v[2] = 3;
    se23_vec3_t x = {{1, 0, 0}}, y;
    se23_act(&T, &x, &y);
    const se23_real_t expected[3] = {1, 3, 3};
    assert_array_near(y.v, expected, 3, TOL, 0);
}

static void test_se23_hat_vee_roundtrip(void **state)
{
    (void)state;
    se23_tangent_t xi = {{0.1, -0.2, 0.3, 1, 2, 3, -4, -5, -6}}, back;
    se23_mat5_t X;
    se23_hat(&xi, &X);
    assert_near(X.m[0][3], xi.v[SE23_IDX_NU], 0, 0);
    assert_near(X.m[2][4], xi.v[SE23_IDX_RHO + 2], 0, 0);
    assert_near(X.m[3][3], 0, 0, 0);
    assert_near(X.m[1][0], xi.v[SE23_IDX_PHI + 2], 0, 0);
    se23_vee(&X, &back);
    assert_array_near(back.v, xi.v, 9, 0, 0);
}

static void test_se23_exp_log_roundtrip(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 13);
    const double edge[] = {0.0, 1e-38, 1e-8, 1e-5, 1e-3, 0.1, 1.0, 3.0};
    const int n_edge = (int)(sizeof edge / sizeof edge[0]);
    for (int n = 0; n < N_RANDOM + n_edge; ++n) {
        se23_tangent_t xi, back;
        se23_pose_t T, T2;
        se23t_random_tangent(&rng, PI - 1e-3, 5.0, &xi);
        if (n < n_edge) {
            se23_vec3_t phi;
            se23t_random_axis_angle(&rng, edge[n], &phi);
            for (int i = 0; i < 3; ++i) {
                xi.v[SE23_IDX_PHI + i] = phi.v[i];
            }
        }
        assert_int_equal(se23_exp(&xi, &T), SE23_OK);
        assert_int_equal(se23_pose_check(&T), SE23_OK);
        assert_int_equal(se23_log(&T, &back), SE23_OK);
        assert_array_near(back.v, xi.v, 9, 16 * TOL, 0);
        /* log then exp on random poses */
        se23t_random_pose(&rng, 5.0, &T);
        assert_int_equal(se23_log(&T, &back), SE23_OK);
        assert_int_equal(se23_exp(&back, &T2), SE23_OK);
        assert_pose_near(&T2, &T, 4 * TOL);
    }
}

static void test_se23_adjoint_is_homomorphism(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 14);
    for (int n = 0; n < N_RANDOM; ++n) {
        se23_pose_t X, Y, XY;
        se23_mat9_t AdX, AdY, AdXY, prod;
        se23t_random_pose(&rng, 5.0, &X);
        se23t_random_pose(&rng, 5.0, &Y);
        se23_compose(&X, &Y, &XY);
        se23_adjoint(&X, &AdX);
        se23_adjoint(&Y, &AdY);
        se23_adjoint(&XY, &AdXY);
        mat9_mul(&AdX, &AdY, &prod);
        assert_array_near(prod.m, AdXY.m, 81, 100 * TOL, 0);
    }
}

static void test_se23_adjoint_inv_inverts_adjoint(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 15);
    for (int n = 0; n < N_RANDOM; ++n) {
        se23_pose_t X, Xi;
        se23_mat9_t Ad, AdInv, AdOfInverse, prod, I = {{0}};
        for (int k = 0; k < 9; ++k) {
            I.m[10 * k] = 1;
        }
        se23t_random_pose(&rng, 5.0, &X);
        se23_adjoint(&X, &Ad);
        se23_adjoint_inv(&X, &AdInv);
        mat9_mul(&Ad, &AdInv, &prod);
        assert_array_near(prod.m, I.m, 81, 100 * TOL, 0);
        se23_inverse(&X, &Xi);
        se23_adjoint(&Xi, &AdOfInverse);
        assert_array_near(AdInv.m, AdOfInverse.m, 81, 100 * TOL, 0);
    }
}

/* X exp(xi) X^-1 = exp(Ad_X xi) */
static void test_se23_adjoint_conjugates_exp(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 16);
    for (int n = 0; n < N_RANDOM; ++n) {
        se23_pose_t X, Xi, E, lhs, rhs;
        se23_tangent_t xi, Adxi;
        se23_mat9_t Ad;
        se23t_random_pose(&rng, 3.0, &X);
        se23t_random_tangent(&rng, 1.0, 1.0, &xi);
        assert_int_equal(se23_exp(&xi, &E), SE23_OK);
        se23_inverse(&X, &Xi);
        se23_compose(&X, &E, &lhs);
        se23_compose(&lhs, &Xi, &lhs);
        se23_adjoint(&X, &Ad);
        mat9_apply(&Ad, &xi, &Adxi);
        assert_int_equal(se23_exp(&Adxi, &rhs), SE23_OK);
        assert_pose_near(&lhs, &rhs, 100 * TOL);
    }
}

static void test_se23_from_mat5_roundtrip_and_rejects(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 17);
    se23_pose_t T, back, untouched;
    se23_mat5_t M;
    se23t_random_pose(&rng, 2.0, &T);
    se23_to_mat5(&T, &M);
    assert_int_equal(se23_from_mat5(&M, &back), SE23_OK);
    assert_pose_near(&back, &T, 0);

    se23_identity(&untouched);
    back = untouched;
    M.m[3][0] = (se23_real_t)0.5;
    assert_int_equal(se23_from_mat5(&M, &back), SE23_ERR_DOMAIN);
    assert_pose_near(&back, &untouched, 0);
    M.m[3][0] = 0;
    M.m[0][0] = (se23_real_t)(M.m[0][0] + 0.01);
    assert_int_equal(se23_from_mat5(&M, &back), SE23_ERR_NOT_ROTATION);
    M.m[0][3] = (se23_real_t)NAN;
    assert_int_equal(se23_from_mat5(&M, &back), SE23_ERR_NONFINITE);
    assert_pose_near(&back, &untouched, 0);
}

static void test_se23_exp_log_reject_bad_input_untouched(void **state)
{
    {
        /* Regression (issue 12, D3): |phi|^2 overflowing gave NaN with SE23_OK. */
        se23_tangent_t big = {{0}};
#if SE23_CFG_DOUBLE
        big.v[SE23_IDX_PHI] = 1e155;
#else
        big.v[SE23_IDX_PHI] = 2e19f;
#endif
        se23_pose_t o, o0;
        memset(&o, 0x5a, sizeof o);
        o0 = o;
        assert_int_equal(se23_exp(&big, &o), SE23_ERR_NONFINITE);
        assert_memory_equal(&o, &o0, sizeof o);
    }
    {
        /* Regression (fuzz_se23): J_l^-1 v overflowing (|J_l^-1| > 1 near
         * |phi| = pi) gave Inf with SE23_OK. */
        const se23_vec3_t phi = {{0, 0, 3}};
        se23_pose_t T;
        se23_tangent_t o, o0;
        se23_identity(&T);
        assert_int_equal(se23_so3_exp(&phi, &T.R), SE23_OK);
        T.v.v[1] = SE23T_REAL_MAX; /* nu_x = 1.5 v_y + ... */
        memset(&o, 0x5a, sizeof o);
        o0 = o;
        assert_int_equal(se23_log(&T, &o), SE23_ERR_NONFINITE);
        assert_memory_equal(&o, &o0, sizeof o);
        T.v.v[1] = 0;
        T.p.v[1] = SE23T_REAL_MAX;
        assert_int_equal(se23_log(&T, &o), SE23_ERR_NONFINITE);
        assert_memory_equal(&o, &o0, sizeof o);
        T.p.v[1] = SE23T_REAL_MAX / 4; /* representable: accepted */
        assert_int_equal(se23_log(&T, &o), SE23_OK);
        assert_true(isfinite(o.v[SE23_IDX_RHO]));
    }
    (void)state;
    se23_tangent_t xi = {{0.1, 0.2, 0.3, 1, 2, 3, 4, 5, (se23_real_t)INFINITY}};
    se23_pose_t T, before;
    se23_identity(&T);
    T.v.v[0] = 42;
    before = T;
    assert_int_equal(se23_exp(&xi, &T), SE23_ERR_NONFINITE);
    assert_pose_near(&T, &before, 0);

    se23_tangent_t out = {{7, 7, 7, 7, 7, 7, 7, 7, 7}}, out_before = out;
    T.p.v[1] = (se23_real_t)NAN;
    assert_int_equal(se23_log(&T, &out), SE23_ERR_NONFINITE);
    assert_int_equal(se23_pose_check(&T), SE23_ERR_NONFINITE);
    T.p.v[1] = 0;
    T.R.m[0][1] = (se23_real_t)0.1;
    assert_int_equal(se23_log(&T, &out), SE23_ERR_NOT_ROTATION);
    assert_int_equal(se23_pose_check(&T), SE23_ERR_NOT_ROTATION);
    assert_array_near(out.v, out_before.v, 9, 0, 0);
}

static void test_se23_null_arguments_return_err_null(void **state)
{
    (void)state;
#if SE23_CFG_ARG_CHECKS
    se23_tangent_t xi = {{0}};
    se23_pose_t T;
    se23_mat5_t M;
    se23_identity(&T);
    se23_to_mat5(&T, &M);
    assert_int_equal(se23_exp(NULL, &T), SE23_ERR_NULL);
    assert_int_equal(se23_exp(&xi, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_log(NULL, &xi), SE23_ERR_NULL);
    assert_int_equal(se23_log(&T, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_from_mat5(NULL, &T), SE23_ERR_NULL);
    assert_int_equal(se23_from_mat5(&M, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_pose_check(NULL), SE23_ERR_NULL);
#else
    skip();
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_se23_compose_inverse_is_identity),
        cmocka_unit_test(test_se23_compose_matches_5x5_product_and_aliases),
        cmocka_unit_test(test_se23_act_is_rotation_plus_translation),
        cmocka_unit_test(test_se23_hat_vee_roundtrip),
        cmocka_unit_test(test_se23_exp_log_roundtrip),
        cmocka_unit_test(test_se23_adjoint_is_homomorphism),
        cmocka_unit_test(test_se23_adjoint_inv_inverts_adjoint),
        cmocka_unit_test(test_se23_adjoint_conjugates_exp),
        cmocka_unit_test(test_se23_from_mat5_roundtrip_and_rejects),
        cmocka_unit_test(test_se23_exp_log_reject_bad_input_untouched),
        cmocka_unit_test(test_se23_null_arguments_return_err_null),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
