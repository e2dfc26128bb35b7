/* Concentrated Gaussians on SE_2(3): F_k, covariance propagation with
 * optional bias states, the noise model and the carried <-> user conversion;
 * see gauss.h. The per-sample covariance step is the block kernel of
 * cov_step.h (rotation and shear factors of F_k, never a dense product). */
#include "se23/gauss.h"

#include "../base/argcheck.h"
#include "cov_check.h"
#include "cov_step.h"
#include "../imu/imu_step.h"
#include "../base/linalg.h"
#include "se23/se23.h"
#include "../base/se23_math.h"

enum { S = SE23_GAUSS_NMAX };

static se23_status_t dt_check(se23_real_t dt)
{
    if (!(dt > SE23_R(0) && dt <= SE23_R(SE23_CFG_DT_MAX))) {
        return SE23_ERR_DT;
    }
    return SE23_OK;
}

/* The state a step is handed: n is checked (O(1)); the rest is trusted
 * (types.h, "Validation policy") unless SE23_CFG_DEEP_CHECKS. */
static se23_status_t state_check(const se23_gauss_t *g)
{
#if SE23_CFG_DEEP_CHECKS
    return se23_gauss_check(g);
#else
    if (g->n != SE23_GAUSS_N_POSE && g->n != SE23_GAUSS_N_BIAS) {
        return SE23_ERR_DIM;
    }
    return SE23_OK;
#endif
}

void se23_gauss_fk_apply(const se23_pose_t *U, se23_real_t dt,
                         const se23_tangent_t *x, se23_tangent_t *y)
{
    se23_vec3_t xp, xn, xr, c, t, out[3];
    se23_v3_load(&x->v[SE23_IDX_PHI], &xp);
    se23_v3_load(&x->v[SE23_IDX_NU], &xn);
    se23_v3_load(&x->v[SE23_IDX_RHO], &xr);
    se23_m3_tmul_v3(&U->R, &xp, &out[0]);
    se23_v3_cross(&U->v, &xp, &c);        /* nu - v^ phi */
    se23_v3_axpy(&xn, SE23_R(-1), &c, &t);
    se23_m3_tmul_v3(&U->R, &t, &out[1]);
    se23_v3_cross(&U->p, &xp, &c);        /* rho + dt nu - p^ phi */
    se23_v3_axpy(&xr, dt, &xn, &t);
    se23_v3_axpy(&t, SE23_R(-1), &c, &t);
    se23_m3_tmul_v3(&U->R, &t, &out[2]);
    se23_v3_store(&out[0], &y->v[SE23_IDX_PHI]);
    se23_v3_store(&out[1], &y->v[SE23_IDX_NU]);
    se23_v3_store(&out[2], &y->v[SE23_IDX_RHO]);
}

void se23_gauss_fk(const se23_pose_t *U, se23_real_t dt, se23_mat9_t *F)
{
    se23_mat9_t out;
    for (int j = 0; j < 9; ++j) {
        se23_tangent_t e = {{SE23_R(0)}}, col;
        e.v[j] = SE23_R(1);
        se23_gauss_fk_apply(U, dt, &e, &col);
        for (int i = 0; i < 9; ++i) {
            out.m[9 * i + j] = col.v[i];
        }
    }
    *F = out;
}

void se23_gauss_fk_mul(const se23_pose_t *U, se23_real_t dt,
                       const se23_mat9x6_t *X, se23_mat9x6_t *Y)
{
    se23_mat9x6_t out;
    for (int j = 0; j < 6; ++j) {
        se23_tangent_t col, res;
        for (int i = 0; i < 9; ++i) {
            col.v[i] = X->m[6 * i + j];
        }
        se23_gauss_fk_apply(U, dt, &col, &res);
        for (int i = 0; i < 9; ++i) {
            out.m[6 * i + j] = res.v[i];
        }
    }
    *Y = out;
}

/* Q += B diag(qg I3, qa I3) B^T on the leading 9x9 block (stride). */
static void add_input_noise(const se23_mat9x6_t *B, se23_real_t qg,
                            se23_real_t qa, se23_real_t *Q, int stride)
{
    for (int i = 0; i < 9; ++i) {
        for (int j = i; j < 9; ++j) {
            se23_real_t sg = SE23_R(0), sa = SE23_R(0);
            for (int k = 0; k < 3; ++k) {
                sg += B->m[6 * i + k] * B->m[6 * j + k];
                sa += B->m[6 * i + k + 3] * B->m[6 * j + k + 3];
            }
            const se23_real_t q = qg * sg + qa * sa;
            Q[stride * i + j] += q;
            if (j != i) {
                Q[stride * j + i] += q;
            }
        }
    }
}

