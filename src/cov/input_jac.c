/* The input matrix B_k of one IMU sample (bias Jacobian of the exact
 * increment); see gauss.h, se23_gauss_input_jac.
 *
 * Computed as Bt = diag(R, R, R) B (cov_step.h), whose blocks need no
 * rotation: dt J(th), dt^2 D_J, dt^3 D_H, dt^2 H(th), J and H shared with
 * the increment (imu_step.h).
 *
 * Derivation. Upsilon(w, f) = (R, dt J(th) f, dt^2 H(th) f), th = w dt.
 * To first order log(Upsilon^-1 Upsilon') = (log(R^T R'), R^T dv, R^T dp).
 *  - exp(th + d) = exp(th) exp(Jr(th) d), so the rotation block is dt Jr(th).
 *  - dv = dt J(th) da + dt^2 D_J(th, f) dg, and R^T J(th) = Jr(th).
 *  - dp = dt^2 H(th) da + dt^3 D_H(th, f) dg.
 * With S(th) = a0 I + a1(t) W + a2(t) W^2 (W = th^, t = |th|),
 * d(W f)/d(th) = -f^, d(W^2 f)/d(th) = (th.f) I + th f^T - 2 f th^T and
 * d(a(t))/d(th) = (a'(t)/t) th^T, which gives D_S in gauss.h. For J,
 * (a1, a2) = (c2, c3); for H, (c3, c4) (so3_series.h). The derivative
 * coefficients dm = cm'(t)/t are, with cm = sum_k (-1)^k t^2k / (2k+m)!,
 *   d2 = (t sin t + 2 cos t - 2)/t^4,
 *   d3 = (3 sin t - 2 t - t cos t)/t^5,
 *   d4 = (4 - 4 cos t - t^2 - t sin t)/t^6,
 *   dm = sum_{k>=1} (-1)^k 2k t^(2k-2) / (2k+m)!.
 *
 * Thresholds. The closed forms lose about eps * 1500 / t^6 (relative, d4,
 * the worst); the Taylor series with DERIV_TERMS terms truncates below
 * 1e-17 (relative) for t^2 <= 2.25 and below 1e-12 for t^2 <= 9. Double:
 * Taylor below t = 1.5 (closed form then within 3e-14). Float: Taylor
 * below t = 3 (closed form then within 3e-7).
 */
#include "se23/gauss.h"

#include "../base/argcheck.h"
#include "cov_step.h"
#include "../imu/imu_step.h"
#include "../base/linalg.h"
#include "../base/se23_math.h"
#include "../lie/so3_series.h"
#include "../base/trig.h"

#define DERIV_TERMS 10

#if SE23_CFG_DOUBLE
#define DERIV_TAYLOR_MAX SE23_R(1.5)
#else
#define DERIV_TAYLOR_MAX SE23_R(3.0)
#endif

/* (-1)^k 2k / (2k+m)!, k = 1..DERIV_TERMS, for m = 2, 3, 4. */
static const se23_real_t d2_taylor[DERIV_TERMS] = {
    SE23_R(-1.0 / 12.0),
    SE23_R(1.0 / 180.0),
    SE23_R(-1.0 / 6720.0),
    SE23_R(1.0 / 453600.0),
    SE23_R(-1.0 / 47900160.0),
    SE23_R(1.0 / 7264857600.0),
    SE23_R(-1.0 / 1494484992000.0),
    SE23_R(1.0 / 400148356608000.0),
    SE23_R(-1.0 / 135161222676480000.0),
    SE23_R(1.0 / 56200036388880384000.0),
};
static const se23_real_t d3_taylor[DERIV_TERMS] = {
    SE23_R(-1.0 / 60.0),
    SE23_R(1.0 / 1260.0),
    SE23_R(-1.0 / 60480.0),
    SE23_R(1.0 / 4989600.0),
    SE23_R(-1.0 / 622702080.0),
    SE23_R(1.0 / 108972864000.0),
    SE23_R(-1.0 / 25406244864000.0),
    SE23_R(1.0 / 7602818775552000.0),
    SE23_R(-1.0 / 2838385676206080000.0),
    SE23_R(1.0 / 1292600836944248832000.0),
};
static const se23_real_t d4_taylor[DERIV_TERMS] = {
    SE23_R(-1.0 / 360.0),
    SE23_R(1.0 / 10080.0),
    SE23_R(-1.0 / 604800.0),
    SE23_R(1.0 / 59875200.0),
    SE23_R(-1.0 / 8717829120.0),
    SE23_R(1.0 / 1743565824000.0),
    SE23_R(-1.0 / 457312407552000.0),
    SE23_R(1.0 / 152056375511040000.0),
    SE23_R(-1.0 / 62444484876533760000.0),
    SE23_R(1.0 / 31022420086661971968000.0),
};

static se23_real_t horner(const se23_real_t *c, int terms, se23_real_t t2)
{
    se23_real_t s = c[terms - 1];
    for (int k = terms - 2; k >= 0; --k) {
        s = s * t2 + c[k];
    }
    return s;
}

typedef struct {
    se23_real_t d2, d3, d4;
} deriv_coeffs_t;

