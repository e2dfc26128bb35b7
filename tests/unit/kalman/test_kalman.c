/* Unit and statistical tests of src/kalman/kalman.c: the update against the dense
 * textbook formulas in double, the retraction, the NIS, every bad-input
 * path, and a 15-state filter (biased noisy IMU + GNSS position) that
 * estimates the biases and stays consistent over many runs (mean NEES of
 * the 15-dim error within its chi^2_15 interval). */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "gauss_test.h"
#include "se23/gauss.h"
#include "se23/imu.h"
#include "se23/kalman.h"
#include "se23/se23.h"
#include "se23/so3.h"
#include "se23_test.h"

enum { S = SE23_GAUSS_NMAX, M = SE23_MEAS_MMAX };

#define SENTINEL 0x5a
#define TOL (256.0 * SE23T_EPS)

static const se23_imu_noise_t KF_NOISE;

static void random_meas(se23t_rng_t *rng, int m, se23_meas_t *y)
{
    memset(y, 0, sizeof *y);
    y->m = m;
    for (int r = 0; r < m; ++r) {
        y->z[r] = (se23_real_t)(0.1 * se23t_normal(rng));
        for (int j = 0; j < S; ++j) {
            y->H[S * r + j] = (se23_real_t)se23t_normal(rng);
        }
    }
    gt_random_cov(rng, m, m, M, 0.1, 1e-2, y->R);
}

/* ------------------------------------------------------------ the update */

static void test_kalman_update_matches_dense_formulas(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 801);
    for (int rep = 0; rep < 40; ++rep) {
        const int n = (rep % 2) ? 15 : 9;
        const int m = 1 + rep % 9;
        se23_gauss_t g, out;
        se23_meas_t y;
        se23_real_t nis;
        gt_random_gauss(&rng, n, &g);
        random_meas(&rng, m, &y);
        assert_int_equal(se23_kalman_update(&g, &y, &out, &nis), SE23_OK);
        /* Dense double: S = H P H^T + R, K = P H^T S^-1, Joseph P+. */
        double P[S * S], H[M * S], PHt[S * M], Sd[M * M], L[M * M], K[S * M];
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                P[S * i + j] = g.P.m[S * i + j];
            }
        }
        for (int r = 0; r < m; ++r) {
            for (int j = 0; j < n; ++j) {
                H[S * r + j] = y.H[S * r + j];
            }
        }
        for (int i = 0; i < n; ++i) {
            for (int r = 0; r < m; ++r) {
                double s = 0;
                for (int j = 0; j < n; ++j) {
                    s += P[S * i + j] * H[S * r + j];
                }
                PHt[M * i + r] = s;
            }
        }
        for (int r = 0; r < m; ++r) {
            for (int q = 0; q < m; ++q) {
                double s = y.R[M * r + q];
                for (int j = 0; j < n; ++j) {
                    s += H[S * r + j] * PHt[M * j + q];
                }
                Sd[m * r + q] = s;
            }
        }
        assert_true(gt_chol(Sd, m, L));
        /* Row i of K = S^-1 (row i of P H^T): L u = row, L^T k = u. */
        for (int i = 0; i < n; ++i) {
            double u[M];
            for (int r = 0; r < m; ++r) {
                double s = PHt[M * i + r];
                for (int k = 0; k < r; ++k) {
                    s -= L[m * r + k] * u[k];
                }
                u[r] = s / L[m * r + r];
            }
            for (int r = m - 1; r >= 0; --r) {
                double s = u[r];
                for (int k = r + 1; k < m; ++k) {
                    s -= L[m * k + r] * K[M * i + k];
                }
                K[M * i + r] = s / L[m * r + r];
            }
        }
        double zd[M];
        for (int r = 0; r < m; ++r) {
            zd[r] = y.z[r];
        }
        assert_near(nis, gt_nees(L, m, zd), 0, 1e3 * SE23T_EPS);
        /* dx, retraction, biases. */
        double dx[S];
        for (int i = 0; i < n; ++i) {
            dx[i] = 0;
            for (int r = 0; r < m; ++r) {
                dx[i] += K[M * i + r] * zd[r];
            }
        }
        se23_tangent_t xi;
        se23_pose_t E, T;
        for (int i = 0; i < 9; ++i) {
            xi.v[i] = (se23_real_t)dx[i];
        }
        assert_int_equal(se23_exp(&xi, &E), SE23_OK);
        se23_compose(&g.T, &E, &T);
        assert_pose_near(&out.T, &T, 1e4 * SE23T_EPS);
        for (int k = 0; k < 3; ++k) {
            const double eg = (n == 15) ? dx[9 + k] : 0.0, ea = (n == 15) ? dx[12 + k] : 0.0;
            assert_near(out.b_g.v[k], g.b_g.v[k] + eg, 1e3 * SE23T_EPS, 0.0);
            assert_near(out.b_a.v[k], g.b_a.v[k] + ea, 1e3 * SE23T_EPS, 0.0);
        }
        /* Joseph: A P A^T + K R K^T, A = I - K H. */
        double A[S * S], AP[S * S];
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                double s = (i == j) ? 1.0 : 0.0;
                for (int r = 0; r < m; ++r) {
                    s -= K[M * i + r] * H[S * r + j];
                }
                A[S * i + j] = s;
            }
        }
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                double s = 0;
                for (int k = 0; k < n; ++k) {
                    s += A[S * i + k] * P[S * k + j];
                }
                AP[S * i + j] = s;
            }
        }
        double scale = 0;
        for (int i = 0; i < n; ++i) {
            scale = fmax(scale, P[S * i + i]);
        }
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                double s = 0;
                for (int k = 0; k < n; ++k) {
                    s += AP[S * i + k] * A[S * j + k];
                }
                for (int r = 0; r < m; ++r) {
                    for (int q = 0; q < m; ++q) {
                        s += K[M * i + r] * y.R[M * r + q] * K[M * j + q];
                    }
                }
                assert_near(out.P.m[S * i + j], s, 1e3 * SE23T_EPS * scale, 0.0);
                assert_true(out.P.m[S * i + j] == out.P.m[S * j + i]);
            }
        }
        /* Aliasing: in place gives the same bits; nis may be NULL. */
        se23_gauss_t inplace = g;
        assert_int_equal(se23_kalman_update(&inplace, &y, &inplace, NULL), SE23_OK);
        assert_memory_equal(&inplace.T, &out.T, sizeof out.T);
        for (int i = 0; i < n; ++i) {
            assert_memory_equal(&inplace.P.m[S * i], &out.P.m[S * i], sizeof(se23_real_t) * (size_t)n);
        }
    }
}

