/* The navigation filter's lost samples (ins.h, "Lost samples"): the
 * sub-intervals of a sample that follows lost ones, their interpolated
 * readings, and the prediction over them. A file apart from the step
 * (ins_step.c) so that the sub-interval's reading is off the stack
 * before the rest updates that follow the prediction. */
#include "ins_internal.h"

#include "../base/linalg.h"
#include "../base/se23_math.h"

/*
 * Sub-intervals of sample s after the reading prev (ins.h, "Lost
 * samples"): n = round(dt / dt_nominal), at most SE23_INS_GAP_STEPS; 1
 * without a reading at the interval's start (prev->dt is 0 before the
 * first accepted sample of a state, in the alignment's last sample, and
 * after an outage or a clock step).
 */
int se23_ins_gap_steps(const se23_ins_t *ins, const se23_imu_sample_t *prev,
                       const se23_imu_sample_t *s)
{
    const se23_real_t r = (s->dt / ins->cfg.dt_nominal) + SE23_R(0.5);
    if ((prev->dt <= SE23_R(0)) || (r < SE23_R(2))) {
        return 1;
    }
    return (r >= (se23_real_t)SE23_INS_GAP_STEPS) ? SE23_INS_GAP_STEPS : (int)r;
}

/*
 * u = the reading of sub-interval j (1..n) of s: linear in time between
 * prev (at the interval's start) and s (at its end), u(t) = prev + (t -
 * t_prev) / dt (s - prev), taken at the sub-interval's end and held over
 * it like a received sample; u = s for j = n.
 */
void se23_ins_gap_sample(const se23_imu_sample_t *prev, const se23_imu_sample_t *s, int j,
                         int n, se23_imu_sample_t *u)
{
    *u = *s;
    if (j < n) {
        const se23_real_t a = (se23_real_t)j / (se23_real_t)n;
        se23_vec3_t dw, df;
        se23_v3_axpy(&s->w_ib_b, SE23_R(-1), &prev->w_ib_b, &dw);
        se23_v3_axpy(&s->f_b, SE23_R(-1), &prev->f_b, &df);
        se23_v3_axpy(&prev->w_ib_b, a, &dw, &u->w_ib_b);
        se23_v3_axpy(&prev->f_b, a, &df, &u->f_b);
    }
    u->dt = s->dt / (se23_real_t)n;
}

int se23_ins_predict_interval(se23_ins_t *ins, const se23_imu_sample_t *s)
{
    const int n = se23_ins_gap_steps(ins, &ins->last, s);
    se23_imu_sample_t u;
    int j;
    if (n == 1) {
        return se23_ins_predict(ins, s);
    }
    ins->work = ins->g;
    for (j = 1; j <= n; ++j) {
        se23_ins_gap_sample(&ins->last, s, j, n, &u);
        if (se23_ins_predict(ins, &u) == 0) {
            ins->g = ins->work;
            return 0;
        }
    }
    return 1;
}

/*
 * The noise of sample s: the white densities (ins->noise: configured or
 * measured at the alignment) plus the motion noise (ins.h,
 * "Motion noise") of the corrected readings w = w_meas + b_g, f = f_meas +
 * b_a. 16 multiply-adds, 2 square roots; every term is bounded by the
 * ranges and the configuration's limits, so the densities stay finite.
 */
static void sample_noise(const se23_ins_t *ins, const se23_imu_sample_t *s,
                         se23_imu_noise_t *noise)
{
    const se23_ins_motion_noise_t *m = &ins->cfg.motion;
    se23_vec3_t w, f;
    se23_real_t w2, f2;
    *noise = ins->noise;
    if (m->corr_time <= SE23_R(0)) {
        return;
    }
    se23_v3_axpy(&s->w_ib_b, SE23_R(1), &ins->g.b_g, &w);
    se23_v3_axpy(&s->f_b, SE23_R(1), &ins->g.b_a, &f);
    w2 = se23_v3_dot(&w, &w);
    f2 = se23_v3_dot(&f, &f);
    noise->gyro_noise = se23_sqrt((noise->gyro_noise * noise->gyro_noise) +
                                  ((((m->gyro_scale * m->gyro_scale) * w2) +
                                    ((m->gyro_g * m->gyro_g) * f2)) *
                                   m->corr_time));
    noise->accel_noise = se23_sqrt((noise->accel_noise * noise->accel_noise) +
                                   (((m->accel_scale * m->accel_scale) * f2) * m->corr_time));
}

int se23_ins_predict(se23_ins_t *ins, const se23_imu_sample_t *s)
{
    se23_imu_noise_t noise;
    sample_noise(ins, s, &noise);
    /* In place (gauss.h: outputs may alias inputs; nothing written on error). */
    if (se23_gauss_predict_work(&ins->model, &ins->g, s, &noise,
                                SE23_INPUT_JAC_EXACT, &ins->kernel.predict, &ins->g) != SE23_OK) {
        if (ins->replaying == 0) {
            se23_ins_count(&ins->c.filter_errors);
        }
        return 0;
    }
    return 1;
}
