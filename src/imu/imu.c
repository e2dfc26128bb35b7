/* Exact IMU increment and propagation step; see imu.h. */
#include "se23/imu.h"

#include "../base/argcheck.h"
#include "imu_step.h"
#include "../base/linalg.h"
#include "se23/se23.h"
#include "se23/so3.h"
#include "../base/se23_math.h"
#include "../lie/so3_series.h"

/* The cached Gamma'(model->dt) is used when the sample's dt is this many
 * epsilons (relative) from model->dt: the difference is then rounding. */
#define GAMMA_CACHE_ULPS SE23_R(4)

se23_status_t se23_imu_sample_check(const se23_imu_sample_t *s, se23_real_t dt_max)
{
    /* x * 0 is 0 for finite x and NaN for NaN or Inf: one test for all. */
    const se23_real_t z = SE23_R(0);
    const se23_real_t bad = s->w_ib_b.v[0] * z + s->w_ib_b.v[1] * z + s->w_ib_b.v[2] * z +
                            s->f_b.v[0] * z + s->f_b.v[1] * z + s->f_b.v[2] * z + s->dt * z;
    if (!se23_is_finite(bad)) {
        return SE23_ERR_NONFINITE;
    }
    if (!(s->dt > SE23_R(0) && s->dt <= dt_max)) {
        return SE23_ERR_DT;
    }
    return SE23_OK;
}

void se23_imu_sample_corrected(const se23_imu_sample_t *s, const se23_vec3_t *b_g,
                               const se23_vec3_t *b_a, se23_imu_sample_t *c)
{
    for (int i = 0; i < 3; ++i) {
        c->w_ib_b.v[i] = s->w_ib_b.v[i] + b_g->v[i];
        c->f_b.v[i] = s->f_b.v[i] + b_a->v[i];
    }
    c->dt = s->dt;
}

int se23_sample_tame(const se23_imu_sample_t *s)
{
    const se23_real_t w1 = se23_fabs(s->w_ib_b.v[0]) + se23_fabs(s->w_ib_b.v[1]) +
                           se23_fabs(s->w_ib_b.v[2]);
    const se23_real_t f1 = se23_fabs(s->f_b.v[0]) + se23_fabs(s->f_b.v[1]) +
                           se23_fabs(s->f_b.v[2]);
    return (s->dt <= SE23_R(8)) && (w1 * s->dt <= SE23_R(8)) && (f1 <= SE23_SAMPLE_F_TAME);
}

/* phi = w dt, the series coefficients at |phi|, and R = exp(phi). */
static void rotation_increment(const se23_imu_sample_t *s, se23_vec3_t *phi,
                               se23_real_t *theta, se23_so3_coeffs_t *c,
                               se23_mat3_t *R)
{
    se23_v3_scale(&s->w_ib_b, s->dt, phi);
    *theta = se23_sqrt(se23_v3_dot(phi, phi));
    se23_so3_coeffs(*theta, c);
    se23_m3_series(SE23_R(1), c->c1, c->c2, phi, R);
}

/* out = k A x, one pass (out may not alias x). */
static void scaled_mul_v3(const se23_mat3_t *A, const se23_vec3_t *x, se23_real_t k,
                          se23_vec3_t *out)
{
    const se23_real_t x0 = x->v[0], x1 = x->v[1], x2 = x->v[2];
    out->v[0] = k * (A->m[0][0] * x0 + A->m[0][1] * x1 + A->m[0][2] * x2);
    out->v[1] = k * (A->m[1][0] * x0 + A->m[1][1] * x1 + A->m[1][2] * x2);
    out->v[2] = k * (A->m[2][0] * x0 + A->m[2][1] * x1 + A->m[2][2] * x2);
}

