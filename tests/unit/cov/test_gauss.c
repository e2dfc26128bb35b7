/* Unit, property and statistical tests of src/cov/gauss.c: F_k (against
 * Ad_{U^-1} F, the exact log-linear propagation and central differences),
 * the covariance propagation with and without bias states against dense
 * products, the noise model, the carried <-> user conversion (M against
 * central differences), the Monte Carlo NEES of the concentrated Gaussian,
 * and every bad-input path. */
#include <float.h>
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "cov/cov_check.h"
#include "gauss_test.h"
#include "se23/gauss.h"
#include "se23/imu.h"
#include "se23/se23.h"
#include "se23/so3.h"
#include "se23_test.h"

enum { S = SE23_GAUSS_NMAX };

#define SENTINEL 0x5a
/* Products of O(1) quantities, a few dozen operations. */
#define TOL (256.0 * SE23T_EPS)

/* ------------------------------------------------------------ helpers */

static se23_imu_sample_t random_sample(se23t_rng_t *rng, double dt)
{
    se23_imu_sample_t s;
    se23t_random_vec3(rng, 2.0, &s.w_ib_b);
    se23t_random_vec3(rng, 15.0, &s.f_b);
    s.dt = (se23_real_t)dt;
    return s;
}

static void increment(const se23_imu_sample_t *s, se23_pose_t *U)
{
    assert_int_equal(se23_imu_increment(s, U), SE23_OK);
}

/* C = A B^T (double), A, B n x k with strides sa, sb; C n x n stride S. */
static void mul_nt(const double *A, const double *B, int n, int k, int sa,
                   int sb, double *C)
{
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            double s = 0;
            for (int r = 0; r < k; ++r) {
                s += A[sa * i + r] * B[sb * j + r];
            }
            C[S * i + j] = s;
        }
    }
}

/* The dense transition Phi = [[F_k, B], [0, I]] (n = 15) or F_k (n = 9),
 * built from se23_adjoint_inv (not from the code under test), stride S. */
static void dense_phi(const se23_pose_t *U, double dt, const se23_mat9x6_t *B,
                      int n, double *Phi)
{
    se23_mat9_t Ad;
    se23_adjoint_inv(U, &Ad);
    memset(Phi, 0, sizeof(double) * S * S);
    for (int i = 0; i < 9; ++i) {
        for (int j = 0; j < 9; ++j) {
            /* (Ad F)_ij: F adds dt times column rho to column nu. */
            double s = Ad.m[9 * i + j];
            if (j >= 3 && j < 6) {
                s += dt * Ad.m[9 * i + j + 3];
            }
            Phi[S * i + j] = s;
        }
        for (int j = 9; j < n; ++j) {
            Phi[S * i + j] = B->m[6 * i + j - 9];
        }
    }
    for (int j = 9; j < n; ++j) {
        Phi[S * j + j] = 1.0;
    }
}

/* out = Phi P Phi^T (double, stride S). */
static void dense_congruence(const double *Phi, const se23_real_t *P, int n,
                             int sp, double *out)
{
    double PhiP[S * S];
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            double s = 0;
            for (int k = 0; k < n; ++k) {
                s += Phi[S * i + k] * (double)P[sp * k + j];
            }
            PhiP[S * i + j] = s;
        }
    }
    mul_nt(PhiP, Phi, n, n, S, S, out);
}

static double max_abs(const double *A, int n, int stride)
{
    double m = 0;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            m = fmax(m, fabs(A[stride * i + j]));
        }
    }
    return m;
}

static double max_abs_real(const se23_real_t *A, int n, int stride)
{
    double m = 0;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            m = fmax(m, fabs((double)A[stride * i + j]));
        }
    }
    return m;
}

static void assert_symmetric(const se23_real_t *A, int n, int stride)
{
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < i; ++j) {
            assert_true(A[stride * i + j] == A[stride * j + i]);
        }
    }
}

/* a and b hold the same state (fields and the leading n x n of P), bit
 * for bit. */
static void assert_gauss_same(const se23_gauss_t *a, const se23_gauss_t *b)
{
    assert_int_equal(a->n, b->n);
    assert_memory_equal(&a->T, &b->T, sizeof a->T);
    assert_memory_equal(&a->b_g, &b->b_g, sizeof a->b_g);
    assert_memory_equal(&a->b_a, &b->b_a, sizeof a->b_a);
    for (int i = 0; i < a->n; ++i) {
        assert_memory_equal(&a->P.m[S * i], &b->P.m[S * i], sizeof(se23_real_t) * (size_t)a->n);
    }
}

/* ------------------------------------------------------------ F_k */

static void test_gauss_fk_matches_adjoint_times_shear(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 601);
    for (int n = 0; n < 50; ++n) {
        const double dt = se23t_uniform(&rng, 0.001, 1.0);
        const se23_imu_sample_t s = random_sample(&rng, dt);
        se23_pose_t U;
        increment(&s, &U);
        se23_mat9_t F;
        double Phi[S * S];
        se23_gauss_fk(&U, (se23_real_t)dt, &F);
        dense_phi(&U, (double)(se23_real_t)dt, NULL, 9, Phi);
        const double scale = max_abs(Phi, 9, S);
        for (int i = 0; i < 9; ++i) {
            for (int j = 0; j < 9; ++j) {
                assert_near(F.m[9 * i + j], Phi[S * i + j], TOL * scale, 0.0);
            }
        }
    }
}

static void test_gauss_fk_is_exact_for_noise_free_step(void **state)
{
    (void)state;
    /* Paper Prop. bananaprop: Gamma Phi(Tbar exp(xi)) U = Tbar+ exp(F_k xi)
     * for any xi (|phi| < pi), any Gamma. */
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 602);
    for (int n = 0; n < 100; ++n) {
        const double dt = se23t_uniform(&rng, 0.001, 0.5);
        const se23_imu_sample_t s = random_sample(&rng, dt);
        se23_pose_t U, Tbar, G, E, T, Tn, Tbn, Tbi, D;
        se23_tangent_t xi, Fxi, d;
        increment(&s, &U);
        se23t_random_pose(&rng, 10.0, &Tbar);
        se23t_random_pose(&rng, 1.0, &G);
        se23t_random_tangent(&rng, 1.5, 1.0, &xi);
        assert_int_equal(se23_exp(&xi, &E), SE23_OK);
        se23_compose(&Tbar, &E, &T);
        se23_imu_transition(&G, &T, &U, s.dt, &Tn);
        se23_imu_transition(&G, &Tbar, &U, s.dt, &Tbn);
        se23_inverse(&Tbn, &Tbi);
        se23_compose(&Tbi, &Tn, &D);
        assert_int_equal(se23_log(&D, &d), SE23_OK);
        se23_gauss_fk_apply(&U, s.dt, &xi, &Fxi);
        assert_array_near(d.v, Fxi.v, 9, 4096 * SE23T_EPS, 0.0);
    }
}

