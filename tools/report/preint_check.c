/* Preintegrated factors against the truth; see preint_check.h. */
#include "preint_check.h"

#include "../lcm/ldmath.h"

/* One factor f from truth a (at f.t0) to truth b (at f.t1): updates r. */
static void check_one(const se23lcm_sim_info *info, const se23lcm_preint_factor *f,
                      const se23lcm_truth *a, const se23lcm_truth *b, preint_check_t *r)
{
    ld_t dt = (ld_t)f->dt_s;
    ld_vec3_t g = ld_vec3_from(info->g_n), w = ld_vec3_from(info->w_ie_n);
    ld_vec3_t mw = ld_scale(&w, -dt);
    ld_mat3_t GR = ld_exp(&mw), GJ = ld_jl(&mw), GK = ld_k_series(&mw);
    ld_vec3_t Gv = ld_mul_v(&GJ, &g), Gx = ld_mul_v(&GK, &g);
    ld_mat3_t R0 = ld_mat3_from(a->R_nb), dR = ld_mat3_from(f->dR), R0dR, R1, E;
    ld_vec3_t p0 = ld_vec3_from(a->p_n), v0 = ld_vec3_from(a->v_n), wxp = ld_cross(&w, &p0);
    ld_vec3_t vc0 = ld_add(&v0, &wxp), dv = ld_vec3_from(f->dv), dp = ld_vec3_from(f->dp);
    ld_vec3_t Rdv = ld_mul_v(&R0, &dv), Rdp = ld_mul_v(&R0, &dp), vA, pA, vc1, p1, v1, e, t;
    int i;
    Gv = ld_scale(&Gv, dt);
    Gx = ld_scale(&Gx, dt * dt);
    R0dR = ld_mul(&R0, &dR);
    R1 = ld_mul(&GR, &R0dR);
    vA = ld_add(&Rdv, &vc0); /* Phi_dt(T'_0) Delta */
    for (i = 0; i < 3; i++) {
        pA.v[i] = Rdp.v[i] + p0.v[i] + dt * vc0.v[i];
    }
    vc1 = ld_mul_v(&GR, &vA); /* Gamma' (...) */
    vc1 = ld_add(&vc1, &Gv);
    p1 = ld_mul_v(&GR, &pA);
    p1 = ld_add(&p1, &Gx);
    wxp = ld_cross(&w, &p1);
    v1 = ld_sub(&vc1, &wxp);
    t = ld_vec3_from(b->p_n);
    e = ld_sub(&p1, &t);
    if ((double)ld_norm(&e) > r->max_pos_err) {
        r->max_pos_err = (double)ld_norm(&e);
    }
    t = ld_vec3_from(b->v_n);
    e = ld_sub(&v1, &t);
    if ((double)ld_norm(&e) > r->max_vel_err) {
        r->max_vel_err = (double)ld_norm(&e);
    }
    {
        ld_mat3_t Rb = ld_mat3_from(b->R_nb);
        E = ld_mul_tn(&R1, &Rb);
    }
    e = ld_log(&E);
    if ((double)ld_norm(&e) > r->max_att_err) {
        r->max_att_err = (double)ld_norm(&e);
    }
    r->n_checked++;
}

void preint_check(const log_data_t *d, preint_check_t *r)
{
    size_t i;
    r->n_checked = 0;
    r->max_pos_err = r->max_vel_err = r->max_att_err = 0.0;
    if (!d->have_info) {
        return;
    }
    for (i = 0; i < d->n_preint_stored; i++) {
        long a = log_find_truth(d, d->preint[i].t0_ns);
        long b = log_find_truth(d, d->preint[i].t1_ns);
        if (a >= 0 && b >= 0) {
            check_one(&d->info, &d->preint[i], &d->truth[a], &d->truth[b], r);
        }
    }
}
