/* Kalman update in exponential coordinates; see kalman.h. */
#include "se23/kalman.h"

#include "argcheck.h"
#include "cov.h"
#include "linalg.h"
#include "se23/se23.h"

enum { S = SE23_GAUSS_NMAX, M = SE23_MEAS_MMAX };

/* x -> (I - K H) x on R^n; K n x m (stride M), H m x n (stride S). */
typedef struct {
    const se23_real_t *K;
    const se23_real_t *H;
    int n, m;
} joseph_ctx_t;

static void joseph_map(const void *ctx, const se23_real_t *x, se23_real_t *y)
{
    const joseph_ctx_t *c = (const joseph_ctx_t *)ctx;
    se23_real_t hx[M];
    for (int r = 0; r < c->m; ++r) {
        se23_real_t s = SE23_R(0);
        for (int j = 0; j < c->n; ++j) {
            s += c->H[S * r + j] * x[j];
        }
        hx[r] = s;
    }
    for (int i = 0; i < c->n; ++i) {
        se23_real_t s = x[i];
        for (int r = 0; r < c->m; ++r) {
            s -= c->K[M * i + r] * hx[r];
        }
        y[i] = s;
    }
}

static se23_status_t check_meas(const se23_meas_t *y, int n)
{
    const int m = y->m;
    if (m < 1 || m > M) {
        return SE23_ERR_DIM;
    }
    if (!se23_all_finite(y->z, m)) {
        return SE23_ERR_NONFINITE;
    }
    for (int r = 0; r < m; ++r) {
        if (!se23_all_finite(&y->H[S * r], n)) {
            return SE23_ERR_NONFINITE;
        }
    }
    return se23_cov_check(y->R, m, M);
}

/* PHt = P H^T (n x m, stride M) and Sm = H PHt + R (m x m, stride M,
 * upper triangle computed and mirrored). */
static void innovation_cov(const se23_real_t *P, const se23_meas_t *y, int n,
                           se23_real_t *PHt, se23_real_t *Sm)
{
    const int m = y->m;
    for (int i = 0; i < n; ++i) {
        for (int r = 0; r < m; ++r) {
            se23_real_t s = SE23_R(0);
            for (int j = 0; j < n; ++j) {
                s += P[S * i + j] * y->H[S * r + j];
            }
            PHt[M * i + r] = s;
        }
    }
    for (int r = 0; r < m; ++r) {
        for (int q = r; q < m; ++q) {
            se23_real_t s = y->R[M * r + q];
            for (int j = 0; j < n; ++j) {
                s += y->H[S * r + j] * PHt[M * j + q];
            }
            Sm[M * r + q] = s;
            Sm[M * q + r] = s;
        }
    }
}

/* K = P H^T S^-1 row by row, in place over PHt (S symmetric, factor L),
 * and dx = K z. */
static void gain(se23_real_t *K, const se23_real_t *L, const se23_meas_t *y,
                 int n, se23_real_t *dx)
{
    const int m = y->m;
    for (int i = 0; i < n; ++i) {
        se23_cov_chol_solve(L, m, &K[M * i]);
        dx[i] = SE23_R(0);
        for (int r = 0; r < m; ++r) {
            dx[i] += K[M * i + r] * y->z[r];
        }
    }
}

/* z^T S^-1 z. */
static se23_real_t nis_of(const se23_real_t *L, const se23_meas_t *y)
{
    se23_real_t u[M], s = SE23_R(0);
    for (int r = 0; r < y->m; ++r) {
        u[r] = y->z[r];
    }
    se23_cov_chol_solve(L, y->m, u);
    for (int r = 0; r < y->m; ++r) {
        s += u[r] * y->z[r];
    }
    return s;
}

/* Pout = (I - K H) P (I - K H)^T + K R K^T, exactly symmetric; Pout may
 * alias P. */
static void joseph(const se23_real_t *P, const se23_real_t *K,
                   const se23_meas_t *y, int n, se23_real_t *Pout)
{
    const int m = y->m;
    const joseph_ctx_t ctx = {K, y->H, n, m};
    se23_cov_congruence(joseph_map, &ctx, n, P, Pout);
    for (int i = 0; i < n; ++i) {
        se23_real_t kr[M]; /* row i of K R */
        for (int q = 0; q < m; ++q) {
            se23_real_t s = SE23_R(0);
            for (int r = 0; r < m; ++r) {
                s += K[M * i + r] * y->R[M * r + q];
            }
            kr[q] = s;
        }
        for (int j = i; j < n; ++j) {
            se23_real_t s = SE23_R(0);
            for (int q = 0; q < m; ++q) {
                s += kr[q] * K[M * j + q];
            }
            Pout[S * i + j] += s;
            if (j != i) {
                Pout[S * j + i] += s;
            }
        }
    }
}

se23_status_t se23_kalman_update(const se23_gauss_t *g, const se23_meas_t *y,
                                 se23_gauss_t *out, se23_real_t *nis)
{
    SE23_CHECK_NOT_NULL(g);
    SE23_CHECK_NOT_NULL(y);
    SE23_CHECK_NOT_NULL(out);
    se23_status_t st = se23_gauss_check(g);
    if (st == SE23_OK) {
        st = check_meas(y, g->n);
    }
    if (st != SE23_OK) {
        return st;
    }
    const int n = g->n;
    se23_real_t K[S * M], Sm[M * M], L[M * M]; /* K holds P H^T first */
    se23_real_t dx[S] = {SE23_R(0)};
    innovation_cov(g->P.m, y, n, K, Sm);
    if (!se23_cov_chol(Sm, y->m, M, SE23_R(0), L)) {
        return SE23_ERR_NOT_PSD;
    }
    gain(K, L, y, n, dx);
    se23_tangent_t xi;
    se23_pose_t E, T;
    for (int i = 0; i < 9; ++i) {
        xi.v[i] = dx[i];
    }
    st = se23_exp(&xi, &E);
    if (st != SE23_OK) {
        return st;
    }
    /* Nothing fails from here on. */
    se23_compose(&g->T, &E, &T);
    if (nis != NULL) {
        *nis = nis_of(L, y);
    }
    joseph(g->P.m, K, y, n, out->P.m);
    out->b_g = g->b_g;
    out->b_a = g->b_a;
    if (n == SE23_GAUSS_N_BIAS) {
        const se23_vec3_t dg = {{dx[SE23_IDX_BG], dx[SE23_IDX_BG + 1], dx[SE23_IDX_BG + 2]}};
        const se23_vec3_t da = {{dx[SE23_IDX_BA], dx[SE23_IDX_BA + 1], dx[SE23_IDX_BA + 2]}};
        se23_v3_axpy(&g->b_g, SE23_R(1), &dg, &out->b_g);
        se23_v3_axpy(&g->b_a, SE23_R(1), &da, &out->b_a);
    }
    out->T = T;
    out->n = n;
    return SE23_OK;
}
