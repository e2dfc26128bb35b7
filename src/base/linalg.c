/* Internal fixed-size linear algebra; see linalg.h. Every function computes
 * into a local and then stores, so outputs may alias inputs. */
#include "linalg.h"

#include "se23_math.h"

int se23_all_finite(const se23_real_t *x, int n)
{
    /* x * 0 is 0 for finite x and NaN for NaN or Inf: one multiply-add per
     * value and one test at the end. */
    se23_real_t bad = SE23_R(0);
    for (int i = 0; i < n; ++i) {
        bad = se23_fma(x[i], SE23_R(0), bad);
    }
    return se23_is_finite(bad);
}

int se23_pose_finite(const se23_pose_t *T)
{
    se23_real_t bad = SE23_R(0); /* x * 0 is NaN for NaN or Inf */
    for (int i = 0; i < 3; ++i) {
        bad = se23_fma(T->R.m[i][0], SE23_R(0), bad);
        bad = se23_fma(T->R.m[i][1], SE23_R(0), bad);
        bad = se23_fma(T->R.m[i][2], SE23_R(0), bad);
        bad = se23_fma(T->v.v[i], SE23_R(0), bad);
        bad = se23_fma(T->p.v[i], SE23_R(0), bad);
    }
    return se23_is_finite(bad);
}

se23_real_t se23_v3_dot(const se23_vec3_t *a, const se23_vec3_t *b)
{
    return a->v[0] * b->v[0] + a->v[1] * b->v[1] + a->v[2] * b->v[2];
}

void se23_v3_cross(const se23_vec3_t *a, const se23_vec3_t *b, se23_vec3_t *out)
{
    se23_vec3_t c;
    c.v[0] = a->v[1] * b->v[2] - a->v[2] * b->v[1];
    c.v[1] = a->v[2] * b->v[0] - a->v[0] * b->v[2];
    c.v[2] = a->v[0] * b->v[1] - a->v[1] * b->v[0];
    *out = c;
}

void se23_v3_axpy(const se23_vec3_t *a, se23_real_t s, const se23_vec3_t *b,
                  se23_vec3_t *out)
{
    out->v[0] = a->v[0] + s * b->v[0];
    out->v[1] = a->v[1] + s * b->v[1];
    out->v[2] = a->v[2] + s * b->v[2];
}

void se23_v3_scale(const se23_vec3_t *a, se23_real_t s, se23_vec3_t *out)
{
    out->v[0] = s * a->v[0];
    out->v[1] = s * a->v[1];
    out->v[2] = s * a->v[2];
}

void se23_m3_identity(se23_mat3_t *out)
{
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            out->m[i][j] = (i == j) ? SE23_R(1) : SE23_R(0);
        }
    }
}

void se23_m3_mul(const se23_mat3_t *A, const se23_mat3_t *B, se23_mat3_t *out)
{
    const se23_real_t a00 = A->m[0][0], a01 = A->m[0][1], a02 = A->m[0][2];
    const se23_real_t a10 = A->m[1][0], a11 = A->m[1][1], a12 = A->m[1][2];
    const se23_real_t a20 = A->m[2][0], a21 = A->m[2][1], a22 = A->m[2][2];
    const se23_real_t b00 = B->m[0][0], b01 = B->m[0][1], b02 = B->m[0][2];
    const se23_real_t b10 = B->m[1][0], b11 = B->m[1][1], b12 = B->m[1][2];
    const se23_real_t b20 = B->m[2][0], b21 = B->m[2][1], b22 = B->m[2][2];
    out->m[0][0] = a00 * b00 + a01 * b10 + a02 * b20;
    out->m[0][1] = a00 * b01 + a01 * b11 + a02 * b21;
    out->m[0][2] = a00 * b02 + a01 * b12 + a02 * b22;
    out->m[1][0] = a10 * b00 + a11 * b10 + a12 * b20;
    out->m[1][1] = a10 * b01 + a11 * b11 + a12 * b21;
    out->m[1][2] = a10 * b02 + a11 * b12 + a12 * b22;
    out->m[2][0] = a20 * b00 + a21 * b10 + a22 * b20;
    out->m[2][1] = a20 * b01 + a21 * b11 + a22 * b21;
    out->m[2][2] = a20 * b02 + a21 * b12 + a22 * b22;
}

