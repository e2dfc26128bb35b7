/* The navigation filter's step of one accepted sample and its
 * preintegrated factor; see ins.h. */
#include "ins_internal.h"

int se23_ins_step(se23_ins_t *ins, int64_t t_ns, const se23_imu_sample_t *s, int rest)
{
    if (se23_ins_predict_interval(ins, s) == 0) {
        return 0;
    }
    ins->t_ns = t_ns;
    ins->last = *s;
    ins->have_last = 1;
    if ((rest & SE23_INS_REST_LEVEL) != SE23_INS_REST_NONE) {
        ins->status |= SE23_INS_ST_STATIONARY;
        (void)se23_ins_zupt(ins, s, rest); /* a failure is counted; the prediction stands */
    } else {
        ins->status &= ~SE23_INS_ST_STATIONARY;
        se23_ins_gravity_follow(ins); /* the position it reached (at rest it stays) */
        if ((rest & SE23_INS_REST_NHC) != 0) {
            (void)se23_ins_nhc(ins); /* a failure is counted; the prediction stands */
        }
    }
    return 1;
}

void se23_ins_factor_reset(se23_ins_t *ins)
{
    if (ins->cfg.preint_window <= SE23_R(0)) {
        return;
    }
    /* The biases of a state the library produced are finite: cannot fail. */
    (void)se23_preint_unc_reset(&ins->g.b_g, &ins->g.b_a, SE23_INPUT_JAC_EXACT, &ins->fac.f);
    ins->fac.t0_ns = ins->t_ns;
    ins->fac.t1_ns = ins->t_ns;
}

void se23_ins_factor_add(se23_ins_t *ins, const se23_imu_sample_t *prev,
                         const se23_imu_sample_t *s)
{
    se23_imu_sample_t u;
    int n, j;
    if (ins->cfg.preint_window <= SE23_R(0)) {
        return;
    }
    if (ins->fac.f.f.n == 0U) {
        ins->fac.seq0 = ins->seq; /* the window's first sample (accept() has set seq) */
    }
    n = se23_ins_gap_steps(ins, prev, s);
    /* the same sub-intervals as the filter's prediction */
    for (j = 1; j <= n; ++j) {
        se23_ins_gap_sample(prev, s, j, n, &u);
        if (se23_preint_unc_add_work(&ins->fac.f, &u, &ins->noise, &ins->kernel.preint) !=
            SE23_OK) {
            se23_ins_count(&ins->c.filter_errors);
            se23_ins_factor_reset(ins);
            return;
        }
    }
    if (ins->fac.f.f.dt >= ins->cfg.preint_window - (SE23_R(0.5) * ins->cfg.dt_nominal)) {
        ins->fac.t1_ns = ins->t_ns;
        ins->fac_out = ins->fac;
        ins->fac_ready = 1;
        se23_ins_factor_reset(ins);
    }
}
