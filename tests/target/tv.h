/**
 * @file tv.h
 * @brief Target test vectors: every public routine run on the target against
 *        inputs and expected outputs computed on the host by the Eigen
 *        reference (tests/reference) and compiled into the image as const
 *        tables by tools/target/gen_vectors.
 *
 * The list of routines is tv_list.h (an X-macro list read by the target
 * runner and by the host generator). A routine is a function of flat real
 * arrays: its inputs and outputs are se23 structs made of se23_real_t only
 * (vec3, mat3, mat5, mat9, tangent, pose, ...), copied to and from the
 * tables as consecutive reals in declaration order (row-major matrices;
 * pose = R, v, p).
 */
#ifndef SE23_TV_H
#define SE23_TV_H

#include <stddef.h>

#include "se23/types.h"

/** Reals in a struct of reals. */
#define TV_REALS(T) ((int)(sizeof(T) / sizeof(se23_real_t)))

/** Reals of a se23_preint_t in a row: delta (pose), dt, n. */
#define TV_PREINT_REALS (TV_REALS(se23_pose_t) + 2)

/** Reals of a se23_gauss_t in a row: T, b_g, b_a, n, P (15 x 15). */
#define TV_GAUSS_REALS (TV_REALS(se23_pose_t) + 3 + 3 + 1 + 15 * 15)

/** Reals of a se23_meas_t in a row: m, z, H (9 x 15), R (9 x 9). */
#define TV_MEAS_REALS                                                          \
    (1 + SE23_MEAS_MMAX + SE23_MEAS_MMAX * SE23_GAUSS_NMAX + SE23_MEAS_MMAX * SE23_MEAS_MMAX)

/** Reals of a se23_preint_unc_t in a row: f (TV_PREINT_REALS), b_g, b_a,
 *  kind, P_left (9 x 9), J_left (9 x 6), the five classical 3 x 3 Jacobians. */
#define TV_PREINT_UNC_REALS (TV_PREINT_REALS + 3 + 3 + 1 + 1 + 81 + 54 + 5 * 9)

/** Literals of the generated tables. */
#define TV_R(x) ((se23_real_t)(x))

/** The vectors of one routine, generated (build/target/<variant>/tv_data.c). */
typedef struct {
    int n_vec;                 /**< number of vectors */
    int n_in;                  /**< reals per input vector */
    int n_out;                 /**< reals per output vector */
    const se23_real_t *in;     /**< n_vec x n_in, or NULL if n_in = 0 */
    const se23_real_t *out;    /**< n_vec x n_out expected (zeros where status != OK) */
    const float *scale;        /**< n_vec x n_out error scales (tv_runner.c) */
    const signed char *status; /**< n_vec expected se23_status_t values */
} tv_data_t;

/**
 * One routine under test: a row of tv_list.h, as three steps over inputs and
 * outputs held in static storage (so that the benchmark image can time the
 * call alone):
 *   load(in)    copies an input row into the input structs and fills the
 *               output structs with TV_SENTINEL;
 *   call()      runs the routine; returns its status (SE23_OK if void);
 *   store(out)  copies the output structs to n_out reals.
 * A routine that fails must leave every output real equal to TV_SENTINEL.
 */
typedef struct {
    const char *name;      /**< the public function's name */
    void (*load)(const se23_real_t *in);
    int (*call)(void);
    void (*store)(se23_real_t *out);
    int n_in;              /**< reals per input row */
    int n_out;             /**< reals per output row */
    int tol;               /**< tolerance, in epsilons of the build (see tv_runner.c) */
    const tv_data_t *data; /**< the generated vectors */
} tv_routine_t;

/** Every row of tv_list.h, in order (tv_adapters.c). */
extern const tv_routine_t tv_routines[];
extern const int tv_n_routines;

/** Value written into outputs before each call. */
#define TV_SENTINEL TV_R(-1234.5)

/** Fills n bytes of reals with TV_SENTINEL. */
void tv_fill_sentinel(void *p, size_t bytes);

/** Routines whose signature is not one of the generic kinds of tv_list.h
 *  have hand-written tv_load_<fn>, tv_call_<fn>, tv_store_<fn> in tv_custom.c. */
#define TV_CUSTOM_DECL(fn)                                                     \
    void tv_load_##fn(const se23_real_t *in);                                  \
    int tv_call_##fn(void);                                                    \
    void tv_store_##fn(se23_real_t *out);

/* The generated data, one per routine of the list. */
#define TV_DATA_DECL(fn) extern const tv_data_t tv_data_##fn;
#define TV_V0(fn, O, tol) TV_DATA_DECL(fn)
#define TV_V1(fn, A, O, tol) TV_DATA_DECL(fn)
#define TV_S1(fn, A, O, tol) TV_DATA_DECL(fn)
#define TV_V2(fn, A, B, O, tol) TV_DATA_DECL(fn)
#define TV_S2(fn, A, B, O, tol) TV_DATA_DECL(fn)
#define TV_C1(fn, A, tol) TV_DATA_DECL(fn)
#define TV_CUSTOM(fn, n_in, n_out, tol) TV_DATA_DECL(fn) TV_CUSTOM_DECL(fn)
#include "tv_list.h"
#undef TV_V0
#undef TV_V1
#undef TV_S1
#undef TV_V2
#undef TV_S2
#undef TV_C1
#undef TV_CUSTOM

#endif /* SE23_TV_H */
