/* Unit and property tests of src/lie/so3.c. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "se23/so3.h"
#include "se23_test.h"

#define N_RANDOM 200
#define PI 3.14159265358979323846

/* Tolerance for a result a few operations away from exact, in the build's
 * precision, for O(1) quantities. */
#define TOL (64.0 * SE23T_EPS)

static const double edge_angles[] = {0.0, 1e-38, 1e-8, 1e-5, 1e-3, 0.1, 1.0, 3.0, PI - 1e-6};
#define N_EDGE ((int)(sizeof edge_angles / sizeof edge_angles[0]))

static void mat3_mul(const se23_mat3_t *A, const se23_mat3_t *B, se23_mat3_t *C)
{
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double s = 0;
            for (int k = 0; k < 3; ++k) {
                s += (double)A->m[i][k] * (double)B->m[k][j];
            }
            C->m[i][j] = (se23_real_t)s;
        }
    }
}

static void mat3_transpose(const se23_mat3_t *A, se23_mat3_t *At)
{
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            At->m[i][j] = A->m[j][i];
        }
    }
}

static double norm3(const se23_vec3_t *x)
{
    return sqrt((double)x->v[0] * x->v[0] + (double)x->v[1] * x->v[1] +
                (double)x->v[2] * x->v[2]);
}

static void assert_is_rotation(const se23_mat3_t *R, double tol)
{
    se23_mat3_t Rt, RtR, I = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    mat3_transpose(R, &Rt);
    mat3_mul(&Rt, R, &RtR);
    assert_mat3_near(&RtR, &I, tol);
}

static void test_so3_hat_vee_roundtrip(void **state)
{
    (void)state;
    se23_vec3_t phi = {{0.3, -1.2, 2.5}}, back;
    se23_mat3_t W;
    se23_so3_hat(&phi, &W);
    assert_near(W.m[0][1], -2.5, 0, 0);
    assert_near(W.m[2][1], phi.v[0], 0, 0);
    se23_so3_vee(&W, &back);
    assert_array_near(back.v, phi.v, 3, 0, 0);
}

static void test_so3_exp_is_rotation_and_log_inverts(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 1);
    for (int n = 0; n < N_RANDOM + N_EDGE; ++n) {
        double angle = n < N_EDGE ? edge_angles[n] : se23t_uniform(&rng, 0, PI - 1e-3);
        se23_vec3_t phi, back;
        se23_mat3_t R;
        se23t_random_axis_angle(&rng, angle, &phi);
        assert_int_equal(se23_so3_exp(&phi, &R), SE23_OK);
        assert_is_rotation(&R, TOL);
        assert_int_equal(se23_so3_log(&R, &back), SE23_OK);
        /* log is conditioned like 1/sin near pi: allow eps/(pi - theta). */
        double tol = TOL * (1.0 + 1.0 / (PI - angle + 1e-300) * 1e-3);
        assert_array_near(back.v, phi.v, 3, tol, 0);
    }
}

static void test_so3_log_at_pi_returns_an_angle_pi_vector(void **state)
{
    (void)state;
    /* Rotation by pi about (1, 2, 2)/3: R = 2 n n^T - I. */
    const double n[3] = {1.0 / 3, 2.0 / 3, 2.0 / 3};
    se23_mat3_t R;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            R.m[i][j] = (se23_real_t)(2 * n[i] * n[j] - (i == j));
        }
    }
    se23_vec3_t phi;
    assert_int_equal(se23_so3_log(&R, &phi), SE23_OK);
    double sign = phi.v[0] > 0 ? 1.0 : -1.0;
    for (int i = 0; i < 3; ++i) {
        assert_near(phi.v[i], sign * PI * n[i], TOL, 0);
    }
}

/* Regression (issue 12, D3): |phi|^2 overflowed to Inf and every series
 * returned NaN with SE23_OK; now SE23_ERR_NONFINITE, nothing written. */
static void test_so3_series_refuse_overflowing_angle(void **state)
{
    (void)state;
#if SE23_CFG_DOUBLE
    const se23_vec3_t phi = {{1e155, 0, 0}};
#else
    const se23_vec3_t phi = {{2e19f, 0, 0}};
#endif
    se23_status_t (*const fns[])(const se23_vec3_t *, se23_mat3_t *) = {
        se23_so3_exp, se23_so3_jl, se23_so3_jr, se23_so3_h, se23_so3_k};
    for (size_t i = 0; i < sizeof fns / sizeof fns[0]; ++i) {
        se23_mat3_t out, out0;
        memset(&out, 0x5a, sizeof out);
        out0 = out;
        assert_int_equal(fns[i](&phi, &out), SE23_ERR_NONFINITE);
        assert_memory_equal(&out, &out0, sizeof out);
    }
}

