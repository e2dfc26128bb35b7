/* Unit tests of src/ins_step.c: the preintegrated factor the filter
 * publishes equals a factor built by preint_unc.h from the same samples at
 * the same bias estimate, and is handed out once. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "ins_test.h"
#include "se23/ins.h"
#include "se23/preint_unc.h"
#include "se23_test.h"

static se23_ins_t ins; /* large: static */

static void test_factor_equals_preint_unc_of_the_same_samples(void **state)
{
    (void)state;
    se23_ins_config_t c;
    se23_gauss_t g;
    se23_preint_unc_t ref;
    se23_ins_factor_t out;
    se23t_rng_t rng;
    it_config(&c, 1);
    c.zupt = 0;
    c.preint_window = SE23_R(1);
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    it_initial(15, 1e-3, 0.01, 0.1, &g);
    g.b_g.v[0] = (se23_real_t)1e-3;
    g.b_a.v[2] = (se23_real_t)0.02;
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_OK);
    assert_int_equal(se23_preint_unc_reset(&g.b_g, &g.b_a, SE23_INPUT_JAC_EXACT, &ref), SE23_OK);
    se23t_rng_seed(&rng, 3);
    for (int k = 1; k <= 200; ++k) {
        se23_imu_sample_t s;
        it_rest_sample(&rng, NULL, NULL, NULL, &s.w_ib_b, &s.f_b);
        assert_int_equal(se23_ins_take_factor(&ins, &out), 0);
        assert_int_equal(se23_ins_imu(&ins, k * IT_DT_NS, k, &s.w_ib_b, &s.f_b), SE23_INS_USED);
        s.dt = (se23_real_t)IT_DT_NS / SE23_R(1e9); /* as the filter forms it */
        assert_int_equal(se23_preint_unc_add(&ref, &s, &c.noise), SE23_OK);
    }
    assert_int_equal(se23_ins_take_factor(&ins, &out), 1);
    assert_int_equal(se23_ins_take_factor(&ins, &out), 0);
    assert_int_equal(out.f.f.n, 200);
    assert_int_equal(out.t0_ns, 0);
    assert_int_equal(out.t1_ns, 200 * IT_DT_NS);
    assert_int_equal(out.seq0, 1);
    assert_memory_equal(&out.f.f.delta, &ref.f.delta, sizeof ref.f.delta);
    assert_memory_equal(out.f.P.m, ref.P.m, sizeof ref.P.m);
    assert_memory_equal(out.f.J.m, ref.J.m, sizeof ref.J.m);
    assert_int_equal(se23_preint_unc_check(&out.f), SE23_OK);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_factor_equals_preint_unc_of_the_same_samples),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
