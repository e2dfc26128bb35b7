/*
 * Hand-written adapters (tv_load_<fn>, tv_call_<fn>, tv_store_<fn>) for the
 * TV_CUSTOM rows of tv_list.h: routines with scalar or enum arguments, three
 * or more inputs, or structs that are not all reals. Same contract as the
 * generic adapters (tv.h): load unpacks the input row in argument order and
 * fills the outputs with TV_SENTINEL; store packs the outputs. Enums and
 * counters travel as reals in the rows.
 */
#include <string.h>

#include "tv.h"

/* Copies the next bytes/sizeof(real) reals of a row into dst. */
static void take(const se23_real_t **in, void *dst, size_t bytes)
{
    memcpy(dst, *in, bytes);
    *in += bytes / sizeof(se23_real_t);
}
static se23_real_t take1(const se23_real_t **in) { return *(*in)++; }
static void give(se23_real_t **out, const void *src, size_t bytes)
{
    memcpy(*out, src, bytes);
    *out += bytes / sizeof(se23_real_t);
}

/* ---- earth.h ---------------------------------------------------------------- */

static struct {
    se23_frame_t frame;
    se23_real_t lat, h, t, dt, dt_max, g;
    se23_vec3_t g_n, w_ie_n, out;
    se23_pose_t gamma;
    se23_earth_model_t model;
} e;

static void e_clear(void)
{
    tv_fill_sentinel(&e.g, sizeof e.g);
    tv_fill_sentinel(&e.out, sizeof e.out);
    tv_fill_sentinel(&e.gamma, sizeof e.gamma);
    tv_fill_sentinel(&e.model, sizeof e.model);
}

void tv_load_se23_earth_gravity(const se23_real_t *in)
{
    e.lat = take1(&in);
    e.h = take1(&in);
    e_clear();
}
int tv_call_se23_earth_gravity(void) { return (int)se23_earth_gravity(e.lat, e.h, &e.g); }
void tv_store_se23_earth_gravity(se23_real_t *out) { out[0] = e.g; }

void tv_load_se23_earth_gravity_vec(const se23_real_t *in)
{
    e.frame = (se23_frame_t)(int)take1(&in);
    e.lat = take1(&in);
    e.h = take1(&in);
    e_clear();
}
int tv_call_se23_earth_gravity_vec(void)
{
    return (int)se23_earth_gravity_vec(e.frame, e.lat, e.h, &e.out);
}
void tv_store_se23_earth_gravity_vec(se23_real_t *out) { give(&out, &e.out, sizeof e.out); }

void tv_load_se23_earth_rate(const se23_real_t *in)
{
    e.frame = (se23_frame_t)(int)take1(&in);
    e.lat = take1(&in);
    e_clear();
}
int tv_call_se23_earth_rate(void) { return (int)se23_earth_rate(e.frame, e.lat, &e.out); }
void tv_store_se23_earth_rate(se23_real_t *out) { give(&out, &e.out, sizeof e.out); }

void tv_load_se23_earth_gamma(const se23_real_t *in)
{
    take(&in, &e.g_n, sizeof e.g_n);
    take(&in, &e.w_ie_n, sizeof e.w_ie_n);
    e.t = take1(&in);
    e_clear();
}
int tv_call_se23_earth_gamma(void) { return (int)se23_earth_gamma(&e.g_n, &e.w_ie_n, e.t, &e.gamma); }
void tv_store_se23_earth_gamma(se23_real_t *out) { give(&out, &e.gamma, sizeof e.gamma); }

void tv_load_se23_earth_model_init(const se23_real_t *in)
{
    take(&in, &e.g_n, sizeof e.g_n);
    take(&in, &e.w_ie_n, sizeof e.w_ie_n);
    e.dt = take1(&in);
    e.dt_max = take1(&in);
    e_clear();
}
int tv_call_se23_earth_model_init(void)
{
    return (int)se23_earth_model_init(&e.g_n, &e.w_ie_n, e.dt, e.dt_max, &e.model);
}
void tv_store_se23_earth_model_init(se23_real_t *out) { give(&out, &e.model, sizeof e.model); }

