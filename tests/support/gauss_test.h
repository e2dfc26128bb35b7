/**
 * @file gauss_test.h
 * @brief Helpers of the uncertainty tests (test_cov, test_gauss,
 *        test_input_jac, test_meas, test_kalman), header-only: a double
 *        reference of SE_2(3) written from the math (5x5 matrix exponential
 *        by scaling and squaring, logarithm near the identity by its
 *        series, the exact IMU increment as the exponential of the
 *        augmented 5x5 matrix), Cholesky, sampling and NEES in double, and
 *        the chi^2 interval of a mean NEES. Independent of the library code
 *        under test.
 */
#ifndef SE23_GAUSS_TEST_H
#define SE23_GAUSS_TEST_H

#include <math.h>

#include <string.h>

#include "se23/gauss.h"
#include "se23/types.h"
#include "se23_rng.h"

typedef struct {
    double m[5][5];
} gt_m5_t;

static inline void gt_m5_mul(const gt_m5_t *A, const gt_m5_t *B, gt_m5_t *C)
{
    gt_m5_t r;
    for (int i = 0; i < 5; ++i) {
        for (int j = 0; j < 5; ++j) {
            double s = 0;
            for (int k = 0; k < 5; ++k) {
                s += A->m[i][k] * B->m[k][j];
            }
            r.m[i][j] = s;
        }
    }
    *C = r;
}

static inline void gt_m5_identity(gt_m5_t *A)
{
    for (int i = 0; i < 5; ++i) {
        for (int j = 0; j < 5; ++j) {
            A->m[i][j] = (i == j) ? 1.0 : 0.0;
        }
    }
}

/* E = exp(A): scale to norm <= 1/8, Taylor to 20 terms, square back. */
static inline void gt_expm(const gt_m5_t *A, gt_m5_t *E)
{
    double nrm = 0;
    for (int i = 0; i < 5; ++i) {
        double r = 0;
        for (int j = 0; j < 5; ++j) {
            r += fabs(A->m[i][j]);
        }
        nrm = fmax(nrm, r);
    }
    int sq = 0;
    double scale = 1;
    while (nrm * scale > 0.125) {
        scale *= 0.5;
        ++sq;
    }
    gt_m5_t X, term, sum;
    for (int i = 0; i < 5; ++i) {
        for (int j = 0; j < 5; ++j) {
            X.m[i][j] = A->m[i][j] * scale;
        }
    }
    gt_m5_identity(&sum);
    gt_m5_identity(&term);
    for (int k = 1; k <= 20; ++k) {
        gt_m5_mul(&term, &X, &term);
        for (int i = 0; i < 5; ++i) {
            for (int j = 0; j < 5; ++j) {
                term.m[i][j] /= k;
                sum.m[i][j] += term.m[i][j];
            }
        }
    }
    for (int s = 0; s < sq; ++s) {
        gt_m5_mul(&sum, &sum, &sum);
    }
    *E = sum;
}

/* L = log(X) for X near the identity (|X - I| < 0.1): the Mercator series. */
static inline void gt_logm_near_identity(const gt_m5_t *X, gt_m5_t *L)
{
    gt_m5_t D, P, sum = {{{0}}};
    for (int i = 0; i < 5; ++i) {
        for (int j = 0; j < 5; ++j) {
            D.m[i][j] = X->m[i][j] - (i == j ? 1.0 : 0.0);
        }
    }
    P = D;
    for (int k = 1; k <= 40; ++k) {
        const double c = ((k % 2) ? 1.0 : -1.0) / k;
        for (int i = 0; i < 5; ++i) {
            for (int j = 0; j < 5; ++j) {
                sum.m[i][j] += c * P.m[i][j];
            }
        }
        gt_m5_mul(&P, &D, &P);
    }
    *L = sum;
}

static inline void gt_hat(const double xi[9], gt_m5_t *X)
{
    const double *w = xi;
    gt_m5_t r = {{{0}}};
    r.m[0][1] = -w[2];
    r.m[0][2] = w[1];
    r.m[1][0] = w[2];
    r.m[1][2] = -w[0];
    r.m[2][0] = -w[1];
    r.m[2][1] = w[0];
    for (int i = 0; i < 3; ++i) {
        r.m[i][3] = xi[3 + i];
        r.m[i][4] = xi[6 + i];
    }
    *X = r;
}

static inline void gt_vee(const gt_m5_t *X, double xi[9])
{
    xi[0] = 0.5 * (X->m[2][1] - X->m[1][2]);
    xi[1] = 0.5 * (X->m[0][2] - X->m[2][0]);
    xi[2] = 0.5 * (X->m[1][0] - X->m[0][1]);
    for (int i = 0; i < 3; ++i) {
        xi[3 + i] = X->m[i][3];
        xi[6 + i] = X->m[i][4];
    }
}

static inline void gt_from_pose(const se23_pose_t *T, gt_m5_t *M)
{
    gt_m5_identity(M);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            M->m[i][j] = (double)T->R.m[i][j];
        }
        M->m[i][3] = (double)T->v.v[i];
        M->m[i][4] = (double)T->p.v[i];
    }
}

