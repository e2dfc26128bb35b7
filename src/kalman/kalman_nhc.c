/* The navigation filter's non-holonomic constraint as one structured
 * Kalman update; see kalman_nhc.h (the measurement) and kalman.h (the
 * update, DESIGN.md section 3).
 *
 * The two rows of H (kalman_nhc.h) hold h_r = [c_r x u, c_r] in the
 * columns phi, nu (0..5) and zeros elsewhere. In multiply-adds:
 *   C = P H^T: c_ir = P_i,0..5 . h_r                    12 per row
 *   S = H C + r I (2 x 2, its lower triangle from C's rows 0..5)    18
 *   S = L L^T: l_00 = S_00^(1/2), l_10, l_11 (reciprocal diagonal)
 *                                        1 (+ 1 multiply, 2 roots)
 *   w = L^-1 z, the NIS |w|^2                        1 (+ 2), 2
 *   U = C L^-T: u_i0 = c_i0 / l_00, u_i1 = (c_i1 - l_10 u_i0) / l_11
 *                                             1 (+ 2 multiplies) per row
 *   dx_i = u_i . w, |U_i|^2 (the bounds, the pin test)   4 per row
 *   P+ = P - U U^T (upper triangle, mirrored)  2 per entry, n(n+1)/2
 * the kernels of kalman_halves.c with m = 2 and only the blocks phi, nu of
 * H active, so U, w and P+ are the general update's to rounding (that
 * update pads m to 3 and scans H; its Joseph step is refused here, see
 * "Scope"). C's rows phi, nu are stored (S needs them first), the others
 * go straight into U. n = 15: 180 + 18 + 4 + 15 x 5 + 240 = 517
 * multiply-adds, 2 square roots and divisions, then the retraction of dx
 * (kalman_halves.c); the general update with these rows: about 840 (m
 * padded to 3), the scan of H, the check of R and se23_meas_nhc's checks
 * besides. make bench-target: 2,896 M4F instructions (3,226 M7 double)
 * against 5,830 (6,350) for se23_meas_nhc + se23_kalman_update. */
#include "kalman_nhc.h"

#include <stddef.h>

#include "../cov/cov_chol.h"
#include "kalman_halves.h"

enum { S = SE23_GAUSS_NMAX, M = SE23_MEAS_MMAX };

void se23_nhc_rows(const se23_pose_t *T, const se23_mat3_t *C_bv, se23_real_t sigma,
                   se23_nhc_meas_t *y)
{
    const se23_mat3_t *R = &T->R;
    const se23_real_t *v = T->v.v;
    se23_real_t u[3];
    for (int k = 0; k < 3; ++k) {
        /* u = R^T v, the body velocity */
        u[k] = ((R->m[0][k] * v[0]) + (R->m[1][k] * v[1])) + (R->m[2][k] * v[2]);
    }
    for (int r = 0; r < 2; ++r) {
        const se23_real_t c0 = C_bv->m[0][r + 1], c1 = C_bv->m[1][r + 1],
                          c2 = C_bv->m[2][r + 1];
        y->h[r][0] = (c1 * u[2]) - (c2 * u[1]);
        y->h[r][1] = (c2 * u[0]) - (c0 * u[2]);
        y->h[r][2] = (c0 * u[1]) - (c1 * u[0]);
        y->h[r][3] = c0;
        y->h[r][4] = c1;
        y->h[r][5] = c2;
        y->z[r] = -(((c0 * u[0]) + (c1 * u[1])) + (c2 * u[2]));
    }
    y->r = sigma * sigma;
}

/* p[0..5] . h (6 multiply-adds). */
static inline se23_real_t dot6(const se23_real_t *p, const se23_real_t *h)
{
    return (((((p[0] * h[0]) + (p[1] * h[1])) + (p[2] * h[2])) + (p[3] * h[3])) +
            (p[4] * h[4])) +
           (p[5] * h[5]);
}

/* Rows i, i + 1, i + 2 of P - U U^T, j >= i, and their mirrors (U's two
 * columns at U[M j], U[M j + 1]): each entry of P loaded and stored once,
 * the rows u_i..u_i+2 in registers, 2 multiply-adds per entry. Rows
 * i..i+2 read only their entries (r, j), j >= r, and write those and their
 * mirrors, left of every column a later row reads: Pout may alias P. */
static void down_rows2(const se23_real_t *P, const se23_real_t *U, int i, int n,
                       se23_real_t *Pout)
{
    const se23_real_t a0 = U[M * i], a1 = U[(M * i) + 1];
    const se23_real_t b0 = U[M * (i + 1)], b1 = U[(M * (i + 1)) + 1];
    const se23_real_t c0 = U[M * (i + 2)], c1 = U[(M * (i + 2)) + 1];
    const se23_real_t *si = &P[S * i], *sj = &P[S * (i + 1)], *sk = &P[S * (i + 2)];
    const se23_real_t d00 = (si[i] - (a0 * a0)) - (a1 * a1);
    const se23_real_t d01 = (si[i + 1] - (a0 * b0)) - (a1 * b1);
    const se23_real_t d02 = (si[i + 2] - (a0 * c0)) - (a1 * c1);
    const se23_real_t d11 = (sj[i + 1] - (b0 * b0)) - (b1 * b1);
    const se23_real_t d12 = (sj[i + 2] - (b0 * c0)) - (b1 * c1);
    const se23_real_t d22 = (sk[i + 2] - (c0 * c0)) - (c1 * c1);
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
        const se23_real_t u0 = U[M * j], u1 = U[(M * j) + 1];
        const se23_real_t e0 = (si[j] - (a0 * u0)) - (a1 * u1);
        const se23_real_t e1 = (sj[j] - (b0 * u0)) - (b1 * u1);
        const se23_real_t e2 = (sk[j] - (c0 * u0)) - (c1 * u1);
        se23_real_t *mirror = &Pout[(S * j) + i];
        oi[j] = e0;
        oj[j] = e1;
        ok[j] = e2;
        mirror[0] = e0;
        mirror[1] = e1;
        mirror[2] = e2;
    }
}