/* d_m as Taylor sums of `terms` terms in t^2. Inline, so a constant term
 * count lets the compiler write the sums out. */
static inline void taylor_derivs(se23_real_t t2, int terms, deriv_coeffs_t *d)
{
    d->d2 = horner(d2_taylor, terms, t2);
    d->d3 = horner(d3_taylor, terms, t2);
    d->d4 = horner(d4_taylor, terms, t2);
}

static void deriv_coeffs(se23_real_t t, deriv_coeffs_t *d)
{
    const se23_real_t t2 = t * t;
    if (t < SE23_SERIES_SMALL_THETA) {
        /* Small angles: the first omitted term is below 3e-17 (double) or
         * 3e-9 (float) relative, as for the series of so3_series.h; no loop. */
        taylor_derivs(t2, SE23_SERIES_SMALL_TERMS, d);
        return;
    }
    if (t < DERIV_TAYLOR_MAX) {
        taylor_derivs(t2, DERIV_TERMS, d);
        return;
    }
    se23_real_t s, c;
    se23_sincos(t, &s, &c);
    const se23_real_t t4 = t2 * t2;
    d->d2 = (t * s + SE23_R(2) * c - SE23_R(2)) / t4;
    d->d3 = (SE23_R(3) * s - SE23_R(2) * t - t * c) / (t4 * t);
    d->d4 = (SE23_R(4) - SE23_R(4) * c - t2 - t * s) / (t4 * t2);
}

/* D = s d(S(th) f)/d(th) for S = a0 I + a1 W + a2 W^2 with a1' / t = b1,
 * a2' / t = b2 (file comment), rearranged as
 *   D/s = th (a2 f)^T + (u - 2 a2 f) th^T - a1 f^ + a2 (th.f) I,
 *   u = b1 th x f + b2 th x (th x f).  [~40 multiply-adds] */
static void series_deriv(se23_real_t a1, se23_real_t a2, se23_real_t b1,
                         se23_real_t b2, const se23_vec3_t *th,
                         const se23_vec3_t *f, se23_real_t s, se23_mat3_t *D)
{
    const se23_real_t t0 = th->v[0], t1 = th->v[1], t2 = th->v[2];
    const se23_real_t f0 = f->v[0], f1 = f->v[1], f2 = f->v[2];
    const se23_real_t x0 = t1 * f2 - t2 * f1; /* th x f */
    const se23_real_t x1 = t2 * f0 - t0 * f2;
    const se23_real_t x2 = t0 * f1 - t1 * f0;
    const se23_real_t y0 = t1 * x2 - t2 * x1; /* th x (th x f) */
    const se23_real_t y1 = t2 * x0 - t0 * x2;
    const se23_real_t y2 = t0 * x1 - t1 * x0;
    const se23_real_t sa2 = s * a2, c = s * a1, d = sa2 * (t0 * f0 + t1 * f1 + t2 * f2);
    const se23_real_t af0 = sa2 * f0, af1 = sa2 * f1, af2 = sa2 * f2;
    const se23_real_t w0 = s * (b1 * x0 + b2 * y0) - SE23_R(2) * af0;
    const se23_real_t w1 = s * (b1 * x1 + b2 * y1) - SE23_R(2) * af1;
    const se23_real_t w2 = s * (b1 * x2 + b2 * y2) - SE23_R(2) * af2;
    const se23_real_t cf0 = c * f0, cf1 = c * f1, cf2 = c * f2;
    D->m[0][0] = t0 * af0 + w0 * t0 + d;
    D->m[0][1] = t0 * af1 + w0 * t1 + cf2;
    D->m[0][2] = t0 * af2 + w0 * t2 - cf1;
    D->m[1][0] = t1 * af0 + w1 * t0 - cf2;
    D->m[1][1] = t1 * af1 + w1 * t1 + d;
    D->m[1][2] = t1 * af2 + w1 * t2 + cf0;
    D->m[2][0] = t2 * af0 + w2 * t0 + cf1;
    D->m[2][1] = t2 * af1 + w2 * t1 - cf0;
    D->m[2][2] = t2 * af2 + w2 * t2 + d;
}

/* A = 0, written out (a zero struct copied in costs a memset and a memcpy
 * call per block on Cortex-M). */
static void zero_block(se23_mat3_t *A)
{
    A->m[0][0] = SE23_R(0);
    A->m[0][1] = SE23_R(0);
    A->m[0][2] = SE23_R(0);
    A->m[1][0] = SE23_R(0);
    A->m[1][1] = SE23_R(0);
    A->m[1][2] = SE23_R(0);
    A->m[2][0] = SE23_R(0);
    A->m[2][1] = SE23_R(0);
    A->m[2][2] = SE23_R(0);
}

/* B = A, written out (a struct copy is a memcpy call on Cortex-M7). */
static void copy_block(const se23_mat3_t *A, se23_mat3_t *B)
{
    B->m[0][0] = A->m[0][0];
    B->m[0][1] = A->m[0][1];
    B->m[0][2] = A->m[0][2];
    B->m[1][0] = A->m[1][0];
    B->m[1][1] = A->m[1][1];
    B->m[1][2] = A->m[1][2];
    B->m[2][0] = A->m[2][0];
    B->m[2][1] = A->m[2][1];
    B->m[2][2] = A->m[2][2];
}

