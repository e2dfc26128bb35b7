/*
 * Hand-written adapters for the gauss.h rows of tv_list.h (see tv_custom.c
 * for the contract). se23_gauss_t travels as T, b_g, b_a, n, P (15x15):
 * TV_GAUSS_REALS reals; n as a real; entries of P outside the leading n x n
 * block are reported as 0 (the library neither reads nor owes them).
 */
#include <string.h>

#include "tv.h"

#define N_SENTINEL (-12345)

static void take(const se23_real_t **in, void *dst, size_t bytes)
{
    memcpy(dst, *in, bytes);
    *in += bytes / sizeof(se23_real_t);
}
static se23_real_t take1(const se23_real_t **in) { return *(*in)++; }

static void take_gauss(const se23_real_t **in, se23_gauss_t *g)
{
    take(in, &g->T, sizeof g->T);
    take(in, &g->b_g, sizeof g->b_g);
    take(in, &g->b_a, sizeof g->b_a);
    g->n = (int)take1(in);
    take(in, &g->P, sizeof g->P);
}
static void fill_gauss(se23_gauss_t *g)
{
    tv_fill_sentinel(&g->T, sizeof g->T);
    tv_fill_sentinel(&g->b_g, sizeof g->b_g);
    tv_fill_sentinel(&g->b_a, sizeof g->b_a);
    tv_fill_sentinel(&g->P, sizeof g->P);
    g->n = N_SENTINEL;
}
static void give_gauss(se23_real_t *out, const se23_gauss_t *g)
{
    int i, j;
    memcpy(out, &g->T, sizeof g->T);
    out += TV_REALS(se23_pose_t);
    memcpy(out, &g->b_g, sizeof g->b_g);
    out += 3;
    memcpy(out, &g->b_a, sizeof g->b_a);
    out += 3;
    *out++ = g->n == N_SENTINEL ? TV_SENTINEL : (se23_real_t)g->n;
    for (i = 0; i < SE23_GAUSS_NMAX; ++i) {
        for (j = 0; j < SE23_GAUSS_NMAX; ++j) {
            const int inside = i < g->n && j < g->n;
            const se23_real_t x = g->P.m[SE23_GAUSS_NMAX * i + j];
            out[SE23_GAUSS_NMAX * i + j] = (g->n == N_SENTINEL || inside) ? x : TV_R(0);
        }
    }
}

static struct {
    se23_earth_model_t model;
    se23_gauss_t g, out;
    se23_pose_t U;
    se23_real_t dt;
    se23_tangent_t x, y;
    se23_mat9_t S, Q, F;
    se23_mat9x6_t X, B;
    se23_vec3_t w, f;
    se23_imu_sample_t s;
    se23_imu_noise_t noise;
    se23_input_jac_kind_t kind;
} c;

void tv_load_se23_gauss_fk_apply(const se23_real_t *in)
{
    take(&in, &c.U, sizeof c.U);
    c.dt = take1(&in);
    take(&in, &c.x, sizeof c.x);
    tv_fill_sentinel(&c.y, sizeof c.y);
}
int tv_call_se23_gauss_fk_apply(void)
{
    se23_gauss_fk_apply(&c.U, c.dt, &c.x, &c.y);
    return SE23_OK;
}
void tv_store_se23_gauss_fk_apply(se23_real_t *out) { memcpy(out, &c.y, sizeof c.y); }

void tv_load_se23_gauss_fk(const se23_real_t *in)
{
    take(&in, &c.U, sizeof c.U);
    c.dt = take1(&in);
    tv_fill_sentinel(&c.F, sizeof c.F);
}
int tv_call_se23_gauss_fk(void)
{
    se23_gauss_fk(&c.U, c.dt, &c.F);
    return SE23_OK;
}
void tv_store_se23_gauss_fk(se23_real_t *out) { memcpy(out, &c.F, sizeof c.F); }

void tv_load_se23_gauss_fk_mul(const se23_real_t *in)
{
    take(&in, &c.U, sizeof c.U);
    c.dt = take1(&in);
    take(&in, &c.X, sizeof c.X);
    tv_fill_sentinel(&c.B, sizeof c.B);
}
int tv_call_se23_gauss_fk_mul(void)
{
    se23_gauss_fk_mul(&c.U, c.dt, &c.X, &c.B);
    return SE23_OK;
}
void tv_store_se23_gauss_fk_mul(se23_real_t *out) { memcpy(out, &c.B, sizeof c.B); }

void tv_load_se23_gauss_input_jac(const se23_real_t *in)
{
    c.kind = (se23_input_jac_kind_t)(int)take1(&in);
    take(&in, &c.w, sizeof c.w);
    take(&in, &c.f, sizeof c.f);
    c.dt = take1(&in);
    tv_fill_sentinel(&c.B, sizeof c.B);
}
int tv_call_se23_gauss_input_jac(void)
{
    return (int)se23_gauss_input_jac(c.kind, &c.w, &c.f, c.dt, &c.B);
}
void tv_store_se23_gauss_input_jac(se23_real_t *out) { memcpy(out, &c.B, sizeof c.B); }

