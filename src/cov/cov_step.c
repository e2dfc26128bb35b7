/* Per-sample covariance kernels by 3x3 blocks; see cov_step.h for the
 * factored transition they evaluate.
 *
 * The covariance step itself (se23_cov_step) is straight-line code that
 * tools/gen/gen_cov_step.py generates into cov_step_kernel.c from this
 * block algorithm. Notation: X_ij, C_ik and Bb_kl are the 3x3 blocks of P
 * (pose x pose, pose x bias, bias x bias), i, j in {phi, nu, rho}, k, l in
 * {g, a}; only blocks with i <= j (k <= l) are read. With W = G X (rows of
 * G: [I, 0, 0], [-v^, I, 0], [-p^, dt I, I]),
 *   W_0j = X_0j,  W_1j = X_1j - v^ X_0j,  W_2j = X_2j + dt X_1j - p^ X_0j,
 * and A = W G^T:
 *   A_i0 = W_i0,  A_i1 = W_i0 v^ + W_i1,  A_i2 = W_i0 p^ + dt W_i1 + W_i2.
 * With bias states, Y = G C and Z = Y + Bt Bb; the pose block gains
 *   E_ij = Bt_i (Z_j + Bt_j N)^T + Y_i Bt_j^T
 * ([G Bt] P [G Bt]^T = G X G^T + G C Bt^T + Bt C^T G^T + Bt Bb Bt^T), the
 * cross block is D Z and the bias block Bb + W. Without bias states
 * E_ij = Bt_i N Bt_j^T. Every block is finally rotated, R^T (A_ij + E_ij) R;
 * the diagonal blocks' upper triangles are computed and mirrored, so P+ is
 * exactly symmetric.
 *
 * se23_cov_step runs the stages of cov_step.h: E into a scratch S of the
 * pose blocks (for 15 states a bias column at a time, storing the cross
 * blocks D Z, then the bias block), then S += G X G^T, then out's pose
 * blocks R^T S R. In place: a stage stores an entry of out only after its
 * read of the entry of P it replaces (the generator orders them so), the
 * cross and bias blocks are read by no later stage, and the pose blocks
 * are stored last. Operation counts: cov_step_kernel.c. */
#include "cov_step.h"

#include "cov_check.h"
#include "../base/linalg.h"
#include "../base/se23_math.h"

enum { PHI = 0, NU = 1, RHO = 2, GYR = 0, ACC = 1 };


/* A = the 3x3 block of P at rows r0.., columns c0.. */
static void blk_load(const se23_real_t *P, int stride, int r0, int c0,
                     se23_mat3_t *A)
{
    const se23_real_t *a = &P[stride * r0 + c0];
    const se23_real_t *b = &P[stride * (r0 + 1) + c0];
    const se23_real_t *c = &P[stride * (r0 + 2) + c0];
    A->m[0][0] = a[0];
    A->m[0][1] = a[1];
    A->m[0][2] = a[2];
    A->m[1][0] = b[0];
    A->m[1][1] = b[1];
    A->m[1][2] = b[2];
    A->m[2][0] = c[0];
    A->m[2][1] = c[1];
    A->m[2][2] = c[2];
}

/* Block (r0, c0) of P = A. */
static void blk_store(se23_real_t *P, int stride, int r0, int c0,
                      const se23_mat3_t *A)
{
    se23_real_t *a = &P[stride * r0 + c0];
    se23_real_t *b = &P[stride * (r0 + 1) + c0];
    se23_real_t *c = &P[stride * (r0 + 2) + c0];
    a[0] = A->m[0][0];
    a[1] = A->m[0][1];
    a[2] = A->m[0][2];
    b[0] = A->m[1][0];
    b[1] = A->m[1][1];
    b[2] = A->m[1][2];
    c[0] = A->m[2][0];
    c[1] = A->m[2][1];
    c[2] = A->m[2][2];
}

/* Block (r0, c0) = A and its mirror, block (c0, r0) = A^T (r0 != c0). */
static void blk_store_pair(se23_real_t *P, int stride, int r0, int c0,
                           const se23_mat3_t *A)
{
    blk_store(P, stride, r0, c0, A);
    se23_real_t *a = &P[stride * c0 + r0];
    se23_real_t *b = &P[stride * (c0 + 1) + r0];
    se23_real_t *c = &P[stride * (c0 + 2) + r0];
    a[0] = A->m[0][0];
    a[1] = A->m[1][0];
    a[2] = A->m[2][0];
    b[0] = A->m[0][1];
    b[1] = A->m[1][1];
    b[2] = A->m[2][1];
    c[0] = A->m[0][2];
    c[1] = A->m[1][2];
    c[2] = A->m[2][2];
}

/* Diagonal block at r0 = the upper triangle of A, mirrored. */
static void blk_store_sym(se23_real_t *P, int stride, int r0,
                          const se23_mat3_t *A)
{
    se23_real_t *a = &P[stride * r0 + r0];
    se23_real_t *b = &P[stride * (r0 + 1) + r0];
    se23_real_t *c = &P[stride * (r0 + 2) + r0];
    a[0] = A->m[0][0];
    a[1] = A->m[0][1];
    b[0] = A->m[0][1];
    a[2] = A->m[0][2];
    c[0] = A->m[0][2];
    b[1] = A->m[1][1];
    b[2] = A->m[1][2];
    c[1] = A->m[1][2];
    c[2] = A->m[2][2];
}

