/* Errors, sigmas and NEES; see metrics.h. */
#include "metrics.h"

#include <math.h>
#include <string.h>

#include "../lcm/ldmath.h"

double metrics_nees(const double *P, int stride, const double *e, int n)
{
    ld_t L[15][15], y[15], q = 0.0L;
    int i, j, k;
    for (j = 0; j < n; j++) {
        ld_t d = P[stride * j + j];
        for (k = 0; k < j; k++) {
            d -= L[j][k] * L[j][k];
        }
        if (!(d > 0.0L)) {
            return NAN;
        }
        L[j][j] = sqrtl(d);
        for (i = j + 1; i < n; i++) {
            ld_t s = P[stride * i + j];
            for (k = 0; k < j; k++) {
                s -= L[i][k] * L[j][k];
            }
            L[i][j] = s / L[j][j];
        }
    }
    for (i = 0; i < n; i++) { /* y = L^-1 e, NEES = |y|^2 */
        ld_t s = e[i];
        for (k = 0; k < i; k++) {
            s -= L[i][k] * y[k];
        }
        y[i] = s / L[i][i];
        q += y[i] * y[i];
    }
    return (double)q;
}

void metrics_nav_cov(const double R_nb[9], const double *P, int b, double C[3][3])
{
    const ld_mat3_t R = ld_mat3_from(R_nb);
    ld_mat3_t B, RB;
    int i, j;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            B.m[i][j] = P[15 * (b + i) + b + j];
        }
    }
    RB = ld_mul(&R, &B);
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            C[i][j] = (double)(RB.m[i][0] * R.m[j][0] + RB.m[i][1] * R.m[j][1] +
                               RB.m[i][2] * R.m[j][2]);
        }
    }
}

/* sigma of each nav axis of Rhat P_blk Rhat^T, P_blk the 3x3 block at b. */
static void nav_sigma(const double R_nb[9], const double *P, int b, double out[3])
{
    double C[3][3];
    int i;
    metrics_nav_cov(R_nb, P, b, C);
    for (i = 0; i < 3; i++) {
        out[i] = C[i][i] > 0.0 ? sqrt(C[i][i]) : 0.0;
    }
}

void metrics_epoch(const se23lcm_truth *tr, const se23lcm_nav_state *nav, epoch_t *e)
{
    ld_mat3_t R = ld_mat3_from(tr->R_nb), Rh = ld_mat3_from(nav->R_nb);
    ld_mat3_t E = ld_mul_tn(&Rh, &R), En, Jinv;
    ld_vec3_t phi = ld_log(&E), dth, dv_b, dp_b, nu, rho;
    ld_mat3_t Rt = ld_transpose(&Rh);
    double err[15];
    int i, has_bias = 0;
    memset(e, 0, sizeof *e);
    e->t = (double)tr->t_ns * 1e-9;
    En = ld_mul(&R, &Rt);
    dth = ld_log(&En);
    for (i = 0; i < 3; i++) {
        e->p_true[i] = tr->p_n[i];
        e->p_est[i] = nav->p_n[i];
        e->dp[i] = tr->p_n[i] - nav->p_n[i];
        e->dv[i] = tr->v_n[i] - nav->v_n[i];
        e->dth[i] = (double)dth.v[i];
        e->bg_true[i] = tr->b_g[i];
        e->bg_est[i] = nav->b_g[i];
        e->ba_true[i] = tr->b_a[i];
        e->ba_est[i] = nav->b_a[i];
        e->sbg[i] = sqrt(fmax(nav->P[15 * (9 + i) + 9 + i], 0.0));
        e->sba[i] = sqrt(fmax(nav->P[15 * (12 + i) + 12 + i], 0.0));
        has_bias |= nav->P[15 * (9 + i) + 9 + i] > 0.0 || nav->P[15 * (12 + i) + 12 + i] > 0.0;
    }
    nav_sigma(nav->R_nb, nav->P, 0, e->sth);
    nav_sigma(nav->R_nb, nav->P, 3, e->sv);
    nav_sigma(nav->R_nb, nav->P, 6, e->sp);
    /* exact xi = log(That^-1 T) */
    {
        ld_vec3_t dv = {{e->dv[0], e->dv[1], e->dv[2]}};
        ld_vec3_t dp = {{e->dp[0], e->dp[1], e->dp[2]}};
        ld_mat3_t J = ld_jl(&phi);
        dv_b = ld_mul_v(&Rt, &dv);
        dp_b = ld_mul_v(&Rt, &dp);
        Jinv = ld_inv(&J);
        nu = ld_mul_v(&Jinv, &dv_b);
        rho = ld_mul_v(&Jinv, &dp_b);
    }
    for (i = 0; i < 3; i++) {
        err[i] = (double)phi.v[i];
        err[3 + i] = (double)nu.v[i];
        err[6 + i] = (double)rho.v[i];
        err[9 + i] = tr->b_g[i] - nav->b_g[i];
        err[12 + i] = tr->b_a[i] - nav->b_a[i];
    }
    e->nees9 = metrics_nees(nav->P, 15, err, 9);
    e->nees15 = has_bias ? metrics_nees(nav->P, 15, err, 15) : NAN;
    e->status = nav->status;
}
