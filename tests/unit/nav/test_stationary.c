/* Unit and statistical tests of src/nav/stationary.c: the SHOE statistic against
 * hand-computed windows and against its definition (double, with the
 * direction u = fbar / |fbar|) over sliding windows; the chi^2_{6W-2}
 * law at rest (the rate at the 95 % threshold and the mean of W T, which
 * tells 6W - 2 from 6W - 3); motion never stationary; means and variances;
 * every status and nothing written on error. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "se23/stationary.h"
#include "se23_test.h"

#define SENTINEL 0x5a
#define G 9.81

/* Standard normal quantile of 0.95. */
#define Z95 1.6448536269514722

/* Wilson-Hilferty quantile of chi^2_k at the normal quantile z. */
static double chi2_quantile(double k, double z)
{
    const double a = 2.0 / (9.0 * k);
    return k * pow(1.0 - a + z * sqrt(a), 3);
}

static se23_stationary_config_t config(int window, double sigma_a, double sigma_g,
                                       double gravity, double threshold)
{
    se23_stationary_config_t c;
    c.window = window;
    c.sigma_a = (se23_real_t)sigma_a;
    c.sigma_g = (se23_real_t)sigma_g;
    c.gravity = (se23_real_t)gravity;
    c.threshold = (se23_real_t)threshold;
    return c;
}

static se23_vec3_t vec(double x, double y, double z)
{
    se23_vec3_t v = {{(se23_real_t)x, (se23_real_t)y, (se23_real_t)z}};
    return v;
}

/* Every field of a equals b's, bit for bit (padding, which struct copies
 * need not preserve, excluded). */
static int same_state(const se23_stationary_t *a, const se23_stationary_t *b)
{
    return a->cfg.window == b->cfg.window &&
           memcmp(&a->cfg.sigma_a, &b->cfg.sigma_a, sizeof a->cfg.sigma_a) == 0 &&
           memcmp(&a->cfg.sigma_g, &b->cfg.sigma_g, sizeof a->cfg.sigma_g) == 0 &&
           memcmp(&a->cfg.gravity, &b->cfg.gravity, sizeof a->cfg.gravity) == 0 &&
           memcmp(&a->cfg.threshold, &b->cfg.threshold, sizeof a->cfg.threshold) == 0 &&
           memcmp(a->w, b->w, sizeof a->w) == 0 && memcmp(a->f, b->f, sizeof a->f) == 0 &&
           a->count == b->count && a->head == b->head &&
           memcmp(&a->stat, &b->stat, sizeof a->stat) == 0 && a->stationary == b->stationary;
}

static void add_ok(se23_stationary_t *d, se23_vec3_t w, se23_vec3_t f, int *flag)
{
    assert_int_equal(se23_stationary_add(d, &w, &f, flag), SE23_OK);
}

/* The definition, in double, over n samples: the direction u = fbar/|fbar|
 * (the form of Skog et al.), not the library's decomposition. */
static double shoe_reference(const se23_vec3_t *w, const se23_vec3_t *f, int n,
                             double sa, double sg, double g)
{
    double fbar[3] = {0, 0, 0};
    for (int k = 0; k < n; ++k) {
        for (int j = 0; j < 3; ++j) {
            fbar[j] += (double)f[k].v[j] / n;
        }
    }
    const double nf = sqrt(fbar[0] * fbar[0] + fbar[1] * fbar[1] + fbar[2] * fbar[2]);
    double t = 0;
    for (int k = 0; k < n; ++k) {
        for (int j = 0; j < 3; ++j) {
            const double e = (double)f[k].v[j] - g * fbar[j] / nf;
            t += e * e / (sa * sa) + (double)w[k].v[j] * w[k].v[j] / (sg * sg);
        }
    }
    return t / n;
}

/* One rest sample: f = g u0 + noise, w = noise. */
static void rest_sample(se23t_rng_t *rng, const double u0[3], double sa, double sg,
                        se23_vec3_t *w, se23_vec3_t *f)
{
    for (int j = 0; j < 3; ++j) {
        f->v[j] = (se23_real_t)(G * u0[j] + sa * se23t_normal(rng));
        w->v[j] = (se23_real_t)(sg * se23t_normal(rng));
    }
}