/* Ti = T^-1 for T in SE_2(3) (R^T, -R^T v, -R^T p). */
static inline void gt_inverse(const gt_m5_t *T, gt_m5_t *Ti)
{
    gt_m5_t r;
    gt_m5_identity(&r);
    for (int i = 0; i < 3; ++i) {
        double sv = 0, sp = 0;
        for (int j = 0; j < 3; ++j) {
            r.m[i][j] = T->m[j][i];
            sv -= T->m[j][i] * T->m[j][3];
            sp -= T->m[j][i] * T->m[j][4];
        }
        r.m[i][3] = sv;
        r.m[i][4] = sp;
    }
    *Ti = r;
}

/* E = exp(xi^). */
static inline void gt_exp(const double xi[9], gt_m5_t *E)
{
    gt_m5_t X;
    gt_hat(xi, &X);
    gt_expm(&X, E);
}

/* xi = log(A^-1 B) for A, B close to each other. */
static inline void gt_log_between(const gt_m5_t *A, const gt_m5_t *B, double xi[9])
{
    gt_m5_t Ai, D, L;
    gt_inverse(A, &Ai);
    gt_m5_mul(&Ai, B, &D);
    gt_logm_near_identity(&D, &L);
    gt_vee(&L, xi);
}

/* U = the exact increment: rows 0..2 of exp(dt [[w^, f, 0], [0, 0, 1], [0, 0, 0]]). */
static inline void gt_increment(const double w[3], const double f[3], double dt,
                                gt_m5_t *U)
{
    const double xi[9] = {w[0] * dt, w[1] * dt, w[2] * dt, f[0] * dt,
                          f[1] * dt, f[2] * dt, 0, 0, 0};
    gt_m5_t A;
    gt_hat(xi, &A);
    A.m[3][4] = dt;
    gt_expm(&A, U);
    U->m[3][4] = 0.0;
}

/* Lower Cholesky factor of the n x n A (stride n) in double; 0 if not PD. */
static inline int gt_chol(const double *A, int n, double *L)
{
    for (int j = 0; j < n; ++j) {
        double d = A[n * j + j];
        for (int k = 0; k < j; ++k) {
            d -= L[n * j + k] * L[n * j + k];
        }
        if (!(d > 0)) {
            return 0;
        }
        L[n * j + j] = sqrt(d);
        for (int i = j + 1; i < n; ++i) {
            double s = A[n * i + j];
            for (int k = 0; k < j; ++k) {
                s -= L[n * i + k] * L[n * j + k];
            }
            L[n * i + j] = s / L[n * j + j];
            L[n * j + i] = 0;
        }
    }
    return 1;
}

/* x = L z, z standard normal: a sample of N(0, L L^T). */
static inline void gt_sample(se23t_rng_t *rng, const double *L, int n, double *x)
{
    double z[16];
    for (int i = 0; i < n; ++i) {
        z[i] = se23t_normal(rng);
    }
    for (int i = 0; i < n; ++i) {
        double s = 0;
        for (int k = 0; k <= i; ++k) {
            s += L[n * i + k] * z[k];
        }
        x[i] = s;
    }
}

/* x^T (L L^T)^-1 x = |L^-1 x|^2. */
static inline double gt_nees(const double *L, int n, const double *x)
{
    double u[16], s = 0;
    for (int i = 0; i < n; ++i) {
        double r = x[i];
        for (int k = 0; k < i; ++k) {
            r -= L[n * i + k] * u[k];
        }
        u[i] = r / L[n * i + i];
        s += u[i] * u[i];
    }
    return s;
}

/* The central 95% interval of the mean of runs independent chi^2_dof
 * variables: their sum is chi^2 with k = dof runs degrees of freedom, whose
 * quantiles the Wilson-Hilferty approximation gives,
 *   q(p) = k (1 - 2/(9k) + z_p sqrt(2/(9k)))^3,  z = -+1.959964
 * (relative error below 1e-4 for k >= 100). The interval is q/runs. */
static inline void gt_chi2_mean_interval(int dof, int runs, double *lo, double *hi)
{
    const double k = (double)dof * runs, z = 1.959963984540054;
    const double a = 1.0 - 2.0 / (9.0 * k), b = sqrt(2.0 / (9.0 * k));
    *lo = k * pow(a - z * b, 3) / runs;
    *hi = k * pow(a + z * b, 3) / runs;
}

/* A = G G^T + d I, G an n x k matrix with entries scale N(0, 1) (rank k
 * when d = 0), stored with row stride `stride`, n, k <= 15. */
static inline void gt_random_cov(se23t_rng_t *rng, int n, int k, int stride,
                                 double scale, double d, se23_real_t *A)
{
    double G[SE23_GAUSS_NMAX * SE23_GAUSS_NMAX];
    for (int i = 0; i < n * k; ++i) {
        G[i] = scale * se23t_normal(rng);
    }
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            double s = (i == j) ? d : 0.0;
            for (int r = 0; r < k; ++r) {
                s += G[k * i + r] * G[k * j + r];
            }
            A[stride * i + j] = (se23_real_t)s;
        }
    }
}

/* A random valid filter state of dimension n (unused storage zeroed). */
static inline void gt_random_gauss(se23t_rng_t *rng, int n, se23_gauss_t *g)
{
    memset(g, 0, sizeof *g);
    se23t_random_pose(rng, 10.0, &g->T);
    se23t_random_vec3(rng, 0.01, &g->b_g);
    se23t_random_vec3(rng, 0.1, &g->b_a);
    g->n = n;
    gt_random_cov(rng, n, n, SE23_GAUSS_NMAX, 0.1, 1e-3, g->P.m);
}

#endif /* SE23_GAUSS_TEST_H */