void se23_m3_mul_tn(const se23_mat3_t *A, const se23_mat3_t *B, se23_mat3_t *out)
{
    const se23_real_t a00 = A->m[0][0], a01 = A->m[0][1], a02 = A->m[0][2];
    const se23_real_t a10 = A->m[1][0], a11 = A->m[1][1], a12 = A->m[1][2];
    const se23_real_t a20 = A->m[2][0], a21 = A->m[2][1], a22 = A->m[2][2];
    const se23_real_t b00 = B->m[0][0], b01 = B->m[0][1], b02 = B->m[0][2];
    const se23_real_t b10 = B->m[1][0], b11 = B->m[1][1], b12 = B->m[1][2];
    const se23_real_t b20 = B->m[2][0], b21 = B->m[2][1], b22 = B->m[2][2];
    out->m[0][0] = a00 * b00 + a10 * b10 + a20 * b20;
    out->m[0][1] = a00 * b01 + a10 * b11 + a20 * b21;
    out->m[0][2] = a00 * b02 + a10 * b12 + a20 * b22;
    out->m[1][0] = a01 * b00 + a11 * b10 + a21 * b20;
    out->m[1][1] = a01 * b01 + a11 * b11 + a21 * b21;
    out->m[1][2] = a01 * b02 + a11 * b12 + a21 * b22;
    out->m[2][0] = a02 * b00 + a12 * b10 + a22 * b20;
    out->m[2][1] = a02 * b01 + a12 * b11 + a22 * b21;
    out->m[2][2] = a02 * b02 + a12 * b12 + a22 * b22;
}

void se23_m3_transpose(const se23_mat3_t *A, se23_mat3_t *out)
{
    const se23_real_t a01 = A->m[0][1], a02 = A->m[0][2], a12 = A->m[1][2];
    out->m[0][0] = A->m[0][0];
    out->m[1][1] = A->m[1][1];
    out->m[2][2] = A->m[2][2];
    out->m[0][1] = A->m[1][0];
    out->m[0][2] = A->m[2][0];
    out->m[1][2] = A->m[2][1];
    out->m[1][0] = a01;
    out->m[2][0] = a02;
    out->m[2][1] = a12;
}

void se23_m3_mul_nt(const se23_mat3_t *A, const se23_mat3_t *B, se23_mat3_t *out)
{
    const se23_real_t a00 = A->m[0][0], a01 = A->m[0][1], a02 = A->m[0][2];
    const se23_real_t a10 = A->m[1][0], a11 = A->m[1][1], a12 = A->m[1][2];
    const se23_real_t a20 = A->m[2][0], a21 = A->m[2][1], a22 = A->m[2][2];
    const se23_real_t b00 = B->m[0][0], b01 = B->m[0][1], b02 = B->m[0][2];
    const se23_real_t b10 = B->m[1][0], b11 = B->m[1][1], b12 = B->m[1][2];
    const se23_real_t b20 = B->m[2][0], b21 = B->m[2][1], b22 = B->m[2][2];
    out->m[0][0] = a00 * b00 + a01 * b01 + a02 * b02;
    out->m[0][1] = a00 * b10 + a01 * b11 + a02 * b12;
    out->m[0][2] = a00 * b20 + a01 * b21 + a02 * b22;
    out->m[1][0] = a10 * b00 + a11 * b01 + a12 * b02;
    out->m[1][1] = a10 * b10 + a11 * b11 + a12 * b12;
    out->m[1][2] = a10 * b20 + a11 * b21 + a12 * b22;
    out->m[2][0] = a20 * b00 + a21 * b01 + a22 * b02;
    out->m[2][1] = a20 * b10 + a21 * b11 + a22 * b12;
    out->m[2][2] = a20 * b20 + a21 * b21 + a22 * b22;
}

void se23_m3_mul_v3(const se23_mat3_t *A, const se23_vec3_t *x, se23_vec3_t *out)
{
    const se23_real_t x0 = x->v[0], x1 = x->v[1], x2 = x->v[2];
    out->v[0] = A->m[0][0] * x0 + A->m[0][1] * x1 + A->m[0][2] * x2;
    out->v[1] = A->m[1][0] * x0 + A->m[1][1] * x1 + A->m[1][2] * x2;
    out->v[2] = A->m[2][0] * x0 + A->m[2][1] * x1 + A->m[2][2] * x2;
}

void se23_m3_tmul_v3(const se23_mat3_t *A, const se23_vec3_t *x, se23_vec3_t *out)
{
    const se23_real_t x0 = x->v[0], x1 = x->v[1], x2 = x->v[2];
    out->v[0] = A->m[0][0] * x0 + A->m[1][0] * x1 + A->m[2][0] * x2;
    out->v[1] = A->m[0][1] * x0 + A->m[1][1] * x1 + A->m[2][1] * x2;
    out->v[2] = A->m[0][2] * x0 + A->m[1][2] * x1 + A->m[2][2] * x2;
}

