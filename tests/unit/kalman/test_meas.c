/* Unit tests of src/kalman/meas.c: the ready-made measurement models (GNSS
 * position with lever arm, velocity in the nav frame, velocity of an
 * antenna at a lever arm, velocity in the body frame, zero angular rate,
 * a vehicle's non-holonomic constraint):
 * residuals, all 15 columns of H against central differences of
 * h(Tbar exp(xi), bbar + db) in the double reference, noise copied, every
 * element of the output defined, bad input (nothing written), and Kalman
 * updates with the rate and lever models. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "gauss_test.h"
#include "se23/kalman.h"
#include "se23/se23.h"
#include "se23/so3.h"
#include "se23_test.h"

enum { S = SE23_GAUSS_NMAX, M = SE23_MEAS_MMAX };

#define SENTINEL 0x5a
#define TOL (64.0 * SE23T_EPS)
/* Step of the central differences. They are taken in the double reference
 * in both builds (from the build's float- or double-valued inputs, exactly
 * converted), so the step is the double one: truncation ~ FD_H^2 |h'''| ~
 * 1e-12 |h|, rounding ~ eps_double |h| / FD_H ~ 1e-8 for |h| ~ 50. */
#define FD_H 1e-6

typedef enum { POS_NAV, VEL_NAV, VEL_NAV_LEVER, VEL_BODY, ZERO_RATE, N_MODELS } model_t;

/* The inputs of any model; each takes the fields it needs. */
typedef struct {
    se23_pose_t T;
    se23_vec3_t y;   /* measured: p_n, v_n or v_b (unused by ZERO_RATE) */
    se23_vec3_t l;   /* lever arm (POS_NAV, VEL_NAV_LEVER) */
    se23_vec3_t w;   /* w_b (VEL_NAV_LEVER), w_meas (ZERO_RATE) */
    se23_vec3_t b_g; /* gyro bias estimate (ZERO_RATE) */
    se23_mat3_t cov;
} case_t;

static int has_pose(model_t which) { return which != ZERO_RATE; }

static se23_status_t call_model(model_t which, const case_t *c, se23_meas_t *out)
{
    switch (which) {
    case POS_NAV:
        return se23_meas_pos_nav(&c->T, &c->y, &c->l, &c->cov, out);
    case VEL_NAV:
        return se23_meas_vel_nav(&c->T, &c->y, &c->cov, out);
    case VEL_NAV_LEVER:
        return se23_meas_vel_nav_lever(&c->T, &c->w, &c->l, &c->y, &c->cov, out);
    case VEL_BODY:
        return se23_meas_vel_body(&c->T, &c->y, &c->cov, out);
    default:
        return se23_meas_zero_rate(&c->w, &c->b_g, &c->cov, out);
    }
}

static void random_case(se23t_rng_t *rng, model_t which, case_t *c)
{
    memset(c, 0, sizeof *c);
    se23t_random_pose(rng, 20.0, &c->T);
    se23t_random_vec3(rng, 20.0, &c->y);
    se23t_random_vec3(rng, 2.0, &c->l);
    se23t_random_vec3(rng, (which == ZERO_RATE) ? 0.05 : 2.0, &c->w);
    se23t_random_vec3(rng, 0.05, &c->b_g);
    gt_random_cov(rng, 3, 3, 3, 1.0, 0.1, &c->cov.m[0][0]);
}

/* h(T, bbar + db_g) in double from the 5x5 form of T; db_g = 0 at the
 * estimate. The bias-corrected rate of the lever model is w_b + db_g, the
 * true rate of the zero-rate model w_meas + b_g + db_g. */
