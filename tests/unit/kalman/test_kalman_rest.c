/* Unit tests of src/kalman/kalman_rest.c, the filter's structured rest update:
 * against the general se23_kalman_update with the same rows of H written
 * out (ZUPT H_v = [0, I, -a^, 0, 0], ZARU H_w = [0, 0, 0, I, 0]) on random
 * positive definite covariances and states, 9 and 15 states, with and
 * without ZARU, in place and not; the NIS of the ZUPT rows against the
 * general update of those rows alone; the refusals (a pinned variance, a
 * block of S not positive definite, a mean out of range, a dimension) with
 * nothing written. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "gauss_test.h"
#include "kalman/kalman_rest.h"
#include "se23/kalman.h"
#include "se23_test.h"

enum { S = SE23_GAUSS_NMAX, M = SE23_MEAS_MMAX };

#define SENTINEL 0x5a

/* Random rest measurements: a of size scale_a, innovations of size 0.1,
 * noise variances between 0.1 and 1 times the covariance's scale (none of
 * them pins a variance of gt_random_gauss's covariances). */
static void random_rest(se23t_rng_t *rng, double scale_a, int zaru, se23_rest_meas_t *y)
{
    memset(y, 0, sizeof *y);
    se23t_random_vec3(rng, scale_a, &y->a);
    se23t_random_vec3(rng, 0.1, &y->z_v);
    se23t_random_vec3(rng, 0.1, &y->z_w);
    y->r_v = (se23_real_t)se23t_uniform(rng, 0.01, 0.1);
    y->r_w = (se23_real_t)se23t_uniform(rng, 0.01, 0.1);
    y->zaru = zaru;
}

/* The same measurement for se23_kalman_update: rows 0..2 the ZUPT's,
 * 3..5 the ZARU's (m = 6), or the ZUPT's alone (zupt_only). */
static void explicit_meas(const se23_rest_meas_t *r, int zupt_only, se23_meas_t *y)
{
    const se23_real_t *a = r->a.v;
    memset(y, 0, sizeof *y);
    y->m = ((r->zaru != 0) && (zupt_only == 0)) ? 6 : 3;
    for (int k = 0; k < 3; ++k) {
        y->H[S * k + SE23_IDX_NU + k] = 1;
        y->z[k] = r->z_v.v[k];
        y->R[M * k + k] = r->r_v;
    }
    /* -a^ in the rho columns of the ZUPT rows */
    y->H[S * 0 + SE23_IDX_RHO + 1] = a[2];
    y->H[S * 0 + SE23_IDX_RHO + 2] = -a[1];
    y->H[S * 1 + SE23_IDX_RHO + 0] = -a[2];
    y->H[S * 1 + SE23_IDX_RHO + 2] = a[0];
    y->H[S * 2 + SE23_IDX_RHO + 0] = a[1];
    y->H[S * 2 + SE23_IDX_RHO + 1] = -a[0];
    if (y->m == 6) {
        for (int k = 0; k < 3; ++k) {
            y->H[S * (3 + k) + SE23_IDX_BG + k] = 1;
            y->z[3 + k] = r->z_w.v[k];
            y->R[M * (3 + k) + 3 + k] = r->r_w;
        }
    }
}

static double p_scale(const se23_gauss_t *g)
{
    double s = 0;
    for (int i = 0; i < g->n; ++i) {
        s = fmax(s, fabs((double)g->P.m[(S + 1) * i]));
    }
    return s;
}

/* a equals b to tol (P relative to its largest variance), and a's P is
 * exactly symmetric. */
static void assert_same_update(const se23_gauss_t *a, const se23_gauss_t *b, double tol,
                               double *worst)
{
    const double ps = p_scale(b);
    assert_int_equal(a->n, b->n);
    for (int i = 0; i < a->n; ++i) {
        for (int j = 0; j < a->n; ++j) {
            const double d = fabs((double)a->P.m[S * i + j] - (double)b->P.m[S * i + j]) / ps;
            *worst = fmax(*worst, d / SE23T_EPS);
            assert_true(d <= tol);
            assert_true(a->P.m[S * i + j] == a->P.m[S * j + i]);
        }
    }
    assert_mat3_near(&a->T.R, &b->T.R, tol);
    assert_array_near(a->T.v.v, b->T.v.v, 3, 10 * tol, tol);
    assert_array_near(a->T.p.v, b->T.p.v, 3, 10 * tol, tol);
    assert_array_near(a->b_g.v, b->b_g.v, 3, tol, tol);
    assert_array_near(a->b_a.v, b->b_a.v, 3, tol, tol);
}