void se23_m3_scale(const se23_mat3_t *A, se23_real_t s, se23_mat3_t *out)
{
    out->m[0][0] = s * A->m[0][0];
    out->m[0][1] = s * A->m[0][1];
    out->m[0][2] = s * A->m[0][2];
    out->m[1][0] = s * A->m[1][0];
    out->m[1][1] = s * A->m[1][1];
    out->m[1][2] = s * A->m[1][2];
    out->m[2][0] = s * A->m[2][0];
    out->m[2][1] = s * A->m[2][1];
    out->m[2][2] = s * A->m[2][2];
}

void se23_m3_axpy(const se23_mat3_t *A, se23_real_t s, const se23_mat3_t *B,
                  se23_mat3_t *out)
{
    out->m[0][0] = A->m[0][0] + s * B->m[0][0];
    out->m[0][1] = A->m[0][1] + s * B->m[0][1];
    out->m[0][2] = A->m[0][2] + s * B->m[0][2];
    out->m[1][0] = A->m[1][0] + s * B->m[1][0];
    out->m[1][1] = A->m[1][1] + s * B->m[1][1];
    out->m[1][2] = A->m[1][2] + s * B->m[1][2];
    out->m[2][0] = A->m[2][0] + s * B->m[2][0];
    out->m[2][1] = A->m[2][1] + s * B->m[2][1];
    out->m[2][2] = A->m[2][2] + s * B->m[2][2];
}

void se23_m3_skew(const se23_vec3_t *v, se23_mat3_t *out)
{
    se23_real_t x = v->v[0], y = v->v[1], z = v->v[2];
    out->m[0][0] = SE23_R(0);
    out->m[0][1] = -z;
    out->m[0][2] = y;
    out->m[1][0] = z;
    out->m[1][1] = SE23_R(0);
    out->m[1][2] = -x;
    out->m[2][0] = -y;
    out->m[2][1] = x;
    out->m[2][2] = SE23_R(0);
}

se23_real_t se23_m3_det(const se23_mat3_t *A)
{
    return A->m[0][0] * (A->m[1][1] * A->m[2][2] - A->m[1][2] * A->m[2][1]) -
           A->m[0][1] * (A->m[1][0] * A->m[2][2] - A->m[1][2] * A->m[2][0]) +
           A->m[0][2] * (A->m[1][0] * A->m[2][1] - A->m[1][1] * A->m[2][0]);
}

void se23_m3_series(se23_real_t a0, se23_real_t a1, se23_real_t a2,
                    const se23_vec3_t *phi, se23_mat3_t *out)
{
    const se23_real_t x = phi->v[0], y = phi->v[1], z = phi->v[2];
    const se23_real_t d = a0 - a2 * (x * x + y * y + z * z);
    /* W^2 = phi phi^T - theta^2 I, so the diagonal gets a0 - a2 theta^2. */
    out->m[0][0] = d + a2 * x * x;
    out->m[1][1] = d + a2 * y * y;
    out->m[2][2] = d + a2 * z * z;
    out->m[0][1] = a2 * x * y - a1 * z;
    out->m[1][0] = a2 * x * y + a1 * z;
    out->m[0][2] = a2 * x * z + a1 * y;
    out->m[2][0] = a2 * x * z - a1 * y;
    out->m[1][2] = a2 * y * z - a1 * x;
    out->m[2][1] = a2 * y * z + a1 * x;
}

/* The accumulating kernels load every operand once into locals before
 * the first store (so C may not alias A or B, and nothing is reloaded),
 * and sum c + a0 b0 + a1 b1 + a2 b2 left to right: three fused
 * multiply-adds where the target has them. */