static void reference_h(model_t which, const gt_m5_t *T, const case_t *c,
                        const double db_g[3], double h[3])
{
    const double l[3] = {c->l.v[0], c->l.v[1], c->l.v[2]};
    double w[3];
    for (int i = 0; i < 3; ++i) {
        w[i] = (double)c->w.v[i] + db_g[i];
    }
    const double u[3] = {w[1] * l[2] - w[2] * l[1], w[2] * l[0] - w[0] * l[2],
                         w[0] * l[1] - w[1] * l[0]};
    for (int i = 0; i < 3; ++i) {
        double s = 0;
        for (int k = 0; k < 3; ++k) {
            switch (which) {
            case POS_NAV:
                s += T->m[i][k] * l[k];
                break;
            case VEL_NAV_LEVER:
                s += T->m[i][k] * u[k];
                break;
            case VEL_BODY:
                s += T->m[k][i] * T->m[k][3];
                break;
            default:
                break;
            }
        }
        switch (which) {
        case POS_NAV:
            s += T->m[i][4];
            break;
        case VEL_NAV:
        case VEL_NAV_LEVER:
            s += T->m[i][3];
            break;
        case ZERO_RATE:
            s = w[i] + (double)c->b_g.v[i];
            break;
        default:
            break;
        }
        h[i] = s;
    }
}

/* The measured vector of the model (0 for the zero-rate model). */
static double measured(model_t which, const case_t *c, int i)
{
    return (which == ZERO_RATE) ? 0.0 : (double)c->y.v[i];
}

/* Central differences of h in all 15 error coordinates (xi by
 * T exp(xi), db_g through the rate, db_a: no model depends on it). */
static void central_differences(model_t which, const case_t *c, double cd[3][S])
{
    gt_m5_t Td;
    gt_from_pose(&c->T, &Td);
    for (int j = 0; j < S; ++j) {
        double hs[2][3];
        for (int sgn = 0; sgn < 2; ++sgn) {
            const double d = sgn ? FD_H : -FD_H;
            double e[9] = {0}, db[3] = {0};
            if (j < 9) {
                e[j] = d;
            } else if (j < 12) {
                db[j - 9] = d;
            }
            gt_m5_t E, Tp;
            gt_exp(e, &E);
            gt_m5_mul(&Td, &E, &Tp);
            reference_h(which, &Tp, c, db, hs[sgn]);
        }
        for (int i = 0; i < 3; ++i) {
            cd[i][j] = (hs[1][i] - hs[0][i]) / (2 * FD_H);
        }
    }
}

/* The largest |cd| in the 3x3 block of column j. */
static double block_scale(double cd[3][S], int j)
{
    double s = 0;
    for (int i = 0; i < 3; ++i) {
        for (int k = 3 * (j / 3); k < 3 * (j / 3) + 3; ++k) {
            s = fmax(s, fabs(cd[i][k]));
        }
    }
    return s;
}

static void test_meas_models_match_central_differences(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 701);
    for (int which = POS_NAV; which < N_MODELS; ++which) {
        const model_t w = (model_t)which;
        for (int rep = 0; rep < 30; ++rep) {
            case_t c;
            se23_meas_t out;
            random_case(&rng, w, &c);
            memset(&out, SENTINEL, sizeof out);
            assert_int_equal(call_model(w, &c, &out), SE23_OK);
            assert_int_equal(out.m, 3);
            gt_m5_t Td;
            gt_from_pose(&c.T, &Td);
            const double none[3] = {0};
            double h0[3], cd[3][S];
            reference_h(w, &Td, &c, none, h0);
            central_differences(w, &c, cd);
            for (int i = 0; i < 3; ++i) {
                assert_near(out.z[i], measured(w, &c, i) - h0[i], 2 * TOL * 40, 0.0);
                for (int j = 0; j < 3; ++j) {
                    assert_true(out.R[M * i + j] == c.cov.m[i][j]);
                }
                /* No model depends on the accelerometer bias. */
                for (int j = SE23_IDX_BA; j < S; ++j) {
                    assert_true(out.H[S * i + j] == SE23_R(0));
                }
                /* Only the lever and rate models on the gyro bias. */
                const int uses_bg = (w == VEL_NAV_LEVER || w == ZERO_RATE);
                for (int j = SE23_IDX_BG; j < SE23_IDX_BA && !uses_bg; ++j) {
                    assert_true(out.H[S * i + j] == SE23_R(0));
                }
                /* Per block: the CD's error (1e-7 absolute and relative)
                 * plus the library's rounding (32 eps of the block's
                 * magnitude). Far below the entries (O(1) to O(40)), so a
                 * wrong sign or block fails. */
                for (int j = 0; j < S; ++j) {
                    const double s = block_scale(cd, j);
                    const double bound = 1e-7 * (1.0 + s) + 32.0 * SE23T_EPS * s;
                    assert_near(out.H[S * i + j], cd[i][j], bound, 0.0);
                }
            }
        }
    }
}