static void random_unit(se23t_rng_t *rng, double u[3])
{
    se23_vec3_t a;
    se23t_random_axis_angle(rng, 1.0, &a);
    for (int j = 0; j < 3; ++j) {
        u[j] = a.v[j];
    }
}

/* ------------------------------------------------------------ the statistic */

static void test_stationary_add_hand_computed_windows(void **state)
{
    (void)state;
    /* W = 2, sigma_a = 1, sigma_g = 0.1, g = 10. f = (0,0,-9), (0,0,-11):
     * fbar = (0,0,-10), u = (0,0,-1), |f_k - g u|^2 = 1 each; w = (0.1,0,0),
     * (0,0.2,0): |w|^2 / sigma_g^2 = 1, 4. T = (2 + 5) / 2 = 3.5. */
    se23_stationary_config_t c = config(2, 1, 0.1, 10, 4);
    se23_stationary_t d;
    int flag = -1;
    assert_int_equal(se23_stationary_init(&c, &d), SE23_OK);
    add_ok(&d, vec(0.1, 0, 0), vec(0, 0, -9), &flag);
    /* One sample: T = (|f| - g)^2 / sigma_a^2 + |w|^2 / sigma_g^2 = 2, below
     * the threshold but the window is not full. */
    assert_near(d.stat, 2.0, 0, 16 * SE23T_EPS);
    assert_int_equal(flag, 0);
    assert_int_equal(d.stationary, 0);
    add_ok(&d, vec(0, 0.2, 0), vec(0, 0, -11), &flag);
    assert_near(d.stat, 3.5, 0, 16 * SE23T_EPS);
    assert_int_equal(flag, 1);
    assert_int_equal(d.stationary, 1);
    assert_int_equal(d.count, 2);
    assert_int_equal(d.head, 0);

    /* Same window, threshold 3: not stationary. */
    c.threshold = 3;
    assert_int_equal(se23_stationary_init(&c, &d), SE23_OK);
    add_ok(&d, vec(0.1, 0, 0), vec(0, 0, -9), NULL);
    add_ok(&d, vec(0, 0.2, 0), vec(0, 0, -11), &flag);
    assert_int_equal(flag, 0);

    /* A tilted mean: f = (6,0,8), (0,0,0): fbar = (3,0,4), |fbar| = 5,
     * g u = (6,0,8): |f_k - g u|^2 = 0, 100; sigma_a = 2, w = 0:
     * T = (100 / 4) / 2 = 12.5. */
    c = config(2, 2, 0.1, 10, 100);
    assert_int_equal(se23_stationary_init(&c, &d), SE23_OK);
    add_ok(&d, vec(0, 0, 0), vec(6, 0, 8), NULL);
    add_ok(&d, vec(0, 0, 0), vec(0, 0, 0), &flag);
    assert_near(d.stat, 12.5, 0, 16 * SE23T_EPS);
    assert_int_equal(flag, 1);

    /* Free fall, fbar = 0 (u undefined): the limit g^2 / sigma_a^2. */
    c = config(4, 0.1, 0.1, G, 100);
    assert_int_equal(se23_stationary_init(&c, &d), SE23_OK);
    for (int k = 0; k < 4; ++k) {
        add_ok(&d, vec(0, 0, 0), vec(0, 0, 0), &flag);
    }
    assert_near(d.stat, G * G / 0.01, 0, 16 * SE23T_EPS);
    assert_int_equal(flag, 0);
}

