/* The two halves of the measurement update; see kalman_parts.h.
 *
 * Cost. Only the active 3-column blocks of H take part (a = 3 x their
 * number). With m rows and n states, in fused multiply-adds:
 *   C  = P H^T             n m a        (active columns of P and H)
 *   S  = H C + R           a m(m+1)/2   (active rows of C)
 *   L L^T = S              m^3/6, m square roots and divisions
 *   w  = L^-1 z            m^2/2;  nis = w.w, m
 *   U  = C L^-T            n m(m-1)/2, n m multiplies
 *   dx = U w, |U_i|^2      2 n m
 *   P+ = P - U U^T         m n(n+1)/2   (upper triangle, mirrored)
 * The kernels take m three rows at a time (zero padding), so m counts as
 * a multiple of 3 in the n-sized terms. GNSS position with a lever arm
 * (n = 15, m = 3, a = 6): 270 + 36 + 10 + 9 + 45 + 90 + 360 = 820
 * multiply-adds and 3 square roots; the dense Joseph form with the same
 * factorisation is about 2 n^3 + 4 n^2 m = 9,500.
 *
 * Why P+ = P - U U^T and not the Joseph form. Both equal P - C S^-1 C^T in
 * exact arithmetic for the gain K = C S^-1 computed from the same P.
 * P - U U^T is the Schur complement of S in the positive semidefinite
 *   M = [[S, C^T], [C, P]] = [H; I] P [H; I]^T + diag(R, 0),
 * i.e. exactly what a Cholesky factorisation of M leaves after its first
 * m columns. Cholesky is backward stable (Higham, Accuracy and Stability
 * of Numerical Algorithms, 2nd ed., Thm 10.3): the computed P+ is the
 * exact Schur complement of M + dM with |dM_ij| <= g (M_ii M_jj)^(1/2),
 * g = (m + 1) eps / (1 - (m + 1) eps), so its eigenvalues are above
 * -g (n + m) max_i M_ii: PSD to rounding whatever R, and no error term
 * grows with the gain. The Joseph form (I - K H) P (I - K H)^T + K R K^T
 * buys insensitivity to errors in a suboptimal K (here K is optimal to
 * rounding) at about n^2 (a + 2 m) + n m^2 = 2,900 multiply-adds even with
 * the structure, and its rounding error carries |I - K H|^2 |P|, which
 * grows with the gain (small R). P+ is symmetric by construction (upper
 * triangle computed, mirrored); test_kalman runs thousands of updates with
 * tiny R and checks the smallest eigenvalue. */
#include "kalman_parts.h"

#include <float.h>

#include "linalg.h"
#include "se23/se23.h"
#include "se23/so3.h"
#include "se23_math.h"

enum { S = SE23_GAUSS_NMAX, M = SE23_MEAS_MMAX };

#if SE23_CFG_DOUBLE
#define REAL_MAX DBL_MAX
#else
#define REAL_MAX FLT_MAX
#endif
/* P_ii <= DIAG_MAX and |U_i|^2 <= DIAG_MAX make every entry of P - U U^T
 * finite: |P_ij| <= (1 + tol) max(P_ii, P_jj) (P PSD) and
 * |U_i . U_j| <= max(|U_i|^2, |U_j|^2), partial sums included. */
#define DIAG_MAX (SE23_R(REAL_MAX) / SE23_R(4))

se23_status_t se23_meas_cov_check(const se23_real_t *A, int m, int stride)
{
    se23_real_t work[SE23_MEAS_TRI];
    return se23_cov_check_work(A, m, stride, work);
}

/* The kernels take the rows of H (the columns of C and U) three at a
 * time, the last group padded with zero rows: h_row gives row r of H or,
 * for r >= m, zero_row. */
static const se23_real_t zero_row[S] = {SE23_R(0)};

static const se23_real_t *h_row(const se23_meas_t *y, int r)
{
    return (r < y->m) ? &y->H[S * r] : zero_row;
}

/* Columns of C and U: m rounded up to a multiple of 3 (<= M). */
static int padded(int m)
{
    return 3 * ((m + 2) / 3);
}

/* C = P H^T over the active blocks: n x padded(m), (i, r) at C[M i + r],
 * padding columns 0. Per group of three rows of H and active block, the
 * 3x3 block of H stays in registers while P's 3-column block streams by
 * (9 multiply-adds per row): n m a in all. The first block starts from
 * zero_row (stride 0) instead of C, so C needs no clearing. */
