/* Unit, property and statistical tests of src/cov/preint_unc.c: the factor's
 * Deltas equal se23_preint_add's; the bias Jacobian J against central
 * differences of a double re-integration (exact B_k: to rounding; the basic
 * dt I_{9,6}: visibly not); the covariance against step-by-step
 * propagation with gauss.h and against a Monte Carlo of noisy Deltas (mean
 * NEES in its chi^2_9 interval); bias correction: exact for an accelerometer
 * bias alone (paper section 4.1, last Proposition), second order in the
 * bias change, and ordered exact <= classical in velocity on a short case;
 * every bad-input path leaves the factor and the outputs unchanged. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "gauss_test.h"
#include "preint_unc_test.h"
#include "se23/gauss.h"
#include "se23/preint.h"
#include "se23/preint_unc.h"
#include "se23/se23.h"
#include "se23/so3.h"
#include "se23_test.h"

#define SENTINEL 0x5a
/* Two exact routes that differ in rounding order only, relative. */
#if SE23_CFG_DOUBLE
#define ROUND_TOL 1e-9
#else
#define ROUND_TOL 2e-3
#endif
/* The basic B_k = dt I_{9,6} misses O(dt) of J: at least this much. */
#define BASIC_MISS 2e-3

/* ------------------------------------------------------------ helpers */

/* col = central difference of log(D(0)^-1 D(h e_j)) / h, exact increments. */
static void fd_column(int n, int j, double col[9])
{
    const double h = (j < 3) ? FD_GYRO : FD_ACCEL;
    double e[6] = {0}, xp[9], xm[9];
    gt_m5_t D0, Dp, Dm;
    ref_factor(n, e, 0, &D0);
    e[j] = h;
    ref_factor(n, e, 0, &Dp);
    e[j] = -h;
    ref_factor(n, e, 0, &Dm);
    gt_log_between(&D0, &Dp, xp);
    gt_log_between(&D0, &Dm, xm);
    for (int i = 0; i < 9; ++i) {
        col[i] = (xp[i] - xm[i]) / (2.0 * h);
    }
}

/* Largest |J - reference| of column j, relative to the column's largest
 * reference entry. */
static double column_error(const se23_mat9x6_t *J, int j, const double col[9])
{
    double err = 0, scale = 0;
    for (int i = 0; i < 9; ++i) {
        err = fmax(err, fabs((double)J->m[6 * i + j] - col[i]));
        scale = fmax(scale, fabs(col[i]));
    }
    return err / scale;
}

/* The three corrections of fu_ex (exact J, classical) and fu_ba (basic J)
 * to BBAR + db, and the double re-integration at BBAR + db. */
enum { M_EXACT, M_BASIC, M_CLASSIC, M_NONE, N_M };
static void corrections(const se23_preint_unc_t *fu_ex, const se23_preint_unc_t *fu_ba,
                        int n, const double db[6], se23_pose_t out[N_M], se23_pose_t *ref)
{
    double b[6];
    for (int i = 0; i < 6; ++i) {
        b[i] = BBAR[i] + db[i];
    }
    se23_vec3_t bg, ba;
    bias_vecs(b, &bg, &ba);
    se23_preint_t r;
    assert_int_equal(se23_preint_unc_correct(fu_ex, &bg, &ba, &r), SE23_OK);
    out[M_EXACT] = r.delta;
    assert_int_equal(se23_preint_unc_correct(fu_ba, &bg, &ba, &r), SE23_OK);
    out[M_BASIC] = r.delta;
    assert_int_equal(se23_preint_unc_correct_classic(fu_ex, &bg, &ba, &r), SE23_OK);
    out[M_CLASSIC] = r.delta;
    out[M_NONE] = fu_ex->f.delta;
    gt_m5_t D;
    ref_factor(n, db, 0, &D);
    pose_of(&D, ref);
}

/* ------------------------------------------------------------ reset, add */

static void test_preint_unc_reset_gives_empty_factor(void **state)
{
    (void)state;
    se23_preint_unc_t fu;
    memset(&fu, SENTINEL, sizeof fu);
    se23_vec3_t bg, ba;
    bias_vecs(BBAR, &bg, &ba);
    assert_int_equal(se23_preint_unc_reset(&bg, &ba, SE23_INPUT_JAC_BASIC, &fu), SE23_OK);
    se23_pose_t I;
    se23_identity(&I);
    assert_memory_equal(&fu.f.delta, &I, sizeof I);
    assert_true(fu.f.dt == SE23_R(0));
    assert_int_equal(fu.f.n, 0);
    assert_memory_equal(&fu.b_g, &bg, sizeof bg);
    assert_memory_equal(&fu.b_a, &ba, sizeof ba);
    assert_int_equal(fu.kind, SE23_INPUT_JAC_BASIC);
    assert_int_equal(fu.classic, 0);
    const se23_real_t *blocks[3] = {fu.P_left.m, fu.J_left.m, &fu.cl.dR_dbg.m[0][0]};
    const int sizes[3] = {81, 54, 9};
    for (int b = 0; b < 3; ++b) {
        for (int i = 0; i < sizes[b]; ++i) {
            assert_true(blocks[b][i] == SE23_R(0));
        }
    }
    const se23_mat3_t *cl[5] = {&fu.cl.dR_dbg, &fu.cl.dV_dbg, &fu.cl.dV_dba,
                                &fu.cl.dX_dbg, &fu.cl.dX_dba};
    for (int b = 0; b < 5; ++b) {
        for (int i = 0; i < 9; ++i) {
            assert_true(cl[b]->m[i / 3][i % 3] == SE23_R(0));
        }
    }
    assert_int_equal(se23_preint_unc_check(&fu), SE23_OK);
}

/* Regression (issue 12, D2): a Delta R that passes the rotation test at
 * 0.9 of its tolerance comes back from either correction orthonormal to
 * rounding, so the corrected Deltas are a valid input again. */
