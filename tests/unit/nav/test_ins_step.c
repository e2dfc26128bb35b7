/* Unit tests of src/nav/ins_step.c: the preintegrated factor the filter
 * publishes equals a factor built by preint_unc.h from the same samples at
 * the same bias estimate, and is handed out once; a sample after lost ones
 * is integrated as the linear interpolation of the readings that bracket
 * the gap (ins.h, "Lost samples"), in the filter and in its factor, and
 * not without a reading before the gap. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "nav/ins_internal.h"
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
    assert_memory_equal(out.f.P_left.m, ref.P_left.m, sizeof ref.P_left.m);
    assert_memory_equal(out.f.J_left.m, ref.J_left.m, sizeof ref.J_left.m);
    assert_int_equal(se23_preint_unc_check(&out.f), SE23_OK);
}

/* A factor's seq0 is the seq of the first sample it received: after lost
 * samples the first that arrived, and up to the largest seq an int64
 * holds (the filter once formed seq + 1 of the last sample for the next
 * window, which overflowed there: UndefinedBehaviorSanitizer aborts this
 * test in the sanitizer trees with that code). Windows of 20 samples; the
 * 21st and 22nd are lost; the last sample's seq is INT64_MAX. */
static void test_factor_seq0_is_its_first_sample_received(void **state)
{
    (void)state;
    const int64_t base = INT64_MAX - 60;
    const int64_t expected[3] = {base + 1, base + 23, base + 41};
    se23_ins_config_t c;
    se23_gauss_t g;
    se23_ins_factor_t out;
    se23t_rng_t rng;
    int got = 0;
    it_config(&c, 1);
    c.zupt = 0;
    c.preint_window = SE23_R(20) * (se23_real_t)IT_DT_NS * SE23_R(1e-9);
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    it_initial(15, 1e-3, 0.01, 0.1, &g);
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_OK);
    se23t_rng_seed(&rng, 5);
    for (int k = 1; k <= 60; ++k) {
        se23_vec3_t w, f;
        it_rest_sample(&rng, NULL, NULL, NULL, &w, &f);
        if ((k == 21) || (k == 22)) {
            continue;
        }
        assert_int_equal(se23_ins_imu(&ins, k * IT_DT_NS, base + k, &w, &f), SE23_INS_USED);
        if (se23_ins_take_factor(&ins, &out) != 0) {
            assert_true(got < 3);
            assert_true(out.seq0 == expected[got]);
            assert_int_equal(out.t0_ns, 20 * got * IT_DT_NS);
            ++got;
        }
    }
    assert_int_equal(got, 3);
    assert_int_equal(ins.c.imu_missing, 2);
}

/* A turning, accelerating body: readings that change fast enough for the
 * reconstruction of a gap to matter (|w| ~ 1-3 rad/s, |f| ~ g). */
static void turning_sample(int k, se23_vec3_t *w, se23_vec3_t *f)
{
    const double t = (double)k * (double)IT_DT_NS * 1e-9;
    w->v[0] = (se23_real_t)(1.5 * sin(9.0 * t));
    w->v[1] = (se23_real_t)(2.0 * cos(7.0 * t));
    w->v[2] = (se23_real_t)(0.5 + t);
    f->v[0] = (se23_real_t)(3.0 * sin(11.0 * t));
    f->v[1] = (se23_real_t)(1.0 - t);
    f->v[2] = (se23_real_t)(-it_gravity() + 2.0 * cos(5.0 * t));
}

/* The lost samples of a gap in a run of 40 samples whose seq 21 and 22 are
 * lost (a gap of three intervals before seq 23), as se23_ins_gap_sample
 * reconstructs them: linear between seq 20 and seq 23. how = 1: those;
 * how = 0: the arriving reading held (the former convention). */
static void gap_reading(int k, int how, se23_vec3_t *w, se23_vec3_t *f)
{
    se23_vec3_t w0, f0, w1, f1;
    const se23_real_t a = (se23_real_t)(k - 20) / SE23_R(3);
    turning_sample(20, &w0, &f0);
    turning_sample(23, &w1, &f1);
    for (int i = 0; i < 3; ++i) {
        w->v[i] = how ? w0.v[i] + a * (w1.v[i] - w0.v[i]) : w1.v[i];
        f->v[i] = how ? f0.v[i] + a * (f1.v[i] - f0.v[i]) : f1.v[i];
    }
}

/* ins = a filter without the detector (the lost samples' readings would
 * change its windows), started level at rest, through the 40 samples with
 * seq 21, 22 lost (lost = 1) or given as gap_reading(how). */
static void run_gap(se23_ins_t *f, int lost, int how)
{
    se23_ins_config_t c;
    se23_gauss_t g;
    it_config(&c, 1);
    c.zupt = 0;
    c.delay_horizon = SE23_R(0);
    assert_int_equal(se23_ins_setup(&c, f), SE23_OK);
    it_initial(15, 1e-3, 0.01, 0.1, &g);
    assert_int_equal(se23_ins_init(f, 0, &g), SE23_OK);
    for (int k = 1; k <= 40; ++k) {
        se23_vec3_t w, a;
        if ((k == 21) || (k == 22)) {
            if (lost) {
                continue;
            }
            gap_reading(k, how, &w, &a);
        } else {
            turning_sample(k, &w, &a);
        }
        assert_int_equal(se23_ins_imu(f, k * IT_DT_NS, k, &w, &a), SE23_INS_USED);
    }
    assert_int_equal(f->c.filter_errors, 0);
}