static void test_kalman_update_ignores_bias_columns_when_n_is_9(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 802);
    se23_gauss_t g, a, b;
    se23_meas_t y;
    gt_random_gauss(&rng, 9, &g);
    random_meas(&rng, 3, &y);
    assert_int_equal(se23_kalman_update(&g, &y, &a, NULL), SE23_OK);
    for (int r = 0; r < 3; ++r) {
        for (int j = 9; j < S; ++j) {
            y.H[S * r + j] = (se23_real_t)NAN;
        }
    }
    assert_int_equal(se23_kalman_update(&g, &y, &b, NULL), SE23_OK);
    assert_memory_equal(&a.T, &b.T, sizeof a.T);
    assert_memory_equal(&a.b_g, &g.b_g, sizeof a.b_g);
}

static void test_kalman_update_rejects_bad_input_untouched(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 803);
    se23_gauss_t g, bad, out, out0;
    se23_meas_t y, yb;
    se23_real_t nis = SE23_R(-7);
    gt_random_gauss(&rng, 15, &g);
    random_meas(&rng, 4, &y);
    memset(&out, SENTINEL, sizeof out);
    out0 = out;
    yb = y;
    yb.m = 0;
    assert_int_equal(se23_kalman_update(&g, &yb, &out, &nis), SE23_ERR_DIM);
    yb.m = 10;
    assert_int_equal(se23_kalman_update(&g, &yb, &out, &nis), SE23_ERR_DIM);
    yb = y;
    yb.z[3] = (se23_real_t)NAN;
    assert_int_equal(se23_kalman_update(&g, &yb, &out, &nis), SE23_ERR_NONFINITE);
    yb = y;
    yb.H[S * 2 + 14] = (se23_real_t)INFINITY;
    assert_int_equal(se23_kalman_update(&g, &yb, &out, &nis), SE23_ERR_NONFINITE);
    yb = y;
    yb.R[M * 1 + 3] += SE23_R(0.5);
    assert_int_equal(se23_kalman_update(&g, &yb, &out, &nis), SE23_ERR_NOT_SYMMETRIC);
    yb = y;
    yb.R[M * 2 + 2] = -SE23_R(10);
    assert_int_equal(se23_kalman_update(&g, &yb, &out, &nis), SE23_ERR_NOT_PSD);
    yb.R[M * 2 + 2] = (se23_real_t)NAN;
    assert_int_equal(se23_kalman_update(&g, &yb, &out, &nis), SE23_ERR_NONFINITE);
    /* Singular S: no prior uncertainty along H and no measurement noise. */
    bad = g;
    memset(&bad.P, 0, sizeof bad.P);
    yb = y;
    memset(yb.R, 0, sizeof yb.R);
    assert_int_equal(se23_kalman_update(&bad, &yb, &out, &nis), SE23_ERR_NOT_PSD);
    /* Two identical rows with zero noise: S has rank m - 1. */
    yb = y;
    memset(yb.R, 0, sizeof yb.R);
    memcpy(&yb.H[S], &yb.H[0], sizeof(se23_real_t) * S);
    assert_int_equal(se23_kalman_update(&g, &yb, &out, &nis), SE23_ERR_NOT_PSD);
    bad = g;
    bad.n = 10;
    assert_int_equal(se23_kalman_update(&bad, &y, &out, &nis), SE23_ERR_DIM);
    /* The state is trusted (types.h): its deep check runs only with
     * SE23_CFG_DEEP_CHECKS. */
