/* The navigation filter: configuration, initial state, output and the
 * screening of samples and fixes where they enter; see ins.h. */
#include "ins_internal.h"

#include "../base/argcheck.h"
#include "../base/linalg.h"
#include "se23/so3.h"
#include "../base/se23_math.h"

/* Largest 1-sigma a fix may state [m, m/s]: its square stays finite in
 * float, and nothing physical is that uncertain. */
#define FIX_SIGMA_MAX SE23_R(1e6)

/* Gravity's bound [m/s^2] (WGS-84 normal gravity is at most 9.84 on the
 * surface, less above it): a body whose specific force f the sensor
 * measures (each axis within accel_range) accelerates at |f_i + g_i| <=
 * accel_range + 10 on each axis, so no 1-sigma of its unknown
 * acceleration (outage_accel, per axis) is larger. */
#define GRAVITY_BOUND SE23_R(10)

/* 1 if every axis of x is within +-range: a data sheet states a range per
 * axis, and a reading within it on every axis (up to sqrt(3) range long) is
 * a reading the sensor made. */
static int axes_within(const se23_vec3_t *x, se23_real_t range)
{
    return ((se23_fabs(x->v[0]) <= range) && (se23_fabs(x->v[1]) <= range) &&
            (se23_fabs(x->v[2]) <= range))
               ? 1
               : 0;
}

void se23_ins_count(uint32_t *c)
{
    if (*c < UINT32_MAX) {
        *c += 1U;
    }
}

void se23_ins_drop_pending(se23_ins_t *ins)
{
    if (ins->have_pending != 0) {
        ins->have_pending = 0;
        se23_ins_count(&ins->c.gnss_pending_dropped);
    }
}

void se23_ins_count_add(uint32_t *c, int64_t k)
{
    const uint32_t room = UINT32_MAX - *c;
    const int64_t room64 = (int64_t)room;
    *c = (k >= room64) ? UINT32_MAX : (*c + (uint32_t)k);
}

int64_t se23_ins_half_sample_ns(const se23_ins_t *ins)
{
    return ins->half_ns;
}

/* Nanoseconds of a checked duration s (0 <= s <= 1e9 s). */
static int64_t to_ns(se23_real_t s)
{
    const se23_real_t ns = s * SE23_INS_NS;
    return (int64_t)ns;
}

static int is_flag(int x)
{
    return (x == 0) || (x == 1);
}