void tv_load_se23_earth_model_init_wgs84(const se23_real_t *in)
{
    e.frame = (se23_frame_t)(int)take1(&in);
    e.lat = take1(&in);
    e.h = take1(&in);
    e.dt = take1(&in);
    e.dt_max = take1(&in);
    e_clear();
}
int tv_call_se23_earth_model_init_wgs84(void)
{
    return (int)se23_earth_model_init_wgs84(e.frame, e.lat, e.h, e.dt, e.dt_max, &e.model);
}
void tv_store_se23_earth_model_init_wgs84(se23_real_t *out)
{
    give(&out, &e.model, sizeof e.model);
}

/* ---- imu.h ------------------------------------------------------------------ */

static struct {
    se23_earth_model_t model;
    se23_pose_t gamma, T, ups, out;
    se23_imu_sample_t s;
    se23_real_t t;
} m;

void tv_load_se23_imu_transition(const se23_real_t *in)
{
    take(&in, &m.gamma, sizeof m.gamma);
    take(&in, &m.T, sizeof m.T);
    take(&in, &m.ups, sizeof m.ups);
    m.t = take1(&in);
    tv_fill_sentinel(&m.out, sizeof m.out);
}
int tv_call_se23_imu_transition(void)
{
    se23_imu_transition(&m.gamma, &m.T, &m.ups, m.t, &m.out);
    return SE23_OK;
}
void tv_store_se23_imu_transition(se23_real_t *out) { give(&out, &m.out, sizeof m.out); }

void tv_load_se23_imu_step(const se23_real_t *in)
{
    take(&in, &m.model, sizeof m.model);
    take(&in, &m.T, sizeof m.T);
    take(&in, &m.s, sizeof m.s);
    tv_fill_sentinel(&m.out, sizeof m.out);
}
int tv_call_se23_imu_step(void) { return (int)se23_imu_step(&m.model, &m.T, &m.s, &m.out); }
void tv_store_se23_imu_step(se23_real_t *out) { give(&out, &m.out, sizeof m.out); }

/* ---- preint.h: se23_preint_t travels as delta, dt, n ---------------------- */

static struct {
    se23_earth_model_t model;
    se23_preint_t f;
    se23_imu_sample_t s;
    se23_pose_t ups, T, out;
    se23_real_t dt;
} p;

static void take_preint(const se23_real_t **in, se23_preint_t *f)
{
    take(in, &f->delta, sizeof f->delta);
    f->dt = take1(in);
    f->n = (uint32_t)take1(in);
}
static void fill_preint(se23_preint_t *f)
{
    tv_fill_sentinel(&f->delta, sizeof f->delta);
    f->dt = TV_SENTINEL;
    f->n = 0xFFFFFFFFu;
}
static void give_preint(se23_real_t *out, const se23_preint_t *f)
{
    give(&out, &f->delta, sizeof f->delta);
    out[0] = f->dt;
    out[1] = f->n == 0xFFFFFFFFu ? TV_SENTINEL : (se23_real_t)f->n;
}

void tv_load_se23_preint_reset(const se23_real_t *in)
{
    (void)in;
    fill_preint(&p.f);
}
int tv_call_se23_preint_reset(void)
{
    se23_preint_reset(&p.f);
    return SE23_OK;
}
void tv_store_se23_preint_reset(se23_real_t *out) { give_preint(out, &p.f); }

/* se23_preint_add updates f in place; on error f must be unchanged, which
 * the runner cannot see through the sentinel: store reports the sentinel
 * unless f changed. */
static se23_preint_t preint_before;
void tv_load_se23_preint_add(const se23_real_t *in)
{
    take_preint(&in, &p.f);
    take(&in, &p.s, sizeof p.s);
    preint_before = p.f;
}
int tv_call_se23_preint_add(void) { return (int)se23_preint_add(&p.f, &p.s); }
void tv_store_se23_preint_add(se23_real_t *out)
{
    se23_preint_t f = p.f;
    if (memcmp(&f, &preint_before, sizeof f) == 0) {
        fill_preint(&f);
    }
    give_preint(out, &f);
}

