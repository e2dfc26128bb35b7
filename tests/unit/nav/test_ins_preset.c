/* Unit tests of src/nav/ins_preset.c: the detector threshold against the
 * table of stationary.h (chi^2_{6W-2} quantiles), and the pedestrian
 * preset: accepted by se23_ins_setup and se23_ins_align as it is, its
 * window a quarter of the shortest stance at any rate, its domain. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "se23/ins.h"
#include "se23_test.h"

static se23_ins_t ins; /* large: static */

static void test_threshold_matches_the_chi2_table(void **state)
{
    (void)state;
    /* stationary.h: W 5 / 10 / 20 / 32 at alpha = 0.01 (z = 2.3263) */
    const int W[] = {5, 10, 20, 32};
    const double expect[] = {9.656, 8.595, 7.832, 7.446};
    for (int k = 0; k < 4; ++k) {
        /* Wilson-Hilferty: within 0.2 % of the exact quantile (W >= 5) */
        assert_near((double)se23_ins_detector_threshold(W[k], (se23_real_t)2.3263479),
                    expect[k], 0.0, 2e-3);
    }
    /* alpha = 0.05 (z = 1.6449) */
    assert_near((double)se23_ins_detector_threshold(20, (se23_real_t)1.6448536), 7.218, 0.0,
                2e-3);
}

static void test_foot_preset_is_usable_at_every_rate(void **state)
{
    (void)state;
    const double rates[] = {50.0, 100.0, 400.0, 1000.0, 10000.0};
    for (int k = 0; k < 5; ++k) {
        se23_ins_config_t c;
        se23_ins_align_t a;
        assert_int_equal(se23_ins_preset_foot((se23_real_t)rates[k], (se23_real_t)0.9, &c, &a),
                         SE23_OK);
        assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
        assert_int_equal(se23_ins_align(&ins, &a), SE23_OK);
        /* 12.5 ms, clipped to [2, WMAX] samples */
        {
            const double w = rates[k] * 0.0125;
            const double expect = w < 2.0 ? 2.0 : w > SE23_STATIONARY_WMAX ? SE23_STATIONARY_WMAX
                                                                           : floor(w + 0.5);
            assert_int_equal(c.detector.window, (int)expect);
        }
        assert_true(c.zupt == 1 && c.bias_states == 1 && c.earth_rotation == 0);
        assert_true(c.zaru_sigma_w > SE23_R(0) && c.zaru_after > SE23_R(0));
    }
}

static void test_foot_preset_domain(void **state)
{
    (void)state;
    se23_ins_config_t c, c0;
    se23_ins_align_t a, a0;
    memset(&c, 0x5a, sizeof c);
    memset(&a, 0x5a, sizeof a);
    c0 = c;
    a0 = a;
    assert_int_equal(se23_ins_preset_foot(SE23_R(49), SE23_R(0), &c, &a), SE23_ERR_DOMAIN);
    assert_int_equal(se23_ins_preset_foot((se23_real_t)NAN, SE23_R(0), &c, &a), SE23_ERR_DOMAIN);
    assert_int_equal(se23_ins_preset_foot(SE23_R(400), SE23_R(3), &c, &a), SE23_ERR_DOMAIN);
    assert_int_equal(se23_ins_preset_foot(SE23_R(400), SE23_R(0), NULL, &a), SE23_ERR_NULL);
    assert_memory_equal(&c, &c0, sizeof c);
    assert_memory_equal(&a, &a0, sizeof a);
}

/* Regression (fuzz_ins, issue 37 S2): se23_ins_preset_foot(100, +-(pi/2 +
 * 5e-7)) returned SE23_OK with a configuration se23_ins_setup refused
 * (SE23_ERR_DOMAIN). Both judge lat by se23_earth_gravity's rule, |lat| <=
 * pi/2 + SE23_EARTH_LAT_SLACK: within it, the preset's configuration is
 * set up; beyond it, both refuse. */
static void test_foot_preset_and_setup_share_the_latitude_rule(void **state)
{
    (void)state;
    const double half_pi = 1.57079632679489661923;
    for (int sign = -1; sign <= 1; sign += 2) {
        se23_ins_config_t c;
        se23_ins_align_t a;
        se23_real_t lat = (se23_real_t)(sign * (half_pi + 5e-7));
        assert_int_equal(se23_ins_preset_foot(SE23_R(100), lat, &c, &a), SE23_OK);
        assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
        assert_int_equal(se23_ins_align(&ins, &a), SE23_OK);
        /* beyond the slack: the preset refuses, and so does setup */
        lat = (se23_real_t)(sign * (half_pi + 2e-6));
        assert_int_equal(se23_ins_preset_foot(SE23_R(100), lat, &c, &a), SE23_ERR_DOMAIN);
        c.lat = lat;
        assert_int_equal(se23_ins_setup(&c, &ins), SE23_ERR_DOMAIN);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_threshold_matches_the_chi2_table),
        cmocka_unit_test(test_foot_preset_is_usable_at_every_rate),
        cmocka_unit_test(test_foot_preset_domain),
        cmocka_unit_test(test_foot_preset_and_setup_share_the_latitude_rule),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