static void test_stationary_add_matches_definition_on_sliding_windows(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 9101);
    double worst = 0;
    for (int rep = 0; rep < 200; ++rep) {
        const int W = 2 + rep % (SE23_STATIONARY_WMAX - 1);
        const double sa = se23t_uniform(&rng, 0.01, 0.5);
        const double sg = se23t_uniform(&rng, 1e-3, 0.1);
        const double motion = (rep % 3 == 0) ? 0.0 : se23t_uniform(&rng, 0, 3);
        se23_stationary_config_t c = config(W, sa, sg, G, 10);
        se23_stationary_t d;
        assert_int_equal(se23_stationary_init(&c, &d), SE23_OK);
        double u0[3];
        random_unit(&rng, u0);
        /* The last W samples, in order (the reference's window). */
        se23_vec3_t ws[3 * SE23_STATIONARY_WMAX + 5], fs[3 * SE23_STATIONARY_WMAX + 5];
        const int n = 3 * W + rep % 5;
        for (int k = 0; k < n; ++k) {
            rest_sample(&rng, u0, sa, sg, &ws[k], &fs[k]);
            for (int j = 0; j < 3; ++j) {
                fs[k].v[j] += (se23_real_t)(motion * se23t_normal(&rng));
                ws[k].v[j] += (se23_real_t)(0.1 * motion * se23t_normal(&rng));
            }
            add_ok(&d, ws[k], fs[k], NULL);
            const int m = (k + 1 < W) ? k + 1 : W;
            const double ref = shoe_reference(&ws[k + 1 - m], &fs[k + 1 - m], m, sa, sg, G);
            /* Float: the rounding of |fbar| (eps g) enters the radial term
             * 2 (|fbar| - g) eps g / sigma_a^2: up to ~g / sigma_a eps of T. */
            const double err = fabs(d.stat - ref) / (ref * SE23T_EPS);
            worst = err > worst ? err : worst;
            assert_true(err < 2.0 * G / sa + 64.0);
            assert_int_equal(d.count, m);
            if (m == W && ref < 10 * (1 - 1e-3)) {
                assert_int_equal(d.stationary, 1);
            }
            if (m < W || ref > 10 * (1 + 1e-3)) {
                assert_int_equal(d.stationary, 0);
            }
        }
        /* Window means and variances of the last W samples. */
        se23_vec3_t wm, fm, wv, fv;
        assert_int_equal(se23_stationary_mean(&d, &wm, &fm), SE23_OK);
        assert_int_equal(se23_stationary_var(&d, &wv, &fv), SE23_OK);
        for (int j = 0; j < 3; ++j) {
            double mw = 0, mf = 0, vw = 0, vf = 0;
            for (int k = n - W; k < n; ++k) {
                mw += (double)ws[k].v[j] / W;
                mf += (double)fs[k].v[j] / W;
            }
            for (int k = n - W; k < n; ++k) {
                vw += ((double)ws[k].v[j] - mw) * ((double)ws[k].v[j] - mw) / (W - 1);
                vf += ((double)fs[k].v[j] - mf) * ((double)fs[k].v[j] - mf) / (W - 1);
            }
            assert_near(wm.v[j], mw, 64 * SE23T_EPS * 0.5, 64 * SE23T_EPS);
            assert_near(fm.v[j], mf, 64 * SE23T_EPS * 10, 64 * SE23T_EPS);
            assert_near(wv.v[j], vw, 0, 256 * SE23T_EPS * 10);
            assert_near(fv.v[j], vf, 0, 256 * SE23T_EPS * 10 * G / sa);
        }
    }
    print_message("SHOE vs definition: worst error %.1f eps of T\n", worst);
}

/* ------------------------------------------------------------ statistics */