static void cross_cov(const se23_real_t *P, const se23_meas_t *y, int n,
                      const int *blk, int nb, se23_real_t *C)
{
    const int mp = padded(y->m);
    for (int g = 0; g < mp; g += 3) {
        const se23_real_t *h0 = h_row(y, g), *h1 = h_row(y, g + 1), *h2 = h_row(y, g + 2);
        for (int k = 0; k < nb; ++k) {
            const int j = 3 * blk[k];
            const se23_real_t a00 = h0[j], a01 = h0[j + 1], a02 = h0[j + 2];
            const se23_real_t a10 = h1[j], a11 = h1[j + 1], a12 = h1[j + 2];
            const se23_real_t a20 = h2[j], a21 = h2[j + 1], a22 = h2[j + 2];
            const se23_real_t *acc = (k == 0) ? zero_row : &C[g];
            const int acc_stride = (k == 0) ? 0 : M;
            for (int i = 0; i < n; ++i) {
                const se23_real_t *p = &P[S * i + j], *c0 = &acc[acc_stride * i];
                const se23_real_t p0 = p[0], p1 = p[1], p2 = p[2];
                const se23_real_t r0 = se23_fma(a02, p2, se23_fma(a01, p1, se23_fma(a00, p0, c0[0])));
                const se23_real_t r1 = se23_fma(a12, p2, se23_fma(a11, p1, se23_fma(a10, p0, c0[1])));
                const se23_real_t r2 = se23_fma(a22, p2, se23_fma(a21, p1, se23_fma(a20, p0, c0[2])));
                se23_real_t *c = &C[M * i + g];
                c[0] = r0;
                c[1] = r1;
                c[2] = r2;
            }
        }
        if (nb == 0) {
            for (int i = 0; i < n; ++i) {
                for (int r = g; r < g + 3; ++r) {
                    C[M * i + r] = SE23_R(0);
                }
            }
        }
    }
}

/* Packed lower triangle of S = H C + R, reading the active rows of C and
 * the upper triangle of R: a m(m+1)/2 multiply-adds. */
static void innovation_cov(const se23_meas_t *y, const int *blk, int nb,
                           const se23_real_t *C, se23_real_t *L)
{
    for (int q = 0; q < y->m; ++q) {
        se23_real_t *lq = &L[SE23_COV_TRI(q)];
        for (int r = 0; r <= q; ++r) {
            const se23_real_t *h = &y->H[S * r];
            se23_real_t s = y->R[M * r + q];
            for (int k = 0; k < nb; ++k) {
                const int j = 3 * blk[k];
                /* C's rows 0..n-1, columns 0..padded(m)-1 are all written
                 * by cross_cov; the analyzer cannot follow the blocks. */
                s = se23_fma(h[j], C[M * j + q], s); // NOLINT(clang-analyzer-core.CallAndMessage)
                s = se23_fma(h[j + 1], C[M * (j + 1) + q], s);
                s = se23_fma(h[j + 2], C[M * (j + 2) + q], s);
            }
            lq[r] = s;
        }
    }
}

/* x = L^-1 x for a factor of se23_cov_chol_packed (reciprocal diagonal). */
static void forward(const se23_real_t *L, int m, se23_real_t *x)
{
    for (int r = 0; r < m; ++r) {
        const se23_real_t *lr = &L[SE23_COV_TRI(r)];
        se23_real_t s = x[r];
        for (int k = 0; k < r; ++k) {
            s = se23_fma(-lr[k], x[k], s);
        }
        x[r] = s * lr[r];
    }
}

/* L_rk of a factor of se23_cov_chol_packed (k < r), 1/L_rr for k = r, and 0
 * past the m rows (the padding). */
static se23_real_t l_at(const se23_real_t *L, int m, int r, int k)
{
    return (r < m) ? L[SE23_COV_TRI(r) + k] : SE23_R(0);
}

/* Columns g..g+2 of U minus the part of the earlier columns h..h+2:
 * c -= L_gh u_h per row, the 3x3 block of L in registers. */
static void solve_u_block(const se23_real_t *L, int n, int m, int g, int h,
                          se23_real_t *U)
{
    const se23_real_t b00 = -l_at(L, m, g, h), b01 = -l_at(L, m, g, h + 1),
                      b02 = -l_at(L, m, g, h + 2);
    const se23_real_t b10 = -l_at(L, m, g + 1, h), b11 = -l_at(L, m, g + 1, h + 1),
                      b12 = -l_at(L, m, g + 1, h + 2);
    const se23_real_t b20 = -l_at(L, m, g + 2, h), b21 = -l_at(L, m, g + 2, h + 1),
                      b22 = -l_at(L, m, g + 2, h + 2);
    for (int i = 0; i < n; ++i) {
        const se23_real_t *u = &U[M * i + h];
        se23_real_t *c = &U[M * i + g];
        const se23_real_t u0 = u[0], u1 = u[1], u2 = u[2];
        const se23_real_t c0 = se23_fma(b02, u2, se23_fma(b01, u1, se23_fma(b00, u0, c[0])));
        const se23_real_t c1 = se23_fma(b12, u2, se23_fma(b11, u1, se23_fma(b10, u0, c[1])));
        const se23_real_t c2 = se23_fma(b22, u2, se23_fma(b21, u1, se23_fma(b20, u0, c[2])));
        c[0] = c0;
        c[1] = c1;
        c[2] = c2;
    }
}

