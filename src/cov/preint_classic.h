/**
 * @file preint_classic.h
 * @brief Internal: the classical first-order bias Jacobians of Forster et
 *        al. (2017) and their correction, for se23_preint_unc_t (see
 *        se23/preint_unc.h for the formulas and the sign convention).
 *        Not part of the public API.
 */
#ifndef SE23_PREINT_CLASSIC_H
#define SE23_PREINT_CLASSIC_H

#include "se23/preint_unc.h"
#include "se23/types.h"

/**
 * c = the classical Jacobians after one more sample of corrected inputs
 * w [rad/s], f [m/s^2] over dt [s], with dR = Delta R before the sample and
 * dR_k = exp(w dt ^) its rotation increment. No checks; c may be updated in
 * place.
 */
void se23_preint_classic_step(se23_preint_classic_t *c, const se23_mat3_t *dR,
                              const se23_mat3_t *dR_k, const se23_vec3_t *w,
                              const se23_vec3_t *f, se23_real_t dt);

/**
 * out = delta corrected by the bias change (dbg, dba) with the classical
 * Jacobians c: (R exp(dR/dbg dbg), v + dV/dbg dbg + dV/dba dba,
 * p + dX/dbg dbg + dX/dba dba). No checks; out may alias delta.
 */
void se23_preint_classic_apply(const se23_preint_classic_t *c,
                               const se23_pose_t *delta,
                               const se23_vec3_t *dbg, const se23_vec3_t *dba,
                               se23_pose_t *out);

#endif /* SE23_PREINT_CLASSIC_H */
