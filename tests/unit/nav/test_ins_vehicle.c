/* Unit tests of the navigation filter's vehicle features (ins.h,
 * "Vehicles"): the non-holonomic constraint applied once per nhc_interval
 * (at the same samples in every run) pulls a wrong lateral velocity to
 * zero and leaves the forward one alone; the GNSS time offset fuses a fix
 * as if stamped on the IMU's clock; rest_speed_max keeps a steady cruise
 * from passing for rest, rest_accel_sigma a car that pulls away; gravity
 * follows the position; the car preset passes setup at any rate it
 * accepts and refuses the others. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "ins_test.h"
#include "se23/earth.h"
#include "se23/geodetic.h"
#include "se23/ins.h"
#include "se23_test.h"

static se23_ins_t ins; /* large: static */

#define M_PI_OVER_180 (3.14159265358979323846 / 180.0)

static double norm2(const se23_vec3_t *v)
{
    return (double)v->v[0] * v->v[0] + (double)v->v[1] * v->v[1] + (double)v->v[2] * v->v[2];
}

/* it_config without ZUPT, 15 states, NHC of sigma_nhc (0: off) once a
 * second, started level at the origin moving at v0 (nav = body frame),
 * velocity 1-sigma s_v. */
static void start_moving(double sigma_nhc, const double v0[3], double s_v)
{
    se23_ins_config_t c;
    se23_gauss_t g;
    it_config(&c, 1);
    c.zupt = 0;
    c.nhc_sigma = (se23_real_t)sigma_nhc;
    c.nhc_interval = SE23_R(1);
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    it_initial(15, 1e-3, s_v, 1.0, &g);
    for (int i = 0; i < 3; ++i) {
        g.T.v.v[i] = (se23_real_t)v0[i];
    }
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_OK);
}

/* n noise-free samples of a level body moving at a constant velocity (it
 * reads what a body at rest reads), from sample k0 + 1. */
static void cruise(int k0, int n)
{
    for (int k = k0 + 1; k <= k0 + n; ++k) {
        se23_vec3_t w, f;
        it_rest_sample(NULL, NULL, NULL, NULL, &w, &f);
        assert_int_equal(se23_ins_imu(&ins, k * IT_DT_NS, k, &w, &f), SE23_INS_USED);
    }
}

static double vel_var(const se23_gauss_t *g, int i)
{
    return (double)g->P.m[SE23_GAUSS_NMAX * (SE23_IDX_NU + i) + (SE23_IDX_NU + i)];
}

/* A car believed to slide sideways at 0.8 m/s (1-sigma 1 m/s) while it
 * drives straight at 10 m/s: five seconds of NHC bring the lateral
 * velocity within its new 1-sigma of zero and below 0.3 m/s; the forward
 * velocity and its variance stay as they were to 1 %; exactly one update
 * per second. Without NHC the lateral velocity stays 0.8 m/s. */
static void test_nhc_pulls_lateral_velocity_to_zero(void **state)
{
    (void)state;
    const double v0[3] = {10.0, 0.8, 0.0};
    se23_gauss_t with, without;
    int64_t t;
    start_moving(0.3, v0, 1.0);
    cruise(0, 5 * 200);
    assert_int_equal(ins.c.nhc_used, 5);
    assert_int_equal(ins.c.filter_errors, 0);
    assert_int_equal(se23_ins_state(&ins, &with, &t), SE23_OK);
    start_moving(0.0, v0, 1.0);
    cruise(0, 5 * 200);
    assert_int_equal(ins.c.nhc_used, 0);
    assert_int_equal(se23_ins_state(&ins, &without, &t), SE23_OK);
    print_message("lateral v: NHC %.4f (1-sigma %.4f), none %.4f\n", (double)with.T.v.v[1],
                  sqrt(vel_var(&with, 1)), (double)without.T.v.v[1]);
    assert_true(fabs((double)with.T.v.v[1]) < 0.3);
    assert_true(fabs((double)with.T.v.v[1]) < 3.0 * sqrt(vel_var(&with, 1)));
    assert_true(vel_var(&with, 1) < 0.3 * 0.3);
    assert_true(fabs((double)without.T.v.v[1] - 0.8) < 0.01);
    assert_true(fabs((double)with.T.v.v[0] - 10.0) < 0.1);
    assert_true(fabs(vel_var(&with, 0) / vel_var(&without, 0) - 1.0) < 0.01);
}

/* nhc_lever: in a turn (yaw rate 0.5 rad/s) the constraint's 1-sigma is
 * sqrt(0.3^2 + (2 m x 0.5)^2) = 1.04 m/s, so after the first update (1 s)
 * the lateral velocity's variance stays larger than with nhc_lever 0; on
 * a straight (no rate) the two runs are the same, value for value. */