static double orthogonality(const se23_mat3_t *R)
{
    double worst = 0;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double s = 0;
            for (int k = 0; k < 3; ++k) {
                s += (double)R->m[k][i] * R->m[k][j];
            }
            worst = fmax(worst, fabs(s - (i == j ? 1.0 : 0.0)));
        }
    }
    return worst;
}

static void test_preint_unc_correct_reorthonormalises(void **state)
{
    (void)state;
    se23_preint_unc_t fu;
    make_factor(30, SE23_INPUT_JAC_EXACT, &NOISE, &fu);
    /* Column 0 grown, column 1 shrunk by 0.45 tol: R^T R is 0.9 tol off I,
     * det R 1 - O(tol^2), so the rotation test still passes. */
    const se23_real_t d = SE23_R(0.45) * SE23_R(SE23_CFG_ROT_TOL);
    for (int i = 0; i < 3; ++i) {
        fu.f.delta.R.m[i][0] *= SE23_R(1) + d;
        fu.f.delta.R.m[i][1] *= SE23_R(1) - d;
    }
    assert_int_equal(se23_so3_check(&fu.f.delta.R), SE23_OK);
    assert_true(orthogonality(&fu.f.delta.R) > 0.8 * SE23_CFG_ROT_TOL);
    se23_vec3_t bg = fu.b_g, ba = fu.b_a;
    bg.v[0] += SE23_R(1e-3);
    ba.v[2] += SE23_R(1e-2);
    se23_preint_t out;
    assert_int_equal(se23_preint_unc_correct(&fu, &bg, &ba, &out), SE23_OK);
    assert_true(orthogonality(&out.delta.R) <= 16 * SE23T_EPS);
    assert_int_equal(se23_preint_unc_correct_classic(&fu, &bg, &ba, &out), SE23_OK);
    assert_true(orthogonality(&out.delta.R) <= 16 * SE23T_EPS);
}

/* The classical Jacobians are opt-in: without them a factor has the same
 * Deltas, P and J bit for bit, zero classical Jacobians, and refuses the
 * classical correction. */
static void test_preint_unc_classic_is_opt_in(void **state)
{
    (void)state;
    se23_preint_unc_t with, without;
    make_factor(40, SE23_INPUT_JAC_EXACT, &NOISE, &with);
    se23_vec3_t bg, ba;
    bias_vecs(BBAR, &bg, &ba);
    memset(&without, 0, sizeof without);
    assert_int_equal(se23_preint_unc_reset(&bg, &ba, SE23_INPUT_JAC_EXACT, &without), SE23_OK);
    static const double zero[6] = {0};
    for (int k = 0; k < 40; ++k) {
        const se23_imu_sample_t s = raw_sample(k, zero);
        assert_int_equal(se23_preint_unc_add(&without, &s, &NOISE), SE23_OK);
    }
    assert_int_equal(with.classic, 1);
    assert_int_equal(without.classic, 0);
    assert_memory_equal(&with.f, &without.f, sizeof with.f);
    assert_memory_equal(&with.P_left, &without.P_left, sizeof with.P_left);
    assert_memory_equal(&with.J_left, &without.J_left, sizeof with.J_left);
    const se23_real_t *cl = &without.cl.dR_dbg.m[0][0];
    for (size_t i = 0; i < sizeof without.cl / sizeof *cl; ++i) {
        assert_true(cl[i] == SE23_R(0));
    }
    assert_false(with.cl.dV_dba.m[0][0] == SE23_R(0));
    se23_preint_t out, out0;
    memset(&out, SENTINEL, sizeof out);
    out0 = out;
    assert_int_equal(se23_preint_unc_correct_classic(&without, &bg, &ba, &out), SE23_ERR_DOMAIN);
    assert_memory_equal(&out, &out0, sizeof out);
    assert_int_equal(se23_preint_unc_correct_classic(&with, &bg, &ba, &out), SE23_OK);
}

/* The work-area variant is the same computation: two factors, one fed by
 * se23_preint_unc_add, one by se23_preint_unc_add_work with a work area
 * refilled with NaN (0xff bytes) or zeros before each sample, stay equal
 * bit for bit (with the classical Jacobians); a NaN sample is refused the
 * same way, the factor untouched. */
static void test_preint_unc_add_work_equals_add_bit_for_bit(void **state)
{
    (void)state;
    se23_preint_unc_t a, b;
    se23_vec3_t bg, ba;
    bias_vecs(BBAR, &bg, &ba);
    memset(&a, 0, sizeof a);
    memset(&b, 0, sizeof b);
    assert_int_equal(se23_preint_unc_reset_classic(&bg, &ba, SE23_INPUT_JAC_EXACT, &a), SE23_OK);
    assert_int_equal(se23_preint_unc_reset_classic(&bg, &ba, SE23_INPUT_JAC_EXACT, &b), SE23_OK);
    se23_preint_work_t w;
    static const double zero[6] = {0};
    for (int k = 0; k < 40; ++k) {
        se23_imu_sample_t s = raw_sample(k, zero);
        memset(&w, (k % 2) ? 0xff : 0x00, sizeof w);
        assert_int_equal(se23_preint_unc_add(&a, &s, &NOISE), SE23_OK);
        assert_int_equal(se23_preint_unc_add_work(&b, &s, &NOISE, &w), SE23_OK);
        assert_memory_equal(&a, &b, sizeof a);
        s.f_b.v[2] = (se23_real_t)NAN;
        assert_int_equal(se23_preint_unc_add_work(&b, &s, &NOISE, &w), SE23_ERR_NONFINITE);
        assert_memory_equal(&a, &b, sizeof a);
    }
}