/* ups and its parts q (both written) of a checked sample. */
static void increment_into(const se23_imu_sample_t *s, se23_pose_t *ups,
                           se23_increment_parts_t *q)
{
    rotation_increment(s, &q->th, &q->t, &q->c, &ups->R);
    se23_m3_series(SE23_R(1), q->c.c2, q->c.c3, &q->th, &q->J);
    scaled_mul_v3(&q->J, &s->f_b, s->dt, &ups->v);
    se23_m3_series(SE23_R(0.5), q->c.c3, q->c.c4, &q->th, &q->H);
    scaled_mul_v3(&q->H, &s->f_b, s->dt * s->dt, &ups->p);
}

void se23_imu_increment_parts(const se23_imu_sample_t *s, se23_pose_t *ups,
                              se23_increment_parts_t *parts)
{
    if (parts != NULL) {
        increment_into(s, ups, parts);
    } else {
        se23_increment_parts_t local;
        increment_into(s, ups, &local);
    }
}

se23_status_t se23_imu_increment(const se23_imu_sample_t *s, se23_pose_t *ups)
{
    SE23_CHECK_NOT_NULL(s);
    SE23_CHECK_NOT_NULL(ups);
    se23_status_t st = se23_imu_sample_check(s, SE23_R(SE23_CFG_DT_MAX));
    if (st != SE23_OK) {
        return st;
    }
    se23_pose_t u;
    se23_imu_increment_parts(s, &u, NULL);
    if (!se23_pose_finite(&u)) {
        return SE23_ERR_NONFINITE; /* |w dt|^2 or dt f overflowed */
    }
    *ups = u;
    return SE23_OK;
}

/* The first-order increments (exp(w dt ^), dt f, pos_coeff dt^2 f): the
 * rotation exact, R held at its start value in the velocity and position
 * lines. pos_coeff = 1/2 is Forster et al.'s model, 0 the paper's eq.
 * backtofuture. */
static se23_status_t first_order_increment(const se23_imu_sample_t *s, se23_real_t pos_coeff,
                                           se23_pose_t *ups)
{
    SE23_CHECK_NOT_NULL(s);
    SE23_CHECK_NOT_NULL(ups);
    se23_status_t st = se23_imu_sample_check(s, SE23_R(SE23_CFG_DT_MAX));
    if (st != SE23_OK) {
        return st;
    }
    se23_vec3_t phi;
    se23_real_t theta;
    se23_so3_coeffs_t c;
    se23_pose_t out;
    rotation_increment(s, &phi, &theta, &c, &out.R);
    se23_v3_scale(&s->f_b, s->dt, &out.v);
    se23_v3_scale(&s->f_b, pos_coeff * s->dt * s->dt, &out.p);
    if (!se23_pose_finite(&out)) {
        return SE23_ERR_NONFINITE; /* |w dt|^2 overflowed */
    }
    *ups = out;
    return SE23_OK;
}

se23_status_t se23_imu_increment_forster(const se23_imu_sample_t *s,
                                         se23_pose_t *ups)
{
    return first_order_increment(s, SE23_R(0.5), ups);
}

se23_status_t se23_imu_increment_paper(const se23_imu_sample_t *s, se23_pose_t *ups)
{
    return first_order_increment(s, SE23_R(0), ups);
}

/* out = gamma Phi_t(T) ups, R re-orthonormalised; out may not alias the
 * inputs (no copies: a pose is a memcpy call on Cortex-M7). */
static void transition_into(const se23_pose_t *gamma, const se23_pose_t *T,
                            const se23_pose_t *ups, se23_real_t t, se23_pose_t *out)
{
    if (gamma != NULL) {
        se23_pose_t P;
        se23_pose_mul_phi(T, ups, t, &P);
        se23_pose_mul_phi(gamma, &P, SE23_R(0), out);
    } else {
        se23_pose_mul_phi(T, ups, t, out);
    }
    /* Each product leaves R about one epsilon off SO(3), and with repeated
     * samples the error adds up linearly: in float a constant sample exceeds
     * SE23_CFG_ROT_TOL within ~100 steps. One Newton-Schulz step whenever
     * the drift passes 4 eps keeps it there (one step takes a drift of a few
     * eps to rounding). A matrix drifted past 0.1, no rotation in the first
     * place, is passed through unchanged by this unchecked function. */
    (void)se23_m3_orthonormalize_step(&out->R, SE23_NORMALIZE_DONE, SE23_R(0.1));
}

