/* Unit tests of src/nav/ins_align.c: static alignment recovers roll and pitch
 * within the bound the accelerometer noise allows (Monte Carlo against the
 * covariance it reports), models the tilt an accelerometer bias causes
 * (the correlation of phi and b_a), gyrocompasses on rotating Earth, and
 * rejects what it cannot use. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

#include <cmocka.h>

#include "gauss_test.h"
#include "ins_test.h"
#include "se23/ins.h"
#include "se23/so3.h"
#include "se23_test.h"

static se23_ins_t ins; /* large: static */

static void align_request(se23_ins_align_t *a)
{
    memset(a, 0, sizeof *a);
    a->sigma_p = SE23_R(1);
    a->yaw = (se23_real_t)0.3;
    a->sigma_yaw = (se23_real_t)0.1;
    a->sigma_v = (se23_real_t)0.01;
    a->sigma_bg = (se23_real_t)1e-3;
    a->sigma_ba = (se23_real_t)1e-2;
}

/* Roll, pitch, yaw -> R = Rz Ry Rx (body -> NED). */
static void euler(double roll, double pitch, double yaw, se23_mat3_t *R)
{
    se23_vec3_t a;
    se23_mat3_t Rx, Ry, Rz, T;
    a.v[0] = (se23_real_t)roll, a.v[1] = 0, a.v[2] = 0;
    assert_int_equal(se23_so3_exp(&a, &Rx), SE23_OK);
    a.v[0] = 0, a.v[1] = (se23_real_t)pitch, a.v[2] = 0;
    assert_int_equal(se23_so3_exp(&a, &Ry), SE23_OK);
    a.v[0] = 0, a.v[1] = 0, a.v[2] = (se23_real_t)yaw;
    assert_int_equal(se23_so3_exp(&a, &Rz), SE23_OK);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double s = 0;
            for (int k = 0; k < 3; ++k) {
                s += (double)Ry.m[i][k] * (double)Rx.m[k][j];
            }
            T.m[i][j] = (se23_real_t)s;
        }
    }
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double s = 0;
            for (int k = 0; k < 3; ++k) {
                s += (double)Rz.m[i][k] * (double)T.m[k][j];
            }
            R->m[i][j] = (se23_real_t)s;
        }
    }
}

/* Feeds rest samples at attitude R until aligned; returns the samples used. */
static int align_at(const se23_mat3_t *R, se23t_rng_t *rng, const double b_a[3])
{
    for (int k = 1; k <= 2000; ++k) {
        se23_vec3_t w, f;
        it_rest_sample(rng, R, NULL, b_a, &w, &f);
        if (se23_ins_imu(&ins, k * IT_DT_NS, k, &w, &f) == SE23_INS_USED) {
            return k;
        }
    }
    return -1;
}

/* The attitude error phi = log(Rbar^T R) of the aligned state. */
static void att_error(const se23_mat3_t *R, se23_vec3_t *phi, se23_gauss_t *out)
{
    se23_mat3_t E;
    int64_t t;
    assert_int_equal(se23_ins_state(&ins, out, &t), SE23_OK);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double s = 0;
            for (int k = 0; k < 3; ++k) {
                s += (double)out->T.R.m[k][i] * (double)R->m[k][j];
            }
            E.m[i][j] = (se23_real_t)s;
        }
    }
    assert_int_equal(se23_so3_log(&E, phi), SE23_OK);
}

