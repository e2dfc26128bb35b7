/* Unit tests of src/nav/ins.c: the configuration and initial-state checks
 * (every status, nothing written on error), the screening of IMU samples
 * and GNSS fixes with one counter per reason, seq bookkeeping that stays
 * defined for corrupted seq values, and the state output. */
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "ins_counters.h"
#include "ins_test.h"
#include "se23/ins.h"
#include "se23_test.h"

static se23_ins_t ins, copy; /* large: static */

/* A value that made the filter's steps overflow (fuzz_ins, issue 37). */
#if SE23_CFG_DOUBLE
#define HUGE_MEAN 1e300
#else
#define HUGE_MEAN 1e30
#endif

static void setup_init(int bias)
{
    se23_ins_config_t c;
    se23_gauss_t g;
    it_config(&c, bias);
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    it_initial(bias ? 15 : 9, 1e-3, 0.1, 1.0, &g);
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_OK);
}

/* ------------------------------------------------------------ setup */

typedef void (*mutate_fn)(se23_ins_config_t *c);
static void m_nan_noise(se23_ins_config_t *c) { c->noise.gyro_noise = (se23_real_t)NAN; }
static void m_neg_noise(se23_ins_config_t *c) { c->noise.accel_walk = SE23_R(-1); }
static void m_zero_range(se23_ins_config_t *c) { c->gyro_range = SE23_R(0); }
static void m_lat(se23_ins_config_t *c) { c->lat = SE23_R(2); }
static void m_flag(se23_ins_config_t *c) { c->bias_states = 2; }
static void m_dt(se23_ins_config_t *c) { c->dt_nominal = SE23_R(0); }
/* Regression (fuzz_ins): max_gap / dt_nominal beyond int64 was converted to
 * max_missing (undefined behaviour); below 1 ns dt_nominal is refused. */
static void m_dt_tiny(se23_ins_config_t *c) { c->dt_nominal = (se23_real_t)1e-30; }
static void m_gap(se23_ins_config_t *c) { c->max_gap = SE23_R(2); }
static void m_gap_small(se23_ins_config_t *c) { c->max_gap = (se23_real_t)1e-3; }
static void m_outage(se23_ins_config_t *c) { c->max_outage = SE23_R(1e4); }
static void m_ring(se23_ins_config_t *c) { c->delay_horizon = SE23_R(5); }
static void m_recover(se23_ins_config_t *c) { c->gate_recover = -1; }
static void m_zupt_sigma(se23_ins_config_t *c) { c->zupt_sigma_v = SE23_R(0); }
static void m_detector(se23_ins_config_t *c) { c->detector.window = 1; }
static void m_inf_lever(se23_ins_config_t *c) { c->lever_b.v[1] = (se23_real_t)INFINITY; }
/* floor updates: at stances (zupt on) and with a step to judge new levels */
static void m_floor(se23_ins_config_t *c) { c->floor_sigma = SE23_R(0.01); }
static void m_floor_no_zupt(se23_ins_config_t *c)
{
    c->floor_sigma = SE23_R(0.01);
    c->floor_step = SE23_R(0.05);
    c->zupt = 0;
}
static void m_floor_neg(se23_ins_config_t *c) { c->floor_sigma = SE23_R(-0.01); }
static void m_floor_nan(se23_ins_config_t *c) { c->floor_step = (se23_real_t)NAN; }
static void m_floor_swing(se23_ins_config_t *c) { c->floor_swing = SE23_INS_MAX_OUTAGE * SE23_R(2); }
/* the physical bounds (ins.h): sensor ranges, the outage's 1-sigmas */
static void m_accel_range(se23_ins_config_t *c)
{
    c->accel_range = SE23_INS_ACCEL_RANGE_MAX * (se23_real_t)1.001;
}
static void m_gyro_range(se23_ins_config_t *c)
{
    c->gyro_range = SE23_INS_GYRO_RANGE_MAX * (se23_real_t)1.001;
}
static void m_outage_accel(se23_ins_config_t *c) { c->outage_accel = (se23_real_t)160.01; }
static void m_outage_rate(se23_ins_config_t *c) { c->outage_rate = (se23_real_t)30.01; }
/* the motion noise (ins.h, "Motion noise") and the rest test's flag */
static void m_motion_neg(se23_ins_config_t *c) { c->motion.gyro_scale = SE23_R(-0.01); }
static void m_motion_nan(se23_ins_config_t *c) { c->motion.accel_scale = (se23_real_t)NAN; }
static void m_motion_big(se23_ins_config_t *c) { c->motion.gyro_g = (se23_real_t)1.01; }
static void m_motion_tau(se23_ins_config_t *c) { c->motion.corr_time = (se23_real_t)1.01; }
static void m_gravity_flag(se23_ins_config_t *c) { c->gravity_test_off = 2; }
static void m_lever_neg(se23_ins_config_t *c) { c->zupt_lever = SE23_R(-0.1); }
static void m_lever_big(se23_ins_config_t *c) { c->zupt_lever = (se23_real_t)1.01; }
static void m_mount_big(se23_ins_config_t *c) { c->mount_bv.v[2] = SE23_R(6.3); }
static void m_mount_nan(se23_ins_config_t *c) { c->mount_bv.v[0] = (se23_real_t)NAN; }
static void m_nhc_neg(se23_ins_config_t *c) { c->nhc_sigma = SE23_R(-0.3); }
static void m_nhc_big(se23_ins_config_t *c) { c->nhc_sigma = SE23_R(2e3); }
static void m_nhc_lever(se23_ins_config_t *c) { c->nhc_lever = SE23_R(11); }
static void m_nhc_no_interval(se23_ins_config_t *c) { c->nhc_sigma = SE23_R(0.3); }
static void m_nhc_long_interval(se23_ins_config_t *c)
{
    c->nhc_sigma = SE23_R(0.3);
    c->nhc_interval = SE23_R(61);
}
static void m_offset_big(se23_ins_config_t *c) { c->gnss_time_offset = SE23_R(-1.01); }
static void m_rest_speed_neg(se23_ins_config_t *c) { c->rest_speed_max = SE23_R(-0.5); }
static void m_rest_accel_nan(se23_ins_config_t *c) { c->rest_accel_sigma = (se23_real_t)NAN; }

