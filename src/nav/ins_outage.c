/* The navigation filter's over-gap samples and outage carry-across; see
 * ins.h, "Outage". */
#include "ins_internal.h"

/* P(i, i) += var for the three axes of the error block at first, raising
 * none above SE23_INS_P_MAX (one already above is left as it is; ins.h,
 * "Outage"): the covariance stays finite however long the outages and
 * however many. */
static void inflate(se23_gauss_t *g, int first, se23_real_t var)
{
    int i;
    for (i = first; i < first + 3; ++i) {
        se23_real_t *d = &g->P.m[se23_ins_idx(i, i)];
        const se23_real_t room = SE23_INS_P_MAX - *d;
        if (room > SE23_R(0)) {
            *d += (var < room) ? var : room;
        }
    }
}

/*
 * Carries the state over gap seconds (<= max_outage) by holding the last
 * accepted sample, in steps the model accepts, then adds the outage
 * dynamics: an unknown rate (phi grows as sr t), acceleration (nu as sa t,
 * rho as sa t^2 / 2), each 1-sigma per axis. A diagonal addition keeps P
 * symmetric PSD.
 */
static void carry_across(se23_ins_t *ins, se23_real_t gap)
{
    const se23_real_t sr = ins->cfg.outage_rate * gap;
    const se23_real_t sv = ins->cfg.outage_accel * gap;
    const se23_real_t sp = SE23_R(0.5) * sv * gap;
    const se23_real_t steps = gap / ins->model.dt_max; /* <= max_outage / dt_max */
    const int n = (int)steps + 1;
    se23_imu_sample_t s = ins->last;
    int k;
    s.dt = gap / (se23_real_t)n; /* n equal steps, each <= dt_max */
    for (k = 0; (k < n) && (ins->have_last != 0); ++k) {
        if (se23_ins_predict(ins, &s) == 0) {
            break;
        }
    }
    inflate(&ins->g, SE23_IDX_PHI, sr * sr);
    inflate(&ins->g, SE23_IDX_NU, sv * sv);
    inflate(&ins->g, SE23_IDX_RHO, sp * sp);
    ins->status |= SE23_INS_ST_DEGRADED;
    se23_ins_drop_pending(ins); /* a fix from inside the outage: cannot be placed */
}

/*
 * The seq numbers the outage skipped, before the streak that confirmed it
 * (seq its last): lost samples if the time gap could hold them, else a
 * corrupted seq.
 */
static void count_lost(se23_ins_t *ins, int64_t t_ns, int64_t seq)
{
    const int64_t first = seq - (SE23_INS_OUTAGE_CONFIRM - 1);
    const int64_t dt_ns = (2 * ins->half_ns > 0) ? (2 * ins->half_ns) : 1;
    const int64_t room = ((t_ns - ins->t_ns) / dt_ns) + ins->max_missing;
    if ((ins->max_seq < 0) || (first <= ins->max_seq)) {
        return; /* no reference, or no seq skipped */
    }
    if (first - ins->max_seq - 1 <= room) {
        se23_ins_count_add(&ins->c.imu_missing, first - ins->max_seq - 1);
    } else {
        se23_ins_count(&ins->c.imu_seq_jumps);
    }
}

se23_ins_verdict_t se23_ins_over_gap(se23_ins_t *ins, int64_t t_ns, int64_t seq)
{
    /* t_ns, seq >= 0 (screened): the differences cannot overflow. */
    se23_real_t gap;
    se23_ins_count(&ins->c.imu_bad_dt);
    if (!((ins->streak > 0) && (t_ns > ins->streak_t_ns) &&
          (t_ns - ins->streak_t_ns <= ins->max_gap_ns) && (seq - 1 == ins->streak_seq))) {
        ins->streak = 0; /* not consistent with the streak: a new one starts */
    }
    ins->streak++;
    ins->streak_t_ns = t_ns;
    ins->streak_seq = seq;
    if (ins->streak < SE23_INS_OUTAGE_CONFIRM) {
        return SE23_INS_BAD_DT;
    }
    /* confirmed: the stream jumped forward */
    ins->streak = 0;
    se23_ins_count(&ins->c.time_resets);
    {
        const int64_t gap_ns = t_ns - ins->t_ns;
        gap = (se23_real_t)gap_ns / SE23_INS_NS;
    }
    if (gap > ins->cfg.max_outage) {
        ins->status |= SE23_INS_ST_LOST;
        ins->status &= ~SE23_INS_ST_INITIALISED;
        se23_ins_drop_pending(ins); /* its state is lost */
        return SE23_INS_OUTAGE;
    }
    carry_across(ins, gap);
    ins->last.dt = SE23_R(0); /* not a reading at the next interval's start: no interpolation */
    count_lost(ins, t_ns, seq);
    ins->t_ns = t_ns;
    ins->seq = seq;
    ins->max_seq = seq;
    if (ins->cfg.zupt != 0) {
        se23_stationary_reset(&ins->det); /* the window would span the outage */
        ins->rest_ns = 0;
    }
    se23_ins_ring_restart(ins);
    se23_ins_factor_reset(ins);
    return SE23_INS_OUTAGE;
}