static void test_preint_unc_add_deltas_equal_preint_add(void **state)
{
    (void)state;
    /* The Deltas of the factor are se23_preint_add's on the corrected
     * samples, bit for bit (one increment serves both). */
    se23_preint_unc_t fu;
    make_factor(150, SE23_INPUT_JAC_EXACT, &NOISE, &fu);
    se23_preint_t ref;
    se23_preint_reset(&ref);
    static const double zero[6] = {0};
    for (int k = 0; k < 150; ++k) {
        se23_imu_sample_t s = raw_sample(k, zero);
        for (int i = 0; i < 3; ++i) {
            s.w_ib_b.v[i] += (se23_real_t)BBAR[i];
            s.f_b.v[i] += (se23_real_t)BBAR[3 + i];
        }
        assert_int_equal(se23_preint_add(&ref, &s), SE23_OK);
    }
    assert_memory_equal(&fu.f.delta, &ref.delta, sizeof ref.delta);
    assert_true(fu.f.dt == ref.dt);
    assert_int_equal(fu.f.n, 150);
    assert_int_equal(se23_preint_unc_check(&fu), SE23_OK);
}

/* ------------------------------------------------------------ Jacobians */

static void test_preint_unc_bias_jacobian_matches_central_differences(void **state)
{
    (void)state;
    /* d = log(Delta(bbar)^-1 Delta(bbar + db)) = J db + O(db^2), 1 s at
     * 100 Hz (DESIGN.md "Bias Jacobian"). Exact B_k: J is the derivative;
     * the basic dt I_{9,6} misses O(dt), which the test must see. */
    enum { N = HZ };
    se23_preint_unc_t ex, ba;
    make_factor(N, SE23_INPUT_JAC_EXACT, &QUIET, &ex);
    make_factor(N, SE23_INPUT_JAC_BASIC, &QUIET, &ba);
    const paper_form_t pf_ex = paper_form(&ex), pf_ba = paper_form(&ba);
    double worst_ex = 0, worst_ba = 0;
    for (int j = 0; j < 6; ++j) {
        double col[9];
        fd_column(N, j, col);
        worst_ex = fmax(worst_ex, column_error(&pf_ex.J, j, col));
        worst_ba = fmax(worst_ba, column_error(&pf_ba.J, j, col));
    }
    print_message("J vs central differences: exact %.2e, basic %.2e (relative)\n",
                  worst_ex, worst_ba);
    assert_true(worst_ex < JAC_TOL);
    assert_true(worst_ba > BASIC_MISS);
}

/* ------------------------------------------------------------ covariance */

static void test_preint_unc_cov_matches_step_by_step_propagation(void **state)
{
    (void)state;
    /* A state Tbar_i exp(xi_i), xi_i ~ N(0, S_i), predicted through the
     * factor: S_j = F_D S_i F_D^T + P, F_D = Ad_{Delta^-1} F_{Delta t}; the
     * same as se23_gauss_predict sample by sample (linear maps compose
     * exactly). Both input matrices. */
    enum { N = 80 };
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 4242);
    se23_earth_model_t model;
    const se23_vec3_t g_n = {{0, 0, SE23_R(9.81)}}, zero = {{0}};
    assert_int_equal(se23_earth_model_init(&g_n, &zero, SE23_R(DT), SE23_R(DT), &model), SE23_OK);
    const se23_input_jac_kind_t kinds[2] = {SE23_INPUT_JAC_EXACT, SE23_INPUT_JAC_BASIC};
    for (int kk = 0; kk < 2; ++kk) {
        se23_preint_unc_t fu;
        make_factor(N, kinds[kk], &NOISE, &fu);
        se23_gauss_t g;
        gt_random_gauss(&rng, 9, &g);
        bias_vecs(BBAR, &g.b_g, &g.b_a);
        double Si[81];
        for (int i = 0; i < 81; ++i) {
            Si[i] = (double)g.P.m[SE23_GAUSS_NMAX * (i / 9) + i % 9];
        }
        static const double no_db[6] = {0};
        for (int k = 0; k < N; ++k) {
            const se23_imu_sample_t s = raw_sample(k, no_db);
            assert_int_equal(se23_gauss_predict(&model, &g, &s, &NOISE, kinds[kk], &g), SE23_OK);
        }
        se23_mat9_t F;
        se23_gauss_fk(&fu.f.delta, fu.f.dt, &F);
        const paper_form_t pf = paper_form(&fu);
        double err = 0, scale = 0;
        for (int i = 0; i < 9; ++i) {
            for (int j = 0; j < 9; ++j) {
                double s = (double)pf.P.m[9 * i + j];
                for (int a = 0; a < 9; ++a) {
                    for (int b = 0; b < 9; ++b) {
                        s += (double)F.m[9 * i + a] * Si[9 * a + b] * (double)F.m[9 * j + b];
                    }
                }
                const double got = (double)g.P.m[SE23_GAUSS_NMAX * i + j];
                err = fmax(err, fabs(got - s));
                scale = fmax(scale, fabs(s));
            }
        }
        print_message("kind %d: step-by-step vs factor covariance %.2e (relative)\n", kk,
                      err / scale);
        assert_true(err / scale < ROUND_TOL);
    }
}

/* The left form over a long window (preint_unc.h): 30 s at 100 Hz, the
 * Deltas' position 2.2 km from the start (the specific force's 9.81
 * m/s^2). Its conversion to the paper's form subtracts the p^ terms that
 * the left form carries, |Delta p|^2 sigma_phi^2 beside the position
 * variance; the result must still match step-by-step propagation in the
 * right form (se23_gauss_predict from a zero covariance), in correlation
 * units |dP_ij| / sqrt(P_ii P_jj). Measured: 1.5e-14 (double), 4.3e-5
 * (float). */
