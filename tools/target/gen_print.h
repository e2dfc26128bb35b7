/*
 * The reference tables of the replay generators (gen_ins_replay.c,
 * gen_walk_replay.c, gen_drive_replay.c) printed as C initialisers of the
 * types of tests/target/ins_replay.h, every real with 17 significant
 * digits: exact for the build's se23_real_t (a float, promoted, prints
 * exactly too); gen_real with the fewest digits that read back exactly.
 * Host only (C99, any SE23_CFG_DOUBLE).
 */
#ifndef SE23_GEN_PRINT_H
#define SE23_GEN_PRINT_H

#include "ins_replay.h"

/** " .name = {x0, x1, ...}," */
void gen_reals(const char *name, const se23_real_t *x, int n);
/** " .name = {.v = {x, y, z}}," */
void gen_vec(const char *name, const se23_vec3_t *x);
/** "  .cfg = {...},\n" (designated fields of se23_ins_config_t) */
void gen_print_config(const se23_ins_config_t *c);
/** "{...},\n" (an se23_ins_align_t) */
void gen_print_align(const se23_ins_align_t *a);
/** "  .start = {...},\n" */
void gen_print_start(const insr_start_t *s);
/** " {...},\n" (one insr_check_t) */
void gen_print_check(const insr_check_t *o);
/** x with the fewest digits that read back (as a double, then rounded to
 *  se23_real_t, as the compiler reads the table) to x exactly. */
void gen_real(se23_real_t x);
/** "{x0, x1, x2}" by gen_real */
void gen_real3(const se23_real_t *x);
/** "static const insr_imu_t imu[n] = {...};\n" */
void gen_print_imu(const insr_imu_t *imu, int n);
/** at of check[j] (j < n - 1): the first of the n_imu samples at or after
 *  times_s[j]; check[n - 1].at the last sample. -1 if they are not in
 *  increasing order. */
int gen_checkpoints(const insr_imu_t *imu, int n_imu, const double *times_s, insr_check_t *check,
                    int n);

#endif /* SE23_GEN_PRINT_H */