/* The largest difference between two filters' means and covariances. */
static double state_diff(const se23_ins_t *a, const se23_ins_t *b)
{
    double d = 0.0;
    for (int i = 0; i < 3; ++i) {
        d = fmax(d, fabs((double)a->g.T.v.v[i] - (double)b->g.T.v.v[i]));
        d = fmax(d, fabs((double)a->g.T.p.v[i] - (double)b->g.T.p.v[i]));
        for (int j = 0; j < 3; ++j) {
            d = fmax(d, fabs((double)a->g.T.R.m[i][j] - (double)b->g.T.R.m[i][j]));
        }
    }
    for (int i = 0; i < 15 * 15; ++i) {
        d = fmax(d, fabs((double)a->g.P.m[i] - (double)b->g.P.m[i]));
    }
    return d;
}

static se23_ins_t ref; /* large: static */

static void test_lost_samples_are_interpolated_between_their_neighbours(void **state)
{
    (void)state;
    const double tol = 1e2 * SE23T_EPS; /* the same steps up to the rounding of dt and a */
    double d_interp;
    run_gap(&ins, 1, 0);
    assert_int_equal(ins.c.imu_missing, 2);
    run_gap(&ref, 0, 1);
    d_interp = state_diff(&ins, &ref);
    assert_true(d_interp < tol);
    /* holding the arriving reading over the gap is measurably different */
    run_gap(&ref, 0, 0);
    assert_true(state_diff(&ins, &ref) > 1e-4); /* 1.4e-3 */
}

static void test_no_interpolation_without_a_reading_before_the_gap(void **state)
{
    (void)state;
    se23_ins_config_t c;
    se23_gauss_t g, exp;
    se23_imu_sample_t s;
    it_config(&c, 1);
    c.zupt = 0;
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    it_initial(15, 1e-3, 0.01, 0.1, &g);
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_OK);
    /* the first sample, three intervals after init: one step holding it */
    turning_sample(3, &s.w_ib_b, &s.f_b);
    s.dt = (se23_real_t)(3 * IT_DT_NS) / SE23_R(1e9);
    assert_int_equal(se23_gauss_predict(&ins.model, &g, &s, &c.noise, SE23_INPUT_JAC_EXACT, &exp),
                     SE23_OK);
    assert_int_equal(se23_ins_imu(&ins, 3 * IT_DT_NS, 3, &s.w_ib_b, &s.f_b), SE23_INS_USED);
    assert_memory_equal(&ins.g.T, &exp.T, sizeof exp.T);
    assert_memory_equal(ins.g.P.m, exp.P.m, sizeof exp.P.m);
}

static void test_factor_integrates_lost_samples_as_the_filter(void **state)
{
    (void)state;
    se23_ins_config_t c;
    se23_gauss_t g;
    se23_preint_unc_t fac;
    se23_ins_factor_t out;
    se23_imu_sample_t prev, s, u;
    it_config(&c, 1);
    c.zupt = 0;
    c.preint_window = SE23_R(1);
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    it_initial(15, 1e-3, 0.01, 0.1, &g);
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_OK);
    assert_int_equal(se23_preint_unc_reset(&g.b_g, &g.b_a, SE23_INPUT_JAC_EXACT, &fac), SE23_OK);
    prev.dt = SE23_R(0);
    for (int k = 1; k <= 200; ++k) { /* 198 samples, 200 intervals: one factor of 1 s */
        const int lost = (k == 101) || (k == 102); /* seq 103 comes after a gap of 3 */
        const int n = (k == 103) ? 3 : 1;
        if (lost) {
            continue;
        }
        turning_sample(k, &s.w_ib_b, &s.f_b);
        assert_int_equal(se23_ins_imu(&ins, k * IT_DT_NS, k, &s.w_ib_b, &s.f_b), SE23_INS_USED);
        s.dt = (se23_real_t)(n * IT_DT_NS) / SE23_R(1e9); /* as the filter forms it */
        for (int j = 1; j <= n; ++j) {
            se23_ins_gap_sample(&prev, &s, j, n, &u);
            assert_int_equal(se23_preint_unc_add(&fac, &u, &c.noise), SE23_OK);
        }
        prev = s;
    }
    assert_int_equal(se23_ins_take_factor(&ins, &out), 1);
    assert_int_equal(out.f.f.n, 200);
    assert_memory_equal(&out.f.f.delta, &fac.f.delta, sizeof fac.f.delta);
    assert_memory_equal(out.f.P_left.m, fac.P_left.m, sizeof fac.P_left.m);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_factor_equals_preint_unc_of_the_same_samples),
        cmocka_unit_test(test_factor_seq0_is_its_first_sample_received),
        cmocka_unit_test(test_lost_samples_are_interpolated_between_their_neighbours),
        cmocka_unit_test(test_no_interpolation_without_a_reading_before_the_gap),
        cmocka_unit_test(test_factor_integrates_lost_samples_as_the_filter),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