/* The blocks of the two new models, the formulas of kalman.h: lever
 * velocity H = [-R (w x l)^, R, 0, -R l^, 0], zero rate [0, 0, 0, I, 0]
 * (exact). */
static void test_meas_new_models_blocks(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 704);
    case_t c;
    se23_meas_t out;
    random_case(&rng, VEL_NAV_LEVER, &c);
    assert_int_equal(call_model(VEL_NAV_LEVER, &c, &out), SE23_OK);
    se23_vec3_t u;
    se23_mat3_t ux, lx;
    u.v[0] = c.w.v[1] * c.l.v[2] - c.w.v[2] * c.l.v[1];
    u.v[1] = c.w.v[2] * c.l.v[0] - c.w.v[0] * c.l.v[2];
    u.v[2] = c.w.v[0] * c.l.v[1] - c.w.v[1] * c.l.v[0];
    se23_so3_hat(&u, &ux);
    se23_so3_hat(&c.l, &lx);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double a = 0, d = 0;
            for (int k = 0; k < 3; ++k) {
                a -= (double)c.T.R.m[i][k] * (double)ux.m[k][j];
                d -= (double)c.T.R.m[i][k] * (double)lx.m[k][j];
            }
            assert_near(out.H[S * i + j], a, 16 * TOL, 0.0);
            assert_true(out.H[S * i + SE23_IDX_NU + j] == c.T.R.m[i][j]);
            assert_true(out.H[S * i + SE23_IDX_RHO + j] == SE23_R(0));
            assert_near(out.H[S * i + SE23_IDX_BG + j], d, 16 * TOL, 0.0);
        }
    }
    random_case(&rng, ZERO_RATE, &c);
    assert_int_equal(call_model(ZERO_RATE, &c, &out), SE23_OK);
    for (int i = 0; i < 3; ++i) {
        assert_true(out.z[i] == -(c.w.v[i] + c.b_g.v[i]));
        for (int j = 0; j < S; ++j) {
            const se23_real_t e = (j == SE23_IDX_BG + i) ? SE23_R(1) : SE23_R(0);
            assert_true(out.H[S * i + j] == e);
        }
    }
}

/* The non-holonomic constraint: h = rows 2 and 3 of C_bv^T R^T v, so its
 * residual and H are those rows of C_bv^T times the body-velocity model's
 * central differences (in double), for random poses and mountings; R =
 * sigma^2 I_2; m = 2. */
static void test_meas_nhc_matches_central_differences(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 706);
    for (int rep = 0; rep < 30; ++rep) {
        case_t c;
        se23_vec3_t m_rv;
        se23_mat3_t C_bv;
        se23_meas_t out;
        random_case(&rng, VEL_BODY, &c);
        se23t_random_vec3(&rng, 1.5, &m_rv);
        assert_int_equal(se23_so3_exp(&m_rv, &C_bv), SE23_OK);
        memset(&out, SENTINEL, sizeof out);
        assert_int_equal(se23_meas_nhc(&c.T, &C_bv, SE23_R(0.3), &out), SE23_OK);
        assert_int_equal(out.m, 2);
        gt_m5_t Td;
        gt_from_pose(&c.T, &Td);
        const double none[3] = {0};
        double u[3], cd[3][S];
        reference_h(VEL_BODY, &Td, &c, none, u);
        central_differences(VEL_BODY, &c, cd);
        for (int r = 0; r < 2; ++r) {
            double h = 0, hj[S] = {0}, scale = 0;
            for (int k = 0; k < 3; ++k) {
                const double ck = (double)C_bv.m[k][r + 1];
                h += ck * u[k];
                for (int j = 0; j < S; ++j) {
                    hj[j] += ck * cd[k][j];
                }
            }
            for (int j = 0; j < S; ++j) {
                scale = fmax(scale, fabs(hj[j]));
            }
            assert_near(out.z[r], -h, 2 * TOL * 40, 0.0);
            for (int j = 0; j < S; ++j) {
                assert_near(out.H[S * r + j], hj[j], 1e-7 * (1.0 + scale) + 32.0 * SE23T_EPS * scale,
                            0.0);
            }
            assert_true(out.R[M * r + r] == SE23_R(0.3) * SE23_R(0.3));
            assert_true(out.R[M * r + (1 - r)] == SE23_R(0));
        }
    }
}

