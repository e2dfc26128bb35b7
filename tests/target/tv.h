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

/** Literals of the generated tables. */
#define TV_R(x) ((se23_real_t)(x))

/** The vectors of one routine, generated (build/target/<variant>/tv_data.c). */
typedef struct {
    int n_vec;                 /**< number of vectors */
    int n_in;                  /**< reals per input vector */
    int n_out;                 /**< reals per output vector */
    const se23_real_t *in;     /**< n_vec x n_in, or NULL if n_in = 0 */
    const se23_real_t *out;    /**< n_vec x n_out expected (zeros where status != OK) */
    const signed char *status; /**< n_vec expected se23_status_t values */
} tv_data_t;

/**
 * Calls the routine on one input row and writes its outputs (n_out reals).
 * The output struct is filled with TV_SENTINEL before the call, so that a
 * routine that fails must leave every output real equal to TV_SENTINEL.
 * @return the routine's status (SE23_OK for void routines).
 */
typedef int (*tv_call_t)(const se23_real_t *in, se23_real_t *out);

/** One routine under test: a row of tv_list.h. */
typedef struct {
    const char *name;      /**< the public function's name */
    tv_call_t call;
    int n_in;              /**< reals per input row */
    int n_out;             /**< reals per output row */
    int tol;               /**< tolerance, in epsilons of the build (see tv_runner.c) */
    const tv_data_t *data; /**< the generated vectors */
} tv_routine_t;

/** Value written into outputs before each call. */
#define TV_SENTINEL TV_R(-1234.5)

/** Routines whose signature is not one of the generic kinds of tv_list.h
 *  have a hand-written adapter tv_call_<name> in tv_custom.c. */
#define TV_CUSTOM_DECL(fn) int tv_call_##fn(const se23_real_t *in, se23_real_t *out);

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