static void test_alignment_tilt_matches_its_covariance(void **state)
{
    (void)state;
    se23_ins_config_t c;
    se23_ins_align_t a;
    se23t_rng_t rng;
    const int trials = 400;
    double nees = 0.0;
    it_config(&c, 0);
    align_request(&a);
    a.sigma_ba = SE23_R(0); /* no bias in the truth: the noise alone */
    se23t_rng_seed(&rng, 11);
    for (int tr = 0; tr < trials; ++tr) {
        se23_mat3_t R;
        se23_vec3_t phi;
        se23_gauss_t out;
        double P[9], L[9], x[3];
        /* the requested heading 0.3 is off the truth by N(0, 0.1^2) */
        euler(se23t_uniform(&rng, -0.5, 0.5), se23t_uniform(&rng, -0.5, 0.5),
              0.3 + 0.1 * se23t_normal(&rng), &R);
        assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
        assert_int_equal(se23_ins_align(&ins, &a), SE23_OK);
        assert_true((ins.status & SE23_INS_ST_ALIGNING) != 0);
        /* the detector's first full window, then one window averaged */
        assert_int_equal(align_at(&R, &rng, NULL), 2 * c.detector.window - 1);
        assert_true((ins.status & SE23_INS_ST_INITIALISED) != 0);
        att_error(&R, &phi, &out);
        /* NEES of the 3-dim attitude error, chi^2_3 for a consistent alignment */
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j) {
                P[3 * i + j] = (double)out.P.m[SE23_GAUSS_NMAX * i + j];
            }
            x[i] = (double)phi.v[i];
        }
        assert_true(gt_chol(P, 3, L) != 0);
        nees += gt_nees(L, 3, x);
    }
    nees /= trials;
    {
        double lo, hi;
        gt_chi2_mean_interval(3, trials, &lo, &hi);
        print_message("alignment: mean NEES %.3f in [%.3f, %.3f]\n", nees, lo, hi);
        assert_true(nees > lo && nees < hi);
    }
}

static void test_alignment_models_the_bias_tilt(void **state)
{
    (void)state;
    const double b_a[3] = {0.03, -0.02, 0.0}; /* a horizontal bias: it tilts */
    se23_ins_config_t c;
    se23_ins_align_t a;
    se23_mat3_t R;
    se23_vec3_t phi;
    se23_gauss_t out;
    it_config(&c, 1);
    align_request(&a);
    euler(0.0, 0.0, 0.3, &R);
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    assert_int_equal(se23_ins_align(&ins, &a), SE23_OK);
    assert_true(align_at(&R, NULL, b_a) > 0);
    att_error(&R, &phi, &out);
    /* noise-free: phi = -(1/g) u^ b_a with u = (0, 0, -1) (up, body) */
    {
        const double g = it_gravity();
        const double expect[3] = {-b_a[1] / g, b_a[0] / g, 0.0};
        for (int i = 0; i < 3; ++i) {
            /* to first order: the Euler heading held by levelling moves phi
             * along the vertical by O(tilt^2) */
            assert_near((double)phi.v[i], expect[i], 1e-5, 1e-3);
        }
        /* and the covariance says the same: Cov(phi, b_a) = -(sb^2/g) u^ */
        const double sb2 = 1e-4;
        assert_near((double)out.P.m[SE23_GAUSS_NMAX * 0 + 13], -sb2 / g, 1e-9, 1e-4);
        assert_near((double)out.P.m[SE23_GAUSS_NMAX * 1 + 12], sb2 / g, 1e-9, 1e-4);
        assert_int_equal(se23_gauss_check(&out), SE23_OK);
    }
}