se23_status_t se23_gauss_input_noise(const se23_mat9x6_t *B,
                                     const se23_imu_noise_t *noise,
                                     se23_real_t dt, se23_mat9_t *Q)
{
    SE23_CHECK_NOT_NULL(B);
    SE23_CHECK_NOT_NULL(noise);
    SE23_CHECK_NOT_NULL(Q);
    se23_step_noise_t q;
    se23_status_t st = dt_check(dt);
    if (st == SE23_OK) {
        st = se23_step_noise(noise, dt, &q);
    }
    if (st == SE23_OK && !se23_all_finite(B->m, 54)) {
        st = SE23_ERR_NONFINITE;
    }
    if (st != SE23_OK) {
        return st;
    }
    se23_mat9_t out = {{SE23_R(0)}};
    add_input_noise(B, q.qg, q.qa, out.m, 9);
    if (!se23_all_finite(out.m, 81)) {
        return SE23_ERR_NONFINITE; /* a finite B N B^T can still overflow */
    }
    *Q = out;
    return SE23_OK;
}

se23_status_t se23_gauss_cov_propagate(const se23_mat9_t *Sg,
                                       const se23_pose_t *U, se23_real_t dt,
                                       const se23_mat9_t *Q,
                                       se23_mat9_t *S_next)
{
    SE23_CHECK_NOT_NULL(Sg);
    SE23_CHECK_NOT_NULL(U);
    SE23_CHECK_NOT_NULL(Q);
    SE23_CHECK_NOT_NULL(S_next);
    se23_status_t st = dt_check(dt);
    if (st == SE23_OK) {
        st = se23_pose_check(U);
    }
    if (st == SE23_OK) {
        st = se23_cov_check(Sg->m, 9, 9);
    }
    if (st == SE23_OK) {
        st = se23_cov_check(Q->m, 9, 9);
    }
    static const se23_input_blocks_t no_input; /* zero */
    static const se23_step_noise_t no_noise;
    /* The bound of se23_gauss_predict: a finite result of a huge U (|v|
     * near the largest real) is no covariance either, it only looks like
     * one where S's entries are exactly zero. */
    if (st == SE23_OK && !se23_cov_step_fits(U, dt, SE23_R(0), &no_noise, SE23_GAUSS_N_POSE,
                                             Sg->m, 9)) {
        st = SE23_ERR_NONFINITE;
    }
    if (st != SE23_OK) {
        return st;
    }
    /* F_k S F_k^T by the kernel without input terms, then + Q, all in a
     * local: S_next may alias S or Q. */
    se23_mat9_t P = {{SE23_R(0)}};
    se23_cov_step(U, dt, &no_input, &no_noise, SE23_GAUSS_N_POSE, Sg->m, P.m, 9);
    for (int i = 0; i < 9; ++i) {
        for (int j = i; j < 9; ++j) {
            /* Q is symmetric within tolerance; use its upper triangle. */
            const se23_real_t x = P.m[9 * i + j] + Q->m[9 * i + j];
            P.m[9 * i + j] = x;
            P.m[9 * j + i] = x;
        }
    }
    if (!se23_all_finite(P.m, 81)) {
        return SE23_ERR_NONFINITE; /* S+ overflowed */
    }
    *S_next = P;
    return SE23_OK;
}

se23_status_t se23_gauss_check(const se23_gauss_t *g)
{
    SE23_CHECK_NOT_NULL(g);
    if (g->n != SE23_GAUSS_N_POSE && g->n != SE23_GAUSS_N_BIAS) {
        return SE23_ERR_DIM;
    }
    se23_status_t st = se23_pose_check(&g->T);
    if (st != SE23_OK) {
        return st;
    }
    if (!se23_all_finite(g->b_g.v, 3) || !se23_all_finite(g->b_a.v, 3)) {
        return SE23_ERR_NONFINITE;
    }
    return se23_cov_check(g->P.m, g->n, S);
}

/* out = g with its covariance stepped through one sample (cov_step.h),
 * mean unchanged; checked inputs, cannot fail. out may alias g. */
static void propagate_cov(const se23_gauss_t *g, const se23_pose_t *U,
                          const se23_input_blocks_t *Bt,
                          const se23_step_noise_t *q, se23_real_t dt,
                          se23_gauss_t *out)
{
    se23_cov_step(U, dt, Bt, q, g->n, g->P.m, out->P.m, S);
    out->T = g->T;
    out->b_g = g->b_g;
    out->b_a = g->b_a;
    out->n = g->n;
}

se23_status_t se23_gauss_propagate(const se23_gauss_t *g, const se23_pose_t *U,
                                   const se23_mat9x6_t *B,
                                   const se23_imu_noise_t *noise,
                                   se23_real_t dt, se23_gauss_t *out)
{
    SE23_CHECK_NOT_NULL(g);
    SE23_CHECK_NOT_NULL(U);
    SE23_CHECK_NOT_NULL(B);
    SE23_CHECK_NOT_NULL(noise);
    SE23_CHECK_NOT_NULL(out);
    se23_step_noise_t q;
    se23_status_t st = state_check(g);
    if (st == SE23_OK) {
        st = dt_check(dt);
    }
    if (st == SE23_OK) {
        st = se23_pose_check(U);
    }
    if (st == SE23_OK && !se23_all_finite(B->m, 54)) {
        st = SE23_ERR_NONFINITE;
    }
    if (st == SE23_OK) {
        st = se23_step_noise(noise, dt, &q);
    }
    if (st != SE23_OK) {
        return st;
    }
    se23_input_blocks_t Bt;
    if (!se23_input_blocks_from(&U->R, B, &Bt)) {
        return SE23_ERR_DOMAIN;
    }
    if (!se23_cov_step_fits(U, dt, se23_input_blocks_row_sum(&Bt), &q, g->n, g->P.m, S)) {
        return SE23_ERR_NONFINITE; /* P+ would overflow */
    }
    propagate_cov(g, U, &Bt, &q, dt, out);
    return SE23_OK;
}

