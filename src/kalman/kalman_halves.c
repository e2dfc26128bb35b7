/* The two halves of the measurement update; see kalman_halves.h.
 *
 * Cost. Only the active 3-column blocks of H take part (a = 3 x their
 * number). With m rows and n states, in fused multiply-adds:
 *   C  = P H^T             n m a        (active columns of P and H)
 *   S  = H C + R           a m^2        (active rows of C, 3x3 blocks)
 *   L L^T = S              m^3/6, m square roots and divisions
 *   w  = L^-1 z            m^2/2;  nis = w.w, m
 *   U  = C L^-T            n m(m-1)/2, n m multiplies
 *   dx = U w, |U_i|^2      2 n m
 *   X  = P - U U^T         m n(n+1)/2   (upper triangle, mirrored)
 *   K  = U L^-1            n m(m-1)/2, n m multiplies
 *   P+ = X - K (H X - R K^T)   n (a m + m^2) + m n(n+1)/2 (joseph_refine)
 * The kernels take m three rows at a time (zero padding), so m counts as
 * a multiple of 3 in the n-sized terms. GNSS position with a lever arm
 * (n = 15, m = 3, a = 6): 270 + 54 + 10 + 9 + 45 + 90 + 360 = 838
 * multiply-adds and 3 square roots for X; when the update pins a variance
 * below SE23_KALMAN_PIN_RATIO of its prior (pins_a_variance), 45 + 765
 * more for K and P+;
 * the dense Joseph form with the same factorisation is about
 * 2 n^3 + 4 n^2 m = 9,500.
 *
 * Why the Schur complement first. Both it and the Joseph form equal
 * P - C S^-1 C^T in
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
 * grows with the gain (small R). But the bound is relative to the prior:
 * where R is below eps times the prior the posterior is below the
 * rounding and X can come out negative there (issue 37, S5), so
 * joseph_refine applies the Joseph form to X itself, which removes that
 * error along the measured directions at any ratio up to 1/eps^2. A state
 * correlated with a measured one keeps X's error, eps times its prior
 * variance (only a factored form would remove it); the filter refuses an
 * update whose result then fails se23_gauss_check (ins_aid.c, commit).
 * P+ is symmetric by construction (upper triangle computed, mirrored);
 * test_kalman runs thousands of updates with tiny R and checks the
 * smallest eigenvalue, and a 1 km prior against a 1 cm fix. */
#include "kalman_halves.h"

#include <float.h>

#include "../base/linalg.h"
#include "se23/se23.h"
#include "../base/se23_math.h"

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

/* Nonzero if 3-column block b of H is active (bit b of mask). */
static int active(unsigned mask, int b)
{
    return (mask & (1u << (unsigned)b)) != 0u;
}

/* C = P H^T over the active blocks: n x padded(m), (i, r) at C[M i + r],
 * padding columns 0. Per group of three rows of H and active block, the
 * 3x3 block of H stays in registers while P's 3-column block streams by
 * (9 multiply-adds per row): n m a in all. The first block starts from
 * zero_row (stride 0) instead of C, so C needs no clearing. */
static void cross_cov(const se23_real_t *P, const se23_meas_t *y, int n, unsigned mask,
                      se23_real_t *C)
{
    const int mp = padded(y->m);
    for (int g = 0; g < mp; g += 3) {
        const se23_real_t *h0 = h_row(y, g), *h1 = h_row(y, g + 1), *h2 = h_row(y, g + 2);
        int k = 0; /* active blocks done */
        for (int b = 0; b < n / 3; ++b) {
            if (!active(mask, b)) {
                continue;
            }
            const int j = 3 * b;
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
            ++k;
        }
        if (k == 0) {
            for (int i = 0; i < n; ++i) {
                for (int r = g; r < g + 3; ++r) {
                    C[M * i + r] = SE23_R(0);
                }
            }
        }
    }
}

/* Entries (q, r0..r0+2) of S = (sums) + R that lie in its packed lower
 * triangle (column <= q) and in its m rows (R's upper triangle read). */
static void store_row(const se23_real_t *R, int m, int q, int r0, se23_real_t s0,
                      se23_real_t s1, se23_real_t s2, se23_real_t *L)
{
    if (q >= m) {
        return;
    }
    se23_real_t *l = &L[SE23_COV_TRI(q) + r0];
    const se23_real_t *r = &R[M * r0 + q];
    l[0] = s0 + r[0];
    if (r0 + 1 <= q) {
        l[1] = s1 + r[M];
    }
    if (r0 + 2 <= q) {
        l[2] = s2 + r[2 * M];
    }
}