static void test_gyrocompass_on_rotating_earth(void **state)
{
    (void)state;
    const double lat = 0.8, yaw = 1.1;
    se23_ins_config_t c;
    se23_ins_align_t a;
    se23_mat3_t R;
    se23_vec3_t g_n, w_ie, phi;
    se23_gauss_t out;
    int done = 0;
    it_config(&c, 0);
    c.earth_rotation = 1;
    c.lat = (se23_real_t)lat;
    /* the detector's gyro term must allow the Earth rate it senses at rest;
     * the alignment's noise is the sensor's (navigation grade) */
    c.detector.sigma_g = (se23_real_t)1e-4;
    c.noise.gyro_noise = (se23_real_t)(1e-7 / sqrt(IT_RATE));
    c.detector.window = 32;
    assert_int_equal(se23_earth_gravity_vec(SE23_FRAME_NED, c.lat, SE23_R(0), &g_n), SE23_OK);
    assert_int_equal(se23_earth_rate(SE23_FRAME_NED, c.lat, &w_ie), SE23_OK);
    c.detector.gravity = g_n.v[2];
    align_request(&a);
    a.gyrocompass = 1;
    euler(0.05, -0.1, yaw, &R);
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    assert_int_equal(se23_ins_align(&ins, &a), SE23_OK);
    for (int k = 1; k <= 100 && done == 0; ++k) {
        se23_vec3_t w, f;
        for (int i = 0; i < 3; ++i) { /* f = R^T (-g_n), w = R^T w_ie, noise-free */
            f.v[i] = -(R.m[0][i] * g_n.v[0] + R.m[1][i] * g_n.v[1] + R.m[2][i] * g_n.v[2]);
            w.v[i] = R.m[0][i] * w_ie.v[0] + R.m[1][i] * w_ie.v[1] + R.m[2][i] * w_ie.v[2];
        }
        done = se23_ins_imu(&ins, k * IT_DT_NS, k, &w, &f) == SE23_INS_USED;
    }
    assert_true(done);
    att_error(&R, &phi, &out);
    print_message("gyrocompass: heading error %.2e rad, sigma %.2e\n", (double)phi.v[2],
                  sqrt((double)out.P.m[SE23_GAUSS_NMAX * 2 + 2]));
    for (int i = 0; i < 3; ++i) {
        assert_true(fabs((double)phi.v[i]) < (SE23_CFG_DOUBLE ? 1e-6 : 2e-2));
    }
    assert_true(sqrt((double)out.P.m[SE23_GAUSS_NMAX * 2 + 2]) < 0.01);
}

/* Heading from the GNSS course: aligned level at rest with the heading
 * unknown, then accelerating along the vehicle's forward axis on a true
 * heading of 1.1 rad, the IMU mounted turned by mount_yaw about the down
 * axis (x_b = Rz(mount_yaw) x_v: forward is body (cos, sin, 0)); the
 * first fix faster than course_speed sets the heading of the vehicle's
 * axis (ins.h, "Vehicles"), so body x points at 1.1 - mount_yaw, and the
 * filter then tracks the truth with fixes that pass the gate. */
