/* Unit tests of src/nav/ins_aid.c: zero-velocity updates hold a body at rest
 * at zero velocity within their noise and make the vertical accelerometer
 * bias and the gyro bias observable; the GNSS lever arm (position and
 * velocity) places the body, not the antenna, at the fix; gate recovery
 * after a configured run of gated fixes, and never without it. */
#include <math.h>
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

static void start(se23_ins_config_t *c, int n)
{
    se23_gauss_t g;
    assert_int_equal(se23_ins_setup(c, &ins), SE23_OK);
    it_initial(n, 1e-2, 0.1, 1.0, &g);
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_OK);
}

static double P_at(const se23_gauss_t *g, int i)
{
    return (double)g->P.m[SE23_GAUSS_NMAX * i + i];
}

static void test_zupt_holds_rest_and_estimates_biases(void **state)
{
    (void)state;
    /* biases the detector tolerates at its threshold (|b| ~ sigma) */
    const double b_g[3] = {5e-4, -3e-4, 4e-4};
    const double b_a[3] = {0.0, 0.0, 0.008};
    se23_ins_config_t c;
    se23_gauss_t out;
    se23t_rng_t rng;
    int64_t t;
    it_config(&c, 1);
    start(&c, 15);
    se23t_rng_seed(&rng, 7);
    for (int k = 1; k <= 60 * 200; ++k) { /* 60 s at rest */
        se23_vec3_t w, f;
        it_rest_sample(&rng, NULL, b_g, b_a, &w, &f);
        assert_int_equal(se23_ins_imu(&ins, k * IT_DT_NS, k, &w, &f), SE23_INS_USED);
    }
    assert_int_equal(se23_ins_state(&ins, &out, &t), SE23_OK);
    /* the detector saw rest nearly always (threshold 12 for a mean of ~6) */
    assert_true(ins.c.zupt_used > 60 * 200 * 9 / 10);
    assert_int_equal(ins.c.zaru_used, ins.c.zupt_used);
    for (int i = 0; i < 3; ++i) {
        const double sv = sqrt(P_at(&out, 3 + i));
        assert_true(sv < 0.01); /* no more than the ZUPT's own 1-sigma */
        assert_true(fabs((double)out.T.v.v[i]) < 4.0 * sv);
        /* gyro bias: observable at rest through ZARU (b estimates add to w_meas) */
        const double sbg = sqrt(P_at(&out, 9 + i));
        assert_true(sbg < 1e-4);
        assert_true(fabs((double)out.b_g.v[i] - b_g[i]) < 4.0 * sbg + 1e-5);
    }
    /* vertical accelerometer bias: observable through ZUPT (the horizontal
     * ones are a tilt at rest, the prior keeps them) */
    {
        const double sba = sqrt(P_at(&out, 14));
        assert_true(sba < 1e-3); /* prior 3.2e-2 */
        assert_true(fabs((double)out.b_a.v[2] - b_a[2]) < 4.0 * sba);
        assert_true(fabs((double)out.b_a.v[2] - b_a[2]) < 2e-3);
    }
    /* without ZUPT the same run drifts: the test can fail */
    c.zupt = 0;
    start(&c, 15);
    se23t_rng_seed(&rng, 7);
    for (int k = 1; k <= 10 * 200; ++k) {
        se23_vec3_t w, f;
        it_rest_sample(&rng, NULL, b_g, b_a, &w, &f);
        (void)se23_ins_imu(&ins, k * IT_DT_NS, k, &w, &f);
    }
    assert_int_equal(se23_ins_state(&ins, &out, &t), SE23_OK);
    assert_true(fabs((double)out.T.v.v[2]) > 0.05); /* ~ b_a t = 0.08 m/s */
}

/* zupt_nis_sum is the NIS of the live ZUPTs: a body at rest started with a
 * velocity error v0 (1-sigma 0.1 m/s) gives at its first ZUPT
 * sum_i v0_i^2 / (P_v + sigma_z^2), P_v grown by the 0.1 s of prediction
 * before the detector's first window (about 1 %, within the 5 % allowed). */
static void test_zupt_nis_sums_the_innovations(void **state)
{
    (void)state;
    const double v0[3] = {0.15, -0.1, 0.05}, sv = 0.1;
    se23_ins_config_t c;
    se23_gauss_t g;
    it_config(&c, 1);
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    it_initial(15, 1e-2, sv, 1.0, &g);
    for (int i = 0; i < 3; ++i) {
        g.T.v.v[i] = (se23_real_t)v0[i];
    }
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_OK);
    const double sz2 = (double)c.zupt_sigma_v * (double)c.zupt_sigma_v;
    const double want = (v0[0] * v0[0] + v0[1] * v0[1] + v0[2] * v0[2]) / (sv * sv + sz2);
    int k = 0;
    while (ins.c.zupt_used == 0U && k < 200) {
        se23_vec3_t w, f;
        ++k;
        assert_true((double)ins.zupt_nis_sum == 0.0);
        it_rest_sample(NULL, NULL, NULL, NULL, &w, &f);
        assert_int_equal(se23_ins_imu(&ins, k * IT_DT_NS, k, &w, &f), SE23_INS_USED);
    }
    assert_int_equal(ins.c.zupt_used, 1);
    assert_true(fabs((double)ins.zupt_nis_sum - want) < 0.05 * want);
}

/* A level body at rest at the origin with the antenna at lever l: fixes at
 * l (R = I). With the lever configured the body goes to the origin; with
 * it not, it goes to the antenna. */
