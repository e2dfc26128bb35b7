/* Internal fixed-size linear algebra; see linalg.h. Every function computes
 * into a local and then stores, so outputs may alias inputs. */
#include "linalg.h"

#include "se23_math.h"

int se23_all_finite(const se23_real_t *x, int n)
{
    for (int i = 0; i < n; ++i) {
        if (!se23_is_finite(x[i])) {
            return 0;
        }
    }
    return 1;
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
    for (int i = 0; i < 3; ++i) {
        out->v[i] = a->v[i] + s * b->v[i];
    }
}

void se23_v3_scale(const se23_vec3_t *a, se23_real_t s, se23_vec3_t *out)
{
    for (int i = 0; i < 3; ++i) {
        out->v[i] = s * a->v[i];
    }
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
    se23_mat3_t C;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            C.m[i][j] = A->m[i][0] * B->m[0][j] + A->m[i][1] * B->m[1][j] +
                        A->m[i][2] * B->m[2][j];
        }
    }
    *out = C;
}

void se23_m3_mul_nt(const se23_mat3_t *A, const se23_mat3_t *B, se23_mat3_t *out)
{
    se23_mat3_t C;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            C.m[i][j] = A->m[i][0] * B->m[j][0] + A->m[i][1] * B->m[j][1] +
                        A->m[i][2] * B->m[j][2];
        }
    }
    *out = C;
}

void se23_m3_mul_v3(const se23_mat3_t *A, const se23_vec3_t *x, se23_vec3_t *out)
{
    se23_vec3_t y;
    for (int i = 0; i < 3; ++i) {
        y.v[i] = A->m[i][0] * x->v[0] + A->m[i][1] * x->v[1] + A->m[i][2] * x->v[2];
    }
    *out = y;
}

void se23_m3_tmul_v3(const se23_mat3_t *A, const se23_vec3_t *x, se23_vec3_t *out)
{
    se23_vec3_t y;
    for (int i = 0; i < 3; ++i) {
        y.v[i] = A->m[0][i] * x->v[0] + A->m[1][i] * x->v[1] + A->m[2][i] * x->v[2];
    }
    *out = y;
}

void se23_m3_axpy(const se23_mat3_t *A, se23_real_t s, const se23_mat3_t *B,
                  se23_mat3_t *out)
{
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            out->m[i][j] = A->m[i][j] + s * B->m[i][j];
        }
    }
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