/* Column j of v^ A is v x A_j. */
void se23_m3_acc_skew_mul(se23_mat3_t *C, se23_real_t s, const se23_vec3_t *v,
                          const se23_mat3_t *A)
{
    const se23_real_t x = s * v->v[0], y = s * v->v[1], z = s * v->v[2];
    const se23_real_t a00 = A->m[0][0], a01 = A->m[0][1], a02 = A->m[0][2];
    const se23_real_t a10 = A->m[1][0], a11 = A->m[1][1], a12 = A->m[1][2];
    const se23_real_t a20 = A->m[2][0], a21 = A->m[2][1], a22 = A->m[2][2];
    C->m[0][0] = C->m[0][0] + y * a20 - z * a10;
    C->m[1][0] = C->m[1][0] + z * a00 - x * a20;
    C->m[2][0] = C->m[2][0] + x * a10 - y * a00;
    C->m[0][1] = C->m[0][1] + y * a21 - z * a11;
    C->m[1][1] = C->m[1][1] + z * a01 - x * a21;
    C->m[2][1] = C->m[2][1] + x * a11 - y * a01;
    C->m[0][2] = C->m[0][2] + y * a22 - z * a12;
    C->m[1][2] = C->m[1][2] + z * a02 - x * a22;
    C->m[2][2] = C->m[2][2] + x * a12 - y * a02;
}

/* Row i of A v^ is A_i x v. */
void se23_m3_acc_mul_skew(se23_mat3_t *C, const se23_mat3_t *A, const se23_vec3_t *v)
{
    const se23_real_t x = v->v[0], y = v->v[1], z = v->v[2];
    const se23_real_t a00 = A->m[0][0], a01 = A->m[0][1], a02 = A->m[0][2];
    const se23_real_t a10 = A->m[1][0], a11 = A->m[1][1], a12 = A->m[1][2];
    const se23_real_t a20 = A->m[2][0], a21 = A->m[2][1], a22 = A->m[2][2];
    C->m[0][0] = C->m[0][0] + a01 * z - a02 * y;
    C->m[0][1] = C->m[0][1] + a02 * x - a00 * z;
    C->m[0][2] = C->m[0][2] + a00 * y - a01 * x;
    C->m[1][0] = C->m[1][0] + a11 * z - a12 * y;
    C->m[1][1] = C->m[1][1] + a12 * x - a10 * z;
    C->m[1][2] = C->m[1][2] + a10 * y - a11 * x;
    C->m[2][0] = C->m[2][0] + a21 * z - a22 * y;
    C->m[2][1] = C->m[2][1] + a22 * x - a20 * z;
    C->m[2][2] = C->m[2][2] + a20 * y - a21 * x;
}


se23_real_t se23_m3_orthonormalize_step(se23_mat3_t *X, se23_real_t done,
                                        se23_real_t max_drift)
{
    /* X^T X is symmetric: its upper triangle (18 multiply-adds, the
     * columns' dot products) carries the drift. */
    const se23_real_t x00 = X->m[0][0], x01 = X->m[0][1], x02 = X->m[0][2];
    const se23_real_t x10 = X->m[1][0], x11 = X->m[1][1], x12 = X->m[1][2];
    const se23_real_t x20 = X->m[2][0], x21 = X->m[2][1], x22 = X->m[2][2];
    se23_mat3_t XtX;
    XtX.m[0][0] = x00 * x00 + x10 * x10 + x20 * x20;
    XtX.m[1][1] = x01 * x01 + x11 * x11 + x21 * x21;
    XtX.m[2][2] = x02 * x02 + x12 * x12 + x22 * x22;
    XtX.m[0][1] = x00 * x01 + x10 * x11 + x20 * x21;
    XtX.m[0][2] = x00 * x02 + x10 * x12 + x20 * x22;
    XtX.m[1][2] = x01 * x02 + x11 * x12 + x21 * x22;
    XtX.m[1][0] = XtX.m[0][1];
    XtX.m[2][0] = XtX.m[0][2];
    XtX.m[2][1] = XtX.m[1][2];
    const se23_real_t e[6] = {
        se23_fabs(XtX.m[0][0] - SE23_R(1)), se23_fabs(XtX.m[1][1] - SE23_R(1)),
        se23_fabs(XtX.m[2][2] - SE23_R(1)), se23_fabs(XtX.m[0][1]),
        se23_fabs(XtX.m[0][2]),             se23_fabs(XtX.m[1][2])};
    se23_real_t drift = e[0];
    for (int i = 1; i < 6; ++i) {
        drift = (e[i] > drift) ? e[i] : drift;
    }
    if (drift > done && drift <= max_drift) {
        /* (3I - X^T X)/2, then X times it. */
        se23_mat3_t M;
        se23_m3_scale(&XtX, SE23_R(-0.5), &M);
        M.m[0][0] += SE23_R(1.5);
        M.m[1][1] += SE23_R(1.5);
        M.m[2][2] += SE23_R(1.5);
        se23_m3_mul(X, &M, X);
    }
    return drift;
}