/* The statuses of se23_ins_setup for cfg, SE23_OK if it is usable. */
static se23_status_t config_check(const se23_ins_config_t *cfg)
{
    /* magnitudes (>= 0), then the signed values (lat is judged by
     * se23_earth_gravity_vec in se23_ins_setup, the rule (earth.h: |lat| <=
     * pi/2 + SE23_EARTH_LAT_SLACK) se23_ins_preset_foot applies too) */
    const se23_real_t reals[] = {
        cfg->noise.gyro_noise, cfg->noise.accel_noise, cfg->noise.gyro_walk,
        cfg->noise.accel_walk, cfg->gyro_range, cfg->accel_range,
        cfg->dt_nominal, cfg->max_gap, cfg->max_outage, cfg->outage_accel,
        cfg->outage_rate, cfg->gnss_gate, cfg->delay_horizon, cfg->preint_window,
        cfg->zupt_sigma_v, cfg->zaru_sigma_w, cfg->zaru_after, cfg->floor_sigma,
        cfg->floor_step, cfg->floor_swing, cfg->motion.gyro_scale, cfg->motion.accel_scale,
        cfg->motion.gyro_g, cfg->motion.corr_time, cfg->zupt_lever, cfg->nhc_sigma,
        cfg->nhc_interval, cfg->rest_speed_max, cfg->rest_accel_sigma, cfg->gravity_step,
        cfg->nhc_lever};
    const se23_real_t signed_reals[] = {
        cfg->lat, cfg->height, cfg->lever_b.v[0], cfg->lever_b.v[1], cfg->lever_b.v[2],
        cfg->mount_bv.v[0], cfg->mount_bv.v[1], cfg->mount_bv.v[2], cfg->gnss_time_offset};
    const size_t n_bytes = sizeof reals, n_signed_bytes = sizeof signed_reals;
    const int n_reals = (int)n_bytes / (int)sizeof reals[0];
    int i;
    if ((se23_all_finite(reals, n_reals) == 0) ||
        (se23_all_finite(signed_reals, (int)n_signed_bytes / (int)sizeof signed_reals[0]) ==
         0)) {
        return SE23_ERR_NONFINITE;
    }
    for (i = 0; i < n_reals; ++i) {
        if (reals[i] < SE23_R(0)) {
            return SE23_ERR_DOMAIN;
        }
    }
    /* The ranges bound every reading and bias estimate a step sees, the
     * outage's 1-sigmas bound its inflation (ins.h). */
    if ((cfg->gyro_range <= SE23_R(0)) || (cfg->gyro_range > SE23_INS_GYRO_RANGE_MAX) ||
        (cfg->accel_range <= SE23_R(0)) || (cfg->accel_range > SE23_INS_ACCEL_RANGE_MAX) ||
        (cfg->outage_accel > cfg->accel_range + GRAVITY_BOUND) ||
        (cfg->outage_rate > cfg->gyro_range) || (cfg->max_outage > SE23_INS_MAX_OUTAGE) ||
        (is_flag(cfg->earth_rotation) == 0) || (is_flag(cfg->bias_states) == 0) ||
        (is_flag(cfg->zupt) == 0) || (cfg->gate_recover < 0) ||
        (cfg->zaru_after > SE23_INS_MAX_OUTAGE) || (cfg->floor_swing > SE23_INS_MAX_OUTAGE) ||
        (is_flag(cfg->gravity_test_off) == 0)) {
        return SE23_ERR_DOMAIN;
    }
    /* bounds far beyond any sensor's that keep the motion noise finite */
    if ((cfg->motion.gyro_scale > SE23_R(1)) || (cfg->motion.accel_scale > SE23_R(1)) ||
        (cfg->motion.gyro_g > SE23_R(1)) || (cfg->motion.corr_time > SE23_R(1)) ||
        (cfg->zupt_lever > SE23_R(1))) {
        return SE23_ERR_DOMAIN;
    }
    /* a mounting within one turn, an NHC update
     * at least once a minute, a GNSS clock within a second of the IMU's */
    if ((se23_v3_dot(&cfg->mount_bv, &cfg->mount_bv) > (SE23_R(4) * (SE23_PI * SE23_PI))) ||
        (cfg->nhc_sigma > SE23_MEAS_NHC_SIGMA_MAX) || (cfg->rest_speed_max > SE23_INS_VEL_MAX) ||
        (cfg->nhc_lever > SE23_R(10)) ||
        ((cfg->nhc_sigma > SE23_R(0)) &&
         ((cfg->nhc_interval <= SE23_R(0)) || (cfg->nhc_interval > SE23_R(60)))) ||
        (se23_fabs(cfg->gnss_time_offset) > SE23_R(1)) ||
        ((cfg->gravity_step > SE23_R(0)) && (cfg->gravity_step < SE23_R(1)))) {
        return SE23_ERR_DOMAIN;
    }
    if ((cfg->zupt != 0) && (cfg->zupt_sigma_v <= SE23_R(0))) {
        return SE23_ERR_DOMAIN;
    }
    if ((cfg->floor_sigma > SE23_R(0)) && ((cfg->zupt == 0) || (cfg->floor_step <= SE23_R(0)))) {
        return SE23_ERR_DOMAIN; /* floor updates happen at stances */
    }
    /* below 1 ns (the clock's resolution) max_gap / dt_nominal would not
     * fit the int64 of max_missing */
    if ((cfg->dt_nominal < SE23_R(1e-9)) || (cfg->max_gap < cfg->dt_nominal) ||
        (cfg->max_gap > SE23_R(SE23_CFG_DT_MAX))) {
        return SE23_ERR_DT;
    }
    if ((SE23_R(2) * cfg->delay_horizon / cfg->dt_nominal) + SE23_R(2) >
        (se23_real_t)SE23_INS_RING) {
        return SE23_ERR_DIM;
    }
    return SE23_OK;
}