static void test_nhc_lever_weakens_the_constraint_in_turns(void **state)
{
    (void)state;
    const double v0[3] = {10.0, 0.0, 0.0};
    const double g = it_gravity();
    for (int turning = 0; turning <= 1; ++turning) {
        se23_gauss_t out[2];
        int64_t t;
        for (int lever = 0; lever <= 1; ++lever) {
            se23_ins_config_t c;
            se23_gauss_t init;
            it_config(&c, 1);
            c.zupt = 0;
            c.nhc_sigma = SE23_R(0.3);
            c.nhc_interval = SE23_R(1);
            c.nhc_lever = (lever != 0) ? SE23_R(2) : SE23_R(0);
            assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
            it_initial(15, 1e-3, 1.0, 1.0, &init);
            for (int i = 0; i < 3; ++i) {
                init.T.v.v[i] = (se23_real_t)v0[i];
            }
            assert_int_equal(se23_ins_init(&ins, 0, &init), SE23_OK);
            for (int k = 1; k <= 200; ++k) {
                const se23_vec3_t w = {{0, 0, (se23_real_t)(turning ? 0.5 : 0.0)}};
                const se23_vec3_t f = {{0, (se23_real_t)(turning ? 5.0 : 0.0), (se23_real_t)-g}};
                assert_int_equal(se23_ins_imu(&ins, k * IT_DT_NS, k, &w, &f), SE23_INS_USED);
            }
            assert_int_equal(ins.c.nhc_used, 1);
            assert_int_equal(se23_ins_state(&ins, &out[lever], &t), SE23_OK);
        }
        if (turning) {
            assert_true(vel_var(&out[1], 1) > 2.0 * vel_var(&out[0], 1));
        } else {
            assert_memory_equal(&out[0].P, &out[1].P, sizeof out[0].P);
        }
    }
}

/* The NHC samples are a function of time alone: a run cut into two calls
 * of the same samples, or started at another sample, applies them at the
 * multiples of nhc_interval: 3 updates in (0, 3.5 s], 2 in (3.5, 5.5]. */
static void test_nhc_at_whole_intervals(void **state)
{
    (void)state;
    const double v0[3] = {10.0, 0.0, 0.0};
    start_moving(0.3, v0, 0.1);
    cruise(0, 700);
    assert_int_equal(ins.c.nhc_used, 3);
    cruise(700, 400);
    assert_int_equal(ins.c.nhc_used, 5);
}

/* A fix stamped on a GNSS clock 0.2 s behind the IMU's, with
 * gnss_time_offset 0.2 s, gives the state the same fix stamped on the
 * IMU's clock gives without it, value for value. */
static void test_gnss_time_offset_moves_the_fix(void **state)
{
    (void)state;
    const double p[3] = {0.3, -0.2, 0.1};
    se23_ins_config_t c;
    se23_gauss_t g, a, b;
    se23_ins_gnss_t fix;
    int64_t t;
    it_config(&c, 1);
    c.gnss_time_offset = (se23_real_t)0.2;
    for (int run = 0; run < 2; ++run) {
        assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
        it_initial(15, 1e-2, 0.1, 1.0, &g);
        assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_OK);
        assert_int_equal(it_run_rest(&ins, NULL, NULL, 0, 0, 200), 200);
        /* at 1 s on the IMU's clock */
        it_fix(1000000000LL - (run == 0 ? 200000000LL : 0), p, 0.05, &fix);
        assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_USED);
        assert_int_equal(it_run_rest(&ins, NULL, NULL, 200 * IT_DT_NS, 200, 10), 10);
        assert_int_equal(se23_ins_state(&ins, run == 0 ? &a : &b, &t), SE23_OK);
        c.gnss_time_offset = SE23_R(0);
    }
    assert_memory_equal(&a.T, &b.T, sizeof a.T);
    assert_memory_equal(&a.P, &b.P, sizeof a.P);
    /* without the offset the same stamp is in the past: fused by replay,
     * a different state */
    c.gnss_time_offset = SE23_R(0);
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_OK);
    assert_int_equal(it_run_rest(&ins, NULL, NULL, 0, 0, 200), 200);
    it_fix(800000000LL, p, 0.05, &fix);
    assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_USED);
    assert_int_equal(ins.c.gnss_delayed, 1);
    /* a negative stamp stays refused whatever the offset */
    c.gnss_time_offset = SE23_R(1);
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_OK);
    it_fix(-500000000LL, p, 0.05, &fix);
    assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_NONFINITE);
}

/* A level body cruising at 10 m/s reads what a body at rest reads: the
 * detector calls its windows stationary, and without rest_speed_max (nor
 * the gravity test) the filter applies ZUPTs and loses the speed (the
 * first ones' bias estimates then make the detector see motion); with it (0.5 m/s) it knows it
 * is moving and applies none. */
