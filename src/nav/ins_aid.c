/* The navigation filter's measurement updates: zero velocity and rate at
 * rest, the floor level at stances, a vehicle's non-holonomic constraint,
 * GNSS with its gate and gate recovery;
 * see ins.h. Every update runs on the user's (R, v, p) in ins->work and is
 * committed to the state only when it succeeded (and passed the gate). */
#include "ins_internal.h"

#include <stddef.h>

#include "../kalman/kalman_nhc.h"
#include "../kalman/kalman_halves.h"
#include "../kalman/kalman_rest.h"
#include "../base/linalg.h"
#include "../base/se23_math.h"

/* ins->work = the user's state of ins->g. */
static se23_status_t user_state(se23_ins_t *ins)
{
    if (ins->cfg.earth_rotation == 0) {
        ins->work = ins->g; /* flat Earth: carried and user's coincide */
        return SE23_OK;
    }
    return se23_gauss_from_carried(&ins->model, &ins->g, &ins->work);
}

/* Nonzero if a variance of ins->work is below SE23_KALMAN_PIN_RATIO of
 * the same variance in ins->g (the state before the updates). */
static int pinned(const se23_ins_t *ins)
{
    int i;
    for (i = 0; i < ins->work.n; ++i) {
        const int d = se23_ins_idx(i, i);
        if (ins->work.P.m[d] < (SE23_KALMAN_PIN_RATIO * ins->g.P.m[d])) {
            return 1;
        }
    }
    return 0;
}

/* ins->g = ins->work, back in the model's coordinates, if ins->work is a
 * valid state. An update is PSD to rounding relative to the prior
 * (kalman.h); a state pinned far below the scale of its prior, in a
 * precision too short for the ratio, can come out of it outside the check
 * of gauss.h. So when the updates left a variance below
 * SE23_KALMAN_PIN_RATIO (2^-10) of its prior, the state is checked with
 * se23_gauss_check (one 15 x 15 factorisation) and refused if it fails
 * (that status, the state kept). Updates that pin nothing (a filter in its
 * steady state) are PSD to rounding relative to a posterior of their
 * prior's scale, and skip the check. */
static se23_status_t commit(se23_ins_t *ins)
{
    if (pinned(ins) != 0) {
        const se23_status_t st = se23_gauss_check(&ins->work);
        if (st != SE23_OK) {
            return st;
        }
    }
    if (ins->cfg.earth_rotation == 0) {
        ins->g = ins->work;
        return SE23_OK;
    }
    return se23_gauss_to_carried(&ins->model, &ins->work, &ins->g);
}

/* C = diag(s0^2, s1^2, s2^2) */
static void diag_cov(se23_real_t s0, se23_real_t s1, se23_real_t s2, se23_mat3_t *C)
{
    se23_m3_identity(C);
    C->m[0][0] = s0 * s0;
    C->m[1][1] = s1 * s1;
    C->m[2][2] = s2 * s2;
}

/* ins->work updated in place with ins->meas; *nis its NIS (if not NULL). */
static se23_status_t update_work(se23_ins_t *ins, se23_real_t *nis)
{
    return se23_kalman_update_work(&ins->work, &ins->meas, &ins->kernel.kalman, &ins->work,
                                   nis);
}

/* What a stance's floor update did. */
enum { FLOOR_NONE, FLOOR_USED, FLOOR_LEVEL };

/*
 * The floor update of a stance's first stationary sample on ins->work
 * (ins.h, "Floor"): the down row of the position model (no lever arm),
 * innovation floor_d - p_D, 1-sigma floor_sigma. The first stance, or one
 * more than floor_step off the level, sets the level instead
 * (*what = FLOOR_LEVEL) and updates nothing.
 */