static void test_stationary_rest_follows_chi2_6w_minus_2(void **state)
{
    (void)state;
    enum { W = 10, WINDOWS = 10000, STREAM = 20000 };
    const double sa = 0.02, sg = 2e-3;
    const double k = 6.0 * W - 2.0;
    const double threshold = chi2_quantile(k, Z95) / W;
    se23_stationary_config_t c = config(W, sa, sg, G, threshold);
    se23_stationary_t d;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 9102);
    double u0[3];
    random_unit(&rng, u0);
    assert_int_equal(se23_stationary_init(&c, &d), SE23_OK);

    /* Independent windows: reset after each. */
    double sum = 0;
    int still = 0;
    for (int i = 0; i < WINDOWS; ++i) {
        se23_stationary_reset(&d);
        int flag = 0;
        for (int s = 0; s < W; ++s) {
            se23_vec3_t w, f;
            rest_sample(&rng, u0, sa, sg, &w, &f);
            add_ok(&d, w, f, &flag);
        }
        sum += W * (double)d.stat;
        still += flag;
    }
    const double mean = sum / WINDOWS;
    const double rate = (double)still / WINDOWS;
    /* Mean of W T: chi^2_k has mean k and variance 2k; 3.3 sigma (99.9 %). */
    const double sd = sqrt(2.0 * k / WINDOWS);
    print_message("rest, W = %d: mean W T = %.3f (chi^2 dof %g +- %.3f), stationary "
                  "at the 95%% threshold %.4f: %.2f%% of %d windows\n",
                  W, mean, k, 3.3 * sd, threshold, 100 * rate, WINDOWS);
    assert_true(fabs(mean - k) < 3.3 * sd);
    assert_true(fabs(mean - (k - 1)) > 3.3 * sd); /* not 6W - 3 */
    /* Binomial: sd of the rate 0.0022; 3.3 sigma. */
    assert_true(rate > 0.95 - 0.0072 && rate < 0.95 + 0.0072);

    /* Sliding windows over one stream: at least ~95 % stationary. */
    se23_stationary_reset(&d);
    int full = 0;
    still = 0;
    for (int s = 0; s < STREAM; ++s) {
        se23_vec3_t w, f;
        int flag = 0;
        rest_sample(&rng, u0, sa, sg, &w, &f);
        add_ok(&d, w, f, &flag);
        if (d.count == W) {
            ++full;
            still += flag;
        }
    }
    print_message("rest, sliding windows: %.2f%% stationary\n", 100.0 * still / full);
    assert_true((double)still / full > 0.93);
}

static void test_stationary_motion_is_never_stationary(void **state)
{
    (void)state;
    enum { W = 10, STREAM = 3000 };
    const double sa = 0.02, sg = 2e-3, rate_hz = 100;
    const double threshold = chi2_quantile(6.0 * W - 2.0, Z95) / W;
    se23_stationary_config_t c = config(W, sa, sg, G, threshold);
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 9103);
    for (int kind = 0; kind < 3; ++kind) {
        se23_stationary_t d;
        assert_int_equal(se23_stationary_init(&c, &d), SE23_OK);
        double u0[3], v[3];
        random_unit(&rng, u0);
        random_unit(&rng, v);
        /* v perpendicular to u0: the smallest change of |f| for a constant
         * extra acceleration. */
        const double vu = v[0] * u0[0] + v[1] * u0[1] + v[2] * u0[2];
        double nv = 0;
        for (int j = 0; j < 3; ++j) {
            v[j] -= vu * u0[j];
            nv += v[j] * v[j];
        }
        for (int j = 0; j < 3; ++j) {
            v[j] /= sqrt(nv);
        }
        int still = 0;
        for (int s = 0; s < STREAM; ++s) {
            se23_vec3_t w, f;
            int flag = 0;
            rest_sample(&rng, u0, sa, sg, &w, &f);
            const double t = s / rate_hz;
            for (int j = 0; j < 3; ++j) {
                if (kind == 0) {
                    w.v[j] += (se23_real_t)v[j]; /* 1 rad/s rotation */
                } else if (kind == 1) {
                    f.v[j] += (se23_real_t)(2.0 * v[j]); /* 2 m/s^2, constant */
                } else {
                    f.v[j] += (se23_real_t)(2.0 * sin(2 * 3.14159265358979 * 2 * t) * v[j]);
                }
            }
            add_ok(&d, w, f, &flag);
            still += flag;
        }
        print_message("motion kind %d: %d of %d windows stationary, last T = %.1f\n",
                      kind, still, STREAM, (double)d.stat);
        assert_int_equal(still, 0);
    }
}

/* ------------------------------------------------------------ window */

