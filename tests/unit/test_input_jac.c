/* Unit tests of src/input_jac.c: the input matrix B_k of one IMU sample
 * (bias Jacobian of the exact increment) against central differences of a
 * double reference increment (exponential of the augmented 5x5 matrix),
 * the basic dt I_{9,6}, both Taylor/closed-form branches, bad input. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "gauss_test.h"
#include "se23/gauss.h"
#include "se23_test.h"

/* Relative to the largest entry of the block row. Double: the central
 * differences are good to ~1e-10. Float: a few eps. */
#if SE23_CFG_DOUBLE
#define JAC_TOL 1e-8
#else
#define JAC_TOL 2e-6
#endif
/* Central-difference steps: 1e-5 rad of rotation angle for the gyro
 * columns (truncation ~1e-11, rounding ~1e-11 relative); the increment is
 * linear in f and the logarithm of a pure translation is exact, so the
 * accelerometer columns take a large step. */
#define FD_ANGLE 1e-5
#define FD_ACCEL 0.1

/* Reference B by central differences of log(U(w, f)^-1 U(w + d, f + e)). */
static void reference_jac(const double w[3], const double f[3], double dt,
                          double B[54])
{
    gt_m5_t U0;
    gt_increment(w, f, dt, &U0);
    for (int j = 0; j < 6; ++j) {
        double xp[9], xm[9];
        const double h = (j < 3) ? FD_ANGLE / dt : FD_ACCEL;
        for (int sgn = -1; sgn <= 1; sgn += 2) {
            double w1[3] = {w[0], w[1], w[2]}, f1[3] = {f[0], f[1], f[2]};
            if (j < 3) {
                w1[j] += sgn * h;
            } else {
                f1[j - 3] += sgn * h;
            }
            gt_m5_t U1;
            gt_increment(w1, f1, dt, &U1);
            gt_log_between(&U0, &U1, sgn > 0 ? xp : xm);
        }
        for (int i = 0; i < 9; ++i) {
            B[6 * i + j] = (xp[i] - xm[i]) / (2 * h);
        }
    }
}

/* Compares B with the reference, block row by block row, relative to the
 * largest entry of each block row (the rows have different units). */
static void check_against_reference(const se23_vec3_t *w, const se23_vec3_t *f,
                                    se23_real_t dt)
{
    se23_mat9x6_t B;
    assert_int_equal(se23_gauss_input_jac(SE23_INPUT_JAC_EXACT, w, f, dt, &B),
                     SE23_OK);
    const double wd[3] = {w->v[0], w->v[1], w->v[2]};
    const double fd[3] = {f->v[0], f->v[1], f->v[2]};
    double ref[54];
    reference_jac(wd, fd, (double)dt, ref);
    for (int blk = 0; blk < 3; ++blk) {
        double scale = 0;
        for (int k = 18 * blk; k < 18 * blk + 18; ++k) {
            scale = fmax(scale, fabs(ref[k]));
        }
        for (int k = 18 * blk; k < 18 * blk + 18; ++k) {
            assert_near(B.m[k], ref[k], JAC_TOL * scale, 0.0);
        }
    }
}

static void test_input_jac_exact_matches_central_differences(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 401);
    /* Angles |w dt| on both sides of each branch threshold (1.5 double,
     * 3 float) and of the so3 series thresholds (1 double, 2 float). */
    const double angles[] = {0.0, 1e-8, 1e-5, 1e-3, 0.1, 0.99, 1.01,
                             1.5 - 1e-6, 1.5 + 1e-6, 1.99, 2.01,
                             3.0 - 1e-6, 3.0 + 1e-6, 5.0};
    const double dts[] = {0.005, 0.1, 0.8};
    for (size_t a = 0; a < sizeof angles / sizeof angles[0]; ++a) {
        for (size_t d = 0; d < sizeof dts / sizeof dts[0]; ++d) {
            se23_vec3_t w, f;
            se23t_random_axis_angle(&rng, angles[a] / dts[d], &w);
            se23t_random_vec3(&rng, 15.0, &f);
            check_against_reference(&w, &f, (se23_real_t)dts[d]);
        }
    }
}

static void test_input_jac_exact_random_samples(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 402);
    for (int n = 0; n < 100; ++n) {
        se23_vec3_t w, f;
        const double dt = se23t_uniform(&rng, 0.001, 0.1);
        se23t_random_vec3(&rng, 5.0, &w);
        se23t_random_vec3(&rng, 20.0, &f);
        check_against_reference(&w, &f, (se23_real_t)dt);
    }
}

