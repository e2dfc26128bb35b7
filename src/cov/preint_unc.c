/* Preintegrated factor with covariance, bias Jacobian and first-order bias
 * correction; see se23/preint_unc.h. F_k, B_k and the noise come from
 * gauss.h (one implementation for the filter and the factor). */
#include "se23/preint_unc.h"

#include "../base/argcheck.h"
#include "cov_check.h"
#include "cov_step.h"
#include "../imu/imu_step.h"
#include "../base/linalg.h"
#include "preint_classic.h"
#include "se23/se23.h"
#include "../base/se23_math.h"

static int kind_known(se23_input_jac_kind_t kind)
{
    return kind == SE23_INPUT_JAC_EXACT || kind == SE23_INPUT_JAC_BASIC;
}

static se23_status_t reset(const se23_vec3_t *b_g, const se23_vec3_t *b_a,
                           se23_input_jac_kind_t kind, int classic,
                           se23_preint_unc_t *fu)
{
    SE23_CHECK_NOT_NULL(b_g);
    SE23_CHECK_NOT_NULL(b_a);
    SE23_CHECK_NOT_NULL(fu);
    if (!se23_all_finite(b_g->v, 3) || !se23_all_finite(b_a->v, 3)) {
        return SE23_ERR_NONFINITE;
    }
    if (!kind_known(kind)) {
        return SE23_ERR_DOMAIN;
    }
    const se23_mat3_t zero3 = {{{SE23_R(0)}}};
    se23_preint_reset(&fu->f);
    fu->b_g = *b_g;
    fu->b_a = *b_a;
    fu->kind = kind;
    fu->classic = classic;
    for (int i = 0; i < 81; ++i) {
        fu->P_left.m[i] = SE23_R(0);
    }
    for (int i = 0; i < 54; ++i) {
        fu->J_left.m[i] = SE23_R(0);
    }
    fu->cl.dR_dbg = zero3;
    fu->cl.dV_dbg = zero3;
    fu->cl.dV_dba = zero3;
    fu->cl.dX_dbg = zero3;
    fu->cl.dX_dba = zero3;
    return SE23_OK;
}

se23_status_t se23_preint_unc_reset(const se23_vec3_t *b_g,
                                    const se23_vec3_t *b_a,
                                    se23_input_jac_kind_t kind,
                                    se23_preint_unc_t *fu)
{
    return reset(b_g, b_a, kind, 0, fu);
}

se23_status_t se23_preint_unc_reset_classic(const se23_vec3_t *b_g,
                                            const se23_vec3_t *b_a,
                                            se23_input_jac_kind_t kind,
                                            se23_preint_unc_t *fu)
{
    return reset(b_g, b_a, kind, 1, fu);
}

se23_status_t se23_preint_unc_check(const se23_preint_unc_t *fu)
{
    SE23_CHECK_NOT_NULL(fu);
    if (!kind_known(fu->kind) || (fu->classic != 0 && fu->classic != 1)) {
        return SE23_ERR_DOMAIN;
    }
    const se23_preint_classic_t *c = &fu->cl;
    if (!se23_all_finite(fu->b_g.v, 3) || !se23_all_finite(fu->b_a.v, 3) ||
        !se23_all_finite(fu->J_left.m, 54) || !se23_all_finite(&c->dR_dbg.m[0][0], 9) ||
        !se23_all_finite(&c->dV_dbg.m[0][0], 9) ||
        !se23_all_finite(&c->dV_dba.m[0][0], 9) ||
        !se23_all_finite(&c->dX_dbg.m[0][0], 9) ||
        !se23_all_finite(&c->dX_dba.m[0][0], 9) || !se23_is_finite(fu->f.dt)) {
        return SE23_ERR_NONFINITE;
    }
    se23_status_t st = se23_pose_check(&fu->f.delta);
    if (st != SE23_OK) {
        return st;
    }
    if (fu->f.dt < SE23_R(0)) {
        return SE23_ERR_DT;
    }
    return se23_cov_check(fu->P_left.m, 9, 9);
}