se23_status_t se23_ins_setup(const se23_ins_config_t *cfg, se23_ins_t *ins)
{
    const se23_vec3_t zero = {{SE23_R(0), SE23_R(0), SE23_R(0)}};
    se23_vec3_t g_n, w_ie_n;
    se23_mat3_t C_bv;
    se23_earth_model_t model;
    se23_status_t st;
    SE23_CHECK_NOT_NULL(cfg);
    SE23_CHECK_NOT_NULL(ins);
    st = config_check(cfg);
    if (st == SE23_OK) {
        st = se23_earth_gravity_vec(SE23_FRAME_NED, cfg->lat, cfg->height, &g_n);
    }
    if (st == SE23_OK) {
        st = se23_earth_rate(SE23_FRAME_NED, cfg->lat, &w_ie_n);
    }
    /* Steps of up to SE23_CFG_DT_MAX: an outage is carried across in few
     * of them; the screening holds single samples to max_gap. */
    if (st == SE23_OK) {
        st = se23_earth_model_init(&g_n, (cfg->earth_rotation != 0) ? &w_ie_n : &zero,
                                   cfg->dt_nominal, SE23_CFG_DT_MAX, &model);
    }
    if (st == SE23_OK) {
        st = se23_so3_exp(&cfg->mount_bv, &C_bv);
    }
    if ((st == SE23_OK) && (cfg->zupt != 0)) {
        st = se23_stationary_init(&cfg->detector, &ins->det); /* nothing written on error */
    }
    if (st != SE23_OK) {
        return st;
    }
    {
        const se23_ins_counters_t none = {0};
        const se23_real_t per_gap = cfg->max_gap / cfg->dt_nominal;
        ins->cfg = *cfg;
        ins->noise = cfg->noise;
        ins->model = model;
        ins->status = 0U;
        if (cfg->earth_rotation != 0) {
            ins->status = SE23_INS_ST_EARTH_RATE;
        }
        ins->half_ns = to_ns(SE23_R(0.5) * cfg->dt_nominal);
        ins->max_gap_ns = to_ns(cfg->max_gap);
        ins->horizon_ns = to_ns(cfg->delay_horizon);
        ins->zaru_after_ns = to_ns(cfg->zaru_after);
        ins->floor_swing_ns = to_ns(cfg->floor_swing);
        ins->nhc_interval_ns = to_ns(cfg->nhc_interval);
        ins->gnss_offset_ns = to_ns(cfg->gnss_time_offset);
        ins->C_bv = C_bv;
        se23_ins_gravity_radii(ins);
        ins->max_missing = (int64_t)per_gap + 1;
        ins->nis_last = SE23_R(0);
        ins->zupt_nis_last = SE23_R(0);
        ins->zupt_nis_sum = SE23_R(0);
        ins->replaying = 0;
        ins->fac_ready = 0;
        ins->have_pending = 0;
        ins->c = none;
    }
    return SE23_OK;
}

void se23_ins_start(se23_ins_t *ins, int64_t t_ns, const se23_gauss_t *g)
{
    const se23_imu_sample_t none = {{{SE23_R(0)}}, {{SE23_R(0)}}, SE23_R(0)};
    ins->g = *g;
    ins->last = none;
    ins->t_ns = t_ns;
    ins->seq = 0;
    ins->max_seq = -1;
    ins->have_last = 0;
    ins->streak = 0;
    ins->back_streak = 0;
    se23_ins_drop_pending(ins); /* stamped for the state that ended */
    ins->last_fix_ns = -1;
    ins->gated_run = 0;
    ins->status = (ins->status & SE23_INS_ST_EARTH_RATE) |
                  SE23_INS_ST_INITIALISED;
    if (ins->cfg.zupt != 0) {
        se23_stationary_reset(&ins->det);
    }
    ins->rest_ns = 0;
    ins->move_ns = ins->floor_swing_ns; /* the first rest is a stance */
    ins->floor_d = SE23_R(0);
    ins->floor_set = 0;
    se23_ins_ring_restart(ins);
    se23_ins_gravity_follow(ins);
    se23_ins_factor_reset(ins);
}