static void test_input_jac_basic_is_dt_identity(void **state)
{
    (void)state;
    const se23_vec3_t w = {{SE23_R(0.3), SE23_R(-2), SE23_R(1)}};
    const se23_vec3_t f = {{SE23_R(1), SE23_R(2), SE23_R(-9.8)}};
    se23_mat9x6_t B;
    assert_int_equal(se23_gauss_input_jac(SE23_INPUT_JAC_BASIC, &w, &f, SE23_R(0.01), &B), SE23_OK);
    for (int i = 0; i < 9; ++i) {
        for (int j = 0; j < 6; ++j) {
            assert_true(B.m[6 * i + j] == ((i == j) ? SE23_R(0.01) : SE23_R(0)));
        }
    }
}

static void test_input_jac_exact_tends_to_basic_for_small_dt(void **state)
{
    (void)state;
    /* B_exact - dt I_{9,6} = O(dt^2): halving dt divides it by about 4. */
    const se23_vec3_t w = {{SE23_R(0.5), SE23_R(-1), SE23_R(2)}};
    const se23_vec3_t f = {{SE23_R(1), SE23_R(2), SE23_R(-9.8)}};
    double err[2];
    for (int k = 0; k < 2; ++k) {
        const se23_real_t dt = SE23_R(0.02) / (se23_real_t)(1 << k);
        se23_mat9x6_t Be, Bb;
        assert_int_equal(se23_gauss_input_jac(SE23_INPUT_JAC_EXACT, &w, &f, dt, &Be), SE23_OK);
        assert_int_equal(se23_gauss_input_jac(SE23_INPUT_JAC_BASIC, &w, &f, dt, &Bb), SE23_OK);
        err[k] = 0;
        for (int i = 0; i < 54; ++i) {
            err[k] = fmax(err[k], fabs((double)Be.m[i] - Bb.m[i]));
        }
    }
    assert_true(err[0] > 0);
    assert_near(err[0] / err[1], 4.0, 0.1, 0.0);
}

static void test_input_jac_rejects_bad_input_untouched(void **state)
{
    (void)state;
    const se23_vec3_t w = {{SE23_R(0.1), SE23_R(0.2), SE23_R(0.3)}};
    const se23_vec3_t f = {{SE23_R(0), SE23_R(0), SE23_R(-9.8)}};
    se23_vec3_t bad = w;
    se23_mat9x6_t B, B0;
    memset(&B, 0x5a, sizeof B);
    B0 = B;
    bad.v[1] = (se23_real_t)NAN;
    assert_int_equal(se23_gauss_input_jac(SE23_INPUT_JAC_EXACT, &bad, &f, SE23_R(0.01), &B), SE23_ERR_NONFINITE);
    bad = f;
    bad.v[2] = (se23_real_t)INFINITY;
    assert_int_equal(se23_gauss_input_jac(SE23_INPUT_JAC_EXACT, &w, &bad, SE23_R(0.01), &B), SE23_ERR_NONFINITE);
    const se23_real_t bad_dt[] = {SE23_R(0), SE23_R(-0.01), (se23_real_t)NAN,
                                  SE23_R(SE23_CFG_DT_MAX) * SE23_R(1.5)};
    for (int k = 0; k < 4; ++k) {
        assert_int_equal(se23_gauss_input_jac(SE23_INPUT_JAC_EXACT, &w, &f, bad_dt[k], &B), SE23_ERR_DT);
        assert_int_equal(se23_gauss_input_jac(SE23_INPUT_JAC_BASIC, &w, &f, bad_dt[k], &B), SE23_ERR_DT);
    }
    assert_int_equal(se23_gauss_input_jac((se23_input_jac_kind_t)7, &w, &f, SE23_R(0.01), &B), SE23_ERR_DOMAIN);
    assert_memory_equal(&B, &B0, sizeof B);
}

static void test_input_jac_null_arguments_return_err_null(void **state)
{
    (void)state;
#if SE23_CFG_ARG_CHECKS
    const se23_vec3_t w = {{0}}, f = {{0}};
    se23_mat9x6_t B;
    assert_int_equal(se23_gauss_input_jac(SE23_INPUT_JAC_EXACT, NULL, &f, SE23_R(0.01), &B), SE23_ERR_NULL);
    assert_int_equal(se23_gauss_input_jac(SE23_INPUT_JAC_EXACT, &w, NULL, SE23_R(0.01), &B), SE23_ERR_NULL);
    assert_int_equal(se23_gauss_input_jac(SE23_INPUT_JAC_EXACT, &w, &f, SE23_R(0.01), NULL), SE23_ERR_NULL);
#else
    skip();
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_input_jac_exact_matches_central_differences),
        cmocka_unit_test(test_input_jac_exact_random_samples),
        cmocka_unit_test(test_input_jac_basic_is_dt_identity),
        cmocka_unit_test(test_input_jac_exact_tends_to_basic_for_small_dt),
        cmocka_unit_test(test_input_jac_rejects_bad_input_untouched),
        cmocka_unit_test(test_input_jac_null_arguments_return_err_null),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