/* A car driving straight along its own axis satisfies the constraint (z =
 * 0); one sliding sideways at 1 m/s has z = (-1, 0); a bad mounting, sigma
 * or pose is refused with y untouched. */
static void test_meas_nhc_values_and_refusals(void **state)
{
    (void)state;
    se23_pose_t T;
    se23_mat3_t I3, bad;
    se23_meas_t y, before;
    const se23_vec3_t no_turn = {{0}};
    se23_identity(&T);
    assert_int_equal(se23_so3_exp(&no_turn, &I3), SE23_OK);
    T.v.v[0] = SE23_R(15);
    assert_int_equal(se23_meas_nhc(&T, &I3, SE23_R(0.3), &y), SE23_OK);
    assert_true(y.z[0] == SE23_R(0) && y.z[1] == SE23_R(0));
    T.v.v[1] = SE23_R(1);
    assert_int_equal(se23_meas_nhc(&T, &I3, SE23_R(0.3), &y), SE23_OK);
    assert_true(y.z[0] == SE23_R(-1) && y.z[1] == SE23_R(0));
    memset(&y, SENTINEL, sizeof y);
    before = y;
    bad = I3;
    bad.m[0][0] = SE23_R(1.1);
    assert_int_equal(se23_meas_nhc(&T, &bad, SE23_R(0.3), &y), SE23_ERR_NOT_ROTATION);
    assert_int_equal(se23_meas_nhc(&T, &I3, SE23_R(0), &y), SE23_ERR_DOMAIN);
    assert_int_equal(se23_meas_nhc(&T, &I3, SE23_R(NAN), &y), SE23_ERR_DOMAIN);
    assert_int_equal(se23_meas_nhc(&T, &I3, SE23_R(2e3), &y), SE23_ERR_DOMAIN);
    T.v.v[2] = SE23_R(INFINITY);
    assert_int_equal(se23_meas_nhc(&T, &I3, SE23_R(0.3), &y), SE23_ERR_NONFINITE);
    assert_memory_equal(&y, &before, sizeof y);
#if SE23_CFG_ARG_CHECKS
    assert_int_equal(se23_meas_nhc(NULL, &I3, SE23_R(0.3), &y), SE23_ERR_NULL);
    assert_int_equal(se23_meas_nhc(&T, NULL, SE23_R(0.3), &y), SE23_ERR_NULL);
    assert_int_equal(se23_meas_nhc(&T, &I3, SE23_R(0.3), NULL), SE23_ERR_NULL);
#endif
}

static void test_meas_vel_body_is_zero_velocity_update(void **state)
{
    (void)state;
    /* At rest with a zero measurement the residual is -R^T v. */
    se23_pose_t T;
    se23_identity(&T);
    T.v.v[0] = SE23_R(0.5);
    const se23_vec3_t zero = {{0}};
    const se23_mat3_t cov = {{{SE23_R(1e-4), 0, 0}, {0, SE23_R(1e-4), 0}, {0, 0, SE23_R(1e-4)}}};
    se23_meas_t y;
    assert_int_equal(se23_meas_vel_body(&T, &zero, &cov, &y), SE23_OK);
    assert_true(y.z[0] == SE23_R(-0.5) && y.z[1] == SE23_R(0) && y.z[2] == SE23_R(0));
}

/* ZUPT (kalman.h) is se23_meas_vel_nav with the zero vector: z = -v; and
 * the lever model with l = 0 is se23_meas_vel_nav, value for value. */