/* The largest diagonal entry of g's covariance (checked finite). */
static se23_real_t p_diag_max(const se23_gauss_t *g)
{
    se23_real_t m = SE23_R(0);
    int i;
    for (i = 0; i < g->n; ++i) {
        const se23_real_t d = g->P.m[se23_ins_idx(i, i)];
        if (d > m) {
            m = d;
        }
    }
    return m;
}

/* P's upper triangle := its lower one, so that the state the filter keeps
 * is exactly symmetric. A caller's covariance is accepted symmetric within
 * a tolerance relative to its largest variance (gauss.h, "Validation"),
 * and an update that shrinks that variance (a GNSS gate reset) would leave
 * the asymmetry beyond it; the lower triangle is the one the check proved
 * positive semidefinite. */
static void mirror_lower(se23_gauss_t *g)
{
    int i, j;
    for (i = 0; i < g->n; ++i) {
        for (j = i + 1; j < g->n; ++j) {
            g->P.m[se23_ins_idx(i, j)] = g->P.m[se23_ins_idx(j, i)];
        }
    }
}

se23_status_t se23_ins_init(se23_ins_t *ins, int64_t t_ns, const se23_gauss_t *g)
{
    se23_status_t st;
    int n;
    SE23_CHECK_NOT_NULL(ins);
    SE23_CHECK_NOT_NULL(g);
    n = SE23_GAUSS_N_POSE;
    if (ins->cfg.bias_states != 0) {
        n = SE23_GAUSS_N_BIAS;
    }
    /* The state enters here: its one deep check. */
    if (g->n != n) {
        st = SE23_ERR_DIM;
    } else if (t_ns < 0) {
        st = SE23_ERR_DT;
    } else {
        st = se23_gauss_check(g);
    }
    if ((st == SE23_OK) && (p_diag_max(g) > SE23_INS_P_MAX)) {
        st = SE23_ERR_DOMAIN; /* an uncertainty no step could carry without overflow */
    }
    /* Means no sensor or vehicle has (ins.h, "Validation"): a bias beyond
     * the sensor's range would put its every reading out of range; v and p
     * beyond SE23_INS_VEL_MAX / SE23_INS_POS_MAX would take the steps
     * toward overflow. */
    if ((st == SE23_OK) && ((se23_ins_norm_within(&g->b_g, ins->cfg.gyro_range) == 0) ||
                            (se23_ins_norm_within(&g->b_a, ins->cfg.accel_range) == 0) ||
                            (se23_ins_norm_within(&g->T.v, SE23_INS_VEL_MAX) == 0) ||
                            (se23_ins_norm_within(&g->T.p, SE23_INS_POS_MAX) == 0))) {
        st = SE23_ERR_DOMAIN;
    }
    if (st == SE23_OK) {
        st = se23_gauss_to_carried(&ins->model, g, &ins->work);
    }
    if (st != SE23_OK) {
        se23_ins_count(&ins->c.init_rejected);
        return st;
    }
    mirror_lower(&ins->work);
    se23_ins_start(ins, t_ns, &ins->work);
    return SE23_OK;
}

se23_status_t se23_ins_state(const se23_ins_t *ins, se23_gauss_t *out, int64_t *t_ns)
{
    se23_status_t st;
    SE23_CHECK_NOT_NULL(ins);
    SE23_CHECK_NOT_NULL(out);
    SE23_CHECK_NOT_NULL(t_ns);
    if ((ins->status & SE23_INS_ST_INITIALISED) == 0U) {
        return SE23_ERR_DIM;
    }
    /* not re-proved here (ins.h): the updates that can leave a state outside
     * se23_gauss_check are checked where they are kept (commit, ins_aid.c) */
    st = se23_gauss_from_carried(&ins->model, &ins->g, out);
    if (st == SE23_OK) {
        *t_ns = ins->t_ns;
    }
    return st;
}

