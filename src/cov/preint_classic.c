/* Classical (Forster et al. 2017) bias Jacobians of a preintegrated factor
 * and their first-order correction; see preint_classic.h and
 * se23/preint_unc.h. */
#include "preint_classic.h"

#include "../base/linalg.h"
#include "../base/se23_math.h"
#include "../lie/so3_series.h"

/* out = A + s B C */
static void m3_add_mul(const se23_mat3_t *A, se23_real_t s,
                       const se23_mat3_t *B, const se23_mat3_t *C,
                       se23_mat3_t *out)
{
    se23_mat3_t BC;
    se23_m3_mul(B, C, &BC);
    se23_m3_axpy(A, s, &BC, out);
}

void se23_preint_classic_step(se23_preint_classic_t *c, const se23_mat3_t *dR,
                              const se23_mat3_t *dR_k, const se23_vec3_t *w,
                              const se23_vec3_t *f, se23_real_t dt)
{
    se23_vec3_t th;
    se23_v3_scale(w, dt, &th);
    se23_so3_coeffs_t k;
    se23_so3_coeffs(se23_sqrt(se23_v3_dot(&th, &th)), &k);
    se23_mat3_t Jr, fx, RFx, t;
    se23_m3_series(SE23_R(1), -k.c2, k.c3, &th, &Jr); /* Jr(th) = J(-th) */
    se23_m3_skew(f, &fx);
    se23_m3_mul(dR, &fx, &RFx);                        /* DeltaR f^ */
    const se23_real_t h = SE23_R(0.5) * dt * dt;
    /* Every right-hand side reads the values before the sample: updated
     * in place in the order X, V, R, each read before its own update. */
    se23_m3_axpy(&c->dX_dbg, dt, &c->dV_dbg, &t);
    m3_add_mul(&t, -h, &RFx, &c->dR_dbg, &c->dX_dbg);
    se23_m3_axpy(&c->dX_dba, dt, &c->dV_dba, &t);
    se23_m3_axpy(&t, h, dR, &c->dX_dba);
    m3_add_mul(&c->dV_dbg, -dt, &RFx, &c->dR_dbg, &c->dV_dbg);
    se23_m3_axpy(&c->dV_dba, dt, dR, &c->dV_dba);
    se23_m3_mul_tn(dR_k, &c->dR_dbg, &t);
    se23_m3_axpy(&t, dt, &Jr, &c->dR_dbg);
}

void se23_preint_classic_apply(const se23_preint_classic_t *c,
                               const se23_pose_t *delta,
                               const se23_vec3_t *dbg, const se23_vec3_t *dba,
                               se23_pose_t *out)
{
    se23_vec3_t phi, a, b;
    se23_so3_coeffs_t k;
    se23_mat3_t E;
    se23_m3_mul_v3(&c->dR_dbg, dbg, &phi);
    se23_so3_coeffs(se23_sqrt(se23_v3_dot(&phi, &phi)), &k);
    se23_m3_series(SE23_R(1), k.c1, k.c2, &phi, &E); /* exp(phi^) */
    se23_pose_t r;
    se23_m3_mul(&delta->R, &E, &r.R);
    se23_m3_mul_v3(&c->dV_dbg, dbg, &a);
    se23_m3_mul_v3(&c->dV_dba, dba, &b);
    se23_v3_axpy(&delta->v, SE23_R(1), &a, &r.v);
    se23_v3_axpy(&r.v, SE23_R(1), &b, &r.v);
    se23_m3_mul_v3(&c->dX_dbg, dbg, &a);
    se23_m3_mul_v3(&c->dX_dba, dba, &b);
    se23_v3_axpy(&delta->p, SE23_R(1), &a, &r.p);
    se23_v3_axpy(&r.p, SE23_R(1), &b, &r.p);
    *out = r;
}
