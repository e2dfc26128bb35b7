/* Ready-made measurement models; see kalman.h. Each writes m = 3 (the
 * non-holonomic constraint: 2), the
 * residual z = y - h(Tbar, bbar), the three rows of H for the
 * right-multiplied error (all 15 columns, zero blocks included) and R's
 * leading 3x3 block: 3 + 45 + 9 stores. The entries beyond those rows,
 * which se23_kalman_update never reads, are left as they are (clearing
 * them cost more than the rest of the model). A residual or a Jacobian
 * entry that would overflow is refused before the first store. */
#include "se23/kalman.h"

#include "../base/argcheck.h"
#include "../base/linalg.h"
#include "kalman_halves.h"
#include "se23/se23.h"
#include "se23/so3.h"

enum {
    S = SE23_GAUSS_NMAX,
    M = SE23_MEAS_MMAX,
    NB = SE23_GAUSS_NMAX / 3 /* 3-column blocks of H: phi, nu, rho, b_g, b_a */
};

/* The checks of the caller's inputs: the nv vectors v[k] finite and cov a
 * valid covariance. */
static se23_status_t check_vecs(const se23_vec3_t *const *v, int nv,
                                const se23_mat3_t *cov)
{
    for (int k = 0; k < nv; ++k) {
        if (se23_all_finite(v[k]->v, 3) == 0) {
            return SE23_ERR_NONFINITE;
        }
    }
    return se23_meas_cov_check(&cov->m[0][0], 3, 3);
}

/* As check_vecs, T a valid pose first. */
static se23_status_t check_inputs(const se23_pose_t *T,
                                  const se23_vec3_t *const *v, int nv,
                                  const se23_mat3_t *cov)
{
    const se23_status_t st = se23_pose_check(T);
    if (st != SE23_OK) {
        return st;
    }
    return check_vecs(v, nv, cov);
}

/* out = -R u^, the Jacobian of R (x u) in phi for R = Rbar exp(phi^):
 * row i of -R u^ is u x (row i of R). */