void se23_input_blocks(se23_input_jac_kind_t kind,
                       const se23_increment_parts_t *q, const se23_mat3_t *R,
                       const se23_vec3_t *f, se23_real_t dt,
                       se23_input_blocks_t *Bt)
{
    zero_block(&Bt->blk[0][1]);
    if (kind == SE23_INPUT_JAC_BASIC) {
        /* D^-1 dt I_{9,6}: dt R in the rotation and velocity rows. */
        se23_m3_scale(R, dt, &Bt->blk[0][0]);
        zero_block(&Bt->blk[1][0]);
        se23_m3_scale(R, dt, &Bt->blk[1][1]);
        zero_block(&Bt->blk[2][0]);
        zero_block(&Bt->blk[2][1]);
        return;
    }
    deriv_coeffs_t d;
    deriv_coeffs(q->t, &d);
    const se23_real_t dt2 = dt * dt;
    se23_m3_scale(&q->J, dt, &Bt->blk[0][0]);
    series_deriv(q->c.c2, q->c.c3, d.d2, d.d3, &q->th, f, dt2, &Bt->blk[1][0]);
    copy_block(&Bt->blk[0][0], &Bt->blk[1][1]); /* dt J in both */
    series_deriv(q->c.c3, q->c.c4, d.d3, d.d4, &q->th, f, dt2 * dt, &Bt->blk[2][0]);
    se23_m3_scale(&q->H, dt2, &Bt->blk[2][1]);
}

se23_real_t se23_input_blocks_bound(const se23_vec3_t *f, se23_real_t dt)
{
    const se23_real_t f1 = se23_fabs(f->v[0]) + se23_fabs(f->v[1]) + se23_fabs(f->v[2]);
    return SE23_R(6) * dt * (SE23_R(1) + dt * f1 * (SE23_R(1) + dt));
}

se23_status_t se23_gauss_input_jac(se23_input_jac_kind_t kind,
                                   const se23_vec3_t *w_b,
                                   const se23_vec3_t *f_b, se23_real_t dt,
                                   se23_mat9x6_t *B)
{
    SE23_CHECK_NOT_NULL(w_b);
    SE23_CHECK_NOT_NULL(f_b);
    SE23_CHECK_NOT_NULL(B);
    if (!se23_all_finite(w_b->v, 3) || !se23_all_finite(f_b->v, 3)) {
        return SE23_ERR_NONFINITE;
    }
    if (!(dt > SE23_R(0) && dt <= SE23_R(SE23_CFG_DT_MAX))) {
        return SE23_ERR_DT;
    }
    if (kind != SE23_INPUT_JAC_EXACT && kind != SE23_INPUT_JAC_BASIC) {
        return SE23_ERR_DOMAIN;
    }
    if (kind == SE23_INPUT_JAC_BASIC) {
        se23_mat9x6_t out = {{SE23_R(0)}};
        for (int i = 0; i < 6; ++i) {
            out.m[6 * i + i] = dt;
        }
        *B = out;
        return SE23_OK;
    }
    se23_imu_sample_t s;
    s.w_ib_b = *w_b;
    s.f_b = *f_b;
    s.dt = dt;
    se23_pose_t U;
    se23_increment_parts_t q;
    se23_input_blocks_t Bt;
    se23_mat9x6_t out;
    se23_imu_increment_parts(&s, &U, &q);
    se23_input_blocks(kind, &q, &U.R, f_b, dt, &Bt);
    se23_input_blocks_rotate(&U.R, &Bt, &out);
    if (!se23_all_finite(out.m, 54)) {
        return SE23_ERR_NONFINITE; /* |w dt|^2 or dt^2 f overflowed */
    }
    *B = out;
    return SE23_OK;
}

void se23_sample_inputs(se23_input_jac_kind_t kind, const se23_imu_sample_t *c,
                        se23_pose_t *U, se23_input_blocks_t *Bt)
{
    se23_increment_parts_t parts;
    se23_imu_increment_parts(c, U, &parts);
    se23_input_blocks(kind, &parts, &U->R, &c->f_b, c->dt, Bt);
}

se23_status_t se23_predict_inputs(const se23_earth_model_t *model, const se23_pose_t *T,
                                  const se23_imu_noise_t *noise, se23_input_jac_kind_t kind,
                                  se23_predict_work_t *w)
{
    se23_step_inputs_t *in = &w->in;
    se23_increment_parts_t parts;
    se23_status_t st = se23_imu_step_ups(model, T, &in->c, &w->T_next, &in->U, &parts);
    if (st == SE23_OK) {
        st = se23_step_noise(noise, in->c.dt, &in->q);
    }
    if (st != SE23_OK) {
        return st;
    }
    se23_input_blocks(kind, &parts, &in->U.R, &in->c.f_b, in->c.dt, &in->Bt);
    return se23_input_blocks_finite(&in->Bt, parts.tame) ? SE23_OK : SE23_ERR_NONFINITE;
}