/* Packed lower triangle of S = H C + R, 3x3 blocks (rows q0..q0+2 of S,
 * columns r0..r0+2, r0 <= q0) over the active rows of C (columns of H):
 * 9 multiply-adds per active row of C and block, the three rows of H and
 * of C streaming by while the block stays in registers: a m^2 for m = 3
 * (the diagonal block's upper half is computed and dropped). Rows
 * past m are H's zero padding and are not stored; R's upper triangle is
 * read. */
static void innovation_block(const se23_meas_t *y, int m, int n, unsigned mask,
                             const se23_real_t *C, int q0, int r0, se23_real_t *L)
{
    const se23_real_t *hr0 = h_row(y, r0), *hr1 = h_row(y, r0 + 1), *hr2 = h_row(y, r0 + 2);
    se23_real_t s00 = SE23_R(0), s01 = SE23_R(0), s02 = SE23_R(0);
    se23_real_t s10 = SE23_R(0), s11 = SE23_R(0), s12 = SE23_R(0);
    se23_real_t s20 = SE23_R(0), s21 = SE23_R(0), s22 = SE23_R(0);
    for (int b = 0; b < n / 3; ++b) {
        if (!active(mask, b)) {
            continue;
        }
        for (int j = 3 * b; j < 3 * b + 3; ++j) {
            /* C's rows 0..n-1, columns 0..padded(m)-1 are all written by
             * cross_cov; the analyzer cannot follow the blocks. */
            const se23_real_t *c = &C[M * j + q0];
            const se23_real_t c0 = c[0], c1 = c[1], c2 = c[2]; // NOLINT(clang-analyzer-core.uninitialized.Assign)
            const se23_real_t h0 = hr0[j], h1 = hr1[j], h2 = hr2[j];
            s00 = se23_fma(c0, h0, s00);
            s01 = se23_fma(c0, h1, s01);
            s02 = se23_fma(c0, h2, s02);
            s10 = se23_fma(c1, h0, s10);
            s11 = se23_fma(c1, h1, s11);
            s12 = se23_fma(c1, h2, s12);
            s20 = se23_fma(c2, h0, s20);
            s21 = se23_fma(c2, h1, s21);
            s22 = se23_fma(c2, h2, s22);
        }
    }
    /* The block's entries in its three rows, no array: an array of the
     * nine sums would sit on the stack under the whole update. */
    store_row(y->R, m, q0, r0, s00, s01, s02, L);
    store_row(y->R, m, q0 + 1, r0, s10, s11, s12, L);
    store_row(y->R, m, q0 + 2, r0, s20, s21, s22, L);
}

