/* SE_2(3): see se23.h. */
#include "se23/se23.h"

#include "../base/argcheck.h"
#include "../base/linalg.h"
#include "se23/so3.h"
#include "../base/se23_math.h"
#include "so3_series.h"

void se23_identity(se23_pose_t *T)
{
    se23_m3_identity(&T->R);
    for (int i = 0; i < 3; ++i) {
        T->v.v[i] = SE23_R(0);
        T->p.v[i] = SE23_R(0);
    }
}

/* out = Phi_t(A) B = (Ra Rb, Ra vb + va, Ra pb + pa + t va), straight
 * line: every operand is loaded once before the first store, so out may
 * not alias A or B. [27 + 9 + 9 + 3 multiply-adds] */
void se23_pose_mul_phi(const se23_pose_t *A, const se23_pose_t *B, se23_real_t t,
                       se23_pose_t *out)
{
    const se23_real_t a00 = A->R.m[0][0], a01 = A->R.m[0][1], a02 = A->R.m[0][2];
    const se23_real_t a10 = A->R.m[1][0], a11 = A->R.m[1][1], a12 = A->R.m[1][2];
    const se23_real_t a20 = A->R.m[2][0], a21 = A->R.m[2][1], a22 = A->R.m[2][2];
    for (int j = 0; j < 3; ++j) {
        const se23_real_t b0 = B->R.m[0][j], b1 = B->R.m[1][j], b2 = B->R.m[2][j];
        out->R.m[0][j] = a00 * b0 + a01 * b1 + a02 * b2;
        out->R.m[1][j] = a10 * b0 + a11 * b1 + a12 * b2;
        out->R.m[2][j] = a20 * b0 + a21 * b1 + a22 * b2;
    }
    const se23_real_t v0 = B->v.v[0], v1 = B->v.v[1], v2 = B->v.v[2];
    const se23_real_t p0 = B->p.v[0], p1 = B->p.v[1], p2 = B->p.v[2];
    const se23_real_t u0 = A->v.v[0], u1 = A->v.v[1], u2 = A->v.v[2];
    /* Summed as (Ra vb) + va and (Ra pb) + (pa + t va): one rounding of
     * the large translation, as in the plain product. */
    out->v.v[0] = (a00 * v0 + a01 * v1 + a02 * v2) + u0;
    out->v.v[1] = (a10 * v0 + a11 * v1 + a12 * v2) + u1;
    out->v.v[2] = (a20 * v0 + a21 * v1 + a22 * v2) + u2;
    out->p.v[0] = (a00 * p0 + a01 * p1 + a02 * p2) + (A->p.v[0] + t * u0);
    out->p.v[1] = (a10 * p0 + a11 * p1 + a12 * p2) + (A->p.v[1] + t * u1);
    out->p.v[2] = (a20 * p0 + a21 * p1 + a22 * p2) + (A->p.v[2] + t * u2);
}

void se23_compose(const se23_pose_t *A, const se23_pose_t *B, se23_pose_t *AB)
{
    se23_pose_t out;
    se23_pose_mul_phi(A, B, SE23_R(0), &out);
    *AB = out;
}

void se23_inverse(const se23_pose_t *T, se23_pose_t *Tinv)
{
    se23_pose_t out;
    se23_m3_transpose(&T->R, &out.R);
    se23_m3_tmul_v3(&T->R, &T->v, &out.v);
    se23_m3_tmul_v3(&T->R, &T->p, &out.p);
    se23_v3_scale(&out.v, SE23_R(-1), &out.v);
    se23_v3_scale(&out.p, SE23_R(-1), &out.p);
    *Tinv = out;
}

void se23_act(const se23_pose_t *T, const se23_vec3_t *x, se23_vec3_t *y)
{
    se23_vec3_t out;
    se23_m3_mul_v3(&T->R, x, &out);
    se23_v3_axpy(&out, SE23_R(1), &T->p, y);
}