#if SE23_CFG_DEEP_CHECKS
    bad = g;
    bad.T.R.m[0][0] = SE23_R(2);
    assert_int_equal(se23_kalman_update(&bad, &y, &out, &nis), SE23_ERR_NOT_ROTATION);
    bad = g;
    bad.P.m[S * 5 + 12] += SE23_R(1);
    assert_int_equal(se23_kalman_update(&bad, &y, &out, &nis), SE23_ERR_NOT_SYMMETRIC);
#endif
    /* A mean that a correction could overflow. */
    bad = g;
    bad.T.p.v[1] = (se23_real_t)INFINITY;
    assert_int_equal(se23_kalman_update(&bad, &y, &out, &nis), SE23_ERR_NONFINITE);
    assert_memory_equal(&out, &out0, sizeof out);
    assert_true(nis == SE23_R(-7));
    /* In place: a failing call leaves the state untouched. */
    bad = g;
    yb = y;
    yb.H[S * 1 + 3] = (se23_real_t)NAN;
    se23_gauss_t copy = bad;
    assert_int_equal(se23_kalman_update(&bad, &yb, &bad, NULL), SE23_ERR_NONFINITE);
    assert_memory_equal(&bad, &copy, sizeof bad);
    yb = y;
    memset(yb.R, 0, sizeof yb.R);
    memset(&bad.P, 0, sizeof bad.P);
    copy = bad;
    assert_int_equal(se23_kalman_update(&bad, &yb, &bad, NULL), SE23_ERR_NOT_PSD);
    assert_memory_equal(&bad, &copy, sizeof bad);
}

/* D3 (issue 12): SE23_OK means finite outputs. P = 0 with a denormal R
 * used to give NIS = Inf with SE23_OK; an innovation far beyond sqrt(R)
 * overflows the NIS; both are refused and nothing is written. */
static void test_kalman_update_refuses_overflowing_results(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 806);
    se23_gauss_t g, out, out0;
    se23_meas_t y;
    se23_real_t nis = SE23_R(-7);
    gt_random_gauss(&rng, 15, &g);
    memset(&out, SENTINEL, sizeof out);
    out0 = out;
    memset(&y, 0, sizeof y);
    y.m = 3;
    for (int r = 0; r < 3; ++r) {
        y.z[r] = SE23_R(0.1);
        y.H[S * r + SE23_IDX_RHO + r] = SE23_R(1);
    }
    /* P = 0, R denormal: S = R has a pivot below the smallest normal. */
    se23_gauss_t g0 = g;
    memset(&g0.P, 0, sizeof g0.P);
#if SE23_CFG_DOUBLE
    const se23_real_t denormal = SE23_R(1e-310);
#else
    const se23_real_t denormal = SE23_R(1e-40);
#endif
    for (int r = 0; r < 3; ++r) {
        y.R[M * r + r] = denormal;
    }
    assert_true(denormal > SE23_R(0));
    assert_int_equal(se23_kalman_update(&g0, &y, &out, &nis), SE23_ERR_NOT_PSD);
    /* R tiny but normal, z huge: the NIS z^T S^-1 z overflows. */
#if SE23_CFG_DOUBLE
    const se23_real_t tiny = SE23_R(1e-200), huge = SE23_R(1e200);
#else
    const se23_real_t tiny = SE23_R(1e-30), huge = SE23_R(1e30);
#endif
    for (int r = 0; r < 3; ++r) {
        y.R[M * r + r] = tiny;
        y.z[r] = huge;
    }
    assert_int_equal(se23_kalman_update(&g0, &y, &out, &nis), SE23_ERR_NONFINITE);
    /* With the prior uncertainty, a correction beyond any sane magnitude
     * (|dx| ~ z) would overflow the retraction: refused too. */
    assert_int_equal(se23_kalman_update(&g, &y, &out, &nis), SE23_ERR_NONFINITE);
    assert_memory_equal(&out, &out0, sizeof out);
    assert_true(nis == SE23_R(-7));
    /* Both sides of the pivot floor: a small normal R is accepted. */
    for (int r = 0; r < 3; ++r) {
        y.R[M * r + r] = tiny;
        y.z[r] = SE23_R(1e-16) * tiny / huge;
    }
    assert_int_equal(se23_kalman_update(&g0, &y, &out, &nis), SE23_OK);
    assert_true(isfinite((double)nis));
}

/* D2 (issue 12): the retraction re-orthonormalises R. An R that passes the
 * rotation test at 0.9 of the tolerance comes back at rounding level, and
 * the next prediction accepts it. */
