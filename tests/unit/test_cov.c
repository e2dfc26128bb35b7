/* Unit tests of src/cov.c: covariance validation (finite, symmetric, PSD
 * within tolerance), the Cholesky factor and solve, and the congruence
 * A P A^T of a linear map. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "cov.h"
#include "gauss_test.h"
#include "se23_test.h"

enum { S = SE23_COV_NMAX };

static void test_cov_check_accepts_psd_and_singular(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 501);
    se23_real_t A[S * S] = {0};
    assert_int_equal(se23_cov_check(A, 15, S), SE23_OK); /* zero matrix */
    for (int n = 1; n <= 15; ++n) {
        gt_random_cov(&rng, n, n, S, 1.0, 0.1, A);
        assert_int_equal(se23_cov_check(A, n, S), SE23_OK);
        gt_random_cov(&rng, n, (n + 1) / 2, S, 1.0, 0.0, A); /* rank deficient */
        assert_int_equal(se23_cov_check(A, n, S), SE23_OK);
    }
    /* Mixed scales: a 1e6 m^2 position next to a 1e-12 rad^2 attitude. */
    memset(A, 0, sizeof A);
    A[0] = SE23_R(1e-12);
    A[S + 1] = SE23_R(1e6);
    assert_int_equal(se23_cov_check(A, 2, S), SE23_OK);
}

static void test_cov_check_rejects_nonfinite(void **state)
{
    (void)state;
    se23_real_t A[S * S] = {0};
    for (int i = 0; i < 9; ++i) {
        A[S * i + i] = SE23_R(1);
    }
    A[S * 4 + 7] = (se23_real_t)NAN;
    assert_int_equal(se23_cov_check(A, 9, S), SE23_ERR_NONFINITE);
    A[S * 4 + 7] = SE23_R(0);
    A[S * 8 + 8] = (se23_real_t)INFINITY;
    assert_int_equal(se23_cov_check(A, 9, S), SE23_ERR_NONFINITE);
    /* Only the leading n x n block is read. */
    assert_int_equal(se23_cov_check(A, 8, S), SE23_OK);
}

static void test_cov_check_symmetry_tolerance_both_ways(void **state)
{
    (void)state;
    se23_real_t A[S * S] = {0};
    for (int i = 0; i < 3; ++i) {
        A[S * i + i] = SE23_R(4);
    }
    const double tol = (double)SE23_CFG_COV_TOL * 4.0;
    A[1] = SE23_R(1);
    A[S] = (se23_real_t)(1.0 + 0.5 * tol);
    assert_int_equal(se23_cov_check(A, 3, S), SE23_OK);
    A[S] = (se23_real_t)(1.0 + 4.0 * tol);
    assert_int_equal(se23_cov_check(A, 3, S), SE23_ERR_NOT_SYMMETRIC);
}

static void test_cov_check_psd_tolerance_both_ways(void **state)
{
    (void)state;
    /* diag(1, -e): accepted for e well inside the tolerance, refused beyond. */
    se23_real_t A[S * S] = {0};
    A[0] = SE23_R(1);
    A[S + 1] = (se23_real_t)(-0.25 * (double)SE23_CFG_COV_TOL);
    assert_int_equal(se23_cov_check(A, 2, S), SE23_OK);
    A[S + 1] = (se23_real_t)(-4.0 * (double)SE23_CFG_COV_TOL);
    assert_int_equal(se23_cov_check(A, 2, S), SE23_ERR_NOT_PSD);
    /* Positive diagonal, indefinite: [[1, 2], [2, 1]] has eigenvalue -1. */
    A[S + 1] = SE23_R(1);
    A[1] = SE23_R(2);
    A[S] = SE23_R(2);
    assert_int_equal(se23_cov_check(A, 2, S), SE23_ERR_NOT_PSD);
    /* Zero diagonal with off-diagonal entries. */
    memset(A, 0, sizeof A);
    A[1] = SE23_R(1e-3);
    A[S] = SE23_R(1e-3);
    assert_int_equal(se23_cov_check(A, 2, S), SE23_ERR_NOT_PSD);
}