static void test_gauss_fk_matches_central_differences(void **state)
{
    (void)state;
    /* In the double reference: d/dh log(Tbar+^-1 Gamma Phi(Tbar exp(h e_j)) U). */
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 603);
    const double h = 1e-5;
    for (int n = 0; n < 20; ++n) {
        const double dt = se23t_uniform(&rng, 0.001, 0.5);
        const se23_imu_sample_t s = random_sample(&rng, dt);
        se23_pose_t U, Tbar, G;
        increment(&s, &U);
        se23t_random_pose(&rng, 10.0, &Tbar);
        se23t_random_pose(&rng, 1.0, &G);
        gt_m5_t Ud, Td, Gd, Nbar;
        gt_from_pose(&U, &Ud);
        gt_from_pose(&Tbar, &Td);
        gt_from_pose(&G, &Gd);
        const double dts = (double)s.dt;
        gt_m5_t Ph = Td;
        for (int i = 0; i < 3; ++i) {
            Ph.m[i][4] += dts * Ph.m[i][3];
        }
        gt_m5_mul(&Gd, &Ph, &Nbar);
        gt_m5_mul(&Nbar, &Ud, &Nbar);
        se23_mat9_t F;
        se23_gauss_fk(&U, s.dt, &F);
        for (int j = 0; j < 9; ++j) {
            double xp[9], xm[9];
            for (int sgn = -1; sgn <= 1; sgn += 2) {
                double e[9] = {0};
                e[j] = sgn * h;
                gt_m5_t E, T, N;
                gt_exp(e, &E);
                gt_m5_mul(&Td, &E, &T);
                for (int i = 0; i < 3; ++i) {
                    T.m[i][4] += dts * T.m[i][3]; /* Phi */
                }
                gt_m5_mul(&Gd, &T, &N);
                gt_m5_mul(&N, &Ud, &N);
                gt_log_between(&Nbar, &N, sgn > 0 ? xp : xm);
            }
            for (int i = 0; i < 9; ++i) {
                const double cd = (xp[i] - xm[i]) / (2 * h);
                assert_near(F.m[9 * i + j], cd, 1e-6 + TOL * fabs(cd), 0.0);
            }
        }
    }
}

static void test_gauss_fk_mul_matches_dense(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 604);
    const se23_imu_sample_t s = random_sample(&rng, 0.05);
    se23_pose_t U;
    increment(&s, &U);
    se23_mat9x6_t X, Y;
    se23_mat9_t F;
    for (int i = 0; i < 54; ++i) {
        X.m[i] = (se23_real_t)se23t_normal(&rng);
    }
    se23_gauss_fk(&U, s.dt, &F);
    se23_gauss_fk_mul(&U, s.dt, &X, &Y);
    for (int i = 0; i < 9; ++i) {
        for (int j = 0; j < 6; ++j) {
            double r = 0;
            for (int k = 0; k < 9; ++k) {
                r += (double)F.m[9 * i + k] * X.m[6 * k + j];
            }
            assert_near(Y.m[6 * i + j], r, 64 * TOL, 0.0);
        }
    }
    se23_gauss_fk_mul(&U, s.dt, &X, &X); /* aliasing */
    assert_memory_equal(&X, &Y, sizeof X);
}

/* ------------------------------------------------------------ noise, Sigma */

static const se23_imu_noise_t NOISE = {SE23_R(0.01), SE23_R(0.1), SE23_R(1e-4),
                                       SE23_R(1e-3)};

static void test_gauss_input_noise_is_b_n_bt(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 605);
    const se23_imu_sample_t s = random_sample(&rng, 0.02);
    se23_mat9x6_t B;
    se23_mat9_t Q;
    assert_int_equal(se23_gauss_input_jac(SE23_INPUT_JAC_EXACT, &s.w_ib_b, &s.f_b, s.dt, &B), SE23_OK);
    assert_int_equal(se23_gauss_input_noise(&B, &NOISE, s.dt, &Q), SE23_OK);
    const double ng = (double)NOISE.gyro_noise * NOISE.gyro_noise / s.dt;
    const double na = (double)NOISE.accel_noise * NOISE.accel_noise / s.dt;
    for (int i = 0; i < 9; ++i) {
        for (int j = 0; j < 9; ++j) {
            double q = 0;
            for (int k = 0; k < 6; ++k) {
                q += (double)B.m[6 * i + k] * B.m[6 * j + k] * (k < 3 ? ng : na);
            }
            assert_near(Q.m[9 * i + j], q, 1e-3 * TOL * na * s.dt * s.dt, 4 * TOL);
        }
    }
    assert_symmetric(Q.m, 9, 9);
    /* The basic B gives the paper's diag(sg^2 dt I3, sa^2 dt I3, 0). */
    assert_int_equal(se23_gauss_input_jac(SE23_INPUT_JAC_BASIC, &s.w_ib_b, &s.f_b, s.dt, &B), SE23_OK);
    assert_int_equal(se23_gauss_input_noise(&B, &NOISE, s.dt, &Q), SE23_OK);
    for (int i = 0; i < 9; ++i) {
        for (int j = 0; j < 9; ++j) {
            const double e = (i != j || i >= 6) ? 0.0
                           : (i < 3 ? (double)NOISE.gyro_noise * NOISE.gyro_noise
                                    : (double)NOISE.accel_noise * NOISE.accel_noise) * s.dt;
            assert_near(Q.m[9 * i + j], e, 0, 8 * SE23T_EPS);
        }
    }
}

static void test_gauss_input_noise_rejects_bad_input_untouched(void **state)
{
    (void)state;
    se23_mat9x6_t B = {{0}};
    se23_mat9_t Q, Q0;
    memset(&Q, SENTINEL, sizeof Q);
    Q0 = Q;
    se23_imu_noise_t nz = NOISE;
    nz.accel_noise = SE23_R(-0.1);
    assert_int_equal(se23_gauss_input_noise(&B, &nz, SE23_R(0.01), &Q), SE23_ERR_DOMAIN);
    nz.accel_noise = (se23_real_t)NAN;
    assert_int_equal(se23_gauss_input_noise(&B, &nz, SE23_R(0.01), &Q), SE23_ERR_NONFINITE);
    assert_int_equal(se23_gauss_input_noise(&B, &NOISE, SE23_R(0), &Q), SE23_ERR_DT);
    B.m[17] = (se23_real_t)INFINITY;
    assert_int_equal(se23_gauss_input_noise(&B, &NOISE, SE23_R(0.01), &Q), SE23_ERR_NONFINITE);
    assert_memory_equal(&Q, &Q0, sizeof Q);
    /* Regression (fuzz_gauss): a finite B whose B N B^T overflows gave Inf
     * with SE23_OK. */
    B.m[17] = (se23_real_t)(0.5 * SE23T_REAL_MAX);
    assert_int_equal(se23_gauss_input_noise(&B, &NOISE, SE23_R(0.01), &Q), SE23_ERR_NONFINITE);
    assert_memory_equal(&Q, &Q0, sizeof Q);
    B.m[17] = SE23_R(1e3); /* and an ordinary one passes */
    assert_int_equal(se23_gauss_input_noise(&B, &NOISE, SE23_R(0.01), &Q), SE23_OK);
}

static void test_gauss_cov_propagate_matches_dense_and_is_symmetric(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 606);
    for (int n = 0; n < 50; ++n) {
        const double dt = se23t_uniform(&rng, 0.001, 0.5);
        const se23_imu_sample_t s = random_sample(&rng, dt);
        se23_pose_t U;
        increment(&s, &U);
        se23_mat9_t Sg, Q, Sn;
        gt_random_cov(&rng, 9, 9, 9, 0.3, 0.0, Sg.m);
        gt_random_cov(&rng, 9, 9, 9, 0.01, 0.0, Q.m);
        assert_int_equal(se23_gauss_cov_propagate(&Sg, &U, s.dt, &Q, &Sn), SE23_OK);
        double Phi[S * S], ref[S * S];
        dense_phi(&U, (double)s.dt, NULL, 9, Phi);
        dense_congruence(Phi, Sg.m, 9, 9, ref);
        const double scale = max_abs(ref, 9, S);
        for (int i = 0; i < 9; ++i) {
            for (int j = 0; j < 9; ++j) {
                assert_near(Sn.m[9 * i + j], ref[S * i + j] + Q.m[9 * i + j], TOL * scale, 0.0);
            }
        }
        assert_symmetric(Sn.m, 9, 9);
        assert_int_equal(se23_gauss_cov_propagate(&Sg, &U, s.dt, &Q, &Sg), SE23_OK);
        assert_memory_equal(&Sg, &Sn, sizeof Sg);
    }
}