static void course_run(double mount_yaw)
{
    const double psi = 1.1, a_x = 1.0, g = it_gravity();
    se23_ins_config_t c;
    se23_ins_align_t a;
    se23_gauss_t out;
    int64_t t;
    int k, fixes = 0;
    it_config(&c, 1);
    c.mount_bv.v[2] = (se23_real_t)mount_yaw;
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    align_request(&a);
    a.yaw = SE23_R(0); /* unused: the course decides */
    a.course_speed = SE23_R(2);
    a.course_sigma = (se23_real_t)0.02;
    assert_int_equal(se23_ins_align(&ins, &a), SE23_OK);
    for (k = 1; k <= 8 * 200; ++k) {
        const double tk = k / IT_RATE, tm = tk - 2.0; /* moving after 2 s at rest */
        se23_vec3_t w = {{0, 0, 0}}, f = {{0, 0, (se23_real_t)-g}};
        if (tm > 0) { /* level, accelerating along the vehicle's forward axis */
            f.v[0] = (se23_real_t)(a_x * cos(mount_yaw));
            f.v[1] = (se23_real_t)(a_x * sin(mount_yaw));
        }
        (void)se23_ins_imu(&ins, k * IT_DT_NS, k, &w, &f);
        if (tm > 0.5 && k % 40 == 0) { /* truth: v = a t (cos psi, sin psi, 0) */
            const double v = a_x * tm, s = 0.5 * a_x * tm * tm;
            const double p[3] = {s * cos(psi), s * sin(psi), 0.0};
            se23_ins_gnss_t fix;
            it_fix(k * IT_DT_NS, p, 0.05, &fix);
            fix.has_vel = 1;
            fix.v_n.v[0] = (se23_real_t)(v * cos(psi));
            fix.v_n.v[1] = (se23_real_t)(v * sin(psi));
            for (int i = 0; i < 3; ++i) {
                fix.sigma_v.v[i] = (se23_real_t)0.05;
            }
            const se23_ins_verdict_t vd = se23_ins_gnss(&ins, &fix);
            if (v < 2.0) {
                assert_true((ins.status & SE23_INS_ST_HEADING_UNKNOWN) != 0);
            } else {
                assert_int_equal(vd, SE23_INS_USED);
                assert_int_equal(ins.status & SE23_INS_ST_HEADING_UNKNOWN, 0);
                fixes++;
            }
        }
    }
    assert_int_equal(ins.c.course_headings, 1);
    assert_true(fixes > 10);
    assert_int_equal(ins.c.gnss_gated, 0);
    assert_int_equal(se23_ins_state(&ins, &out, &t), SE23_OK);
    assert_int_equal(se23_gauss_check(&out), SE23_OK);
    {
        const double yaw = atan2((double)out.T.R.m[1][0], (double)out.T.R.m[0][0]);
        const double want = remainder(psi - mount_yaw, 2.0 * 3.14159265358979323846);
        const double s_yaw = sqrt((double)out.P.m[SE23_GAUSS_NMAX * 2 + 2]);
        print_message("course heading: body yaw %.4f (truth %.4f), sigma %.4f\n", yaw, want,
                      s_yaw);
        assert_true(fabs(remainder(yaw - want, 2.0 * 3.14159265358979323846)) < 3 * s_yaw + 1e-3);
        assert_true(s_yaw < 0.03);
    }
}

static void test_heading_from_gnss_course(void **state)
{
    (void)state;
    se23_ins_align_t a;
    course_run(0.0);
    /* the request's checks */
    align_request(&a);
    a.course_speed = SE23_R(2);
    assert_int_equal(se23_ins_align(&ins, &a), SE23_ERR_DOMAIN); /* no course_sigma */
}

/* An IMU mounted sideways (forward is body y) and one turned by 0.8 rad.
 * (Before the course the heading's 1-sigma is 1 rad: a true heading much
 * further from the aligned one gates the position-only fixes of the
 * test's gate; the mounting does not change that.) */
static void test_course_heading_is_the_vehicles_axis(void **state)
{
    (void)state;
    course_run(3.14159265358979323846 / 2.0);
    course_run(0.8);
}

/* measure_noise (ins.h, "Alignment"): the densities the filter propagates
 * become those the rest shows where they are above the configured ones
 * (the data sheet a floor), the configured ones where the rest is
 * quieter; without it they stay configured. The rest's noise is IT_SG,
 * IT_SA per sample: densities IT_SG sqrt(dt), IT_SA sqrt(dt). */
static void test_alignment_measures_the_noise(void **state)
{
    (void)state;
    const double dt = 1.0 / IT_RATE;
    const double want_g = IT_SG * sqrt(dt), want_a = IT_SA * sqrt(dt);
    for (int k = 0; k < 3; ++k) {
        se23_ins_config_t c;
        se23_ins_align_t a;
        se23t_rng_t rng;
        se23t_rng_seed(&rng, 34u + (unsigned)k);
        it_config(&c, 1);
        align_request(&a);
        a.duration = SE23_R(2); /* 400 samples, 1,200 readings per sensor */
        /* k = 0: a data sheet 10x below the unit; 1: 10x above; 2: no measuring */
        const double scale = (k == 1) ? 10.0 : 0.1;
        c.noise.gyro_noise = (se23_real_t)(want_g * scale);
        c.noise.accel_noise = (se23_real_t)(want_a * scale);
        a.measure_noise = (k == 2) ? 0 : 1;
        assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
        assert_int_equal(se23_ins_align(&ins, &a), SE23_OK);
        assert_true(align_at(NULL, &rng, NULL) > 0);
        if (k == 0) { /* measured: within 10 % (the std's sampling error is 2 %) */
            assert_near((double)ins.noise.gyro_noise, want_g, 0.0, 0.1);
            assert_near((double)ins.noise.accel_noise, want_a, 0.0, 0.1);
        } else { /* the configured densities */
            assert_true(ins.noise.gyro_noise == c.noise.gyro_noise);
            assert_true(ins.noise.accel_noise == c.noise.accel_noise);
        }
    }
    /* a request with measure_noise neither 0 nor 1 is refused */
    {
        se23_ins_config_t c;
        se23_ins_align_t a;
        it_config(&c, 1);
        align_request(&a);
        a.measure_noise = 2;
        assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
        assert_int_equal(se23_ins_align(&ins, &a), SE23_ERR_DOMAIN);
    }
}

