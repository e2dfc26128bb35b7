/* The navigation filter's static alignment; see ins.h, "Alignment", and
 * align.h. */
#include "ins_internal.h"

#include "../base/argcheck.h"
#include "../base/linalg.h"
#include "se23/align.h"
#include "../base/se23_math.h"
#include "../base/trig.h"

/* The statuses of se23_ins_align for a, SE23_OK if it is usable. */
static se23_status_t align_check(const se23_ins_t *ins, const se23_ins_align_t *a)
{
    const se23_real_t reals[] = {a->p_n.v[0],  a->p_n.v[1],  a->p_n.v[2], a->sigma_p,
                                 a->yaw,        a->sigma_yaw,  a->sigma_v,  a->sigma_bg,
                                 a->sigma_ba,   a->duration,   a->course_speed,
                                 a->course_sigma};
    const int bias = ins->cfg.bias_states;
    se23_status_t st = SE23_OK;
    const size_t n_bytes = sizeof reals;
    if (se23_all_finite(reals, (int)n_bytes / (int)sizeof reals[0]) == 0) {
        st = SE23_ERR_NONFINITE;
    } else if ((ins->cfg.zupt == 0) || ((a->gyrocompass != 0) && (ins->cfg.earth_rotation == 0)) ||
               (a->sigma_p <= SE23_R(0)) || (a->sigma_v <= SE23_R(0)) ||
               (((a->measure_noise != 0) && (a->measure_noise != 1))) ||
               ((a->gyrocompass == 0) && (a->course_speed <= SE23_R(0)) &&
                (a->sigma_yaw <= SE23_R(0))) ||
               (a->course_speed < SE23_R(0)) ||
               ((a->course_speed > SE23_R(0)) &&
                ((a->gyrocompass != 0) || !(a->course_sigma > SE23_R(0)) ||
                 (a->course_sigma > SE23_R(3)))) ||
               ((bias != 0) && ((a->sigma_bg <= SE23_R(0)) || (a->sigma_ba <= SE23_R(0)))) ||
               (a->sigma_ba < SE23_R(0)) || (a->duration < SE23_R(0)) ||
               (a->duration > SE23_INS_MAX_OUTAGE) || (a->sigma_p > SE23_R(1e6)) ||
               (a->sigma_v > SE23_R(1e6)) || (a->sigma_yaw > SE23_R(1e6)) ||
               (a->sigma_bg > SE23_R(1e6)) || (a->sigma_ba > SE23_R(1e6)) ||
               (se23_ins_norm_within(&a->p_n, SE23_INS_POS_MAX) == 0)) {
        st = SE23_ERR_DOMAIN;
    } else {
        /* usable */
    }
    return st;
}

se23_status_t se23_ins_align(se23_ins_t *ins, const se23_ins_align_t *a)
{
    se23_status_t st;
    SE23_CHECK_NOT_NULL(ins);
    SE23_CHECK_NOT_NULL(a);
    st = align_check(ins, a);
    if (st != SE23_OK) {
        se23_ins_count(&ins->c.init_rejected);
        return st;
    }
    ins->align = *a;
    ins->noise = ins->cfg.noise; /* until the rest measures it */
    se23_ins_drop_pending(ins); /* stamped for the state that ends here */
    ins->status = (ins->status & SE23_INS_ST_EARTH_RATE) | SE23_INS_ST_ALIGNING;
    se23_stationary_reset(&ins->det);
    se23_ins_align_reset_sums(ins);
    return SE23_OK;
}

/* Per-axis std of one sample from the window's variances, floored at the
 * sensor's white noise over one nominal sample, density / sqrt(dt) (a
 * short quiet window says little about the noise), and at a tiny positive
 * value for a noise-free sensor. */
static se23_real_t window_std(const se23_ins_t *ins, const se23_vec3_t *var,
                              se23_real_t density)
{
    const se23_real_t floor_std = density / se23_sqrt(ins->cfg.dt_nominal);
    const se23_real_t s = se23_sqrt((var->v[0] + var->v[1] + var->v[2]) / SE23_R(3));
    const se23_real_t tiny = SE23_R(1e-9);
    const se23_real_t m = (s > floor_std) ? s : floor_std;
    return (m > tiny) ? m : tiny;
}

/* P's block (b, c) = A (and (c, b) = A^T). */
static void put_block(se23_gauss_t *g, int b, int c, const se23_mat3_t *A)
{
    int i, j;
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            g->P.m[se23_ins_idx(b + i, c + j)] = A->m[i][j];
            g->P.m[se23_ins_idx(c + j, b + i)] = A->m[i][j];
        }
    }
}

