/* Unit tests of src/cov/cov_check.c: covariance validation (finite, symmetric, PSD
 * within tolerance) and the packed Cholesky factor. */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "cov/cov_check.h"
#include "gauss_test.h"
#include "se23_test.h"

enum { S = SE23_GAUSS_NMAX };

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
    /* [[1, c], [c, 1]], c = 1 + e: eigenvalue -e; accepted for e well
     * inside the tolerance, refused beyond. A negative variance is refused
     * however small (issue 37, S4): diag(1, -e). */
    se23_real_t A[S * S] = {0};
    A[0] = SE23_R(1);
    A[S + 1] = SE23_R(1);
    A[1] = A[S] = (se23_real_t)(1.0 + 0.25 * (double)SE23_CFG_COV_TOL);
    assert_int_equal(se23_cov_check(A, 2, S), SE23_OK);
    A[1] = A[S] = (se23_real_t)(1.0 + 4.0 * (double)SE23_CFG_COV_TOL);
    assert_int_equal(se23_cov_check(A, 2, S), SE23_ERR_NOT_PSD);
    A[1] = A[S] = SE23_R(0);
    A[S + 1] = (se23_real_t)(-0.25 * (double)SE23_CFG_COV_TOL);
    assert_int_equal(se23_cov_check(A, 2, S), SE23_ERR_NOT_PSD);
    A[S + 1] = -SE23_R(1e-38);
    assert_int_equal(se23_cov_check(A, 2, S), SE23_ERR_NOT_PSD);
    assert_int_equal(se23_cov_check(A, 3, S), SE23_ERR_NOT_PSD);
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

/* L = the packed lower triangle of the leading n x n block of A. */
static void pack_lower(const se23_real_t *A, int n, se23_real_t *L)
{
    for (int i = 0, k = 0; i < n; ++i) {
        for (int j = 0; j <= i; ++j) {
            L[k++] = A[S * i + j];
        }
    }
}

/* Regression (fuzz_align: se23_align_cov's P with a variance near the
 * largest real failed se23_gauss_check): A_ii + tol s overflowed, so a
 * valid covariance was refused as not PSD. The check now factors A / 4 at
 * that scale; the verdicts are those of the same matrix scaled down. */
static void test_cov_check_near_the_largest_real(void **state)
{
    (void)state;
    const se23_real_t big = (se23_real_t)SE23T_REAL_MAX;
    se23_real_t A[S * S] = {0}, B[S * S] = {0};
    A[0] = SE23_R(0.0044);
    A[S + 1] = big;
    A[2 * S + 2] = big;
    assert_int_equal(se23_cov_check(A, 3, S), SE23_OK);
    /* the same verdicts as at an ordinary scale, both ways */
    const double c[] = {0.5, 1.0, 1.0 + 1e-3};
    const se23_status_t want[] = {SE23_OK, SE23_OK, SE23_ERR_NOT_PSD};
    for (int k = 0; k < 3; ++k) {
        const se23_real_t off = (se23_real_t)(c[k] * 0.5 * SE23T_REAL_MAX);
        A[0] = A[S + 1] = (se23_real_t)(0.5 * SE23T_REAL_MAX);
        A[1] = A[S] = off;
        B[0] = B[S + 1] = SE23_R(0.5);
        B[1] = B[S] = (se23_real_t)(c[k] * 0.5);
        assert_int_equal(se23_cov_check(B, 2, S), want[k]);
        assert_int_equal(se23_cov_check(A, 2, S), want[k]);
    }
}

/* Regression (make fuzz, fuzz_preint_unc, float): a covariance step from
 * P = 0 with denormal noise gave entries below the smallest normal float,
 * one diagonal -2.8e-45; the zero matrix's shift (the smallest normal)
 * then fell below the pivot rule's minimum and the result, zero to
 * rounding, was refused. The steps now raise such a variance to 0
 * (se23_cov_clamp_variances), and the check refuses any negative one. */
static void test_cov_check_denormal_noise_around_zero(void **state)
{
    (void)state;
    se23_real_t A[S * S] = {0};
    A[0] = (se23_real_t)8e-42;
    A[2] = A[2 * S] = (se23_real_t)-7.3e-42;
    A[2 * S + 2] = (se23_real_t)6.7e-42;
    A[S + 1] = SE23_R(0);
    assert_int_equal(se23_cov_check(A, 3, S), SE23_OK);
    A[S + 1] = (se23_real_t)-2.8e-45;
    assert_int_equal(se23_cov_check(A, 3, S), SE23_ERR_NOT_PSD);
    A[S + 1] = (se23_real_t)-1e-30; /* a normal negative variance is still refused */
    assert_int_equal(se23_cov_check(A, 3, S), SE23_ERR_NOT_PSD);
}