void tv_load_se23_preint_add_increment(const se23_real_t *in)
{
    take_preint(&in, &p.f);
    take(&in, &p.ups, sizeof p.ups);
    p.dt = take1(&in);
}
int tv_call_se23_preint_add_increment(void)
{
    se23_preint_add_increment(&p.f, &p.ups, p.dt);
    return SE23_OK;
}
void tv_store_se23_preint_add_increment(se23_real_t *out) { give_preint(out, &p.f); }

void tv_load_se23_preint_predict(const se23_real_t *in)
{
    take(&in, &p.model, sizeof p.model);
    take_preint(&in, &p.f);
    take(&in, &p.T, sizeof p.T);
    tv_fill_sentinel(&p.out, sizeof p.out);
}
int tv_call_se23_preint_predict(void) { return (int)se23_preint_predict(&p.model, &p.f, &p.T, &p.out); }
void tv_store_se23_preint_predict(se23_real_t *out) { give(&out, &p.out, sizeof p.out); }

void tv_load_se23_preint_predict_carried(const se23_real_t *in) { tv_load_se23_preint_predict(in); }
int tv_call_se23_preint_predict_carried(void)
{
    return (int)se23_preint_predict_carried(&p.model, &p.f, &p.T, &p.out);
}
void tv_store_se23_preint_predict_carried(se23_real_t *out) { give(&out, &p.out, sizeof p.out); }

/* ---- preint_unc.h: se23_preint_unc_t travels as TV_PREINT_UNC_REALS reals
 * (f, b_g, b_a, kind, P_left, J_left, classical Jacobians) -------------------------- */

#define KIND_SENTINEL ((se23_input_jac_kind_t)-7)
#define CLASSIC_SENTINEL (-7)

static struct {
    se23_preint_unc_t fu, before;
    se23_imu_sample_t s;
    se23_imu_noise_t noise;
    se23_vec3_t b_g, b_a;
    se23_input_jac_kind_t kind;
    se23_preint_t out;
    se23_mat9_t P;
    se23_mat9x6_t J;
} u;

static void take_unc(const se23_real_t **in, se23_preint_unc_t *fu)
{
    take_preint(in, &fu->f);
    take(in, &fu->b_g, sizeof fu->b_g);
    take(in, &fu->b_a, sizeof fu->b_a);
    fu->kind = (se23_input_jac_kind_t)(int)take1(in);
    fu->classic = (int)take1(in);
    take(in, &fu->P_left, sizeof fu->P_left);
    take(in, &fu->J_left, sizeof fu->J_left);
    take(in, &fu->cl, sizeof fu->cl);
}
static void give_unc(se23_real_t *out, const se23_preint_unc_t *fu)
{
    give_preint(out, &fu->f);
    out += TV_PREINT_REALS;
    give(&out, &fu->b_g, sizeof fu->b_g);
    give(&out, &fu->b_a, sizeof fu->b_a);
    *out++ = fu->kind == KIND_SENTINEL ? TV_SENTINEL : (se23_real_t)fu->kind;
    *out++ = fu->classic == CLASSIC_SENTINEL ? TV_SENTINEL : (se23_real_t)fu->classic;
    give(&out, &fu->P_left, sizeof fu->P_left);
    give(&out, &fu->J_left, sizeof fu->J_left);
    give(&out, &fu->cl, sizeof fu->cl);
}
static void fill_unc(se23_preint_unc_t *fu)
{
    fill_preint(&fu->f);
    tv_fill_sentinel(&fu->b_g, sizeof fu->b_g);
    tv_fill_sentinel(&fu->b_a, sizeof fu->b_a);
    fu->kind = KIND_SENTINEL;
    fu->classic = CLASSIC_SENTINEL;
    tv_fill_sentinel(&fu->P_left, sizeof fu->P_left);
    tv_fill_sentinel(&fu->J_left, sizeof fu->J_left);
    tv_fill_sentinel(&fu->cl, sizeof fu->cl);
}

