/* Long-double 3x3 helpers of the simulator; see ldmath.h. */
#include "ldmath.h"

#include <math.h>

ld_mat3_t ld_identity(void)
{
    ld_mat3_t I = {{{1.0L, 0.0L, 0.0L}, {0.0L, 1.0L, 0.0L}, {0.0L, 0.0L, 1.0L}}};
    return I;
}

ld_mat3_t ld_mat3_from(const double m[9])
{
    ld_mat3_t R;
    int i, j;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            R.m[i][j] = m[3 * i + j];
        }
    }
    return R;
}

ld_vec3_t ld_vec3_from(const double x[3])
{
    ld_vec3_t v;
    int i;
    for (i = 0; i < 3; i++) {
        v.v[i] = x[i];
    }
    return v;
}

void ld_mat3_to(const ld_mat3_t *A, double m[9])
{
    int i, j;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            m[3 * i + j] = (double)A->m[i][j];
        }
    }
}

void ld_vec3_to(const ld_vec3_t *a, double x[3])
{
    int i;
    for (i = 0; i < 3; i++) {
        x[i] = (double)a->v[i];
    }
}

ld_mat3_t ld_mul(const ld_mat3_t *A, const ld_mat3_t *B)
{
    ld_mat3_t C;
    int i, j;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            C.m[i][j] = A->m[i][0] * B->m[0][j] + A->m[i][1] * B->m[1][j] + A->m[i][2] * B->m[2][j];
        }
    }
    return C;
}

ld_mat3_t ld_mul_tn(const ld_mat3_t *A, const ld_mat3_t *B)
{
    ld_mat3_t At = ld_transpose(A);
    return ld_mul(&At, B);
}

ld_mat3_t ld_transpose(const ld_mat3_t *A)
{
    ld_mat3_t T;
    int i, j;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            T.m[i][j] = A->m[j][i];
        }
    }
    return T;
}

ld_vec3_t ld_mul_v(const ld_mat3_t *A, const ld_vec3_t *x)
{
    ld_vec3_t y;
    int i;
    for (i = 0; i < 3; i++) {
        y.v[i] = A->m[i][0] * x->v[0] + A->m[i][1] * x->v[1] + A->m[i][2] * x->v[2];
    }
    return y;
}

ld_vec3_t ld_tmul_v(const ld_mat3_t *A, const ld_vec3_t *x)
{
    ld_vec3_t y;
    int i;
    for (i = 0; i < 3; i++) {
        y.v[i] = A->m[0][i] * x->v[0] + A->m[1][i] * x->v[1] + A->m[2][i] * x->v[2];
    }
    return y;
}

ld_vec3_t ld_cross(const ld_vec3_t *a, const ld_vec3_t *b)
{
    ld_vec3_t c;
    c.v[0] = a->v[1] * b->v[2] - a->v[2] * b->v[1];
    c.v[1] = a->v[2] * b->v[0] - a->v[0] * b->v[2];
    c.v[2] = a->v[0] * b->v[1] - a->v[1] * b->v[0];
    return c;
}

ld_vec3_t ld_add(const ld_vec3_t *a, const ld_vec3_t *b)
{
    ld_vec3_t c;
    int i;
    for (i = 0; i < 3; i++) {
        c.v[i] = a->v[i] + b->v[i];
    }
    return c;
}

ld_vec3_t ld_sub(const ld_vec3_t *a, const ld_vec3_t *b)
{
    ld_vec3_t c;
    int i;
    for (i = 0; i < 3; i++) {
        c.v[i] = a->v[i] - b->v[i];
    }
    return c;
}

ld_vec3_t ld_scale(const ld_vec3_t *a, ld_t s)
{
    ld_vec3_t c;
    int i;
    for (i = 0; i < 3; i++) {
        c.v[i] = a->v[i] * s;
    }
    return c;
}

ld_t ld_norm(const ld_vec3_t *a)
{
    return sqrtl(a->v[0] * a->v[0] + a->v[1] * a->v[1] + a->v[2] * a->v[2]);
}

ld_mat3_t ld_hat(const ld_vec3_t *w)
{
    ld_mat3_t W = {{{0.0L, -w->v[2], w->v[1]}, {w->v[2], 0.0L, -w->v[0]}, {-w->v[1], w->v[0], 0.0L}}};
    return W;
}

/* I a0 + a1 W + a2 W^2 with W = phi^. */
static ld_mat3_t series(ld_t a0, ld_t a1, ld_t a2, const ld_vec3_t *phi)
{
    ld_mat3_t W = ld_hat(phi);
    ld_mat3_t W2 = ld_mul(&W, &W);
    ld_mat3_t S;
    int i, j;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            S.m[i][j] = a1 * W.m[i][j] + a2 * W2.m[i][j] + (i == j ? a0 : 0.0L);
        }
    }
    return S;
}

