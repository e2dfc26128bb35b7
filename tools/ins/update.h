/**
 * @file update.h
 * @brief GNSS measurement update of the INS engine, on the user's state,
 *        with the library's models and Kalman update (se23/kalman.h):
 *        position (se23_meas_pos_nav, no lever arm) and velocity
 *        (se23_meas_vel_nav) stacked into one 6-row measurement, so that
 *        one chi-square gate covers the whole fix.
 */
#ifndef INS_UPDATE_H
#define INS_UPDATE_H

#include "ins.h"

/**
 * Applies fix to g (user's distribution, n = 9 or 15). gate <= 0: no gate.
 * Returns 0 (applied; *nis set), 1 (gated out; *nis set, g untouched) or
 * -1 (invalid fix or a library error; g untouched).
 */
int ins_update_gnss(se23_gauss_t *g, const ins_gnss_t *fix, double gate, double *nis);

#endif /* INS_UPDATE_H */