static se23_status_t floor_update(se23_ins_t *ins, int *what)
{
    const se23_vec3_t no_lever = {{SE23_R(0), SE23_R(0), SE23_R(0)}};
    const se23_real_t sh = ins->cfg.floor_sigma;
    se23_meas_t *y = &ins->meas;
    se23_vec3_t on_floor = ins->work.T.p;
    se23_mat3_t C;
    se23_status_t st;
    int j;
    *what = FLOOR_LEVEL;
    if ((ins->floor_set == 0) ||
        !(se23_fabs(ins->floor_d - on_floor.v[2]) <= ins->cfg.floor_step)) {
        return SE23_OK;
    }
    on_floor.v[2] = ins->floor_d;
    diag_cov(sh, sh, sh, &C);
    st = se23_meas_pos_nav(&ins->work.T, &on_floor, &no_lever, &C, y);
    if (st != SE23_OK) {
        return st;
    }
    y->m = 1; /* the down row only (R's leading entry is C's: sh^2) */
    y->z[0] = y->z[2];
    for (j = 0; j < SE23_GAUSS_NMAX; ++j) {
        y->H[j] = y->H[(2 * SE23_GAUSS_NMAX) + j];
    }
    *what = FLOOR_USED;
    return update_work(ins, NULL);
}

/* The ZUPT's 1-sigma at sample s (ins.h, "Zero-velocity updates"):
 * sqrt(zupt_sigma_v^2 + W (zupt_lever |w|)^2), w = w_meas + b_g. 8
 * multiply-adds and a square root. */
static se23_real_t zupt_sigma(const se23_ins_t *ins, const se23_imu_sample_t *s)
{
    const se23_real_t sv = ins->cfg.zupt_sigma_v, l = ins->cfg.zupt_lever;
    se23_vec3_t w;
    se23_v3_axpy(&s->w_ib_b, SE23_R(1), &ins->g.b_g, &w);
    return se23_sqrt((sv * sv) +
                     ((se23_real_t)ins->det.cfg.window * ((l * l) * se23_v3_dot(&w, &w))));
}

/*
 * The rest measurements in the filter's coordinates (kalman_rest.h): a =
 * R^T Omega, the user's velocity v' - Omega x p in the body frame, the
 * rate less a. Refused with nothing written (SE23_ERR_DOMAIN) when the
 * update would pin a variance, and on any error of se23_kalman_rest: the
 * general path (rest_general) then decides.
 */
se23_status_t se23_ins_rest_steady(se23_ins_t *ins, const se23_imu_sample_t *s, int zaru)
{
    const se23_gauss_t *g = &ins->g;
    const se23_mat3_t *R = &g->T.R;
    const se23_real_t *om = ins->model.w_ie_n.v, *p = g->T.p.v;
    const se23_real_t sv = zupt_sigma(ins, s);
    const se23_real_t sw = ins->cfg.zaru_sigma_w;
    /* the user's velocity v = v' - Omega x p */
    const se23_real_t v[3] = {g->T.v.v[0] - ((om[1] * p[2]) - (om[2] * p[1])),
                              g->T.v.v[1] - ((om[2] * p[0]) - (om[0] * p[2])),
                              g->T.v.v[2] - ((om[0] * p[1]) - (om[1] * p[0]))};
    se23_rest_meas_t y;
    for (int i = 0; i < 3; ++i) {
        /* a = R^T Omega, z_v = -R^T v, z_w = a - (w_meas + b_g) */
        y.a.v[i] = ((R->m[0][i] * om[0]) + (R->m[1][i] * om[1])) + (R->m[2][i] * om[2]);
        y.z_v.v[i] = -(((R->m[0][i] * v[0]) + (R->m[1][i] * v[1])) + (R->m[2][i] * v[2]));
        y.z_w.v[i] = y.a.v[i] - (s->w_ib_b.v[i] + g->b_g.v[i]);
    }
    y.r_v = sv * sv;
    y.r_w = sw * sw;
    y.zaru = zaru;
    return se23_kalman_rest(&ins->g, &y, &ins->kernel.kalman, &ins->g, &ins->zupt_nis_last);
}

/*
 * The rest updates on the user's state in ins->work, one model after the
 * other (se23_kalman_update_work), and the floor update if rest has
 * SE23_INS_REST_FLOOR (*floor: what it did), committed with the filter's
 * check (commit). The path of a stance's first sample (floor updates on)
 * and of an update that pins a variance.
 */