static void test_cov_chol_packed_factors(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 502);
    for (int n = 1; n <= 15; ++n) {
        se23_real_t A[S * S], L[SE23_COV_TRI(S)];
        gt_random_cov(&rng, n, n, S, 1.0, 0.5, A);
        pack_lower(A, n, L);
        assert_true(se23_cov_chol_packed(L, n));
        /* The diagonal holds 1 / L_jj. */
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j <= i; ++j) {
                double s = 0;
                for (int k = 0; k <= j; ++k) {
                    const double li = (k == i) ? 1.0 / L[SE23_COV_TRI(i) + k] : L[SE23_COV_TRI(i) + k];
                    const double lj = (k == j) ? 1.0 / L[SE23_COV_TRI(j) + k] : L[SE23_COV_TRI(j) + k];
                    s += li * lj;
                }
                assert_near(s, A[S * i + j], 64 * SE23T_EPS * n * 10, 0.0);
            }
        }
    }
}

/* Each refusal rule, on both sides of its threshold. */
static void test_cov_chol_packed_pivot_rules_both_ways(void **state)
{
    (void)state;
    se23_real_t L[3];
    /* [[1, 0], [0, 0]]: zero pivot; shifted by 1e-3 it factors. */
    L[0] = SE23_R(1), L[1] = SE23_R(0), L[2] = SE23_R(0);
    assert_false(se23_cov_chol_packed(L, 2));
    L[0] = SE23_R(1), L[1] = SE23_R(0), L[2] = SE23_R(1e-3);
    assert_true(se23_cov_chol_packed(L, 2));
    /* [[1, 1], [1, 1 + d]]: the second pivot d must exceed 16 eps (1 + d). */
    const se23_real_t eps = (se23_real_t)SE23T_EPS;
    L[0] = SE23_R(1), L[1] = SE23_R(1), L[2] = SE23_R(1) + SE23_R(8) * eps;
    assert_false(se23_cov_chol_packed(L, 2));
    L[0] = SE23_R(1), L[1] = SE23_R(1), L[2] = SE23_R(1) + SE23_R(64) * eps;
    assert_true(se23_cov_chol_packed(L, 2));
    /* A pivot below the smallest normal number is refused, one at it not. */
#if SE23_CFG_DOUBLE
    const se23_real_t tiny = DBL_MIN;
#else
    const se23_real_t tiny = FLT_MIN;
#endif
    L[0] = tiny / SE23_R(2);
    assert_false(se23_cov_chol_packed(L, 1));
    L[0] = tiny;
    assert_true(se23_cov_chol_packed(L, 1));
    L[0] = SE23_R(1), L[1] = SE23_R(0), L[2] = (se23_real_t)NAN;
    assert_false(se23_cov_chol_packed(L, 2));
    L[0] = (se23_real_t)INFINITY;
    assert_false(se23_cov_chol_packed(L, 1));
}

/* The unrolled 3 x 3 factor (every measurement model's shape) is the
 * loop's: the factor of a leading block is the leading block of the
 * factor, so a 4 x 4 matrix around the 3 x 3 one (factored by the loop)
 * must give the same verdict and, on success, the same bits. Random
 * positive definite matrices, each pivot made zero, negative, denormal
 * and NaN in turn. */
static void test_cov_chol_packed_3x3_is_the_loop(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 504);
    int refused = 0;
    for (int trial = 0; trial < 400; ++trial) {
        se23_real_t A[S * S], L3[SE23_COV_TRI(3)], L4[SE23_COV_TRI(4)];
        gt_random_cov(&rng, 4, 4, S, 1.0, 0.5, A);
        pack_lower(A, 4, L4);
        const int spoil = trial % 5; /* 0: none; 1..4: the kind below */
        const int at = (trial / 5) % 3;
        const se23_real_t d = spoil == 1 ? SE23_R(0) : spoil == 2 ? -SE23_R(1e-3)
                            : spoil == 3 ? SE23_R(1e-40) : (se23_real_t)NAN;
        if (spoil != 0) {
            /* Pivot `at` becomes d: A_aa = sum of the squares before it + d. */
            se23_real_t F[SE23_COV_TRI(4)];
            memcpy(F, L4, sizeof F);
            assert_true(se23_cov_chol_packed(F, 4));
            se23_real_t sq = SE23_R(0);
            for (int k = 0; k < at; ++k) {
                sq += F[SE23_COV_TRI(at) + k] * F[SE23_COV_TRI(at) + k];
            }
            L4[SE23_COV_TRI(at) + at] = sq + d;
        }
        memcpy(L3, L4, sizeof L3);
        const int ok3 = se23_cov_chol_packed(L3, 3);
        const int ok4 = se23_cov_chol_packed(L4, 4);
        refused += !ok3;
        assert_int_equal(ok3, ok4);
        if (ok3) {
            assert_memory_equal(L3, L4, sizeof L3);
        }
    }
    assert_true(refused >= 4 * 400 / 5 / 2); /* the spoiled pivots are seen */
}