void tv_load_se23_preint_unc_reset(const se23_real_t *in)
{
    take(&in, &u.b_g, sizeof u.b_g);
    take(&in, &u.b_a, sizeof u.b_a);
    u.kind = (se23_input_jac_kind_t)(int)take1(&in);
    fill_unc(&u.fu);
}
int tv_call_se23_preint_unc_reset(void)
{
    return (int)se23_preint_unc_reset(&u.b_g, &u.b_a, u.kind, &u.fu);
}
void tv_store_se23_preint_unc_reset(se23_real_t *out) { give_unc(out, &u.fu); }

void tv_load_se23_preint_unc_reset_classic(const se23_real_t *in)
{
    tv_load_se23_preint_unc_reset(in);
}
int tv_call_se23_preint_unc_reset_classic(void)
{
    return (int)se23_preint_unc_reset_classic(&u.b_g, &u.b_a, u.kind, &u.fu);
}
void tv_store_se23_preint_unc_reset_classic(se23_real_t *out) { give_unc(out, &u.fu); }

/* In-place update: on error the factor must be unchanged; store reports the
 * sentinel unless it changed (as for se23_preint_add). */
void tv_load_se23_preint_unc_add(const se23_real_t *in)
{
    take_unc(&in, &u.fu);
    take(&in, &u.s, sizeof u.s);
    take(&in, &u.noise, sizeof u.noise);
    u.before = u.fu;
}
int tv_call_se23_preint_unc_add(void) { return (int)se23_preint_unc_add(&u.fu, &u.s, &u.noise); }
void tv_store_se23_preint_unc_add(se23_real_t *out)
{
    se23_preint_unc_t fu = u.fu;
    if (memcmp(&fu, &u.before, sizeof fu) == 0) {
        fill_unc(&fu);
    }
    give_unc(out, &fu);
}

void tv_load_se23_preint_unc_check(const se23_real_t *in) { take_unc(&in, &u.fu); }
int tv_call_se23_preint_unc_check(void) { return (int)se23_preint_unc_check(&u.fu); }
void tv_store_se23_preint_unc_check(se23_real_t *out) { (void)out; }

void tv_load_se23_preint_unc_correct(const se23_real_t *in)
{
    take_unc(&in, &u.fu);
    take(&in, &u.b_g, sizeof u.b_g);
    take(&in, &u.b_a, sizeof u.b_a);
    fill_preint(&u.out);
}
int tv_call_se23_preint_unc_correct(void)
{
    return (int)se23_preint_unc_correct(&u.fu, &u.b_g, &u.b_a, &u.out);
}
void tv_store_se23_preint_unc_correct(se23_real_t *out) { give_preint(out, &u.out); }

void tv_load_se23_preint_unc_correct_classic(const se23_real_t *in)
{
    tv_load_se23_preint_unc_correct(in);
}
int tv_call_se23_preint_unc_correct_classic(void)
{
    return (int)se23_preint_unc_correct_classic(&u.fu, &u.b_g, &u.b_a, &u.out);
}
void tv_store_se23_preint_unc_correct_classic(se23_real_t *out) { give_preint(out, &u.out); }

void tv_load_se23_preint_unc_cov(const se23_real_t *in)
{
    take_unc(&in, &u.fu);
    tv_fill_sentinel(&u.P, sizeof u.P);
    tv_fill_sentinel(&u.J, sizeof u.J);
}
int tv_call_se23_preint_unc_cov(void) { return (int)se23_preint_unc_cov(&u.fu, &u.P, &u.J); }
void tv_store_se23_preint_unc_cov(se23_real_t *out)
{
    give(&out, &u.P, sizeof u.P);
    give(&out, &u.J, sizeof u.J);
}

/* ---- stationary.h: a row holds the configuration (window as a real), k and
 * TV_ST_SAMPLES samples (w, f); the j-th add uses sample j mod TV_ST_SAMPLES.
 * load runs init and the adds before the call under test (an add that
 * fails stores nothing; the generator replays the same sequence) -------- */