static void test_kalman_update_keeps_rotation_valid(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 807);
    se23_gauss_t g, out;
    se23_meas_t y;
    gt_random_gauss(&rng, 15, &g);
    /* R diag(1 + d, 1 - d, 1): R^T R - I = diag(2d, -2d, 0) (to d^2),
     * det = 1 - d^2. */
    const double d = 0.45 * (double)SE23_CFG_ROT_TOL;
    for (int i = 0; i < 3; ++i) {
        g.T.R.m[i][0] = (se23_real_t)((double)g.T.R.m[i][0] * (1.0 + d));
        g.T.R.m[i][1] = (se23_real_t)((double)g.T.R.m[i][1] * (1.0 - d));
    }
    assert_int_equal(se23_so3_check(&g.T.R), SE23_OK);
    const se23_vec3_t p = {{SE23_R(1), SE23_R(-2), SE23_R(0.5)}}, lever = {{SE23_R(0.3), 0, 0}};
    const se23_mat3_t cov = {{{SE23_R(0.1), 0, 0}, {0, SE23_R(0.1), 0}, {0, 0, SE23_R(0.1)}}};
    assert_int_equal(se23_meas_pos_nav(&g.T, &p, &lever, &cov, &y), SE23_OK);
    assert_int_equal(se23_kalman_update(&g, &y, &out, NULL), SE23_OK);
    double worst = 0;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double s = (i == j) ? -1.0 : 0.0;
            for (int k = 0; k < 3; ++k) {
                s += (double)out.T.R.m[k][i] * (double)out.T.R.m[k][j];
            }
            worst = fmax(worst, fabs(s));
        }
    }
    assert_true(worst <= 16.0 * SE23T_EPS);
    assert_int_equal(se23_so3_check(&out.T.R), SE23_OK);
    se23_earth_model_t model;
    const se23_vec3_t g_n = {{0, 0, SE23_R(9.81)}}, zero = {{0}};
    assert_int_equal(se23_earth_model_init(&g_n, &zero, SE23_R(0.01), SE23_R(0.01), &model), SE23_OK);
    const se23_imu_sample_t s = {{{SE23_R(0.1), 0, 0}}, {{0, 0, SE23_R(-9.81)}}, SE23_R(0.01)};
    assert_int_equal(se23_gauss_predict(&model, &out, &s, &KF_NOISE, SE23_INPUT_JAC_EXACT, &out),
                     SE23_OK);
    assert_int_equal(se23_gauss_check(&out), SE23_OK);
}

/* Smallest eigenvalue of the leading n x n block of a symmetric A (stride
 * S), by cyclic Jacobi in double. */
static double min_eigenvalue(const se23_real_t *A, int n)
{
    double a[S][S];
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            a[i][j] = (double)A[S * i + j];
        }
    }
    for (int sweep = 0; sweep < 30; ++sweep) {
        double off = 0;
        for (int p = 0; p < n; ++p) {
            for (int q = p + 1; q < n; ++q) {
                off += a[p][q] * a[p][q];
            }
        }
        if (off < 1e-300) {
            break;
        }
        for (int p = 0; p < n; ++p) {
            for (int q = p + 1; q < n; ++q) {
                if (fabs(a[p][q]) < 1e-300) {
                    continue;
                }
                const double th = 0.5 * (a[q][q] - a[p][p]) / a[p][q];
                const double t = (th >= 0 ? 1.0 : -1.0) / (fabs(th) + sqrt(th * th + 1.0));
                const double c = 1.0 / sqrt(t * t + 1.0), sn = t * c;
                for (int k = 0; k < n; ++k) {
                    const double akp = a[k][p], akq = a[k][q];
                    a[k][p] = c * akp - sn * akq;
                    a[k][q] = sn * akp + c * akq;
                }
                for (int k = 0; k < n; ++k) {
                    const double apk = a[p][k], aqk = a[q][k];
                    a[p][k] = c * apk - sn * aqk;
                    a[q][k] = sn * apk + c * aqk;
                }
            }
        }
    }
    double lo = a[0][0];
    for (int i = 1; i < n; ++i) {
        lo = fmin(lo, a[i][i]);
    }
    return lo;
}

/* The update form keeps P PSD: thousands of GNSS-like updates with a
 * measurement noise far below the prior (R = 1e-12 of the largest variance
 * in double, 1e-6 = 8 eps in float), at varying attitude and lever arm,
 * interleaved with velocity updates; every P passes se23_gauss_check and
 * its smallest eigenvalue stays above -tol max_i P_ii. */
static void test_kalman_update_keeps_p_psd_with_tiny_noise(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 808);
    se23_gauss_t g;
    gt_random_gauss(&rng, 15, &g);
    gt_random_cov(&rng, 15, 15, S, 1.0, 1e-2, g.P.m);
#if SE23_CFG_DOUBLE
    const double rel = 1e-12;