/* Regression (issue 12, D1): with the output aliasing Q the lower triangle
 * read Q after it was overwritten (S+(6,3) = 0.02, S+(3,6) = 0.01). Every
 * aliasing gives the plain call's result, bit for bit. */
static void test_gauss_cov_propagate_output_may_alias_inputs(void **state)
{
    (void)state;
    se23_mat9_t S0 = {{0}}, Q0 = {{0}}, plain, a;
    se23_pose_t U;
    se23_identity(&U);
    for (int i = 0; i < 9; ++i) {
        S0.m[9 * i + i] = SE23_R(1);
        Q0.m[9 * i + i] = SE23_R(0.01);
    }
    assert_int_equal(se23_gauss_cov_propagate(&S0, &U, SE23_R(0.01), &Q0, &plain), SE23_OK);
    assert_true(plain.m[9 * 6 + 3] == plain.m[9 * 3 + 6]);
    a = Q0;
    assert_int_equal(se23_gauss_cov_propagate(&S0, &U, SE23_R(0.01), &a, &a), SE23_OK);
    assert_memory_equal(&a, &plain, sizeof a);
    a = S0;
    assert_int_equal(se23_gauss_cov_propagate(&a, &U, SE23_R(0.01), &Q0, &a), SE23_OK);
    assert_memory_equal(&a, &plain, sizeof a);
}

static void test_gauss_cov_propagate_rejects_bad_input_untouched(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 607);
    const se23_imu_sample_t s = random_sample(&rng, 0.01);
    se23_pose_t U, badU;
    increment(&s, &U);
    se23_mat9_t Sg, Q, out, out0, bad;
    gt_random_cov(&rng, 9, 9, 9, 0.3, 0.0, Sg.m);
    gt_random_cov(&rng, 9, 9, 9, 0.01, 0.0, Q.m);
    memset(&out, SENTINEL, sizeof out);
    out0 = out;
    bad = Sg;
    bad.m[9 * 2 + 5] += SE23_R(0.1);
    assert_int_equal(se23_gauss_cov_propagate(&bad, &U, s.dt, &Q, &out), SE23_ERR_NOT_SYMMETRIC);
    assert_int_equal(se23_gauss_cov_propagate(&Sg, &U, s.dt, &bad, &out), SE23_ERR_NOT_SYMMETRIC);
    bad = Sg;
    bad.m[9 * 4 + 4] = -bad.m[9 * 4 + 4];
    assert_int_equal(se23_gauss_cov_propagate(&bad, &U, s.dt, &Q, &out), SE23_ERR_NOT_PSD);
    bad.m[9 * 4 + 4] = (se23_real_t)NAN;
    assert_int_equal(se23_gauss_cov_propagate(&bad, &U, s.dt, &Q, &out), SE23_ERR_NONFINITE);
    badU = U;
    badU.R.m[0][0] += SE23_R(0.01);
    assert_int_equal(se23_gauss_cov_propagate(&Sg, &badU, s.dt, &Q, &out), SE23_ERR_NOT_ROTATION);
    badU = U;
    badU.p.v[1] = (se23_real_t)INFINITY;
    assert_int_equal(se23_gauss_cov_propagate(&Sg, &badU, s.dt, &Q, &out), SE23_ERR_NONFINITE);
    const se23_real_t bad_dt[] = {SE23_R(0), SE23_R(-1), (se23_real_t)NAN,
                                  SE23_R(2) * SE23_R(SE23_CFG_DT_MAX)};
    for (int k = 0; k < 4; ++k) {
        assert_int_equal(se23_gauss_cov_propagate(&Sg, &U, bad_dt[k], &Q, &out), SE23_ERR_DT);
    }
    assert_memory_equal(&out, &out0, sizeof out);
    /* Regression (make fuzz, fuzz_gauss): an increment with |v| near the
     * largest real and an S that is PSD only within tolerance (a tiny
     * covariance beside a zero variance) gave a finite S_next with
     * variances of -1e114, with SE23_OK; the bound of se23_gauss_predict
     * now refuses it. */
    se23_pose_t huge;
    se23_mat9_t S0 = {{0}}, Q0 = {{0}};
    se23_identity(&huge);
#if SE23_CFG_DOUBLE
    huge.v.v[0] = -1.89165e302;
    S0.m[1] = S0.m[9] = -2.16e-243;
#else
    huge.v.v[0] = -1.89165e37f;
    S0.m[1] = S0.m[9] = -2.16e-40f;
#endif
    huge.v.v[1] = SE23_R(1e3);
    huge.p.v[0] = SE23_R(-7e3);
    S0.m[0] = (se23_real_t)7.29e-5;
    assert_int_equal(se23_cov_check(S0.m, 9, 9), SE23_OK);
    assert_int_equal(se23_gauss_cov_propagate(&S0, &huge, (se23_real_t)7.29e-5, &Q0, &out),
                     SE23_ERR_NONFINITE);
    assert_memory_equal(&out, &out0, sizeof out);
}

/* Fuzzing (tests/fuzz/corpus/gauss/known-*): the covariance check admits
 * an eigenvalue down to -SE23_COV_ABS_TOL (twice the smallest normal
 * float), and a step scales that slack by its gain squared: a variance of
 * -1e-250 (double; -1e-40 in float) through |v| = 1e172 (1e37) came back
 * as about -1e94 (-1e34) with SE23_OK. A negative variance is now refused
 * by the check itself (issue 37, S4); the slack remains for an
 * off-diagonal entry (eigenvalue -1e-250), and the step's bound counts it
 * and refuses the step; nothing is written. */
static void test_gauss_cov_propagate_refuses_an_amplified_tolerance(void **state)
{
    (void)state;
    se23_pose_t U;
    se23_mat9_t S0 = {{0}}, Q0 = {{0}}, out, out0;
    memset(&out, 0x5a, sizeof out);
    out0 = out;
    se23_identity(&U);
#if SE23_CFG_DOUBLE
    const se23_real_t e = SE23_R(1e-250);
    U.v.v[1] = SE23_R(1e172);
#else
    const se23_real_t e = SE23_R(1e-40);
    U.v.v[1] = SE23_R(1e37);
#endif
    S0.m[0] = -e;
    assert_int_equal(se23_cov_check(S0.m, 9, 9), SE23_ERR_NOT_PSD);
    S0.m[0] = SE23_R(0);
    S0.m[1] = S0.m[9] = e;
    assert_int_equal(se23_cov_check(S0.m, 9, 9), SE23_OK);
    assert_int_equal(se23_gauss_cov_propagate(&S0, &U, SE23_R(0.01), &Q0, &out),
                     SE23_ERR_NONFINITE);
    assert_memory_equal(&out, &out0, sizeof out);
}

/* ------------------------------------------------------------ gauss_t */

