/* The navigation filter's rest updates as one structured Kalman update;
 * see kalman_rest.h (the measurement) and kalman.h (the update, DESIGN.md
 * section 3; paper section 3: the right-multiplied error T = Tbar exp(xi)).
 *
 * The rows of H (kalman_rest.h): H_v = [0, I, -a^, 0, 0] (ZUPT) and
 * H_w = [0, 0, 0, I, 0] (ZARU). Row by row of P (i = 0..n-1), in
 * multiply-adds:
 *   c_i  = P_i,nu - a x P_i,rho          C = P H_v^T                  6
 *   u_i  = L_v^-1 c_i                    U_v = C L_v^-T      3 (+ 3 multiplies)
 *   e_i  = P_i,bg - M u_i                P H_w^T after the ZUPT       9
 *   k_i  = L_w^-1 e_i                    U_w = (P H_w^T - U_v M^T) L_w^-T
 *                                                            3 (+ 3 multiplies)
 *   dx_i = u_i . w_v + k_i . w_w         dx = U w                     6
 *   |U_i|^2 (the bounds, the pin test)                                6
 * with M = the rows bg of U_v (the off-diagonal block of S's Cholesky
 * factor), S_v = H_v C + r_v I = L_v L_v^T, S_w = P_bg,bg - M M^T + r_w I =
 * L_w L_w^T (the Schur complement: S's factor is [[L_v, 0], [M, L_w]]),
 * w_v = L_v^-1 z_v (the ZUPT's NIS |w_v|^2) and w_w = L_w^-1 (z_w - M w_v):
 * the blockwise elimination of kalman_halves.c's factorisation, so U and w
 * are the general update's. The blocks of S first: C's rows nu, rho (36)
 * and S_v's lower triangle (12); with ZARU, M (27) and S_w's (18). Then
 * P+ = P - U U^T in one pass (down_rows: 6 or 3 multiply-adds for each of
 * the n(n+1)/2 entries) and the retraction of dx (kalman.c). n = 15 with
 * ZARU: 48 + 45 + 15 x 33 + 720 = 1,308 multiply-adds and 6 square roots;
 * the ZUPT alone 48 + 15 x 15 + 360 = 633 (the general update with these
 * rows: about 2,300 and 830, its scan of H and check of R besides). */
#include "kalman_rest.h"

#include "../cov/cov_chol.h"
#include "kalman_halves.h"

enum {
    S = SE23_GAUSS_NMAX,
    M = SE23_MEAS_MMAX,
    NU = SE23_IDX_NU,
    RHO = SE23_IDX_RHO,
    BG = SE23_IDX_BG
};

/* a . b over 3 entries. */
static inline se23_real_t dot3(const se23_real_t *a, const se23_real_t *b)
{
    return ((a[0] * b[0]) + (a[1] * b[1])) + (a[2] * b[2]);
}

/* The ZUPT column of row p of P: c = P_i,nu - a x P_i,rho (6 multiply-adds). */
static inline void zupt_col(const se23_real_t *p, const se23_real_t a[3], se23_real_t c[3])
{
    const se23_real_t r0 = p[RHO], r1 = p[RHO + 1], r2 = p[RHO + 2];
    c[0] = (p[NU] - (a[1] * r2)) + (a[2] * r1);
    c[1] = (p[NU + 1] - (a[2] * r0)) + (a[0] * r2);
    c[2] = (p[NU + 2] - (a[0] * r1)) + (a[1] * r0);
}

/* x = L^-1 x for a packed 3x3 factor of se23_chol3 (reciprocal diagonal):
 * 3 multiply-adds, 3 multiplies. */
static inline void solve3(const se23_real_t *L, se23_real_t x[3])
{
    const se23_real_t x0 = x[0] * L[0];
    const se23_real_t x1 = (x[1] - (L[1] * x0)) * L[2];
    x[2] = ((x[2] - (L[3] * x0)) - (L[4] * x1)) * L[5];
    x[0] = x0;
    x[1] = x1;
}

/* What the rows need (kept in registers across them): a, the two packed
 * factors (reciprocal diagonals), M (row k at m[3 k]), w_v and w_w. */
typedef struct {
    se23_real_t a[3], lv[6], lw[6], m[9], wv[3], ww[3];
} rest_fac_t;

/* f->lv = the packed lower triangle of S_v = H_v P H_v^T + r_v I from the
 * rows nu and rho of C = P H_v^T: S_v = C_nu - a^ C_rho (48 multiply-adds). */
