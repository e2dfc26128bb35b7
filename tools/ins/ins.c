/* The INS engine of se23-ins; see ins.h. */
#include "ins.h"

#include <math.h>
#include <string.h>

#include "se23/so3.h"
#include "update.h"

#define NS_PER_S 1e9
#define NORMALIZE_EVERY 1000 /* steps between re-orthonormalisations of R */

static int all_finite(const double *x, int n)
{
    int i;
    for (i = 0; i < n; i++) {
        if (!isfinite(x[i])) {
            return 0;
        }
    }
    return 1;
}

static double norm3(const double x[3])
{
    return sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
}

int ins_setup(ins_t *ins, const ins_config_t *cfg)
{
    se23_vec3_t g_n, w_ie_n, zero = {{0.0, 0.0, 0.0}};
    memset(ins, 0, sizeof *ins);
    if (!(cfg->dt_nominal > 0.0) || !(cfg->max_gap >= cfg->dt_nominal) ||
        !(cfg->max_gap <= SE23_CFG_DT_MAX) || !(cfg->max_outage >= 0.0)) {
        return -1;
    }
    ins->cfg = *cfg;
    if (se23_earth_gravity_vec(SE23_FRAME_NED, cfg->lat, 0.0, &g_n) != SE23_OK ||
        se23_earth_rate(SE23_FRAME_NED, cfg->lat, &w_ie_n) != SE23_OK) {
        return -1;
    }
    if (se23_earth_model_init(&g_n, cfg->earth_rotation ? &w_ie_n : &zero, cfg->dt_nominal,
                              cfg->max_gap, &ins->model) != SE23_OK) {
        return -1;
    }
    ins->status = cfg->earth_rotation ? INS_ST_EARTH_RATE : 0;
    return 0;
}

static void factor_reset(ins_t *ins)
{
    int i;
    se23_preint_reset(&ins->fac.f);
    memset(&ins->fac.cov, 0, sizeof ins->fac.cov);
    memset(&ins->fac.J, 0, sizeof ins->fac.J);
    ins->fac.t0_ns = ins->t_ns;
    ins->fac.seq0 = ins->seq + 1;
    for (i = 0; i < 3; i++) {
        ins->fac.b_g_lin[i] = ins->g.b_g.v[i];
        ins->fac.b_a_lin[i] = ins->g.b_a.v[i];
    }
}

int ins_init(ins_t *ins, const ins_init_t *init)
{
    se23_gauss_t user, carried;
    const int n = ins->cfg.bias_states ? SE23_GAUSS_N_BIAS : SE23_GAUSS_N_POSE;
    int i, j;
    memset(&user, 0, sizeof user);
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            user.T.R.m[i][j] = init->R_nb[3 * i + j];
        }
        user.T.v.v[i] = init->v_n[i];
        user.T.p.v[i] = init->p_n[i];
        user.b_g.v[i] = init->b_g[i];
        user.b_a.v[i] = init->b_a[i];
    }
    user.n = n;
    for (i = 0; i < n; i++) {
        for (j = 0; j < n; j++) {
            user.P.m[SE23_GAUSS_NMAX * i + j] = init->P[15 * i + j];
        }
    }
    /* The state enters here: checked once (the steps trust it after). */
    if (se23_gauss_check(&user) != SE23_OK ||
        se23_gauss_to_carried(&ins->model, &user, &carried) != SE23_OK) {
        ins->c.init_rejected++; /* invalid pose or covariance: state kept */
        return -1;
    }
    ins->g = carried;
    ins->t_ns = init->t_ns;
    ins->seq = 0;
    ins->max_seq_seen = 0;
    ins->have_last = 0;
    ins->streak = 0;
    ins->have_pending = 0;
    ins->status = (ins->status & INS_ST_EARTH_RATE) | INS_ST_INITIALISED;
    factor_reset(ins);
    return 0;
}