static struct {
    se23_stationary_config_t cfg;
    se23_stationary_t d, before;
    se23_vec3_t w[TV_ST_SAMPLES], f[TV_ST_SAMPLES];
    se23_vec3_t a, b;
    int k, flag;
} st;

static void take_st_cfg(const se23_real_t **in, se23_stationary_config_t *c)
{
    c->window = (int)take1(in);
    c->sigma_a = take1(in);
    c->sigma_g = take1(in);
    c->gravity = take1(in);
    c->threshold = take1(in);
}
/* cfg, k and the samples of a row; then init. */
static void take_st(const se23_real_t *in)
{
    int j;
    take_st_cfg(&in, &st.cfg);
    st.k = (int)take1(&in);
    for (j = 0; j < TV_ST_SAMPLES; ++j) {
        take(&in, &st.w[j], sizeof st.w[j]);
        take(&in, &st.f[j], sizeof st.f[j]);
    }
    memset(&st.d, 0, sizeof st.d);
    (void)se23_stationary_init(&st.cfg, &st.d);
}
/* The adds 0..n-1 of the row's sequence. */
static void st_adds(int n)
{
    int j;
    for (j = 0; j < n; ++j) {
        (void)se23_stationary_add(&st.d, &st.w[j % TV_ST_SAMPLES], &st.f[j % TV_ST_SAMPLES],
                                  NULL);
    }
}
/* cfg, count, head, stat, stationary; the sentinel where init wrote nothing. */
static void give_st_state(se23_real_t *out, const se23_stationary_t *d)
{
    int unwritten = d->cfg.window == -7;
    out[0] = unwritten ? TV_SENTINEL : (se23_real_t)d->cfg.window;
    out[1] = d->cfg.sigma_a;
    out[2] = d->cfg.sigma_g;
    out[3] = d->cfg.gravity;
    out[4] = d->cfg.threshold;
    out[5] = unwritten ? TV_SENTINEL : (se23_real_t)d->count;
    out[6] = unwritten ? TV_SENTINEL : (se23_real_t)d->head;
    out[7] = d->stat;
    out[8] = unwritten ? TV_SENTINEL : (se23_real_t)d->stationary;
}

void tv_load_se23_stationary_init(const se23_real_t *in)
{
    take_st_cfg(&in, &st.cfg);
    tv_fill_sentinel(&st.d.cfg.sigma_a, 4 * sizeof(se23_real_t));
    st.d.cfg.window = -7;
    st.d.stat = TV_SENTINEL;
}
int tv_call_se23_stationary_init(void) { return (int)se23_stationary_init(&st.cfg, &st.d); }
void tv_store_se23_stationary_init(se23_real_t *out) { give_st_state(out, &st.d); }

/* In-place update: on error the detector must be unchanged; store reports
 * the sentinel unless it changed (as for se23_preint_add). */
void tv_load_se23_stationary_add(const se23_real_t *in)
{
    take_st(in);
    st_adds(st.k - 1);
    memcpy(&st.before, &st.d, sizeof st.d);
    st.flag = -7;
}
int tv_call_se23_stationary_add(void)
{
    const int j = (st.k - 1) % TV_ST_SAMPLES;
    return (int)se23_stationary_add(&st.d, &st.w[j], &st.f[j], &st.flag);
}
void tv_store_se23_stationary_add(se23_real_t *out)
{
    const int same = memcmp(&st.d, &st.before, sizeof st.d) == 0;
    out[0] = same ? TV_SENTINEL : st.d.stat;
    out[1] = same ? TV_SENTINEL : (se23_real_t)st.d.stationary;
    out[2] = st.flag == -7 ? TV_SENTINEL : (se23_real_t)st.flag;
    out[3] = same ? TV_SENTINEL : (se23_real_t)st.d.count;
    out[4] = same ? TV_SENTINEL : (se23_real_t)st.d.head;
}