/* In place over C: U = C L^-T (row i solves L u_i = c_i), three columns
 * at a time: the earlier columns' part, then the 3x3 triangle; padding
 * columns stay 0. Along the way dx = U w and the largest |u|^2 over rows
 * and groups of three columns (qmax; NaN stays NaN), so |U_i|^2 <= 3 qmax.
 * n m(m+1)/2 + 2 n m multiply-adds, n m multiplies. */
static void solve_u(const se23_real_t *L, const se23_real_t *w, int n, int m,
                    se23_real_t *U, se23_real_t *dx, se23_real_t *qmax)
{
    se23_real_t worst = SE23_R(0);
    for (int g = 0; g < padded(m); g += 3) {
        for (int h = 0; h < g; h += 3) {
            solve_u_block(L, n, m, g, h, U);
        }
        const se23_real_t d0 = l_at(L, m, g, g), d1 = l_at(L, m, g + 1, g + 1),
                          d2 = l_at(L, m, g + 2, g + 2);
        const se23_real_t l10 = -l_at(L, m, g + 1, g), l20 = -l_at(L, m, g + 2, g),
                          l21 = -l_at(L, m, g + 2, g + 1);
        const se23_real_t w0 = w[g], w1 = w[g + 1], w2 = w[g + 2];
        for (int i = 0; i < n; ++i) {
            se23_real_t *c = &U[M * i + g];
            const se23_real_t u0 = c[0] * d0;
            const se23_real_t u1 = se23_fma(l10, u0, c[1]) * d1;
            const se23_real_t u2 = se23_fma(l21, u1, se23_fma(l20, u0, c[2])) * d2;
            c[0] = u0;
            c[1] = u1;
            c[2] = u2;
            const se23_real_t d = (g == 0) ? SE23_R(0) : dx[i];
            dx[i] = se23_fma(u2, w2, se23_fma(u1, w1, se23_fma(u0, w0, d)));
            const se23_real_t q = se23_fma(u2, u2, se23_fma(u1, u1, u0 * u0));
            worst = (q > worst || !se23_is_finite(q)) ? q : worst;
        }
    }
    *qmax = worst;
}

/* Entry (i, j) and its mirror of src - U U^T for columns g..g+2 of U,
 * with (a0, a1, a2) = -(row i of U). */
static inline void down_entry(const se23_real_t *src, const se23_real_t *U,
                              int i, int j, int g, const se23_real_t a[3],
                              se23_real_t *Pout)
{
    const se23_real_t *u = &U[M * j + g];
    const se23_real_t s = se23_fma(a[2], u[2], se23_fma(a[1], u[1], se23_fma(a[0], u[0], src[S * i + j])));
    Pout[S * i + j] = s;
    Pout[S * j + i] = s;
}

/* Rows i, i + 1, i + 2 of src - U U^T (columns g..g+2 of U), j >= i: the
 * three rows share each load of u_j (9 multiply-adds per 3 loads). */
static void down_rows3(const se23_real_t *src, const se23_real_t *U, int i,
                       int n, int g, se23_real_t *Pout)
{
    const se23_real_t a[3] = {-U[M * i + g], -U[M * i + g + 1], -U[M * i + g + 2]};
    const se23_real_t b[3] = {-U[M * (i + 1) + g], -U[M * (i + 1) + g + 1],
                              -U[M * (i + 1) + g + 2]};
    const se23_real_t c0 = -U[M * (i + 2) + g], c1 = -U[M * (i + 2) + g + 1],
                      c2 = -U[M * (i + 2) + g + 2];
    down_entry(src, U, i, i, g, a, Pout);
    down_entry(src, U, i, i + 1, g, a, Pout);
    down_entry(src, U, i + 1, i + 1, g, b, Pout);
    for (int j = i + 2; j < n; ++j) {
        const se23_real_t *u = &U[M * j + g];
        const se23_real_t u0 = u[0], u1 = u[1], u2 = u[2];
        const se23_real_t s = se23_fma(a[2], u2, se23_fma(a[1], u1, se23_fma(a[0], u0, src[S * i + j])));
        const se23_real_t t = se23_fma(b[2], u2, se23_fma(b[1], u1, se23_fma(b[0], u0, src[S * (i + 1) + j])));
        const se23_real_t v = se23_fma(c2, u2, se23_fma(c1, u1, se23_fma(c0, u0, src[S * (i + 2) + j])));
        Pout[S * i + j] = s;
        Pout[S * j + i] = s;
        Pout[S * (i + 1) + j] = t;
        Pout[S * j + i + 1] = t;
        Pout[S * (i + 2) + j] = v;
        Pout[S * j + i + 2] = v;
    }
}