void ins_decode_error(ins_t *ins)
{
    ins->c.decode_errors++;
}

/* Applies fix now: in the user's coordinates, then back to carried. */
static void apply_gnss(ins_t *ins, const ins_gnss_t *fix)
{
    se23_gauss_t user, carried;
    double nis = 0.0;
    int rc;
    if (se23_gauss_from_carried(&ins->model, &ins->g, &user) != SE23_OK) {
        ins->c.filter_errors++;
        ins->c.gnss_rejected++;
        return;
    }
    rc = ins_update_gnss(&user, fix, ins->cfg.gnss_gate, &nis);
    if (rc == 0 && se23_gauss_to_carried(&ins->model, &user, &carried) == SE23_OK) {
        ins->g = carried;
        ins->nis_last = nis;
        ins->c.gnss_used++;
        ins->status |= INS_ST_GNSS_AIDED;
        ins->status &= ~(INS_ST_DEGRADED | INS_ST_GNSS_GATED);
        return;
    }
    ins->c.gnss_rejected++;
    if (rc == 1) {
        ins->nis_last = nis;
        ins->status |= INS_ST_GNSS_GATED;
    } else {
        ins->c.filter_errors++;
    }
}

static int64_t half_sample_ns(const ins_t *ins)
{
    return (int64_t)(0.5 * ins->cfg.dt_nominal * NS_PER_S);
}

/* A pending fix whose time the state has reached is applied; a stale one dropped. */
static void service_pending(ins_t *ins)
{
    int64_t half = half_sample_ns(ins);
    if (!ins->have_pending) {
        return;
    }
    if (ins->pending.t_ns < ins->t_ns - half) {
        ins->have_pending = 0;
        ins->c.gnss_rejected++;
    } else if (ins->pending.t_ns <= ins->t_ns + half) {
        ins->have_pending = 0;
        apply_gnss(ins, &ins->pending);
    }
}

int ins_gnss(ins_t *ins, const ins_gnss_t *fix)
{
    int64_t half = half_sample_ns(ins);
    int i;
    if (!(ins->status & INS_ST_INITIALISED) || (ins->status & INS_ST_LOST)) {
        ins->c.gnss_rejected++;
        return 0;
    }
    for (i = 0; i < 3; i++) {
        if (!isfinite(fix->p_n[i]) || !(fix->sigma_p[i] > 0.0) || !isfinite(fix->sigma_p[i]) ||
            (fix->has_vel && (!isfinite(fix->v_n[i]) || !(fix->sigma_v[i] > 0.0) ||
                              !isfinite(fix->sigma_v[i])))) {
            ins->c.gnss_rejected++;
            return 0;
        }
    }
    if (fix->t_ns < ins->t_ns - half) {
        ins->c.gnss_rejected++; /* stale */
        return 0;
    }
    if (fix->t_ns > ins->t_ns + half) {
        if (ins->have_pending) {
            ins->c.gnss_rejected++; /* superseded */
        }
        ins->pending = *fix;
        ins->have_pending = 1;
        return 0;
    }
    apply_gnss(ins, fix);
    return (ins->status & INS_ST_GNSS_GATED) ? 0 : 1;
}