static void test_lever_arm_places_the_body(void **state)
{
    (void)state;
    const double lever[3] = {0.5, -0.3, -1.0};
    for (int with_lever = 0; with_lever <= 1; ++with_lever) {
        se23_ins_config_t c;
        se23_gauss_t out;
        int64_t t;
        it_config(&c, 1);
        for (int i = 0; i < 3; ++i) {
            c.lever_b.v[i] = (se23_real_t)(with_lever ? lever[i] : 0.0);
        }
        start(&c, 15);
        for (int k = 1; k <= 10 * 200; ++k) {
            se23_vec3_t w, f;
            it_rest_sample(NULL, NULL, NULL, NULL, &w, &f);
            assert_int_equal(se23_ins_imu(&ins, k * IT_DT_NS, k, &w, &f), SE23_INS_USED);
            if (k % 40 == 0) {
                se23_ins_gnss_t fix;
                it_fix(k * IT_DT_NS, lever, 0.05, &fix);
                fix.has_vel = 1;
                for (int i = 0; i < 3; ++i) {
                    fix.sigma_v.v[i] = (se23_real_t)0.05;
                }
                assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_USED);
            }
        }
        assert_int_equal(se23_ins_state(&ins, &out, &t), SE23_OK);
        for (int i = 0; i < 3; ++i) {
            const double expect = with_lever ? 0.0 : lever[i];
            assert_near((double)out.T.p.v[i], expect, 0.02, 0.0);
            assert_near((double)out.T.v.v[i], 0.0, 0.01, 0.0);
        }
    }
}

/* A fix stamped 2 ms after the state's sample (within half a 200 Hz
 * sample: fused now) is moved to the state's time along the velocity: a
 * body cruising at 20 m/s, exact fixes (1 cm) at t_k + 2 ms; the state
 * lands within 5 mm of the truth at its own time, where taking the fix as
 * the state's would put it 4 cm ahead. Fixes 2 ms before the sample, the
 * same. */
static void test_fix_within_half_a_sample_is_moved_to_the_state(void **state)
{
    (void)state;
    const double speed = 20.0;
    for (int sign = -1; sign <= 1; sign += 2) {
        se23_ins_config_t c;
        se23_gauss_t g, out;
        int64_t t;
        it_config(&c, 1);
        c.zupt = 0;
        assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
        it_initial(15, 1e-3, 0.01, 0.05, &g);
        g.T.v.v[0] = (se23_real_t)speed;
        assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_OK);
        for (int k = 1; k <= 5 * 200; ++k) {
            se23_vec3_t w, f;
            it_rest_sample(NULL, NULL, NULL, NULL, &w, &f); /* level, no acceleration */
            assert_int_equal(se23_ins_imu(&ins, k * IT_DT_NS, k, &w, &f), SE23_INS_USED);
            if (k % 40 == 0) {
                const long long t_fix = k * IT_DT_NS + sign * 2000000LL;
                const double p[3] = {speed * (double)t_fix * 1e-9, 0.0, 0.0};
                se23_ins_gnss_t fix;
                it_fix(t_fix, p, 0.01, &fix);
                assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_USED);
            }
        }
        assert_int_equal(se23_ins_state(&ins, &out, &t), SE23_OK);
        print_message("fix %+d ms off the sample: position error %.4f m\n", 2 * sign,
                      (double)out.T.p.v[0] - speed * (double)t * 1e-9);
        assert_near((double)out.T.p.v[0], speed * (double)t * 1e-9, 0.005, 0.0);
    }
}

/* Fixes that jump 50 m away: gated, then after gate_recover of them the
 * filter resets position to the fix and flags it; the next fix passes. */
static void test_gate_recovery(void **state)
{
    (void)state;
    const double far[3] = {50.0, 0.0, 0.0};
    for (int recover = 0; recover <= 5; recover += 5) {
        se23_ins_config_t c;
        se23_gauss_t out;
        int64_t t;
        int k = 0, resets = 0;
        it_config(&c, 1);
        c.gate_recover = recover;
        c.zupt = 0;
        start(&c, 15);
        for (int fixno = 1; fixno <= 8; ++fixno) {
            se23_ins_gnss_t fix;
            se23_ins_verdict_t v;
            assert_int_equal(it_run_rest(&ins, NULL, NULL, k * IT_DT_NS, k, 40), 40);
            k += 40;
            it_fix(k * IT_DT_NS, far, 0.5, &fix);
            v = se23_ins_gnss(&ins, &fix);
            if (recover == 0 || fixno < recover) {
                assert_int_equal(v, SE23_INS_GATED);
                assert_true((ins.status & SE23_INS_ST_GNSS_GATED) != 0);
            } else if (fixno == recover) {
                assert_int_equal(v, SE23_INS_RESET);
                assert_true((ins.status & SE23_INS_ST_GATE_RESET) != 0);
                assert_int_equal(se23_ins_state(&ins, &out, &t), SE23_OK);
                assert_near((double)out.T.p.v[0], 50.0, 1e-4, 0.0);
                assert_near(P_at(&out, 6), 0.25, 1e-6, 1e-5);
                assert_int_equal(se23_gauss_check(&out), SE23_OK);
                resets++;
            } else {
                assert_int_equal(v, SE23_INS_USED);
                assert_int_equal(ins.status & SE23_INS_ST_GATE_RESET, 0);
            }
        }
        assert_int_equal(ins.c.gate_resets, resets);
        assert_int_equal(ins.c.gnss_gated, recover == 0 ? 8 : recover);
    }
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_zupt_holds_rest_and_estimates_biases),
        cmocka_unit_test(test_zupt_nis_sums_the_innovations),
        cmocka_unit_test(test_lever_arm_places_the_body),
        cmocka_unit_test(test_gate_recovery),
        cmocka_unit_test(test_fix_within_half_a_sample_is_moved_to_the_state),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