/*
 * The aligned state in the user's coordinates, in ins->work. The tilt error
 * comes from the accelerometer noise averaged over the window and from the
 * accelerometer bias, which levelling cannot tell from a tilt: with
 * f_mean = f - b_a - noise (gauss.h sign convention), u = f_mean/|f_mean|,
 *   phi_tilt = -(1/g) u^ (b_a + noise)       (body-frame error, R = Rbar exp(phi^)),
 * so Cov(phi) = (sb^2 + sf^2/N)/g^2 (I - u u^T) + syaw^2 u u^T (align.h
 * with the noise std sqrt(sf^2 + N sb^2)) and, with bias states,
 * Cov(phi, db_a) = -(sb^2/g) u^. The gyro bias: levelling alone leaves
 * the gyro free to measure it, b_g = R^T Omega - w_mean (the reading at
 * rest is the Earth rate less the bias), to the noise of the window's mean
 * (var_bg per axis); a gyrocompass spends the gyro on the heading, so there
 * b_g = 0 with the caller's sigma_bg (its effect on the heading is not
 * modelled). b_g0 NULL: the gyrocompass case.
 */
static se23_status_t aligned_state(se23_ins_t *ins, const se23_vec3_t *f_mean,
                                   const se23_mat3_t *R, se23_real_t sigma_f,
                                   se23_real_t sigma_yaw, const se23_vec3_t *b_g0,
                                   se23_real_t var_bg, int W)
{
    const se23_ins_align_t *a = &ins->align;
    const se23_real_t g0 = ins->det.cfg.gravity;
    const se23_real_t sb = a->sigma_ba;
    const se23_real_t sf_eff = se23_sqrt((sigma_f * sigma_f) + ((se23_real_t)W * sb * sb));
    se23_gauss_t *g = &ins->work;
    se23_mat3_t P, C;
    se23_vec3_t u;
    int i;
    const se23_status_t st = se23_align_cov(R, sf_eff, W, g0, sigma_yaw, &P);
    if (st != SE23_OK) {
        return st;
    }
    g->n = SE23_GAUSS_N_POSE;
    if (ins->cfg.bias_states != 0) {
        g->n = SE23_GAUSS_N_BIAS;
    }
    for (i = 0; i < (SE23_GAUSS_NMAX * SE23_GAUSS_NMAX); ++i) {
        g->P.m[i] = SE23_R(0);
    }
    g->T.R = *R;
    for (i = 0; i < 3; ++i) {
        g->T.v.v[i] = SE23_R(0);
        g->T.p.v[i] = a->p_n.v[i];
        g->b_g.v[i] = (b_g0 != NULL) ? b_g0->v[i] : SE23_R(0);
        g->b_a.v[i] = SE23_R(0);
        g->P.m[se23_ins_idx(SE23_IDX_NU + i, SE23_IDX_NU + i)] = a->sigma_v * a->sigma_v;
        g->P.m[se23_ins_idx(SE23_IDX_RHO + i, SE23_IDX_RHO + i)] = a->sigma_p * a->sigma_p;
    }
    put_block(g, SE23_IDX_PHI, SE23_IDX_PHI, &P);
    if (g->n == SE23_GAUSS_N_BIAS) {
        se23_v3_scale(f_mean, SE23_R(1) / se23_sqrt(se23_v3_dot(f_mean, f_mean)), &u);
        se23_m3_skew(&u, &C);
        se23_m3_scale(&C, -(sb * sb) / g0, &C);
        put_block(g, SE23_IDX_PHI, SE23_IDX_BA, &C);
        for (i = 0; i < 3; ++i) {
            g->P.m[se23_ins_idx(SE23_IDX_BG + i, SE23_IDX_BG + i)] =
                (b_g0 != NULL) ? var_bg : (a->sigma_bg * a->sigma_bg);
            g->P.m[se23_ins_idx(SE23_IDX_BA + i, SE23_IDX_BA + i)] = sb * sb;
        }
    }
    return SE23_OK;
}

/* Adds one stationary sample to the alignment's sums. */
static void sums_add(se23_ins_align_sums_t *a, const se23_imu_sample_t *s)
{
    int i;
    if (a->n == 0) {
        a->w0 = s->w_ib_b;
        a->f0 = s->f_b;
    }
    for (i = 0; i < 3; ++i) {
        const se23_real_t dw = s->w_ib_b.v[i] - a->w0.v[i];
        const se23_real_t df = s->f_b.v[i] - a->f0.v[i];
        a->sw.v[i] += dw;
        a->sf.v[i] += df;
        a->sww.v[i] += dw * dw;
        a->sff.v[i] += df * df;
    }
    a->n++;
}