static void zupt_block(const se23_real_t *P, se23_real_t r_v, rest_fac_t *f)
{
    se23_real_t v[3][3], w[3][3];
    const se23_real_t *a = f->a;
    for (int q = 0; q < 3; ++q) {
        zupt_col(&P[S * (NU + q)], a, v[q]);
        zupt_col(&P[S * (RHO + q)], a, w[q]);
    }
    /* entry (q, r), q >= r: v_qr - (a x w_r)_q, w_r = column r of w */
    f->lv[0] = ((v[0][0] - (a[1] * w[2][0])) + (a[2] * w[1][0])) + r_v;
    f->lv[1] = (v[1][0] - (a[2] * w[0][0])) + (a[0] * w[2][0]);
    f->lv[2] = ((v[1][1] - (a[2] * w[0][1])) + (a[0] * w[2][1])) + r_v;
    f->lv[3] = (v[2][0] - (a[0] * w[1][0])) + (a[1] * w[0][0]);
    f->lv[4] = (v[2][1] - (a[0] * w[1][1])) + (a[1] * w[0][1]);
    f->lv[5] = ((v[2][2] - (a[0] * w[1][2])) + (a[1] * w[0][2])) + r_v;
}

/* f->m = the rows bg of U_v = C L_v^-T, and f->lw = the packed lower
 * triangle of S_w = P_bg,bg - M M^T + r_w I (45 multiply-adds, 9
 * multiplies). */
static void zaru_block(const se23_real_t *P, se23_real_t r_w, rest_fac_t *f)
{
    const se23_real_t *m0 = f->m, *m1 = &f->m[3], *m2 = &f->m[6];
    const se23_real_t *b0 = &P[S * BG + BG], *b1 = &P[S * (BG + 1) + BG],
                      *b2 = &P[S * (BG + 2) + BG];
    for (int k = 0; k < 3; ++k) {
        zupt_col(&P[S * (BG + k)], f->a, &f->m[3 * k]);
        solve3(f->lv, &f->m[3 * k]);
    }
    f->lw[0] = (b0[0] - dot3(m0, m0)) + r_w;
    f->lw[1] = b1[0] - dot3(m1, m0);
    f->lw[2] = (b1[1] - dot3(m1, m1)) + r_w;
    f->lw[3] = b2[0] - dot3(m2, m0);
    f->lw[4] = b2[1] - dot3(m2, m1);
    f->lw[5] = (b2[2] - dot3(m2, m2)) + r_w;
}

/* Row U_i (3 values at u, 6 with ZARU) from row p of P, and dx_i;
 * returns |U_i|^2 (the table above: 33 multiply-adds and 6 multiplies with
 * ZARU, 15 and 3 without). Computed in locals and stored once: the
 * compiler must assume that u may alias p. */
static inline se23_real_t rest_row(const se23_real_t *p, const rest_fac_t *f, int zaru,
                                   se23_real_t *u, se23_real_t *dx_i)
{
    se23_real_t c[3];
    zupt_col(p, f->a, c);
    solve3(f->lv, c);
    se23_real_t d = dot3(c, f->wv);
    se23_real_t s = dot3(c, c);
    if (zaru != 0) {
        se23_real_t k[3] = {p[BG] - dot3(f->m, c), p[BG + 1] - dot3(&f->m[3], c),
                            p[BG + 2] - dot3(&f->m[6], c)};
        solve3(f->lw, k);
        d += dot3(k, f->ww);
        s += dot3(k, k);
        u[3] = k[0];
        u[4] = k[1];
        u[5] = k[2];
    }
    u[0] = c[0];
    u[1] = c[1];
    u[2] = c[2];
    *dx_i = d;
    return s;
}

/* x - a . u over 3 columns (3 multiply-adds, fused into subtractions). */
static inline se23_real_t minus_dot3(se23_real_t x, const se23_real_t *a, const se23_real_t *u)
{
    return ((x - (a[0] * u[0])) - (a[1] * u[1])) - (a[2] * u[2]);
}

/* Entry (r, j) of P - U U^T from src = P_rj, rows a of U_r and u of U_j:
 * the ZUPT's 3 columns, and the ZARU's 3 more if zaru. */
static inline se23_real_t down_entry(se23_real_t src, const se23_real_t *a, const se23_real_t *u,
                                     int zaru)
{
    const se23_real_t e = minus_dot3(src, a, u);
    return (zaru != 0) ? minus_dot3(e, &a[3], &u[3]) : e;
}

/* Rows i, i + 1, i + 2 of P - U U^T, j >= i, and their mirrors, for the 3
 * columns of U (the ZUPT), or 6 (and the ZARU) in the same pass: each entry
 * of P loaded and stored once, each row u_j loaded once for the three rows,
 * whose 9 or 18 values stay in registers on the M4F (32 single-precision
 * registers): 3 or 6 multiply-adds per entry. Rows i..i+2 read only their
 * entries (r, j), j >= r, and write those and their mirrors, left of every
 * column a later row reads: Pout may alias P. */
