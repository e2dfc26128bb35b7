/* Unit tests of src/nav/ins_outage.c: a forward jump of the stream is confirmed
 * by SE23_INS_OUTAGE_CONFIRM consistent samples and carried across with the
 * covariance inflated; inconsistent over-gap samples never confirm one; an
 * outage beyond max_outage (even of years) loses the state at bounded cost
 * and a new init recovers. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "ins_test.h"
#include "se23/ins.h"
#include "se23_test.h"

static se23_ins_t ins; /* large: static */

static void start(void)
{
    se23_ins_config_t c;
    se23_gauss_t g;
    it_config(&c, 1);
    c.zupt = 0;
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    it_initial(15, 1e-3, 0.01, 0.1, &g);
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_OK);
    assert_int_equal(it_run_rest(&ins, NULL, NULL, 0, 0, 100), 100);
}

static se23_ins_verdict_t sample(long long t, long long seq)
{
    se23_vec3_t w, f;
    it_rest_sample(NULL, NULL, NULL, NULL, &w, &f);
    return se23_ins_imu(&ins, t, seq, &w, &f);
}

static void test_outage_confirmed_and_carried_across(void **state)
{
    (void)state;
    const long long t0 = 100 * IT_DT_NS + 2000000000LL; /* 2 s later */
    double p_before, p_after;
    start();
    p_before = (double)ins.g.P.m[SE23_GAUSS_NMAX * 6 + 6];
    assert_int_equal(sample(t0, 501), SE23_INS_BAD_DT);
    assert_int_equal(sample(t0 + IT_DT_NS, 502), SE23_INS_BAD_DT);
    assert_int_equal(sample(t0 + 2 * IT_DT_NS, 503), SE23_INS_OUTAGE);
    assert_int_equal(ins.c.time_resets, 1);
    assert_int_equal(ins.c.imu_bad_dt, 3);
    assert_int_equal(ins.t_ns, t0 + 2 * IT_DT_NS);
    assert_true((ins.status & SE23_INS_ST_DEGRADED) != 0);
    p_after = (double)ins.g.P.m[SE23_GAUSS_NMAX * 6 + 6];
    /* rho grows by at least (a t^2 / 2)^2 with a = 1 m/s^2, t = 2 s */
    assert_true(p_after >= p_before + 4.0 - 1e-3);
    assert_int_equal(se23_gauss_check(&ins.g), SE23_OK);
    /* the stream goes on from there, and a fix ends the degraded state */
    assert_int_equal(sample(t0 + 3 * IT_DT_NS, 504), SE23_INS_USED);
    {
        const double p0[3] = {0.0, 0.0, 0.0};
        se23_ins_gnss_t fix;
        it_fix(t0 + 3 * IT_DT_NS, p0, 1.0, &fix);
        assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_USED);
        assert_int_equal(ins.status & SE23_INS_ST_DEGRADED, 0);
    }
}

static void test_inconsistent_over_gap_samples_never_confirm(void **state)
{
    (void)state;
    const long long t0 = 100 * IT_DT_NS + 2000000000LL;
    start();
    for (int k = 0; k < 20; ++k) { /* seq not consecutive */
        assert_int_equal(sample(t0 + k * IT_DT_NS, 1000 + 2 * k), SE23_INS_BAD_DT);
    }
    for (int k = 0; k < 20; ++k) { /* consecutive seq, but 1 s apart */
        assert_int_equal(sample(t0 + 1000000000LL * (k + 1), 5000 + k), SE23_INS_BAD_DT);
    }
    assert_int_equal(ins.c.time_resets, 0);
    assert_int_equal(ins.t_ns, 100 * IT_DT_NS);
}