/* The filter's RAM as ins.h and tools/doc/pages/filter.md state it (a firmware's budget):
 * a fixed part plus the ring of SE23_INS_RING samples. */
static void test_ins_memory_is_as_documented(void **state)
{
    (void)state;
#if SE23_CFG_DOUBLE
    assert_int_equal(sizeof(se23_ins_hist_t), 72);
    assert_int_equal(sizeof(se23_ins_t), 17992 + SE23_INS_RING * 72);
#else
    assert_int_equal(sizeof(se23_ins_hist_t), 48);
    assert_int_equal(sizeof(se23_ins_t), 9240 + SE23_INS_RING * 48);
#endif
}

static void test_setup_rejects_each_bad_field_and_writes_nothing(void **state)
{
    (void)state;
    const struct {
        mutate_fn m;
        se23_status_t st;
    } cases[] = {
        {m_nan_noise, SE23_ERR_NONFINITE}, {m_neg_noise, SE23_ERR_DOMAIN},
        {m_zero_range, SE23_ERR_DOMAIN},   {m_lat, SE23_ERR_DOMAIN},
        {m_flag, SE23_ERR_DOMAIN},         {m_dt, SE23_ERR_DT},
        {m_dt_tiny, SE23_ERR_DT},
        {m_gap, SE23_ERR_DT},              {m_gap_small, SE23_ERR_DT},
        {m_outage, SE23_ERR_DOMAIN},       {m_ring, SE23_ERR_DIM},
        {m_recover, SE23_ERR_DOMAIN},      {m_zupt_sigma, SE23_ERR_DOMAIN},
        {m_detector, SE23_ERR_DIM},        {m_inf_lever, SE23_ERR_NONFINITE},
        {m_floor, SE23_ERR_DOMAIN},        {m_floor_no_zupt, SE23_ERR_DOMAIN},
        {m_floor_neg, SE23_ERR_DOMAIN},    {m_floor_nan, SE23_ERR_NONFINITE},
        {m_floor_swing, SE23_ERR_DOMAIN},
        {m_accel_range, SE23_ERR_DOMAIN},  {m_gyro_range, SE23_ERR_DOMAIN},
        {m_outage_accel, SE23_ERR_DOMAIN}, {m_outage_rate, SE23_ERR_DOMAIN},
        {m_motion_neg, SE23_ERR_DOMAIN},   {m_motion_nan, SE23_ERR_NONFINITE},
        {m_motion_big, SE23_ERR_DOMAIN},   {m_motion_tau, SE23_ERR_DOMAIN},
        {m_gravity_flag, SE23_ERR_DOMAIN}, {m_lever_neg, SE23_ERR_DOMAIN},
        {m_lever_big, SE23_ERR_DOMAIN},
        {m_mount_big, SE23_ERR_DOMAIN},
        {m_mount_nan, SE23_ERR_NONFINITE},
        {m_nhc_neg, SE23_ERR_DOMAIN},
        {m_nhc_big, SE23_ERR_DOMAIN},
        {m_nhc_lever, SE23_ERR_DOMAIN},
        {m_nhc_no_interval, SE23_ERR_DOMAIN},
        {m_nhc_long_interval, SE23_ERR_DOMAIN},
        {m_offset_big, SE23_ERR_DOMAIN},
        {m_rest_speed_neg, SE23_ERR_DOMAIN},
        {m_rest_accel_nan, SE23_ERR_NONFINITE},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        se23_ins_config_t c;
        it_config(&c, 1);
        cases[k].m(&c);
        memset(&ins, 0x5a, sizeof ins);
        memcpy(&copy, &ins, sizeof ins);
        assert_int_equal(se23_ins_setup(&c, &ins), cases[k].st);
        assert_memory_equal(&ins, &copy, sizeof ins);
    }
    {
        se23_ins_config_t c;
        it_config(&c, 1);
        assert_int_equal(se23_ins_setup(NULL, &ins), SE23_ERR_NULL);
        assert_int_equal(se23_ins_setup(&c, NULL), SE23_ERR_NULL);
        /* The ring's limit, both sides: 2 H / dt + 2 <= SE23_INS_RING. */
        c.delay_horizon = (se23_real_t)((SE23_INS_RING - 2) / (2.0 * IT_RATE));
        assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
        c.delay_horizon = (se23_real_t)((SE23_INS_RING - 1) / (2.0 * IT_RATE));
        assert_int_equal(se23_ins_setup(&c, &ins), SE23_ERR_DIM);
        /* dt_nominal's limit, both sides: 1 ns. */
        c.delay_horizon = SE23_R(0);
        c.dt_nominal = SE23_R(1e-9);
        assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
        c.dt_nominal = SE23_R(0.99e-9);
        assert_int_equal(se23_ins_setup(&c, &ins), SE23_ERR_DT);
        /* The physical bounds, the other side: at them (the outage's
         * 1-sigmas: accel_range + 10 m/s^2 and gyro_range). */
        it_config(&c, 1);
        c.accel_range = SE23_INS_ACCEL_RANGE_MAX;
        c.gyro_range = SE23_INS_GYRO_RANGE_MAX;
        assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
        it_config(&c, 1);
        c.outage_accel = SE23_R(160);
        c.outage_rate = SE23_R(30);
        assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    }
}