void tv_load_se23_stationary_reset(const se23_real_t *in)
{
    take_st_cfg(&in, &st.cfg);
    st.k = (int)take1(&in);
    take(&in, &st.w[0], sizeof st.w[0]);
    take(&in, &st.f[0], sizeof st.f[0]);
    memset(&st.d, 0, sizeof st.d);
    (void)se23_stationary_init(&st.cfg, &st.d);
    {
        int j;
        for (j = 0; j < st.k; ++j) {
            (void)se23_stationary_add(&st.d, &st.w[0], &st.f[0], NULL);
        }
    }
}
int tv_call_se23_stationary_reset(void)
{
    se23_stationary_reset(&st.d);
    return SE23_OK;
}
void tv_store_se23_stationary_reset(se23_real_t *out) { give_st_state(out, &st.d); }

void tv_load_se23_stationary_mean(const se23_real_t *in)
{
    take_st(in);
    st_adds(st.k);
    tv_fill_sentinel(&st.a, sizeof st.a);
    tv_fill_sentinel(&st.b, sizeof st.b);
}
int tv_call_se23_stationary_mean(void) { return (int)se23_stationary_mean(&st.d, &st.a, &st.b); }
void tv_store_se23_stationary_mean(se23_real_t *out)
{
    give(&out, &st.a, sizeof st.a);
    give(&out, &st.b, sizeof st.b);
}

void tv_load_se23_stationary_var(const se23_real_t *in) { tv_load_se23_stationary_mean(in); }
int tv_call_se23_stationary_var(void) { return (int)se23_stationary_var(&st.d, &st.a, &st.b); }
void tv_store_se23_stationary_var(se23_real_t *out) { tv_store_se23_stationary_mean(out); }

/* ---- align.h ------------------------------------------------------------ */

static struct {
    se23_frame_t frame;
    se23_vec3_t f, w;
    se23_real_t yaw, lat, sigma_f, g, sigma_yaw, sigma_w, yaw_out, sigma_out;
    int n;
    se23_mat3_t R, P;
} al;

void tv_load_se23_align_level(const se23_real_t *in)
{
    al.frame = (se23_frame_t)(int)take1(&in);
    take(&in, &al.f, sizeof al.f);
    al.yaw = take1(&in);
    tv_fill_sentinel(&al.R, sizeof al.R);
}
int tv_call_se23_align_level(void) { return (int)se23_align_level(al.frame, &al.f, al.yaw, &al.R); }
void tv_store_se23_align_level(se23_real_t *out) { give(&out, &al.R, sizeof al.R); }

void tv_load_se23_align_cov(const se23_real_t *in)
{
    take(&in, &al.R, sizeof al.R);
    al.sigma_f = take1(&in);
    al.n = (int)take1(&in);
    al.g = take1(&in);
    al.sigma_yaw = take1(&in);
    tv_fill_sentinel(&al.P, sizeof al.P);
}
int tv_call_se23_align_cov(void)
{
    return (int)se23_align_cov(&al.R, al.sigma_f, al.n, al.g, al.sigma_yaw, &al.P);
}
void tv_store_se23_align_cov(se23_real_t *out) { give(&out, &al.P, sizeof al.P); }

void tv_load_se23_align_gyrocompass(const se23_real_t *in)
{
    al.frame = (se23_frame_t)(int)take1(&in);
    al.lat = take1(&in);
    take(&in, &al.f, sizeof al.f);
    take(&in, &al.w, sizeof al.w);
    al.sigma_w = take1(&in);
    al.n = (int)take1(&in);
    tv_fill_sentinel(&al.R, sizeof al.R);
    al.yaw_out = TV_SENTINEL;
    al.sigma_out = TV_SENTINEL;
}
int tv_call_se23_align_gyrocompass(void)
{
    return (int)se23_align_gyrocompass(al.frame, al.lat, &al.f, &al.w, al.sigma_w, al.n, &al.R,
                                       &al.yaw_out, &al.sigma_out);
}
void tv_store_se23_align_gyrocompass(se23_real_t *out)
{
    give(&out, &al.R, sizeof al.R);
    out[0] = al.yaw_out;
    out[1] = al.sigma_out;
}