se23_status_t se23_gauss_predict_work(const se23_earth_model_t *model,
                                      const se23_gauss_t *g,
                                      const se23_imu_sample_t *s,
                                      const se23_imu_noise_t *noise,
                                      se23_input_jac_kind_t kind,
                                      se23_predict_work_t *w, se23_gauss_t *out)
{
    SE23_CHECK_NOT_NULL(model);
    SE23_CHECK_NOT_NULL(g);
    SE23_CHECK_NOT_NULL(s);
    SE23_CHECK_NOT_NULL(noise);
    SE23_CHECK_NOT_NULL(w);
    SE23_CHECK_NOT_NULL(out);
    se23_status_t st = state_check(g);
    if (st == SE23_OK && kind != SE23_INPUT_JAC_EXACT && kind != SE23_INPUT_JAC_BASIC) {
        st = SE23_ERR_DOMAIN;
    }
    if (st != SE23_OK) {
        return st;
    }
    const se23_step_inputs_t *in = &w->in;
    se23_imu_sample_corrected(s, &g->b_g, &g->b_a, &w->in.c);
    /* The step checks the sample; its outputs stay in w until the end. */
    st = se23_predict_inputs(model, &g->T, noise, kind, w);
    if (st != SE23_OK) {
        return st;
    }
    if (!se23_cov_step_fits(&in->U, in->c.dt, se23_input_blocks_bound(&in->c.f_b, in->c.dt),
                            &in->q, g->n, g->P.m, S)) {
        return SE23_ERR_NONFINITE; /* P+ would overflow */
    }
    /* Nothing fails from here on (the covariance step reads only g->P). */
    se23_cov_step(&in->U, in->c.dt, &in->Bt, &in->q, g->n, g->P.m, out->P.m, S);
    out->T = w->T_next;
    out->b_g = g->b_g;
    out->b_a = g->b_a;
    out->n = g->n;
    return SE23_OK;
}

se23_status_t se23_gauss_predict(const se23_earth_model_t *model,
                                 const se23_gauss_t *g,
                                 const se23_imu_sample_t *s,
                                 const se23_imu_noise_t *noise,
                                 se23_input_jac_kind_t kind,
                                 se23_gauss_t *out)
{
    se23_predict_work_t w;
    return se23_gauss_predict_work(model, g, s, noise, kind, &w, out);
}

static se23_status_t convert(const se23_earth_model_t *model,
                             const se23_gauss_t *g, se23_real_t sign,
                             se23_gauss_t *out)
{
    SE23_CHECK_NOT_NULL(model);
    SE23_CHECK_NOT_NULL(g);
    SE23_CHECK_NOT_NULL(out);
    se23_status_t st = state_check(g);
    if (st == SE23_OK && !se23_all_finite(model->w_ie_n.v, 3)) {
        st = SE23_ERR_NONFINITE;
    }
    if (st != SE23_OK) {
        return st;
    }
    /* M = I + sign [[0,0,0],[0,0,w^],[0,0,0]], w = Rbar^T Omega (gauss.h). */
    se23_vec3_t a;
    se23_m3_tmul_v3(&g->T.R, &model->w_ie_n, &a);
    se23_v3_scale(&a, sign, &a);
    se23_pose_t T;
    if (sign < SE23_R(0)) {
        se23_imu_user_from_carried(model, &g->T, &T);
    } else {
        se23_imu_carried_from_user(model, &g->T, &T);
    }
    /* A finite Omega x p or M P M^T can still overflow. */
    if (!se23_pose_finite(&T) || !se23_cov_nu_shear_fits(&a, g->n, g->P.m, S)) {
        return SE23_ERR_NONFINITE;
    }
    se23_cov_nu_shear(&a, g->n, g->P.m, out->P.m, S);
    out->T = T;
    out->b_g = g->b_g;
    out->b_a = g->b_a;
    out->n = g->n;
    return SE23_OK;
}

se23_status_t se23_gauss_from_carried(const se23_earth_model_t *model,
                                      const se23_gauss_t *g,
                                      se23_gauss_t *out)
{
    return convert(model, g, SE23_R(-1), out);
}

se23_status_t se23_gauss_to_carried(const se23_earth_model_t *model,
                                    const se23_gauss_t *g,
                                    se23_gauss_t *out)
{
    return convert(model, g, SE23_R(1), out);
}