void tv_load_se23_gauss_input_noise(const se23_real_t *in)
{
    take(&in, &c.B, sizeof c.B);
    take(&in, &c.noise, sizeof c.noise);
    c.dt = take1(&in);
    tv_fill_sentinel(&c.Q, sizeof c.Q);
}
int tv_call_se23_gauss_input_noise(void)
{
    return (int)se23_gauss_input_noise(&c.B, &c.noise, c.dt, &c.Q);
}
void tv_store_se23_gauss_input_noise(se23_real_t *out) { memcpy(out, &c.Q, sizeof c.Q); }

void tv_load_se23_gauss_cov_propagate(const se23_real_t *in)
{
    take(&in, &c.S, sizeof c.S);
    take(&in, &c.U, sizeof c.U);
    c.dt = take1(&in);
    take(&in, &c.Q, sizeof c.Q);
    tv_fill_sentinel(&c.F, sizeof c.F);
}
int tv_call_se23_gauss_cov_propagate(void)
{
    return (int)se23_gauss_cov_propagate(&c.S, &c.U, c.dt, &c.Q, &c.F);
}
void tv_store_se23_gauss_cov_propagate(se23_real_t *out) { memcpy(out, &c.F, sizeof c.F); }

void tv_load_se23_gauss_check(const se23_real_t *in) { take_gauss(&in, &c.g); }
int tv_call_se23_gauss_check(void) { return (int)se23_gauss_check(&c.g); }
void tv_store_se23_gauss_check(se23_real_t *out) { (void)out; }

void tv_load_se23_gauss_propagate(const se23_real_t *in)
{
    take_gauss(&in, &c.g);
    take(&in, &c.U, sizeof c.U);
    take(&in, &c.B, sizeof c.B);
    take(&in, &c.noise, sizeof c.noise);
    c.dt = take1(&in);
    fill_gauss(&c.out);
}
int tv_call_se23_gauss_propagate(void)
{
    return (int)se23_gauss_propagate(&c.g, &c.U, &c.B, &c.noise, c.dt, &c.out);
}
void tv_store_se23_gauss_propagate(se23_real_t *out) { give_gauss(out, &c.out); }

void tv_load_se23_gauss_predict(const se23_real_t *in)
{
    take(&in, &c.model, sizeof c.model);
    take_gauss(&in, &c.g);
    take(&in, &c.s, sizeof c.s);
    take(&in, &c.noise, sizeof c.noise);
    c.kind = (se23_input_jac_kind_t)(int)take1(&in);
    fill_gauss(&c.out);
}
int tv_call_se23_gauss_predict(void)
{
    return (int)se23_gauss_predict(&c.model, &c.g, &c.s, &c.noise, c.kind, &c.out);
}
void tv_store_se23_gauss_predict(se23_real_t *out) { give_gauss(out, &c.out); }

void tv_load_se23_gauss_from_carried(const se23_real_t *in)
{
    take(&in, &c.model, sizeof c.model);
    take_gauss(&in, &c.g);
    fill_gauss(&c.out);
}
int tv_call_se23_gauss_from_carried(void)
{
    return (int)se23_gauss_from_carried(&c.model, &c.g, &c.out);
}
void tv_store_se23_gauss_from_carried(se23_real_t *out) { give_gauss(out, &c.out); }

void tv_load_se23_gauss_to_carried(const se23_real_t *in) { tv_load_se23_gauss_from_carried(in); }
int tv_call_se23_gauss_to_carried(void) { return (int)se23_gauss_to_carried(&c.model, &c.g, &c.out); }
void tv_store_se23_gauss_to_carried(se23_real_t *out) { give_gauss(out, &c.out); }

/* ---- kalman.h: se23_meas_t travels as m, z (9), H (9x15), R (9x9); rows
 * and entries beyond m are reported as 0 ---------------------------------- */

static struct {
    se23_meas_t y;
    se23_pose_t T;
    se23_vec3_t x, lever, w;
    se23_mat3_t cov; /* also se23_meas_nhc's C_bv */
    se23_real_t nis, sigma;
} k;

static void take_meas(const se23_real_t **in, se23_meas_t *y)
{
    y->m = (int)take1(in);
    take(in, y->z, sizeof y->z);
    take(in, y->H, sizeof y->H);
    take(in, y->R, sizeof y->R);
}
static void fill_meas(se23_meas_t *y)
{
    y->m = N_SENTINEL;
    tv_fill_sentinel(y->z, sizeof y->z);
    tv_fill_sentinel(y->H, sizeof y->H);
    tv_fill_sentinel(y->R, sizeof y->R);
}
static void give_meas(se23_real_t *out, const se23_meas_t *y)
{
    const int raw = y->m == N_SENTINEL;
    int i, j;
    *out++ = raw ? TV_SENTINEL : (se23_real_t)y->m;
    for (i = 0; i < SE23_MEAS_MMAX; ++i) {
        *out++ = (raw || i < y->m) ? y->z[i] : TV_R(0);
    }
    for (i = 0; i < SE23_MEAS_MMAX; ++i) {
        for (j = 0; j < SE23_GAUSS_NMAX; ++j) {
            *out++ = (raw || i < y->m) ? y->H[SE23_GAUSS_NMAX * i + j] : TV_R(0);
        }
    }
    for (i = 0; i < SE23_MEAS_MMAX; ++i) {
        for (j = 0; j < SE23_MEAS_MMAX; ++j) {
            *out++ = (raw || (i < y->m && j < y->m)) ? y->R[SE23_MEAS_MMAX * i + j] : TV_R(0);
        }
    }
}