/* Adds the (raw) sample s to the preintegrated factor. */
static void factor_add(ins_t *ins, const se23_imu_sample_t *s)
{
    se23_imu_sample_t c = *s;
    se23_pose_t U;
    se23_mat9x6_t B, FJ;
    se23_mat9_t Q, cov;
    int i;
    if (ins->cfg.preint_window <= 0.0) {
        return;
    }
    for (i = 0; i < 3; i++) { /* corrected with the factor's linearisation biases */
        c.w_ib_b.v[i] += ins->fac.b_g_lin[i];
        c.f_b.v[i] += ins->fac.b_a_lin[i];
    }
    if (se23_imu_increment(&c, &U) != SE23_OK ||
        se23_gauss_input_jac(SE23_INPUT_JAC_EXACT, &c.w_ib_b, &c.f_b, c.dt, &B) != SE23_OK ||
        se23_gauss_input_noise(&B, &ins->cfg.noise, c.dt, &Q) != SE23_OK ||
        se23_gauss_cov_propagate(&ins->fac.cov, &U, c.dt, &Q, &cov) != SE23_OK) {
        ins->c.filter_errors++;
        factor_reset(ins);
        return;
    }
    se23_gauss_fk_mul(&U, c.dt, &ins->fac.J, &FJ); /* J+ = F_k J + B_k */
    for (i = 0; i < 54; i++) {
        ins->fac.J.m[i] = FJ.m[i] + B.m[i];
    }
    ins->fac.cov = cov;
    se23_preint_add_increment(&ins->fac.f, &U, c.dt);
    if (ins->fac.f.dt >= ins->cfg.preint_window - 0.5 * ins->cfg.dt_nominal) {
        ins->fac.t1_ns = ins->t_ns;
        ins->fac_out = ins->fac;
        ins->fac_ready = 1;
        factor_reset(ins);
    }
}

/* One prediction step; the state is kept on failure. */
static int predict(ins_t *ins, const se23_imu_sample_t *s)
{
    se23_gauss_t next;
    if (se23_gauss_predict(&ins->model, &ins->g, s, &ins->cfg.noise, SE23_INPUT_JAC_EXACT,
                           &next) != SE23_OK) {
        ins->c.filter_errors++;
        return 0;
    }
    if (++ins->steps_since_norm >= NORMALIZE_EVERY) {
        se23_mat3_t Rn;
        if (se23_so3_normalize(&next.T.R, &Rn) == SE23_OK) {
            next.T.R = Rn;
        }
        ins->steps_since_norm = 0;
    }
    ins->g = next;
    return 1;
}

/*
 * Carries the state over an outage of gap seconds by holding the last
 * accepted sample (in chunks the model accepts), then inflates the
 * covariance by the outage dynamics.
 */
static void carry_across(ins_t *ins, double gap)
{
    double left = gap;
    double sr = ins->cfg.outage_rate * gap;
    double sv = ins->cfg.outage_accel * gap;
    double sp = 0.5 * ins->cfg.outage_accel * gap * gap;
    int i;
    while (left > 0.0 && ins->have_last) {
        se23_imu_sample_t s = ins->last;
        s.dt = left > ins->model.dt_max ? ins->model.dt_max : left;
        if (!predict(ins, &s)) {
            break;
        }
        left -= s.dt;
    }
    for (i = 0; i < 3; i++) {
        ins->g.P.m[SE23_GAUSS_NMAX * (SE23_IDX_PHI + i) + SE23_IDX_PHI + i] += sr * sr;
        ins->g.P.m[SE23_GAUSS_NMAX * (SE23_IDX_NU + i) + SE23_IDX_NU + i] += sv * sv;
        ins->g.P.m[SE23_GAUSS_NMAX * (SE23_IDX_RHO + i) + SE23_IDX_RHO + i] += sp * sp;
    }
    ins->status |= INS_ST_DEGRADED;
    if (ins->have_pending) { /* a fix from inside the outage: cannot be placed */
        ins->have_pending = 0;
        ins->c.gnss_rejected++;
    }
    factor_reset(ins);
}