/* What the rows need (kept in registers across them): the factor of S
 * (reciprocal diagonal) and w = L^-1 z. */
typedef struct {
    se23_real_t i0, l10, i1, w0, w1;
} nhc_fac_t;

/* Row U_i = (u0, u1) = C_i L^-T from C_i = (c0, c1), stored at u, and
 * dx_i = U_i . w; returns |U_i|^2 (5 multiply-adds, 2 multiplies). */
static inline se23_real_t nhc_row(se23_real_t c0, se23_real_t c1, const nhc_fac_t *f,
                                  se23_real_t *u, se23_real_t *dx_i)
{
    const se23_real_t u0 = c0 * f->i0;
    const se23_real_t u1 = se23_fma(-f->l10, u0, c1) * f->i1;
    u[0] = u0;
    u[1] = u1;
    *dx_i = se23_fma(u1, f->w1, u0 * f->w0);
    return se23_fma(u1, u1, u0 * u0);
}

se23_status_t se23_kalman_nhc_cov(const se23_gauss_t *g, const se23_nhc_meas_t *y,
                             se23_kalman_work_t *wk, se23_real_t *dx, se23_real_t *q,
                             se23_real_t *Pout)
{
    const int n = g->n;
    const se23_real_t *P = g->P.m;
    const se23_real_t *h0 = y->h[0], *h1 = y->h[1];
    se23_real_t *U = wk->U;
    se23_real_t usq = SE23_R(0);
    int pinned = 0;
    if ((n != SE23_GAUSS_N_POSE) && (n != SE23_GAUSS_N_BIAS)) {
        return SE23_ERR_DIM;
    }
    /* C's rows phi, nu first: S needs them */
    for (int i = 0; i < 6; ++i) {
        const se23_real_t *p = &P[S * i];
        U[M * i] = dot6(p, h0);
        U[(M * i) + 1] = dot6(p, h1);
    }
    /* S's lower triangle from C's rows phi, nu: S_rs = h_r . C_s + r */
    se23_real_t s00 = y->r, s10 = SE23_R(0), s11 = y->r;
    for (int k = 0; k < 6; ++k) {
        const se23_real_t c0 = U[M * k], c1 = U[(M * k) + 1];
        s00 += h0[k] * c0;
        s10 += h1[k] * c0;
        s11 += h1[k] * c1;
    }
    /* the 2 x 2 factor of se23_cov_chol_packed, reciprocal diagonal */
    if (!se23_chol_pivot_ok(s00, s00)) {
        return SE23_ERR_NOT_PSD;
    }
    nhc_fac_t f;
    f.i0 = SE23_R(1) / se23_sqrt(s00);
    f.l10 = s10 * f.i0;
    const se23_real_t d1 = se23_fma(-f.l10, f.l10, s11);
    if (!se23_chol_pivot_ok(d1, s11)) {
        return SE23_ERR_NOT_PSD;
    }
    f.i1 = SE23_R(1) / se23_sqrt(d1);
    f.w0 = y->z[0] * f.i0;
    f.w1 = se23_fma(-f.l10, f.w0, y->z[1]) * f.i1;
    const se23_real_t nis = se23_fma(f.w1, f.w1, f.w0 * f.w0);
    /* U row by row: C's rows phi, nu from U, the others formed here (their
     * C never stored) */
    for (int i = 0; i < 6; ++i) {
        const se23_real_t s = nhc_row(U[M * i], U[(M * i) + 1], &f, &U[M * i], &dx[i]);
        usq += s;
        if (se23_kalman_pins(P[(S + 1) * i], s) != 0) {
            pinned = 1;
        }
    }
    for (int i = 6; i < n; ++i) {
        const se23_real_t *p = &P[S * i];
        const se23_real_t s = nhc_row(dot6(p, h0), dot6(p, h1), &f, &U[M * i], &dx[i]);
        usq += s;
        if (se23_kalman_pins(P[(S + 1) * i], s) != 0) {
            pinned = 1;
        }
    }
    if (se23_kalman_fits(P, n, usq, nis) == 0) {
        return SE23_ERR_NONFINITE;
    }
    if (pinned != 0) {
        return SE23_ERR_DOMAIN;
    }
    /* Nothing fails from here on. */
    for (int i = 0; i < n; i += 3) {
        down_rows2(P, U, i, n, Pout);
    }
    *q = nis;
    return SE23_OK;
}