static void neg_r_skew(const se23_mat3_t *R, const se23_vec3_t *u,
                       se23_mat3_t *out)
{
    for (int i = 0; i < 3; ++i) {
        const se23_vec3_t ri = {{R->m[i][0], R->m[i][1], R->m[i][2]}};
        se23_vec3_t a;
        se23_v3_cross(u, &ri, &a);
        for (int j = 0; j < 3; ++j) {
            out->m[i][j] = a.v[j];
        }
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

/* A 3-row measurement: m, z = meas - pred, R = cov, H = [blk[0], ...,
 * blk[4]] (blocks phi, nu, rho, b_g, b_a; NULL for a zero block); rows
 * beyond the third are not touched. Refuses (SE23_ERR_NONFINITE, nothing
 * written) a z or a block that overflowed. */
static se23_status_t put3(const se23_vec3_t *meas, const se23_vec3_t *pred,
                          const se23_mat3_t *cov,
                          const se23_mat3_t *const *blk, se23_meas_t *y)
{
    se23_vec3_t z;
    se23_v3_axpy(meas, SE23_R(-1), pred, &z);
    if (se23_all_finite(z.v, 3) == 0) {
        return SE23_ERR_NONFINITE;
    }
    for (int b = 0; b < NB; ++b) {
        if ((blk[b] != NULL) && (se23_all_finite(&blk[b]->m[0][0], 9) == 0)) {
            return SE23_ERR_NONFINITE;
        }
    }
    y->m = 3;
    for (int b = 0; b < NB; ++b) {
        put_block(y, 3 * b, blk[b]);
    }
    for (int i = 0; i < 3; ++i) {
        y->z[i] = z.v[i];
        for (int j = 0; j < 3; ++j) {
            y->R[M * i + j] = cov->m[i][j];
        }
    }
    return SE23_OK;
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
    const se23_vec3_t *const in[2] = {p_n, lever_b};
    const se23_status_t st = check_inputs(T, in, 2, cov);
    if (st != SE23_OK) {
        return st;
    }
    /* h = p + R l; H = [-R l^, 0, R, 0, 0]. */
    se23_vec3_t h;
    se23_mat3_t A;
    se23_act(T, lever_b, &h);
    neg_r_skew(&T->R, lever_b, &A);
    const se23_mat3_t *const blk[NB] = {&A, NULL, &T->R, NULL, NULL};
    return put3(p_n, &h, cov, blk, y);
}

se23_status_t se23_meas_vel_nav(const se23_pose_t *T, const se23_vec3_t *v_n,
                                const se23_mat3_t *cov, se23_meas_t *y)
{
    SE23_CHECK_NOT_NULL(T);
    SE23_CHECK_NOT_NULL(v_n);
    SE23_CHECK_NOT_NULL(cov);
    SE23_CHECK_NOT_NULL(y);
    const se23_vec3_t *const in[1] = {v_n};
    const se23_status_t st = check_inputs(T, in, 1, cov);
    if (st != SE23_OK) {
        return st;
    }
    const se23_mat3_t *const blk[NB] = {NULL, &T->R, NULL, NULL, NULL};
    return put3(v_n, &T->v, cov, blk, y);
}

se23_status_t se23_meas_vel_nav_lever(const se23_pose_t *T,
                                      const se23_vec3_t *w_b,
                                      const se23_vec3_t *lever_b,
                                      const se23_vec3_t *v_n,
                                      const se23_mat3_t *cov, se23_meas_t *y)
{
    SE23_CHECK_NOT_NULL(T);
    SE23_CHECK_NOT_NULL(w_b);
    SE23_CHECK_NOT_NULL(lever_b);
    SE23_CHECK_NOT_NULL(v_n);
    SE23_CHECK_NOT_NULL(cov);
    SE23_CHECK_NOT_NULL(y);
    const se23_vec3_t *const in[3] = {w_b, lever_b, v_n};
    const se23_status_t st = check_inputs(T, in, 3, cov);
    if (st != SE23_OK) {
        return st;
    }
    /* h = v + R u, u = w x l (kalman.h); H = [-R u^, R, 0, -R l^, 0]. */
    se23_vec3_t u, h;
    se23_mat3_t A, D;
    se23_v3_cross(w_b, lever_b, &u);
    se23_m3_mul_v3(&T->R, &u, &h);
    se23_v3_axpy(&T->v, SE23_R(1), &h, &h);
    neg_r_skew(&T->R, &u, &A);
    neg_r_skew(&T->R, lever_b, &D);
    const se23_mat3_t *const blk[NB] = {&A, &T->R, NULL, &D, NULL};
    return put3(v_n, &h, cov, blk, y);
}

se23_status_t se23_meas_vel_body(const se23_pose_t *T, const se23_vec3_t *v_b,
                                 const se23_mat3_t *cov, se23_meas_t *y)
{
    SE23_CHECK_NOT_NULL(T);
    SE23_CHECK_NOT_NULL(v_b);
    SE23_CHECK_NOT_NULL(cov);
    SE23_CHECK_NOT_NULL(y);
    const se23_vec3_t *const in[1] = {v_b};
    const se23_status_t st = check_inputs(T, in, 1, cov);
    if (st != SE23_OK) {
        return st;
    }
    /* h = R^T v; H = [h^, I, 0, 0, 0]. */
    se23_vec3_t h;
    se23_mat3_t A, I;
    se23_m3_tmul_v3(&T->R, &T->v, &h);
    se23_m3_skew(&h, &A);
    se23_m3_identity(&I);
    const se23_mat3_t *const blk[NB] = {&A, &I, NULL, NULL, NULL};
    return put3(v_b, &h, cov, blk, y);
}

se23_status_t se23_meas_zero_rate(const se23_vec3_t *w_meas,
                                  const se23_vec3_t *b_g,
                                  const se23_mat3_t *cov, se23_meas_t *y)
{
    SE23_CHECK_NOT_NULL(w_meas);
    SE23_CHECK_NOT_NULL(b_g);
    SE23_CHECK_NOT_NULL(cov);
    SE23_CHECK_NOT_NULL(y);
    const se23_vec3_t *const in[2] = {w_meas, b_g};
    const se23_status_t st = check_vecs(in, 2, cov);
    if (st != SE23_OK) {
        return st;
    }
    /* y = 0, h = w_meas + b_g; H = [0, 0, 0, I, 0]. */
    const se23_vec3_t rest = {{SE23_R(0), SE23_R(0), SE23_R(0)}};
    se23_vec3_t h;
    se23_mat3_t I;
    se23_v3_axpy(w_meas, SE23_R(1), b_g, &h);
    se23_m3_identity(&I);
    const se23_mat3_t *const blk[NB] = {NULL, NULL, NULL, &I, NULL};
    return put3(&rest, &h, cov, blk, y);
}

se23_status_t se23_meas_nhc(const se23_pose_t *T, const se23_mat3_t *C_bv, se23_real_t sigma,
                            se23_meas_t *y)
{
    SE23_CHECK_NOT_NULL(T);
    SE23_CHECK_NOT_NULL(C_bv);
    SE23_CHECK_NOT_NULL(y);
    se23_status_t st = se23_pose_check(T);
    if (st == SE23_OK) {
        st = se23_so3_check(C_bv);
    }
    if (st != SE23_OK) {
        return st;
    }
    if (!((sigma > SE23_R(0)) && (sigma <= SE23_MEAS_NHC_SIGMA_MAX))) {
        return SE23_ERR_DOMAIN;
    }
    /* u = R^T v, the body velocity; h_r = c_r . u for c_r = column r of
     * C_bv (the vehicle's right and down axes in the body frame), and
     * H_r = c_r^T [u^, I, 0, 0, 0] (se23_meas_vel_body's H): c^T u^ phi =
     * c . (u x phi) = (c x u) . phi, so H_r = [(c_r x u)^T, c_r^T, 0...].
     * 27 multiplies. */
    se23_vec3_t u;
    se23_real_t z[2], H[2][6];
    se23_m3_tmul_v3(&T->R, &T->v, &u);
    for (int r = 0; r < 2; ++r) {
        const se23_vec3_t c = {{C_bv->m[0][r + 1], C_bv->m[1][r + 1], C_bv->m[2][r + 1]}};
        se23_vec3_t cu;
        se23_v3_cross(&c, &u, &cu);
        z[r] = -se23_v3_dot(&c, &u);
        for (int j = 0; j < 3; ++j) {
            H[r][j] = cu.v[j];
            H[r][3 + j] = c.v[j];
        }
    }
    if ((se23_all_finite(z, 2) == 0) || (se23_all_finite(&H[0][0], 12) == 0)) {
        return SE23_ERR_NONFINITE;
    }
    y->m = 2;
    for (int r = 0; r < 2; ++r) {
        y->z[r] = z[r];
        for (int j = 0; j < S; ++j) {
            y->H[(S * r) + j] = (j < 6) ? H[r][j] : SE23_R(0);
        }
        y->R[(M * r) + r] = sigma * sigma;
        y->R[(M * r) + (1 - r)] = SE23_R(0);
    }
    return SE23_OK;
}
