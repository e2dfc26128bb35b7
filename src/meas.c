/* Ready-made measurement models; see kalman.h. Each writes the residual
 * z = y - h(Tbar) and the rows of H for the right-multiplied error. */
#include "se23/kalman.h"

#include "argcheck.h"
#include "cov.h"
#include "linalg.h"
#include "se23/se23.h"

enum { S = SE23_GAUSS_NMAX, M = SE23_MEAS_MMAX };

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
    return se23_cov_check(&cov->m[0][0], 3, 3);
}

/* y = 3-row measurement with residual meas - pred, zero H, R = cov.
 * Written in place: called only once every check has passed. */
static void init3(const se23_vec3_t *meas, const se23_vec3_t *pred,
                  const se23_mat3_t *cov, se23_meas_t *y)
{
    y->m = 3;
    for (int i = 0; i < M; ++i) {
        y->z[i] = SE23_R(0);
        for (int j = 0; j < S; ++j) {
            y->H[S * i + j] = SE23_R(0);
        }
        for (int j = 0; j < M; ++j) {
            y->R[M * i + j] = SE23_R(0);
        }
    }
    for (int i = 0; i < 3; ++i) {
        y->z[i] = meas->v[i] - pred->v[i];
        for (int j = 0; j < 3; ++j) {
            y->R[M * i + j] = cov->m[i][j];
        }
    }
}

/* Rows 0..2, columns col..col+2 of H = A. */
static void put_h(se23_meas_t *y, int col, const se23_mat3_t *A)
{
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            y->H[S * i + col + j] = A->m[i][j];
        }
    }
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
    se23_vec3_t h, neg_l;
    se23_mat3_t A;
    se23_act(T, lever_b, &h); /* p + R l */
    se23_v3_scale(lever_b, SE23_R(-1), &neg_l);
    se23_m3_skew(&neg_l, &A);
    se23_m3_mul(&T->R, &A, &A); /* -R l^ */
    init3(p_n, &h, cov, y);
    put_h(y, SE23_IDX_PHI, &A);
    put_h(y, SE23_IDX_RHO, &T->R);
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
    init3(v_n, &T->v, cov, y);
    put_h(y, SE23_IDX_NU, &T->R);
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
    se23_vec3_t h;
    se23_mat3_t A, I;
    se23_m3_tmul_v3(&T->R, &T->v, &h); /* R^T v */
    se23_m3_skew(&h, &A);
    se23_m3_identity(&I);
    init3(v_b, &h, cov, y);
    put_h(y, SE23_IDX_PHI, &A);
    put_h(y, SE23_IDX_NU, &I);
    return SE23_OK;
}