static void test_rest_speed_max_keeps_a_cruise_moving(void **state)
{
    (void)state;
    se23_ins_config_t c;
    se23_gauss_t g, out;
    int64_t t;
    for (int run = 0; run < 2; ++run) {
        it_config(&c, 1);
        c.rest_speed_max = (run == 0) ? SE23_R(0) : SE23_R(0.5);
        c.gravity_test_off = 1; /* the speed test alone */
        assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
        it_initial(15, 1e-3, 0.05, 1.0, &g);
        g.T.v.v[0] = SE23_R(10);
        assert_int_equal(se23_ins_init(&ins, 0, &g), SE23_OK);
        cruise(0, 400);
        assert_int_equal(se23_ins_state(&ins, &out, &t), SE23_OK);
        print_message("rest_speed_max %g: %u ZUPTs, v %.3f m/s\n", (double)c.rest_speed_max,
                      ins.c.zupt_used, (double)out.T.v.v[0]);
        if (run == 0) {
            assert_true(ins.c.zupt_used >= 1);
            assert_true((double)out.T.v.v[0] < 5.0);
        } else {
            assert_int_equal(ins.c.zupt_used, 0);
            assert_true(fabs((double)out.T.v.v[0] - 10.0) < 0.01);
        }
    }
}

/* A car pulling away at 1 m/s^2 after 2 s at rest, under a detector wide
 * enough for an idling engine's vibration (sigma_a 1.5 m/s^2, which the
 * pull passes): with the gravity test's 1-sigma at white noise's
 * sigma_a / sqrt(W) (0.34 m/s^2) the ZUPTs hold it still for seconds; with
 * rest_accel_sigma 0.1 m/s^2 none is applied after the first window of
 * motion and the speed after 3 s is the truth's 3 m/s. */
static void test_rest_accel_sigma_lets_a_car_pull_away(void **state)
{
    (void)state;
    const double g = it_gravity();
    se23_ins_config_t c;
    se23_gauss_t init, out;
    int64_t t;
    for (int run = 0; run < 2; ++run) {
        uint32_t zupt_at_start = 0;
        it_config(&c, 1);
        c.detector.sigma_a = SE23_R(1.5);
        c.rest_accel_sigma = (run == 0) ? SE23_R(0) : SE23_R(0.1);
        assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
        it_initial(15, 1e-3, 0.01, 1.0, &init);
        assert_int_equal(se23_ins_init(&ins, 0, &init), SE23_OK);
        for (int k = 1; k <= 5 * 200; ++k) {
            se23_vec3_t w = {{0, 0, 0}}, f = {{0, 0, (se23_real_t)-g}};
            if (k > 2 * 200) {
                f.v[0] = SE23_R(1); /* level, pulling away along x */
            }
            if (k == 2 * 200 + 40) { /* 0.2 s into the motion: a window's worth */
                zupt_at_start = ins.c.zupt_used;
            }
            assert_int_equal(se23_ins_imu(&ins, k * IT_DT_NS, k, &w, &f), SE23_INS_USED);
        }
        assert_int_equal(se23_ins_state(&ins, &out, &t), SE23_OK);
        print_message("rest_accel_sigma %g: %u ZUPTs in motion, speed %.3f m/s (truth 3)\n",
                      (double)c.rest_accel_sigma, ins.c.zupt_used - zupt_at_start,
                      (double)out.T.v.v[0]);
        if (run == 0) {
            assert_true(ins.c.zupt_used - zupt_at_start > 100);
            assert_true((double)out.T.v.v[0] < 2.0);
        } else {
            assert_int_equal(ins.c.zupt_used, zupt_at_start);
            assert_true(fabs((double)out.T.v.v[0] - 3.0) < 0.05);
        }
    }
}

/* Gravity follows the position ("Frame"): a body at rest 10 km north and 5
 * km east of the origin (40 deg N, 1600 m) senses the gravity of that place,
 * whose direction in the origin's frame is the ellipsoid normal there
 * (se23_geo_down_at, tested on its own against the ECEF route) and whose
 * size is the normal gravity at that point's latitude and height
 * (se23_geo_from_ned, se23_earth_gravity). Unaided for 60 s, level in the
 * origin's axes: with gravity_step 100 m the filter's velocity stays within
 * 2 cm/s (the cube's centre is up to 50 m off: 15 ug, 8 urad); with the
 * origin's gravity everywhere (step 0) the 1.8 mrad tilt drifts it by about
 * 1 m/s. */
