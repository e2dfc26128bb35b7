/**
 * @file types.h
 * @brief Scalar, vector, matrix and group-element types of se23, and the
 *        status codes every fallible function returns.
 *
 * Conventions (also stated in se23.h and tools/doc/pages/conventions.md):
 *  - Matrices are row-major. 3x3 as m[row][col]; 9x9 as a flat m[81] with
 *    element (i, j) at m[9*i + j].
 *  - Tangent vectors of SE_2(3) are xi = (phi, nu, rho) in R^9:
 *    rotation, velocity, position, the paper's order. Index constants below.
 *  - Arrays are wrapped in structs so that they can be passed as const.
 */
#ifndef SE23_TYPES_H
#define SE23_TYPES_H

#include "se23/config.h"

#ifdef __cplusplus
extern "C" {
#endif

#if SE23_CFG_DOUBLE
typedef double se23_real_t; /**< the scalar: double (SE23_CFG_DOUBLE 1) or float (0) */
#else
typedef float se23_real_t; /**< the scalar: double (SE23_CFG_DOUBLE 1) or float (0) */
#endif

/** Literal of the configured precision: SE23_R(0.5) is 0.5f in the float build. */
#define SE23_R(x) ((se23_real_t)(x))

/** Column 3-vector. */
typedef struct {
    se23_real_t v[3]; /**< x, y, z */
} se23_vec3_t;

/** 3x3 matrix, row-major. */
typedef struct {
    se23_real_t m[3][3]; /**< m[row][column] */
} se23_mat3_t;

/** 5x5 matrix, row-major (the embedding of SE_2(3) and its Lie algebra). */
typedef struct {
    se23_real_t m[5][5]; /**< m[row][column] */
} se23_mat5_t;

/** 9x9 matrix, flat row-major: element (i, j) is m[9*i + j]. */
typedef struct {
    se23_real_t m[81]; /**< element (i, j) at m[9*i + j] */
} se23_mat9_t;

/** Element of R^9 = se_2(3) in the basis (phi, nu, rho). */
typedef struct {
    se23_real_t v[9]; /**< phi (0-2), nu (3-5), rho (6-8) */
} se23_tangent_t;

/** First index of each block of a tangent vector. */
enum {
    SE23_IDX_PHI = 0, /**< rotation block phi [rad] */
    SE23_IDX_NU = 3,  /**< velocity block nu [m/s] */
    SE23_IDX_RHO = 6  /**< position block rho [m] */
};

/**
 * Extended pose T = (R, v, p) in SE_2(3):
 *     | R  v  p |
 * T = | 0  1  0 |
 *     | 0  0  1 |
 * R maps body to navigation frame; v [m/s] and p [m] are in the navigation
 * frame.
 */
typedef struct {
    se23_mat3_t R; /**< attitude, body -> nav */
    se23_vec3_t v; /**< velocity in nav frame [m/s] */
    se23_vec3_t p; /**< position in nav frame [m] */
} se23_pose_t;

/**
 * Result of every fallible function. On any value but SE23_OK the function
 * has written nothing to its outputs; SE23_OK means every output is finite
 * and valid (R in SO(3) within SE23_CFG_ROT_TOL, covariances symmetric and
 * positive semidefinite).
 *
 * Validation policy: check what enters, trust what the library built.
 *  - Checked on every call, O(n): what the caller hands in for that call:
 *    IMU samples and dt, noise densities, measurements and their noise
 *    covariance, poses and vectors passed to the Lie-group routines.
 *  - Checked once, where it enters: a state or factor the caller builds
 *    (se23_gauss_t, a covariance it sets). Call se23_gauss_check on it
 *    before the first step; se23_preint_unc_reset starts factors valid.
 *  - Trusted, not re-proved per sample: a state the library produced. It
 *    stays valid by construction: covariances are symmetric by construction
 *    (upper triangle computed, mirrored), positive semidefinite by the
 *    update forms used, R re-orthonormalised after every product and
 *    retraction. A result that would overflow is refused
 *    (SE23_ERR_NONFINITE) before anything is stored.
 *  - SE23_CFG_DEEP_CHECKS=1 (config.h) re-runs the deep checks
 *    (se23_gauss_check, se23_preint_unc_check) inside every call that takes
 *    a state, for debugging.
 */
typedef enum {
    SE23_OK = 0,              /**< success */
    SE23_ERR_NULL = 1,        /**< a required pointer is NULL (SE23_CFG_ARG_CHECKS) */
    SE23_ERR_NONFINITE = 2,   /**< an input holds NaN or Inf, or a result would overflow */
    SE23_ERR_NOT_ROTATION = 3, /**< a matrix is not in SO(3) within SE23_CFG_ROT_TOL */
    SE23_ERR_DOMAIN = 4,      /**< input outside the function's domain (e.g. |phi| >= 2 pi for jl_inv) */
    SE23_ERR_DT = 5,          /**< time step <= 0 or above the configured maximum */
    SE23_ERR_NOT_SYMMETRIC = 6, /**< a covariance is not symmetric */
    SE23_ERR_NOT_PSD = 7,     /**< a covariance is not positive (semi)definite */
    SE23_ERR_DIM = 8          /**< a dimension argument is out of range */
} se23_status_t;

/**
 * Short constant name of a status, e.g. "SE23_ERR_DT".
 * @param status the status
 * @return never NULL ("SE23_ERR_UNKNOWN" for a value that is not a status).
 */
const char *se23_status_str(se23_status_t status);

#ifdef __cplusplus
}
#endif

#endif /* SE23_TYPES_H */
