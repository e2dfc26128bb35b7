/**
 * @file linalg.h
 * @brief Internal: the small fixed-size linear algebra every module uses
 *        (3-vectors, 3x3 matrices, the a0 I + a1 W + a2 W^2 series form).
 *        Not part of the public API. Outputs may alias inputs.
 */
#ifndef SE23_LINALG_H
#define SE23_LINALG_H

#include "se23/types.h"

/** Nonzero if all n values are finite. */
int se23_all_finite(const se23_real_t *x, int n);

/** Nonzero if every entry of T is finite: the last test of a fallible
 *  function whose finite inputs may still overflow (types.h). */
int se23_pose_finite(const se23_pose_t *T);

/** out = Phi_t(A) B: the product A B with t A.v added to its position
 *  (Phi_t of paper eq. discrete2 applied to A first; t = 0 is se23_compose). out
 *  may NOT alias A or B (the exception to this header's rule); se23.c. */
void se23_pose_mul_phi(const se23_pose_t *A, const se23_pose_t *B, se23_real_t t,
                       se23_pose_t *out);

/** a = (x[0], x[1], x[2]): a 3-block of a flat array as a vector.
 *  Inline: it sits in the per-column loops of the covariance products. */
static inline void se23_v3_load(const se23_real_t *x, se23_vec3_t *a)
{
    a->v[0] = x[0];
    a->v[1] = x[1];
    a->v[2] = x[2];
}

/** (x[0], x[1], x[2]) = a. */
static inline void se23_v3_store(const se23_vec3_t *a, se23_real_t *x)
{
    x[0] = a->v[0];
    x[1] = a->v[1];
    x[2] = a->v[2];
}

se23_real_t se23_v3_dot(const se23_vec3_t *a, const se23_vec3_t *b);
/** out = a x b */
void se23_v3_cross(const se23_vec3_t *a, const se23_vec3_t *b, se23_vec3_t *out);
/** out = a + s b */
void se23_v3_axpy(const se23_vec3_t *a, se23_real_t s, const se23_vec3_t *b,
                  se23_vec3_t *out);
/** out = s a */
void se23_v3_scale(const se23_vec3_t *a, se23_real_t s, se23_vec3_t *out);

void se23_m3_identity(se23_mat3_t *out);
/** out = A B */
void se23_m3_mul(const se23_mat3_t *A, const se23_mat3_t *B, se23_mat3_t *out);
/** out = A^T B */
void se23_m3_mul_tn(const se23_mat3_t *A, const se23_mat3_t *B, se23_mat3_t *out);
/** out = A B^T */
void se23_m3_mul_nt(const se23_mat3_t *A, const se23_mat3_t *B, se23_mat3_t *out);
void se23_m3_transpose(const se23_mat3_t *A, se23_mat3_t *out);/** out = A x */
void se23_m3_mul_v3(const se23_mat3_t *A, const se23_vec3_t *x, se23_vec3_t *out);
/** out = A^T x */
void se23_m3_tmul_v3(const se23_mat3_t *A, const se23_vec3_t *x, se23_vec3_t *out);
/** out = s A */
void se23_m3_scale(const se23_mat3_t *A, se23_real_t s, se23_mat3_t *out);
/** out = A + s B */
void se23_m3_axpy(const se23_mat3_t *A, se23_real_t s, const se23_mat3_t *B,
                  se23_mat3_t *out);
/** out = v^ (skew matrix, v^ x = v cross x) */
void se23_m3_skew(const se23_vec3_t *v, se23_mat3_t *out);
se23_real_t se23_m3_det(const se23_mat3_t *A);

/*
 * Accumulating 3x3 kernels of the covariance steps (cov_step.c):
 * written out, no loops; C is updated in place and may alias the other
 * operands (they are read before the first store). Multiply-add counts in brackets.
 */
/** C += s v^ A [18 + 3] */
void se23_m3_acc_skew_mul(se23_mat3_t *C, se23_real_t s, const se23_vec3_t *v,
                          const se23_mat3_t *A);
/** C += A v^ [18] */
void se23_m3_acc_mul_skew(se23_mat3_t *C, const se23_mat3_t *A, const se23_vec3_t *v);

/**
 * Measures the drift d = max |(X^T X - I)_ij| and, if done < d <= max_drift,
 * takes one Newton-Schulz step X <- X (3I - X^T X)/2 toward the orthogonal
 * polar factor (quadratic: a drift of k eps becomes ~k^2 eps^2). Returns d
 * (before the step). [27 + 36 when it steps]
 */
se23_real_t se23_m3_orthonormalize_step(se23_mat3_t *X, se23_real_t done,
                                        se23_real_t max_drift);

/**
 * out = a0 I + a1 W + a2 W^2 with W = phi^, using W^2 = phi phi^T - |phi|^2 I.
 * Every SO(3) series (exp, J, H, K, J^-1) is of this form.
 */
void se23_m3_series(se23_real_t a0, se23_real_t a1, se23_real_t a2,
                    const se23_vec3_t *phi, se23_mat3_t *out);

#endif /* SE23_LINALG_H */