static void test_align_rejects_what_it_cannot_use(void **state)
{
    (void)state;
    se23_ins_config_t c;
    se23_ins_align_t a;
    it_config(&c, 1);
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    align_request(&a);
    a.sigma_p = SE23_R(0);
    assert_int_equal(se23_ins_align(&ins, &a), SE23_ERR_DOMAIN);
    align_request(&a);
    a.yaw = (se23_real_t)NAN;
    assert_int_equal(se23_ins_align(&ins, &a), SE23_ERR_NONFINITE);
    align_request(&a);
    a.gyrocompass = 1; /* flat Earth */
    assert_int_equal(se23_ins_align(&ins, &a), SE23_ERR_DOMAIN);
    align_request(&a);
    a.sigma_bg = SE23_R(0); /* bias states need it */
    assert_int_equal(se23_ins_align(&ins, &a), SE23_ERR_DOMAIN);
    /* a position beyond SE23_INS_POS_MAX (ins.h, "Validation"), on the
     * diagonal: the bound is on |p| */
    align_request(&a);
    for (int i = 0; i < 3; ++i) {
        a.p_n.v[i] = (se23_real_t)((double)SE23_INS_POS_MAX * 1.001 / sqrt(3.0));
    }
    assert_int_equal(se23_ins_align(&ins, &a), SE23_ERR_DOMAIN);
    assert_int_equal(se23_ins_align(NULL, &a), SE23_ERR_NULL);
    assert_int_equal(ins.c.init_rejected, 5);
    assert_int_equal(ins.status & SE23_INS_ST_ALIGNING, 0);
    c.zupt = 0; /* no detector */
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    align_request(&a);
    assert_int_equal(se23_ins_align(&ins, &a), SE23_ERR_DOMAIN);
    /* moving: never aligned, every sample counted */
    it_config(&c, 1);
    assert_int_equal(se23_ins_setup(&c, &ins), SE23_OK);
    assert_int_equal(se23_ins_align(&ins, &a), SE23_OK);
    for (int k = 1; k <= 100; ++k) {
        se23_vec3_t w, f;
        it_rest_sample(NULL, NULL, NULL, NULL, &w, &f);
        w.v[2] = SE23_R(1); /* turning */
        assert_int_equal(se23_ins_imu(&ins, k * IT_DT_NS, k, &w, &f), SE23_INS_EARLY);
    }
    assert_int_equal(ins.c.imu_align, 100);
    assert_int_equal(ins.status & SE23_INS_ST_INITIALISED, 0);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_alignment_tilt_matches_its_covariance),
        cmocka_unit_test(test_alignment_models_the_bias_tilt),
        cmocka_unit_test(test_gyrocompass_on_rotating_earth),
        cmocka_unit_test(test_heading_from_gnss_course),
        cmocka_unit_test(test_course_heading_is_the_vehicles_axis),
        cmocka_unit_test(test_alignment_measures_the_noise),
        cmocka_unit_test(test_align_rejects_what_it_cannot_use),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
