/* Tests of src/lie/so3_series.c: every coefficient against its closed form
 * evaluated in long double, across both branches and at their seams. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "se23_test.h"
#include "lie/so3_series.h"

/* Reference in long double: below theta = 1 each Taylor series summed
 * term by term (truncation < 1e-19, no cancellation); above, the closed
 * forms, whose cancellation then costs at most about 12 ulp of the type
 * (long double natively; double under valgrind, which emulates x87 long
 * double in double precision). */
static void expected_coeffs(long double t, long double out[7])
{
    long double t2 = t * t;
    if (t < 1.0L) {
        /* c_m = sum (-t2)^k/(2k+m)!; k1, k2 likewise; e from its table. */
        /* e = sum (-1)^(n+1) B_2n theta^(2n-2) / (2n)!, radius 2 pi: 13
         * terms reach 1e-20 at theta = 1. */
        static const long double e_series[13] = {
            1.0L / 12.0L,
            1.0L / 720.0L,
            1.0L / 30240.0L,
            1.0L / 1209600.0L,
            1.0L / 47900160.0L,
            691.0L / 1307674368000.0L,
            1.0L / 74724249600.0L,
            3617.0L / 10670622842880000.0L,
            43867.0L / 5109094217170944000.0L,
            174611.0L / 802857662698291200000.0L,
            77683.0L / 14101100039391805440000.0L,
            236364091.0L / 1693824136731743669452800000.0L,
            657931.0L / 186134520519971831808000000.0L,
        };
        for (int i = 0; i < 7; ++i) {
            out[i] = 0;
        }
        for (int m = 1; m <= 4; ++m) {
            long double term = 1;
            for (int j = 2; j <= m; ++j) {
                term /= j;
            }
            for (int k = 0; k < 16; ++k) {
                out[m - 1] += term;
                term *= -t2 / ((2 * k + m + 1) * (2 * k + m + 2));
            }
        }
        long double f1 = 1, f2 = 2; /* (2k+1)!, (2k+2)! */
        long double p = 1;
        for (int k = 0; k < 16; ++k) {
            out[4] += p / (f1 * (2 * k + 3));
            out[5] += p / (f2 * (2 * k + 4));
            p *= -t2;
            f1 *= (2 * k + 2) * (2 * k + 3);
            f2 *= (2 * k + 3) * (2 * k + 4);
        }
        long double q = 1;
        for (int k = 0; k < 13; ++k) {
            out[6] += e_series[k] * q;
            q *= t2;
        }
        return;
    }
    long double s = sinl(t), c = cosl(t);
    out[0] = s / t;
    out[1] = (1 - c) / t2;
    out[2] = (t - s) / (t2 * t);
    out[3] = (t2 / 2 + c - 1) / (t2 * t2);
    out[4] = (s - t * c) / (t2 * t);
    out[5] = (t2 / 2 - c - t * s + 1) / (t2 * t2);
    out[6] = (1 - (t / 2) * cosl(t / 2) / sinl(t / 2)) / t2;
}

/* The epsilon long double really has here: 1e-19 natively, but double's
 * under valgrind. The reference's own rounding is added to the bound. */
static double reference_eps(void)
{
    volatile long double e = 1;
    while ((long double)1 + e / 2 != (long double)1) {
        e /= 2;
    }
    return (double)e;
}

/* Worst |got - expected| / (eps * scale) per coefficient over the run. */
static double worst_ulps[7];

static void check_at(se23_real_t theta)
{
    static double ref_eps = 0;
    if (ref_eps == 0) {
        ref_eps = reference_eps();
    }
    long double e[7];
    expected_coeffs((long double)theta, e);
    se23_so3_coeffs_t c;
    se23_real_t k1, k2;
    se23_so3_coeffs(theta, &c);
    se23_so3_k_coeffs(theta, &k1, &k2);
    const se23_real_t got[7] = {c.c1, c.c2, c.c3, c.c4, k1, k2,
                                se23_so3_jl_inv_coeff(theta)};
    for (int i = 0; i < 7; ++i) {
        /* The bound: 16 epsilon relative, both precisions, plus
         * the reference's own cancellation (about 16 of its ulp). c1 and k1
         * have zeros (sin theta = 0, tan theta = theta): there the bound is
         * relative to their size, as closed forms are only absolutely
         * accurate near a zero. */
        double scale = fabs((double)e[i]) > 0.05 ? fabs((double)e[i]) : 0.05;
        double tol = 16 * (SE23T_EPS + ref_eps) * scale;
        double ulps = fabs((double)got[i] - (double)e[i]) / ((SE23T_EPS + ref_eps) * scale);
        if (ulps > worst_ulps[i]) {
            worst_ulps[i] = ulps;
        }
        if (!se23t_near(got[i], (double)e[i], tol, 0)) {
            print_error("coefficient %d at theta = %.9g\n", i, (double)theta);
        }
        assert_near(got[i], (double)e[i], tol, 0);
    }
}

static void test_so3_series_coeffs_match_closed_forms(void **state)
{
    (void)state;
    const double angles[] = {0.0, 1e-30, 1e-8, 1e-5, 1e-3, 0.1, 0.4999, 0.5, 0.5001,
                             0.9999, 1.0, 1.0001, 1.4999, 1.5, 1.5001, 1.9999,
                             2.0, 2.0001, 3.0, 3.14159, 4.0, 5.0, 6.0};
    for (size_t i = 0; i < sizeof angles / sizeof angles[0]; ++i) {
        check_at((se23_real_t)angles[i]);
    }
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 21);
    for (int n = 0; n < 2000; ++n) {
        check_at((se23_real_t)se23t_uniform(&rng, 0, 6.2));
    }
    /* At the accuracy the code reaches, not only the 16 eps requirement:
     * the worst errors measured over these angles (c1, c2, c3, c4, k1, k2,
     * jl_inv; double 0.99 / 1.20 / 1.81 / 8.12 / 2.51 / 6.44 / 2.07 eps,
     * float 1.25 / 1.14 / 1.47 / 1.19 / 1.70 / 1.71 / 1.76 eps, with the
     * sine and cosine of trig.c), bounded at 1.5 to 2 times that. A dropped
     * series term (e.g. the ninth Horner term of c1: 15.3 eps near
     * theta = 1) fails here. */
    if (SE23_CFG_DOUBLE && (reference_eps() > 1e-17)) {
        /* long double computed in double (valgrind): the reference cannot
         * resolve these bounds; the native runs (sanitizer trees) check them */
        print_message("reference without extended precision: tight bounds not checked\n");
        return;
    }
#if SE23_CFG_DOUBLE
    const double reached[7] = {1.5, 2.7, 2.9, 16.0, 4.3, 12.9, 3.1};
#else
    const double reached[7] = {1.9, 2.4, 2.2, 2.6, 3.8, 2.6, 2.7};
#endif
    int within = 1;
    for (int i = 0; i < 7; ++i) {
        print_message("coefficient %d: worst %.2f eps (bound %.1f)\n", i, worst_ulps[i],
                      reached[i]);
        within = within && (worst_ulps[i] <= reached[i]);
    }
    assert_true(within);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_so3_series_coeffs_match_closed_forms),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