static void test_stationary_window_slides_and_reset_empties(void **state)
{
    (void)state;
    se23_stationary_config_t c = config(3, 0.1, 0.01, G, 8);
    se23_stationary_t d, e;
    assert_int_equal(se23_stationary_init(&c, &d), SE23_OK);
    assert_int_equal(se23_stationary_init(&c, &e), SE23_OK);
    for (int k = 0; k < 7; ++k) {
        add_ok(&d, vec(0.01 * k, 0, 0), vec(0, 0.1 * k, -G), NULL);
        assert_int_equal(d.head, (k + 1) % 3);
    }
    /* Only the last three samples count. */
    for (int k = 4; k < 7; ++k) {
        add_ok(&e, vec(0.01 * k, 0, 0), vec(0, 0.1 * k, -G), NULL);
    }
    assert_near(d.stat, e.stat, 0, 16 * SE23T_EPS);
    se23_vec3_t wm, fm;
    assert_int_equal(se23_stationary_mean(&d, &wm, &fm), SE23_OK);
    assert_near(wm.v[0], 0.05, 0, 8 * SE23T_EPS);
    assert_near(fm.v[1], 0.5, 0, 8 * SE23T_EPS);
    assert_near(fm.v[2], -G, 0, 8 * SE23T_EPS);

    se23_stationary_reset(&d);
    assert_int_equal(d.count, 0);
    assert_int_equal(d.head, 0);
    assert_int_equal(d.stationary, 0);
    assert_true(d.stat == 0);
    assert_int_equal(d.cfg.window, 3);
    assert_true(d.cfg.threshold == (se23_real_t)8);
    assert_int_equal(se23_stationary_mean(&d, &wm, &fm), SE23_ERR_DIM);
    /* After the reset it behaves as a new detector. */
    for (int k = 4; k < 7; ++k) {
        add_ok(&d, vec(0.01 * k, 0, 0), vec(0, 0.1 * k, -G), NULL);
    }
    assert_true(d.stat == e.stat);
}

/* ------------------------------------------------------------ statuses */

static void test_stationary_init_rejects_bad_config_untouched(void **state)
{
    (void)state;
#if SE23_CFG_DOUBLE
    const double tiny = 1e-160, huge = 1e160;
#else
    const double tiny = 1e-20, huge = 1e20;
#endif
    const struct {
        se23_stationary_config_t c;
        se23_status_t st;
    } cases[] = {
        {config(10, NAN, 0.1, G, 5), SE23_ERR_NONFINITE},
        {config(10, 0.1, INFINITY, G, 5), SE23_ERR_NONFINITE},
        {config(10, 0.1, 0.1, NAN, 5), SE23_ERR_NONFINITE},
        {config(10, 0.1, 0.1, G, -INFINITY), SE23_ERR_NONFINITE},
        {config(1, 0.1, 0.1, G, 5), SE23_ERR_DIM},
        {config(SE23_STATIONARY_WMAX + 1, 0.1, 0.1, G, 5), SE23_ERR_DIM},
        {config(-3, 0.1, 0.1, G, 5), SE23_ERR_DIM},
        {config(10, 0, 0.1, G, 5), SE23_ERR_DOMAIN},
        {config(10, 0.1, -0.1, G, 5), SE23_ERR_DOMAIN},
        {config(10, tiny, 0.1, G, 5), SE23_ERR_DOMAIN},
        {config(10, 0.1, huge, G, 5), SE23_ERR_DOMAIN},
        {config(10, 0.1, 0.1, 0, 5), SE23_ERR_DOMAIN},
        {config(10, 0.1, 0.1, G, 0), SE23_ERR_DOMAIN},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i) {
        se23_stationary_t d, ref;
        memset(&d, SENTINEL, sizeof d);
        memset(&ref, SENTINEL, sizeof ref);
        assert_int_equal(se23_stationary_init(&cases[i].c, &d), cases[i].st);
        assert_memory_equal(&d, &ref, sizeof d);
    }
    /* The limits themselves are accepted. */
    se23_stationary_t d;
    se23_stationary_config_t c = config(2, 1e-3, 1e-3, G, 1);
    assert_int_equal(se23_stationary_init(&c, &d), SE23_OK);
    c.window = SE23_STATIONARY_WMAX;
    assert_int_equal(se23_stationary_init(&c, &d), SE23_OK);
    assert_int_equal(d.count, 0);
    assert_int_equal(d.head, 0);
    assert_int_equal(d.stationary, 0);
    assert_true(d.stat == 0);
}

