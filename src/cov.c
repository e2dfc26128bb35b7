/* Covariance checks, Cholesky, congruence; see cov.h. */
#include "cov.h"

#include <float.h>

#include "linalg.h"
#include "se23_math.h"

#if SE23_CFG_DOUBLE
#define EPS SE23_R(DBL_EPSILON)
#else
#define EPS SE23_R(FLT_EPSILON)
#endif
/* Pivots must exceed PIVOT_EPS (A_jj + shift). */
#define PIVOT_EPS (SE23_R(16) * EPS)
/* Added to the PSD shift so that the zero matrix passes. */
#define TINY SE23_R(FLT_MIN)

int se23_cov_chol(const se23_real_t *A, int n, int stride, se23_real_t shift,
                  se23_real_t *L)
{
    for (int j = 0; j < n; ++j) {
        se23_real_t d = A[stride * j + j] + shift;
        const se23_real_t pmin = PIVOT_EPS * d;
        for (int k = 0; k < j; ++k) {
            d -= L[n * j + k] * L[n * j + k];
        }
        if (!(d > pmin) || !se23_is_finite(d)) {
            return 0;
        }
        const se23_real_t ljj = se23_sqrt(d);
        L[n * j + j] = ljj;
        for (int i = j + 1; i < n; ++i) {
            se23_real_t s = A[stride * i + j];
            for (int k = 0; k < j; ++k) {
                s -= L[n * i + k] * L[n * j + k];
            }
            L[n * i + j] = s / ljj;
            L[n * j + i] = SE23_R(0);
        }
    }
    return 1;
}

void se23_cov_chol_solve(const se23_real_t *L, int n, se23_real_t *x)
{
    for (int i = 0; i < n; ++i) {
        se23_real_t s = x[i];
        for (int k = 0; k < i; ++k) {
            s -= L[n * i + k] * x[k];
        }
        x[i] = s / L[n * i + i];
    }
    for (int i = n - 1; i >= 0; --i) {
        se23_real_t s = x[i];
        for (int k = i + 1; k < n; ++k) {
            s -= L[n * k + i] * x[k];
        }
        x[i] = s / L[n * i + i];
    }
}

se23_status_t se23_cov_check(const se23_real_t *A, int n, int stride)
{
    se23_real_t s = SE23_R(0);
    for (int i = 0; i < n; ++i) {
        if (!se23_all_finite(&A[stride * i], n)) {
            return SE23_ERR_NONFINITE;
        }
        const se23_real_t d = se23_fabs(A[stride * i + i]);
        s = (d > s) ? d : s;
    }
    const se23_real_t tol = SE23_R(SE23_CFG_COV_TOL) * s;
    for (int i = 0; i < n; ++i) {
        for (int j = i + 1; j < n; ++j) {
            if (se23_fabs(A[stride * i + j] - A[stride * j + i]) > tol) {
                return SE23_ERR_NOT_SYMMETRIC;
            }
        }
    }
    se23_real_t L[SE23_COV_NMAX * SE23_COV_NMAX];
    if (!se23_cov_chol(A, n, stride, tol + TINY, L)) {
        return SE23_ERR_NOT_PSD;
    }
    return SE23_OK;
}

void se23_cov_congruence(se23_cov_map_fn map, const void *ctx, int n,
                         const se23_real_t *P, se23_real_t *out)
{
    enum { S = SE23_COV_NMAX };
    se23_real_t W[S * S]; /* W = A P, column by column */
    se23_real_t x[S], y[S];
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            x[i] = P[S * i + j];
        }
        map(ctx, x, y);
        for (int i = 0; i < n; ++i) {
            W[S * i + j] = y[i];
        }
    }
    /* P is no longer read: column i of A W^T = A (row i of W) goes straight
     * to out, rows 0..i (upper triangle), then the mirror. */
    for (int i = 0; i < n; ++i) {
        map(ctx, &W[S * i], y);
        for (int r = 0; r <= i; ++r) {
            out[S * r + i] = y[r];
        }
    }
    for (int i = 0; i < n; ++i) {
        for (int j = i + 1; j < n; ++j) {
            out[S * j + i] = out[S * i + j];
        }
    }
}
