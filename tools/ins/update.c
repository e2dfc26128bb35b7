/* GNSS measurement update of the INS engine; see update.h. */
#include "update.h"

#include <string.h>

#include "se23/kalman.h"

/* Appends the rows of a to y. */
static void stack(se23_meas_t *y, const se23_meas_t *a)
{
    int i, j;
    for (i = 0; i < a->m; i++) {
        y->z[y->m + i] = a->z[i];
        memcpy(&y->H[SE23_GAUSS_NMAX * (y->m + i)], &a->H[SE23_GAUSS_NMAX * i],
               sizeof(se23_real_t) * SE23_GAUSS_NMAX);
        for (j = 0; j < a->m; j++) {
            y->R[SE23_MEAS_MMAX * (y->m + i) + y->m + j] = a->R[SE23_MEAS_MMAX * i + j];
        }
    }
    y->m += a->m;
}

/* Diagonal covariance from 1-sigma values; -1 unless each is finite and > 0. */
static int diag_cov(const double sig[3], se23_mat3_t *C)
{
    int i;
    memset(C, 0, sizeof *C);
    for (i = 0; i < 3; i++) {
        if (!(sig[i] > 0.0 && sig[i] < 1e150)) {
            return -1;
        }
        C->m[i][i] = sig[i] * sig[i];
    }
    return 0;
}

int ins_update_gnss(se23_gauss_t *g, const ins_gnss_t *fix, double gate, double *nis)
{
    se23_meas_t y, part;
    se23_vec3_t meas, no_lever = {{0.0, 0.0, 0.0}};
    se23_mat3_t C;
    se23_gauss_t out;
    se23_real_t q;
    int i;
    memset(&y, 0, sizeof y);
    for (i = 0; i < 3; i++) {
        meas.v[i] = fix->p_n[i];
    }
    if (diag_cov(fix->sigma_p, &C) != 0 ||
        se23_meas_pos_nav(&g->T, &meas, &no_lever, &C, &part) != SE23_OK) {
        return -1;
    }
    stack(&y, &part);
    if (fix->has_vel) {
        for (i = 0; i < 3; i++) {
            meas.v[i] = fix->v_n[i];
        }
        if (diag_cov(fix->sigma_v, &C) != 0 ||
            se23_meas_vel_nav(&g->T, &meas, &C, &part) != SE23_OK) {
            return -1;
        }
        stack(&y, &part);
    }
    if (se23_kalman_update(g, &y, &out, &q) != SE23_OK) {
        return -1;
    }
    *nis = q;
    if (gate > 0.0 && !(q <= gate)) {
        return 1;
    }
    *g = out;
    return 0;
}