static void test_stationary_add_rejects_bad_input_untouched(void **state)
{
    (void)state;
#if SE23_CFG_DOUBLE
    const double huge = 1e300;
#else
    const double huge = 1e30;
#endif
    se23_stationary_config_t c = config(4, 0.1, 0.01, G, 8);
    se23_stationary_t d, before;
    assert_int_equal(se23_stationary_init(&c, &d), SE23_OK);
    for (int k = 0; k < 5; ++k) {
        add_ok(&d, vec(0, 0, 0.001), vec(0, 0, -G), NULL);
    }
    const se23_vec3_t ok = vec(0, 0, -G);
    const se23_vec3_t bad[] = {vec(NAN, 0, 0), vec(0, INFINITY, 0), vec(0, 0, -INFINITY)};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i) {
        int flag = -7;
        before = d;
        assert_int_equal(se23_stationary_add(&d, &bad[i], &ok, &flag), SE23_ERR_NONFINITE);
        assert_int_equal(se23_stationary_add(&d, &ok, &bad[i], &flag), SE23_ERR_NONFINITE);
        assert_true(same_state(&d, &before));
        assert_int_equal(flag, -7);
    }
    /* Finite but the statistic overflows: refused, not stored. */
    {
        const se23_vec3_t big = vec(huge, 0, 0);
        int flag = -7;
        before = d;
        assert_int_equal(se23_stationary_add(&d, &ok, &big, &flag), SE23_ERR_NONFINITE);
        assert_int_equal(se23_stationary_add(&d, &big, &ok, &flag), SE23_ERR_NONFINITE);
        assert_true(same_state(&d, &before));
        assert_int_equal(flag, -7);
    }
    /* A corrupted state: window, count or head out of range. */
    for (int i = 0; i < 6; ++i) {
        se23_stationary_t x = d;
        int flag = -7;
        if (i == 0) x.cfg.window = SE23_STATIONARY_WMAX + 1;
        if (i == 1) x.cfg.window = 1;
        if (i == 2) x.count = -1;
        if (i == 3) x.count = 5;
        if (i == 4) x.head = 4;
        if (i == 5) x.head = -1;
        before = x;
        assert_int_equal(se23_stationary_add(&x, &ok, &ok, &flag), SE23_ERR_DIM);
        assert_true(same_state(&x, &before));
        assert_int_equal(flag, -7);
        se23_vec3_t a, b, a0, b0;
        memset(&a, SENTINEL, sizeof a);
        memset(&b, SENTINEL, sizeof b);
        a0 = a;
        b0 = b;
        assert_int_equal(se23_stationary_mean(&x, &a, &b), SE23_ERR_DIM);
        assert_int_equal(se23_stationary_var(&x, &a, &b), SE23_ERR_DIM);
        assert_memory_equal(&a, &a0, sizeof a);
        assert_memory_equal(&b, &b0, sizeof b);
    }
    /* NULL: d, w_b, f_b required; stationary optional. */
    assert_int_equal(se23_stationary_add(NULL, &ok, &ok, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_stationary_add(&d, NULL, &ok, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_stationary_add(&d, &ok, NULL, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_stationary_add(&d, &ok, &ok, NULL), SE23_OK);
    assert_int_equal(se23_stationary_init(NULL, &d), SE23_ERR_NULL);
    assert_int_equal(se23_stationary_init(&c, NULL), SE23_ERR_NULL);
}

static void test_stationary_mean_var_need_a_full_window(void **state)
{
    (void)state;
#if SE23_CFG_DOUBLE
    const double big = 1e308;
#else
    const double big = 3e38;
#endif
    se23_stationary_config_t c = config(3, 0.1, 0.01, G, 8);
    se23_stationary_t d;
    assert_int_equal(se23_stationary_init(&c, &d), SE23_OK);
    se23_vec3_t a, b, a0, b0;
    memset(&a, SENTINEL, sizeof a);
    memset(&b, SENTINEL, sizeof b);
    a0 = a;
    b0 = b;
    for (int k = 0; k < 3; ++k) {
        assert_int_equal(se23_stationary_mean(&d, &a, &b), SE23_ERR_DIM);
        assert_int_equal(se23_stationary_var(&d, &a, &b), SE23_ERR_DIM);
        assert_memory_equal(&a, &a0, sizeof a);
        assert_memory_equal(&b, &b0, sizeof b);
        add_ok(&d, vec(0.01, 0.02 * k, 0), vec(1.0 * k, 0, -G), NULL);
    }
    assert_int_equal(se23_stationary_mean(&d, &a, &b), SE23_OK);
    assert_near(a.v[1], 0.02, 0, 8 * SE23T_EPS);
    assert_near(b.v[0], 1.0, 0, 8 * SE23T_EPS);
    assert_int_equal(se23_stationary_var(&d, &a, &b), SE23_OK);
    /* Samples 0, 1, 2 (x 0.02 and x 1): variance 1 (x 0.02^2). */
    /* Equal samples: variance 0 up to the rounding of the mean. */
    assert_near(a.v[0], 0, 64 * (SE23T_EPS * 0.01) * (SE23T_EPS * 0.01), 0);
    assert_near(a.v[1], 0.02 * 0.02, 0, 16 * SE23T_EPS);
    assert_near(b.v[0], 1.0, 0, 16 * SE23T_EPS);
    assert_near(b.v[2], 0, 64 * (SE23T_EPS * G) * (SE23T_EPS * G), 0);
    /* A state the library did not produce, whose sums overflow: the
     * samples var sums, the running sums mean reads. */
    se23_stationary_t x = d;
    for (int k = 0; k < 3; ++k) {
        x.f[k].v[0] = (se23_real_t)big;
        x.w[k].v[2] = (se23_real_t)-big;
    }
    x.recent.sf.v[0] = x.older.sf.v[0] = (se23_real_t)big;
    x.recent.sw.v[2] = x.older.sw.v[2] = (se23_real_t)-big;
    memset(&a, SENTINEL, sizeof a);
    memset(&b, SENTINEL, sizeof b);
    assert_int_equal(se23_stationary_mean(&x, &a, &b), SE23_ERR_NONFINITE);
    assert_int_equal(se23_stationary_var(&x, &a, &b), SE23_ERR_NONFINITE);
    assert_memory_equal(&a, &a0, sizeof a);
    assert_memory_equal(&b, &b0, sizeof b);
    assert_int_equal(se23_stationary_mean(NULL, &a, &b), SE23_ERR_NULL);
    assert_int_equal(se23_stationary_mean(&d, NULL, &b), SE23_ERR_NULL);
    assert_int_equal(se23_stationary_mean(&d, &a, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_stationary_var(NULL, &a, &b), SE23_ERR_NULL);
    assert_int_equal(se23_stationary_var(&d, NULL, &b), SE23_ERR_NULL);
    assert_int_equal(se23_stationary_var(&d, &a, NULL), SE23_ERR_NULL);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_stationary_add_hand_computed_windows),
        cmocka_unit_test(test_stationary_add_matches_definition_on_sliding_windows),
        cmocka_unit_test(test_stationary_rest_follows_chi2_6w_minus_2),
        cmocka_unit_test(test_stationary_motion_is_never_stationary),
        cmocka_unit_test(test_stationary_window_slides_and_reset_empties),
        cmocka_unit_test(test_stationary_init_rejects_bad_config_untouched),
        cmocka_unit_test(test_stationary_add_rejects_bad_input_untouched),
        cmocka_unit_test(test_stationary_mean_var_need_a_full_window),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