/* A sample with dt > max_gap: rejected, or it confirms an outage. */
static void over_gap(ins_t *ins, int64_t t_ns, int64_t seq)
{
    int consistent = ins->streak > 0 && t_ns > ins->streak_t_ns &&
                     (double)(t_ns - ins->streak_t_ns) <= ins->cfg.max_gap * NS_PER_S &&
                     seq == ins->streak_seq + 1;
    ins->c.imu_bad_dt++;
    if (!consistent) {
        ins->streak = 0;
        ins->streak_t0_ns = t_ns;
    }
    ins->streak++;
    ins->streak_t_ns = t_ns;
    ins->streak_seq = seq;
    if (ins->streak < INS_OUTAGE_CONFIRM) {
        return;
    }
    /* confirmed: the stream jumped forward */
    ins->streak = 0;
    ins->c.time_resets++;
    {
        double gap = (double)(t_ns - ins->t_ns) / NS_PER_S;
        if (gap > ins->cfg.max_outage) {
            ins->status |= INS_ST_LOST;
            ins->status &= ~INS_ST_INITIALISED;
            return;
        }
        carry_across(ins, gap);
    }
    ins->t_ns = t_ns;
    ins->seq = seq;
}

int ins_imu(ins_t *ins, int64_t t_ns, int64_t seq, const double omega[3], const double accel[3])
{
    se23_imu_sample_t s;
    double dt;
    int i;
    if (!(ins->status & INS_ST_INITIALISED)) {
        ins->c.imu_early++;
        return 0;
    }
    if (ins->max_seq_seen > 0 && seq > ins->max_seq_seen + 1) {
        ins->c.imu_missing += seq - ins->max_seq_seen - 1; /* lost in transit */
    }
    if (seq > ins->max_seq_seen) {
        ins->max_seq_seen = seq;
    }
    if (!all_finite(omega, 3) || !all_finite(accel, 3)) {
        ins->c.imu_nonfinite++;
        return 0;
    }
    if (norm3(omega) > ins->cfg.gyro_range || norm3(accel) > ins->cfg.accel_range) {
        ins->c.imu_range++;
        return 0;
    }
    if (t_ns <= ins->t_ns) {
        if (ins->seq > 0 && seq == ins->seq) {
            ins->c.imu_duplicate++;
        } else if (ins->seq > 0 && seq < ins->seq) {
            ins->c.imu_out_of_order++;
        } else {
            ins->c.imu_bad_time++;
        }
        return 0;
    }
    dt = (double)(t_ns - ins->t_ns) / NS_PER_S;
    if (dt > ins->cfg.max_gap) {
        over_gap(ins, t_ns, seq);
        return 0;
    }
    for (i = 0; i < 3; i++) {
        s.w_ib_b.v[i] = omega[i];
        s.f_b.v[i] = accel[i];
    }
    s.dt = dt;
    if (!predict(ins, &s)) {
        return 0;
    }
    ins->streak = 0;
    ins->t_ns = t_ns;
    ins->seq = seq;
    ins->last = s;
    ins->have_last = 1;
    ins->c.imu_used++;
    factor_add(ins, &s);
    service_pending(ins);
    return 1;
}

int ins_output(const ins_t *ins, ins_output_t *out)
{
    se23_gauss_t user;
    int i, j;
    if (!(ins->status & INS_ST_INITIALISED) ||
        se23_gauss_from_carried(&ins->model, &ins->g, &user) != SE23_OK) {
        return -1;
    }
    memset(out, 0, sizeof *out);
    out->t_ns = ins->t_ns;
    out->seq = ins->seq;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            out->R_nb[3 * i + j] = user.T.R.m[i][j];
        }
        out->v_n[i] = user.T.v.v[i];
        out->p_n[i] = user.T.p.v[i];
        out->b_g[i] = user.b_g.v[i];
        out->b_a[i] = user.b_a.v[i];
    }
    for (i = 0; i < user.n; i++) {
        for (j = 0; j < user.n; j++) {
            out->P[15 * i + j] = user.P.m[SE23_GAUSS_NMAX * i + j];
        }
    }
    out->status = ins->status;
    out->nis_last = ins->nis_last;
    return 0;
}

int ins_take_factor(ins_t *ins, ins_factor_t *out)
{
    if (!ins->fac_ready) {
        return 0;
    }
    *out = ins->fac_out;
    ins->fac_ready = 0;
    return 1;
}