static void test_gauss_propagate_matches_dense_with_and_without_biases(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 608);
    for (int rep = 0; rep < 20; ++rep) {
        const int n = (rep % 2) ? 15 : 9;
        const double dt = se23t_uniform(&rng, 0.001, 0.2);
        const se23_imu_sample_t s = random_sample(&rng, dt);
        se23_pose_t U;
        se23_mat9x6_t B;
        se23_mat9_t Q;
        se23_gauss_t g, out;
        increment(&s, &U);
        gt_random_gauss(&rng, n, &g);
        memset(&out, 0, sizeof out);
        assert_int_equal(se23_gauss_input_jac(SE23_INPUT_JAC_EXACT, &s.w_ib_b, &s.f_b, s.dt, &B), SE23_OK);
        assert_int_equal(se23_gauss_input_noise(&B, &NOISE, s.dt, &Q), SE23_OK);
        assert_int_equal(se23_gauss_propagate(&g, &U, &B, &NOISE, s.dt, &out), SE23_OK);
        double Phi[S * S], ref[S * S];
        dense_phi(&U, (double)s.dt, &B, n, Phi);
        dense_congruence(Phi, g.P.m, n, S, ref);
        for (int i = 0; i < 9; ++i) {
            for (int j = 0; j < 9; ++j) {
                ref[S * i + j] += Q.m[9 * i + j];
            }
        }
        for (int k = 9; k < n; ++k) {
            const double w = (k < 12) ? NOISE.gyro_walk : NOISE.accel_walk;
            ref[S * k + k] += w * w * s.dt;
        }
        const double scale = max_abs(ref, n, S);
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                assert_near(out.P.m[S * i + j], ref[S * i + j], TOL * scale, 0.0);
            }
        }
        assert_symmetric(out.P.m, n, S);
        assert_memory_equal(&out.T, &g.T, sizeof g.T);
        assert_memory_equal(&out.b_g, &g.b_g, sizeof g.b_g);
        assert_int_equal(out.n, n);
        if (n == 9) { /* the 9x9 block is se23_gauss_cov_propagate with Q */
            se23_mat9_t S9, S9n;
            for (int i = 0; i < 81; ++i) {
                S9.m[i] = g.P.m[S * (i / 9) + i % 9];
            }
            assert_int_equal(se23_gauss_cov_propagate(&S9, &U, s.dt, &Q, &S9n), SE23_OK);
            for (int i = 0; i < 81; ++i) {
                assert_near(out.P.m[S * (i / 9) + i % 9], S9n.m[i], TOL * scale, 0.0);
            }
        }
        assert_int_equal(se23_gauss_propagate(&g, &U, &B, &NOISE, s.dt, &g), SE23_OK);
        assert_gauss_same(&g, &out);
    }
}

static void test_gauss_check_reports_each_defect(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 609);
    se23_gauss_t g, bad;
    gt_random_gauss(&rng, 15, &g);
    assert_int_equal(se23_gauss_check(&g), SE23_OK);
    bad = g;
    bad.n = 12;
    assert_int_equal(se23_gauss_check(&bad), SE23_ERR_DIM);
    bad = g;
    bad.T.R.m[1][2] += SE23_R(0.01);
    assert_int_equal(se23_gauss_check(&bad), SE23_ERR_NOT_ROTATION);
    bad = g;
    bad.T.v.v[0] = (se23_real_t)NAN;
    assert_int_equal(se23_gauss_check(&bad), SE23_ERR_NONFINITE);
    bad = g;
    bad.b_a.v[2] = (se23_real_t)INFINITY;
    assert_int_equal(se23_gauss_check(&bad), SE23_ERR_NONFINITE);
    bad = g;
    bad.P.m[S * 13 + 2] += SE23_R(1e-2);
    assert_int_equal(se23_gauss_check(&bad), SE23_ERR_NOT_SYMMETRIC);
    bad = g;
    bad.P.m[S * 14 + 14] = SE23_R(-1e-3);
    assert_int_equal(se23_gauss_check(&bad), SE23_ERR_NOT_PSD);
    /* With n = 9 the bias block is not read. */
    bad.n = 9;
    assert_int_equal(se23_gauss_check(&bad), SE23_OK);
    /* Regression (issue 37, S4): a negative variance is refused however
     * small, alone (below the absolute tolerance) or beside a variance of
     * 1 (within the relative one). */
    memset(&bad.P, 0, sizeof bad.P);
    bad.n = 15;
    bad.P.m[0] = -SE23_R(1e-38);
    assert_int_equal(se23_gauss_check(&bad), SE23_ERR_NOT_PSD);
    bad.P.m[0] = SE23_R(1);
    bad.P.m[S * 4 + 4] = -SE23_R(1e-10);
    assert_int_equal(se23_gauss_check(&bad), SE23_ERR_NOT_PSD);
    bad.P.m[S * 4 + 4] = SE23_R(0);
    assert_int_equal(se23_gauss_check(&bad), SE23_OK);
}

/* Regression (issue 37, S1): a covariance accepted symmetric within the
 * check's tolerance comes back exactly symmetric from both conversions
 * (gauss.h: symmetric outputs), in place too. */
static void test_gauss_carried_conversion_output_is_symmetric(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 615);
    se23_earth_model_t model;
    assert_int_equal(se23_earth_model_init_wgs84(SE23_FRAME_NED, SE23_R(0.7), SE23_R(0),
                                                 SE23_R(0.01), SE23_R(0.01), &model), SE23_OK);
    for (int n = 9; n <= 15; n += 6) {
        se23_gauss_t g, out;
        gt_random_gauss(&rng, n, &g);
        g.P.m[1] += SE23_R(SE23_CFG_COV_TOL) * SE23_R(0.25) * g.P.m[0];
        g.P.m[S * (n - 1) + 2] += SE23_R(SE23_CFG_COV_TOL) * SE23_R(0.25) * g.P.m[0];
        assert_int_equal(se23_gauss_check(&g), SE23_OK);
        for (int dir = 0; dir < 2; ++dir) {
            out = g;
            const se23_status_t st = dir ? se23_gauss_to_carried(&model, &out, &out)
                                         : se23_gauss_from_carried(&model, &g, &out);
            assert_int_equal(st, SE23_OK);
            for (int i = 0; i < n; ++i) {
                for (int j = 0; j < i; ++j) {
                    assert_true(out.P.m[S * i + j] == out.P.m[S * j + i]);
                }
            }
        }
    }
}

static void test_gauss_propagate_rejects_bad_input_untouched(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 610);
    const se23_imu_sample_t s = random_sample(&rng, 0.01);
    se23_pose_t U, badU;
    se23_mat9x6_t B, badB;
    se23_gauss_t g, bad, out, out0;
    increment(&s, &U);
    assert_int_equal(se23_gauss_input_jac(SE23_INPUT_JAC_EXACT, &s.w_ib_b, &s.f_b, s.dt, &B), SE23_OK);
    gt_random_gauss(&rng, 15, &g);
    memset(&out, SENTINEL, sizeof out);
    out0 = out;
    bad = g;
    bad.n = 0;
    assert_int_equal(se23_gauss_propagate(&bad, &U, &B, &NOISE, s.dt, &out), SE23_ERR_DIM);
#if SE23_CFG_DEEP_CHECKS
    /* The state is re-proved only in the debugging build (types.h). */
    bad = g;
    bad.P.m[S * 10 + 10] = -SE23_R(1);
    assert_int_equal(se23_gauss_propagate(&bad, &U, &B, &NOISE, s.dt, &out), SE23_ERR_NOT_PSD);
