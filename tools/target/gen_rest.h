/*
 * The filter's second rest test (src/ins.c, accel_nis) recomputed in double
 * from its public state, for the replay generators (gen_ins_replay.c,
 * gen_walk_replay.c): they check that it reproduces every rest flag the
 * filter set and measure how far each decision lies from its threshold.
 * Host only (C99, any SE23_CFG_DOUBLE).
 */
#ifndef SE23_GEN_REST_H
#define SE23_GEN_REST_H

#include "se23/ins.h"

/* The quantile of the filter's mean-acceleration test at rest (src/ins.c,
 * ACCEL_TEST_Q: chi^2_3 at 0.999). */
#define GEN_ACCEL_TEST_Q 16.27

/*
 * a = R^T (fbar_n + g_n), fbar_n the mean of the detector's window (the
 * corrected readings in the nav frame), against
 * C = sigma_a^2 / W I + M P M^T, M = [-f^, I] on (phi, db_a), f the
 * corrected sample f_raw + b_a; R, P, b_a those before the sample's step
 * (x), the window that after it (ins->det). Returns a^T C^-1 a.
 */
double gen_accel_nis(const se23_ins_t *ins, const se23_gauss_t *x, const se23_real_t f_raw[3]);

#endif /* SE23_GEN_REST_H */