static void test_gravity_follows_the_position(void **state)
{
    (void)state;
    const se23_geo_t origin = {40000000000LL, -105000000000LL, 1600000};
    const se23_vec3_t p = {{SE23_R(10000), SE23_R(5000), SE23_R(0)}};
    se23_geo_frame_t frame;
    se23_geo_t here;
    se23_vec3_t down;
    se23_real_t g = SE23_R(0);
    double drift[2] = {0, 0};
    assert_int_equal(se23_geo_origin(&origin, &frame), SE23_OK);
    assert_int_equal(se23_geo_down_at(&frame, &p, &down), SE23_OK);
    assert_int_equal(se23_geo_from_ned(&frame, &p, &here), SE23_OK);
    assert_int_equal(se23_earth_gravity((se23_real_t)((double)here.lat_e9 * 1e-9 * M_PI_OVER_180),
                                        (se23_real_t)(here.h_mm * 1e-3), &g),
                     SE23_OK);
    for (int run = 0; run < 2; ++run) {
        se23_ins_config_t c;
        se23_gauss_t init, out;
        int64_t t;
        it_config(&c, 1);
        c.zupt = 0;
        c.lat = (se23_real_t)(40.0 * M_PI_OVER_180);
        c.height = SE23_R(1600);
        c.gravity_step = (run == 0) ? SE23_R(100) : SE23_R(0);
        assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
        it_initial(15, 1e-3, 0.01, 1.0, &init);
        init.T.p = p;
        assert_int_equal(se23_ins_init(&ins, 0, &init), SE23_OK);
        for (int k = 1; k <= 60 * 200; ++k) {
            /* at rest, body axes = the origin's NED: f = -g_true */
            const se23_vec3_t w = {{0, 0, 0}};
            const se23_vec3_t f = {{-g * down.v[0], -g * down.v[1], -g * down.v[2]}};
            assert_int_equal(se23_ins_imu(&ins, k * IT_DT_NS, k, &w, &f), SE23_INS_USED);
        }
        assert_int_equal(se23_ins_state(&ins, &out, &t), SE23_OK);
        drift[run] = sqrt((double)norm2(&out.T.v));
    }
    print_message("60 s at rest 11 km from the origin: |v| %.4f m/s with gravity_step 100 m,"
                  " %.3f m/s with the origin's gravity\n", drift[0], drift[1]);
    assert_true(drift[0] < 0.02);
    assert_true(drift[1] > 0.5);
}

/* The car preset passes se23_ins_setup and its alignment se23_ins_align at
 * rates from 50 Hz to 10 kHz (the detector window capped, the delay
 * horizon fitted to the ring), the installation left to the caller
 * (lever, mounting zero); other rates and latitudes are refused. */
static void test_car_preset(void **state)
{
    (void)state;
    const double rates[] = {50.0, 99.5, 100.0, 400.0, 1000.0, 10000.0};
    se23_ins_config_t c;
    se23_ins_align_t a;
    for (size_t k = 0; k < sizeof rates / sizeof rates[0]; ++k) {
        assert_int_equal(se23_ins_preset_car((se23_real_t)rates[k], (se23_real_t)0.7, &c, &a),
                         SE23_OK);
        assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
        assert_int_equal(se23_ins_align(&ins, &a), SE23_OK);
        assert_true(c.nhc_sigma > SE23_R(0) && c.earth_rotation == 1 && c.zupt == 1);
        assert_true(c.detector.window >= 2 && c.detector.window <= SE23_STATIONARY_WMAX);
        assert_true(a.course_speed > SE23_R(0));
        for (int i = 0; i < 3; ++i) {
            assert_true(c.lever_b.v[i] == SE23_R(0) && c.mount_bv.v[i] == SE23_R(0));
        }
    }
    assert_int_equal(se23_ins_preset_car(SE23_R(49), SE23_R(0), &c, &a), SE23_ERR_DOMAIN);
    assert_int_equal(se23_ins_preset_car((se23_real_t)NAN, SE23_R(0), &c, &a), SE23_ERR_DOMAIN);
    assert_int_equal(se23_ins_preset_car(SE23_R(100), SE23_R(3), &c, &a), SE23_ERR_DOMAIN);
#if SE23_CFG_ARG_CHECKS
    assert_int_equal(se23_ins_preset_car(SE23_R(100), SE23_R(0), NULL, &a), SE23_ERR_NULL);
    assert_int_equal(se23_ins_preset_car(SE23_R(100), SE23_R(0), &c, NULL), SE23_ERR_NULL);
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_nhc_pulls_lateral_velocity_to_zero),
        cmocka_unit_test(test_nhc_at_whole_intervals),
        cmocka_unit_test(test_nhc_lever_weakens_the_constraint_in_turns),
        cmocka_unit_test(test_gnss_time_offset_moves_the_fix),
        cmocka_unit_test(test_rest_speed_max_keeps_a_cruise_moving),
        cmocka_unit_test(test_rest_accel_sigma_lets_a_car_pull_away),
        cmocka_unit_test(test_gravity_follows_the_position),
        cmocka_unit_test(test_car_preset),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