#endif
    badU = U;
    badU.R.m[2][2] = -badU.R.m[2][2];
    assert_int_equal(se23_gauss_propagate(&g, &badU, &B, &NOISE, s.dt, &out), SE23_ERR_NOT_ROTATION);
    badB = B;
    badB.m[40] = (se23_real_t)NAN;
    assert_int_equal(se23_gauss_propagate(&g, &U, &badB, &NOISE, s.dt, &out), SE23_ERR_NONFINITE);
    se23_imu_noise_t nz = NOISE;
    nz.gyro_walk = SE23_R(-1);
    assert_int_equal(se23_gauss_propagate(&g, &U, &B, &nz, s.dt, &out), SE23_ERR_DOMAIN);
    assert_int_equal(se23_gauss_propagate(&g, &U, &B, &NOISE, SE23_R(0), &out), SE23_ERR_DT);
    assert_memory_equal(&out, &out0, sizeof out);
    /* In place: a failing call leaves the state itself untouched. */
    bad = g;
    se23_gauss_t copy = bad;
    assert_int_equal(se23_gauss_propagate(&bad, &U, &badB, &NOISE, s.dt, &bad), SE23_ERR_NONFINITE);
    assert_memory_equal(&bad, &copy, sizeof bad);
}

/* The rotating-Earth model of the prediction tests: NED, 0.8 rad
 * latitude, 100 m, samples of 10 ms (at most 50 ms). */
static void ned_model(se23_earth_model_t *model)
{
    assert_int_equal(se23_earth_model_init_wgs84(SE23_FRAME_NED, SE23_R(0.8), SE23_R(100),
                                                 SE23_R(0.01), SE23_R(0.05), model), SE23_OK);
}

static void test_gauss_predict_matches_step_and_propagate(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 611);
    se23_earth_model_t model;
    ned_model(&model);
    for (int rep = 0; rep < 10; ++rep) {
        const int n = (rep % 2) ? 15 : 9;
        const se23_imu_sample_t s = random_sample(&rng, 0.01);
        se23_gauss_t g, out, ref;
        gt_random_gauss(&rng, n, &g);
        assert_int_equal(se23_gauss_predict(&model, &g, &s, &NOISE, SE23_INPUT_JAC_EXACT, &out), SE23_OK);
        /* Corrected inputs w + b_g, f + b_a. */
        se23_imu_sample_t c = s;
        for (int k = 0; k < 3; ++k) {
            c.w_ib_b.v[k] += g.b_g.v[k];
            c.f_b.v[k] += g.b_a.v[k];
        }
        se23_pose_t U, Tn;
        se23_mat9x6_t B;
        increment(&c, &U);
        assert_int_equal(se23_imu_step(&model, &g.T, &c, &Tn), SE23_OK);
        assert_int_equal(se23_gauss_input_jac(SE23_INPUT_JAC_EXACT, &c.w_ib_b, &c.f_b, c.dt, &B), SE23_OK);
        assert_int_equal(se23_gauss_propagate(&g, &U, &B, &NOISE, c.dt, &ref), SE23_OK);
        ref.T = Tn;
        /* Same mean bit for bit; the covariance within rounding: propagate
         * un-rotates the public B_k that predict never forms. */
        assert_memory_equal(&out.T, &ref.T, sizeof out.T);
        assert_memory_equal(&out.b_g, &ref.b_g, sizeof out.b_g);
        assert_memory_equal(&out.b_a, &ref.b_a, sizeof out.b_a);
        const double scale = max_abs_real(ref.P.m, n, S);
        for (int i = 0; i < n; ++i) {
            assert_array_near(&out.P.m[S * i], &ref.P.m[S * i], n, 16 * SE23T_EPS * scale, 0.0);
        }
        /* The basic input matrix is accepted too and differs. */
        assert_int_equal(se23_gauss_predict(&model, &g, &s, &NOISE, SE23_INPUT_JAC_BASIC, &ref), SE23_OK);
        assert_true(memcmp(&ref.P, &out.P, sizeof out.P) != 0);
    }
}

/* The work-area variant is the same computation: equal bits with a work
 * area full of NaN (0xff bytes) or of zeros, whatever it held before, and
 * the same status, out untouched, on a bad sample. */
static void test_gauss_predict_work_equals_predict_bit_for_bit(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 613);
    se23_earth_model_t model;
    ned_model(&model);
    se23_predict_work_t w;
    for (int rep = 0; rep < 10; ++rep) {
        const int n = (rep % 2) ? 15 : 9;
        se23_imu_sample_t s = random_sample(&rng, 0.01);
        se23_gauss_t g, out, ref;
        gt_random_gauss(&rng, n, &g);
        memset(&w, (rep < 5) ? 0xff : 0x00, sizeof w);
        memset(&out, SENTINEL, sizeof out);
        memset(&ref, SENTINEL, sizeof ref);
        assert_int_equal(se23_gauss_predict(&model, &g, &s, &NOISE, SE23_INPUT_JAC_EXACT, &ref), SE23_OK);
        assert_int_equal(se23_gauss_predict_work(&model, &g, &s, &NOISE, SE23_INPUT_JAC_EXACT, &w, &out),
                         SE23_OK);
        assert_memory_equal(&out, &ref, sizeof out);
        s.w_ib_b.v[1] = (se23_real_t)NAN;
        assert_int_equal(se23_gauss_predict_work(&model, &g, &s, &NOISE, SE23_INPUT_JAC_EXACT, &w, &out),
                         SE23_ERR_NONFINITE);
        assert_memory_equal(&out, &ref, sizeof out);
    }
}

static void test_gauss_predict_rejects_bad_input_untouched(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 612);
    se23_earth_model_t model;
    const se23_vec3_t g_n = {{0, 0, SE23_R(9.81)}}, zero = {{0}};
    assert_int_equal(se23_earth_model_init(&g_n, &zero, SE23_R(0.01), SE23_R(0.02), &model), SE23_OK);
    se23_imu_sample_t s = random_sample(&rng, 0.01);
    se23_gauss_t g, bad, out, out0;
    gt_random_gauss(&rng, 15, &g);
    memset(&out, SENTINEL, sizeof out);
    out0 = out;
    bad = g;
    bad.n = 16;
    assert_int_equal(se23_gauss_predict(&model, &bad, &s, &NOISE, SE23_INPUT_JAC_EXACT, &out), SE23_ERR_DIM);
    s.dt = SE23_R(0.03); /* above model.dt_max */
    assert_int_equal(se23_gauss_predict(&model, &g, &s, &NOISE, SE23_INPUT_JAC_EXACT, &out), SE23_ERR_DT);
    s.dt = SE23_R(0.01);
    s.f_b.v[0] = (se23_real_t)NAN;
    assert_int_equal(se23_gauss_predict(&model, &g, &s, &NOISE, SE23_INPUT_JAC_EXACT, &out), SE23_ERR_NONFINITE);
    s.f_b.v[0] = SE23_R(0);
    assert_int_equal(se23_gauss_predict(&model, &g, &s, &NOISE, (se23_input_jac_kind_t)3, &out), SE23_ERR_DOMAIN);
    se23_imu_noise_t nz = NOISE;
    nz.gyro_noise = (se23_real_t)-INFINITY;
    assert_int_equal(se23_gauss_predict(&model, &g, &s, &nz, SE23_INPUT_JAC_EXACT, &out), SE23_ERR_NONFINITE);
    assert_memory_equal(&out, &out0, sizeof out);
}