void se23_hat(const se23_tangent_t *xi, se23_mat5_t *X)
{
    se23_vec3_t phi;
    se23_mat3_t W;
    se23_v3_load(&xi->v[SE23_IDX_PHI], &phi);
    se23_m3_skew(&phi, &W);
    se23_mat5_t out = {{{0}}};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            out.m[i][j] = W.m[i][j];
        }
        out.m[i][3] = xi->v[SE23_IDX_NU + i];
        out.m[i][4] = xi->v[SE23_IDX_RHO + i];
    }
    *X = out;
}

void se23_vee(const se23_mat5_t *X, se23_tangent_t *xi)
{
    se23_tangent_t out;
    out.v[SE23_IDX_PHI] = SE23_R(0.5) * (X->m[2][1] - X->m[1][2]);
    out.v[SE23_IDX_PHI + 1] = SE23_R(0.5) * (X->m[0][2] - X->m[2][0]);
    out.v[SE23_IDX_PHI + 2] = SE23_R(0.5) * (X->m[1][0] - X->m[0][1]);
    for (int i = 0; i < 3; ++i) {
        out.v[SE23_IDX_NU + i] = X->m[i][3];
        out.v[SE23_IDX_RHO + i] = X->m[i][4];
    }
    *xi = out;
}

void se23_to_mat5(const se23_pose_t *T, se23_mat5_t *M)
{
    se23_mat5_t out = {{{0}}};
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            out.m[i][j] = T->R.m[i][j];
        }
        out.m[i][3] = T->v.v[i];
        out.m[i][4] = T->p.v[i];
    }
    out.m[3][3] = SE23_R(1);
    out.m[4][4] = SE23_R(1);
    *M = out;
}

se23_status_t se23_from_mat5(const se23_mat5_t *M, se23_pose_t *T)
{
    SE23_CHECK_NOT_NULL(M);
    SE23_CHECK_NOT_NULL(T);
    if (!se23_all_finite(&M->m[0][0], 25)) {
        return SE23_ERR_NONFINITE;
    }
    for (int i = 3; i < 5; ++i) {
        for (int j = 0; j < 5; ++j) {
            const se23_real_t expected = (i == j) ? SE23_R(1) : SE23_R(0);
            if (!(se23_fabs(M->m[i][j] - expected) <= SE23_R(SE23_CFG_ROT_TOL))) {
                return SE23_ERR_DOMAIN;
            }
        }
    }
    se23_pose_t out;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            out.R.m[i][j] = M->m[i][j];
        }
        out.v.v[i] = M->m[i][3];
        out.p.v[i] = M->m[i][4];
    }
    se23_status_t st = se23_so3_check(&out.R);
    if (st != SE23_OK) {
        return st;
    }
    *T = out;
    return SE23_OK;
}

se23_status_t se23_exp(const se23_tangent_t *xi, se23_pose_t *T)
{
    SE23_CHECK_NOT_NULL(xi);
    SE23_CHECK_NOT_NULL(T);
    if (!se23_all_finite(xi->v, 9)) {
        return SE23_ERR_NONFINITE;
    }
    se23_vec3_t phi;
    se23_vec3_t nu;
    se23_vec3_t rho;
    se23_v3_load(&xi->v[SE23_IDX_PHI], &phi);
    se23_v3_load(&xi->v[SE23_IDX_NU], &nu);
    se23_v3_load(&xi->v[SE23_IDX_RHO], &rho);
    /* exp(phi^) = I + c1 W + c2 W^2 and J_l = I + c2 W + c3 W^2 share
     * their coefficients: evaluate them once. */
    se23_so3_coeffs_t c;
    se23_so3_coeffs(se23_sqrt(se23_v3_dot(&phi, &phi)), &c);
    se23_pose_t out;
    se23_mat3_t J;
    se23_m3_series(SE23_R(1), c.c1, c.c2, &phi, &out.R);
    se23_m3_series(SE23_R(1), c.c2, c.c3, &phi, &J);
    se23_m3_mul_v3(&J, &nu, &out.v);
    se23_m3_mul_v3(&J, &rho, &out.p);
    if (!se23_pose_finite(&out)) {
        return SE23_ERR_NONFINITE; /* |phi|^2 or J nu overflowed */
    }
    *T = out;
    return SE23_OK;
}