/* mean = x0 + s / n and the per-axis sample variance (n >= 2) of summed
 * deviations. */
static void sums_stats(int n, const se23_vec3_t *x0, const se23_vec3_t *s, const se23_vec3_t *ss,
                       se23_vec3_t *mean, se23_vec3_t *var)
{
    const se23_real_t rn = (se23_real_t)n;
    int i;
    for (i = 0; i < 3; ++i) {
        const se23_real_t m = s->v[i] / rn;
        const se23_real_t v = (ss->v[i] - (rn * m * m)) / (rn - SE23_R(1));
        mean->v[i] = x0->v[i] + m;
        var->v[i] = (v > SE23_R(0)) ? v : SE23_R(0);
    }
}

void se23_ins_align_reset_sums(se23_ins_t *ins)
{
    const se23_ins_align_sums_t none = {0};
    ins->sums = none;
}

/* Samples the alignment averages: duration at the nominal rate, at least
 * one detector window. */
static int align_samples(const se23_ins_t *ins)
{
    const se23_real_t k = ins->align.duration / ins->cfg.dt_nominal;
    const int n = (k < (se23_real_t)INT16_MAX) ? (int)k : (int)INT16_MAX;
    return (n > ins->det.cfg.window) ? n : ins->det.cfg.window;
}

se23_ins_verdict_t se23_ins_align_sample(se23_ins_t *ins, int64_t t_ns,
                                         const se23_imu_sample_t *s)
{
    se23_ins_align_sums_t *a = &ins->sums;
    se23_vec3_t w_mean, f_mean, w_var, f_var;
    se23_real_t yaw;
    /* an unknown heading (GNSS course to come): 1 rad, until the course */
    se23_real_t sigma_yaw = (ins->align.course_speed > SE23_R(0)) ? SE23_R(1)
                                                                 : ins->align.sigma_yaw;
    se23_mat3_t R;
    int stationary = 0;
    se23_status_t st = se23_stationary_add(&ins->det, &s->w_ib_b, &s->f_b, &stationary);
    if ((st != SE23_OK) || (stationary == 0)) {
        se23_ins_align_reset_sums(ins); /* moving: the rest starts again */
        return SE23_INS_EARLY;
    }
    sums_add(a, s);
    if (a->n < align_samples(ins)) {
        return SE23_INS_EARLY;
    }
    sums_stats(a->n, &a->w0, &a->sw, &a->sww, &w_mean, &w_var);
    sums_stats(a->n, &a->f0, &a->sf, &a->sff, &f_mean, &f_var);
    if (ins->align.gyrocompass != 0) {
        st = se23_align_gyrocompass(SE23_FRAME_NED, ins->cfg.lat, &f_mean, &w_mean,
                                    window_std(ins, &w_var, ins->cfg.noise.gyro_noise), a->n, &R,
                                    &yaw, &sigma_yaw);
    } else {
        st = se23_align_level(SE23_FRAME_NED, &f_mean, ins->align.yaw, &R);
    }
    if (st == SE23_OK) {
        const se23_real_t sw = window_std(ins, &w_var, ins->cfg.noise.gyro_noise);
        const se23_real_t var_bg = (sw * sw) / (se23_real_t)a->n;
        se23_vec3_t w_ie_b, b_g0;
        se23_m3_tmul_v3(&R, &ins->model.w_ie_n, &w_ie_b);
        se23_v3_axpy(&w_ie_b, SE23_R(-1), &w_mean, &b_g0);
        st = aligned_state(ins, &f_mean, &R, window_std(ins, &f_var, ins->cfg.noise.accel_noise),
                           sigma_yaw, (ins->align.gyrocompass != 0) ? NULL : &b_g0, var_bg, a->n);
    }
    if (st == SE23_OK) {
        st = se23_gauss_to_carried(&ins->model, &ins->work, &ins->work);
    }
    se23_ins_align_reset_sums(ins);
    if (st != SE23_OK) {
        return SE23_INS_EARLY; /* not usable (e.g. |f| far from g): keep aligning */
    }
    if (ins->align.measure_noise != 0) {
        /* window_std is floored at the configured density / sqrt(dt) */
        const se23_real_t rt = se23_sqrt(ins->cfg.dt_nominal);
        ins->noise.gyro_noise = window_std(ins, &w_var, ins->cfg.noise.gyro_noise) * rt;
        ins->noise.accel_noise = window_std(ins, &f_var, ins->cfg.noise.accel_noise) * rt;
    }
    se23_ins_start(ins, t_ns, &ins->work);
    ins->last = *s;
    if (ins->align.course_speed > SE23_R(0)) {
        ins->status |= SE23_INS_ST_HEADING_UNKNOWN;
    }
    return SE23_INS_USED;
}