static void test_so3_exp_log_roundtrip_random_rotations(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 2);
    for (int n = 0; n < N_RANDOM; ++n) {
        se23_pose_t T;
        se23_vec3_t phi;
        se23_mat3_t R;
        se23t_random_pose(&rng, 1.0, &T);
        assert_int_equal(se23_so3_log(&T.R, &phi), SE23_OK);
        assert_true(norm3(&phi) <= PI + TOL);
        assert_int_equal(se23_so3_exp(&phi, &R), SE23_OK);
        assert_mat3_near(&R, &T.R, TOL);
    }
}

/* Central differences: step and tolerance per precision. */
#if SE23_CFG_DOUBLE
#define FD_STEP 1e-5
#define FD_TOL 1e-8
#else
#define FD_STEP 1e-2
#define FD_TOL 2e-3
#endif

/* (log(exp(phi + h d) exp(phi)^T) - log(exp(phi - h d) exp(phi)^T)) / 2h,
 * or with the product order swapped (right) : the Jacobian times d. */
static void fd_jacobian_column(const se23_vec3_t *phi, int col, int right,
                               se23_vec3_t *out)
{
    se23_mat3_t R0, R0t;
    assert_int_equal(se23_so3_exp(phi, &R0), SE23_OK);
    mat3_transpose(&R0, &R0t);
    se23_vec3_t logs[2];
    for (int s = 0; s < 2; ++s) {
        se23_vec3_t p = *phi;
        p.v[col] = (se23_real_t)(p.v[col] + (s == 0 ? FD_STEP : -FD_STEP));
        se23_mat3_t R, D;
        assert_int_equal(se23_so3_exp(&p, &R), SE23_OK);
        if (right) {
            mat3_mul(&R0t, &R, &D);
        } else {
            mat3_mul(&R, &R0t, &D);
        }
        assert_int_equal(se23_so3_log(&D, &logs[s]), SE23_OK);
    }
    for (int i = 0; i < 3; ++i) {
        out->v[i] = (se23_real_t)(((double)logs[0].v[i] - logs[1].v[i]) / (2 * FD_STEP));
    }
}

static void check_jacobian_by_differences(int right)
{
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 3 + (uint64_t)right);
    for (int n = 0; n < 50 + N_EDGE - 1; ++n) {
        double angle = n < N_EDGE - 1 ? edge_angles[n] : se23t_uniform(&rng, 0, 2.5);
        se23_vec3_t phi;
        se23_mat3_t J;
        se23t_random_axis_angle(&rng, angle, &phi);
        assert_int_equal(right ? se23_so3_jr(&phi, &J) : se23_so3_jl(&phi, &J), SE23_OK);
        for (int col = 0; col < 3; ++col) {
            se23_vec3_t fd;
            fd_jacobian_column(&phi, col, right, &fd);
            for (int i = 0; i < 3; ++i) {
                assert_near(J.m[i][col], fd.v[i], FD_TOL, 0);
            }
        }
    }
}

static void test_so3_jl_matches_central_differences(void **state)
{
    (void)state;
    check_jacobian_by_differences(0);
}

static void test_so3_jr_matches_central_differences(void **state)
{
    (void)state;
    check_jacobian_by_differences(1);
}

static void test_so3_jl_inv_inverts_jl(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 5);
    se23_mat3_t I = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    for (int n = 0; n < N_RANDOM + N_EDGE; ++n) {
        double angle = n < N_EDGE ? edge_angles[n] : se23t_uniform(&rng, 0, 6.0);
        se23_vec3_t phi;
        se23_mat3_t J, Jinv, P;
        se23t_random_axis_angle(&rng, angle, &phi);
        assert_int_equal(se23_so3_jl(&phi, &J), SE23_OK);
        assert_int_equal(se23_so3_jl_inv(&phi, &Jinv), SE23_OK);
        mat3_mul(&Jinv, &J, &P);
        /* J^-1 grows like 1/(2 pi - theta): scale the tolerance with it. */
        assert_mat3_near(&P, &I, TOL * (1.0 + 10.0 / (2 * PI - angle)));
    }
}