static void test_meas_zupt_and_zero_lever_are_vel_nav(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 705);
    case_t c;
    random_case(&rng, VEL_NAV_LEVER, &c);
    const se23_vec3_t zero = {{0}};
    se23_meas_t a, b;
    assert_int_equal(se23_meas_vel_nav(&c.T, &zero, &c.cov, &a), SE23_OK);
    for (int i = 0; i < 3; ++i) {
        assert_true(a.z[i] == -c.T.v.v[i]);
    }
    memset(&b, SENTINEL, sizeof b);
    assert_int_equal(se23_meas_vel_nav_lever(&c.T, &c.w, &zero, &zero, &c.cov, &b), SE23_OK);
    assert_int_equal(b.m, a.m);
    for (int i = 0; i < a.m; ++i) {
        assert_true(b.z[i] == a.z[i]);
        for (int j = 0; j < S; ++j) {
            assert_true(b.H[S * i + j] == a.H[S * i + j]);
        }
        for (int j = 0; j < a.m; ++j) {
            assert_true(b.R[M * i + j] == a.R[M * i + j]);
        }
    }
}

/* A vector input of the model by position (0, 1, 2), NULL past its last. */
static se23_vec3_t *vec_input(model_t which, case_t *c, int k)
{
    se23_vec3_t *const pos_nav[] = {&c->y, &c->l, NULL};
    se23_vec3_t *const one[] = {&c->y, NULL, NULL};
    se23_vec3_t *const lever[] = {&c->w, &c->l, &c->y};
    se23_vec3_t *const rate[] = {&c->w, &c->b_g, NULL};
    switch (which) {
    case POS_NAV:
        return pos_nav[k];
    case VEL_NAV_LEVER:
        return lever[k];
    case ZERO_RATE:
        return rate[k];
    default:
        return one[k];
    }
}

static void test_meas_models_reject_bad_input_untouched(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 702);
    se23_meas_t out, out0;
    memset(&out, SENTINEL, sizeof out);
    out0 = out;
    for (int which = POS_NAV; which < N_MODELS; ++which) {
        const model_t w = (model_t)which;
        case_t c, bad;
        random_case(&rng, w, &c);
        for (int k = 0; k < 3 && vec_input(w, &c, k) != NULL; ++k) {
            for (int i = 0; i < 3; ++i) {
                bad = c;
                vec_input(w, &bad, k)->v[i] = (se23_real_t)((i == 1) ? -INFINITY : NAN);
                assert_int_equal(call_model(w, &bad, &out), SE23_ERR_NONFINITE);
            }
        }
        if (has_pose(w)) {
            bad = c;
            bad.T.R.m[0][1] += SE23_R(0.01);
            assert_int_equal(call_model(w, &bad, &out), SE23_ERR_NOT_ROTATION);
            bad = c;
            bad.T.v.v[2] = (se23_real_t)INFINITY;
            assert_int_equal(call_model(w, &bad, &out), SE23_ERR_NONFINITE);
            bad = c;
            bad.T.p.v[0] = (se23_real_t)NAN;
            assert_int_equal(call_model(w, &bad, &out), SE23_ERR_NONFINITE);
        }
        bad = c;
        bad.cov.m[0][2] += SE23_R(0.5);
        assert_int_equal(call_model(w, &bad, &out), SE23_ERR_NOT_SYMMETRIC);
        bad = c;
        bad.cov.m[1][1] = -bad.cov.m[1][1];
        assert_int_equal(call_model(w, &bad, &out), SE23_ERR_NOT_PSD);
        bad.cov.m[1][1] = (se23_real_t)NAN;
        assert_int_equal(call_model(w, &bad, &out), SE23_ERR_NONFINITE);
    }
    assert_memory_equal(&out, &out0, sizeof out);
}

/* Finite inputs whose residual or Jacobian would overflow are refused
 * (types.h: SE23_OK means finite outputs), nothing written. */