static void test_init_checks_the_state_once_and_counts_rejections(void **state)
{
    (void)state;
    se23_ins_config_t c;
    se23_gauss_t g, out;
    int64_t t;
    it_config(&c, 1);
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    assert_int_equal(se23_ins_state(&ins, &out, &t), SE23_ERR_DIM); /* no state yet */
    it_initial(9, 1e-3, 0.1, 1.0, &g);
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_ERR_DIM); /* 15 states configured */
    it_initial(15, 1e-3, 0.1, 1.0, &g);
    assert_int_equal(se23_ins_init(&ins, -1, &g), SE23_ERR_DT);
    g.P.m[1] = SE23_R(1); /* not symmetric */
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_ERR_NOT_SYMMETRIC);
    it_initial(15, 1e-3, 0.1, 1.0, &g);
    g.P.m[0] = SE23_R(-1);
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_ERR_NOT_PSD);
    it_initial(15, 1e-3, 0.1, 1.0, &g);
    g.T.R.m[0][1] = SE23_R(0.1);
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_ERR_NOT_ROTATION);
    assert_int_equal(ins.c.init_rejected, 5);
    assert_int_equal(ins.status & SE23_INS_ST_INITIALISED, 0);
    it_initial(15, 1e-3, 0.1, 1.0, &g);
    g.T.p.v[0] = SE23_R(3);
    assert_int_equal(se23_ins_init(&ins, 7, &g), SE23_OK);
    assert_int_equal(se23_ins_state(&ins, &out, &t), SE23_OK);
    assert_int_equal(t, 7);
    assert_int_equal(out.n, 15);
    assert_true(out.T.p.v[0] == SE23_R(3));
}

/* Regression (fuzz_ins): a covariance is accepted symmetric within a
 * tolerance relative to its largest variance; a GNSS gate reset that then
 * shrank that variance left the kept asymmetry beyond it, and the state
 * failed se23_gauss_check after SE23_INS_RESET. The filter keeps the lower
 * triangle, the one the check proved positive semidefinite, mirrored. */
static void test_init_keeps_an_exactly_symmetric_covariance(void **state)
{
    (void)state;
    se23_ins_config_t c;
    se23_gauss_t g, out;
    int64_t t;
    it_config(&c, 1);
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    it_initial(15, 1e-3, 0.1, 1e3, &g); /* largest variance 1e6 */
    g.P.m[1] = SE23_R(0.5) * (se23_real_t)SE23_CFG_COV_TOL * SE23_R(1e6); /* (0, 1) */
    g.P.m[15 + 2] = SE23_R(1e-7);                                       /* (1, 2) */
    g.P.m[15 * 2 + 1] = SE23_R(2e-7);                                   /* (2, 1) */
    assert_int_equal(se23_gauss_check(&g), SE23_OK);
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_OK);
    assert_int_equal(se23_ins_state(&ins, &out, &t), SE23_OK);
    for (int i = 0; i < 15; ++i) {
        for (int j = 0; j < i; ++j) {
            assert_true(out.P.m[15 * i + j] == g.P.m[15 * i + j]);
            assert_true(out.P.m[15 * j + i] == out.P.m[15 * i + j]);
        }
    }
}

/* ------------------------------------------------------------ screening */