/* Simpson's rule for int_0^1 s f(s phi) ds, f = J_l (for H) or exp (for K). */
static void integrate_s_times(const se23_vec3_t *phi, int use_exp, se23_mat3_t *out)
{
    const int n = 200;
    double acc[3][3] = {{0}};
    for (int k = 0; k <= n; ++k) {
        double s = (double)k / n;
        double w = (k == 0 || k == n) ? 1.0 : (k % 2 ? 4.0 : 2.0);
        se23_vec3_t p;
        se23_mat3_t M;
        for (int i = 0; i < 3; ++i) {
            p.v[i] = (se23_real_t)(s * phi->v[i]);
        }
        assert_int_equal(use_exp ? se23_so3_exp(&p, &M) : se23_so3_jl(&p, &M), SE23_OK);
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                acc[i][j] += w * s * M.m[i][j];
            }
        }
    }
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            out->m[i][j] = (se23_real_t)(acc[i][j] / (3.0 * n));
        }
    }
}

/* H = int_0^1 s J_l(s phi) ds and K = int_0^1 s exp(s phi^) ds, term by term
 * from their series: an independent route to both. */
static void test_so3_h_and_k_match_their_integrals(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 6);
    for (int n = 0; n < 20 + N_EDGE; ++n) {
        double angle = n < N_EDGE ? edge_angles[n] : se23t_uniform(&rng, 0, 4.0);
        se23_vec3_t phi;
        se23_mat3_t H, K, Hq, Kq;
        se23t_random_axis_angle(&rng, angle, &phi);
        assert_int_equal(se23_so3_h(&phi, &H), SE23_OK);
        assert_int_equal(se23_so3_k(&phi, &K), SE23_OK);
        integrate_s_times(&phi, 0, &Hq);
        integrate_s_times(&phi, 1, &Kq);
        /* Simpson with 200 panels: error ~ theta^4 / 1e10. */
        assert_mat3_near(&H, &Hq, TOL + 1e-9);
        assert_mat3_near(&K, &Kq, TOL + 1e-9);
    }
}

static void test_so3_normalize_repairs_drift(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 7);
    for (int n = 0; n < N_RANDOM; ++n) {
        se23_pose_t T;
        se23t_random_pose(&rng, 1.0, &T);
        se23_mat3_t drifted = T.R, Rn;
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                drifted.m[i][j] = (se23_real_t)(drifted.m[i][j] + se23t_uniform(&rng, -1e-3, 1e-3));
            }
        }
        assert_int_equal(se23_so3_check(&drifted), SE23_ERR_NOT_ROTATION);
        assert_int_equal(se23_so3_normalize(&drifted, &Rn), SE23_OK);
        assert_int_equal(se23_so3_check(&Rn), SE23_OK);
        assert_is_rotation(&Rn, 8 * SE23T_EPS);
        assert_mat3_near(&Rn, &T.R, 4e-3);
    }
}

