/* Unit tests of src/nav/ins_delay.c: a fix delivered late (within the horizon)
 * gives bit for bit the state of the same fix delivered at its own time, in
 * both precisions, with zero-velocity updates in between; the horizon's
 * boundary; a ring overrun (samples faster than the nominal rate) degrades
 * to "stale", never to a wrong placement. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "ins_test.h"
#include "se23/ins.h"
#include "se23_test.h"

static se23_ins_t live, late; /* large: static */

#define FIX_EVERY 40 /* samples between fixes (0.2 s) */

/* One run of n samples (noise from seed) with a fix every FIX_EVERY
 * samples, delivered lag samples after its time. */
static void run(se23_ins_t *ins, int lag, int n, int zupt)
{
    se23_ins_config_t c;
    se23_gauss_t g;
    se23t_rng_t rng;
    const double b_a[3] = {0.02, -0.01, 0.005};
    it_config(&c, 1);
    c.zupt = zupt;
    assert_int_equal(se23_ins_setup(&c, ins), SE23_OK);
    it_initial(15, 1e-2, 0.1, 1.0, &g);
    assert_int_equal(se23_ins_init(ins, 0, &g), SE23_OK);
    se23t_rng_seed(&rng, 4242);
    for (int k = 1; k <= n; ++k) {
        se23_vec3_t w, f;
        it_rest_sample(&rng, NULL, NULL, b_a, &w, &f);
        assert_int_equal(se23_ins_imu(ins, k * IT_DT_NS, k, &w, &f), SE23_INS_USED);
        if (k > lag && (k - lag) % FIX_EVERY == 0) {
            const long long t_fix = (long long)(k - lag) * IT_DT_NS;
            se23t_rng_t r; /* the same noise for the same fix in both runs */
            double p[3];
            se23_ins_gnss_t fix;
            se23t_rng_seed(&r, (uint64_t)(k - lag));
            for (int i = 0; i < 3; ++i) {
                p[i] = 0.5 * se23t_normal(&r) + (double)(k - lag) * 1e-3;
            }
            it_fix(t_fix, p, 0.5, &fix);
            assert_int_equal(se23_ins_gnss(ins, &fix), SE23_INS_USED);
        }
    }
}

static void test_late_fix_equals_fix_at_its_own_time(void **state)
{
    (void)state;
    for (int zupt = 0; zupt <= 1; ++zupt) {
        const int n = 10 * FIX_EVERY + 20;
        run(&live, 0, n, zupt);
        run(&late, 20, n, zupt); /* 0.1 s late, horizon 0.25 s */
        assert_int_equal(live.c.gnss_used, 10);
        assert_int_equal(late.c.gnss_used, 10);
        assert_int_equal(live.c.gnss_delayed, 0);
        assert_int_equal(late.c.gnss_delayed, 10);
        if (zupt != 0) {
            assert_true(late.c.zupt_used > 0);
            assert_int_equal(late.c.zupt_used, live.c.zupt_used); /* replays not counted */
        }
        assert_int_equal(late.t_ns, live.t_ns);
        /* Same operations in the same order: the same bits. */
        assert_memory_equal(&late.g.T, &live.g.T, sizeof live.g.T);
        assert_memory_equal(&late.g.b_a, &live.g.b_a, sizeof live.g.b_a);
        assert_memory_equal(late.g.P.m, live.g.P.m, sizeof live.g.P.m);
    }
}

static void test_horizon_boundary(void **state)
{
    (void)state;
    const double p0[3] = {0.0, 0.0, 0.0};
    se23_ins_config_t c;
    se23_gauss_t g;
    se23_ins_gnss_t fix;
    it_config(&c, 0);
    assert_int_equal(se23_ins_setup(&c, &live), SE23_OK);
    it_initial(9, 1e-2, 0.1, 1.0, &g);
    assert_int_equal(se23_ins_init(&live, 0, &g), SE23_OK);
    assert_int_equal(it_run_rest(&live, NULL, NULL, 0, 0, 400), 400);
    /* The state is at sample 400: 0.25 s (50 samples) plus half a sample
     * back is the oldest placeable time. */
    it_fix(349 * IT_DT_NS, p0, 1.0, &fix);
    assert_int_equal(se23_ins_gnss(&live, &fix), SE23_INS_STALE);
    it_fix(350 * IT_DT_NS, p0, 1.0, &fix);
    assert_int_equal(se23_ins_gnss(&live, &fix), SE23_INS_USED);
    assert_int_equal(live.c.gnss_delayed, 1);
    assert_int_equal(live.t_ns, 400 * IT_DT_NS); /* replayed back to the present */
    it_fix(345 * IT_DT_NS + 1, p0, 1.0, &fix);
    assert_int_equal(se23_ins_gnss(&live, &fix), SE23_INS_STALE); /* before the last fused */
    /* without a horizon a late fix is stale */
    c.delay_horizon = SE23_R(0);
    assert_int_equal(se23_ins_setup(&c, &late), SE23_OK);
    assert_int_equal(se23_ins_init(&late, 0, &g), SE23_OK);
    assert_int_equal(it_run_rest(&late, NULL, NULL, 0, 0, 100), 100);
    it_fix(99 * IT_DT_NS, p0, 1.0, &fix);
    assert_int_equal(se23_ins_gnss(&late, &fix), SE23_INS_STALE);
}

static void test_ring_overrun_restarts_instead_of_misplacing(void **state)
{
    (void)state;
    const double p0[3] = {0.0, 0.0, 0.0};
    se23_ins_config_t c;
    se23_gauss_t g;
    se23_ins_gnss_t fix;
    it_config(&c, 0);
    c.delay_horizon = (se23_real_t)((SE23_INS_RING - 2) / (2.0 * IT_RATE));
    assert_int_equal(se23_ins_setup(&c, &live), SE23_OK);
    it_initial(9, 1e-2, 0.1, 1.0, &g);
    assert_int_equal(se23_ins_init(&live, 0, &g), SE23_OK);
    /* samples 5x faster than nominal: the ring fills before the horizon
     * and starts again */
    int restarts = 0;
    for (int k = 1; k <= 3 * SE23_INS_RING; ++k) {
        se23_vec3_t w, f;
        const int before = live.ring_count;
        it_rest_sample(NULL, NULL, NULL, NULL, &w, &f);
        assert_int_equal(se23_ins_imu(&live, k * (IT_DT_NS / 5), k, &w, &f), SE23_INS_USED);
        assert_true(live.ring_count <= SE23_INS_RING);
        restarts += live.ring_count < before;
    }
    assert_true(restarts >= 2);
    it_fix((3 * SE23_INS_RING - SE23_INS_RING / 2) * (IT_DT_NS / 5), p0, 1.0, &fix);
    {
        const se23_ins_verdict_t v = se23_ins_gnss(&live, &fix);
        assert_true(v == SE23_INS_USED || v == SE23_INS_STALE);
    }
    assert_int_equal(live.c.filter_errors, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_late_fix_equals_fix_at_its_own_time),
        cmocka_unit_test(test_horizon_boundary),
        cmocka_unit_test(test_ring_overrun_restarts_instead_of_misplacing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