static void test_every_sample_ends_in_one_counter(void **state)
{
    (void)state;
    se23_ins_config_t c;
    se23_gauss_t g;
    se23_vec3_t w, f, bad;
    it_config(&c, 1);
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    it_rest_sample(NULL, NULL, NULL, NULL, &w, &f);
    assert_int_equal(se23_ins_imu(&ins, IT_DT_NS, 1, &w, &f), SE23_INS_EARLY);
    it_initial(15, 1e-3, 0.1, 1.0, &g);
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_OK);
    assert_int_equal(se23_ins_imu(&ins, 1 * IT_DT_NS, 1, &w, &f), SE23_INS_USED);
    assert_int_equal(se23_ins_imu(&ins, 2 * IT_DT_NS, 2, &w, &f), SE23_INS_USED);
    bad = w;
    bad.v[1] = (se23_real_t)NAN;
    assert_int_equal(se23_ins_imu(&ins, 3 * IT_DT_NS, 3, &bad, &f), SE23_INS_NONFINITE);
    assert_int_equal(se23_ins_imu(&ins, -1, 3, &w, &f), SE23_INS_BAD_TIME);
    assert_int_equal(se23_ins_imu(&ins, 3 * IT_DT_NS, -3, &w, &f), SE23_INS_BAD_TIME);
    bad = w;
    bad.v[0] = SE23_R(31); /* beyond the 30 rad/s range */
    assert_int_equal(se23_ins_imu(&ins, 3 * IT_DT_NS, 3, &bad, &f), SE23_INS_RANGE);
    assert_int_equal(se23_ins_imu(&ins, 2 * IT_DT_NS, 2, &w, &f), SE23_INS_DUPLICATE);
    assert_int_equal(se23_ins_imu(&ins, 1 * IT_DT_NS, 1, &w, &f), SE23_INS_OUT_OF_ORDER);
    assert_int_equal(se23_ins_imu(&ins, 2 * IT_DT_NS, 9, &w, &f), SE23_INS_BAD_TIME);
    /* seq 3 and 4 lost: the next sample arrives with seq 5 */
    assert_int_equal(se23_ins_imu(&ins, 5 * IT_DT_NS, 5, &w, &f), SE23_INS_USED);
    /* one interval above max_gap (0.125 s): rejected, not (yet) an outage */
    assert_int_equal(se23_ins_imu(&ins, 5 * IT_DT_NS + 200000000LL, 6, &w, &f),
                     SE23_INS_BAD_DT);
    /* a corrupted seq: counted as a jump, arithmetic stays defined */
    assert_int_equal(se23_ins_imu(&ins, 6 * IT_DT_NS, INT64_MAX, &w, &f), SE23_INS_USED);
    assert_int_equal(se23_ins_imu(&ins, 7 * IT_DT_NS, 7, &w, &f), SE23_INS_USED);
    assert_int_equal(ins.c.imu_early, 1);
    assert_int_equal(ins.c.imu_used, 5);
    assert_int_equal(ins.c.imu_nonfinite, 1);
    assert_int_equal(ins.c.imu_range, 1);
    assert_int_equal(ins.c.imu_duplicate, 1);
    assert_int_equal(ins.c.imu_out_of_order, 1);
    assert_int_equal(ins.c.imu_bad_time, 3);
    assert_int_equal(ins.c.imu_bad_dt, 1);
    assert_int_equal(ins.c.imu_missing, 5); /* the bad-time seq 9 skipped 4..8 */
    assert_int_equal(ins.c.imu_seq_jumps, 1);
    assert_int_equal(ins.c.filter_errors, 0);
    assert_int_equal(se23_ins_imu(NULL, 0, 0, &w, &f), SE23_INS_FAILED);
    assert_int_equal(se23_ins_imu(&ins, 0, 0, NULL, &f), SE23_INS_FAILED);
    assert_int_equal(ins.c.imu_failed, 1); /* the NULL reading */
}

/* The motion noise (ins.h, "Motion noise") is the white noise of the
 * density it states: a filter with it predicts the covariance of one whose
 * densities are sqrt(n^2 + (k_g^2 |w|^2 + s_g^2 |f|^2) tau) and
 * sqrt(n^2 + k_a^2 |f|^2 tau) of the readings, computed here in double. */
static void test_motion_noise_is_the_density_it_states(void **state)
{
    (void)state;
    static se23_ins_t plain;
    const double w[3] = {0.5, -1.0, 2.0}, f[3] = {1.0, 2.0, -9.0};
    const double ks_g = 0.01, ks_a = 0.02, kg_g = 1e-3, tau = 0.1;
    const double w2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
    const double f2 = f[0] * f[0] + f[1] * f[1] + f[2] * f[2];
    se23_ins_config_t c, cp;
    se23_gauss_t g;
    se23_vec3_t wv, fv;
    it_config(&c, 1);
    c.zupt = 0;
    cp = c;
    c.motion.gyro_scale = (se23_real_t)ks_g;
    c.motion.accel_scale = (se23_real_t)ks_a;
    c.motion.gyro_g = (se23_real_t)kg_g;
    c.motion.corr_time = (se23_real_t)tau;
    cp.noise.gyro_noise = (se23_real_t)sqrt(IT_SG * IT_SG / IT_RATE +
                                            (ks_g * ks_g * w2 + kg_g * kg_g * f2) * tau);
    cp.noise.accel_noise = (se23_real_t)sqrt(IT_SA * IT_SA / IT_RATE + ks_a * ks_a * f2 * tau);
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    assert_int_equal(se23_ins_setup(&cp, &plain), SE23_OK);
    it_initial(15, 1e-3, 0.1, 1.0, &g);
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_OK);
    assert_int_equal(se23_ins_init(&plain, 0, &g), SE23_OK);
    for (int i = 0; i < 3; ++i) {
        wv.v[i] = (se23_real_t)w[i];
        fv.v[i] = (se23_real_t)f[i];
    }
    for (long long k = 1; k <= 3; ++k) {
        assert_int_equal(se23_ins_imu(&ins, k * IT_DT_NS, k, &wv, &fv), SE23_INS_USED);
        assert_int_equal(se23_ins_imu(&plain, k * IT_DT_NS, k, &wv, &fv), SE23_INS_USED);
    }
    for (int i = 0; i < 15 * 15; ++i) {
        const double a = (double)ins.g.P.m[i], b = (double)plain.g.P.m[i];
        assert_true(fabs(a - b) <= 1e3 * SE23T_EPS * (fabs(b) + 1e-12));
    }
    /* and it is not the white noise alone: the attitude variance grew more */
    assert_true((double)ins.g.P.m[0] > 1.01 * (double)g.P.m[0] &&
                (double)cp.noise.gyro_noise > 3.0 * (double)c.noise.gyro_noise);
}

/* The ZUPT's 1-sigma grows with the rate (ins.h, "Zero-velocity updates"):
 * a filter with zupt_lever updates at rest as one whose zupt_sigma_v is
 * sqrt(s^2 + W (l |w|)^2) for the sample's rate, computed here in double. */