int se23_input_blocks_finite(const se23_input_blocks_t *Bt, int tame)
{
    if (tame != 0) {
        return 1;
    }
    for (int i = PHI; i <= RHO; ++i) {
        for (int k = GYR; k <= ACC; ++k) {
            if (se23_all_finite(&Bt->blk[i][k].m[0][0], 9) == 0) {
                return 0;
            }
        }
    }
    return 1;
}

se23_real_t se23_input_blocks_row_sum(const se23_input_blocks_t *Bt)
{
    se23_real_t b = SE23_R(0);
    for (int i = PHI; i <= RHO; ++i) {
        for (int r = 0; r < 3; ++r) {
            se23_real_t x = SE23_R(0);
            for (int k = GYR; k <= ACC; ++k) {
                const se23_real_t *row = Bt->blk[i][k].m[r];
                x += se23_fabs(row[0]) + se23_fabs(row[1]) + se23_fabs(row[2]);
            }
            b = (x > b) ? x : b;
        }
    }
    return b;
}

/* SE23_COV_ABS_TOL + sum_i |P_ii| (n a multiple of 3), at least the
 * largest variance: for a PSD P (trusted) a bound on every |P_ij|, cheaper
 * than the maximum. The check's absolute slack is part of it: a checked P
 * may have a variance of -SE23_COV_ABS_TOL, which a step scales like the
 * rest (a step whose gain squared is ~1e300 would turn it into a variance
 * of -1e262: refused by the bound instead). */
static se23_real_t variance_bound(int n, const se23_real_t *P, int stride)
{
    se23_real_t d = SE23_COV_ABS_TOL;
    for (int i = 0; i < n; i += 3) {
        const se23_real_t *p = &P[stride * i + i];
        d += se23_fabs(p[0]) + se23_fabs(p[stride + 1]) + se23_fabs(p[(2 * stride) + 2]);
    }
    return d;
}

/* se23_cov_fits, inlined into both callers of the per-sample path. */
static int fits(se23_real_t g, se23_real_t b, const se23_step_noise_t *q, int n,
                const se23_real_t *P, int stride)
{
    const se23_real_t d = variance_bound(n, P, stride);
    /* Row sums: the shear's at most g, [G, Bt]'s that plus b, R^T's at
     * most sqrt(3) < 2; q at most the larger density. */
    const se23_real_t r = SE23_R(2) * (g + b) + SE23_R(1);
    const se23_real_t qm = (q->qg > q->qa) ? q->qg : q->qa;
    const se23_real_t w = (q->wg > q->wa) ? q->wg : q->wa;
    const se23_real_t bound = SE23_R(2) * d * r * r + SE23_R(4) * qm * b * b + w;
    return bound <= SE23_COV_STEP_MAX;
}

int se23_cov_fits(se23_real_t g, se23_real_t b, const se23_step_noise_t *q, int n,
                  const se23_real_t *P, int stride)
{
    return fits(g, b, q, n, P, stride);
}

int se23_cov_step_fits(const se23_pose_t *U, se23_real_t dt, se23_real_t b,
                       const se23_step_noise_t *q, int n, const se23_real_t *P,
                       int stride)
{
    const se23_real_t g = SE23_R(1) + dt + se23_fabs(U->v.v[0]) + se23_fabs(U->v.v[1]) +
                          se23_fabs(U->v.v[2]) + se23_fabs(U->p.v[0]) +
                          se23_fabs(U->p.v[1]) + se23_fabs(U->p.v[2]);
    return fits(g, b, q, n, P, stride);
}

se23_status_t se23_step_noise(const se23_imu_noise_t *nz, se23_real_t dt,
                              se23_step_noise_t *q)
{
    const se23_real_t d0 = nz->gyro_noise, d1 = nz->accel_noise;
    const se23_real_t d2 = nz->gyro_walk, d3 = nz->accel_walk;
    const se23_real_t qg = d0 * d0 / dt, qa = d1 * d1 / dt;
    const se23_real_t wg = d2 * d2 * dt, wa = d3 * d3 * dt;
    /* A NaN or infinite density (dt > 0 is checked) makes its q so, as a
     * huge density or a denormal dt does; x * 0 is NaN for NaN or Inf. */
    if (!se23_is_finite(qg * SE23_R(0) + qa * SE23_R(0) + wg * SE23_R(0) + wa * SE23_R(0))) {
        return SE23_ERR_NONFINITE;
    }
    if (d0 < SE23_R(0) || d1 < SE23_R(0) || d2 < SE23_R(0) || d3 < SE23_R(0)) {
        return SE23_ERR_DOMAIN;
    }
    q->qg = qg;
    q->qa = qa;
    q->wg = wg;
    q->wa = wa;
    return SE23_OK;
}