static void test_meas_models_refuse_overflow_untouched(void **state)
{
    (void)state;
#if SE23_CFG_DOUBLE
    const se23_real_t big = SE23_R(1e200), huge = SE23_R(0.75 * DBL_MAX);
#else
    const se23_real_t big = SE23_R(1e30), huge = SE23_R(0.75 * FLT_MAX);
#endif
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 706);
    se23_meas_t out, out0;
    memset(&out, SENTINEL, sizeof out);
    out0 = out;
    case_t c;
    random_case(&rng, VEL_NAV_LEVER, &c);
    /* |w x l| ~ big^2: h, z and -R (w x l)^ overflow. */
    c.w.v[0] = big;
    c.l.v[1] = big;
    assert_int_equal(call_model(VEL_NAV_LEVER, &c, &out), SE23_ERR_NONFINITE);
    /* -R l^ alone (w = 0, z finite): R a turn of pi/4 about z, l = (huge,
     * -huge, 0): (l x r_1)_2 = huge (cos + sin) = 1.06 max. */
    random_case(&rng, VEL_NAV_LEVER, &c);
    const se23_vec3_t turn = {{SE23_R(0), SE23_R(0), SE23_R(0.78539816339744831)}};
    assert_int_equal(se23_so3_exp(&turn, &c.T.R), SE23_OK);
    memset(&c.w, 0, sizeof c.w);
    c.l.v[0] = huge;
    c.l.v[1] = -huge;
    c.l.v[2] = SE23_R(0);
    assert_int_equal(call_model(VEL_NAV_LEVER, &c, &out), SE23_ERR_NONFINITE);
    /* The same with a moderate lever is accepted (the refusal above is
     * the overflow, not the input). */
    c.l.v[0] = SE23_R(1);
    c.l.v[1] = SE23_R(-1);
    se23_meas_t ok;
    assert_int_equal(call_model(VEL_NAV_LEVER, &c, &ok), SE23_OK);
    /* w_meas + b_g overflows. */
    random_case(&rng, ZERO_RATE, &c);
    c.w.v[2] = huge;
    c.b_g.v[2] = huge;
    assert_int_equal(call_model(ZERO_RATE, &c, &out), SE23_ERR_NONFINITE);
    /* The residual of the position model: p_n - p. */
    random_case(&rng, POS_NAV, &c);
    c.y.v[0] = huge;
    c.T.p.v[0] = -huge;
    assert_int_equal(call_model(POS_NAV, &c, &out), SE23_ERR_NONFINITE);
    assert_memory_equal(&out, &out0, sizeof out);
}

/* The models write m = 3, z, H and R in the three rows (the bias columns
 * a model does not use 0, whatever the buffer held) and leave every entry
 * beyond them as it was: se23_kalman_update reads only those. */
static void test_meas_models_write_their_three_rows(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23_meas_t before;
    memset(&before, SENTINEL, sizeof before);
    se23t_rng_seed(&rng, 703);
    for (int which = POS_NAV; which < N_MODELS; ++which) {
        const model_t w = (model_t)which;
        const int bias_cols = (w == VEL_NAV_LEVER || w == ZERO_RATE) ? SE23_IDX_BA : SE23_IDX_BG;
        case_t c;
        se23_meas_t out = before;
        random_case(&rng, w, &c);
        assert_int_equal(call_model(w, &c, &out), SE23_OK);
        assert_int_equal(out.m, 3);
        for (int i = 0; i < M; ++i) {
            const int row = i < 3;
            assert_true(row ? isfinite(out.z[i]) : memcmp(&out.z[i], &before.z[i], sizeof out.z[i]) == 0);
            for (int j = 0; j < S; ++j) {
                const se23_real_t h = out.H[S * i + j];
                assert_true(!row ? memcmp(&h, &before.H[S * i + j], sizeof h) == 0
                                 : (j >= bias_cols ? h == SE23_R(0) : isfinite(h)));
            }
            for (int j = 0; j < M; ++j) {
                const se23_real_t r = out.R[M * i + j];
                assert_true((row && j < 3) ? r == c.cov.m[i][j]
                                           : memcmp(&r, &before.R[M * i + j], sizeof r) == 0);
            }
        }
    }
}

/* The noise check is that of gauss.h, both sides of each tolerance:
 * asymmetry and a negative eigenvalue of 0.5 tol s pass, 2 tol s fail. */
