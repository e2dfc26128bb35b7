/**
 * @file ldmath.h
 * @brief Small long-double 3-vector / 3x3 helpers of the harness tools.
 *
 * The simulator's truth must not depend on the library under test, so it
 * carries its own (simple, long double) rotation arithmetic.
 * Matrices are row-major m[3][3].
 */
#ifndef HARNESS_LDMATH_H
#define HARNESS_LDMATH_H

typedef long double ld_t;

typedef struct {
    ld_t v[3];
} ld_vec3_t;

typedef struct {
    ld_t m[3][3];
} ld_mat3_t;

ld_mat3_t ld_identity(void);
ld_mat3_t ld_mat3_from(const double m[9]);      /* from row-major doubles */
ld_vec3_t ld_vec3_from(const double x[3]);
void ld_mat3_to(const ld_mat3_t *A, double m[9]); /* to row-major doubles */
void ld_vec3_to(const ld_vec3_t *a, double x[3]);
ld_mat3_t ld_mul(const ld_mat3_t *A, const ld_mat3_t *B);     /* A B */
ld_mat3_t ld_mul_tn(const ld_mat3_t *A, const ld_mat3_t *B);  /* A^T B */
ld_mat3_t ld_transpose(const ld_mat3_t *A);
ld_vec3_t ld_mul_v(const ld_mat3_t *A, const ld_vec3_t *x);   /* A x */
ld_vec3_t ld_tmul_v(const ld_mat3_t *A, const ld_vec3_t *x);  /* A^T x */
ld_vec3_t ld_cross(const ld_vec3_t *a, const ld_vec3_t *b);
ld_vec3_t ld_add(const ld_vec3_t *a, const ld_vec3_t *b);
ld_vec3_t ld_sub(const ld_vec3_t *a, const ld_vec3_t *b);
ld_vec3_t ld_scale(const ld_vec3_t *a, ld_t s);
ld_t ld_norm(const ld_vec3_t *a);
ld_mat3_t ld_hat(const ld_vec3_t *w);
/** exp(phi^) by Rodrigues' formula (Taylor branch near 0). */
ld_mat3_t ld_exp(const ld_vec3_t *phi);
/** Principal log of a rotation (for angles well below pi; the simulator's use). */
ld_vec3_t ld_log(const ld_mat3_t *R);
/** Left Jacobian J(phi) = sum phi^^n/(n+1)!. */
ld_mat3_t ld_jl(const ld_vec3_t *phi);
/** K(phi) = sum phi^^n / (n! (n+2)) by direct summation (|phi| <= 1). */
ld_mat3_t ld_k_series(const ld_vec3_t *phi);
/** R = Rz(yaw) Ry(pitch) Rx(roll): body FRD -> NED. */
ld_mat3_t ld_euler(ld_t roll, ld_t pitch, ld_t yaw);
/** Inverse of a 3x3 matrix by cofactors (the caller ensures it is regular). */
ld_mat3_t ld_inv(const ld_mat3_t *A);
/** One Newton-Schulz step R (3I - R^T R)/2 towards SO(3). */
ld_mat3_t ld_orthonormalize(const ld_mat3_t *R);

#endif /* HARNESS_LDMATH_H */