/* Pout = P - U U^T, three columns of U at a time (zero padding), upper
 * triangle computed and mirrored, three rows per pass (n = 9 or 15):
 * m n(n+1)/2 multiply-adds (padded m). Rows i..i+2 read only their
 * entries (r, j), j >= r, and write those and their mirrors, which lie left
 * of every column a later row reads: Pout may alias P. The groups after
 * the first read Pout's upper triangle. */
static void downdate(const se23_real_t *P, const se23_real_t *U, int n, int m,
                     se23_real_t *Pout)
{
    for (int g = 0; g < padded(m); g += 3) {
        const se23_real_t *src = (g == 0) ? P : Pout;
        for (int i = 0; i < n; i += 3) {
            down_rows3(src, U, i, n, g, Pout);
        }
    }
}

/* Nonzero if every |dx_i| <= SE23_KALMAN_CORR_MAX and P_ii <= DIAG_MAX
 * (NaN fails). */
static int in_range(const se23_real_t *P, const se23_real_t *dx, int n)
{
    for (int i = 0; i < n; ++i) {
        if (!(se23_fabs(dx[i]) <= SE23_KALMAN_CORR_MAX) || !(P[S * i + i] <= DIAG_MAX)) {
            return 0;
        }
    }
    return 1;
}

se23_status_t se23_kalman_cov(const se23_gauss_t *g, const se23_meas_t *y,
                              unsigned mask, se23_real_t *dx, se23_real_t *nis,
                              se23_real_t *Pout)
{
    const int n = g->n, m = y->m;
    se23_real_t U[S * M], L[SE23_MEAS_TRI], w[M];
    int blk[SE23_GAUSS_NMAX / 3], nb = 0;
    for (int b = 0; b < n / 3; ++b) {
        if ((mask & (1u << (unsigned)b)) != 0u) {
            blk[nb] = b;
            ++nb;
        }
    }
    cross_cov(g->P.m, y, n, blk, nb, U);
    innovation_cov(y, blk, nb, U, L);
    if (!se23_cov_chol_packed(L, m)) {
        return SE23_ERR_NOT_PSD;
    }
    for (int r = 0; r < M; ++r) {
        w[r] = (r < m) ? y->z[r] : SE23_R(0);
    }
    forward(L, m, w);
    se23_real_t q = SE23_R(0), qmax;
    for (int r = 0; r < m; ++r) {
        q = se23_fma(w[r], w[r], q);
    }
    solve_u(L, w, n, m, U, dx, &qmax);
    if (!se23_is_finite(q) || !(qmax <= DIAG_MAX / SE23_R(3)) || !in_range(g->P.m, dx, n)) {
        return SE23_ERR_NONFINITE;
    }
    /* Nothing fails from here on. */
    downdate(g->P.m, U, n, m, Pout);
    *nis = q;
    return SE23_OK;
}

void se23_kalman_retract(const se23_gauss_t *g, const se23_real_t *dx,
                         se23_gauss_t *out)
{
    se23_tangent_t xi;
    se23_pose_t E;
    for (int i = 0; i < 9; ++i) {
        xi.v[i] = dx[i];
    }
    (void)se23_exp(&xi, &E);
    se23_compose(&g->T, &E, &out->T);
    /* Each product leaves R about an epsilon further from SO(3); without
     * this an R that passed the rotation test could come back outside it
     * and fail the next call (as in se23_imu_transition). */
    (void)se23_so3_normalize(&out->T.R, &out->T.R);
    if (g->n == SE23_GAUSS_N_BIAS) {
        for (int i = 0; i < 3; ++i) {
            out->b_g.v[i] = g->b_g.v[i] + dx[SE23_IDX_BG + i];
            out->b_a.v[i] = g->b_a.v[i] + dx[SE23_IDX_BA + i];
        }
    } else {
        out->b_g = g->b_g;
        out->b_a = g->b_a;
    }
    out->n = g->n;
}