static void test_preint_unc_long_window_matches_step_by_step(void **state)
{
    (void)state;
    enum { N = 30 * HZ };
#if SE23_CFG_DOUBLE
    const double tol = 1e-11;
#else
    const double tol = 5e-4;
#endif
    se23_preint_unc_t fu;
    make_factor(N, SE23_INPUT_JAC_EXACT, &NOISE, &fu);
    se23_earth_model_t model;
    const se23_vec3_t g_n = {{0, 0, SE23_R(9.81)}}, zero = {{0}};
    assert_int_equal(se23_earth_model_init(&g_n, &zero, SE23_R(DT), SE23_R(DT), &model), SE23_OK);
    static se23_gauss_t g; /* large: static */
    memset(&g, 0, sizeof g);
    se23_identity(&g.T);
    g.n = 9;
    bias_vecs(BBAR, &g.b_g, &g.b_a);
    static const double no_db[6] = {0};
    for (int k = 0; k < N; ++k) {
        const se23_imu_sample_t s = raw_sample(k, no_db);
        assert_int_equal(se23_gauss_predict(&model, &g, &s, &NOISE, SE23_INPUT_JAC_EXACT, &g),
                         SE23_OK);
    }
    const paper_form_t pf = paper_form(&fu);
    double worst = 0;
    for (int i = 0; i < 9; ++i) {
        for (int j = 0; j < 9; ++j) {
            const double want = (double)g.P.m[SE23_GAUSS_NMAX * i + j];
            const double s = sqrt((double)g.P.m[SE23_GAUSS_NMAX * i + i] *
                                  (double)g.P.m[SE23_GAUSS_NMAX * j + j]);
            worst = fmax(worst, fabs((double)pf.P.m[9 * i + j] - want) / s);
        }
    }
    const se23_real_t *p = fu.f.delta.p.v;
    const double dp = sqrt((double)(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
    print_message("30 s window, |Delta p| %.0f m: factor vs step-by-step %.2e (correlation)\n",
                  dp, worst);
    assert_true(worst < tol);
}

#define MC_RUNS 1000
#define MC_N 50

/* Mean NEES of MC_RUNS noisy re-integrations of MC_N samples against the
 * factor covariance P scaled by `scale`. */
static double mc_mean_nees(const se23_preint_unc_t *fu, double scale)
{
    double P[81], L[81];
    const paper_form_t pf = paper_form(fu);
    for (int i = 0; i < 81; ++i) {
        P[i] = scale * (double)pf.P.m[i];
    }
    assert_true(gt_chol(P, 9, L));
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 77);
    const double sg = (double)NOISE.gyro_noise / sqrt(DT);
    const double sa = (double)NOISE.accel_noise / sqrt(DT);
    double sum = 0;
    se23_pose_t Di;
    se23_inverse(&fu->f.delta, &Di);
    for (int r = 0; r < MC_RUNS; ++r) {
        double eta[6];
        se23_preint_t f;
        se23_preint_reset(&f);
        for (int k = 0; k < MC_N; ++k) {
            for (int i = 0; i < 6; ++i) {
                eta[i] = (i < 3 ? sg : sa) * se23t_normal(&rng);
            }
            se23_imu_sample_t s = raw_sample(k, eta);
            for (int i = 0; i < 3; ++i) { /* corrected by the estimate */
                s.w_ib_b.v[i] += fu->b_g.v[i];
                s.f_b.v[i] += fu->b_a.v[i];
            }
            assert_int_equal(se23_preint_add(&f, &s), SE23_OK);
        }
        se23_pose_t E;
        se23_tangent_t xi;
        se23_compose(&Di, &f.delta, &E);
        assert_int_equal(se23_log(&E, &xi), SE23_OK);
        double x[9];
        for (int i = 0; i < 9; ++i) {
            x[i] = (double)xi.v[i];
        }
        sum += gt_nees(L, 9, x);
    }
    return sum / MC_RUNS;
}

static void test_preint_unc_cov_monte_carlo_nees_within_chi2_interval(void **state)
{
    (void)state;
    /* Noisy Deltas Delta exp(xi): xi against P (paper eq. riccati) over
     * MC_RUNS runs of 0.5 s; noise per sample 0.2 rad/s and 2 m/s^2. The
     * control, P with the noise underestimated 1.3x, must fail. */
    se23_preint_unc_t fu;
    make_factor(MC_N, SE23_INPUT_JAC_EXACT, &NOISE, &fu);
    const double nees = mc_mean_nees(&fu, 1.0);
    const double ctl = mc_mean_nees(&fu, 1.0 / (1.3 * 1.3));
    double lo, hi;
    gt_chi2_mean_interval(9, MC_RUNS, &lo, &hi);
    print_message("factor mean NEES %.3f over %d runs, 95%% interval [%.3f, %.3f]; "
                  "control %.3f\n", nees, MC_RUNS, lo, hi, ctl);
    assert_true(nees > lo && nees < hi);
    assert_true(ctl > hi);
}

/* ------------------------------------------------------------ correction */

static void test_preint_unc_correct_to_same_bias_is_identity(void **state)
{
    (void)state;
    se23_preint_unc_t fu;
    make_factor(60, SE23_INPUT_JAC_EXACT, &QUIET, &fu);
    se23_preint_t a, b;
    assert_int_equal(se23_preint_unc_correct(&fu, &fu.b_g, &fu.b_a, &a), SE23_OK);
    assert_int_equal(se23_preint_unc_correct_classic(&fu, &fu.b_g, &fu.b_a, &b), SE23_OK);
    assert_pose_near(&a.delta, &fu.f.delta, 0.0);
    assert_pose_near(&b.delta, &fu.f.delta, 0.0);
    assert_true(a.dt == fu.f.dt && b.dt == fu.f.dt);
    assert_int_equal(a.n, 60);
    assert_int_equal(b.n, 60);
}

static void test_preint_unc_correct_accel_bias_alone_is_exact(void **state)
{
    (void)state;
    /* Paper section 4.1, last Proposition: without a gyro bias change the
     * exponential correction is exact (with the exact B_k: every step is
     * a pure translation). 2 s, db_a of 1 m/s^2 per axis. The basic B_k is
     * not exact, and neither is the classical (Euler Jacobians). */
    enum { N = 2 * HZ };
    se23_preint_unc_t ex, ba;
    make_factor(N, SE23_INPUT_JAC_EXACT, &QUIET, &ex);
    make_factor(N, SE23_INPUT_JAC_BASIC, &QUIET, &ba);
    const double db[6] = {0, 0, 0, 1.0, -1.0, 1.0};
    se23_pose_t c[N_M], ref;
    corrections(&ex, &ba, N, db, c, &ref);
    double ev[N_M], ep[N_M];
    for (int m = 0; m < N_M; ++m) {
        vp_errors(&c[m], &ref, &ev[m], &ep[m]);
    }
    print_message("accel bias alone: |dv| exact %.2e basic %.2e classical %.2e, "
                  "|dp| exact %.2e\n", ev[M_EXACT], ev[M_BASIC], ev[M_CLASSIC], ep[M_EXACT]);
    /* Rounding of Deltas of size ~20 m/s, ~20 m. */
    const double tol = 20.0 * 400.0 * SE23T_EPS;
    assert_true(ev[M_EXACT] < tol && ep[M_EXACT] < tol);
    assert_mat3_near(&c[M_EXACT].R, &ref.R, tol);
    /* Both miss dt^2 f / 2 per sample of the velocity input: ~ 6 mm/s. */
    assert_true(ev[M_BASIC] > 1e-3);
    assert_true(ev[M_CLASSIC] > 1e-3);
}

static void test_preint_unc_correct_error_is_second_order(void **state)
{
    (void)state;
    /* Halving the bias change quarters the error of the exponential
     * correction with the exact J (first order exactly right), and only
     * halves the uncorrected error. The classical correction's ratio is
     * printed: its Euler Jacobians leave an O(dt) first-order residual. */
    enum { N = 2 * HZ };
    se23_preint_unc_t ex, ba;
    make_factor(N, SE23_INPUT_JAC_EXACT, &QUIET, &ex);
    make_factor(N, SE23_INPUT_JAC_BASIC, &QUIET, &ba);
    const double db1[6] = {0.02, -0.015, 0.01, 0.05, 0.03, -0.04};
    double db2[6];
    for (int i = 0; i < 6; ++i) {
        db2[i] = 0.5 * db1[i];
    }
    se23_pose_t c1[N_M], c2[N_M], r1, r2;
    corrections(&ex, &ba, N, db1, c1, &r1);
    corrections(&ex, &ba, N, db2, c2, &r2);
    double e1[N_M], e2[N_M], p1, p2;
    for (int m = 0; m < N_M; ++m) {
        vp_errors(&c1[m], &r1, &e1[m], &p1);
        vp_errors(&c2[m], &r2, &e2[m], &p2);
        e1[m] += p1;
        e2[m] += p2;
    }
    print_message("error ratio at db and db/2: exact %.2f classical %.2f none %.2f\n",
                  e1[M_EXACT] / e2[M_EXACT], e1[M_CLASSIC] / e2[M_CLASSIC],
                  e1[M_NONE] / e2[M_NONE]);
    assert_true(e1[M_EXACT] / e2[M_EXACT] > 3.5 && e1[M_EXACT] / e2[M_EXACT] < 4.5);
    assert_true(e1[M_NONE] / e2[M_NONE] > 1.8 && e1[M_NONE] / e2[M_NONE] < 2.2);
}

static void test_preint_unc_correct_exact_beats_classical_on_short_case(void **state)
{
    (void)state;
    /* Low-cost IMU (1 deg/s, 100 mg per axis), factors of 2 s, 16 random
     * bias changes: velocity RMS against re-integration. The exponential
     * correction with the exact J is no worse than the basic one and
     * better than the classical one (the paper's Table, reduced); every
     * correction is far better than none. */
    enum { N = 2 * HZ, DRAWS = 16 };
    se23_preint_unc_t ex, ba;
    make_factor(N, SE23_INPUT_JAC_EXACT, &QUIET, &ex);
    make_factor(N, SE23_INPUT_JAC_BASIC, &QUIET, &ba);
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 2020);
    double v2[N_M] = {0};
    for (int d = 0; d < DRAWS; ++d) {
        double db[6];
        for (int i = 0; i < 6; ++i) {
            db[i] = (i < 3 ? PI / 180.0 : 0.980665) * se23t_normal(&rng);
        }
        se23_pose_t c[N_M], ref;
        corrections(&ex, &ba, N, db, c, &ref);
        for (int m = 0; m < N_M; ++m) {
            double ev, ep;
            vp_errors(&c[m], &ref, &ev, &ep);
            v2[m] += ev * ev / DRAWS;
        }
    }
    print_message("velocity RMS [m/s]: exact %.3e basic %.3e classical %.3e none %.3e\n",
                  sqrt(v2[M_EXACT]), sqrt(v2[M_BASIC]), sqrt(v2[M_CLASSIC]), sqrt(v2[M_NONE]));
    assert_true(v2[M_EXACT] <= v2[M_BASIC]);
    assert_true(v2[M_EXACT] < v2[M_CLASSIC]);
    assert_true(v2[M_CLASSIC] < 0.01 * v2[M_NONE]);
}

