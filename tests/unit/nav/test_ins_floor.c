/* Unit tests of the floor updates (ins.h, "Floor"; src/nav/ins_aid.c,
 * src/nav/ins_rest.c): a body that hops and lands again on its level is put
 * back on it (without floor updates it stays where its IMU put it); a hop
 * of a stair riser starts a new level and the next stance holds to that
 * one; a blip shorter than floor_swing is not a new stance; a delayed fix
 * replayed across a stance equals the same fix on time; off, the floor
 * needs no settings (the refusals: test_ins.c). Noise-free samples of a level
 * body on flat Earth: the truth needs no integrator. */
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

static se23_ins_t ins, ref; /* large: static */
static long long k_now;     /* samples fed since init */

static void floor_config(se23_ins_config_t *c, double sigma)
{
    it_config(c, 1);
    c->floor_sigma = (se23_real_t)sigma;
    c->floor_step = (se23_real_t)0.05;
    c->floor_swing = (se23_real_t)0.2;
}

static void start(se23_ins_t *f, const se23_ins_config_t *c)
{
    se23_gauss_t g;
    assert_int_equal(se23_ins_setup(c, f), SE23_OK);
    it_initial(15, 1e-3, 0.01, 1.0, &g); /* height 1-sigma 1 m: the floor decides */
    assert_int_equal(se23_ins_init(f, 0, &g), SE23_OK);
    k_now = 0;
}

static void feed(se23_ins_t *f, double up_accel, int n)
{
    const double g = it_gravity();
    for (int k = 0; k < n; ++k) {
        const se23_vec3_t w = {{SE23_R(0), SE23_R(0), SE23_R(0)}};
        const se23_vec3_t sf = {{SE23_R(0), SE23_R(0), (se23_real_t)(-g - up_accel)}};
        ++k_now;
        assert_int_equal(se23_ins_imu(f, k_now * IT_DT_NS, k_now, &w, &sf), SE23_INS_USED);
    }
}

/* A vertical hop of height h [m] over 0.2 s (up at a for 0.1 s, then the
 * same down: v back to 0, h = a (0.1 s)^2), then 0.5 s at rest. */
static void hop(se23_ins_t *f, double h)
{
    const double a = h / 0.01;
    feed(f, a, 20);
    feed(f, -a, 20);
    feed(f, 0.0, 100);
}

/* ins with the floor's 1-sigma sigma, after 0.5 s at rest: the first
 * stance has set the level. */
static void start_on_floor(double sigma, se23_ins_config_t *c)
{
    floor_config(c, sigma);
    start(&ins, c);
    feed(&ins, 0.0, 100);
}

static double down(const se23_ins_t *f)
{
    se23_gauss_t out;
    int64_t t;
    assert_int_equal(se23_ins_state(f, &out, &t), SE23_OK);
    return (double)out.T.p.v[2];
}

static void test_floor_holds_a_hop_to_the_level(void **state)
{
    (void)state;
    se23_ins_config_t c;
    start_on_floor(1e-3, &c); /* the first rest sets the level */
    assert_int_equal(ins.c.floor_levels, 1);
    assert_int_equal(ins.c.floor_used, 0);
    assert_true(ins.floor_set == 1 && fabs((double)ins.floor_d) < 1e-9);
    hop(&ins, 0.02);
    assert_int_equal(ins.c.floor_used, 1);
    assert_int_equal(ins.c.floor_levels, 1);
    assert_true(fabs(down(&ins)) < 2e-3);
    /* without floor updates the same hop ends 2 cm up: the test can fail */
    start_on_floor(0.0, &c);
    hop(&ins, 0.02);
    assert_int_equal(ins.c.floor_used + ins.c.floor_levels, 0);
    assert_near(down(&ins), -0.02, 0.0, 2e-3);
}

static void test_a_stair_starts_a_new_level(void **state)
{
    (void)state;
    se23_ins_config_t c;
    start_on_floor(1e-3, &c);
    hop(&ins, 0.15); /* a riser: 3x floor_step */
    assert_int_equal(ins.c.floor_levels, 2);
    assert_int_equal(ins.c.floor_used, 0);
    assert_near(down(&ins), -0.15, 0.0, 2e-3);
    assert_near((double)ins.floor_d, -0.15, 0.0, 2e-3);
    hop(&ins, 0.02); /* within floor_step of the new level: held to it */
    assert_int_equal(ins.c.floor_levels, 2);
    assert_int_equal(ins.c.floor_used, 1);
    assert_near(down(&ins), (double)ins.floor_d, 0.0, 2e-3);
}

static void test_a_blip_is_not_a_new_stance(void **state)
{
    (void)state;
    se23_ins_config_t c;
    start_on_floor(1e-3, &c);
    feed(&ins, 1.0, 1); /* moving for one window, 0.1 s < floor_swing */
    feed(&ins, 0.0, 100);
    assert_true(ins.c.zupt_used > 150U); /* rest resumed */
    assert_int_equal(ins.c.floor_levels, 1);
    assert_int_equal(ins.c.floor_used, 0);
    hop(&ins, 0.02); /* 0.3 s of motion: a stance */
    assert_int_equal(ins.c.floor_used, 1);
}

/* A fix stamped in the last samples of a stair's hop (0.15 m), fused
 * 0.16 s late, after the stance on the new level began: the replay starts
 * from the snapshot's level (the old one) and sets the new level again,
 * as live; the state equals the fix applied on time. (Replayed from the
 * present level instead, the stance would be an update.) */
static void test_delayed_fix_replays_the_floor(void **state)
{
    (void)state;
    const double p[3] = {0.0, 0.0, -0.15};
    se23_ins_config_t c;
    se23_ins_gnss_t fix;
    floor_config(&c, 1e-2);
    c.gnss_gate = SE23_R(0);
    start(&ref, &c);
    feed(&ref, 0.0, 100);
    feed(&ref, 15.0, 20);
    feed(&ref, -15.0, 18);
    it_fix(k_now * IT_DT_NS, p, 0.5, &fix);
    assert_int_equal(se23_ins_gnss(&ref, &fix), SE23_INS_USED);
    feed(&ref, -15.0, 2);
    feed(&ref, 0.0, 60);
    assert_int_equal(ref.c.floor_levels, 2);
    start(&ins, &c);
    feed(&ins, 0.0, 100);
    feed(&ins, 15.0, 20);
    feed(&ins, -15.0, 20);
    feed(&ins, 0.0, 30);
    assert_int_equal(ins.c.floor_levels, 2); /* before the fix */
    assert_int_equal(se23_ins_gnss(&ins, &fix), SE23_INS_USED);
    assert_int_equal(ins.c.gnss_delayed, 1);
    feed(&ins, 0.0, 30);
    assert_int_equal(ins.c.floor_levels, 2); /* the replay does not count again */
    assert_int_equal(ins.c.floor_used, 0);
    assert_memory_equal(&ins.g, &ref.g, sizeof ins.g);
    assert_true(ins.floor_d == ref.floor_d);
}

/* The refusals are in test_ins.c's table; off, the other two settings are
 * not needed. */
static void test_floor_off_needs_no_settings(void **state)
{
    (void)state;
    se23_ins_config_t c;
    floor_config(&c, 0.0);
    c.floor_step = SE23_R(0);
    c.floor_swing = SE23_R(0);
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_floor_holds_a_hop_to_the_level),
        cmocka_unit_test(test_a_stair_starts_a_new_level),
        cmocka_unit_test(test_a_blip_is_not_a_new_stance),
        cmocka_unit_test(test_delayed_fix_replays_the_floor),
        cmocka_unit_test(test_floor_off_needs_no_settings),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
