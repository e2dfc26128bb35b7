/* The navigation filter's rest decision: the stationary detector on the
 * corrected readings, confirmed by the filter's own gravity; see ins.h,
 * "Zero-velocity updates". A file of its own so that the detector's work
 * (about 250 B of 3x3 matrices on the M4F) is off the stack before the
 * step that follows it (se23_ins_step: the prediction, ZUPT and ZARU). */
#include "ins_internal.h"

#include "../base/linalg.h"
#include "../base/se23_math.h"

/* chi^2_3 quantile at 0.999: the mean acceleration test of at_rest. */
#define ACCEL_TEST_Q SE23_R(16.27)

/* Entry (row, col) of g's covariance. */
static se23_real_t p_at(const se23_gauss_t *g, int row, int col)
{
    return g->P.m[se23_ins_idx(row, col)];
}

/*
 * NIS of "the body does not accelerate" over the detector's window: a =
 * R^T (fbar_n + g_n), the window's mean acceleration in the current body
 * frame, against its covariance at rest
 *   C = s^2 I + M P M^T,  M = [-f^, I] on (phi, db_a),
 * s = rest_accel_sigma, or sigma_a / sqrt(W) if that is 0 (white noise)
 * (a_true - a = -f^ phi + db_a to first order, f the corrected specific
 * force; with 9 states only the phi term):
 *   C = f^ P_pp f^T - G - G^T + P_aa + sigma_a^2 / W I,  G = f^ P_pa.
 * C is symmetric positive definite (sigma_a > 0); a^T C^-1 a by its
 * adjugate. Straight-line over the structure (f^ has a zero diagonal, C
 * is symmetric): T = f^ P_pp, the 8 entries C needs (16 multiply-adds),
 * T f^T on the lower triangle (12), G (18), a (9), the adjugate (12), its
 * determinant (3), the quadratic form (12): 82 multiply-adds, 64 without
 * the bias terms (about 150 with general 3x3 products).
 */
static se23_real_t accel_nis(const se23_ins_t *ins, const se23_vec3_t *fbar_n,
                             const se23_vec3_t *f_b)
{
    const se23_gauss_t *g = &ins->g;
    const se23_real_t sm = ins->cfg.rest_accel_sigma;
    const se23_real_t s2 = (sm > SE23_R(0)) ? (sm * sm)
                                            : ((ins->det.cfg.sigma_a * ins->det.cfg.sigma_a) /
                                               (se23_real_t)ins->det.cfg.window);
    const se23_real_t f0 = f_b->v[0], f1 = f_b->v[1], f2 = f_b->v[2];
    /* T = f^ B, B = P_pp; rows of f^: (0, -f2, f1), (f2, 0, -f0), (-f1, f0, 0) */
    const se23_real_t b00 = p_at(g, 0, 0), b01 = p_at(g, 0, 1), b02 = p_at(g, 0, 2);
    const se23_real_t b11 = p_at(g, 1, 1), b12 = p_at(g, 1, 2), b22 = p_at(g, 2, 2);
    const se23_real_t t01 = (f1 * b12) - (f2 * b11), t02 = (f1 * b22) - (f2 * b12);
    const se23_real_t t10 = (f2 * b00) - (f0 * b02), t11 = (f2 * b01) - (f0 * b12),
                      t12 = (f2 * b02) - (f0 * b22);
    const se23_real_t t20 = (f0 * b01) - (f1 * b00), t21 = (f0 * b11) - (f1 * b01),
                      t22 = (f0 * b12) - (f1 * b02);
    /* C = T f^T + s2 I, lower triangle: C_ij = T_i . (row j of f^) */
    se23_real_t c00 = ((f1 * t02) - (f2 * t01)) + s2;
    se23_real_t c10 = (f1 * t12) - (f2 * t11);
    se23_real_t c11 = ((f2 * t10) - (f0 * t12)) + s2;
    se23_real_t c20 = (f1 * t22) - (f2 * t21);
    se23_real_t c21 = (f2 * t20) - (f0 * t22);
    se23_real_t c22 = ((f0 * t21) - (f1 * t20)) + s2;
    if (g->n == SE23_GAUSS_N_BIAS) {
        /* G = f^ X, X = P_pa (rows phi, columns b_a); C -= G + G^T, += P_aa */
        const int a = SE23_IDX_BA;
        const se23_real_t x00 = p_at(g, 0, a), x01 = p_at(g, 0, a + 1), x02 = p_at(g, 0, a + 2);
        const se23_real_t x10 = p_at(g, 1, a), x11 = p_at(g, 1, a + 1), x12 = p_at(g, 1, a + 2);
        const se23_real_t x20 = p_at(g, 2, a), x21 = p_at(g, 2, a + 1), x22 = p_at(g, 2, a + 2);
        const se23_real_t g00 = (f1 * x20) - (f2 * x10), g01 = (f1 * x21) - (f2 * x11),
                          g02 = (f1 * x22) - (f2 * x12);
        const se23_real_t g10 = (f2 * x00) - (f0 * x20), g11 = (f2 * x01) - (f0 * x21),
                          g12 = (f2 * x02) - (f0 * x22);
        const se23_real_t g20 = (f0 * x10) - (f1 * x00), g21 = (f0 * x11) - (f1 * x01),
                          g22 = (f0 * x12) - (f1 * x02);
        c00 += p_at(g, a, a) - (g00 + g00);
        c10 += p_at(g, a + 1, a) - (g10 + g01);
        c11 += p_at(g, a + 1, a + 1) - (g11 + g11);
        c20 += p_at(g, a + 2, a) - (g20 + g02);
        c21 += p_at(g, a + 2, a + 1) - (g21 + g12);
        c22 += p_at(g, a + 2, a + 2) - (g22 + g22);
    }
    /* a = R^T (fbar_n + g_n) */
    const se23_real_t n0 = fbar_n->v[0] + ins->model.g_n.v[0];
    const se23_real_t n1 = fbar_n->v[1] + ins->model.g_n.v[1];
    const se23_real_t n2 = fbar_n->v[2] + ins->model.g_n.v[2];
    const se23_mat3_t *R = &g->T.R;
    const se23_real_t a0 = (R->m[0][0] * n0) + (R->m[1][0] * n1) + (R->m[2][0] * n2);
    const se23_real_t a1 = (R->m[0][1] * n0) + (R->m[1][1] * n1) + (R->m[2][1] * n2);
    const se23_real_t a2 = (R->m[0][2] * n0) + (R->m[1][2] * n1) + (R->m[2][2] * n2);
    /* adjugate of the symmetric C, its determinant, a^T adj(C) a / det C */
    const se23_real_t j00 = (c11 * c22) - (c21 * c21);
    const se23_real_t j10 = (c20 * c21) - (c10 * c22);
    const se23_real_t j11 = (c00 * c22) - (c20 * c20);
    const se23_real_t j20 = (c10 * c21) - (c20 * c11);
    const se23_real_t j21 = (c20 * c10) - (c00 * c21);
    const se23_real_t j22 = (c00 * c11) - (c10 * c10);
    const se23_real_t det = (c00 * j00) + (c10 * j10) + (c20 * j20);
    const se23_real_t y0 = (j00 * a0) + (j10 * a1) + (j20 * a2);
    const se23_real_t y1 = (j10 * a0) + (j11 * a1) + (j21 * a2);
    const se23_real_t y2 = (j20 * a0) + (j21 * a1) + (j22 * a2);
    return ((a0 * y0) + (a1 * y1) + (a2 * y2)) / det;
}

