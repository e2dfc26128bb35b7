/* Ready-made measurement models; see kalman.h. Each writes the residual
 * z = y - h(Tbar), the rows of H for the right-multiplied error and R, and
 * zeros in every entry beyond the m = 3 rows: every element of the output
 * exactly once (z 9, H 135, R 81 stores), so the output is fully defined
 * whatever the caller's buffer held. */
#include "se23/kalman.h"

#include "argcheck.h"
#include "linalg.h"
#include "kalman_parts.h"
#include "se23/se23.h"

enum { S = SE23_GAUSS_NMAX, M = SE23_MEAS_MMAX, BG = SE23_IDX_BG };

/* Shared checks: T a valid pose, the measured vectors finite, cov valid. */
static se23_status_t check_inputs(const se23_pose_t *T, const se23_vec3_t *a,
                                  const se23_vec3_t *b, const se23_mat3_t *cov)
{
    se23_status_t st = se23_pose_check(T);
    if (st != SE23_OK) {
        return st;
    }
    if (!se23_all_finite(a->v, 3) || !se23_all_finite(b->v, 3)) {
        return SE23_ERR_NONFINITE;
    }
    return se23_meas_cov_check(&cov->m[0][0], 3, 3);
}

/* x[0..n-1] = 0 */
static void zero(se23_real_t *x, int n)
{
    for (int i = 0; i < n; ++i) {
        x[i] = SE23_R(0);
    }
}

/* Rows 0..2, columns col..col+2 of H = A, or 0 if A is NULL. */
static void put_block(se23_meas_t *y, int col, const se23_mat3_t *A)
{
    for (int i = 0; i < 3; ++i) {
        se23_real_t *h = &y->H[S * i + col];
        for (int j = 0; j < 3; ++j) {
            h[j] = (A != NULL) ? A->m[i][j] : SE23_R(0);
        }
    }
}

/* A 3-row measurement: m, z = meas - pred, R = cov, H = [A, B, C, 0, 0]
 * (blocks phi, nu, rho, b_g, b_a; NULL for a zero block), and zeros in
 * every entry beyond the three rows. Written only once every check has
 * passed; every element once. */
static void put3(const se23_vec3_t *meas, const se23_vec3_t *pred,
                 const se23_mat3_t *cov, const se23_mat3_t *A,
                 const se23_mat3_t *B, const se23_mat3_t *C, se23_meas_t *y)
{
    y->m = 3;
    put_block(y, SE23_IDX_PHI, A);
    put_block(y, SE23_IDX_NU, B);
    put_block(y, SE23_IDX_RHO, C);
    for (int i = 0; i < 3; ++i) {
        y->z[i] = meas->v[i] - pred->v[i];
        for (int j = 0; j < 3; ++j) {
            y->R[M * i + j] = cov->m[i][j];
        }
    }
    /* The zeros, as contiguous runs: bias columns of rows 0 and 1, then
     * row 2's bias columns through the end of H; likewise for R. */
    zero(&y->z[3], M - 3);
    zero(&y->H[BG], S - BG);
    zero(&y->H[S + BG], S - BG);
    zero(&y->H[2 * S + BG], S * M - (2 * S + BG));
    zero(&y->R[3], M - 3);
    zero(&y->R[M + 3], M - 3);
    zero(&y->R[2 * M + 3], M * M - (2 * M + 3));
}

se23_status_t se23_meas_pos_nav(const se23_pose_t *T, const se23_vec3_t *p_n,
                                const se23_vec3_t *lever_b,
                                const se23_mat3_t *cov, se23_meas_t *y)
{
    SE23_CHECK_NOT_NULL(T);
    SE23_CHECK_NOT_NULL(p_n);
    SE23_CHECK_NOT_NULL(lever_b);
    SE23_CHECK_NOT_NULL(cov);
    SE23_CHECK_NOT_NULL(y);
    const se23_status_t st = check_inputs(T, p_n, lever_b, cov);
    if (st != SE23_OK) {
        return st;
    }
    /* h = p + R l; H_phi = -R l^, whose row i is l x (row i of R). */
    se23_vec3_t h;
    se23_mat3_t A;
    se23_act(T, lever_b, &h);
    for (int i = 0; i < 3; ++i) {
        const se23_vec3_t ri = {{T->R.m[i][0], T->R.m[i][1], T->R.m[i][2]}};
        se23_vec3_t a;
        se23_v3_cross(lever_b, &ri, &a);
        for (int j = 0; j < 3; ++j) {
            A.m[i][j] = a.v[j];
        }
    }
    put3(p_n, &h, cov, &A, NULL, &T->R, y);
    return SE23_OK;
}

se23_status_t se23_meas_vel_nav(const se23_pose_t *T, const se23_vec3_t *v_n,
                                const se23_mat3_t *cov, se23_meas_t *y)
{
    SE23_CHECK_NOT_NULL(T);
    SE23_CHECK_NOT_NULL(v_n);
    SE23_CHECK_NOT_NULL(cov);
    SE23_CHECK_NOT_NULL(y);
    const se23_status_t st = check_inputs(T, v_n, v_n, cov);
    if (st != SE23_OK) {
        return st;
    }
    put3(v_n, &T->v, cov, NULL, &T->R, NULL, y);
    return SE23_OK;
}

se23_status_t se23_meas_vel_body(const se23_pose_t *T, const se23_vec3_t *v_b,
                                 const se23_mat3_t *cov, se23_meas_t *y)
{
    SE23_CHECK_NOT_NULL(T);
    SE23_CHECK_NOT_NULL(v_b);
    SE23_CHECK_NOT_NULL(cov);
    SE23_CHECK_NOT_NULL(y);
    const se23_status_t st = check_inputs(T, v_b, v_b, cov);
    if (st != SE23_OK) {
        return st;
    }
    /* h = R^T v; H = [h^, I, 0]. */
    se23_vec3_t h;
    se23_mat3_t A, I;
    se23_m3_tmul_v3(&T->R, &T->v, &h);
    se23_m3_skew(&h, &A);
    se23_m3_identity(&I);
    put3(v_b, &h, cov, &A, &I, NULL, y);
    return SE23_OK;
}