/* ------------------------------------------------------------ bad input */

/* fu after a failed call must equal the saved copy, bit for bit. */
static void assert_factor_same(const se23_preint_unc_t *a, const se23_preint_unc_t *b)
{
    assert_memory_equal(a, b, sizeof *a);
}

static void test_preint_unc_reset_rejects_bad_input_untouched(void **state)
{
    (void)state;
    se23_preint_unc_t fu, saved;
    memset(&fu, SENTINEL, sizeof fu);
    saved = fu;
    se23_vec3_t bg = {{0}}, ba = {{0}};
    bg.v[1] = (se23_real_t)NAN;
    assert_int_equal(se23_preint_unc_reset(&bg, &ba, SE23_INPUT_JAC_EXACT, &fu), SE23_ERR_NONFINITE);
    bg.v[1] = 0;
    ba.v[2] = (se23_real_t)INFINITY;
    assert_int_equal(se23_preint_unc_reset(&bg, &ba, SE23_INPUT_JAC_EXACT, &fu), SE23_ERR_NONFINITE);
    ba.v[2] = 0;
    assert_int_equal(se23_preint_unc_reset(&bg, &ba, (se23_input_jac_kind_t)7, &fu), SE23_ERR_DOMAIN);
    assert_factor_same(&fu, &saved);
}