static void test_zupt_sigma_grows_with_the_rate(void **state)
{
    (void)state;
    static se23_ins_t plain;
    const double l = 0.2, s0 = 0.01, wz = 0.05;
    se23_ins_config_t c, cp;
    se23_gauss_t g;
    se23_vec3_t w, f;
    it_config(&c, 1);
    c.detector.sigma_g = SE23_R(0.1); /* a turn of 0.05 rad/s is rest */
    c.zaru_sigma_w = SE23_R(0);       /* b_g, and so w + b_g, stays */
    cp = c;
    c.zupt_lever = (se23_real_t)l;
    cp.zupt_sigma_v = (se23_real_t)sqrt(s0 * s0 + c.detector.window * (l * wz) * (l * wz));
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    assert_int_equal(se23_ins_setup(&cp, &plain), SE23_OK);
    it_initial(15, 1e-3, 0.1, 1.0, &g);
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_OK);
    assert_int_equal(se23_ins_init(&plain, 0, &g), SE23_OK);
    it_rest_sample(NULL, NULL, NULL, NULL, &w, &f);
    w.v[2] = (se23_real_t)wz;
    for (long long k = 1; k <= 2 * c.detector.window; ++k) {
        assert_int_equal(se23_ins_imu(&ins, k * IT_DT_NS, k, &w, &f), SE23_INS_USED);
        assert_int_equal(se23_ins_imu(&plain, k * IT_DT_NS, k, &w, &f), SE23_INS_USED);
    }
    assert_true(ins.c.zupt_used > 0 && ins.c.zupt_used == plain.c.zupt_used);
    /* entry (i, j) on its natural scale sqrt(P_ii P_jj): the updates take
     * the velocity variances down by orders, the rounding with them */
    for (int i = 0; i < 15; ++i) {
        for (int j = 0; j < 15; ++j) {
            const double a = (double)ins.g.P.m[15 * i + j], b = (double)plain.g.P.m[15 * i + j];
            const double scale = sqrt((double)plain.g.P.m[16 * i] * (double)plain.g.P.m[16 * j]);
            assert_true(fabs(a - b) <= 1e3 * SE23T_EPS * scale);
        }
    }
}

/* Issue 34: the range is per axis, as data sheets state it. A heel strike
 * of 12 g on each of two axes (17 g long) is within a 16 g range and is
 * used; 16.1 g on one axis is beyond it. */
static void test_range_is_per_axis(void **state)
{
    (void)state;
    se23_ins_config_t c;
    se23_gauss_t g;
    se23_vec3_t w = {{SE23_R(0), SE23_R(0), SE23_R(0)}};
    se23_vec3_t f = {{(se23_real_t)(12 * IT_G), (se23_real_t)(-12 * IT_G), SE23_R(0)}};
    it_config(&c, 1);
    c.accel_range = (se23_real_t)(16 * IT_G);
    c.outage_accel = SE23_R(1);
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    it_initial(15, 1e-3, 0.1, 1.0, &g);
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_OK);
    assert_int_equal(se23_ins_imu(&ins, IT_DT_NS, 1, &w, &f), SE23_INS_USED);
    f.v[0] = (se23_real_t)(16.1 * IT_G);
    f.v[1] = SE23_R(0);
    assert_int_equal(se23_ins_imu(&ins, 2 * IT_DT_NS, 2, &w, &f), SE23_INS_RANGE);
    w.v[2] = (se23_real_t)-30.01; /* the gyro's 30 rad/s, one axis beyond */
    f.v[0] = SE23_R(0);
    assert_int_equal(se23_ins_imu(&ins, 2 * IT_DT_NS, 2, &w, &f), SE23_INS_RANGE);
    assert_int_equal(ins.c.imu_range, 2);
    assert_int_equal(ins.c.imu_used, 1);
}

/* Regression (fuzz_ins, issue 37 S6): a NaN reading with seq -1 was judged
 * SE23_INS_BAD_TIME; ins.h screens NaN/Inf before the time. */
static void test_nonfinite_reading_is_judged_before_its_time(void **state)
{
    (void)state;
    se23_vec3_t w, f, bad_w, bad_f;
    setup_init(1);
    it_rest_sample(NULL, NULL, NULL, NULL, &w, &f);
    bad_w = w;
    bad_w.v[0] = (se23_real_t)NAN;
    bad_f = f;
    bad_f.v[2] = (se23_real_t)INFINITY;
    memcpy(&copy, &ins, sizeof ins);
    assert_int_equal(se23_ins_imu(&ins, IT_DT_NS, -1, &bad_w, &f), SE23_INS_NONFINITE);
    assert_int_equal(se23_ins_imu(&ins, -1, -1, &w, &bad_f), SE23_INS_NONFINITE);
    assert_int_equal(se23_ins_imu(&ins, -1, -1, &bad_w, &bad_f), SE23_INS_NONFINITE);
    assert_int_equal(ins.c.imu_nonfinite, 3);
    assert_int_equal(ins.c.imu_bad_time, 0);
    /* finite readings at a time outside the clock's domain: BAD_TIME */
    assert_int_equal(se23_ins_imu(&ins, IT_DT_NS, -1, &w, &f), SE23_INS_BAD_TIME);
    assert_int_equal(ins.c.imu_bad_time, 1);
    /* nothing but the counters changed */
    copy.c = ins.c;
    assert_memory_equal(&ins, &copy, sizeof ins);
}

/* Regression (fuzz_ins, issue 37 S7): a sample whose step failed ended in
 * no imu_ counter. A state no step can carry (poked in here: se23_ins_init
 * refuses one, test_init_refuses_means_beyond_the_physical_bounds) fails
 * the steps; each sample still ends in exactly one counter, imu_failed for
 * a failed step, which leaves the state as it was. */