#else
    const double rel = 1e-6;
#endif
    double worst = INFINITY;
    for (int k = 0; k < 3000; ++k) {
        se23_pose_t T;
        se23_vec3_t p, lever;
        se23t_random_pose(&rng, 10.0, &T);
        g.T.R = T.R;
        se23t_random_vec3(&rng, 0.01, &p);
        se23t_random_vec3(&rng, 1.0, &lever);
        double s = 0;
        for (int i = 0; i < 15; ++i) {
            s = fmax(s, (double)g.P.m[S * i + i]);
        }
        const se23_real_t r = (se23_real_t)(rel * s);
        const se23_mat3_t cov = {{{r, 0, 0}, {0, r, 0}, {0, 0, r}}};
        se23_meas_t y;
        for (int i = 0; i < 3; ++i) {
            p.v[i] += g.T.p.v[i];
        }
        if (k % 3 == 2) {
            assert_int_equal(se23_meas_vel_nav(&g.T, &g.T.v, &cov, &y), SE23_OK);
        } else {
            assert_int_equal(se23_meas_pos_nav(&g.T, &p, &lever, &cov, &y), SE23_OK);
        }
        assert_int_equal(se23_kalman_update(&g, &y, &g, NULL), SE23_OK);
        assert_int_equal(se23_gauss_check(&g), SE23_OK);
        if (k % 100 == 99) {
            /* Re-inflate, as a prediction would, so that updates keep acting. */
            for (int i = 0; i < 15; ++i) {
                g.P.m[S * i + i] += SE23_R(1e-2);
            }
        }
        if (k % 10 == 0) {
            double smax = 0;
            for (int i = 0; i < 15; ++i) {
                smax = fmax(smax, (double)g.P.m[S * i + i]);
            }
            const double lo = min_eigenvalue(g.P.m, 15) / smax;
            worst = fmin(worst, lo);
            assert_true(lo >= -(double)SE23_CFG_COV_TOL);
        }
    }
    print_message("smallest eigenvalue / max P_ii over 3000 updates: %.3g (tol %.1g)\n", worst,
                  (double)SE23_CFG_COV_TOL);
}

/* A precise measurement on a vague prior (issue 37, S5): position 1-sigma
 * 1 km and a 1 cm fix in float, 10 km and 1 um in double, a prior-to-R
 * ratio of 1e10 / 1e20, beyond 1/eps. The Schur complement alone left
 * P(6,6) = -0.125 (float) and -1.5e-8 (double); the posterior must be the
 * exact one, R P / (P + R) (the prior is diagonal, so each axis is a
 * scalar update), within the refined form's bound (kalman_halves.c: the
 * error eps |G| |P| ~ eps^2 P, relative eps^2 P / R, plus rounding), the
 * other variances untouched, and the state must pass se23_gauss_check. A
 * velocity correlated with the position, nu = c rho + w (var w = 1e-2, as
 * after a prediction), keeps P+ PSD; such a state keeps the Schur
 * complement's error, eps P_nunu (kalman_halves.c), so c^2 var_p is 16 var
 * w, within what float carries (the filter refuses an update it cannot
 * honour: test_ins_precision). */
