/**
 * @file config.h
 * @brief Build-time configuration of se23.
 *
 * Every option has a default here. A firmware build overrides them either
 * with -D flags or by defining SE23_CFG_OPTS_FILE to the name of a header
 * that sets them (e.g. -DSE23_CFG_OPTS_FILE='"se23_opts.h"'), which is
 * included before the defaults below.
 *
 * Options:
 *   SE23_CFG_DOUBLE      0: se23_real_t is float (Cortex-M4F),
 *                        1: se23_real_t is double (Cortex-M7, host). Default 1.
 *   SE23_CFG_ARG_CHECKS  1: public functions return SE23_ERR_NULL for NULL
 *                        pointer arguments. 0: no check (smaller, faster).
 *                        Default 1.
 *   SE23_CFG_ROT_TOL     Max |R^T R - I| entry (and |det R - 1|) accepted as a
 *                        rotation. Default 1e-5 (float) / 1e-9 (double).
 *   SE23_CFG_DT_MAX      Largest IMU sample interval [s] the propagation
 *                        accepts. Default 1.0 s.
 *   SE23_CFG_COV_TOL     Relative tolerance of the covariance checks
 *                        (symmetry and positive semidefiniteness, gauss.h).
 *                        Default 1e-5 (float) / 1e-9 (double).
 *   SE23_CFG_DEEP_CHECKS 1: every call also re-proves the state it is handed
 *                        (se23_gauss_check, se23_preint_unc_check: O(n^3)
 *                        Cholesky of the covariance), for debugging.
 *                        0: state the library produced is trusted (types.h,
 *                        "Validation policy"). Default 0.
 */
#ifndef SE23_CONFIG_H
#define SE23_CONFIG_H

#ifdef SE23_CFG_OPTS_FILE
#include SE23_CFG_OPTS_FILE
#endif

#ifndef SE23_CFG_DOUBLE
#define SE23_CFG_DOUBLE 1
#endif

#if (SE23_CFG_DOUBLE != 0) && (SE23_CFG_DOUBLE != 1)
#error "SE23_CFG_DOUBLE must be 0 (float) or 1 (double)"
#endif

#ifndef SE23_CFG_ARG_CHECKS
/** 1: NULL pointer arguments give SE23_ERR_NULL; 0: not checked (see above). */
#define SE23_CFG_ARG_CHECKS 1
#endif

#ifndef SE23_CFG_ROT_TOL
#if SE23_CFG_DOUBLE
/** Largest |R^T R - I| entry and |det R - 1| accepted as a rotation. */
#define SE23_CFG_ROT_TOL 1e-9
#else
#define SE23_CFG_ROT_TOL 1e-5f
#endif
#endif

#ifndef SE23_CFG_DT_MAX
/** Largest IMU sample interval [s] the propagation accepts. */
#define SE23_CFG_DT_MAX 1.0
#endif

#ifndef SE23_CFG_COV_TOL
#if SE23_CFG_DOUBLE
/** Relative tolerance of the covariance checks (symmetry, PSD; gauss.h). */
#define SE23_CFG_COV_TOL 1e-9
#else
#define SE23_CFG_COV_TOL 1e-5f
#endif
#endif

#ifndef SE23_CFG_DEEP_CHECKS
/** 1: every call re-proves the state it is handed (O(n^3)); 0: trusted. */
#define SE23_CFG_DEEP_CHECKS 0
#endif

#if (SE23_CFG_DEEP_CHECKS != 0) && (SE23_CFG_DEEP_CHECKS != 1)
#error "SE23_CFG_DEEP_CHECKS must be 0 or 1"
#endif

#endif /* SE23_CONFIG_H */
