/* Tests of src/base/trig.c: se23_sincos against long double sinl/cosl over its
 * exact range and at the quadrant seams, sin^2 + cos^2 = 1 beyond it (one
 * reduction for both), and NaN for NaN and infinite arguments. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "se23_test.h"
#include "base/trig.h"

/* The epsilon long double really has here: 1e-19 natively, double's under
 * valgrind (which emulates x87 long double in double precision). */
static double reference_eps(void)
{
    volatile long double e = 1;
    while ((long double)1 + e / 2 != (long double)1) {
        e /= 2;
    }
    return (double)e;
}

/* Worst |error| in eps of the type: absolute where the value is above 1/2,
 * relative below (near a zero, as tiny arguments have tiny sines). */
static double worst;

static double err_eps(se23_real_t got, long double want)
{
    const long double scale = fabsl(want) > 0.5L ? 1.0L : fabsl(want);
    if (scale == 0.0L) {
        return got == 0 ? 0.0 : INFINITY;
    }
    return (double)(fabsl((long double)got - want) / scale) / SE23T_EPS;
}

static void check_at(se23_real_t x)
{
    se23_real_t s = 0, c = 0;
    se23_sincos(x, &s, &c);
    const double es = err_eps(s, sinl((long double)x));
    const double ec = err_eps(c, cosl((long double)x));
    const double e = es > ec ? es : ec;
    /* 1.5 times the worst measured (0.66 eps double, 0.63 float), plus the
     * reference's own rounding. */
    const double bound = 1.0 + (reference_eps() / SE23T_EPS);
    if (e > worst) {
        worst = e;
    }
    if (!(e <= bound)) {
        print_error("x = %.17g: sin %.17g, cos %.17g (%.2f eps)\n", (double)x, (double)s,
                    (double)c, e);
    }
    assert_true(e <= bound);
}

static void test_trig_matches_libm_within_exact_range(void **state)
{
    (void)state;
    const double fixed[] = {0.0, -0.0, 1e-30, -1e-30, 1e-8, 1e-3, 0.5, 0.785, 0.786, 1.5707963,
                            1.5707964, 3.1415926, 3.1415927, 4.712389, 6.2831853, 100.0};
    for (size_t i = 0; i < sizeof fixed / sizeof fixed[0]; ++i) {
        check_at((se23_real_t)fixed[i]);
        check_at((se23_real_t)-fixed[i]);
    }
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 5);
    for (int n = 0; n < 20000; ++n) {
        check_at((se23_real_t)se23t_uniform(&rng, -8, 8));
        check_at((se23_real_t)se23t_uniform(&rng, -(double)SE23_TRIG_EXACT_MAX,
                                            (double)SE23_TRIG_EXACT_MAX));
    }
    /* Either side of each multiple of pi/4 up to 1000 quadrants (the seams
     * of the reduction and of the kernels). */
    for (int k = -1000; k <= 1000; ++k) {
        const double q = k * 0.78539816339744830962;
        if (fabs(q) < (double)SE23_TRIG_EXACT_MAX) {
            check_at(nextafter((se23_real_t)q, (se23_real_t)-1e9));
            check_at(nextafter((se23_real_t)q, (se23_real_t)1e9));
        }
    }
    print_message("worst %.2f eps\n", worst);
}

/* Beyond the exact range: s and c of one angle, whatever its error. */
static void test_trig_is_consistent_beyond_exact_range(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 6);
    for (int n = 0; n < 20000; ++n) {
        const double mag = pow(10.0, se23t_uniform(&rng, log10((double)SE23_TRIG_EXACT_MAX),
                                                   log10(SE23T_REAL_MAX) - 0.01));
        const se23_real_t x = (se23_real_t)((n % 2 == 0) ? mag : -mag);
        se23_real_t s = 2, c = 2;
        se23_sincos(x, &s, &c);
        const double r = (double)s * s + (double)c * c;
        if (!(fabs(r - 1.0) <= 4 * SE23T_EPS)) {
            print_error("x = %.9g: s^2 + c^2 - 1 = %.3g\n", (double)x, r - 1.0);
        }
        assert_true(fabs(r - 1.0) <= 4 * SE23T_EPS);
    }
}

static void test_trig_nan_for_nonfinite(void **state)
{
    (void)state;
    const se23_real_t bad[] = {(se23_real_t)NAN, (se23_real_t)INFINITY, -(se23_real_t)INFINITY};
    for (size_t i = 0; i < 3; ++i) {
        se23_real_t s = 0, c = 0;
        se23_sincos(bad[i], &s, &c);
        assert_true(isnan(s) && isnan(c));
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_trig_matches_libm_within_exact_range),
        cmocka_unit_test(test_trig_is_consistent_beyond_exact_range),
        cmocka_unit_test(test_trig_nan_for_nonfinite),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