static void innovation_cov(const se23_meas_t *y, int m, int n, unsigned mask,
                           const se23_real_t *C, se23_real_t *L)
{
    for (int q0 = 0; q0 < m; q0 += 3) {
        for (int r0 = 0; r0 <= q0; r0 += 3) {
            innovation_block(y, m, n, mask, C, q0, r0, L);
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
 * columns stay 0. Along the way dx = U w and *usq = sum_i |U_i|^2 (NaN
 * stays NaN), which bounds every |U_i|^2. n m(m+1)/2 + 2 n m
 * multiply-adds, n m multiplies. */
static void solve_u(const se23_real_t *L, const se23_real_t *w, int n, int m,
                    se23_real_t *U, se23_real_t *dx, se23_real_t *usq)
{
    se23_real_t sum = SE23_R(0);
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
            sum = se23_fma(u2, u2, se23_fma(u1, u1, se23_fma(u0, u0, sum)));
        }
    }
    *usq = sum;
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
    /* Rows i..i+2 left to right from column i + 2 (read at in[0], in[S],
     * in[2 S], written at out[...]); the mirrors go down columns i..i+2. */
    const se23_real_t *in = &src[S * i + i + 2], *u = &U[M * (i + 2) + g];
    se23_real_t *out = &Pout[S * i + i + 2], *mirror = &Pout[S * (i + 2) + i];
    for (int j = i + 2; j < n; ++j) {
        const se23_real_t u0 = u[0], u1 = u[1], u2 = u[2];
        const se23_real_t e0 = se23_fma(a[2], u2, se23_fma(a[1], u1, se23_fma(a[0], u0, in[0])));
        const se23_real_t e1 = se23_fma(b[2], u2, se23_fma(b[1], u1, se23_fma(b[0], u0, in[S])));
        const se23_real_t e2 = se23_fma(c2, u2, se23_fma(c1, u1, se23_fma(c0, u0, in[2 * S])));
        out[0] = e0;
        out[S] = e1;
        out[2 * S] = e2;
        mirror[0] = e0;
        mirror[1] = e1;
        mirror[2] = e2;
        in = &in[1];
        out = &out[1];
        u = &u[M];
        mirror = &mirror[S];
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

/* In place over U = C L^-T: the gain K = C S^-1 = U L^-1 (row i solves
 * L^T k_i = u_i, backward), padding columns left 0. n m(m-1)/2
 * multiply-adds, n m multiplies. */
static void gain_from_u(const se23_real_t *L, int n, int m, se23_real_t *U)
{
    for (int i = 0; i < n; ++i) {
        se23_real_t *k = &U[M * i];
        for (int r = m - 1; r >= 0; --r) {
            se23_real_t s = k[r];
            for (int q = r + 1; q < m; ++q) {
                s = se23_fma(-L[SE23_COV_TRI(q) + r], k[q], s);
            }
            k[r] = s * L[SE23_COV_TRI(r) + r];
        }
    }
}

/* Column j's residual z = H X_j - R k_j of the constraint H X = R K^T
 * (m values; X_j the column, k_j row j of K): a m + m^2 multiply-adds. */
static void constraint_residual(const se23_meas_t *y, int n, unsigned mask,
                                const se23_real_t *X, const se23_real_t *K, int j,
                                se23_real_t *z)
{
    const se23_real_t *kj = &K[M * j];
    for (int r = 0; r < y->m; ++r) {
        const se23_real_t *h = &y->H[S * r], *rr = &y->R[M * r];
        se23_real_t s = SE23_R(0);
        for (int b = 0; b < n / 3; ++b) {
            if (active(mask, b) != 0) {
                const int l = 3 * b;
                s = se23_fma(h[l], X[S * l + j], s);
                s = se23_fma(h[l + 1], X[S * (l + 1) + j], s);
                s = se23_fma(h[l + 2], X[S * (l + 2) + j], s);
            }
        }
        for (int c = 0; c < y->m; ++c) {
            s = se23_fma(-rr[c], kj[c], s);
        }
        z[r] = s;
    }
}

/* P+ = X - K (H X - R K^T) in place over X = P - U U^T, the upper
 * triangle column by column, mirrored; a negative variance (the rounding
 * of a zero one) is raised to 0 (cov_check.h).
 *
 * Why. X = P G^T, G = I - K H, and the Joseph form is
 * P+ = G X + K R K^T = X - K Z, Z = H X - R K^T. In exact arithmetic
 * H X = C^T - (S - R) K^T = R K^T, so Z = 0 and P+ = X; computed, X carries
 * the Schur complement's rounding, of order eps |P|, which exceeds the
 * posterior itself along a direction the measurement pins far below its
 * prior (a 1 km prior, a 1 cm fix: 1e6 against 1e-4 m^2, float eps 6e-8):
 * the variance comes out negative. Subtracting K Z multiplies that error by
 * G, which is small exactly there (G = R S^-1 for a measured state), so
 * the error becomes eps |G| |P| ~ eps R: the Joseph form's accuracy at any
 * prior-to-R ratio below 1/eps^2, for the extra cost below and no storage
 * but K in U's place and z.
 *
 * In place: column j reads X's entries (l, j), l in the active blocks,
 * before it writes; the upper entries of column j are written only by
 * column j and its lower entries only by the mirrors of later columns.
 * Z is rounding-sized (|K Z| ~ eps |P|), so P+ stays within the bounds
 * that keep X finite. n (a m + m^2) + m n(n+1)/2 multiply-adds (GNSS
 * position with a lever arm: 405 + 360). */
static void joseph_refine(const se23_meas_t *y, int n, unsigned mask,
                          const se23_real_t *K, se23_real_t *z, se23_real_t *X)
{
    const int m = y->m;
    for (int j = 0; j < n; ++j) {
        constraint_residual(y, n, mask, X, K, j, z);
        for (int i = 0; i <= j; ++i) {
            const se23_real_t *ki = &K[M * i];
            se23_real_t v = X[S * i + j];
            for (int r = 0; r < m; ++r) {
                v = se23_fma(-ki[r], z[r], v);
            }
            X[S * i + j] = v;
            X[S * j + i] = v;
        }
    }
    se23_cov_clamp_variances(X, n, S);
}

/* Nonzero if the update left a variance below SE23_KALMAN_PIN_RATIO of
 * its prior, from X = P - U U^T and U: X_ii < r P_ii = r (X_ii + |U_i|^2),
 * i.e. (1 - r) X_ii < r |U_i|^2 (no cancellation in the test). Only then
 * can X's rounding, of order eps P_ii, be a sizeable part of the
 * posterior (above 2^10 eps of it), and joseph_refine runs; otherwise it
 * would change nothing that matters, and an update of a filter in its
 * steady state (a fix, a ZUPT) costs what the Schur complement costs.
 * n padded(m) multiply-adds. */
static int pins_a_variance(const se23_real_t *X, const se23_real_t *U, int n, int m)
{
    const se23_real_t r = SE23_KALMAN_PIN_RATIO, keep = SE23_R(1) - SE23_KALMAN_PIN_RATIO;
    int pinned = 0;
    for (int i = 0; i < n; ++i) {
        const se23_real_t *u = &U[M * i];
        se23_real_t q = SE23_R(0);
        for (int k = 0; k < padded(m); ++k) {
            q = se23_fma(u[k], u[k], q);
        }
        if (keep * X[(S + 1) * i] < r * q) {
            pinned = 1;
        }
    }
    return pinned;
}

/* tr P = sum_i P_ii (P PSD: it bounds every P_ii; NaN stays NaN), three
 * partial sums (n = 9 or 15). */
static se23_real_t trace(const se23_real_t *P, int n)
{
    se23_real_t t0 = SE23_R(0), t1 = SE23_R(0), t2 = SE23_R(0);
    for (int i = 0; i < n; i += 3) {
        t0 += P[(S + 1) * i];
        t1 += P[(S + 1) * (i + 1)];
        t2 += P[(S + 1) * (i + 2)];
    }
    return (t0 + t1) + t2;
}

int se23_kalman_fits(const se23_real_t *P, int n, se23_real_t usq, se23_real_t q)
{
    /* |dx_i| = |U_i . w| <= (|U_i|^2 q)^(1/2) <= (usq q)^(1/2) (Cauchy-
     * Schwarz); usq and tr P bound |U_i|^2 and P_ii (DIAG_MAX). A product
     * that overflows fails the test, as NaN does. */
    return se23_is_finite(q) && (usq <= DIAG_MAX) && (trace(P, n) <= DIAG_MAX) &&
           (usq * q <= SE23_KALMAN_CORR_MAX * SE23_KALMAN_CORR_MAX);
}

int se23_kalman_mean_in_range(const se23_gauss_t *g)
{
    const se23_real_t *parts[4] = {g->T.v.v, g->T.p.v, g->b_g.v, g->b_a.v};
    for (int k = 0; k < 4; ++k) {
        for (int i = 0; i < 3; ++i) {
            if (!(se23_fabs(parts[k][i]) <= SE23_KALMAN_MEAN_MAX)) {
                return 0;
            }
        }
    }
    return 1;
}

se23_status_t se23_kalman_cov_work(const se23_gauss_t *g, const se23_meas_t *y,
                                   unsigned mask, se23_kalman_work_t *wk,
                                   se23_real_t *dx, se23_real_t *nis, se23_real_t *Pout)
{
    const int n = g->n, m = y->m;
    /* Addresses only: every entry is written before it is read (cross_cov,
     * innovation_cov, the loop on w), which cppcheck's whole-program check
     * cannot see when se23_kalman_cov passes its uninitialised work area. */
    // cppcheck-suppress ctuuninitvar
    se23_real_t *U = wk->U, *L = wk->L, *w = wk->w;
    cross_cov(g->P.m, y, n, mask, U);
    innovation_cov(y, m, n, mask, U, L);
    if (!se23_cov_chol_packed(L, m)) {
        return SE23_ERR_NOT_PSD;
    }
    for (int r = 0; r < M; ++r) {
        w[r] = (r < m) ? y->z[r] : SE23_R(0);
    }
    forward(L, m, w);
    se23_real_t q = SE23_R(0), usq;
    for (int r = 0; r < m; ++r) {
        q = se23_fma(w[r], w[r], q);
    }
    solve_u(L, w, n, m, U, dx, &usq);
    if (se23_kalman_fits(g->P.m, n, usq, q) == 0) {
        return SE23_ERR_NONFINITE;
    }
    /* Nothing fails from here on; w is free once dx is formed. */
    downdate(g->P.m, U, n, m, Pout);
    if (pins_a_variance(Pout, U, n, m) != 0) {
        gain_from_u(L, n, m, U);
        joseph_refine(y, n, mask, U, w, Pout);
    }
    *nis = q;
    return SE23_OK;
}

se23_status_t se23_kalman_cov(const se23_gauss_t *g, const se23_meas_t *y,
                              unsigned mask, se23_real_t *dx, se23_real_t *nis,
                              se23_real_t *Pout)
{
    se23_kalman_work_t wk;
    return se23_kalman_cov_work(g, y, mask, &wk, dx, nis, Pout);
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
     * and fail the next call. The state's R is within SE23_CFG_ROT_TOL of
     * SO(3) (trusted) and exp(phi^) within rounding, so one Newton-Schulz
     * step (drift e -> 3 e^2 / 4) brings the product to rounding level, as
     * in se23_imu_transition; no check of what the library built. */
    (void)se23_m3_orthonormalize_step(&out->T.R, SE23_NORMALIZE_DONE, SE23_R(0.1));
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