static void test_every_sample_ends_in_one_counter_when_the_step_fails(void **state)
{
    (void)state;
    se23_vec3_t w, f;
    setup_init(1);
    assert_int_equal(it_run_rest(&ins, NULL, NULL, 0, 0, 10), 10);
    ins.g.b_a.v[0] = (se23_real_t)HUGE_MEAN;
    for (int k = 11; k <= 110; ++k) {
        const uint32_t before = it_imu_sum(&ins.c);
        se23_ins_verdict_t v;
        memcpy(&copy, &ins, sizeof ins);
        it_rest_sample(NULL, NULL, NULL, NULL, &w, &f);
        v = se23_ins_imu(&ins, k * IT_DT_NS, k, &w, &f);
        assert_int_equal(it_imu_sum(&ins.c), before + 1U);
        if (v == SE23_INS_FAILED) {
            assert_int_equal(ins.c.imu_failed, copy.c.imu_failed + 1U);
            assert_true(ins.c.filter_errors > copy.c.filter_errors);
            assert_memory_equal(&ins.g, &copy.g, sizeof ins.g);
            assert_int_equal(ins.t_ns, copy.t_ns);
        }
    }
    assert_true(ins.c.imu_failed > 0U);
    assert_int_equal(it_imu_sum(&ins.c), 110U);
}

/* Regression (fuzz_ins, issue 37 S7): se23_ins_init accepted b_a = 1e300,
 * after which most samples failed their step. Means beyond the physical
 * bounds (ins.h, "Validation") are refused on both sides of each bound,
 * along the diagonal (the bound is on the norm), the filter unchanged but
 * for init_rejected; the state it kept goes on. */
static void test_init_refuses_means_beyond_the_physical_bounds(void **state)
{
    (void)state;
    const double bound[4] = {30.0, 150.0, (double)SE23_INS_VEL_MAX, (double)SE23_INS_POS_MAX};
    se23_gauss_t g;
    setup_init(1); /* gyro_range 30 rad/s, accel_range 150 m/s^2 */
    assert_int_equal(it_run_rest(&ins, NULL, NULL, 0, 0, 10), 10);
    for (int k = 0; k < 5; ++k) {
        for (int side = 0; side < 2; ++side) {
            const double x = k == 4 ? HUGE_MEAN : bound[k] * (side ? 0.999 : 1.001) / sqrt(3.0);
            se23_vec3_t *m;
            it_initial(15, 1e-3, 0.1, 1.0, &g);
            m = k == 0 ? &g.b_g : k == 1 ? &g.b_a : k == 2 ? &g.T.v : k == 3 ? &g.T.p : &g.b_a;
            for (int i = 0; i < 3; ++i) {
                m->v[i] = (se23_real_t)(k == 4 && i > 0 ? 0.0 : x);
            }
            if (side == 0 || k == 4) {
                memcpy(&copy, &ins, sizeof ins);
                assert_int_equal(se23_ins_init(&ins, 10 * IT_DT_NS, &g), SE23_ERR_DOMAIN);
                copy.c.init_rejected++;
                assert_memory_equal(&ins, &copy, sizeof ins);
            } else {
                assert_int_equal(se23_ins_init(&ins, 10 * IT_DT_NS, &g), SE23_OK);
                setup_init(1);
                assert_int_equal(it_run_rest(&ins, NULL, NULL, 0, 0, 10), 10);
            }
        }
    }
    assert_int_equal(ins.c.init_rejected, 2);
    assert_int_equal(it_run_rest(&ins, NULL, NULL, 10 * IT_DT_NS, 10, 100), 100);
    assert_int_equal(it_imu_sum(&ins.c), 110U);
    assert_int_equal(ins.c.filter_errors, 0);
}

static void test_counters_saturate(void **state)
{
    (void)state;
    setup_init(0);
    ins.c.imu_bad_time = UINT32_MAX - 1U;
    for (int k = 0; k < 3; ++k) {
        se23_vec3_t w, f;
        it_rest_sample(NULL, NULL, NULL, NULL, &w, &f);
        assert_int_equal(se23_ins_imu(&ins, 0, 1, &w, &f), SE23_INS_BAD_TIME);
    }
    assert_true(ins.c.imu_bad_time == UINT32_MAX);
}