/* A sample whose B_k overflows in its products (fuzz_gauss). */
static void ovf_sample(se23_imu_sample_t *s)
{
#if SE23_CFG_DOUBLE
    const se23_imu_sample_t h = {{{1.34078e154, 1.34078e154, 1.34078e154}},
                                 {{1.34078e154, 7.29211e-05, 0.001}}, 7.29211e-05};
#else
    const se23_imu_sample_t h = {{{1e-12f, 0.5f, -1.32226e23f}}, {{1e18f, 7.29212e-05f, -3.14159f}},
                                 1e-05f};
#endif
    *s = h;
}

/* Regression (issue 12, D3): finite inputs whose result would overflow
 * gave SE23_OK with Inf; now SE23_ERR_NONFINITE, nothing written. */
static void test_gauss_predict_refuses_overflow_untouched(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 615);
    se23_earth_model_t model;
    const se23_vec3_t g_n = {{0, 0, SE23_R(9.81)}}, zero = {{0}};
    assert_int_equal(se23_earth_model_init(&g_n, &zero, SE23_R(0.01), SE23_R(0.02), &model), SE23_OK);
    se23_imu_sample_t s = random_sample(&rng, 0.01);
    se23_gauss_t g, big, out, out0;
    gt_random_gauss(&rng, 15, &g);
    memset(&out, SENTINEL, sizeof out);
    out0 = out;
#if SE23_CFG_DOUBLE
    const se23_real_t tiny_dt = 4.9e-324, huge = DBL_MAX / 8;
#else
    const se23_real_t tiny_dt = 1.4e-45f, huge = FLT_MAX / 8;
#endif
    /* A denormal dt: sigma^2 / dt overflows. */
    s.dt = tiny_dt;
    assert_int_equal(se23_gauss_predict(&model, &g, &s, &NOISE, SE23_INPUT_JAC_EXACT, &out), SE23_ERR_NONFINITE);
    s.dt = SE23_R(0.01);
    /* A huge noise density. */
    se23_imu_noise_t nz = NOISE;
    nz.accel_noise = huge;
    assert_int_equal(se23_gauss_predict(&model, &g, &s, &nz, SE23_INPUT_JAC_EXACT, &out), SE23_ERR_NONFINITE);
    /* A covariance so large that P+ overflows. */
    big = g;
    for (int i = 0; i < 15; ++i) {
        big.P.m[S * i + i] = huge;
    }
    assert_int_equal(se23_gauss_predict(&model, &big, &s, &NOISE, SE23_INPUT_JAC_EXACT, &out), SE23_ERR_NONFINITE);
    /* A state so fast that the mean overflows. */
    big = g;
    big.T.v.v[0] = huge * SE23_R(4);
    s.f_b.v[0] = huge * SE23_R(4);
    assert_int_equal(se23_gauss_predict(&model, &big, &s, &NOISE, SE23_INPUT_JAC_EXACT, &out), SE23_ERR_NONFINITE);
    assert_memory_equal(&out, &out0, sizeof out);
    /* Regression (fuzz_gauss, fuzz_preint_unc): a huge rate and force whose
     * B_k overflows inside its products (the bound of the step, exact
     * arithmetic, is finite) gave NaN in P+ with SE23_OK. */
    se23_imu_sample_t h;
    ovf_sample(&h);
    assert_int_equal(se23_gauss_predict(&model, &g, &h, &NOISE, SE23_INPUT_JAC_EXACT, &out), SE23_ERR_NONFINITE);
    assert_memory_equal(&out, &out0, sizeof out);
}

/* ------------------------------------------------------------ carried <-> user */

static void test_gauss_from_carried_m_matches_central_differences(void **state)
{
    (void)state;
    /* xi' -> T' = Tbar' exp(xi'), T = (R, v' - Omega x p, p), xi = log(Tbar^-1 T):
     * d xi / d xi' at 0 must be M = [[I,0,0],[0,I,-(R^T Omega)^],[0,0,I]].
     * A large Omega makes the term visible in both precisions. */
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 613);
    se23_earth_model_t model;
    const se23_vec3_t g_n = {{0, 0, SE23_R(9.81)}};
    const se23_vec3_t om = {{SE23_R(0.3), SE23_R(-0.2), SE23_R(0.5)}};
    assert_int_equal(se23_earth_model_init(&g_n, &om, SE23_R(0.01), SE23_R(0.01), &model), SE23_OK);
    const double h = 1e-5;
    for (int rep = 0; rep < 10; ++rep) {
        se23_gauss_t gp, gu, back;
        gt_random_gauss(&rng, (rep % 2) ? 15 : 9, &gp);
        const int n = gp.n;
        assert_int_equal(se23_gauss_from_carried(&model, &gp, &gu), SE23_OK);
        /* Mean: v = v' - Omega x p. */
        for (int i = 0; i < 3; ++i) {
            const double c = (double)om.v[(i + 1) % 3] * gp.T.p.v[(i + 2) % 3] -
                             (double)om.v[(i + 2) % 3] * gp.T.p.v[(i + 1) % 3];
            assert_near(gu.T.v.v[i], gp.T.v.v[i] - c, TOL * 10, 0.0);
        }
        /* M by central differences in the double reference. */
        gt_m5_t Tp, Tu;
        gt_from_pose(&gp.T, &Tp);
        gt_from_pose(&gu.T, &Tu);
        double M[S * S] = {0};
        for (int k = 9; k < S; ++k) {
            M[S * k + k] = 1.0;
        }
        for (int j = 0; j < 9; ++j) {
            double xp[9], xm[9];
            for (int sgn = -1; sgn <= 1; sgn += 2) {
                double e[9] = {0};
                e[j] = sgn * h;
                gt_m5_t E, T;
                gt_exp(e, &E);
                gt_m5_mul(&Tp, &E, &T);
                double wxp[3];
                for (int i = 0; i < 3; ++i) {
                    wxp[i] = (double)om.v[(i + 1) % 3] * T.m[(i + 2) % 3][4] -
                             (double)om.v[(i + 2) % 3] * T.m[(i + 1) % 3][4];
                }
                for (int i = 0; i < 3; ++i) {
                    T.m[i][3] -= wxp[i];
                }
                gt_log_between(&Tu, &T, sgn > 0 ? xp : xm);
            }
            for (int i = 0; i < 9; ++i) {
                M[S * i + j] = (xp[i] - xm[i]) / (2 * h);
            }
        }
        double ref[S * S];
        dense_congruence(M, gp.P.m, n, S, ref);
        const double scale = max_abs(ref, n, S);
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                assert_near(gu.P.m[S * i + j], ref[S * i + j], 1e-8 * scale + TOL * scale, 0.0);
            }
        }
        assert_symmetric(gu.P.m, n, S);
        /* Round trip. */
        assert_int_equal(se23_gauss_to_carried(&model, &gu, &back), SE23_OK);
        assert_pose_near(&back.T, &gp.T, 10 * TOL * 10);
        for (int i = 0; i < n; ++i) {
            assert_array_near(&back.P.m[S * i], &gp.P.m[S * i], n, 10 * TOL, 0.0);
        }
    }
}

static void test_gauss_carried_conversion_rejects_bad_input_untouched(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 614);
    se23_earth_model_t model;
    assert_int_equal(se23_earth_model_init_wgs84(SE23_FRAME_ENU, SE23_R(0.5), SE23_R(0),
                                                 SE23_R(0.01), SE23_R(0.01), &model), SE23_OK);
    se23_gauss_t g, out, out0;
    gt_random_gauss(&rng, 9, &g);
    memset(&out, SENTINEL, sizeof out);
    out0 = out;