static void test_preint_unc_add_rejects_bad_sample_and_noise_untouched(void **state)
{
    (void)state;
    se23_preint_unc_t fu, saved;
    make_factor(20, SE23_INPUT_JAC_EXACT, &NOISE, &fu);
    saved = fu;
    static const double zero[6] = {0};
    const se23_imu_sample_t good = raw_sample(20, zero);
    se23_imu_sample_t s = good;
    s.w_ib_b.v[0] = (se23_real_t)NAN;
    assert_int_equal(se23_preint_unc_add(&fu, &s, &NOISE), SE23_ERR_NONFINITE);
    s = good;
    s.f_b.v[2] = (se23_real_t)INFINITY;
    assert_int_equal(se23_preint_unc_add(&fu, &s, &NOISE), SE23_ERR_NONFINITE);
    s = good;
    s.dt = SE23_R(0);
    assert_int_equal(se23_preint_unc_add(&fu, &s, &NOISE), SE23_ERR_DT);
    s.dt = SE23_R(-0.01);
    assert_int_equal(se23_preint_unc_add(&fu, &s, &NOISE), SE23_ERR_DT);
    s.dt = SE23_R(2.0 * SE23_CFG_DT_MAX);
    assert_int_equal(se23_preint_unc_add(&fu, &s, &NOISE), SE23_ERR_DT);
    s.dt = (se23_real_t)NAN;
    assert_int_equal(se23_preint_unc_add(&fu, &s, &NOISE), SE23_ERR_NONFINITE);
    se23_imu_noise_t nz = NOISE;
    nz.gyro_noise = (se23_real_t)NAN;
    assert_int_equal(se23_preint_unc_add(&fu, &good, &nz), SE23_ERR_NONFINITE);
    nz = NOISE;
    nz.accel_noise = SE23_R(-0.1);
    assert_int_equal(se23_preint_unc_add(&fu, &good, &nz), SE23_ERR_DOMAIN);
    assert_factor_same(&fu, &saved);
    assert_int_equal(se23_preint_unc_add(&fu, &good, &NOISE), SE23_OK);
}

/* Regression (issue 12, D3): a denormal dt or a huge density overflowed the
 * noise with SE23_OK; now SE23_ERR_NONFINITE, the factor untouched. */
static void test_preint_unc_add_refuses_overflow_untouched(void **state)
{
    (void)state;
    se23_preint_unc_t fu, saved;
    make_factor(10, SE23_INPUT_JAC_EXACT, &NOISE, &fu);
    saved = fu;
    static const double zero[6] = {0};
    se23_imu_sample_t s = raw_sample(10, zero);
#if SE23_CFG_DOUBLE
    s.dt = 4.9e-324;
#else
    s.dt = 1.4e-45f;
#endif
    assert_int_equal(se23_preint_unc_add(&fu, &s, &NOISE), SE23_ERR_NONFINITE);
    s = raw_sample(10, zero);
    se23_imu_noise_t nz = NOISE;
#if SE23_CFG_DOUBLE
    nz.gyro_noise = 1e200; /* its square overflows */
#else
    nz.gyro_noise = 1e30f;
#endif
    assert_int_equal(se23_preint_unc_add(&fu, &s, &nz), SE23_ERR_NONFINITE);
    assert_factor_same(&fu, &saved);
    /* Regression (fuzz_preint_unc): a huge rate and force whose B_k
     * overflows inside its products (the bound of the step, exact
     * arithmetic, is finite) gave NaN in P and J with SE23_OK. */
#if SE23_CFG_DOUBLE
    const se23_imu_sample_t h = {{{1.34078e154, 1.34078e154, 1.34078e154}},
                                 {{1.34078e154, 7.29211e-05, 0.001}}, 7.29211e-05};
#else
    const se23_imu_sample_t h = {{{1e-12f, 0.5f, -1.32226e23f}}, {{1e18f, 7.29212e-05f, -3.14159f}},
                                 1e-05f};
#endif
    assert_int_equal(se23_preint_unc_add(&fu, &h, &NOISE), SE23_ERR_NONFINITE);
    assert_factor_same(&fu, &saved);
    /* Regression (make fuzz, fuzz_preint_unc): without noise (P = 0, so
     * the bound on P+ is 0) a force near the largest real overflowed the
     * classical Jacobians (Delta R f^ dR/dbg) with SE23_OK. The float
     * case reproduces it with gcc as with clang; in double gcc's rounding
     * already refuses the increment, clang's did not. */
    static const se23_imu_noise_t none = {0, 0, 0, 0};
    const se23_vec3_t b0 = {{0, 0, 0}};
    const se23_real_t M = (se23_real_t)SE23T_REAL_MAX;
    memset(&fu, 0, sizeof fu);
    assert_int_equal(se23_preint_unc_reset_classic(&b0, &b0, SE23_INPUT_JAC_EXACT, &fu), SE23_OK);
#if SE23_CFG_DOUBLE
    const se23_imu_sample_t s2 = {{{0, 1, 1e12}}, {{M, 1, 1e12}}, 0.005};
#else
    const se23_imu_sample_t s1 = {{{7.292115e-05f, 0, -49.1953125f}}, {{1, 1, 7.292115e-05f}},
                                  0.44033f};
    const se23_imu_sample_t s2 = {{{7.292115e-05f, 7.292115e-05f, 0}}, {{M, 0, 0}}, 1e-5f};
    assert_int_equal(se23_preint_unc_add(&fu, &s1, &none), SE23_OK);
#endif
    saved = fu;
    assert_int_equal(se23_preint_unc_add(&fu, &s2, &none), SE23_ERR_NONFINITE);
    assert_factor_same(&fu, &saved);
}

/* A valid factor with one defect planted by `plant`; add, correct,
 * correct_classic and check must return `expect` and change nothing. */
