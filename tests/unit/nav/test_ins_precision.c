/* The filter on a precise measurement against a vague prior (issue 37, S5):
 * the first fix or ZUPT pins a state far below the scale of its prior, a
 * ratio beyond 1/eps. Whatever the update makes of it, the filter must
 * never hold, nor report with SE23_OK, a state that se23_gauss_check
 * refuses, and the fixes that follow must be fused. Both precisions. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>

#include <cmocka.h>

#include "ins_test.h"
#include "se23/gauss.h"
#include "se23_test.h"

static se23_ins_t ins;

/* se23_ins_state's answer is a state se23_gauss_check accepts. */
static void assert_state_valid(void)
{
    se23_gauss_t g;
    int64_t t;
    assert_int_equal(se23_ins_state(&ins, &g, &t), SE23_OK);
    assert_int_equal(se23_gauss_check(&g), SE23_OK);
}

/* Float: position 1-sigma 1 km and 1 cm fixes; double: 10 km and 1 um.
 * The Schur complement alone left P(6,6) = -0.125 (float), -1.5e-8
 * (double) after the first fix, and 9 of the next 10 fixes failed. */
static void test_precise_fixes_on_a_vague_position(void **state)
{
    (void)state;
#if SE23_CFG_DOUBLE
    const double s_p = 1e4, s_fix = 1e-6;
#else
    const double s_p = 1e3, s_fix = 1e-2;
#endif
    se23_ins_config_t c;
    se23_gauss_t g;
    it_config(&c, 1);
    c.zupt = 0;
    c.gnss_gate = SE23_R(0); /* no gate: every fix is fused */
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    it_initial(15, 0.01, 0.1, s_p, &g);
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_OK);
    const double p[3] = {0, 0, 0};
    for (int k = 1; k <= 11; ++k) {
        se23_ins_gnss_t fix;
        assert_int_equal(it_run_rest(&ins, NULL, NULL, (k - 1) * 20 * IT_DT_NS,
                                     (k - 1) * 20, 20), 20);
        it_fix(k * 20 * IT_DT_NS, p, s_fix, &fix);
        assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_USED);
        assert_state_valid();
    }
    assert_int_equal(ins.c.filter_errors, 0);
    assert_int_equal(ins.c.gnss_used, 11);
    se23_gauss_t out;
    int64_t t;
    assert_int_equal(se23_ins_state(&ins, &out, &t), SE23_OK);
    for (int i = 6; i < 9; ++i) {
        const double sd = sqrt((double)out.P.m[16 * i]);
        assert_true(sd > 0.1 * s_fix && sd <= s_fix);
    }
}

/* Velocity 1-sigma 1 km/s and the filter at rest: its ZUPTs pin the
 * velocity to 1 cm/s (1e10 below the prior) while the position has been
 * correlated with it by the samples before the first one. */
static void test_zupts_on_a_vague_velocity(void **state)
{
    (void)state;
    se23_ins_config_t c;
    se23_gauss_t g;
    it_config(&c, 1);
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    it_initial(15, 0.01, 1e3, 0.01, &g);
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_OK);
    for (int k = 0; k < 20; ++k) {
        (void)it_run_rest(&ins, NULL, NULL, k * 10 * IT_DT_NS, k * 10, 10);
        assert_state_valid();
    }
    /* In float the first few cannot be honoured (the position's variance
     * would come out beyond the check): they are refused, the state kept
     * (filter_errors), and the later ones pin the velocity. */
    print_message("ZUPTs fused %u, refused %u\n", (unsigned)ins.c.zupt_used,
                  (unsigned)ins.c.filter_errors);
    assert_true(ins.c.zupt_used > ins.c.filter_errors);
    se23_gauss_t out;
    int64_t t;
    assert_int_equal(se23_ins_state(&ins, &out, &t), SE23_OK);
    assert_true(sqrt((double)out.P.m[16 * 3]) < 0.1);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_precise_fixes_on_a_vague_position),
        cmocka_unit_test(test_zupts_on_a_vague_velocity),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