#if SE23_CFG_DEEP_CHECKS
    g.P.m[S * 1 + 1] = -SE23_R(1);
    assert_int_equal(se23_gauss_from_carried(&model, &g, &out), SE23_ERR_NOT_PSD);
    assert_int_equal(se23_gauss_to_carried(&model, &g, &out), SE23_ERR_NOT_PSD);
    g.P.m[S * 1 + 1] = SE23_R(1);
#endif
    model.w_ie_n.v[1] = (se23_real_t)NAN;
    assert_int_equal(se23_gauss_from_carried(&model, &g, &out), SE23_ERR_NONFINITE);
    assert_int_equal(se23_gauss_to_carried(&model, &g, &out), SE23_ERR_NONFINITE);
    assert_memory_equal(&out, &out0, sizeof out);
    /* Regression (fuzz_gauss): a valid state and model whose Omega x p or
     * M P M^T overflows gave Inf with SE23_OK. */
    const se23_vec3_t g_n = {{0, 0, SE23_R(9.8)}}, w = {{0, 0, SE23_R(4)}};
    assert_int_equal(se23_earth_model_init(&g_n, &w, SE23_R(0.01), SE23_R(0.01), &model), SE23_OK);
    se23_gauss_t h = g;
    h.T.p.v[0] = (se23_real_t)(0.5 * SE23T_REAL_MAX); /* |Omega x p| = 2 x the largest real */
    assert_int_equal(se23_gauss_check(&h), SE23_OK);
    assert_int_equal(se23_gauss_from_carried(&model, &h, &out), SE23_ERR_NONFINITE);
    assert_int_equal(se23_gauss_to_carried(&model, &h, &out), SE23_ERR_NONFINITE);
    assert_memory_equal(&out, &out0, sizeof out);
    h = g;
    for (int i = 0; i < 9; ++i) {
        h.P.m[(S + 1) * i] = (se23_real_t)(0.1 * SE23T_REAL_MAX); /* x (1 + |Omega|)^2 */
    }
    assert_int_equal(se23_gauss_check(&h), SE23_OK);
    assert_int_equal(se23_gauss_from_carried(&model, &h, &out), SE23_ERR_NONFINITE);
    assert_int_equal(se23_gauss_to_carried(&model, &h, &out), SE23_ERR_NONFINITE);
    assert_memory_equal(&out, &out0, sizeof out);
    assert_int_equal(se23_gauss_from_carried(&model, &g, &out), SE23_OK); /* an ordinary one */
}

/* ------------------------------------------------------------ Monte Carlo */

#define MC_RUNS 2000
#define MC_STEPS 50
#define MC_DT 0.02

/* Sample k of the Monte Carlo trajectory: nominal inputs plus white noise
 * of per-sample std sg (gyro) and sa (accel), as an IMU would average it. */
static se23_imu_sample_t mc_sample(int k, se23t_rng_t *rng, double sg, double sa)
{
    se23_imu_sample_t s;
    const double t = k * MC_DT;
    const double w[3] = {0.4 * sin(2.0 * t), 0.3, -0.5};
    const double f[3] = {2.0, cos(3.0 * t), -9.81};
    for (int i = 0; i < 3; ++i) {
        s.w_ib_b.v[i] = (se23_real_t)(w[i] + (sg > 0 ? sg * se23t_normal(rng) : 0.0));
        s.f_b.v[i] = (se23_real_t)(f[i] + (sa > 0 ? sa * se23t_normal(rng) : 0.0));
    }
    s.dt = SE23_R(MC_DT);
    return s;
}

/* Riccati propagation of g0 through the nominal inputs of the Monte Carlo
 * with the noise densities scaled by noise_scale: Tbar and Sigma (double). */
static void mc_riccati(const se23_earth_model_t *model, const se23_gauss_t *g0,
                       double noise_scale, se23_pose_t *Tbar, double *Sigma)
{
    se23_imu_noise_t nz = NOISE;
    nz.gyro_noise = (se23_real_t)(noise_scale * NOISE.gyro_noise);
    nz.accel_noise = (se23_real_t)(noise_scale * NOISE.accel_noise);
    se23_gauss_t g = *g0;
    for (int k = 0; k < MC_STEPS; ++k) {
        const se23_imu_sample_t s = mc_sample(k, NULL, 0, 0);
        assert_int_equal(se23_gauss_predict(model, &g, &s, &nz, SE23_INPUT_JAC_EXACT, &g), SE23_OK);
    }
    *Tbar = g.T;
    for (int i = 0; i < 81; ++i) {
        Sigma[i] = (double)g.P.m[S * (i / 9) + i % 9];
    }
}

/* Mean NEES over MC_RUNS of the endpoint error log(Tbar^-1 T), under the
 * two covariances Sig[0] and Sig[1], for noisy propagations from
 * T0 = Tbar0 exp(xi0), xi0 ~ N(0, P0). */
static void mc_mean_nees(const se23_earth_model_t *model,
                         const se23_gauss_t *g0, const se23_pose_t *Tbar,
                         double Sig[2][81], double nees[2])
{
    double L[2][81], L0[81], S0[81];
    for (int i = 0; i < 81; ++i) {
        S0[i] = (double)g0->P.m[S * (i / 9) + i % 9];
    }
    assert_true(gt_chol(Sig[0], 9, L[0]));
    assert_true(gt_chol(Sig[1], 9, L[1]));
    assert_true(gt_chol(S0, 9, L0));
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 615);
    const double sg = NOISE.gyro_noise / sqrt(MC_DT);
    const double sa = NOISE.accel_noise / sqrt(MC_DT);
    nees[0] = nees[1] = 0;
    for (int r = 0; r < MC_RUNS; ++r) {
        double x[9];
        gt_sample(&rng, L0, 9, x);
        se23_tangent_t xi;
        se23_pose_t E, T, Ti, D;
        for (int i = 0; i < 9; ++i) {
            xi.v[i] = (se23_real_t)x[i];
        }
        assert_int_equal(se23_exp(&xi, &E), SE23_OK);
        se23_compose(&g0->T, &E, &T);
        for (int k = 0; k < MC_STEPS; ++k) {
            const se23_imu_sample_t s = mc_sample(k, &rng, sg, sa);
            assert_int_equal(se23_imu_step(model, &T, &s, &T), SE23_OK);
        }
        se23_inverse(Tbar, &Ti);
        se23_compose(&Ti, &T, &D);
        assert_int_equal(se23_log(&D, &xi), SE23_OK);
        for (int i = 0; i < 9; ++i) {
            x[i] = (double)xi.v[i];
        }
        nees[0] += gt_nees(L[0], 9, x) / MC_RUNS;
        nees[1] += gt_nees(L[1], 9, x) / MC_RUNS;
    }
}