ld_mat3_t ld_exp(const ld_vec3_t *phi)
{
    ld_t th = ld_norm(phi);
    ld_t t2 = th * th;
    ld_t a1, a2;
    if (th < 1e-4L) {
        a1 = 1.0L - t2 / 6.0L + t2 * t2 / 120.0L;
        a2 = 0.5L - t2 / 24.0L + t2 * t2 / 720.0L;
    } else {
        a1 = sinl(th) / th;
        a2 = (1.0L - cosl(th)) / t2;
    }
    return series(1.0L, a1, a2, phi);
}

ld_vec3_t ld_log(const ld_mat3_t *R)
{
    ld_vec3_t w = {{R->m[2][1] - R->m[1][2], R->m[0][2] - R->m[2][0], R->m[1][0] - R->m[0][1]}};
    ld_t s = 0.5L * ld_norm(&w);
    ld_t c = 0.5L * (R->m[0][0] + R->m[1][1] + R->m[2][2] - 1.0L);
    ld_t th = atan2l(s, c);
    ld_t k = (th < 1e-6L) ? 0.5L * (1.0L + th * th / 6.0L) : 0.5L * th / sinl(th);
    return ld_scale(&w, k);
}

ld_mat3_t ld_jl(const ld_vec3_t *phi)
{
    ld_t th = ld_norm(phi);
    ld_t t2 = th * th;
    ld_t a1, a2;
    if (th < 1e-4L) {
        a1 = 0.5L - t2 / 24.0L + t2 * t2 / 720.0L;
        a2 = 1.0L / 6.0L - t2 / 120.0L + t2 * t2 / 5040.0L;
    } else {
        a1 = (1.0L - cosl(th)) / t2;
        a2 = (th - sinl(th)) / (t2 * th);
    }
    return series(1.0L, a1, a2, phi);
}

ld_mat3_t ld_k_series(const ld_vec3_t *phi)
{
    ld_mat3_t W = ld_hat(phi), P = ld_identity(), K;
    ld_t fact = 1.0L; /* n! */
    int n, i, j;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            K.m[i][j] = (i == j) ? 0.5L : 0.0L;
        }
    }
    for (n = 1; n < 30; n++) {
        P = ld_mul(&P, &W);
        fact *= (ld_t)n;
        for (i = 0; i < 3; i++) {
            for (j = 0; j < 3; j++) {
                K.m[i][j] += P.m[i][j] / (fact * (ld_t)(n + 2));
            }
        }
    }
    return K;
}

ld_mat3_t ld_euler(ld_t roll, ld_t pitch, ld_t yaw)
{
    ld_t cr = cosl(roll), sr = sinl(roll);
    ld_t cp = cosl(pitch), sp = sinl(pitch);
    ld_t cy = cosl(yaw), sy = sinl(yaw);
    ld_mat3_t R = {{{cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr},
                    {sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr},
                    {-sp, cp * sr, cp * cr}}};
    return R;
}

ld_mat3_t ld_inv(const ld_mat3_t *A)
{
    const ld_t(*a)[3] = A->m;
    ld_mat3_t C;
    ld_t det;
    int i, j;
    C.m[0][0] = a[1][1] * a[2][2] - a[1][2] * a[2][1];
    C.m[0][1] = a[0][2] * a[2][1] - a[0][1] * a[2][2];
    C.m[0][2] = a[0][1] * a[1][2] - a[0][2] * a[1][1];
    C.m[1][0] = a[1][2] * a[2][0] - a[1][0] * a[2][2];
    C.m[1][1] = a[0][0] * a[2][2] - a[0][2] * a[2][0];
    C.m[1][2] = a[0][2] * a[1][0] - a[0][0] * a[1][2];
    C.m[2][0] = a[1][0] * a[2][1] - a[1][1] * a[2][0];
    C.m[2][1] = a[0][1] * a[2][0] - a[0][0] * a[2][1];
    C.m[2][2] = a[0][0] * a[1][1] - a[0][1] * a[1][0];
    det = a[0][0] * C.m[0][0] + a[0][1] * C.m[1][0] + a[0][2] * C.m[2][0];
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            C.m[i][j] /= det;
        }
    }
    return C;
}

ld_mat3_t ld_orthonormalize(const ld_mat3_t *R)
{
    ld_mat3_t RtR = ld_mul_tn(R, R);
    ld_mat3_t M, out;
    int i, j;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            M.m[i][j] = -0.5L * RtR.m[i][j] + (i == j ? 1.5L : 0.0L);
        }
    }
    out = ld_mul(R, &M);
    return out;
}