void se23_cov_step(const se23_pose_t *U, se23_real_t dt,
                   const se23_input_blocks_t *Bt, const se23_step_noise_t *q,
                   int n, const se23_real_t *P, se23_real_t *out, int stride)
{
    se23_cov_pose_t S;
    if (n == SE23_GAUSS_N_BIAS) {
        se23_cov_step15_gyro(U, dt, Bt, q, P, out, &S);
        se23_cov_step15_accel(U, dt, Bt, q, P, out, &S);
        se23_cov_step15_bias(q, P, out);
    } else {
        se23_cov_step9_noise(Bt, q, &S);
    }
    se23_cov_shear_pose(U, dt, P, stride, &S);
    se23_cov_rotate_pose(U, &S, out, stride);
    se23_cov_clamp_variances(out, n, stride);
}

void se23_cov_fk_congruence(const se23_pose_t *U, se23_real_t dt, const se23_real_t *P,
                            se23_real_t *out, int stride)
{
    se23_cov_pose_t S = {{SE23_R(0)}};
    se23_cov_shear_pose(U, dt, P, stride, &S);
    se23_cov_rotate_pose(U, &S, out, stride);
    se23_cov_clamp_variances(out, SE23_GAUSS_N_POSE, stride);
}

/* Block (a, b) of a symmetric P from its lower triangle (the one the
 * covariance check factors). */
static void blk_load_sym(const se23_real_t *P, int stride, int a, int b,
                         se23_mat3_t *A)
{
    if (a >= b) {
        blk_load(P, stride, 3 * a, 3 * b, A);
    } else {
        blk_load(P, stride, 3 * b, 3 * a, A);
        se23_m3_transpose(A, A);
    }
}

int se23_cov_nu_shear_fits(const se23_vec3_t *a, int n, const se23_real_t *P, int stride)
{
    const se23_real_t d = variance_bound(n, P, stride);
    const se23_real_t s =
        SE23_R(1) + se23_fabs(a->v[0]) + se23_fabs(a->v[1]) + se23_fabs(a->v[2]);
    return (d * s * s) <= SE23_COV_STEP_MAX; /* NaN fails */
}

void se23_cov_nu_shear(const se23_vec3_t *a, int n, const se23_real_t *P,
                       se23_real_t *out, int stride)
{
    int nb = 3; /* 3x3 blocks per row */
    if (n == SE23_GAUSS_N_BIAS) {
        nb = 5;
    }
    se23_mat3_t Rj[SE23_GAUSS_NMAX / 3], X;
    /* R_j = X_nu,j + a^ X_rho,j from the old blocks: row nu of M P. */
    for (int j = 0; j < nb; ++j) {
        blk_load_sym(P, stride, NU, j, &Rj[j]);
        blk_load_sym(P, stride, RHO, j, &X);
        se23_m3_acc_skew_mul(&Rj[j], SE23_R(1), a, &X);
    }
    /* The other entries unchanged: the lower triangle, the one the blocks
     * were read from, copied and mirrored, so that a P accepted symmetric
     * within the check's tolerance comes out exactly symmetric (in place
     * too: each entry is read before its mirror is written). */
    for (int i = 0; i < n; ++i) {
        for (int j = i; j < n; ++j) {
            const se23_real_t v = P[stride * j + i];
            out[stride * i + j] = v;
            out[stride * j + i] = v;
        }
    }
    /* Row and column nu of M P M^T; (nu, nu) = R_nu + R_rho (a^)^T
     * = R_nu - R_rho a^. */
    const se23_vec3_t neg_a = {{-a->v[0], -a->v[1], -a->v[2]}};
    se23_m3_acc_mul_skew(&Rj[NU], &Rj[RHO], &neg_a);
    for (int j = 0; j < nb; ++j) {
        if (j == NU) {
            blk_store_sym(out, stride, 3 * NU, &Rj[NU]);
        } else {
            blk_store_pair(out, stride, 3 * NU, 3 * j, &Rj[j]);
        }
    }
    se23_cov_clamp_variances(&out[(stride + 1) * 3 * NU], 3, stride);
}

void se23_input_blocks_rotate(const se23_mat3_t *R,
                              const se23_input_blocks_t *Bt, se23_mat9x6_t *B)
{
    for (int i = PHI; i <= RHO; ++i) {
        for (int k = GYR; k <= ACC; ++k) {
            se23_mat3_t b;
            se23_m3_mul_tn(R, &Bt->blk[i][k], &b);
            blk_store(B->m, 6, 3 * i, 3 * k, &b);
        }
    }
}

int se23_input_blocks_from(const se23_mat3_t *R, const se23_mat9x6_t *B,
                           se23_input_blocks_t *Bt)
{
    for (int r = 0; r < 3; ++r) {
        for (int c = 3; c < 6; ++c) {
            if (B->m[6 * r + c] != SE23_R(0)) {
                return 0;
            }
        }
    }
    se23_mat3_t b;
    for (int i = PHI; i <= RHO; ++i) {
        for (int k = GYR; k <= ACC; ++k) {
            blk_load(B->m, 6, 3 * i, 3 * k, &b);
            se23_m3_mul(R, &b, &Bt->blk[i][k]);
        }
    }
    return 1;
}