static void test_gauss_monte_carlo_nees_within_chi2_interval(void **state)
{
    (void)state;
    /* Paper section 3 / Figure MC: an uncertain start, noisy IMU, 1 s at
     * 50 Hz with a fast rotation and 10 m/s; the endpoint errors
     * log(Tbar^-1 T) of MC_RUNS noisy runs against the Riccati Sigma
     * (exact B_k, sample-averaged noise). Per-sample noise std: gyro
     * 0.07 rad/s, accel 0.7 m/s^2; endpoint attitude std ~ 0.06 rad. */
    se23_earth_model_t model;
    const se23_vec3_t g_n = {{0, 0, SE23_R(9.81)}}, zero = {{0}};
    assert_int_equal(se23_earth_model_init(&g_n, &zero, SE23_R(MC_DT), SE23_R(MC_DT), &model), SE23_OK);
    se23_gauss_t g0;
    memset(&g0, 0, sizeof g0);
    se23_identity(&g0.T);
    g0.T.v.v[0] = SE23_R(10);
    g0.n = 9;
    const double sd0[9] = {0.03, 0.03, 0.05, 0.1, 0.1, 0.1, 0.3, 0.3, 0.3};
    for (int i = 0; i < 9; ++i) {
        g0.P.m[S * i + i] = (se23_real_t)(sd0[i] * sd0[i]);
    }
    /* Sig[1]: the Riccati with noise densities 1/1.3 of the true ones, the
     * control that shows the test can fail. */
    double Sig[2][81], nees[2];
    se23_pose_t Tbar, T1;
    mc_riccati(&model, &g0, 1.0, &Tbar, Sig[0]);
    mc_riccati(&model, &g0, 1.0 / 1.3, &T1, Sig[1]);
    mc_mean_nees(&model, &g0, &Tbar, Sig, nees);
    double lo, hi;
    gt_chi2_mean_interval(9, MC_RUNS, &lo, &hi);
    print_message("mean NEES %.4f over %d runs, 95%% interval [%.4f, %.4f]; "
                  "noise underestimated 1.3x: %.4f\n", nees[0], MC_RUNS, lo, hi, nees[1]);
    assert_true(nees[0] > lo && nees[0] < hi);
    assert_true(nees[1] > hi);
}

/* ------------------------------------------------------------ NULL */

static void test_gauss_null_arguments_return_err_null(void **state)
{
    (void)state;
#if SE23_CFG_ARG_CHECKS
    se23_gauss_t g;
    se23_pose_t U;
    se23_mat9x6_t B = {{0}};
    se23_mat9_t M = {{0}};
    se23_earth_model_t model;
    se23_imu_sample_t s = {{{0}}, {{0}}, SE23_R(0.01)};
    memset(&model, 0, sizeof model);
    memset(&g, 0, sizeof g);
    se23_identity(&U);
    assert_int_equal(se23_gauss_input_noise(NULL, &NOISE, SE23_R(0.01), &M), SE23_ERR_NULL);
    assert_int_equal(se23_gauss_input_noise(&B, NULL, SE23_R(0.01), &M), SE23_ERR_NULL);
    assert_int_equal(se23_gauss_input_noise(&B, &NOISE, SE23_R(0.01), NULL), SE23_ERR_NULL);
    assert_int_equal(se23_gauss_cov_propagate(NULL, &U, SE23_R(0.01), &M, &M), SE23_ERR_NULL);
    assert_int_equal(se23_gauss_cov_propagate(&M, NULL, SE23_R(0.01), &M, &M), SE23_ERR_NULL);
    assert_int_equal(se23_gauss_cov_propagate(&M, &U, SE23_R(0.01), NULL, &M), SE23_ERR_NULL);
    assert_int_equal(se23_gauss_cov_propagate(&M, &U, SE23_R(0.01), &M, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_gauss_check(NULL), SE23_ERR_NULL);
    assert_int_equal(se23_gauss_propagate(NULL, &U, &B, &NOISE, SE23_R(0.01), &g), SE23_ERR_NULL);
    assert_int_equal(se23_gauss_propagate(&g, NULL, &B, &NOISE, SE23_R(0.01), &g), SE23_ERR_NULL);
    assert_int_equal(se23_gauss_propagate(&g, &U, NULL, &NOISE, SE23_R(0.01), &g), SE23_ERR_NULL);
    assert_int_equal(se23_gauss_propagate(&g, &U, &B, NULL, SE23_R(0.01), &g), SE23_ERR_NULL);
    assert_int_equal(se23_gauss_propagate(&g, &U, &B, &NOISE, SE23_R(0.01), NULL), SE23_ERR_NULL);
    assert_int_equal(se23_gauss_predict(NULL, &g, &s, &NOISE, SE23_INPUT_JAC_EXACT, &g), SE23_ERR_NULL);
    assert_int_equal(se23_gauss_predict(&model, NULL, &s, &NOISE, SE23_INPUT_JAC_EXACT, &g), SE23_ERR_NULL);
    assert_int_equal(se23_gauss_predict(&model, &g, NULL, &NOISE, SE23_INPUT_JAC_EXACT, &g), SE23_ERR_NULL);
    assert_int_equal(se23_gauss_predict(&model, &g, &s, NULL, SE23_INPUT_JAC_EXACT, &g), SE23_ERR_NULL);
    assert_int_equal(se23_gauss_predict(&model, &g, &s, &NOISE, SE23_INPUT_JAC_EXACT, NULL), SE23_ERR_NULL);
    se23_predict_work_t w;
    assert_int_equal(se23_gauss_predict_work(&model, &g, &s, &NOISE, SE23_INPUT_JAC_EXACT, NULL, &g),
                     SE23_ERR_NULL);
    assert_int_equal(se23_gauss_predict_work(&model, &g, &s, &NOISE, SE23_INPUT_JAC_EXACT, &w, NULL),
                     SE23_ERR_NULL);
    assert_int_equal(se23_gauss_from_carried(NULL, &g, &g), SE23_ERR_NULL);
    assert_int_equal(se23_gauss_from_carried(&model, NULL, &g), SE23_ERR_NULL);
    assert_int_equal(se23_gauss_from_carried(&model, &g, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_gauss_to_carried(NULL, &g, &g), SE23_ERR_NULL);
#else
    skip();
#endif
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_gauss_fk_matches_adjoint_times_shear),
        cmocka_unit_test(test_gauss_fk_is_exact_for_noise_free_step),
        cmocka_unit_test(test_gauss_fk_matches_central_differences),
        cmocka_unit_test(test_gauss_fk_mul_matches_dense),
        cmocka_unit_test(test_gauss_input_noise_is_b_n_bt),
        cmocka_unit_test(test_gauss_input_noise_rejects_bad_input_untouched),
        cmocka_unit_test(test_gauss_cov_propagate_matches_dense_and_is_symmetric),
        cmocka_unit_test(test_gauss_cov_propagate_output_may_alias_inputs),
        cmocka_unit_test(test_gauss_cov_propagate_rejects_bad_input_untouched),
        cmocka_unit_test(test_gauss_cov_propagate_refuses_an_amplified_tolerance),
        cmocka_unit_test(test_gauss_propagate_matches_dense_with_and_without_biases),
        cmocka_unit_test(test_gauss_check_reports_each_defect),
        cmocka_unit_test(test_gauss_propagate_rejects_bad_input_untouched),
        cmocka_unit_test(test_gauss_predict_matches_step_and_propagate),
        cmocka_unit_test(test_gauss_predict_work_equals_predict_bit_for_bit),
        cmocka_unit_test(test_gauss_predict_rejects_bad_input_untouched),
        cmocka_unit_test(test_gauss_predict_refuses_overflow_untouched),
        cmocka_unit_test(test_gauss_from_carried_m_matches_central_differences),
        cmocka_unit_test(test_gauss_carried_conversion_rejects_bad_input_untouched),
        cmocka_unit_test(test_gauss_carried_conversion_output_is_symmetric),
        cmocka_unit_test(test_gauss_monte_carlo_nees_within_chi2_interval),
        cmocka_unit_test(test_gauss_null_arguments_return_err_null),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