static void load_meas_model(const se23_real_t *in, int lever)
{
    take(&in, &k.T, sizeof k.T);
    take(&in, &k.x, sizeof k.x);
    if (lever) {
        take(&in, &k.lever, sizeof k.lever);
    }
    take(&in, &k.cov, sizeof k.cov);
    fill_meas(&k.y);
}

void tv_load_se23_meas_pos_nav(const se23_real_t *in) { load_meas_model(in, 1); }
int tv_call_se23_meas_pos_nav(void) { return (int)se23_meas_pos_nav(&k.T, &k.x, &k.lever, &k.cov, &k.y); }
void tv_store_se23_meas_pos_nav(se23_real_t *out) { give_meas(out, &k.y); }

void tv_load_se23_meas_vel_nav(const se23_real_t *in) { load_meas_model(in, 0); }
int tv_call_se23_meas_vel_nav(void) { return (int)se23_meas_vel_nav(&k.T, &k.x, &k.cov, &k.y); }
void tv_store_se23_meas_vel_nav(se23_real_t *out) { give_meas(out, &k.y); }

void tv_load_se23_meas_vel_body(const se23_real_t *in) { load_meas_model(in, 0); }
int tv_call_se23_meas_vel_body(void) { return (int)se23_meas_vel_body(&k.T, &k.x, &k.cov, &k.y); }
void tv_store_se23_meas_vel_body(se23_real_t *out) { give_meas(out, &k.y); }

/* T, w_b, lever_b, v_n, cov (the argument order). */
void tv_load_se23_meas_vel_nav_lever(const se23_real_t *in)
{
    take(&in, &k.T, sizeof k.T);
    take(&in, &k.w, sizeof k.w);
    take(&in, &k.lever, sizeof k.lever);
    take(&in, &k.x, sizeof k.x);
    take(&in, &k.cov, sizeof k.cov);
    fill_meas(&k.y);
}
int tv_call_se23_meas_vel_nav_lever(void)
{
    return (int)se23_meas_vel_nav_lever(&k.T, &k.w, &k.lever, &k.x, &k.cov, &k.y);
}
void tv_store_se23_meas_vel_nav_lever(se23_real_t *out) { give_meas(out, &k.y); }

/* w_meas, b_g, cov. */
void tv_load_se23_meas_zero_rate(const se23_real_t *in)
{
    take(&in, &k.w, sizeof k.w);
    take(&in, &k.x, sizeof k.x);
    take(&in, &k.cov, sizeof k.cov);
    fill_meas(&k.y);
}
int tv_call_se23_meas_zero_rate(void) { return (int)se23_meas_zero_rate(&k.w, &k.x, &k.cov, &k.y); }
void tv_store_se23_meas_zero_rate(se23_real_t *out) { give_meas(out, &k.y); }

/* T, C_bv, sigma. */
void tv_load_se23_meas_nhc(const se23_real_t *in)
{
    take(&in, &k.T, sizeof k.T);
    take(&in, &k.cov, sizeof k.cov);
    k.sigma = take1(&in);
    fill_meas(&k.y);
}
int tv_call_se23_meas_nhc(void) { return (int)se23_meas_nhc(&k.T, &k.cov, k.sigma, &k.y); }
/* m, z[0..1], H's rows 0..1, R's leading 2 x 2 (tv_list.h). */
void tv_store_se23_meas_nhc(se23_real_t *out)
{
    int i, j;
    *out++ = k.y.m == N_SENTINEL ? TV_SENTINEL : (se23_real_t)k.y.m;
    for (i = 0; i < 2; ++i) {
        *out++ = k.y.z[i];
    }
    for (i = 0; i < 2 * SE23_GAUSS_NMAX; ++i) {
        *out++ = k.y.H[i];
    }
    for (i = 0; i < 2; ++i) {
        for (j = 0; j < 2; ++j) {
            *out++ = k.y.R[SE23_MEAS_MMAX * i + j];
        }
    }
}

void tv_load_se23_kalman_update(const se23_real_t *in)
{
    take_gauss(&in, &c.g);
    take_meas(&in, &k.y);
    fill_gauss(&c.out);
    k.nis = TV_SENTINEL;
}
int tv_call_se23_kalman_update(void) { return (int)se23_kalman_update(&c.g, &k.y, &c.out, &k.nis); }
void tv_store_se23_kalman_update(se23_real_t *out)
{
    give_gauss(out, &c.out);
    out[TV_GAUSS_REALS] = k.nis;
}