static se23_status_t rest_general(se23_ins_t *ins, const se23_imu_sample_t *s, int rest,
                                  int zaru, int *floor)
{
    const se23_vec3_t zero = {{SE23_R(0), SE23_R(0), SE23_R(0)}};
    const se23_real_t sv = zupt_sigma(ins, s);
    const se23_real_t sw = ins->cfg.zaru_sigma_w;
    se23_mat3_t C;
    se23_status_t st = user_state(ins);
    diag_cov(sv, sv, sv, &C);
    if (st == SE23_OK) {
        st = se23_meas_vel_nav(&ins->work.T, &zero, &C, &ins->meas);
    }
    if (st == SE23_OK) {
        st = update_work(ins, &ins->zupt_nis_last);
    }
    if ((st == SE23_OK) && (zaru != 0)) {
        /* at rest the gyro senses the Earth rate, R^T Omega (zero on flat
         * Earth): the reading less it should be -b_g */
        se23_vec3_t w_ie_b, w_rest;
        se23_m3_tmul_v3(&ins->work.T.R, &ins->model.w_ie_n, &w_ie_b);
        se23_v3_axpy(&s->w_ib_b, SE23_R(-1), &w_ie_b, &w_rest);
        diag_cov(sw, sw, sw, &C);
        st = se23_meas_zero_rate(&w_rest, &ins->work.b_g, &C, &ins->meas);
        if (st == SE23_OK) {
            st = update_work(ins, NULL);
        }
    }
    if ((st == SE23_OK) && ((rest & SE23_INS_REST_FLOOR) != 0)) {
        st = floor_update(ins, floor);
    }
    if (st == SE23_OK) {
        st = commit(ins);
    }
    if ((st == SE23_OK) && (*floor == FLOOR_LEVEL)) {
        ins->floor_d = ins->work.T.p.v[2];
        ins->floor_set = 1;
    }
    return st;
}

int se23_ins_zupt(se23_ins_t *ins, const se23_imu_sample_t *s, int rest)
{
    int zaru = 0, floor = FLOOR_NONE;
    se23_status_t st = SE23_ERR_DOMAIN;
    if (((rest & SE23_INS_REST_LEVEL) == SE23_INS_REST_ZARU) && (ins->cfg.bias_states != 0) &&
        (ins->cfg.zaru_sigma_w > SE23_R(0))) {
        zaru = 1;
    }
    if ((rest & SE23_INS_REST_FLOOR) == 0) {
        st = se23_ins_rest_steady(ins, s, zaru);
    }
    if (st != SE23_OK) {
        st = rest_general(ins, s, rest, zaru, &floor);
    }
    if (ins->replaying != 0) {
        return (st == SE23_OK) ? 1 : 0; /* counted when it was first applied */
    }
    if (st != SE23_OK) {
        se23_ins_count(&ins->c.filter_errors);
        return 0;
    }
    se23_ins_count(&ins->c.zupt_used);
    ins->zupt_nis_sum += ins->zupt_nis_last;
    if (zaru != 0) {
        se23_ins_count(&ins->c.zaru_used);
    }
    if (floor == FLOOR_USED) {
        se23_ins_count(&ins->c.floor_used);
    } else if (floor == FLOOR_LEVEL) {
        se23_ins_count(&ins->c.floor_levels);
    } else {
        /* no stance began */
    }
    return 1;
}

/* The NHC's 1-sigma (ins.h, "Vehicles"): sqrt(nhc_sigma^2 + (nhc_lever
 * |w|)^2), w the body rate of the last sample (bias-corrected): an IMU
 * nhc_lever from the rear axle moves sideways at the yaw rate times that,
 * and up or down at the pitch rate times it. 6 multiply-adds and a
 * square root. */
static se23_real_t nhc_sigma(const se23_ins_t *ins)
{
    const se23_real_t s0 = ins->cfg.nhc_sigma, l = ins->cfg.nhc_lever;
    se23_vec3_t w;
    se23_ins_body_rate(ins, &w);
    return se23_sqrt((s0 * s0) + ((l * l) * se23_v3_dot(&w, &w)));
}

/*
 * The NHC on the user's state in ins->work as one structured update
 * (kalman_nhc.h), committed with the filter's check. Refused with nothing
 * written (ins->work is then the user's state still) when the update would
 * pin a variance or its sigma is outside se23_meas_nhc's range, and on any
 * error of se23_kalman_nhc: the general path (se23_ins_nhc) then decides.
 */
static se23_status_t nhc_steady(se23_ins_t *ins)
{
    se23_nhc_meas_t y;
    se23_status_t st = user_state(ins);
    if (st == SE23_OK) {
        const se23_real_t sigma = nhc_sigma(ins);
        if ((sigma > SE23_R(0)) && (sigma <= SE23_MEAS_NHC_SIGMA_MAX)) {
            se23_nhc_rows(&ins->work.T, &ins->C_bv, sigma, &y);
            st = se23_kalman_nhc(&ins->work, &y, &ins->kernel.kalman, &ins->work, NULL);
        } else {
            st = SE23_ERR_DOMAIN;
        }
    }
    return st;
}