se23_status_t se23_log(const se23_pose_t *T, se23_tangent_t *xi)
{
    SE23_CHECK_NOT_NULL(T);
    SE23_CHECK_NOT_NULL(xi);
    if (!se23_all_finite(T->v.v, 3) || !se23_all_finite(T->p.v, 3)) {
        return SE23_ERR_NONFINITE;
    }
    se23_vec3_t phi;
    se23_status_t st = se23_so3_log(&T->R, &phi);
    if (st != SE23_OK) {
        return st;
    }
    se23_mat3_t Jinv;
    (void)se23_so3_jl_inv(&phi, &Jinv); /* cannot fail: |phi| <= pi */
    se23_vec3_t nu;
    se23_vec3_t rho;
    se23_m3_mul_v3(&Jinv, &T->v, &nu);
    se23_m3_mul_v3(&Jinv, &T->p, &rho);
    /* |J_l^-1| exceeds 1: a v or p near the largest real can overflow. */
    if (!se23_all_finite(nu.v, 3) || !se23_all_finite(rho.v, 3)) {
        return SE23_ERR_NONFINITE;
    }
    se23_v3_store(&phi, &xi->v[SE23_IDX_PHI]);
    se23_v3_store(&nu, &xi->v[SE23_IDX_NU]);
    se23_v3_store(&rho, &xi->v[SE23_IDX_RHO]);
    return SE23_OK;
}

/* Writes the 3x3 block (bi, bj) of a 9x9 matrix. */
static void mat9_set_block(se23_mat9_t *M, int bi, int bj, const se23_mat3_t *B)
{
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            M->m[9 * (3 * bi + i) + 3 * bj + j] = B->m[i][j];
        }
    }
}

/* Ad = [[A, 0, 0], [B, A, 0], [C, 0, A]]: the shape of Ad_T and Ad_{T^-1}. */
static void adjoint_from_blocks(const se23_mat3_t *A, const se23_mat3_t *B,
                                const se23_mat3_t *C, se23_mat9_t *Ad)
{
    for (int k = 0; k < 81; ++k) {
        Ad->m[k] = SE23_R(0);
    }
    for (int b = 0; b < 3; ++b) {
        mat9_set_block(Ad, b, b, A);
    }
    mat9_set_block(Ad, 1, 0, B);
    mat9_set_block(Ad, 2, 0, C);
}

void se23_adjoint(const se23_pose_t *T, se23_mat9_t *Ad)
{
    se23_mat3_t vx;
    se23_mat3_t px;
    se23_m3_skew(&T->v, &vx);
    se23_m3_skew(&T->p, &px);
    se23_m3_mul(&vx, &T->R, &vx); /* v^ R */
    se23_m3_mul(&px, &T->R, &px); /* p^ R */
    adjoint_from_blocks(&T->R, &vx, &px, Ad);
}

void se23_adjoint_inv(const se23_pose_t *T, se23_mat9_t *Ad)
{
    se23_mat3_t Rt;
    se23_mat3_t vx;
    se23_mat3_t px;
    se23_vec3_t minus_v;
    se23_vec3_t minus_p;
    se23_m3_transpose(&T->R, &Rt);
    se23_v3_scale(&T->v, SE23_R(-1), &minus_v);
    se23_v3_scale(&T->p, SE23_R(-1), &minus_p);
    se23_m3_skew(&minus_v, &vx);
    se23_m3_skew(&minus_p, &px);
    se23_m3_mul(&Rt, &vx, &vx); /* -R^T v^ */
    se23_m3_mul(&Rt, &px, &px); /* -R^T p^ */
    adjoint_from_blocks(&Rt, &vx, &px, Ad);
}

se23_status_t se23_pose_check(const se23_pose_t *T)
{
    SE23_CHECK_NOT_NULL(T);
    if (!se23_all_finite(T->v.v, 3) || !se23_all_finite(T->p.v, 3)) {
        return SE23_ERR_NONFINITE;
    }
    return se23_so3_check(&T->R);
}
