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
/** out = A^T B (27 multiply-adds). Inline, written out: it is the rotation
 *  step of every covariance kernel. out may alias A or B. */
static inline void se23_m3_mul_tn(const se23_mat3_t *A, const se23_mat3_t *B,
                                  se23_mat3_t *out)
{
    se23_mat3_t C;
    for (int i = 0; i < 3; ++i) {
        const se23_real_t a0 = A->m[0][i], a1 = A->m[1][i], a2 = A->m[2][i];
        C.m[i][0] = a0 * B->m[0][0] + a1 * B->m[1][0] + a2 * B->m[2][0];
        C.m[i][1] = a0 * B->m[0][1] + a1 * B->m[1][1] + a2 * B->m[2][1];
        C.m[i][2] = a0 * B->m[0][2] + a1 * B->m[1][2] + a2 * B->m[2][2];
    }
    *out = C;
}
/** out = A B^T */
void se23_m3_mul_nt(const se23_mat3_t *A, const se23_mat3_t *B, se23_mat3_t *out);
/** out = A^T; out may alias A. */
static inline void se23_m3_transpose(const se23_mat3_t *A, se23_mat3_t *out)
{
    se23_mat3_t C;
    C.m[0][0] = A->m[0][0];
    C.m[0][1] = A->m[1][0];
    C.m[0][2] = A->m[2][0];
    C.m[1][0] = A->m[0][1];
    C.m[1][1] = A->m[1][1];
    C.m[1][2] = A->m[2][1];
    C.m[2][0] = A->m[0][2];
    C.m[2][1] = A->m[1][2];
    C.m[2][2] = A->m[2][2];
    *out = C;
}
/** out = A x */
void se23_m3_mul_v3(const se23_mat3_t *A, const se23_vec3_t *x, se23_vec3_t *out);
/** out = A^T x */
void se23_m3_tmul_v3(const se23_mat3_t *A, const se23_vec3_t *x, se23_vec3_t *out);
/** out = A + s B */
void se23_m3_axpy(const se23_mat3_t *A, se23_real_t s, const se23_mat3_t *B,
                  se23_mat3_t *out);
/** out = v^ (skew matrix, v^ x = v cross x) */
void se23_m3_skew(const se23_vec3_t *v, se23_mat3_t *out);
se23_real_t se23_m3_det(const se23_mat3_t *A);

/**
 * out = a0 I + a1 W + a2 W^2 with W = phi^, using W^2 = phi phi^T - |phi|^2 I.
 * Every SO(3) series (exp, J, H, K, J^-1) is of this form.
 */
void se23_m3_series(se23_real_t a0, se23_real_t a1, se23_real_t a2,
                    const se23_vec3_t *phi, se23_mat3_t *out);

#endif /* SE23_LINALG_H */