/*
 * The heading from the GNSS course (ins.h, "Alignment"): the attitude is
 * turned about the nav vertical so that body x points along the fix's
 * horizontal velocity, the velocity is set to the fix's, and the
 * covariance follows: with r = R^T e_down (the vertical in the body error),
 * P <- T P T^T + D, T = I - r r^T on phi (the old heading error dropped)
 * and 0 on nu, D = s^2 r r^T on phi (s^2 = course_sigma^2 + sigma_v^2 /
 * speed^2) and the fix's velocity covariance on nu: PSD as a congruence
 * plus PSD terms. work holds the user's state; the caller commits it (and
 * then clears SE23_INS_ST_HEADING_UNKNOWN).
 */
void se23_ins_course_heading(se23_ins_t *ins, const se23_ins_gnss_t *fix, se23_real_t speed)
{
    se23_gauss_t *g = &ins->work;
    const se23_real_t sv = se23_fabs(fix->sigma_v.v[0]) + se23_fabs(fix->sigma_v.v[1]);
    const se23_real_t sh = SE23_R(0.5) * sv / speed;
    const se23_real_t s2 = (ins->align.course_sigma * ins->align.course_sigma) + (sh * sh);
    int i;
    /* the vehicle's forward axis in the nav frame, R C_bv e_1 (ins.h,
     * "Vehicles"), turned onto the course */
    se23_vec3_t fwd_b, fwd_n;
    for (i = 0; i < 3; ++i) {
        fwd_b.v[i] = ins->C_bv.m[i][0];
    }
    se23_m3_mul_v3(&g->T.R, &fwd_b, &fwd_n);
    const se23_real_t d = se23_atan2(fix->v_n.v[1], fix->v_n.v[0]) -
                          se23_atan2(fwd_n.v[1], fwd_n.v[0]);
    se23_real_t sn, c;
    se23_sincos(d, &sn, &c);
    se23_mat3_t Rz, R;
    se23_vec3_t r, w, wl, Rwl;
    int j, k;
    se23_m3_identity(&Rz);
    Rz.m[0][0] = c;
    Rz.m[0][1] = -sn;
    Rz.m[1][0] = sn;
    Rz.m[1][1] = c;
    se23_m3_mul(&Rz, &g->T.R, &R);
    g->T.R = R;
    for (i = 0; i < 3; ++i) {
        r.v[i] = R.m[2][i];
    }
    /* rows, then columns, of phi times T = I - r r^T */
    for (j = 0; j < g->n; ++j) {
        se23_real_t dot = SE23_R(0);
        for (k = 0; k < 3; ++k) {
            dot += r.v[k] * g->P.m[se23_ins_idx(SE23_IDX_PHI + k, j)];
        }
        for (i = 0; i < 3; ++i) {
            g->P.m[se23_ins_idx(SE23_IDX_PHI + i, j)] -= r.v[i] * dot;
        }
    }
    for (i = 0; i < g->n; ++i) {
        se23_real_t dot = SE23_R(0);
        for (k = 0; k < 3; ++k) {
            dot += g->P.m[se23_ins_idx(i, SE23_IDX_PHI + k)] * r.v[k];
        }
        for (j = 0; j < 3; ++j) {
            g->P.m[se23_ins_idx(i, SE23_IDX_PHI + j)] -= dot * r.v[j];
        }
    }
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            g->P.m[se23_ins_idx(SE23_IDX_PHI + i, SE23_IDX_PHI + j)] += s2 * r.v[i] * r.v[j];
        }
    }
    se23_ins_body_rate(ins, &w);
    se23_v3_cross(&w, &ins->cfg.lever_b, &wl);
    se23_m3_mul_v3(&R, &wl, &Rwl);
    se23_v3_axpy(&fix->v_n, SE23_R(-1), &Rwl, &g->T.v);
    se23_ins_reset_block(g, SE23_IDX_NU, &fix->sigma_v);
}