int se23_ins_take_factor(se23_ins_t *ins, se23_ins_factor_t *out)
{
    if ((ins == NULL) || (out == NULL) || (ins->fac_ready == 0)) {
        return 0;
    }
    *out = ins->fac_out;
    ins->fac_ready = 0;
    return 1;
}

/* Seq bookkeeping of a received sample (seq >= 0): losses in transit, or a
 * jump too large to be one; an over-gap sample's large jump is left to the
 * outage logic (over_gap nonzero). */
static void count_missing(se23_ins_t *ins, int64_t seq, int over_gap)
{
    if (ins->max_seq < 0) {
        ins->max_seq = seq;
    } else if (seq > ins->max_seq) {
        const int64_t lost = seq - ins->max_seq - 1; /* both >= 0: no overflow */
        if (lost <= ins->max_missing) {
            se23_ins_count_add(&ins->c.imu_missing, lost);
            ins->max_seq = seq;
        } else if (over_gap == 0) {
            se23_ins_count(&ins->c.imu_seq_jumps);
        } else {
            /* maybe an outage: judged when it is confirmed */
        }
    } else {
        /* an old or repeated seq: judged by the time screening */
    }
}

/*
 * A clock that stepped back and stays there: SE23_INS_OUTAGE_CONFIRM
 * consecutive bad-time samples that agree among themselves (consecutive
 * seq, 0 < dt <= max_gap between them) re-base the filter's time on the
 * new clock. The interval between the last good sample and the step is
 * unknown: the state is kept as it is (the few samples of the streak are
 * lost), the rest bookkeeping starts again, status DEGRADED until a fix.
 * Returns 1 if this sample confirmed the step.
 */
static int clock_stepped_back(se23_ins_t *ins, int64_t t_ns, int64_t seq)
{
    if (!((ins->back_streak > 0) && (t_ns > ins->back_t_ns) &&
          (t_ns - ins->back_t_ns <= ins->max_gap_ns) && (seq - 1 == ins->back_seq))) {
        ins->back_streak = 0;
    }
    ins->back_streak++;
    ins->back_t_ns = t_ns;
    ins->back_seq = seq;
    if (ins->back_streak < SE23_INS_OUTAGE_CONFIRM) {
        return 0;
    }
    ins->back_streak = 0;
    se23_ins_count(&ins->c.time_resets);
    ins->t_ns = t_ns;
    ins->seq = seq;
    ins->max_seq = seq;
    ins->last.dt = SE23_R(0); /* not a reading at the next interval's start: no interpolation */
    ins->last_fix_ns = -1;
    se23_ins_drop_pending(ins); /* stamped by the old clock */
    ins->status |= SE23_INS_ST_DEGRADED;
    if (ins->cfg.zupt != 0) {
        se23_stationary_reset(&ins->det);
    }
    ins->rest_ns = 0;
    se23_ins_ring_restart(ins);
    se23_ins_factor_reset(ins);
    return 1;
}

/* The screening verdict of a finite, in-range sample that is not after the
 * last accepted one. */
static se23_ins_verdict_t not_after(se23_ins_t *ins, int64_t t_ns, int64_t seq)
{
    if ((ins->have_last != 0) && (seq == ins->seq)) {
        se23_ins_count(&ins->c.imu_duplicate);
        return SE23_INS_DUPLICATE;
    }
    if ((ins->have_last != 0) && (seq < ins->seq)) {
        se23_ins_count(&ins->c.imu_out_of_order);
        return SE23_INS_OUT_OF_ORDER;
    }
    se23_ins_count(&ins->c.imu_bad_time);
    return (clock_stepped_back(ins, t_ns, seq) != 0) ? SE23_INS_OUTAGE : SE23_INS_BAD_TIME;
}

static se23_ins_verdict_t fix_verdict(se23_ins_t *ins, const se23_ins_gnss_t *fix);

/* A pending fix whose time the state has reached is fused (its time
 * already on the IMU's clock). */