static void test_kalman_update_precise_fix_on_vague_prior(void **state)
{
    (void)state;
#if SE23_CFG_DOUBLE
    const double var_p = 1e8, var_r = 1e-12;
#else
    const double var_p = 1e6, var_r = 1e-4;
#endif
    for (int correlated = 0; correlated <= 1; ++correlated) {
        se23_gauss_t g;
        memset(&g, 0, sizeof g);
        g.n = 15;
        g.T.R = (se23_mat3_t){{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
        for (int i = 0; i < 15; ++i) {
            g.P.m[S * i + i] = SE23_R(1e-2);
        }
        for (int i = 6; i < 9; ++i) {
            g.P.m[S * i + i] = (se23_real_t)var_p;
            if (correlated) {
                const double c = sqrt(16e-2 / var_p);
                g.P.m[S * (i - 3) + (i - 3)] = (se23_real_t)(c * c * var_p + 1e-2);
                g.P.m[S * (i - 3) + i] = (se23_real_t)(c * var_p);
                g.P.m[S * i + (i - 3)] = (se23_real_t)(c * var_p);
            }
        }
        assert_int_equal(se23_gauss_check(&g), SE23_OK);
        const se23_real_t r = (se23_real_t)var_r;
        const se23_mat3_t cov = {{{r, 0, 0}, {0, r, 0}, {0, 0, r}}};
        const se23_vec3_t p = {{1, 2, 3}}, lever = {{0, 0, 0}};
        se23_meas_t y;
        assert_int_equal(se23_meas_pos_nav(&g.T, &p, &lever, &cov, &y), SE23_OK);
        assert_int_equal(se23_kalman_update(&g, &y, &g, NULL), SE23_OK);
        assert_int_equal(se23_gauss_check(&g), SE23_OK);
        const double want = var_r * var_p / (var_p + var_r);
        const double rel = 16.0 * SE23T_EPS + 4.0 * SE23T_EPS * SE23T_EPS * var_p / var_r;
        for (int i = 6; i < 9; ++i) {
            assert_near((double)g.P.m[S * i + i], want, 0.0, rel);
        }
        if (correlated) {
            /* nu given rho: the independent 0.1 m/s, and P+ PSD */
            assert_near((double)g.P.m[S * 3 + 3], 1e-2, 0.0, 1e-3);
            assert_true(min_eigenvalue(g.P.m, 15) >= -(double)SE23_CFG_COV_TOL * 1e-2);
        } else {
            assert_true((double)g.P.m[S * 3 + 3] == (double)SE23_R(1e-2));
        }
    }
}

/* The structure scan: zero blocks of H are skipped, so an H with only the
 * rho block nonzero gives the same update as the dense formulas (covered
 * above); here every single-block H and the all-zero H (S = R, P
 * unchanged, dx = 0). */
static void test_kalman_update_structure_blocks(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 809);
    se23_gauss_t g, a, b;
    gt_random_gauss(&rng, 15, &g);
    for (int blk = -1; blk < 5; ++blk) {
        se23_meas_t y, yd;
        random_meas(&rng, 4, &y);
        for (int r = 0; r < 4; ++r) {
            for (int j = 0; j < S; ++j) {
                if (j / 3 != blk) {
                    y.H[S * r + j] = SE23_R(0);
                }
            }
        }
        /* yd: the same H with denormal-free tiny entries in the zero
         * blocks would take the dense path; compare with P's reference. */
        yd = y;
        se23_real_t nis_a, nis_b;
        assert_int_equal(se23_kalman_update(&g, &y, &a, &nis_a), SE23_OK);
        if (blk < 0) {
            for (int i = 0; i < S * S; ++i) {
                assert_true(a.P.m[i] == g.P.m[i]);
            }
            assert_memory_equal(&a.b_g, &g.b_g, sizeof a.b_g);
        }
        for (int r = 0; r < 4; ++r) {
            yd.H[S * r + ((blk + 1) % 5) * 3] = SE23_R(1e-30);
        }
        assert_int_equal(se23_kalman_update(&g, &yd, &b, &nis_b), SE23_OK);
        assert_near(nis_a, nis_b, 1e3 * SE23T_EPS, 1e3 * SE23T_EPS);
        for (int i = 0; i < S * S; ++i) {
            assert_near(a.P.m[i], b.P.m[i], 1e3 * SE23T_EPS, 1e3 * SE23T_EPS);
        }
    }
}

/* The work-area variant is the same computation: equal bits (state and
 * NIS) for every m with a work area full of NaN (0xff bytes) or of zeros,
 * and on a refused measurement the same status, out and nis untouched. */
static void test_kalman_update_work_equals_update_bit_for_bit(void **state)
{
    (void)state;
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 810);
    se23_kalman_work_t w;
    for (int rep = 0; rep < 18; ++rep) {
        const int n = (rep % 2) ? 15 : 9;
        const int m = 1 + rep % 9;
        se23_gauss_t g, out, ref;
        se23_meas_t y;
        se23_real_t nis = SE23_R(-1), nis_ref = SE23_R(-2);
        gt_random_gauss(&rng, n, &g);
        random_meas(&rng, m, &y);
        memset(&w, (rep < 9) ? 0xff : 0x00, sizeof w);
        memset(&out, SENTINEL, sizeof out);
        memset(&ref, SENTINEL, sizeof ref);
        assert_int_equal(se23_kalman_update(&g, &y, &ref, &nis_ref), SE23_OK);
        assert_int_equal(se23_kalman_update_work(&g, &y, &w, &out, &nis), SE23_OK);
        assert_memory_equal(&out, &ref, sizeof out);
        assert_memory_equal(&nis, &nis_ref, sizeof nis);
        y.z[m - 1] = (se23_real_t)NAN;
        assert_int_equal(se23_kalman_update_work(&g, &y, &w, &out, &nis), SE23_ERR_NONFINITE);
        assert_memory_equal(&out, &ref, sizeof out);
        assert_memory_equal(&nis, &nis_ref, sizeof nis);
    }
}