static void test_rest_update_is_the_general_update_of_its_rows(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 3401);
    const double tol = 64 * SE23T_EPS;
    double worst = 0;
    int pinned = 0, compared = 0;
    for (int rep = 0; rep < 400; ++rep) {
        const int n = (rep % 4 == 0) ? SE23_GAUSS_N_POSE : SE23_GAUSS_N_BIAS;
        const int zaru = (n == SE23_GAUSS_N_BIAS) && (rep % 2 == 1);
        /* Earth-rate sized, larger, and zero (flat Earth: H_v selects nu) */
        const double scale_a = (rep % 3 == 0) ? 0.0 : ((rep % 3 == 1) ? 7.3e-5 : 0.5);
        se23_gauss_t g, fast, in_place, general, zupt_alone;
        se23_rest_meas_t r;
        se23_meas_t y;
        se23_kalman_work_t wk;
        se23_real_t nis_fast = 0, nis_general = 0, nis_zupt = 0;
        gt_random_gauss(&rng, n, &g);
        random_rest(&rng, scale_a, zaru, &r);
        memset(&fast, SENTINEL, sizeof fast);
        const se23_status_t st = se23_kalman_rest(&g, &r, &wk, &fast, &nis_fast);
        if (st == SE23_ERR_DOMAIN) {
            ++pinned;
            continue;
        }
        assert_int_equal(st, SE23_OK);
        ++compared;
        explicit_meas(&r, 0, &y);
        assert_int_equal(se23_kalman_update(&g, &y, &general, &nis_general), SE23_OK);
        assert_same_update(&fast, &general, tol, &worst);
        /* the NIS of the ZUPT rows alone */
        explicit_meas(&r, 1, &y);
        assert_int_equal(se23_kalman_update(&g, &y, &zupt_alone, &nis_zupt), SE23_OK);
        assert_near(nis_fast, nis_zupt, 0, tol);
        /* in place: the same result bit for bit */
        in_place = g;
        se23_real_t nis_in_place = 0;
        assert_int_equal(se23_kalman_rest(&in_place, &r, &wk, &in_place, &nis_in_place), SE23_OK);
        for (int i = 0; i < n; ++i) {
            assert_memory_equal(&in_place.P.m[S * i], &fast.P.m[S * i],
                                (size_t)n * sizeof fast.P.m[0]);
        }
        assert_memory_equal(&in_place.T, &fast.T, sizeof fast.T);
        assert_memory_equal(&in_place.b_g, &fast.b_g, sizeof fast.b_g);
        assert_memory_equal(&in_place.b_a, &fast.b_a, sizeof fast.b_a);
        assert_true(nis_in_place == nis_fast);
    }
    assert_true(pinned < compared / 10);
    print_message("rest update vs general update: %d compared, %d pinned, worst P error %.1f eps "
                  "of the largest variance\n",
                  compared, pinned, worst);
}

/* The cases the structured update leaves to the general one, or refuses;
 * out and nis untouched. */
static void expect_refused(const se23_gauss_t *g, const se23_rest_meas_t *r, se23_status_t want)
{
    se23_gauss_t out, out0;
    se23_kalman_work_t wk;
    se23_real_t nis, nis0;
    memset(&out, SENTINEL, sizeof out);
    memset(&nis, SENTINEL, sizeof nis);
    out0 = out;
    nis0 = nis;
    assert_int_equal(se23_kalman_rest(g, r, &wk, &out, &nis), want);
    assert_memory_equal(&out, &out0, sizeof out);
    assert_memory_equal(&nis, &nis0, sizeof nis);
}

static void test_rest_update_refuses_and_writes_nothing(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 3402);
    se23_gauss_t g, x;
    se23_rest_meas_t r;
    gt_random_gauss(&rng, SE23_GAUSS_N_BIAS, &g);
    random_rest(&rng, 7.3e-5, 1, &r);
    /* a velocity measured far below its prior: the general update's Joseph
     * step and the filter's check are needed */
    x = g;
    for (int k = 0; k < 3; ++k) {
        x.P.m[(S + 1) * (SE23_IDX_NU + k)] *= (se23_real_t)1e6;
    }
    expect_refused(&x, &r, SE23_ERR_DOMAIN);
    {
        se23_rest_meas_t tight = r;
        tight.r_v = (se23_real_t)1e-9;
        expect_refused(&g, &tight, SE23_ERR_DOMAIN);
    }
    /* S_v singular: no velocity uncertainty, no noise */
    {
        se23_rest_meas_t exact = r;
        exact.r_v = 0;
        exact.a.v[0] = exact.a.v[1] = exact.a.v[2] = 0;
        x = g;
        for (int i = 0; i < S; ++i) {
            for (int k = 0; k < 3; ++k) {
                x.P.m[S * i + SE23_IDX_NU + k] = 0;
                x.P.m[S * (SE23_IDX_NU + k) + i] = 0;
            }
        }
        expect_refused(&x, &exact, SE23_ERR_NOT_PSD);
    }
    /* a mean the retraction could overflow, a NaN innovation */
    x = g;
    x.T.p.v[1] = (se23_real_t)(SE23T_REAL_MAX / 2);
    expect_refused(&x, &r, SE23_ERR_NONFINITE);
    {
        se23_rest_meas_t bad = r;
        bad.z_w.v[2] = (se23_real_t)NAN;
        expect_refused(&g, &bad, SE23_ERR_NONFINITE);
    }
    /* ZARU needs the bias states; n must be 9 or 15 */
    x = g;
    x.n = SE23_GAUSS_N_POSE;
    expect_refused(&x, &r, SE23_ERR_DIM);
    x.n = 12;
    r.zaru = 0;
    expect_refused(&x, &r, SE23_ERR_DIM);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_rest_update_is_the_general_update_of_its_rows),
        cmocka_unit_test(test_rest_update_refuses_and_writes_nothing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