static void service_pending(se23_ins_t *ins)
{
    /* t_ns - half_ns: t_ns + half_ns can overflow near INT64_MAX */
    if ((ins->have_pending != 0) && (ins->pending.t_ns - ins->half_ns <= ins->t_ns)) {
        ins->have_pending = 0;
        (void)fix_verdict(ins, &ins->pending);
    }
}

/* An accepted live sample: the step, then the bookkeeping. */
static se23_ins_verdict_t accept(se23_ins_t *ins, int64_t t_ns, int64_t seq,
                                 const se23_imu_sample_t *s)
{
    const int rest = se23_ins_rest_level(ins, s, t_ns - ins->t_ns);
    const se23_imu_sample_t prev = ins->last;
    if (se23_ins_step(ins, t_ns, s, rest) == 0) {
        se23_ins_count(&ins->c.imu_failed); /* and filter_errors, by the step */
        return SE23_INS_FAILED;
    }
    ins->streak = 0;
    ins->seq = seq;
    se23_ins_count(&ins->c.imu_used);
    se23_ins_factor_add(ins, &prev, s);
    se23_ins_ring_push(ins, s, rest);
    service_pending(ins);
    return SE23_INS_USED;
}

se23_ins_verdict_t se23_ins_imu(se23_ins_t *ins, int64_t t_ns, int64_t seq,
                                const se23_vec3_t *w_b, const se23_vec3_t *f_b)
{
    se23_imu_sample_t s;
    const uint32_t live = SE23_INS_ST_INITIALISED | SE23_INS_ST_ALIGNING;
    if (ins == NULL) {
        return SE23_INS_FAILED;
    }
    if ((w_b == NULL) || (f_b == NULL)) {
        se23_ins_count(&ins->c.imu_failed);
        return SE23_INS_FAILED;
    }
    if ((ins->status & live) == 0U) {
        se23_ins_count(&ins->c.imu_early);
        return SE23_INS_EARLY;
    }
    if ((seq >= 0) && ((ins->status & SE23_INS_ST_ALIGNING) == 0U)) {
        /* every received sample's seq counts, whatever its verdict
         * (ins->t_ns >= 0: t_ns - ins->t_ns cannot overflow) */
        count_missing(ins, seq, (t_ns > ins->t_ns) && (t_ns - ins->t_ns > ins->max_gap_ns));
    }
    if ((se23_all_finite(w_b->v, 3) == 0) || (se23_all_finite(f_b->v, 3) == 0)) {
        se23_ins_count(&ins->c.imu_nonfinite);
        return SE23_INS_NONFINITE;
    }
    if ((t_ns < 0) || (seq < 0)) {
        se23_ins_count(&ins->c.imu_bad_time); /* outside the clock's domain */
        return SE23_INS_BAD_TIME;
    }
    s.w_ib_b = *w_b;
    s.f_b = *f_b;
    s.dt = SE23_R(0);
    if ((axes_within(w_b, ins->cfg.gyro_range) == 0) ||
        (axes_within(f_b, ins->cfg.accel_range) == 0)) {
        se23_ins_count(&ins->c.imu_range);
        return SE23_INS_RANGE;
    }
    if ((ins->status & SE23_INS_ST_ALIGNING) != 0U) {
        se23_ins_count(&ins->c.imu_align);
        return se23_ins_align_sample(ins, t_ns, &s);
    }
    if (t_ns <= ins->t_ns) {
        return not_after(ins, t_ns, seq);
    }
    ins->back_streak = 0;
    if (t_ns - ins->t_ns > ins->max_gap_ns) {
        return se23_ins_over_gap(ins, t_ns, seq);
    }
    {
        const int64_t dt_ns = t_ns - ins->t_ns;
        s.dt = (se23_real_t)dt_ns / SE23_INS_NS;
    }
    return accept(ins, t_ns, seq, &s);
}

/* A usable 1-sigma: positive and at most FIX_SIGMA_MAX. */
static int sigma_ok(const se23_vec3_t *s)
{
    int i;
    for (i = 0; i < 3; ++i) {
        if (!((s->v[i] > SE23_R(0)) && (s->v[i] <= FIX_SIGMA_MAX))) {
            return 0;
        }
    }
    return 1;
}