static void test_cov_chol_factors_and_solves(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 502);
    for (int n = 1; n <= 15; ++n) {
        se23_real_t A[S * S], L[S * S], x[S], b[S];
        gt_random_cov(&rng, n, n, S, 1.0, 0.5, A);
        assert_true(se23_cov_chol(A, n, S, SE23_R(0), L));
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                double s = 0;
                for (int k = 0; k < n; ++k) {
                    s += (double)L[n * i + k] * L[n * j + k];
                }
                assert_near(s, A[S * i + j], 64 * SE23T_EPS * n * 10, 0.0);
                if (j > i) {
                    assert_true(L[n * i + j] == SE23_R(0));
                }
            }
            x[i] = (se23_real_t)se23t_normal(&rng);
        }
        for (int i = 0; i < n; ++i) {
            double s = 0;
            for (int k = 0; k < n; ++k) {
                s += (double)A[S * i + k] * x[k];
            }
            b[i] = (se23_real_t)s;
        }
        se23_cov_chol_solve(L, n, b);
        /* cond(A) <= ~ (|G|^2 + 0.5) / 0.5: a few hundred. */
        assert_array_near(b, x, n, 1e5 * SE23T_EPS, 0.0);
    }
}

static void test_cov_chol_refuses_singular_and_nan(void **state)
{
    (void)state;
    se23_real_t A[S * S] = {0}, L[S * S];
    A[0] = SE23_R(1);
    assert_false(se23_cov_chol(A, 2, S, SE23_R(0), L)); /* zero pivot */
    assert_true(se23_cov_chol(A, 2, S, SE23_R(1e-3), L)); /* shifted */
    /* Rank one [[1, 1], [1, 1]]: second pivot is rounding noise. */
    A[1] = A[S] = A[S + 1] = SE23_R(1);
    assert_false(se23_cov_chol(A, 2, S, SE23_R(0), L));
    A[S + 1] = (se23_real_t)NAN;
    assert_false(se23_cov_chol(A, 2, S, SE23_R(1), L));
}

/* A map given by a dense n x n matrix (row-major, stride S). */
typedef struct {
    const se23_real_t *A;
    int n;
} dense_ctx_t;

static void dense_map(const void *ctx, const se23_real_t *x, se23_real_t *y)
{
    const dense_ctx_t *c = (const dense_ctx_t *)ctx;
    for (int i = 0; i < c->n; ++i) {
        se23_real_t s = 0;
        for (int k = 0; k < c->n; ++k) {
            s += c->A[S * i + k] * x[k];
        }
        y[i] = s;
    }
}

static void test_cov_congruence_matches_dense_and_is_symmetric(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 503);
    for (int n = 1; n <= 15; n += 7) {
        se23_real_t A[S * S], P[S * S] = {0}, out[S * S] = {0};
        for (int i = 0; i < S * S; ++i) {
            A[i] = (se23_real_t)se23t_normal(&rng);
        }
        gt_random_cov(&rng, n, n, S, 1.0, 0.1, P);
        const dense_ctx_t ctx = {A, n};
        se23_cov_congruence(dense_map, &ctx, n, P, out);
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                double s = 0, mag = 0;
                for (int k = 0; k < n; ++k) {
                    for (int l = 0; l < n; ++l) {
                        const double t = (double)A[S * i + k] * P[S * k + l] * A[S * j + l];
                        s += t;
                        mag += fabs(t);
                    }
                }
                assert_near(out[S * i + j], s, 4.0 * n * SE23T_EPS * mag, 0.0);
                assert_true(out[S * i + j] == out[S * j + i]);
            }
        }
        se23_cov_congruence(dense_map, &ctx, n, P, P); /* aliasing */
        assert_memory_equal(P, out, sizeof P);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cov_check_accepts_psd_and_singular),
        cmocka_unit_test(test_cov_check_rejects_nonfinite),
        cmocka_unit_test(test_cov_check_symmetry_tolerance_both_ways),
        cmocka_unit_test(test_cov_check_psd_tolerance_both_ways),
        cmocka_unit_test(test_cov_chol_factors_and_solves),
        cmocka_unit_test(test_cov_chol_refuses_singular_and_nan),
        cmocka_unit_test(test_cov_congruence_matches_dense_and_is_symmetric),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