/* Nonzero if the filter's speed rules rest out (ins.h, "Zero-velocity
 * updates"): |v| > rest_speed_max, v the carried velocity (on rotating
 * Earth it differs from the user's by Omega x p, 7e-5 m/s per metre from
 * the origin: far below the bound over a drive). No margin for the
 * velocity's uncertainty: a ZUPT at speed is a catastrophe, a missed one
 * only a lost help, and an uncertain speed (a long outage) would widen
 * the margin past the speeds of a car (on a real drive, 3 sigma after a
 * minute without GNSS passed a car at 10 m/s for rest). 5 multiply-adds. */
static int moving_fast(const se23_ins_t *ins)
{
    const se23_real_t vm = ins->cfg.rest_speed_max;
    const se23_real_t *v = ins->g.T.v.v;
    if (vm <= SE23_R(0)) {
        return 0;
    }
    return (((v[0] * v[0]) + (v[1] * v[1])) + (v[2] * v[2]) > (vm * vm)) ? 1 : 0;
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
    const se23_mat3_t *R = &ins->g.T.R;
    const se23_vec3_t *om = &ins->model.w_ie_n;
    se23_vec3_t w, f, f_n;
    int stationary = 0;
    for (int i = 0; i < 3; ++i) {
        /* w = w_meas + b_g - R^T Omega, f = f_meas + b_a */
        w.v[i] = (s->w_ib_b.v[i] + ins->g.b_g.v[i]) -
                 (((R->m[0][i] * om->v[0]) + (R->m[1][i] * om->v[1])) + (R->m[2][i] * om->v[2]));
        f.v[i] = s->f_b.v[i] + ins->g.b_a.v[i];
    }
    for (int i = 0; i < 3; ++i) {
        f_n.v[i] = ((R->m[i][0] * f.v[0]) + (R->m[i][1] * f.v[1])) + (R->m[i][2] * f.v[2]);
    }
    if ((se23_stationary_add(&ins->det, &w, &f_n, &stationary) != SE23_OK) || (stationary == 0)) {
        return 0; /* moving, or (absurd readings) a detector overflow */
    }
    if (moving_fast(ins) != 0) {
        return 0;
    }
    if (ins->cfg.gravity_test_off != 0) {
        return 1;
    }
    /* the window is full: det.fbar is its mean of f_n */
    return (accel_nis(ins, &ins->det.fbar, &f) < ACCEL_TEST_Q) ? 1 : 0;
}

/* SE23_INS_REST_NHC if the sample ending dt_ns after the state starts a new
 * nhc_interval (ins.h, "Vehicles"), else SE23_INS_REST_NONE. */
static int nhc_due(const se23_ins_t *ins, int64_t dt_ns)
{
    if (!(ins->cfg.nhc_sigma > SE23_R(0))) {
        return SE23_INS_REST_NONE;
    }
    return ((ins->t_ns / ins->nhc_interval_ns) != ((ins->t_ns + dt_ns) / ins->nhc_interval_ns))
               ? SE23_INS_REST_NHC
               : SE23_INS_REST_NONE;
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
        return nhc_due(ins, dt_ns);
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