int se23_ins_nhc(se23_ins_t *ins)
{
    se23_status_t st = nhc_steady(ins);
    if (st != SE23_OK) {
        /* the general path: se23_meas_nhc's checks, the Joseph step */
        st = user_state(ins);
        if (st == SE23_OK) {
            st = se23_meas_nhc(&ins->work.T, &ins->C_bv, nhc_sigma(ins), &ins->meas);
        }
        if (st == SE23_OK) {
            st = update_work(ins, NULL);
        }
    }
    if (st == SE23_OK) {
        st = commit(ins);
    }
    if (ins->replaying != 0) {
        return (st == SE23_OK) ? 1 : 0; /* counted when it was first applied */
    }
    if (st != SE23_OK) {
        se23_ins_count(&ins->c.filter_errors);
        return 0;
    }
    se23_ins_count(&ins->c.nhc_used);
    return 1;
}

void se23_ins_reset_block(se23_gauss_t *g, int b, const se23_vec3_t *s)
{
    se23_mat3_t C, RtC, B;
    int i, j;
    for (i = 0; i < g->n; ++i) {
        for (j = b; j < b + 3; ++j) {
            g->P.m[se23_ins_idx(i, j)] = SE23_R(0);
            g->P.m[se23_ins_idx(j, i)] = SE23_R(0);
        }
    }
    diag_cov(s->v[0], s->v[1], s->v[2], &C);
    se23_m3_mul_tn(&g->T.R, &C, &RtC);
    se23_m3_mul(&RtC, &g->T.R, &B);
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            g->P.m[se23_ins_idx(b + i, b + j)] = SE23_R(0.5) * (B.m[i][j] + B.m[j][i]);
        }
    }
}

void se23_ins_body_rate(const se23_ins_t *ins, se23_vec3_t *w)
{
    se23_v3_axpy(&ins->last.w_ib_b, SE23_R(1), &ins->work.b_g, w);
}

/*
 * Gate recovery: position (and velocity, if the fix has it) taken from the
 * fix, p = p_fix - R l, v = v_fix - R (w x l), with the fix's covariance
 * and no correlation with the rest; attitude and biases kept. Dropping
 * correlations of a PSD matrix block-diagonally keeps it PSD.
 */
se23_ins_verdict_t se23_ins_gate_reset(se23_ins_t *ins, const se23_ins_gnss_t *fix)
{
    se23_vec3_t Rl, w, wl, Rwl;
    if (user_state(ins) != SE23_OK) {
        se23_ins_count(&ins->c.filter_errors);
        return SE23_INS_FAILED;
    }
    se23_m3_mul_v3(&ins->work.T.R, &ins->cfg.lever_b, &Rl);
    se23_v3_axpy(&fix->p_n, SE23_R(-1), &Rl, &ins->work.T.p);
    se23_ins_reset_block(&ins->work, SE23_IDX_RHO, &fix->sigma_p);
    if (fix->has_vel != 0) {
        se23_ins_body_rate(ins, &w);
        se23_v3_cross(&w, &ins->cfg.lever_b, &wl);
        se23_m3_mul_v3(&ins->work.T.R, &wl, &Rwl);
        se23_v3_axpy(&fix->v_n, SE23_R(-1), &Rwl, &ins->work.T.v);
        se23_ins_reset_block(&ins->work, SE23_IDX_NU, &fix->sigma_v);
    }
    if (commit(ins) != SE23_OK) {
        se23_ins_count(&ins->c.filter_errors);
        return SE23_INS_FAILED;
    }
    ins->gated_run = 0;
    ins->last_fix_ns = fix->t_ns;
    se23_ins_count(&ins->c.gate_resets);
    ins->status |= SE23_INS_ST_GATE_RESET;
    return SE23_INS_RESET;
}

/* Nonzero if nis fails the configured gate. */
static int gated(const se23_ins_t *ins, se23_real_t nis)
{
    return ((ins->cfg.gnss_gate > SE23_R(0)) && !(nis <= ins->cfg.gnss_gate)) ? 1 : 0;
}