static void test_outage_beyond_the_limit_loses_the_state(void **state)
{
    (void)state;
    const long long years = 100000000000000000LL; /* 3 years */
    se23_gauss_t g, out;
    int64_t t;
    start();
    assert_int_equal(sample(years, 1), SE23_INS_BAD_DT);
    assert_int_equal(sample(years + IT_DT_NS, 2), SE23_INS_BAD_DT);
    assert_int_equal(sample(years + 2 * IT_DT_NS, 3), SE23_INS_OUTAGE);
    assert_true((ins.status & SE23_INS_ST_LOST) != 0);
    assert_int_equal(ins.status & SE23_INS_ST_INITIALISED, 0);
    assert_int_equal(sample(years + 3 * IT_DT_NS, 4), SE23_INS_EARLY);
    assert_int_equal(se23_ins_state(&ins, &out, &t), SE23_ERR_DIM);
    it_initial(15, 1e-3, 0.01, 0.1, &g);
    assert_int_equal(se23_ins_init(&ins, years + 3 * IT_DT_NS, &g), SE23_OK);
    assert_int_equal(ins.status & SE23_INS_ST_LOST, 0);
    assert_int_equal(sample(years + 4 * IT_DT_NS, 5), SE23_INS_USED);
}

/* A clock that steps back by an hour and stays there is re-based on; a
 * single stale timestamp, or stale ones out of sequence, are not. */
static void test_clock_stepped_back_is_recovered(void **state)
{
    (void)state;
    const long long t0 = 3700000000000LL; /* the clock will step back by 1 h */
    se23_ins_config_t c;
    se23_gauss_t g;
    it_config(&c, 1);
    c.zupt = 0;
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    it_initial(15, 1e-3, 0.01, 0.1, &g);
    assert_int_equal(se23_ins_init(&ins, t0, &g), SE23_OK);
    assert_int_equal(it_run_rest(&ins, NULL, NULL, t0, 0, 100), 100);
    {
        const long long tb = t0 + 100 * IT_DT_NS - 3600000000000LL;
        /* one stale sample, then the stream goes on: no step */
        assert_int_equal(sample(tb, 101), SE23_INS_BAD_TIME);
        assert_int_equal(sample(t0 + 101 * IT_DT_NS, 102), SE23_INS_USED);
        /* stale samples out of sequence: no step */
        assert_int_equal(sample(tb, 103), SE23_INS_BAD_TIME);
        assert_int_equal(sample(tb + IT_DT_NS, 105), SE23_INS_BAD_TIME);
        assert_int_equal(sample(tb + 2 * IT_DT_NS, 107), SE23_INS_BAD_TIME);
        assert_int_equal(ins.c.time_resets, 0);
        /* the clock really stepped back: consecutive and consistent */
        assert_int_equal(sample(tb + 10 * IT_DT_NS, 110), SE23_INS_BAD_TIME);
        assert_int_equal(sample(tb + 11 * IT_DT_NS, 111), SE23_INS_BAD_TIME);
        assert_int_equal(sample(tb + 12 * IT_DT_NS, 112), SE23_INS_OUTAGE);
        assert_int_equal(ins.c.time_resets, 1);
        assert_true((ins.status & SE23_INS_ST_DEGRADED) != 0);
        assert_int_equal(ins.t_ns, tb + 12 * IT_DT_NS);
        for (int k = 13; k < 40; ++k) {
            assert_int_equal(sample(tb + k * IT_DT_NS, 100 + k), SE23_INS_USED);
        }
        assert_int_equal(ins.c.imu_bad_time, 7);
        assert_int_equal(se23_gauss_check(&ins.g), SE23_OK);
    }
}

/* Regression (fuzz_ins, issue 37 S10): outage_accel 1e150 (double) or
 * 3e14 (float) passed se23_ins_setup; a 100 s outage on flat Earth then
 * left a covariance se23_ins_state refused (SE23_ERR_NONFINITE, documented
 * for rotating Earth only) and later samples failed. The outage's 1-sigmas
 * are bounded by the sensor ranges (ins.h), nothing written on refusal. */
static void test_outage_sigma_beyond_the_sensor_range_is_refused(void **state)
{
    (void)state;
    se23_ins_config_t c;
    static se23_ins_t before;
    it_config(&c, 1);
#if SE23_CFG_DOUBLE
    c.outage_accel = SE23_R(1e150);
#else
    c.outage_accel = SE23_R(3e14);
#endif
    c.max_outage = SE23_INS_MAX_OUTAGE;
    memset(&ins, 0x5a, sizeof ins);
    memcpy(&before, &ins, sizeof ins);
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_ERR_DOMAIN);
    assert_memory_equal(&ins, &before, sizeof ins);
    c.outage_accel = SE23_R(1);
    c.outage_rate = SE23_R(1e3); /* above the 30 rad/s range */
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_ERR_DOMAIN);
    assert_memory_equal(&ins, &before, sizeof ins);
}