static void test_meas_cov_check_tolerance_boundaries(void **state)
{
    (void)state;
    se23_pose_t T;
    se23_identity(&T);
    const se23_vec3_t y = {{0}}, l = {{0}};
    const double tol = (double)SE23_CFG_COV_TOL;
    se23_meas_t out;
    for (int side = 0; side < 2; ++side) {
        const double k = side ? 2.0 : 0.5;
        se23_mat3_t cov = {{{SE23_R(1), 0, 0}, {0, SE23_R(1), 0}, {0, 0, SE23_R(1)}}};
        cov.m[0][2] = (se23_real_t)(k * tol);
        assert_int_equal(se23_meas_pos_nav(&T, &y, &l, &cov, &out),
                         side ? SE23_ERR_NOT_SYMMETRIC : SE23_OK);
        assert_int_equal(se23_meas_zero_rate(&y, &l, &cov, &out),
                         side ? SE23_ERR_NOT_SYMMETRIC : SE23_OK);
        /* (0, 1) = (1, 0) = 1 + k tol: smallest eigenvalue -k tol s, s = 1. */
        const se23_real_t c = (se23_real_t)(1.0 + k * tol);
        se23_mat3_t neg = {{{SE23_R(1), c, 0}, {c, SE23_R(1), 0}, {0, 0, SE23_R(1)}}};
        assert_int_equal(se23_meas_pos_nav(&T, &y, &l, &neg, &out),
                         side ? SE23_ERR_NOT_PSD : SE23_OK);
        assert_int_equal(se23_meas_zero_rate(&y, &l, &neg, &out),
                         side ? SE23_ERR_NOT_PSD : SE23_OK);
    }
    /* The zero matrix (an exact measurement) is valid. */
    const se23_mat3_t zero = {{{0}}};
    assert_int_equal(se23_meas_pos_nav(&T, &y, &l, &zero, &out), SE23_OK);
}

/* ZARU in a 15-state filter: each update lowers the gyro-bias variances
 * and moves bbar_g toward -w_meas (the true rate at rest is 0), the
 * distance shrinking by the factor r / (P_bb + r) of an isotropic noise;
 * repeated, bbar_g converges to -w_meas. With n = 9 the update leaves the
 * state as it was (H's first 9 columns are zero). */
static void test_meas_zero_rate_update_estimates_gyro_bias(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 707);
    se23_gauss_t g;
    gt_random_gauss(&rng, 15, &g);
    const se23_vec3_t w_meas = {{SE23_R(0.012), SE23_R(-0.021), SE23_R(0.0053)}};
    const se23_real_t r = SE23_R(1e-6);
    const se23_mat3_t cov = {{{r, 0, 0}, {0, r, 0}, {0, 0, r}}};
    double dist = 0;
    for (int i = 0; i < 3; ++i) {
        const double d = (double)g.b_g.v[i] + (double)w_meas.v[i];
        dist += d * d;
    }
    for (int k = 0; k < 20; ++k) {
        se23_meas_t y;
        se23_gauss_t out;
        assert_int_equal(se23_meas_zero_rate(&w_meas, &g.b_g, &cov, &y), SE23_OK);
        assert_int_equal(se23_kalman_update(&g, &y, &out, NULL), SE23_OK);
        double nd = 0;
        for (int i = 0; i < 3; ++i) {
            const int b = SE23_IDX_BG + i;
            assert_true(out.P.m[S * b + b] < g.P.m[S * b + b]);
            const double d = (double)out.b_g.v[i] + (double)w_meas.v[i];
            nd += d * d;
        }
        assert_true(nd < dist);
        dist = nd;
        g = out;
    }
    /* After 20 updates: P_bb ~ r / 20 per axis, the distance ~ r / P_bb0
     * of the start at most (P_bb0 >= 1e-3 here) and far below |w_meas|. */
    assert_true(sqrt(dist) < 1e-3 * 0.025);
    for (int i = 0; i < 3; ++i) {
        const int b = SE23_IDX_BG + i;
        assert_true(g.P.m[S * b + b] < 2.0 * (double)r / 20.0 + 1e-9);
    }
    /* n = 9: nothing moves. */
    se23_gauss_t g9, out9;
    gt_random_gauss(&rng, 9, &g9);
    se23_meas_t y;
    assert_int_equal(se23_meas_zero_rate(&w_meas, &g9.b_g, &cov, &y), SE23_OK);
    assert_int_equal(se23_kalman_update(&g9, &y, &out9, NULL), SE23_OK);
    assert_memory_equal(&out9.T, &g9.T, sizeof g9.T);
    for (int i = 0; i < 9; ++i) {
        assert_memory_equal(&out9.P.m[S * i], &g9.P.m[S * i], sizeof(se23_real_t) * 9);
    }
}