se23_ins_verdict_t se23_ins_fuse_gnss(se23_ins_t *ins, const se23_ins_gnss_t *fix)
{
    const se23_vec3_t *sp = &fix->sigma_p;
    const se23_vec3_t *sv = &fix->sigma_v;
    se23_real_t nis_p = SE23_R(0), nis_v = SE23_R(0);
    se23_mat3_t C;
    se23_vec3_t w;
    int out = 0;
    /* Position, then velocity: sequential updates of independent rows,
     * each gated on its own NIS (3 degrees of freedom). While the heading
     * awaits the course, a fast enough fix sets it (and the velocity) and
     * fuses its position; a slower one only its position. */
    int use_vel = fix->has_vel;
    int course = 0;
    se23_status_t st = user_state(ins);
    if ((st == SE23_OK) && ((ins->status & SE23_INS_ST_HEADING_UNKNOWN) != 0U)) {
        const se23_real_t speed = se23_sqrt((fix->v_n.v[0] * fix->v_n.v[0]) +
                                            (fix->v_n.v[1] * fix->v_n.v[1]));
        if ((fix->has_vel != 0) && (speed >= ins->align.course_speed)) {
            se23_ins_course_heading(ins, fix, speed);
            course = 1;
        }
        use_vel = 0;
    }
    diag_cov(sp->v[0], sp->v[1], sp->v[2], &C);
    if (st == SE23_OK) {
        /* The fix refers to its own time, up to half a sample from the
         * state's: moved to the state's time along the state's velocity,
         * p - v dt (at 30 m/s the 5 ms of half a 100 Hz sample are 15 cm;
         * the error of v, and the antenna's turn about the IMU in 5 ms, add
         * well under a millimetre) */
        const int64_t dt_ns = fix->t_ns - ins->t_ns;
        const se23_real_t dt = (se23_real_t)dt_ns / SE23_INS_NS;
        se23_vec3_t p_now;
        se23_v3_axpy(&fix->p_n, -dt, &ins->work.T.v, &p_now);
        st = se23_meas_pos_nav(&ins->work.T, &p_now, &ins->cfg.lever_b, &C, &ins->meas);
    }
    if (st == SE23_OK) {
        st = update_work(ins, &nis_p);
        out = gated(ins, nis_p);
    }
    if ((st == SE23_OK) && (out == 0) && (use_vel != 0)) {
        se23_ins_body_rate(ins, &w);
        diag_cov(sv->v[0], sv->v[1], sv->v[2], &C);
        st = se23_meas_vel_nav_lever(&ins->work.T, &w, &ins->cfg.lever_b, &fix->v_n, &C,
                                     &ins->meas);
        if (st == SE23_OK) {
            st = update_work(ins, &nis_v);
            out = gated(ins, nis_v);
        }
    }
    if (st != SE23_OK) {
        se23_ins_count(&ins->c.filter_errors);
        return SE23_INS_FAILED;
    }
    ins->nis_last = nis_p + nis_v;
    if (out != 0) {
        se23_ins_verdict_t v = SE23_INS_GATED;
        ins->status |= SE23_INS_ST_GNSS_GATED;
        ins->gated_run++;
        if ((ins->cfg.gate_recover > 0) && (ins->gated_run >= ins->cfg.gate_recover)) {
            v = se23_ins_gate_reset(ins, fix);
        }
        /* a reset fix is also gated; a failed reset is counted as failed
         * only (gnss_failed), so that the fix is in one counter */
        if (v != SE23_INS_FAILED) {
            se23_ins_count(&ins->c.gnss_gated);
        }
        return v;
    }
    if (commit(ins) != SE23_OK) {
        se23_ins_count(&ins->c.filter_errors);
        return SE23_INS_FAILED;
    }
    ins->gated_run = 0;
    ins->last_fix_ns = fix->t_ns;
    if (course != 0) {
        ins->status &= ~SE23_INS_ST_HEADING_UNKNOWN;
        se23_ins_count(&ins->c.course_headings);
    }
    se23_ins_count(&ins->c.gnss_used);
    ins->status |= SE23_INS_ST_GNSS_AIDED;
    ins->status &= ~(SE23_INS_ST_DEGRADED | SE23_INS_ST_GNSS_GATED |
                     SE23_INS_ST_GATE_RESET);
    return SE23_INS_USED;
}
