/* GNSS measurement update of the INS engine; see update.h. */
#include "update.h"

#include <math.h>
#include <string.h>

#include "se23/se23.h"

#define NMAX 15
#define MMAX 6

/* Lower Cholesky factor of the m x m matrix A (stride MMAX); 0 on failure. */
static int chol(double A[MMAX][MMAX], int m, double L[MMAX][MMAX])
{
    int i, j, k;
    memset(L, 0, sizeof(double) * MMAX * MMAX);
    for (j = 0; j < m; j++) {
        double d = A[j][j];
        for (k = 0; k < j; k++) {
            d -= L[j][k] * L[j][k];
        }
        if (!(d > 1e-300) || !isfinite(d)) {
            return 0;
        }
        L[j][j] = sqrt(d);
        for (i = j + 1; i < m; i++) {
            double s = A[i][j];
            for (k = 0; k < j; k++) {
                s -= L[i][k] * L[j][k];
            }
            L[i][j] = s / L[j][j];
        }
    }
    return 1;
}

/* x = (L L^T)^-1 x */
static void chol_solve(double L[MMAX][MMAX], int m, double *x)
{
    int i, k;
    for (i = 0; i < m; i++) {
        for (k = 0; k < i; k++) {
            x[i] -= L[i][k] * x[k];
        }
        x[i] /= L[i][i];
    }
    for (i = m - 1; i >= 0; i--) {
        for (k = i + 1; k < m; k++) {
            x[i] -= L[k][i] * x[k];
        }
        x[i] /= L[i][i];
    }
}

int ins_update_gnss(se23_gauss_t *g, const ins_gnss_t *fix, double gate, double *nis)
{
    const int n = g->n;
    double H[MMAX][NMAX], z[MMAX], Rn[MMAX], S[MMAX][MMAX], L[MMAX][MMAX];
    double PHt[NMAX][MMAX], K[NMAX][MMAX], A[NMAX][NMAX], AP[NMAX][NMAX];
    double Pn[NMAX][NMAX], dx[NMAX], y[MMAX], q;
    int m = 0, i, j, k, blk;
    se23_tangent_t xi;
    se23_pose_t E, Tn;
    se23_gauss_t out;

    memset(H, 0, sizeof H);
    for (blk = 0; blk < 2; blk++) {
        /* block 0: position (rho), block 1: velocity (nu) */
        const double *meas = blk == 0 ? fix->p_n : fix->v_n;
        const double *sig = blk == 0 ? fix->sigma_p : fix->sigma_v;
        const se23_real_t *est = blk == 0 ? g->T.p.v : g->T.v.v;
        int col = blk == 0 ? SE23_IDX_RHO : SE23_IDX_NU;
        if (blk == 1 && !fix->has_vel) {
            break;
        }
        for (i = 0; i < 3; i++) {
            if (!isfinite(meas[i]) || !isfinite(sig[i]) || !(sig[i] > 0.0)) {
                return -1;
            }
            z[m + i] = meas[i] - est[i];
            Rn[m + i] = sig[i] * sig[i];
            for (j = 0; j < 3; j++) {
                H[m + i][col + j] = g->T.R.m[i][j];
            }
        }
        m += 3;
    }
    /* PHt = P H^T, S = H P H^T + R */
    for (i = 0; i < n; i++) {
        for (j = 0; j < m; j++) {
            double s = 0.0;
            for (k = 0; k < n; k++) {
                s += g->P.m[NMAX * i + k] * H[j][k];
            }
            PHt[i][j] = s;
        }
    }
    for (i = 0; i < m; i++) {
        for (j = 0; j < m; j++) {
            double s = 0.0;
            for (k = 0; k < n; k++) {
                s += H[i][k] * PHt[k][j];
            }
            S[i][j] = s + (i == j ? Rn[i] : 0.0);
        }
    }
    for (i = 0; i < m; i++) { /* exactly symmetric */
        for (j = 0; j < i; j++) {
            S[i][j] = S[j][i] = 0.5 * (S[i][j] + S[j][i]);
        }
    }
    if (!chol(S, m, L)) {
        return -1;
    }
    memcpy(y, z, sizeof y);
    chol_solve(L, m, y);
    q = 0.0;
    for (i = 0; i < m; i++) {
        q += z[i] * y[i];
    }
    *nis = q;
    if (gate > 0.0 && !(q <= gate)) {
        return 1;
    }
    /* K = P H^T S^-1, row by row (S symmetric) */
    for (i = 0; i < n; i++) {
        double r[MMAX];
        for (j = 0; j < m; j++) {
            r[j] = PHt[i][j];
        }
        chol_solve(L, m, r);
        for (j = 0; j < m; j++) {
            K[i][j] = r[j];
        }
    }
    for (i = 0; i < n; i++) {
        dx[i] = 0.0;
        for (j = 0; j < m; j++) {
            dx[i] += K[i][j] * z[j];
        }
    }
    /* Joseph form: P+ = A P A^T + K R K^T, A = I - K H */
    for (i = 0; i < n; i++) {
        for (j = 0; j < n; j++) {
            double s = (i == j) ? 1.0 : 0.0;
            for (k = 0; k < m; k++) {
                s -= K[i][k] * H[k][j];
            }
            A[i][j] = s;
        }
    }
    for (i = 0; i < n; i++) {
        for (j = 0; j < n; j++) {
            double s = 0.0;
            for (k = 0; k < n; k++) {
                s += A[i][k] * g->P.m[NMAX * k + j];
            }
            AP[i][j] = s;
        }
    }
    for (i = 0; i < n; i++) {
        for (j = 0; j <= i; j++) {
            double s = 0.0;
            for (k = 0; k < n; k++) {
                s += AP[i][k] * A[j][k];
            }
            for (k = 0; k < m; k++) {
                s += K[i][k] * Rn[k] * K[j][k];
            }
            Pn[i][j] = Pn[j][i] = s;
        }
    }
    for (i = 0; i < 9; i++) {
        xi.v[i] = dx[i];
    }
    if (se23_exp(&xi, &E) != SE23_OK) {
        return -1;
    }
    se23_compose(&g->T, &E, &Tn);
    out = *g;
    out.T = Tn;
    if (n == SE23_GAUSS_N_BIAS) {
        for (i = 0; i < 3; i++) {
            out.b_g.v[i] += dx[SE23_IDX_BG + i];
            out.b_a.v[i] += dx[SE23_IDX_BA + i];
        }
    }
    for (i = 0; i < n; i++) {
        for (j = 0; j < n; j++) {
            out.P.m[NMAX * i + j] = Pn[i][j];
        }
    }
    if (se23_gauss_check(&out) != SE23_OK) {
        return -1;
    }
    *g = out;
    return 0;
}