/* The sum of |x_i| of n reals (n a multiple of 3), a bound on each
 * (cheaper than their maximum on Cortex-M: no compare and move), three
 * at a time. */
static se23_real_t sum_abs(const se23_real_t *x, int n)
{
    se23_real_t m = SE23_R(0);
    for (int i = 0; i < n; i += 3) {
        m += se23_fabs(x[i]) + se23_fabs(x[i + 1]) + se23_fabs(x[i + 2]);
    }
    return m;
}

/* |v|_1 + |p|_1 of a pose: the bound of its shear's row sums, less 1. */
static se23_real_t translation_sum(const se23_pose_t *T)
{
    return sum_abs(T->v.v, 3) + sum_abs(T->p.v, 3);
}

/*
 * Nonzero if every result of one step stays below SE23_COV_STEP_MAX
 * (partial results included), for the increment U, the corrected force f,
 * dt, b (se23_input_blocks_bound) and the noise q: an O(n) bound decides
 * before anything is stored. Rows of rotations sum to at most sqrt 3 < 2,
 * |Jr| <= 1 (taken as 2), a skew row to at most the vector's 1-norm;
 * u = |U.v|_1 + |U.p|_1, f1 = |f|_1, entries of the factor at most mc, md,
 * mJ (classical, Deltas, J_left: the sums of the entries' magnitudes):
 *   classical (preint_classic.c; Delta R f^ at most 2 f1, times dR/dbg
 *   at most 6 f1 mc): (mc + 1)(2 + dt + 6 f1 (1 + dt)) + 2 dt
 *   Deltas (Phi_dt(Delta) U): d = md (1 + dt) + 2 u, which also bounds
 *   |v+|_1 + |p+|_1, so the rows of Bl = Ad_{Delta+} D Bt (cov_step.h,
 *   "The left form") sum to at most bl = 2 b (1 + d)
 *   J_left+ = F J_left + Bl: (1 + dt) mJ + bl
 *   P_left+ = F P_left F^T + Bl N Bl^T: se23_cov_fits, F's rows 1 + dt
 * (dt <= SE23_CFG_DT_MAX = 1). NaN fails.
 */
static int step_fits(const se23_preint_unc_t *fu, const se23_pose_t *U, const se23_vec3_t *f,
                     se23_real_t dt, se23_real_t b, const se23_step_noise_t *q)
{
    const se23_real_t u = translation_sum(U);
    const se23_real_t f1 = se23_fabs(f->v[0]) + se23_fabs(f->v[1]) + se23_fabs(f->v[2]);
    const se23_real_t md = translation_sum(&fu->f.delta);
    se23_real_t mc = SE23_R(0);
    if (fu->classic != 0) {
        const se23_preint_classic_t *c = &fu->cl;
        mc = sum_abs(&c->dR_dbg.m[0][0], 9) + sum_abs(&c->dV_dbg.m[0][0], 9) +
             sum_abs(&c->dV_dba.m[0][0], 9) + sum_abs(&c->dX_dbg.m[0][0], 9) +
             sum_abs(&c->dX_dba.m[0][0], 9);
    }
    const se23_real_t cb = ((mc + SE23_R(1)) * (SE23_R(2) + dt + (SE23_R(6) * f1 * (SE23_R(1) + dt)))) +
                           (SE23_R(2) * dt);
    const se23_real_t d = (md * (SE23_R(1) + dt)) + (SE23_R(2) * u);
    const se23_real_t bl = SE23_R(2) * b * (SE23_R(1) + d);
    const se23_real_t jb = ((SE23_R(1) + dt) * sum_abs(fu->J_left.m, 54)) + bl;
    return (cb <= SE23_COV_STEP_MAX) && (d <= SE23_COV_STEP_MAX) &&
           (jb <= SE23_COV_STEP_MAX) &&
           se23_cov_fits(SE23_R(1) + dt, bl, q, SE23_GAUSS_N_POSE, fu->P_left.m, 9);
}