/* The largest outage at the largest configuration the bounds allow (ranges
 * at their maxima, the outage's 1-sigmas at the ranges), again and again
 * on flat Earth: the inflation raises no variance above SE23_INS_P_MAX,
 * se23_ins_state answers SE23_OK every time and the stream goes on. */
static void test_outages_at_the_bounds_keep_the_state_finite(void **state)
{
    (void)state;
    const long long outage = 600000000000LL; /* SE23_INS_MAX_OUTAGE */
    const double cap = (double)SE23_INS_P_MAX * (1.0 + 1e-6);
    se23_ins_config_t c;
    se23_gauss_t g, out;
    int64_t t;
    long long t0 = 100 * IT_DT_NS, seq = 100;
    it_config(&c, 1);
    c.zupt = 0;
    c.accel_range = SE23_INS_ACCEL_RANGE_MAX;
    c.gyro_range = SE23_INS_GYRO_RANGE_MAX;
    c.outage_accel = c.accel_range + SE23_R(10);
    c.outage_rate = c.gyro_range;
    c.max_outage = SE23_INS_MAX_OUTAGE;
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    it_initial(15, 1e-3, 0.01, 0.1, &g);
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_OK);
    assert_int_equal(it_run_rest(&ins, NULL, NULL, 0, 0, 100), 100);
    for (int k = 0; k < 4; ++k) {
        const long long ts = t0 + outage - 2 * IT_DT_NS; /* the third sample: 600 s */
        double before[15];
        for (int i = 0; i < 15; ++i) {
            before[i] = (double)ins.g.P.m[16 * i];
        }
        assert_int_equal(sample(ts, seq + 1), SE23_INS_BAD_DT);
        assert_int_equal(sample(ts + IT_DT_NS, seq + 2), SE23_INS_BAD_DT);
        assert_int_equal(sample(ts + 2 * IT_DT_NS, seq + 3), SE23_INS_OUTAGE);
        assert_int_equal(ins.c.time_resets, (uint32_t)(k + 1));
        assert_int_equal(se23_ins_state(&ins, &out, &t), SE23_OK);
        for (int i = 0; i < 15; ++i) {
            const double d = (double)out.P.m[16 * i];
            assert_true(isfinite(d) && d >= 0.0);
            if (k == 0) { /* the first outage starts far below the cap */
                assert_true(before[i] < (double)SE23_INS_P_MAX);
                assert_true(d <= cap);
            }
        }
        /* the outage itself grew them by at least what it added, or to the cap */
        assert_true((double)out.P.m[16 * 6] >=
                    (1.0 - 1e-6) * fmin(before[6] + 1e12, (double)SE23_INS_P_MAX));
        t0 = ts + 2 * IT_DT_NS;
        seq += 3;
        assert_int_equal(it_run_rest(&ins, NULL, NULL, t0, seq, 20), 20);
        t0 += 20 * IT_DT_NS;
        seq += 20;
        assert_int_equal(se23_ins_state(&ins, &out, &t), SE23_OK);
    }
    assert_int_equal(ins.c.filter_errors, 0);
}

/* An initial covariance no step could carry is refused where it enters. */
static void test_huge_initial_covariance_is_refused(void **state)
{
    (void)state;
    se23_ins_config_t c;
    se23_gauss_t g;
    it_config(&c, 1);
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    it_initial(15, 1e-3, 0.01, 1e10, &g); /* variance 1e20: finite, valid, useless */
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_ERR_DOMAIN);
    it_initial(15, 1e-3, 0.01, 1e6, &g); /* the limit: variance 1e12 */
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_OK);
    it_initial(15, 1e-3, 0.01, 1.01e6, &g);
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_ERR_DOMAIN);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_outage_confirmed_and_carried_across),
        cmocka_unit_test(test_inconsistent_over_gap_samples_never_confirm),
        cmocka_unit_test(test_outage_beyond_the_limit_loses_the_state),
        cmocka_unit_test(test_clock_stepped_back_is_recovered),
        cmocka_unit_test(test_huge_initial_covariance_is_refused),
        cmocka_unit_test(test_outage_sigma_beyond_the_sensor_range_is_refused),
        cmocka_unit_test(test_outages_at_the_bounds_keep_the_state_finite),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