/* Nonzero if every field fix states is finite, within the bounds of a
 * state (SE23_INS_POS_MAX, SE23_INS_VEL_MAX: a gate reset makes it the
 * state), and its sigmas usable (NaN fails the sigma test too). */
static int fix_valid(const se23_ins_gnss_t *fix)
{
    if ((fix->t_ns < 0) || (se23_all_finite(fix->p_n.v, 3) == 0) ||
        (se23_ins_norm_within(&fix->p_n, SE23_INS_POS_MAX) == 0) ||
        (sigma_ok(&fix->sigma_p) == 0)) {
        return 0;
    }
    if ((fix->has_vel != 0) &&
        ((se23_all_finite(fix->v_n.v, 3) == 0) ||
         (se23_ins_norm_within(&fix->v_n, SE23_INS_VEL_MAX) == 0) ||
         (sigma_ok(&fix->sigma_v) == 0))) {
        return 0;
    }
    return 1;
}

/* The verdict of a fix that is not NULL (se23_ins_gnss). */
static se23_ins_verdict_t judge_fix(se23_ins_t *ins, const se23_ins_gnss_t *fix)
{
    se23_ins_verdict_t v;
    if (((ins->status & SE23_INS_ST_INITIALISED) == 0U) ||
        ((ins->status & SE23_INS_ST_LOST) != 0U)) {
        se23_ins_count(&ins->c.gnss_early);
        return SE23_INS_EARLY;
    }
    if (fix_valid(fix) == 0) {
        se23_ins_count(&ins->c.gnss_nonfinite);
        return SE23_INS_NONFINITE;
    }
    /* ahead: waits for the state (fix->t_ns >= 0: the difference cannot
     * overflow, ins->t_ns + half_ns could) */
    if (fix->t_ns - ins->half_ns > ins->t_ns) {
        se23_ins_drop_pending(ins); /* replaced */
        ins->pending = *fix;
        ins->have_pending = 1;
        return SE23_INS_PENDING;
    }
    if ((fix->t_ns <= ins->last_fix_ns) || (fix->t_ns < ins->t_ns - ins->half_ns - ins->horizon_ns)) {
        se23_ins_count(&ins->c.gnss_stale);
        return SE23_INS_STALE;
    }
    if (fix->t_ns >= ins->t_ns - ins->half_ns) { /* now */
        v = se23_ins_fuse_gnss(ins, fix);
        if ((v == SE23_INS_USED) || (v == SE23_INS_RESET)) {
            se23_ins_ring_restart(ins); /* later fixes are after this one */
        }
    } else {
        v = se23_ins_fuse_delayed(ins, fix);
    }
    return v;
}

/* The verdict of a fix on the IMU's clock, a failure counted. */
static se23_ins_verdict_t fix_verdict(se23_ins_t *ins, const se23_ins_gnss_t *fix)
{
    const se23_ins_verdict_t v = judge_fix(ins, fix);
    if (v == SE23_INS_FAILED) {
        se23_ins_count(&ins->c.gnss_failed); /* a failed update: also in filter_errors */
    }
    return v;
}

se23_ins_verdict_t se23_ins_gnss(se23_ins_t *ins, const se23_ins_gnss_t *fix)
{
    se23_ins_gnss_t on_imu_clock;
    if (ins == NULL) {
        return SE23_INS_FAILED;
    }
    if (fix == NULL) {
        se23_ins_count(&ins->c.gnss_failed);
        return SE23_INS_FAILED;
    }
    on_imu_clock = *fix;
    /* t + offset, |offset| <= 1 s: only a time within a second of
     * INT64_MAX can overflow; a negative time, before or after the
     * offset, fix_valid refuses */
    if ((fix->t_ns < 0) ||
        ((ins->gnss_offset_ns > 0) && (fix->t_ns > INT64_MAX - ins->gnss_offset_ns))) {
        on_imu_clock.t_ns = -1;
    } else {
        on_imu_clock.t_ns = fix->t_ns + ins->gnss_offset_ns;
    }
    return fix_verdict(ins, &on_imu_clock);
}
