/**
 * @file update.h
 * @brief GNSS measurement update of the INS engine (user's state).
 *
 * Measurements, to first order in the right-multiplied error
 * T = That exp(xi) (paper eq. error:rep1):
 *   p_meas = p + n_p   ->  p_meas - phat = Rhat rho + n_p,
 *   v_meas = v + n_v   ->  v_meas - vhat = Rhat nu + n_v,
 * i.e. H = [0 0 Rhat 0 0] (position) and [0 Rhat 0 0 0] (velocity) on
 * (phi, nu, rho, db_g, db_a). Kalman update in exponential coordinates:
 * S = H P H^T + R by Cholesky (no inverse), Joseph form for P, then
 * That <- That exp(dxi), bhat <- bhat + db.
 */
#ifndef INS_UPDATE_H
#define INS_UPDATE_H

#include "ins.h"

/**
 * Applies fix to g (user's distribution, n = 9 or 15). gate <= 0: no gate.
 * Returns 0 (applied; *nis set), 1 (gated out; *nis set, g untouched) or
 * -1 (numerical failure or invalid fix; g untouched).
 */
int ins_update_gnss(se23_gauss_t *g, const ins_gnss_t *fix, double gate, double *nis);

#endif /* INS_UPDATE_H */