static void down_rows(const se23_real_t *P, const se23_real_t *U, int i, int n, int zaru,
                      se23_real_t *Pout)
{
    const se23_real_t *ua = &U[M * i], *ub = &U[M * (i + 1)], *uc = &U[M * (i + 2)];
    const se23_real_t a[6] = {ua[0], ua[1], ua[2], ua[3], ua[4], ua[5]};
    const se23_real_t b[6] = {ub[0], ub[1], ub[2], ub[3], ub[4], ub[5]};
    const se23_real_t c[6] = {uc[0], uc[1], uc[2], uc[3], uc[4], uc[5]};
    const se23_real_t *si = &P[S * i], *sj = &P[S * (i + 1)], *sk = &P[S * (i + 2)];
    const se23_real_t d00 = down_entry(si[i], a, ua, zaru),
                      d01 = down_entry(si[i + 1], a, ub, zaru),
                      d02 = down_entry(si[i + 2], a, uc, zaru),
                      d11 = down_entry(sj[i + 1], b, ub, zaru),
                      d12 = down_entry(sj[i + 2], b, uc, zaru),
                      d22 = down_entry(sk[i + 2], c, uc, zaru);
    se23_real_t *oi = &Pout[S * i], *oj = &Pout[S * (i + 1)], *ok = &Pout[S * (i + 2)];
    oi[i] = d00;
    oi[i + 1] = d01;
    oi[i + 2] = d02;
    oj[i] = d01;
    oj[i + 1] = d11;
    oj[i + 2] = d12;
    ok[i] = d02;
    ok[i + 1] = d12;
    ok[i + 2] = d22;
    for (int j = i + 3; j < n; ++j) {
        const se23_real_t *u = &U[M * j];
        const se23_real_t e0 = down_entry(si[j], a, u, zaru);
        const se23_real_t e1 = down_entry(sj[j], b, u, zaru);
        const se23_real_t e2 = down_entry(sk[j], c, u, zaru);
        se23_real_t *mirror = &Pout[S * j + i];
        oi[j] = e0;
        oj[j] = e1;
        ok[j] = e2;
        mirror[0] = e0;
        mirror[1] = e1;
        mirror[2] = e2;
    }
}

se23_status_t se23_kalman_rest_cov(const se23_gauss_t *g, const se23_rest_meas_t *y,
                                   se23_kalman_work_t *wk, se23_real_t *dx, se23_real_t *nis,
                                   se23_real_t *Pout)
{
    const int n = g->n;
    int zaru = 0;
    const se23_real_t *P = g->P.m;
    rest_fac_t f;
    se23_real_t usq = SE23_R(0);
    int pinned = 0;
    if (y->zaru != 0) {
        zaru = 1;
    }
    if (((n != SE23_GAUSS_N_POSE) && (n != SE23_GAUSS_N_BIAS)) ||
        ((zaru != 0) && (n != SE23_GAUSS_N_BIAS))) {
        return SE23_ERR_DIM;
    }
    for (int k = 0; k < 3; ++k) {
        f.a[k] = y->a.v[k];
        f.wv[k] = y->z_v.v[k];
        f.ww[k] = y->z_w.v[k];
    }
    zupt_block(P, y->r_v, &f);
    if (se23_chol3(f.lv) == 0) {
        return SE23_ERR_NOT_PSD;
    }
    solve3(f.lv, f.wv);
    const se23_real_t q_v = dot3(f.wv, f.wv);
    se23_real_t q = q_v;
    if (zaru != 0) {
        zaru_block(P, y->r_w, &f);
        if (se23_chol3(f.lw) == 0) {
            return SE23_ERR_NOT_PSD;
        }
        f.ww[0] -= dot3(f.m, f.wv);
        f.ww[1] -= dot3(&f.m[3], f.wv);
        f.ww[2] -= dot3(&f.m[6], f.wv);
        solve3(f.lw, f.ww);
        q += dot3(f.ww, f.ww);
    }
    for (int i = 0; i < n; ++i) {
        const se23_real_t s = rest_row(&P[S * i], &f, zaru, &wk->U[M * i], &dx[i]);
        usq += s;
        if (se23_kalman_pins(P[(S + 1) * i], s) != 0) {
            pinned = 1;
        }
    }
    if (se23_kalman_fits(P, n, usq, q) == 0) {
        return SE23_ERR_NONFINITE;
    }
    if (pinned != 0) {
        return SE23_ERR_DOMAIN;
    }
    /* Nothing fails from here on. */
    for (int i = 0; i < n; i += 3) {
        down_rows(P, wk->U, i, n, zaru, Pout);
    }
    *nis = q_v;
    return SE23_OK;
}