static void expect_rejected(void (*plant)(se23_preint_unc_t *), se23_status_t expect)
{
    se23_preint_unc_t fu, saved;
    make_factor(30, SE23_INPUT_JAC_EXACT, &NOISE, &fu);
    plant(&fu);
    saved = fu;
    static const double zero[6] = {0};
    const se23_imu_sample_t s = raw_sample(30, zero);
    assert_int_equal(se23_preint_unc_check(&fu), expect);
#if SE23_CFG_DEEP_CHECKS
    /* add trusts the factor it built, except in the debugging build. */
    assert_int_equal(se23_preint_unc_add(&fu, &s, &NOISE), expect);
#else
    (void)s;
#endif
    se23_preint_t out, out0;
    memset(&out, SENTINEL, sizeof out);
    out0 = out;
    assert_int_equal(se23_preint_unc_correct(&fu, &fu.b_g, &fu.b_a, &out), expect);
    assert_int_equal(se23_preint_unc_correct_classic(&fu, &fu.b_g, &fu.b_a, &out), expect);
    assert_memory_equal(&out, &out0, sizeof out);
    se23_mat9_t P, P0;
    se23_mat9x6_t J, J0;
    memset(&P, SENTINEL, sizeof P);
    memset(&J, SENTINEL, sizeof J);
    P0 = P;
    J0 = J;
    assert_int_equal(se23_preint_unc_cov(&fu, &P, &J), expect);
    assert_memory_equal(&P, &P0, sizeof P);
    assert_memory_equal(&J, &J0, sizeof J);
    assert_factor_same(&fu, &saved);
}

static void plant_not_psd(se23_preint_unc_t *fu) { fu->P_left.m[9 * 4 + 4] = SE23_R(-1); }
static void plant_not_symmetric(se23_preint_unc_t *fu) { fu->P_left.m[9 * 0 + 5] += SE23_R(0.5); }
static void plant_nan_p(se23_preint_unc_t *fu) { fu->P_left.m[9 * 8 + 8] = (se23_real_t)NAN; }
static void plant_nan_j(se23_preint_unc_t *fu) { fu->J_left.m[17] = (se23_real_t)NAN; }
static void plant_nan_classic(se23_preint_unc_t *fu) { fu->cl.dX_dba.m[2][1] = (se23_real_t)INFINITY; }
static void plant_nan_bias(se23_preint_unc_t *fu) { fu->b_a.v[0] = (se23_real_t)NAN; }
static void plant_nan_delta(se23_preint_unc_t *fu) { fu->f.delta.p.v[1] = (se23_real_t)NAN; }
static void plant_bad_rotation(se23_preint_unc_t *fu) { fu->f.delta.R.m[0][0] += SE23_R(0.01); }
static void plant_negative_dt(se23_preint_unc_t *fu) { fu->f.dt = SE23_R(-1); }
static void plant_nan_dt(se23_preint_unc_t *fu) { fu->f.dt = (se23_real_t)NAN; }
static void plant_bad_kind(se23_preint_unc_t *fu) { fu->kind = (se23_input_jac_kind_t)3; }
static void plant_bad_classic(se23_preint_unc_t *fu) { fu->classic = 2; }

static void test_preint_unc_corrupted_factor_is_rejected_untouched(void **state)
{
    (void)state;
    expect_rejected(plant_not_psd, SE23_ERR_NOT_PSD);
    expect_rejected(plant_not_symmetric, SE23_ERR_NOT_SYMMETRIC);
    expect_rejected(plant_nan_p, SE23_ERR_NONFINITE);
    expect_rejected(plant_nan_j, SE23_ERR_NONFINITE);
    expect_rejected(plant_nan_classic, SE23_ERR_NONFINITE);
    expect_rejected(plant_nan_bias, SE23_ERR_NONFINITE);
    expect_rejected(plant_nan_delta, SE23_ERR_NONFINITE);
    expect_rejected(plant_bad_rotation, SE23_ERR_NOT_ROTATION);
    expect_rejected(plant_negative_dt, SE23_ERR_DT);
    expect_rejected(plant_nan_dt, SE23_ERR_NONFINITE);
    expect_rejected(plant_bad_kind, SE23_ERR_DOMAIN);
    expect_rejected(plant_bad_classic, SE23_ERR_DOMAIN);
}

/* se23_preint_unc_cov: J is optional and P the same without it; Deltas
 * whose shear would overflow P (a valid factor: finite, in SO(3)) are
 * refused, nothing written; P NULL is refused. */