/* The lever model with n = 9: the b_g columns are ignored, the update is
 * that of the same H without them, bit for bit (kalman.h). */
static void test_meas_vel_nav_lever_n9_ignores_bias_columns(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 708);
    se23_gauss_t g, a, b;
    gt_random_gauss(&rng, 9, &g);
    case_t c;
    random_case(&rng, VEL_NAV_LEVER, &c);
    c.T = g.T;
    se23_meas_t y;
    assert_int_equal(call_model(VEL_NAV_LEVER, &c, &y), SE23_OK);
    assert_int_equal(se23_kalman_update(&g, &y, &a, NULL), SE23_OK);
    for (int i = 0; i < 3; ++i) {
        for (int j = SE23_IDX_BG; j < S; ++j) {
            y.H[S * i + j] = SE23_R(0);
        }
    }
    assert_int_equal(se23_kalman_update(&g, &y, &b, NULL), SE23_OK);
    assert_memory_equal(&a.T, &b.T, sizeof a.T);
    for (int i = 0; i < 9; ++i) {
        assert_memory_equal(&a.P.m[S * i], &b.P.m[S * i], sizeof(se23_real_t) * 9);
    }
}

static void test_meas_null_arguments_return_err_null(void **state)
{
    (void)state;
#if SE23_CFG_ARG_CHECKS
    se23_pose_t T;
    se23_vec3_t y = {{0}};
    se23_mat3_t cov = {{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
    se23_meas_t out;
    se23_identity(&T);
    assert_int_equal(se23_meas_pos_nav(NULL, &y, &y, &cov, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_pos_nav(&T, NULL, &y, &cov, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_pos_nav(&T, &y, NULL, &cov, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_pos_nav(&T, &y, &y, NULL, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_pos_nav(&T, &y, &y, &cov, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_meas_vel_nav(NULL, &y, &cov, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_vel_nav(&T, NULL, &cov, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_vel_nav(&T, &y, NULL, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_vel_nav(&T, &y, &cov, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_meas_vel_nav_lever(NULL, &y, &y, &y, &cov, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_vel_nav_lever(&T, NULL, &y, &y, &cov, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_vel_nav_lever(&T, &y, NULL, &y, &cov, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_vel_nav_lever(&T, &y, &y, NULL, &cov, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_vel_nav_lever(&T, &y, &y, &y, NULL, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_vel_nav_lever(&T, &y, &y, &y, &cov, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_meas_vel_body(NULL, &y, &cov, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_vel_body(&T, NULL, &cov, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_vel_body(&T, &y, NULL, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_vel_body(&T, &y, &cov, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_meas_zero_rate(NULL, &y, &cov, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_zero_rate(&y, NULL, &cov, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_zero_rate(&y, &y, NULL, &out), SE23_ERR_NULL);
    assert_int_equal(se23_meas_zero_rate(&y, &y, &cov, NULL), SE23_ERR_NULL);
#else
    skip();
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_meas_models_match_central_differences),
        cmocka_unit_test(test_meas_new_models_blocks),
        cmocka_unit_test(test_meas_nhc_matches_central_differences),
        cmocka_unit_test(test_meas_nhc_values_and_refusals),
        cmocka_unit_test(test_meas_vel_body_is_zero_velocity_update),
        cmocka_unit_test(test_meas_zupt_and_zero_lever_are_vel_nav),
        cmocka_unit_test(test_meas_models_reject_bad_input_untouched),
        cmocka_unit_test(test_meas_models_refuse_overflow_untouched),
        cmocka_unit_test(test_meas_models_write_their_three_rows),
        cmocka_unit_test(test_meas_cov_check_tolerance_boundaries),
        cmocka_unit_test(test_meas_zero_rate_update_estimates_gyro_bias),
        cmocka_unit_test(test_meas_vel_nav_lever_n9_ignores_bias_columns),
        cmocka_unit_test(test_meas_null_arguments_return_err_null),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