/* The unrolled 3 x 3 check is the loop's: A and the 4 x 4 matrix
 * diag(A, s), s = max |A_ii| (same tolerance, one more pivot that always
 * passes), get the same status, for clean matrices and for matrices with
 * an asymmetry or an eigenvalue either side of the tolerance, a NaN or an
 * Inf, at unit scale and above the rescaling threshold. */
static void test_cov_check_3x3_is_the_loop(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 505);
    int seen[SE23_ERR_NOT_PSD + 1] = {0};
    const se23_real_t tol = SE23_R(SE23_CFG_COV_TOL);
    for (int trial = 0; trial < 600; ++trial) {
        se23_real_t A[S * S] = {0}, B[S * S] = {0}, w3[SE23_COV_TRI(3)], w4[SE23_COV_TRI(4)];
        gt_random_cov(&rng, 3, 2 + trial % 2, S, 1.0, 0.0, A);
        const se23_real_t big = (trial % 7 == 0) ? SE23_R(FLT_MAX) / SE23_R(3) : SE23_R(1);
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                A[S * i + j] *= big;
            }
        }
        const se23_real_t s = fmax(fmax(A[0], A[S + 1]), A[2 * S + 2]);
        const int r = 1 + (trial / 5) % 2, c = (trial / 10) % r;
        switch (trial % 5) {
        case 1: /* asymmetric by 0.5 or 2 tol s */
            A[S * r + c] += ((trial / 3) % 2 ? SE23_R(0.5) : SE23_R(2)) * tol * s;
            break;
        case 2: /* axis r decoupled, its eigenvalue -0.5 or -2 tol s */
            for (int k = 0; k < 3; ++k) {
                A[S * r + k] = SE23_R(0);
                A[S * k + r] = SE23_R(0);
            }
            A[S * r + r] = -((trial / 3) % 2 ? SE23_R(0.5) : SE23_R(2)) * tol * s;
            break;
        case 3:
            A[S * r + c] = (trial / 3) % 2 ? (se23_real_t)NAN : (se23_real_t)INFINITY;
            break;
        default:
            break;
        }
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                B[S * i + j] = A[S * i + j];
            }
        }
        B[S * 3 + 3] = fmax(fmax(fabs(A[0]), fabs(A[S + 1])), fabs(A[2 * S + 2]));
        const se23_status_t st = se23_cov_check_work(A, 3, S, w3);
        assert_int_equal(st, se23_cov_check_work(B, 4, S, w4));
        ++seen[st];
    }
    assert_true(seen[SE23_OK] > 0 && seen[SE23_ERR_NONFINITE] > 0 &&
                seen[SE23_ERR_NOT_SYMMETRIC] > 0 && seen[SE23_ERR_NOT_PSD] > 0);
}

/* The check with a small work buffer gives the same answers. */
static void test_cov_check_work_matches_check(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 503);
    for (int n = 1; n <= 9; ++n) {
        se23_real_t A[S * S], work[SE23_COV_TRI(9)];
        gt_random_cov(&rng, n, n, S, 1.0, 0.1, A);
        assert_int_equal(se23_cov_check_work(A, n, S, work), se23_cov_check(A, n, S));
        A[S * (n - 1) + (n - 1)] = -SE23_R(1);
        assert_int_equal(se23_cov_check_work(A, n, S, work), SE23_ERR_NOT_PSD);
        assert_int_equal(se23_cov_check(A, n, S), SE23_ERR_NOT_PSD);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_cov_check_accepts_psd_and_singular),
        cmocka_unit_test(test_cov_check_rejects_nonfinite),
        cmocka_unit_test(test_cov_check_symmetry_tolerance_both_ways),
        cmocka_unit_test(test_cov_check_psd_tolerance_both_ways),
        cmocka_unit_test(test_cov_check_near_the_largest_real),
        cmocka_unit_test(test_cov_check_denormal_noise_around_zero),
        cmocka_unit_test(test_cov_chol_packed_factors),
        cmocka_unit_test(test_cov_chol_packed_pivot_rules_both_ways),
        cmocka_unit_test(test_cov_chol_packed_3x3_is_the_loop),
        cmocka_unit_test(test_cov_check_3x3_is_the_loop),
        cmocka_unit_test(test_cov_check_work_matches_check),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