static void test_kalman_null_arguments_return_err_null(void **state)
{
    (void)state;
#if SE23_CFG_ARG_CHECKS
    se23_gauss_t g;
    se23_meas_t y;
    memset(&g, 0, sizeof g);
    memset(&y, 0, sizeof y);
    assert_int_equal(se23_kalman_update(NULL, &y, &g, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_kalman_update(&g, NULL, &g, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_kalman_update(&g, &y, NULL, NULL), SE23_ERR_NULL);
    se23_kalman_work_t w;
    assert_int_equal(se23_kalman_update_work(NULL, &y, &w, &g, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_kalman_update_work(&g, NULL, &w, &g, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_kalman_update_work(&g, &y, NULL, &g, NULL), SE23_ERR_NULL);
    assert_int_equal(se23_kalman_update_work(&g, &y, &w, NULL, NULL), SE23_ERR_NULL);
#else
    skip();
#endif
}

/* ------------------------------------------------------------ the filter */

#define KF_RUNS 100
#define KF_DT 0.1
#define KF_STEPS 200   /* 20 s */
#define KF_GNSS_EVERY 5 /* 2 Hz */
#define KF_GNSS_SD 0.3

static const se23_imu_noise_t KF_NOISE = {SE23_R(2e-4), SE23_R(2e-3),
                                          SE23_R(1e-5), SE23_R(1e-4)};
/* Prior std: attitude, velocity, position, gyro bias, accel bias. */
static const double KF_SD0[15] = {0.01, 0.01, 0.05, 0.2, 0.2, 0.2, 1.0, 1.0, 1.0,
                                  0.005, 0.005, 0.005, 0.1, 0.1, 0.1};

/* True inputs at step k for the true state T: a weaving, climbing path
 * (nav-frame acceleration a_n, so f = R^T (a_n - g)) and a varying rate. */
static void kf_truth_inputs(int k, const se23_pose_t *T, const se23_vec3_t *g_n,
                            se23_vec3_t *w, se23_vec3_t *f)
{
    const double t = k * KF_DT;
    w->v[0] = (se23_real_t)(0.3 * sin(0.5 * t));
    w->v[1] = (se23_real_t)(0.3 * cos(0.7 * t));
    w->v[2] = (se23_real_t)(0.4 + 0.3 * sin(0.3 * t));
    se23_vec3_t a;
    a.v[0] = (se23_real_t)(2.0 * sin(0.4 * t) - (double)g_n->v[0]);
    a.v[1] = (se23_real_t)(2.0 * cos(0.3 * t) - (double)g_n->v[1]);
    a.v[2] = (se23_real_t)(0.5 * sin(0.5 * t) - (double)g_n->v[2]);
    for (int i = 0; i < 3; ++i) {
        f->v[i] = T->R.m[0][i] * a.v[0] + T->R.m[1][i] * a.v[1] + T->R.m[2][i] * a.v[2];
    }
}

static void normalize(se23_pose_t *T)
{
    assert_int_equal(se23_so3_normalize(&T->R, &T->R), SE23_OK);
}

/* One run: returns the final 15-dim NEES and the final bias errors and stds. */
static double kf_run(se23t_rng_t *rng, const se23_earth_model_t *model,
                     double berr[6], double bsd[6])
{
    double L0[225] = {0}, x0[15];
    for (int i = 0; i < 15; ++i) {
        L0[15 * i + i] = KF_SD0[i];
    }
    gt_sample(rng, L0, 15, x0);
    se23_gauss_t g;
    memset(&g, 0, sizeof g);
    g.n = 15;
    se23_identity(&g.T);
    g.T.v.v[0] = SE23_R(5);
    for (int i = 0; i < 15; ++i) {
        g.P.m[S * i + i] = (se23_real_t)(KF_SD0[i] * KF_SD0[i]);
    }
    /* Truth: T = Tbar exp(xi0), b = bbar + db0 (bbar = 0). */
    se23_tangent_t xi;
    se23_pose_t E, T;
    for (int i = 0; i < 9; ++i) {
        xi.v[i] = (se23_real_t)x0[i];
    }
    assert_int_equal(se23_exp(&xi, &E), SE23_OK);
    se23_compose(&g.T, &E, &T);
    double b[6];
    for (int i = 0; i < 6; ++i) {
        b[i] = x0[9 + i];
    }
    const double sg = KF_NOISE.gyro_noise / sqrt(KF_DT), sa = KF_NOISE.accel_noise / sqrt(KF_DT);
    const double wg = KF_NOISE.gyro_walk * sqrt(KF_DT), wa = KF_NOISE.accel_walk * sqrt(KF_DT);
    const se23_mat3_t cov = {{{SE23_R(KF_GNSS_SD * KF_GNSS_SD), 0, 0},
                              {0, SE23_R(KF_GNSS_SD * KF_GNSS_SD), 0},
                              {0, 0, SE23_R(KF_GNSS_SD * KF_GNSS_SD)}}};
    const se23_vec3_t lever = {{0}};
    for (int k = 0; k < KF_STEPS; ++k) {
        se23_imu_sample_t truth, meas;
        kf_truth_inputs(k, &T, &model->g_n, &truth.w_ib_b, &truth.f_b);
        truth.dt = meas.dt = SE23_R(KF_DT);
        /* The IMU reads w - b - eta (paper section 3.3). */
        for (int i = 0; i < 3; ++i) {
            meas.w_ib_b.v[i] = (se23_real_t)((double)truth.w_ib_b.v[i] - b[i] - sg * se23t_normal(rng));
            meas.f_b.v[i] = (se23_real_t)((double)truth.f_b.v[i] - b[3 + i] - sa * se23t_normal(rng));
        }
        assert_int_equal(se23_imu_step(model, &T, &truth, &T), SE23_OK);
        assert_int_equal(se23_gauss_predict(model, &g, &meas, &KF_NOISE, SE23_INPUT_JAC_EXACT, &g), SE23_OK);
        for (int i = 0; i < 3; ++i) {
            b[i] += wg * se23t_normal(rng);
            b[3 + i] += wa * se23t_normal(rng);
        }
        if ((k + 1) % KF_GNSS_EVERY == 0) {
            se23_vec3_t p;
            for (int i = 0; i < 3; ++i) {
                p.v[i] = (se23_real_t)((double)T.p.v[i] + KF_GNSS_SD * se23t_normal(rng));
            }
            se23_meas_t y;
            assert_int_equal(se23_meas_pos_nav(&g.T, &p, &lever, &cov, &y), SE23_OK);
            assert_int_equal(se23_kalman_update(&g, &y, &g, NULL), SE23_OK);
            normalize(&T);
            normalize(&g.T);
        }
    }
    /* e = (log(Tbar^-1 T), b - bbar). */
    se23_pose_t Ti, D;
    se23_inverse(&g.T, &Ti);
    se23_compose(&Ti, &T, &D);
    assert_int_equal(se23_log(&D, &xi), SE23_OK);
    double e[15], P[225], L[225];
    for (int i = 0; i < 9; ++i) {
        e[i] = (double)xi.v[i];
    }
    for (int i = 0; i < 3; ++i) {
        e[9 + i] = b[i] - (double)g.b_g.v[i];
        e[12 + i] = b[3 + i] - (double)g.b_a.v[i];
    }
    for (int i = 0; i < 225; ++i) {
        P[i] = (double)g.P.m[S * (i / 15) + i % 15];
    }
    assert_true(gt_chol(P, 15, L));
    for (int i = 0; i < 6; ++i) {
        berr[i] = e[9 + i];
        bsd[i] = sqrt(P[15 * (9 + i) + 9 + i]);
    }
    return gt_nees(L, 15, e);
}

static void test_kalman_filter_estimates_biases_consistently(void **state)
{
    (void)state;
    se23_earth_model_t model;
    const se23_vec3_t g_n = {{0, 0, SE23_R(9.81)}}, zero = {{0}};
    assert_int_equal(se23_earth_model_init(&g_n, &zero, SE23_R(KF_DT), SE23_R(KF_DT), &model), SE23_OK);
    se23t_rng_t rng;
    se23t_rng_seed(&rng, 804);
    double nees = 0, ms[6] = {0}, sd[6] = {0};
    for (int r = 0; r < KF_RUNS; ++r) {
        double berr[6], bsd[6];
        nees += kf_run(&rng, &model, berr, bsd) / KF_RUNS;
        for (int i = 0; i < 6; ++i) {
            ms[i] += berr[i] * berr[i] / KF_RUNS;
            sd[i] += bsd[i] / KF_RUNS;
        }
    }
    double lo, hi;
    gt_chi2_mean_interval(15, KF_RUNS, &lo, &hi);
    print_message("15-state filter: mean NEES %.3f over %d runs, 95%% interval [%.3f, %.3f]\n",
                  nees, KF_RUNS, lo, hi);
    for (int i = 0; i < 6; ++i) {
        print_message("  bias %s%c: prior std %.2e, filter std %.2e, RMS error %.2e\n",
                      i < 3 ? "gyro " : "accel ", "xyz"[i % 3], KF_SD0[9 + i], sd[i], sqrt(ms[i]));
    }
    for (int i = 0; i < 6; ++i) {
        /* Estimated: the error shrinks well below the prior. */
        assert_true(sqrt(ms[i]) < 0.5 * KF_SD0[9 + i]);
    }
    assert_true(nees > lo && nees < hi);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_kalman_update_matches_dense_formulas),
        cmocka_unit_test(test_kalman_update_ignores_bias_columns_when_n_is_9),
        cmocka_unit_test(test_kalman_update_rejects_bad_input_untouched),
        cmocka_unit_test(test_kalman_update_refuses_overflowing_results),
        cmocka_unit_test(test_kalman_update_keeps_rotation_valid),
        cmocka_unit_test(test_kalman_update_keeps_p_psd_with_tiny_noise),
        cmocka_unit_test(test_kalman_update_precise_fix_on_vague_prior),
        cmocka_unit_test(test_kalman_update_structure_blocks),
        cmocka_unit_test(test_kalman_update_work_equals_update_bit_for_bit),
        cmocka_unit_test(test_kalman_null_arguments_return_err_null),
        cmocka_unit_test(test_kalman_filter_estimates_biases_consistently),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