static void test_every_fix_ends_in_one_counter(void **state)
{
    (void)state;
    const double p0[3] = {0.0, 0.0, 0.0};
    se23_ins_config_t c;
    se23_ins_gnss_t fix;
    se23_gauss_t g;
    it_config(&c, 1);
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    it_fix(0, p0, 1.0, &fix);
    assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_EARLY);
    it_initial(15, 1e-3, 0.1, 1.0, &g);
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_OK);
    assert_int_equal(it_run_rest(&ins, NULL, NULL, 0, 0, 100), 100); /* t = 0.5 s */
    it_fix(100 * IT_DT_NS, p0, 1.0, &fix);
    fix.p_n.v[2] = (se23_real_t)NAN;
    assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_NONFINITE);
    it_fix(100 * IT_DT_NS, p0, 0.0, &fix);
    assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_NONFINITE);
    it_fix(100 * IT_DT_NS, p0, 2e6, &fix);
    assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_NONFINITE);
    it_fix(100 * IT_DT_NS, p0, 1.0, &fix);
    fix.has_vel = 1; /* sigma_v left 0 */
    assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_NONFINITE);
    it_fix(-5, p0, 1.0, &fix);
    assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_NONFINITE);
    /* beyond the 0.25 s horizon */
    it_fix(30 * IT_DT_NS, p0, 1.0, &fix);
    assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_STALE);
    /* now */
    it_fix(100 * IT_DT_NS, p0, 1.0, &fix);
    assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_USED);
    /* not after the last fused fix */
    it_fix(99 * IT_DT_NS, p0, 1.0, &fix);
    assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_STALE);
    /* ahead: held, superseded by a newer one, which is fused when due */
    it_fix(103 * IT_DT_NS, p0, 1.0, &fix);
    assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_PENDING);
    it_fix(104 * IT_DT_NS, p0, 1.0, &fix);
    assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_PENDING);
    assert_int_equal(it_run_rest(&ins, NULL, NULL, 100 * IT_DT_NS, 100, 4), 4);
    assert_int_equal(ins.have_pending, 0);
    assert_int_equal(ins.c.gnss_early, 1);
    assert_int_equal(ins.c.gnss_nonfinite, 5);
    assert_int_equal(ins.c.gnss_stale, 2);
    assert_int_equal(ins.c.gnss_used, 2);
    assert_int_equal(ins.c.gnss_pending_dropped, 1);
    assert_true((ins.status & SE23_INS_ST_GNSS_AIDED) != 0);
    assert_int_equal(it_gnss_sum(&ins.c), 11U);
    assert_int_equal(se23_ins_gnss(&ins, NULL), SE23_INS_FAILED);
    assert_int_equal(ins.c.gnss_failed, 1);
}

/* A fix farther than a state may be (ins.h, "Validation": a gate reset
 * would make it the state) is refused as invalid, both sides of the
 * bounds; one whose update fails (a state poked in beyond them) ends in
 * gnss_failed, the state kept. */
static void test_every_fix_ends_in_one_counter_at_the_bounds(void **state)
{
    (void)state;
    const double p0[3] = {0.0, 0.0, 0.0};
    se23_ins_gnss_t fix;
    setup_init(1);
    assert_int_equal(it_run_rest(&ins, NULL, NULL, 0, 0, 100), 100);
    for (int side = 0; side < 2; ++side) {
        const double s = (side ? 0.999 : 1.001) / sqrt(3.0);
        it_fix(100 * IT_DT_NS, p0, 1.0, &fix);
        for (int i = 0; i < 3; ++i) {
            fix.p_n.v[i] = (se23_real_t)((double)SE23_INS_POS_MAX * s);
        }
        assert_int_equal(se23_ins_gnss(&ins, &fix),
                         side ? SE23_INS_GATED : SE23_INS_NONFINITE);
        it_fix(100 * IT_DT_NS, p0, 1.0, &fix);
        fix.has_vel = 1;
        for (int i = 0; i < 3; ++i) {
            fix.v_n.v[i] = (se23_real_t)((double)SE23_INS_VEL_MAX * s);
            fix.sigma_v.v[i] = SE23_R(1);
        }
        assert_int_equal(se23_ins_gnss(&ins, &fix),
                         side ? SE23_INS_GATED : SE23_INS_NONFINITE);
    }
    assert_int_equal(ins.c.gnss_nonfinite, 2);
    assert_int_equal(ins.c.gnss_gated, 2);
    ins.cfg.gnss_gate = SE23_R(0);
    ins.g.T.p.v[0] = (se23_real_t)HUGE_MEAN;
    memcpy(&copy, &ins, sizeof ins);
    it_fix(100 * IT_DT_NS, p0, 1.0, &fix);
    assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_FAILED);
    assert_int_equal(ins.c.gnss_failed, 1);
    assert_true(ins.c.filter_errors > copy.c.filter_errors);
    assert_memory_equal(&ins.g, &copy.g, sizeof ins.g);
    assert_int_equal(it_gnss_sum(&ins.c), 5U);
}

/* Regression (fuzz_ins, issue 37 S3): a pending fix vanished uncounted when
 * a clock step was confirmed; it is stamped by the old clock, and is
 * dropped into gnss_pending_dropped (ins.h, "GNSS"). */
static void test_pending_fix_dropped_by_a_clock_step_is_counted(void **state)
{
    (void)state;
    const double p0[3] = {0.0, 0.0, 0.0};
    se23_ins_gnss_t fix;
    se23_vec3_t w, f;
    setup_init(1);
    assert_int_equal(it_run_rest(&ins, NULL, NULL, 0, 0, 100), 100); /* t = 0.5 s */
    it_fix(103 * IT_DT_NS, p0, 1.0, &fix);
    assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_PENDING);
    it_rest_sample(NULL, NULL, NULL, NULL, &w, &f);
    /* the clock steps back by 0.4 s and stays there */
    assert_int_equal(se23_ins_imu(&ins, 20 * IT_DT_NS, 101, &w, &f), SE23_INS_BAD_TIME);
    assert_int_equal(se23_ins_imu(&ins, 21 * IT_DT_NS, 102, &w, &f), SE23_INS_BAD_TIME);
    assert_int_equal(ins.have_pending, 1);
    assert_int_equal(se23_ins_imu(&ins, 22 * IT_DT_NS, 103, &w, &f), SE23_INS_OUTAGE);
    assert_int_equal(ins.have_pending, 0);
    assert_int_equal(ins.c.gnss_pending_dropped, 1);
    assert_int_equal(it_gnss_sum(&ins.c), 1U);
    assert_int_equal(it_run_rest(&ins, NULL, NULL, 22 * IT_DT_NS, 103, 100), 100);
    assert_int_equal(ins.c.gnss_used, 0);
    assert_int_equal(it_gnss_sum(&ins.c), 1U);
}