void se23_imu_transition(const se23_pose_t *gamma, const se23_pose_t *T,
                         const se23_pose_t *ups, se23_real_t t,
                         se23_pose_t *out)
{
    se23_pose_t P;
    transition_into(gamma, T, ups, t, &P);
    *out = P;
}

se23_status_t se23_imu_step(const se23_earth_model_t *model,
                            const se23_pose_t *T, const se23_imu_sample_t *s,
                            se23_pose_t *T_next)
{
    SE23_CHECK_NOT_NULL(T);
    SE23_CHECK_NOT_NULL(T_next);
    se23_status_t st = se23_pose_check(T);
    if (st != SE23_OK) {
        return st;
    }
    se23_pose_t ups, next;
    st = se23_imu_step_ups(model, T, s, &next, &ups, NULL);
    if (st == SE23_OK) {
        *T_next = next;
    }
    return st;
}

se23_status_t se23_imu_step_ups(const se23_earth_model_t *model,
                                const se23_pose_t *T, const se23_imu_sample_t *s,
                                se23_pose_t *T_next, se23_pose_t *ups,
                                se23_increment_parts_t *parts)
{
    SE23_CHECK_NOT_NULL(model);
    SE23_CHECK_NOT_NULL(T);
    SE23_CHECK_NOT_NULL(s);
    SE23_CHECK_NOT_NULL(T_next);
    SE23_CHECK_NOT_NULL(ups);
    se23_status_t st = se23_imu_sample_check(s, model->dt_max);
    if (st != SE23_OK) {
        return st;
    }
    se23_pose_t gamma_dt;
    const se23_pose_t *gamma = &model->gamma;
    if (se23_fabs(s->dt - model->dt) > GAMMA_CACHE_ULPS * SE23_EPSILON * model->dt) {
        st = se23_earth_gamma(&model->g_n, &model->w_ie_n, s->dt, &gamma_dt);
        if (st != SE23_OK) {
            return st;
        }
        gamma = &gamma_dt;
    }
    se23_imu_increment_parts(s, ups, parts);
    transition_into(gamma, T, ups, s->dt, T_next);
    /* Finite inputs can still overflow (|f| dt near the largest real, or a
     * state near it): refuse instead of returning Inf with SE23_OK. The
     * increment of a tame sample cannot. */
    const int tame = se23_sample_tame(s);
    if (parts != NULL) {
        parts->tame = tame;
    }
    if ((!tame && !se23_pose_finite(ups)) || !se23_pose_finite(T_next)) {
        return SE23_ERR_NONFINITE;
    }
    return SE23_OK;
}

/* Tout = (R, v + sign Omega x p, p). */
static void shift_velocity(const se23_earth_model_t *model, const se23_pose_t *T,
                           se23_real_t sign, se23_pose_t *Tout)
{
    se23_vec3_t wxp;
    se23_v3_cross(&model->w_ie_n, &T->p, &wxp);
    se23_pose_t out = *T;
    se23_v3_axpy(&T->v, sign, &wxp, &out.v);
    *Tout = out;
}

void se23_imu_carried_from_user(const se23_earth_model_t *model,
                                const se23_pose_t *T, se23_pose_t *Tc)
{
    shift_velocity(model, T, SE23_R(1), Tc);
}

void se23_imu_user_from_carried(const se23_earth_model_t *model,
                                const se23_pose_t *Tc, se23_pose_t *T)
{
    shift_velocity(model, Tc, SE23_R(-1), T);
}