se23_status_t se23_preint_unc_add_work(se23_preint_unc_t *fu,
                                       const se23_imu_sample_t *s,
                                       const se23_imu_noise_t *noise,
                                       se23_preint_work_t *w)
{
    SE23_CHECK_NOT_NULL(fu);
    SE23_CHECK_NOT_NULL(s);
    SE23_CHECK_NOT_NULL(noise);
    SE23_CHECK_NOT_NULL(w);
    se23_step_inputs_t *in = &w->in;
#if SE23_CFG_DEEP_CHECKS
    se23_status_t st = se23_preint_unc_check(fu);
    if (st == SE23_OK) {
        st = se23_imu_sample_check(s, SE23_R(SE23_CFG_DT_MAX));
    }
#else
    se23_status_t st = se23_imu_sample_check(s, SE23_R(SE23_CFG_DT_MAX));
#endif
    if (st == SE23_OK) {
        st = se23_step_noise(noise, s->dt, &in->q);
    }
    if (st != SE23_OK) {
        return st;
    }
    se23_imu_sample_t *c = &in->c;
    se23_pose_t *U = &in->U;
    se23_imu_sample_corrected(s, &fu->b_g, &fu->b_a, c);
    const int tame = se23_sample_tame(c); /* finite, and its increment too */
    if (tame == 0 && (!se23_all_finite(c->w_ib_b.v, 3) || !se23_all_finite(c->f_b.v, 3))) {
        return SE23_ERR_NONFINITE; /* finite reading + bias overflowed */
    }
    se23_sample_inputs(fu->kind, c, U, &in->Bt);
    if ((tame == 0 && !se23_pose_finite(U)) || !se23_input_blocks_finite(&in->Bt, tame) ||
        !step_fits(fu, U, &c->f_b, c->dt, se23_input_blocks_bound(&c->f_b, c->dt), &in->q)) {
        return SE23_ERR_NONFINITE; /* the increment, B_k or a result would overflow */
    }
    /* Nothing below can fail: update in place. The classical step and Bl
     * take Delta R before the step, Bl Delta's v and p after it. */
    if (fu->classic != 0) {
        se23_preint_classic_step(&fu->cl, &fu->f.delta.R, &U->R, &c->w_ib_b,
                                 &c->f_b, c->dt);
    }
    const se23_mat3_t R = fu->f.delta.R;
    se23_preint_add_increment(&fu->f, U, c->dt);
    se23_input_blocks_left(&R, &fu->f.delta.v, &fu->f.delta.p, &in->Bt);
    se23_cov_left_step(c->dt, &in->Bt, &in->q, fu->P_left.m);
    se23_cov_left_jac_step(c->dt, &in->Bt, &fu->J_left);
    return SE23_OK;
}

se23_status_t se23_preint_unc_cov(const se23_preint_unc_t *fu, se23_mat9_t *P,
                                  se23_mat9x6_t *J)
{
    SE23_CHECK_NOT_NULL(P);
    se23_status_t st = se23_preint_unc_check(fu);
    if (st != SE23_OK) {
        return st;
    }
    /* Ad_{Delta^-1} = D G with U = Delta, dt = 0 (cov_step.h): the step's
     * shear and rotation stages, without input or noise. */
    const se23_pose_t *D = &fu->f.delta;
    const se23_step_noise_t none = {SE23_R(0), SE23_R(0), SE23_R(0), SE23_R(0)};
    const se23_real_t g = SE23_R(1) + translation_sum(D);
    const se23_real_t jb = SE23_R(2) * g * sum_abs(fu->J_left.m, 54);
    if (!se23_cov_fits(g, SE23_R(0), &none, SE23_GAUSS_N_POSE, fu->P_left.m, 9) ||
        !(jb <= SE23_COV_STEP_MAX)) {
        return SE23_ERR_NONFINITE;
    }
    /* Nothing below can fail. */
    se23_cov_fk_congruence(D, SE23_R(0), fu->P_left.m, P->m, 9);
    if (J != NULL) {
        se23_gauss_fk_mul(D, SE23_R(0), &fu->J_left, J);
    }
    return SE23_OK;
}

