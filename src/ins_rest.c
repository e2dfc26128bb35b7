/* The navigation filter's rest decision: the stationary detector on the
 * corrected readings, confirmed by the filter's own gravity; see ins.h,
 * "Zero-velocity updates". A file of its own so that the detector's work
 * (about 250 B of 3x3 matrices on the M4F) is off the stack before the
 * step that follows it (se23_ins_step: the prediction, ZUPT and ZARU). */
#include "ins_internal.h"

#include "linalg.h"
#include "se23_math.h"

/* chi^2_3 quantile at 0.999: the mean acceleration test of at_rest. */
#define ACCEL_TEST_Q SE23_R(16.27)

/* A = P's 3x3 block at (row, col). */
static void p_block(const se23_gauss_t *g, int row, int col, se23_mat3_t *A)
{
    int i, j;
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            A->m[i][j] = g->P.m[se23_ins_idx(row + i, col + j)];
        }
    }
}

/*
 * NIS of "the body does not accelerate" over the detector's window: a =
 * R^T (fbar_n + g_n), the window's mean acceleration in the current body
 * frame, against its covariance at rest
 *   C = sigma_a^2 / W I + M P M^T,  M = [-f^, I] on (phi, db_a)
 * (a_true - a = -f^ phi + db_a to first order, f the corrected specific
 * force; with 9 states only the phi term). C is symmetric positive
 * definite (sigma_a > 0); a^T C^-1 a by its adjugate. About 150
 * multiply-adds.
 */
static se23_real_t accel_nis(const se23_ins_t *ins, const se23_vec3_t *fbar_n,
                             const se23_vec3_t *f_b)
{
    const se23_gauss_t *g = &ins->g;
    const se23_real_t s2 = (ins->det.cfg.sigma_a * ins->det.cfg.sigma_a) /
                           (se23_real_t)ins->det.cfg.window;
    se23_mat3_t F, B, T, C, adj;
    se23_vec3_t a_n, a, y;
    int i;
    se23_v3_axpy(fbar_n, SE23_R(1), &ins->model.g_n, &a_n);
    se23_m3_tmul_v3(&g->T.R, &a_n, &a);
    se23_m3_skew(f_b, &F);
    p_block(g, SE23_IDX_PHI, SE23_IDX_PHI, &B);
    se23_m3_mul(&F, &B, &T);
    se23_m3_mul_nt(&T, &F, &C); /* f^ P_phiphi f^T */
    if (g->n == SE23_GAUSS_N_BIAS) {
        p_block(g, SE23_IDX_PHI, SE23_IDX_BA, &B);
        se23_m3_mul(&F, &B, &T); /* f^ P_phi,ba */
        se23_m3_axpy(&C, SE23_R(-1), &T, &C);
        se23_m3_transpose(&T, &B);
        se23_m3_axpy(&C, SE23_R(-1), &B, &C);
        p_block(g, SE23_IDX_BA, SE23_IDX_BA, &B);
        se23_m3_axpy(&C, SE23_R(1), &B, &C);
    }
    for (i = 0; i < 3; ++i) {
        C.m[i][i] += s2;
    }
    /* adjugate of the symmetric C */
    adj.m[0][0] = (C.m[1][1] * C.m[2][2]) - (C.m[1][2] * C.m[2][1]);
    adj.m[0][1] = (C.m[0][2] * C.m[2][1]) - (C.m[0][1] * C.m[2][2]);
    adj.m[0][2] = (C.m[0][1] * C.m[1][2]) - (C.m[0][2] * C.m[1][1]);
    adj.m[1][1] = (C.m[0][0] * C.m[2][2]) - (C.m[0][2] * C.m[2][0]);
    adj.m[1][2] = (C.m[0][2] * C.m[1][0]) - (C.m[0][0] * C.m[1][2]);
    adj.m[2][2] = (C.m[0][0] * C.m[1][1]) - (C.m[0][1] * C.m[1][0]);
    adj.m[1][0] = adj.m[0][1];
    adj.m[2][0] = adj.m[0][2];
    adj.m[2][1] = adj.m[1][2];
    se23_m3_mul_v3(&adj, &a, &y);
    return se23_v3_dot(&a, &y) / se23_m3_det(&C);
}

/*
 * The detector's verdict on the window ending with sample s (ins.h,
 * "Zero-velocity updates"). It sees the readings as the filter corrects
 * them, biases added, the specific force in the nav frame (R f) and the
 * Earth rate a body at rest senses taken out of the gyro: at rest only the
 * sensor noise remains. SHOE estimates the gravity direction from the
 * window, so a smooth start (acceleration growing from zero, which only
 * turns the mean specific force) passes it; the filter knows where gravity
 * is, so the window's mean acceleration must also be noise: accel_nis below
 * the chi^2_3 quantile ACCEL_TEST_Q (unless gravity_test_off).
 */
static int stationary_window(se23_ins_t *ins, const se23_imu_sample_t *s)
{
    se23_vec3_t w_ie_b, w, f, f_n, w_mean, fbar_n;
    int stationary = 0;
    se23_m3_tmul_v3(&ins->g.T.R, &ins->model.w_ie_n, &w_ie_b);
    se23_v3_axpy(&s->w_ib_b, SE23_R(1), &ins->g.b_g, &w);
    se23_v3_axpy(&w, SE23_R(-1), &w_ie_b, &w);
    se23_v3_axpy(&s->f_b, SE23_R(1), &ins->g.b_a, &f);
    se23_m3_mul_v3(&ins->g.T.R, &f, &f_n);
    if ((se23_stationary_add(&ins->det, &w, &f_n, &stationary) != SE23_OK) || (stationary == 0) ||
        (se23_stationary_mean(&ins->det, &w_mean, &fbar_n) != SE23_OK)) {
        return 0; /* moving, or (absurd readings) a detector overflow */
    }
    if (ins->cfg.gravity_test_off != 0) {
        return 1;
    }
    return (accel_nis(ins, &fbar_n, &f) < ACCEL_TEST_Q) ? 1 : 0;
}

int se23_ins_rest_level(se23_ins_t *ins, const se23_imu_sample_t *s, int64_t dt_ns)
{
    int rest;
    /* both sums stay below their cap + max_gap_ns: no overflow */
    if ((ins->cfg.zupt == 0) || (stationary_window(ins, s) == 0)) {
        ins->rest_ns = 0;
        if (ins->move_ns < ins->floor_swing_ns) {
            ins->move_ns += dt_ns;
        }
        return SE23_INS_REST_NONE;
    }
    if (ins->rest_ns < ins->zaru_after_ns) {
        ins->rest_ns += dt_ns;
    }
    rest = (ins->rest_ns >= ins->zaru_after_ns) ? SE23_INS_REST_ZARU : SE23_INS_REST_ZUPT;
    if ((ins->cfg.floor_sigma > SE23_R(0)) && (ins->move_ns >= ins->floor_swing_ns)) {
        rest |= SE23_INS_REST_FLOOR; /* a stance begins */
    }
    ins->move_ns = 0;
    return rest;
}