static void test_so3_normalize_refuses_far_from_rotation(void **state)
{
    (void)state;
    se23_mat3_t M = {{{1, 0.5, 0}, {0, 1, 0}, {0, 0, 1}}};
    se23_mat3_t out = {{{7, 7, 7}, {7, 7, 7}, {7, 7, 7}}}, before = out;
    assert_int_equal(se23_so3_normalize(&M, &out), SE23_ERR_NOT_ROTATION);
    assert_mat3_near(&out, &before, 0);
    se23_mat3_t reflection = {{{-1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    assert_int_equal(se23_so3_normalize(&reflection, &out), SE23_ERR_NOT_ROTATION);
    assert_int_equal(se23_so3_check(&reflection), SE23_ERR_NOT_ROTATION);
}

typedef se23_status_t (*vec_to_mat_fn)(const se23_vec3_t *, se23_mat3_t *);

static void test_so3_nonfinite_inputs_leave_output_untouched(void **state)
{
    (void)state;
    const vec_to_mat_fn fns[] = {se23_so3_exp, se23_so3_jl, se23_so3_jr,
                                 se23_so3_jl_inv, se23_so3_h, se23_so3_k};
    const se23_real_t bad[] = {(se23_real_t)NAN, (se23_real_t)INFINITY, -(se23_real_t)INFINITY};
    for (size_t f = 0; f < sizeof fns / sizeof fns[0]; ++f) {
        for (size_t b = 0; b < 3; ++b) {
            se23_vec3_t phi = {{0.1, bad[b], 0.2}};
            se23_mat3_t out = {{{7, 7, 7}, {7, 7, 7}, {7, 7, 7}}}, before = out;
            assert_int_equal(fns[f](&phi, &out), SE23_ERR_NONFINITE);
            assert_mat3_near(&out, &before, 0);
        }
    }
    se23_mat3_t R = {{{1, 0, 0}, {0, (se23_real_t)NAN, 0}, {0, 0, 1}}}, Rn;
    se23_vec3_t phi = {{7, 7, 7}};
    assert_int_equal(se23_so3_log(&R, &phi), SE23_ERR_NONFINITE);
    assert_near(phi.v[0], 7, 0, 0);
    assert_int_equal(se23_so3_check(&R), SE23_ERR_NONFINITE);
    assert_int_equal(se23_so3_normalize(&R, &Rn), SE23_ERR_NONFINITE);
}

static void test_so3_log_rejects_non_rotation(void **state)
{
    (void)state;
    se23_mat3_t M = {{{1, 1e-3, 0}, {0, 1, 0}, {0, 0, 1}}};
    se23_vec3_t phi = {{7, 7, 7}};
    assert_int_equal(se23_so3_log(&M, &phi), SE23_ERR_NOT_ROTATION);
    assert_near(phi.v[1], 7, 0, 0);
}

/* (1 + s) I with s = 0.45 tol: R^T R - I = 0.9 tol passes, but det - 1 =
 * 1.35 tol must not. */
static void test_so3_check_rejects_uniform_scaling(void **state)
{
    (void)state;
    const double s = 1.0 + 0.45 * (double)SE23_CFG_ROT_TOL;
    se23_mat3_t M = {{{(se23_real_t)s, 0, 0}, {0, (se23_real_t)s, 0}, {0, 0, (se23_real_t)s}}};
    assert_int_equal(se23_so3_check(&M), SE23_ERR_NOT_ROTATION);
    se23_vec3_t phi = {{7, 7, 7}};
    assert_int_equal(se23_so3_log(&M, &phi), SE23_ERR_NOT_ROTATION);
    assert_near(phi.v[0], 7, 0, 0);
    /* normalize repairs it */
    se23_mat3_t Rn;
    assert_int_equal(se23_so3_normalize(&M, &Rn), SE23_OK);
    assert_int_equal(se23_so3_check(&Rn), SE23_OK);
}

static void test_so3_jl_inv_rejects_near_two_pi(void **state)
{
    (void)state;
    se23_vec3_t phi = {{0, 0, (se23_real_t)(2 * PI)}};
    se23_mat3_t out = {{{7, 7, 7}, {7, 7, 7}, {7, 7, 7}}}, before = out;
    assert_int_equal(se23_so3_jl_inv(&phi, &out), SE23_ERR_DOMAIN);
    assert_mat3_near(&out, &before, 0);
    phi.v[2] = (se23_real_t)(2 * PI - 0.01);
    assert_int_equal(se23_so3_jl_inv(&phi, &out), SE23_OK);
}

static void test_so3_null_arguments_return_err_null(void **state)
{
    (void)state;
#if SE23_CFG_ARG_CHECKS
    se23_vec3_t phi = {{0.1, 0.2, 0.3}};
    se23_mat3_t M = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    assert_int_equal(se23_so3_exp(NULL, &M), SE23_ERR_NULL);
    assert_int_equal(se23_so3_exp(&phi, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_so3_log(NULL, &phi), SE23_ERR_NULL);
    assert_int_equal(se23_so3_log(&M, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_so3_jl(NULL, &M), SE23_ERR_NULL);
    assert_int_equal(se23_so3_jr(&phi, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_so3_jl_inv(NULL, &M), SE23_ERR_NULL);
    assert_int_equal(se23_so3_h(&phi, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_so3_k(NULL, &M), SE23_ERR_NULL);
    assert_int_equal(se23_so3_check(NULL), SE23_ERR_NULL);
    assert_int_equal(se23_so3_normalize(&M, NULL), SE23_ERR_NULL);
#else
    skip();
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_so3_hat_vee_roundtrip),
        cmocka_unit_test(test_so3_exp_is_rotation_and_log_inverts),
        cmocka_unit_test(test_so3_log_at_pi_returns_an_angle_pi_vector),
        cmocka_unit_test(test_so3_exp_log_roundtrip_random_rotations),
        cmocka_unit_test(test_so3_series_refuse_overflowing_angle),
        cmocka_unit_test(test_so3_jl_matches_central_differences),
        cmocka_unit_test(test_so3_jr_matches_central_differences),
        cmocka_unit_test(test_so3_jl_inv_inverts_jl),
        cmocka_unit_test(test_so3_h_and_k_match_their_integrals),
        cmocka_unit_test(test_so3_normalize_repairs_drift),
        cmocka_unit_test(test_so3_normalize_refuses_far_from_rotation),
        cmocka_unit_test(test_so3_nonfinite_inputs_leave_output_untouched),
        cmocka_unit_test(test_so3_log_rejects_non_rotation),
        cmocka_unit_test(test_so3_check_rejects_uniform_scaling),
        cmocka_unit_test(test_so3_jl_inv_rejects_near_two_pi),
        cmocka_unit_test(test_so3_null_arguments_return_err_null),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