static void test_preint_unc_cov_outputs_and_refusals(void **state)
{
    (void)state;
    se23_preint_unc_t fu;
    make_factor(30, SE23_INPUT_JAC_EXACT, &NOISE, &fu);
    const paper_form_t pf = paper_form(&fu);
    se23_mat9_t P, P0;
    memset(&P, SENTINEL, sizeof P);
    assert_int_equal(se23_preint_unc_cov(&fu, &P, NULL), SE23_OK);
    assert_memory_equal(&P, &pf.P, sizeof P);
    for (int i = 0; i < 9; ++i) {
        for (int j = 0; j < 9; ++j) {
            assert_true(P.m[9 * i + j] == P.m[9 * j + i]);
        }
    }
    assert_int_equal(se23_preint_unc_cov(&fu, NULL, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_preint_unc_cov(NULL, &P, NULL), SE23_ERR_NULL);
    fu.f.delta.p.v[0] = (se23_real_t)(SE23T_REAL_MAX / 1e6);
    assert_int_equal(se23_preint_unc_check(&fu), SE23_OK);
    memset(&P, SENTINEL, sizeof P);
    P0 = P;
    assert_int_equal(se23_preint_unc_cov(&fu, &P, NULL), SE23_ERR_NONFINITE);
    assert_memory_equal(&P, &P0, sizeof P);
}

static void test_preint_unc_correct_rejects_bad_bias_untouched(void **state)
{
    (void)state;
    se23_preint_unc_t fu;
    make_factor(2 * HZ, SE23_INPUT_JAC_EXACT, &QUIET, &fu); /* J entries up to ~20 */
    se23_preint_t out, out0;
    memset(&out, SENTINEL, sizeof out);
    out0 = out;
    se23_vec3_t bg = fu.b_g, ba = fu.b_a;
    bg.v[2] = (se23_real_t)NAN;
    assert_int_equal(se23_preint_unc_correct(&fu, &bg, &ba, &out), SE23_ERR_NONFINITE);
    assert_int_equal(se23_preint_unc_correct_classic(&fu, &bg, &ba, &out), SE23_ERR_NONFINITE);
    bg = fu.b_g;
    ba.v[0] = (se23_real_t)-INFINITY;
    assert_int_equal(se23_preint_unc_correct(&fu, &bg, &ba, &out), SE23_ERR_NONFINITE);
    assert_int_equal(se23_preint_unc_correct_classic(&fu, &bg, &ba, &out), SE23_ERR_NONFINITE);
    /* Finite but so large that J db overflows. */
    ba = fu.b_a;
#if SE23_CFG_DOUBLE
    bg.v[0] = SE23_R(1e308);
#else
    bg.v[0] = SE23_R(3e38);
#endif
    assert_int_equal(se23_preint_unc_correct(&fu, &bg, &ba, &out), SE23_ERR_NONFINITE);
    /* Regression (fuzz_preint_unc): the classical correction of the same
     * bias (dV/dbg db_g beyond the largest real) gave Inf with SE23_OK. */
    assert_int_equal(se23_preint_unc_correct_classic(&fu, &bg, &ba, &out), SE23_ERR_NONFINITE);
    assert_memory_equal(&out, &out0, sizeof out);
}

static void test_preint_unc_null_arguments_return_err_null(void **state)
{
    (void)state;
#if SE23_CFG_ARG_CHECKS
    se23_preint_unc_t fu;
    make_factor(2, SE23_INPUT_JAC_EXACT, &QUIET, &fu);
    static const double zero[6] = {0};
    const se23_imu_sample_t s = raw_sample(0, zero);
    se23_preint_t out;
    const se23_vec3_t b = {{0}};
    assert_int_equal(se23_preint_unc_reset(NULL, &b, SE23_INPUT_JAC_EXACT, &fu), SE23_ERR_NULL);
    assert_int_equal(se23_preint_unc_reset(&b, NULL, SE23_INPUT_JAC_EXACT, &fu), SE23_ERR_NULL);
    assert_int_equal(se23_preint_unc_reset(&b, &b, SE23_INPUT_JAC_EXACT, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_preint_unc_add(NULL, &s, &QUIET), SE23_ERR_NULL);
    assert_int_equal(se23_preint_unc_add(&fu, NULL, &QUIET), SE23_ERR_NULL);
    assert_int_equal(se23_preint_unc_add(&fu, &s, NULL), SE23_ERR_NULL);
    se23_preint_work_t w;
    assert_int_equal(se23_preint_unc_add_work(NULL, &s, &QUIET, &w), SE23_ERR_NULL);
    assert_int_equal(se23_preint_unc_add_work(&fu, &s, &QUIET, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_preint_unc_check(NULL), SE23_ERR_NULL);
    assert_int_equal(se23_preint_unc_correct(NULL, &b, &b, &out), SE23_ERR_NULL);
    assert_int_equal(se23_preint_unc_correct(&fu, NULL, &b, &out), SE23_ERR_NULL);
    assert_int_equal(se23_preint_unc_correct(&fu, &b, NULL, &out), SE23_ERR_NULL);
    assert_int_equal(se23_preint_unc_correct(&fu, &b, &b, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_preint_unc_correct_classic(NULL, &b, &b, &out), SE23_ERR_NULL);
    assert_int_equal(se23_preint_unc_correct_classic(&fu, NULL, &b, &out), SE23_ERR_NULL);
    assert_int_equal(se23_preint_unc_correct_classic(&fu, &b, NULL, &out), SE23_ERR_NULL);
    assert_int_equal(se23_preint_unc_correct_classic(&fu, &b, &b, NULL), SE23_ERR_NULL);
#else
    skip();
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_preint_unc_reset_gives_empty_factor),
        cmocka_unit_test(test_preint_unc_classic_is_opt_in),
        cmocka_unit_test(test_preint_unc_correct_reorthonormalises),
        cmocka_unit_test(test_preint_unc_add_refuses_overflow_untouched),
        cmocka_unit_test(test_preint_unc_add_work_equals_add_bit_for_bit),
        cmocka_unit_test(test_preint_unc_add_deltas_equal_preint_add),
        cmocka_unit_test(test_preint_unc_bias_jacobian_matches_central_differences),
        cmocka_unit_test(test_preint_unc_cov_matches_step_by_step_propagation),
        cmocka_unit_test(test_preint_unc_long_window_matches_step_by_step),
        cmocka_unit_test(test_preint_unc_cov_monte_carlo_nees_within_chi2_interval),
        cmocka_unit_test(test_preint_unc_correct_to_same_bias_is_identity),
        cmocka_unit_test(test_preint_unc_correct_accel_bias_alone_is_exact),
        cmocka_unit_test(test_preint_unc_correct_error_is_second_order),
        cmocka_unit_test(test_preint_unc_correct_exact_beats_classical_on_short_case),
        cmocka_unit_test(test_preint_unc_reset_rejects_bad_input_untouched),
        cmocka_unit_test(test_preint_unc_add_rejects_bad_sample_and_noise_untouched),
        cmocka_unit_test(test_preint_unc_corrupted_factor_is_rejected_untouched),
        cmocka_unit_test(test_preint_unc_cov_outputs_and_refusals),
        cmocka_unit_test(test_preint_unc_correct_rejects_bad_bias_untouched),
        cmocka_unit_test(test_preint_unc_null_arguments_return_err_null),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