/* Regression (fuzz_ins, issue 37 S3): a pending fix vanished uncounted at a
 * new init; so at an alignment and when an outage loses the state. Each
 * drops it into gnss_pending_dropped; a refused init or alignment changes
 * nothing, the fix still held. */
static void test_pending_fix_dropped_by_a_new_state_is_counted(void **state)
{
    (void)state;
    const double p0[3] = {0.0, 0.0, 0.0};
    se23_ins_gnss_t fix;
    se23_ins_align_t a;
    se23_gauss_t g;
    setup_init(1);
    it_initial(15, 1e-3, 0.1, 1.0, &g);
    memset(&a, 0, sizeof a);
    a.sigma_p = a.sigma_v = a.sigma_yaw = a.sigma_bg = a.sigma_ba = SE23_R(1);
    assert_int_equal(it_run_rest(&ins, NULL, NULL, 0, 0, 100), 100);
    it_fix(103 * IT_DT_NS, p0, 1.0, &fix);
    assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_PENDING);
    /* refused: nothing changes */
    assert_int_equal(se23_ins_init(&ins, -1, &g), SE23_ERR_DT);
    a.sigma_p = SE23_R(-1);
    assert_int_equal(se23_ins_align(&ins, &a), SE23_ERR_DOMAIN);
    a.sigma_p = SE23_R(1);
    assert_int_equal(ins.have_pending, 1);
    assert_int_equal(it_gnss_sum(&ins.c), 0U);
    /* a new init */
    assert_int_equal(se23_ins_init(&ins, 100 * IT_DT_NS, &g), SE23_OK);
    assert_int_equal(ins.have_pending, 0);
    assert_int_equal(ins.c.gnss_pending_dropped, 1);
    /* an alignment */
    assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_PENDING);
    assert_int_equal(se23_ins_align(&ins, &a), SE23_OK);
    assert_int_equal(ins.have_pending, 0);
    assert_int_equal(ins.c.gnss_pending_dropped, 2);
    /* an outage beyond max_outage (10 s) */
    assert_int_equal(se23_ins_init(&ins, 100 * IT_DT_NS, &g), SE23_OK);
    assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_PENDING);
    assert_int_equal(it_run_rest(&ins, NULL, NULL, 4000 * IT_DT_NS, 4000, 3), 0);
    assert_true((ins.status & SE23_INS_ST_LOST) != 0);
    assert_int_equal(ins.have_pending, 0);
    assert_int_equal(ins.c.gnss_pending_dropped, 3);
    assert_int_equal(it_gnss_sum(&ins.c), 3U);
}

/* Regression (fuzz_ins, UBSan): a state near INT64_MAX ns (any t >= 0 is
 * a valid time) made the fix screening compute t_ns + half a sample,
 * a signed overflow (undefined behaviour). The fixes are judged as at
 * any other time: a fix 10 ms ahead is held, then fused when its sample
 * arrives. */
static void test_fixes_near_the_end_of_time(void **state)
{
    (void)state;
    se23_ins_config_t c;
    se23_gauss_t g;
    se23_ins_gnss_t fix;
    const double p0[3] = {0, 0, 0};
    const long long t0 = INT64_MAX - 2 * IT_DT_NS;
    it_config(&c, 1);
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    it_initial(15, 1e-3, 0.1, 1.0, &g);
    assert_int_equal(se23_ins_init(&ins, t0, &g), SE23_OK);
    it_fix(INT64_MAX, p0, 1.0, &fix);
    assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_PENDING);
    assert_int_equal(it_run_rest(&ins, NULL, NULL, t0, 0, 1), 1); /* 5 ms to go: held */
    assert_int_equal(ins.have_pending, 1);
    assert_int_equal(it_run_rest(&ins, NULL, NULL, t0 + IT_DT_NS, 1, 1), 1); /* due */
    assert_int_equal(ins.have_pending, 0);
    assert_int_equal(ins.c.gnss_used, 1);
    assert_int_equal(ins.t_ns, INT64_MAX);
    it_fix(INT64_MAX, p0, 1.0, &fix); /* not after the last fused fix */
    assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_STALE);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_ins_memory_is_as_documented),
        cmocka_unit_test(test_setup_rejects_each_bad_field_and_writes_nothing),
        cmocka_unit_test(test_init_checks_the_state_once_and_counts_rejections),
        cmocka_unit_test(test_init_keeps_an_exactly_symmetric_covariance),
        cmocka_unit_test(test_every_sample_ends_in_one_counter),
        cmocka_unit_test(test_motion_noise_is_the_density_it_states),
        cmocka_unit_test(test_range_is_per_axis),
        cmocka_unit_test(test_zupt_sigma_grows_with_the_rate),
        cmocka_unit_test(test_nonfinite_reading_is_judged_before_its_time),
        cmocka_unit_test(test_every_sample_ends_in_one_counter_when_the_step_fails),
        cmocka_unit_test(test_init_refuses_means_beyond_the_physical_bounds),
        cmocka_unit_test(test_counters_saturate),
        cmocka_unit_test(test_every_fix_ends_in_one_counter),
        cmocka_unit_test(test_every_fix_ends_in_one_counter_at_the_bounds),
        cmocka_unit_test(test_pending_fix_dropped_by_a_clock_step_is_counted),
        cmocka_unit_test(test_pending_fix_dropped_by_a_new_state_is_counted),
        cmocka_unit_test(test_fixes_near_the_end_of_time),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
