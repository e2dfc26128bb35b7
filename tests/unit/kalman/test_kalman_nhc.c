/* Unit tests of src/kalman/kalman_nhc.c, the filter's structured NHC update:
 * against the general se23_meas_nhc + se23_kalman_update on random
 * positive definite covariances, states and mountings, 9 and 15 states, in
 * place and not; the refusals (a pinned variance, S not positive definite,
 * a mean out of range, a dimension) with nothing written. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "gauss_test.h"
#include "kalman/kalman_nhc.h"
#include "se23/kalman.h"
#include "se23/so3.h"
#include "base/linalg.h"
#include "se23_test.h"

enum { S = SE23_GAUSS_NMAX };

#define SENTINEL 0x5a

static void random_mount(se23t_rng_t *rng, se23_mat3_t *C_bv)
{
    se23_vec3_t phi;
    se23t_random_vec3(rng, 2.0, &phi);
    assert_int_equal(se23_so3_exp(&phi, C_bv), SE23_OK);
}

/* g's velocity that of a vehicle on C_bv driving at up to 20 m/s with a
 * slip of up to 0.1 m/s: v = R C_bv (speed, lateral, vertical) (the
 * innovations then of the filter's size). */
static void vehicle_velocity(se23t_rng_t *rng, const se23_mat3_t *C_bv, se23_gauss_t *g)
{
    const double vv[3] = {se23t_uniform(rng, -20.0, 20.0), se23t_uniform(rng, -0.1, 0.1),
                          se23t_uniform(rng, -0.1, 0.1)};
    for (int i = 0; i < 3; ++i) {
        double vb = 0;
        for (int k = 0; k < 3; ++k) {
            vb += (double)C_bv->m[i][k] * vv[k];
        }
        g->T.v.v[i] = (se23_real_t)vb; /* body frame, rotated below */
    }
    se23_vec3_t vb = g->T.v;
    for (int i = 0; i < 3; ++i) {
        g->T.v.v[i] = g->T.R.m[i][0] * vb.v[0] + g->T.R.m[i][1] * vb.v[1] +
                      g->T.R.m[i][2] * vb.v[2];
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

static void test_nhc_update_is_the_general_update(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 3501);
    const double tol = 64 * SE23T_EPS;
    double worst = 0;
    int pinned = 0, compared = 0;
    for (int rep = 0; rep < 400; ++rep) {
        const int n = (rep % 4 == 0) ? SE23_GAUSS_N_POSE : SE23_GAUSS_N_BIAS;
        const se23_real_t sigma = (se23_real_t)se23t_uniform(&rng, 0.1, 0.5);
        se23_gauss_t g, fast, in_place, general;
        se23_mat3_t C_bv;
        se23_nhc_meas_t r;
        se23_meas_t y;
        se23_kalman_work_t wk;
        se23_real_t nis_fast = 0, nis_general = 0;
        gt_random_gauss(&rng, n, &g);
        random_mount(&rng, &C_bv);
        vehicle_velocity(&rng, &C_bv, &g);
        se23_nhc_rows(&g.T, &C_bv, sigma, &r);
        memset(&y, 0, sizeof y);
        assert_int_equal(se23_meas_nhc(&g.T, &C_bv, sigma, &y), SE23_OK);
        /* the same rows as se23_meas_nhc's */
        for (int k = 0; k < 2; ++k) {
            assert_array_near(r.h[k], &y.H[S * k], 6, 0, 8 * SE23T_EPS);
            assert_near(r.z[k], y.z[k], 0, 8 * SE23T_EPS);
        }
        assert_true(r.r == y.R[0]);
        memset(&fast, SENTINEL, sizeof fast);
        const se23_status_t st = se23_kalman_nhc(&g, &r, &wk, &fast, &nis_fast);
        if (st == SE23_ERR_DOMAIN) {
            ++pinned;
            continue;
        }
        assert_int_equal(st, SE23_OK);
        ++compared;
        assert_int_equal(se23_kalman_update(&g, &y, &general, &nis_general), SE23_OK);
        assert_same_update(&fast, &general, tol, &worst);
        assert_near(nis_fast, nis_general, 0, tol);
        /* in place: the same result bit for bit */
        in_place = g;
        se23_real_t nis_in_place = 0;
        assert_int_equal(se23_kalman_nhc(&in_place, &r, &wk, &in_place, &nis_in_place), SE23_OK);
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
    print_message("NHC update vs general update: %d compared, %d pinned, worst P error %.1f eps "
                  "of the largest variance\n",
                  compared, pinned, worst);
}

/* The cases the structured update leaves to the general one, or refuses;
 * out and nis untouched. */
static void expect_refused(const se23_gauss_t *g, const se23_nhc_meas_t *r, se23_status_t want)
{
    se23_gauss_t out, out0;
    se23_kalman_work_t wk;
    se23_real_t nis, nis0;
    memset(&out, SENTINEL, sizeof out);
    memset(&nis, SENTINEL, sizeof nis);
    out0 = out;
    nis0 = nis;
    assert_int_equal(se23_kalman_nhc(g, r, &wk, &out, &nis), want);
    assert_memory_equal(&out, &out0, sizeof out);
    assert_memory_equal(&nis, &nis0, sizeof nis);
}

static void test_nhc_update_refuses_and_writes_nothing(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 3502);
    se23_gauss_t g, x;
    se23_mat3_t C_bv;
    se23_nhc_meas_t r;
    gt_random_gauss(&rng, SE23_GAUSS_N_BIAS, &g);
    se23_m3_identity(&C_bv); /* nu's axes y, z measured alone */
    vehicle_velocity(&rng, &C_bv, &g);
    se23_nhc_rows(&g.T, &C_bv, SE23_R(0.3), &r);
    /* a velocity measured far below its prior: the general update's Joseph
     * step and the filter's check are needed */
    x = g;
    for (int k = 0; k < 3; ++k) {
        x.P.m[(S + 1) * (SE23_IDX_NU + k)] *= (se23_real_t)1e6;
    }
    expect_refused(&x, &r, SE23_ERR_DOMAIN);
    {
        /* at a standstill the rows select nu's axes y, z alone */
        se23_nhc_meas_t tight;
        x = g;
        x.T.v.v[0] = x.T.v.v[1] = x.T.v.v[2] = 0;
        se23_nhc_rows(&x.T, &C_bv, SE23_R(3e-5), &tight);
        expect_refused(&x, &tight, SE23_ERR_DOMAIN);
    }
    /* S singular: no attitude and velocity uncertainty, no noise */
    {
        se23_nhc_meas_t exact = r;
        exact.r = 0;
        x = g;
        for (int i = 0; i < S; ++i) {
            for (int k = 0; k < 6; ++k) {
                x.P.m[S * i + k] = 0;
                x.P.m[S * k + i] = 0;
            }
        }
        expect_refused(&x, &exact, SE23_ERR_NOT_PSD);
    }
    /* a NaN row lands in the pivot test */
    {
        se23_nhc_meas_t bad = r;
        bad.h[1][2] = (se23_real_t)NAN;
        expect_refused(&g, &bad, SE23_ERR_NOT_PSD);
    }
    /* a mean the retraction could overflow, a NaN innovation */
    x = g;
    x.T.p.v[1] = (se23_real_t)(SE23T_REAL_MAX / 2);
    expect_refused(&x, &r, SE23_ERR_NONFINITE);
    {
        se23_nhc_meas_t bad = r;
        bad.z[0] = (se23_real_t)NAN;
        expect_refused(&g, &bad, SE23_ERR_NONFINITE);
    }
    /* n must be 9 or 15 */
    x = g;
    x.n = 12;
    expect_refused(&x, &r, SE23_ERR_DIM);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_nhc_update_is_the_general_update),
        cmocka_unit_test(test_nhc_update_refuses_and_writes_nothing),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