se23_status_t se23_preint_unc_add(se23_preint_unc_t *fu,
                                  const se23_imu_sample_t *s,
                                  const se23_imu_noise_t *noise)
{
    se23_preint_work_t w;
    return se23_preint_unc_add_work(fu, s, noise, &w);
}

/* d = J db, the discrepancy of paper eq. bias:discrep to first order (of
 * the left form with J_left). */
static void bias_discrepancy(const se23_mat9x6_t *J, const se23_vec3_t *dbg,
                             const se23_vec3_t *dba, se23_tangent_t *d)
{
    const se23_real_t db[6] = {dbg->v[0], dbg->v[1], dbg->v[2],
                               dba->v[0], dba->v[1], dba->v[2]};
    for (int i = 0; i < 9; ++i) {
        se23_real_t sum = SE23_R(0);
        for (int j = 0; j < 6; ++j) {
            sum += J->m[6 * i + j] * db[j];
        }
        d->v[i] = sum;
    }
}

typedef enum { EXPONENTIAL, CLASSIC } method_t;

/* out = fu's Deltas corrected to bhat = (b_g, b_a), in exponential
 * coordinates or with Forster et al.'s Jacobians. */
static se23_status_t correct(const se23_preint_unc_t *fu,
                             const se23_vec3_t *b_g, const se23_vec3_t *b_a,
                             method_t method, se23_preint_t *out)
{
    SE23_CHECK_NOT_NULL(fu);
    SE23_CHECK_NOT_NULL(b_g);
    SE23_CHECK_NOT_NULL(b_a);
    SE23_CHECK_NOT_NULL(out);
    se23_status_t st = se23_preint_unc_check(fu);
    if (st != SE23_OK) {
        return st;
    }
    if (!se23_all_finite(b_g->v, 3) || !se23_all_finite(b_a->v, 3)) {
        return SE23_ERR_NONFINITE;
    }
    if (method == CLASSIC && !fu->classic) {
        return SE23_ERR_DOMAIN;
    }
    se23_vec3_t dbg, dba;
    se23_v3_axpy(b_g, SE23_R(-1), &fu->b_g, &dbg);
    se23_v3_axpy(b_a, SE23_R(-1), &fu->b_a, &dba);
    se23_preint_t r = fu->f;
    if (method == CLASSIC) {
        se23_preint_classic_apply(&fu->cl, &fu->f.delta, &dbg, &dba, &r.delta);
    } else {
        se23_tangent_t d;
        se23_pose_t E;
        bias_discrepancy(&fu->J_left, &dbg, &dba, &d);
        st = se23_exp(&d, &E); /* NONFINITE if J db overflowed */
        if (st != SE23_OK) {
            return st;
        }
        se23_compose(&E, &fu->f.delta, &r.delta); /* exp(J_left db) Delta */
    }
    /* Finite Deltas, Jacobians and biases can still overflow: b - bbar,
     * J db, Delta V + dV/db db. */
    if (!se23_pose_finite(&r.delta)) {
        return SE23_ERR_NONFINITE;
    }
    /* The retraction keeps R in SO(3) to rounding, so that an SE23_OK
     * output is always a valid input (one step: Delta R passed the check,
     * its drift is at most SE23_CFG_ROT_TOL). */
    (void)se23_m3_orthonormalize_step(&r.delta.R, SE23_NORMALIZE_DONE, SE23_R(0.1));
    *out = r;
    return SE23_OK;
}

se23_status_t se23_preint_unc_correct(const se23_preint_unc_t *fu,
                                      const se23_vec3_t *b_g,
                                      const se23_vec3_t *b_a,
                                      se23_preint_t *out)
{
    return correct(fu, b_g, b_a, EXPONENTIAL, out);
}

se23_status_t se23_preint_unc_correct_classic(const se23_preint_unc_t *fu,
                                              const se23_vec3_t *b_g,
                                              const se23_vec3_t *b_a,
                                              se23_preint_t *out)
{
    return correct(fu, b_g, b_a, CLASSIC, out);
}
