/* Tests of src/base/linalg.c, the internal 3x3 helpers, against products written
 * out element by element in double. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "base/linalg.h"
#include "se23_test.h"

#define TOL (8.0 * SE23T_EPS)

static void random_mat3(se23t_rng_t *rng, se23_mat3_t *M)
{
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            M->m[i][j] = (se23_real_t)se23t_uniform(rng, -1, 1);
        }
    }
}

static double entry(const se23_mat3_t *M, int i, int j, int transposed)
{
    return transposed ? (double)M->m[j][i] : (double)M->m[i][j];
}

static void check_product(void (*fn)(const se23_mat3_t *, const se23_mat3_t *, se23_mat3_t *),
                          int ta, int tb)
{
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 31);
    for (int n = 0; n < 50; ++n) {
        se23_mat3_t A, B, C;
        random_mat3(&rng, &A);
        random_mat3(&rng, &B);
        fn(&A, &B, &C);
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                double s = 0;
                for (int k = 0; k < 3; ++k) {
                    s += entry(&A, i, k, ta) * entry(&B, k, j, tb);
                }
                assert_near(C.m[i][j], s, TOL, 0);
            }
        }
        fn(&A, &B, &A); /* aliasing the output with an input */
        assert_mat3_near(&A, &C, 0);
    }
}

static void test_linalg_m3_products(void **state)
{
    (void)state;
    check_product(se23_m3_mul, 0, 0);
    check_product(se23_m3_mul_tn, 1, 0);
    check_product(se23_m3_mul_nt, 0, 1);
}

static void test_linalg_m3_vector_products_and_skew(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 32);
    se23_mat3_t A, S, At;
    se23_vec3_t x, y, z, w;
    random_mat3(&rng, &A);
    se23t_random_vec3(&rng, 1, &x);
    se23t_random_vec3(&rng, 1, &y);
    se23_m3_mul_v3(&A, &x, &z);
    se23_m3_transpose(&A, &At);
    se23_m3_tmul_v3(&At, &x, &w);
    assert_array_near(w.v, z.v, 3, TOL, 0);
    for (int i = 0; i < 3; ++i) {
        double s = 0;
        for (int k = 0; k < 3; ++k) {
            s += (double)A.m[i][k] * x.v[k];
        }
        assert_near(z.v[i], s, TOL, 0);
    }
    /* skew(x) y = x cross y */
    se23_m3_skew(&x, &S);
    se23_m3_mul_v3(&S, &y, &z);
    se23_v3_cross(&x, &y, &w);
    assert_array_near(z.v, w.v, 3, TOL, 0);
    assert_near(se23_v3_dot(&x, &w), 0, TOL, 0);
    assert_near(w.v[0], (double)x.v[1] * y.v[2] - (double)x.v[2] * y.v[1], TOL, 0);
}

static void test_linalg_m3_series_matches_explicit_form(void **state)
{
    (void)state;
    const se23_vec3_t phi = {{0.3, -0.7, 1.1}};
    const se23_real_t a0 = (se23_real_t)0.9, a1 = (se23_real_t)-0.4, a2 = (se23_real_t)0.25;
    se23_mat3_t W, W2, out, expected;
    se23_m3_skew(&phi, &W);
    se23_m3_mul(&W, &W, &W2);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            expected.m[i][j] = (se23_real_t)((i == j ? a0 : 0) + a1 * W.m[i][j] + a2 * W2.m[i][j]);
        }
    }
    se23_m3_series(a0, a1, a2, &phi, &out);
    assert_mat3_near(&out, &expected, TOL);
}

static void test_linalg_det_axpy_load_store_finite(void **state)
{
    (void)state;
    se23_mat3_t I, M = {{{2, 1, 0}, {0, 3, 1}, {1, 0, 1}}}, out;
    se23_m3_identity(&I);
    assert_near(se23_m3_det(&I), 1, 0, 0);
    assert_near(se23_m3_det(&M), 2 * 3 - 1 * (0 - 1), TOL, 0);
    se23_m3_axpy(&I, 2, &M, &out);
    assert_near(out.m[0][0], 5, TOL, 0);
    assert_near(out.m[2][0], 2, TOL, 0);
    se23_vec3_t a = {{1, 2, 3}}, b = {{1, 1, 1}}, c;
    se23_v3_axpy(&a, -2, &b, &c);
    assert_near(c.v[2], 1, 0, 0);
    se23_v3_scale(&a, 3, &c);
    assert_near(c.v[1], 6, 0, 0);
    se23_real_t flat[5] = {9, 9, 9, 9, 9};
    se23_v3_store(&a, &flat[1]);
    assert_near(flat[0], 9, 0, 0);
    assert_near(flat[3], 3, 0, 0);
    assert_near(flat[4], 9, 0, 0);
    se23_v3_load(&flat[1], &c);
    assert_array_near(c.v, a.v, 3, 0, 0);
    const se23_real_t ok[3] = {1, 2, 3};
    const se23_real_t bad[3] = {1, (se23_real_t)NAN, 3};
    const se23_real_t inf[3] = {1, 2, -(se23_real_t)INFINITY};
    assert_true(se23_all_finite(ok, 3));
    assert_false(se23_all_finite(bad, 3));
    assert_false(se23_all_finite(inf, 3));
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_linalg_m3_products),
        cmocka_unit_test(test_linalg_m3_vector_products_and_skew),
        cmocka_unit_test(test_linalg_m3_series_matches_explicit_form),
        cmocka_unit_test(test_linalg_det_axpy_load_store_finite),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
