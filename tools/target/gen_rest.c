/* The filter's second rest test recomputed in double; see gen_rest.h. */
#include "gen_rest.h"

#include <string.h>

double gen_accel_nis(const se23_ins_t *ins, const se23_gauss_t *x, const se23_real_t f_raw[3])
{
    const se23_stationary_t *d = &ins->det;
    const int W = d->cfg.window;
    double R[3][3], f[3], a_n[3] = {0.0, 0.0, 0.0}, a[3], F[3][3], C[3][3], y[3];
    double det, nis = 0.0;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            R[i][j] = x->T.R.m[i][j];
        }
        f[i] = f_raw[i] + x->b_a.v[i];
        for (int k = 0; k < W; ++k) {
            a_n[i] += d->f[k].v[i] / W;
        }
        a_n[i] += ins->model.g_n.v[i];
    }
    for (int i = 0; i < 3; ++i) {
        a[i] = R[0][i] * a_n[0] + R[1][i] * a_n[1] + R[2][i] * a_n[2];
    }
    memset(F, 0, sizeof F);
    F[0][1] = -f[2];
    F[0][2] = f[1];
    F[1][0] = f[2];
    F[1][2] = -f[0];
    F[2][0] = -f[1];
    F[2][1] = f[0];
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double c = (i == j) ? (double)d->cfg.sigma_a * d->cfg.sigma_a / W : 0.0;
            for (int k = 0; k < 3; ++k) {
                for (int l = 0; l < 3; ++l) {
                    c += F[i][k] * x->P.m[SE23_GAUSS_NMAX * k + l] * F[j][l];
                }
                if (x->n == SE23_GAUSS_N_BIAS) {
                    c -= F[i][k] * x->P.m[SE23_GAUSS_NMAX * k + SE23_IDX_BA + j];
                    c -= F[j][k] * x->P.m[SE23_GAUSS_NMAX * k + SE23_IDX_BA + i];
                }
            }
            if (x->n == SE23_GAUSS_N_BIAS) {
                c += x->P.m[SE23_GAUSS_NMAX * (SE23_IDX_BA + i) + SE23_IDX_BA + j];
            }
            C[i][j] = c;
        }
    }
    /* y = C^-1 a by the adjugate */
    det = C[0][0] * (C[1][1] * C[2][2] - C[1][2] * C[2][1]) -
          C[0][1] * (C[1][0] * C[2][2] - C[1][2] * C[2][0]) +
          C[0][2] * (C[1][0] * C[2][1] - C[1][1] * C[2][0]);
    for (int i = 0; i < 3; ++i) {
        const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
        y[i] = 0.0;
        for (int j = 0; j < 3; ++j) {
            const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            y[i] += (C[j1][i1] * C[j2][i2] - C[j1][i2] * C[j2][i1]) * a[j]; /* adj(C)[i][j] */
        }
        nis += a[i] * y[i] / det;
    }
    return nis;
}
