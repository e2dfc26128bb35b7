/*
 * Benchmarked operations that are not rows of tests/target/tv_list.h (see
 * bench_steps.h), i.e. composite steps and the navigation filter's calls
 * per sample: one shared, realistic setup -- a 200 Hz IMU sample on the
 * rotating Earth (WGS-84, NED, latitude 0.8 rad), a moving pose, a
 * covariance with and without bias states, a GNSS fix -- and one small
 * function per operation. Adding an operation: one function and one row of bench_steps[].
 * When a routine gains reference vectors (a row of tv_list.h), drop its row
 * here: the benchmark runs every tv_list.h row by itself.
 */
#include <string.h>

#include "bench_steps.h"
#include "se23/earth.h"
#include "se23/gauss.h"
#include "se23/imu.h"
#include "se23/ins.h"
#include "se23/kalman.h"
#include "se23/preint_unc.h"
#include "se23/so3.h"

/* internal: the filter's structured NHC update (no -Isrc in the target's
 * flags) */
#include "../../src/kalman/kalman_nhc.h"

static struct {
    se23_earth_model_t model;
    se23_imu_sample_t s;
    se23_imu_noise_t noise;
    se23_pose_t T;
    se23_gauss_t g9, g15, gout;
    se23_preint_unc_t factor;
    se23_meas_t y;
    se23_vec3_t p_gnss, lever;
    se23_mat3_t cov, C_bv;
    se23_nhc_meas_t nhc;
    se23_kalman_work_t wk;
} c;

static void set_gauss(se23_gauss_t *g, int n)
{
    int i;
    memset(g, 0, sizeof *g);
    g->T = c.T;
    g->b_g.v[0] = SE23_R(1e-4);
    g->b_a.v[2] = SE23_R(-2e-2);
    g->n = n;
    for (i = 0; i < n; ++i) {
        g->P.m[SE23_GAUSS_NMAX * i + i] = (i < 3) ? SE23_R(1e-4) : SE23_R(1e-2);
    }
    g->P.m[SE23_GAUSS_NMAX * 0 + 4] = SE23_R(1e-6);
    g->P.m[SE23_GAUSS_NMAX * 4 + 0] = SE23_R(1e-6);
}

static void setup(void)
{
    const se23_vec3_t phi = {{SE23_R(0.3), SE23_R(0.2), SE23_R(-0.5)}};
    int i;
    memset(&c, 0, sizeof c);
    (void)se23_earth_model_init_wgs84(SE23_FRAME_NED, SE23_R(0.8), SE23_R(100), SE23_R(0.005),
                                      SE23_R(0.02), &c.model);
    c.s.w_ib_b.v[0] = SE23_R(0.1);
    c.s.w_ib_b.v[1] = SE23_R(-0.2);
    c.s.w_ib_b.v[2] = SE23_R(0.3);
    c.s.f_b.v[0] = SE23_R(0.3);
    c.s.f_b.v[1] = SE23_R(-0.2);
    c.s.f_b.v[2] = SE23_R(-9.8);
    c.s.dt = SE23_R(0.005);
    c.noise.gyro_noise = SE23_R(1e-4);
    c.noise.accel_noise = SE23_R(1e-3);
    c.noise.gyro_walk = SE23_R(1e-6);
    c.noise.accel_walk = SE23_R(1e-5);
    (void)se23_so3_exp(&phi, &c.T.R);
    {
        const se23_vec3_t mount = {{SE23_R(0.1), SE23_R(-0.12), SE23_R(1.6)}};
        (void)se23_so3_exp(&mount, &c.C_bv);
    }
    c.T.v.v[0] = SE23_R(10);
    c.T.v.v[1] = SE23_R(1);
    c.T.p.v[0] = SE23_R(100);
    c.T.p.v[2] = SE23_R(-20);
    set_gauss(&c.g9, SE23_GAUSS_N_POSE);
    set_gauss(&c.g15, SE23_GAUSS_N_BIAS);
    for (i = 0; i < 3; ++i) {
        c.p_gnss.v[i] = c.T.p.v[i] + SE23_R(0.5);
        c.lever.v[i] = SE23_R(0.1) * (se23_real_t)(i + 1);
        c.cov.m[i][i] = SE23_R(4.0);
    }
    (void)se23_preint_unc_reset(&c.g15.b_g, &c.g15.b_a, SE23_INPUT_JAC_EXACT, &c.factor);
    for (i = 0; i < 20; ++i) {
        (void)se23_preint_unc_add(&c.factor, &c.s, &c.noise);
    }
}

/* Composite: one full propagation step (mean + covariance), rotating Earth. */
static int step_cov9(void)
{
    return (int)se23_gauss_predict(&c.model, &c.g9, &c.s, &c.noise, SE23_INPUT_JAC_EXACT, &c.gout);
}
static int step_cov15(void)
{
    return (int)se23_gauss_predict(&c.model, &c.g15, &c.s, &c.noise, SE23_INPUT_JAC_EXACT, &c.gout);
}
/* Composite: one GNSS position update (model + Kalman update), n = 15. */
static int update_gnss15(void)
{
    se23_status_t st = se23_meas_pos_nav(&c.g15.T, &c.p_gnss, &c.lever, &c.cov, &c.y);
    return st != SE23_OK ? (int)st : (int)se23_kalman_update(&c.g15, &c.y, &c.gout, NULL);
}
/* Composite: one non-holonomic constraint update (model + Kalman update,
 * 2 rows), n = 15, the IMU mounted turned (C_bv = exp of 0.1, -0.12, 1.6). */
static int update_nhc15(void)
{
    se23_status_t st = se23_meas_nhc(&c.g15.T, &c.C_bv, SE23_R(0.3), &c.y);
    return st != SE23_OK ? (int)st : (int)se23_kalman_update(&c.g15, &c.y, &c.gout, NULL);
}
/* The same update on the filter's path (ins_aid.c, se23_ins_nhc): the rows
 * without se23_meas_nhc's checks and the structured 2-row update
 * (kalman_nhc.c), the work area the filter's. */
static int update_nhc15_structured(void)
{
    se23_nhc_rows(&c.g15.T, &c.C_bv, SE23_R(0.3), &c.nhc);
    return (int)se23_kalman_nhc(&c.g15, &c.nhc, &c.wk, &c.gout, NULL);
}
/* Composite: one sample into a preintegrated factor (Deltas, P, J; no
 * classical Jacobians), 20 samples in. */
static int step_preint(void)
{
    return (int)se23_preint_unc_add(&c.factor, &c.s, &c.noise);
}
static int step_cov15_basic(void)
{
    return (int)se23_gauss_predict(&c.model, &c.g15, &c.s, &c.noise, SE23_INPUT_JAC_BASIC, &c.gout);
}

/* ---- the navigation filter (se23/ins.h): one call of se23_ins_imu or
 * se23_ins_gnss on a filter set up with 15 states on rotating Earth at the
 * same latitude, initialised at the shared state and fed FEED samples
 * first (outside the measured region), without the delayed-fix ring and
 * the preintegrated factor (delay_horizon = preint_window = 0), so that a
 * row is the per-sample cost alone. */

static se23_ins_t ins; /* large (about 20 kB in double): static */
static int64_t ins_t_ns, ins_seq;
static se23_ins_gnss_t ins_fix;
#define INS_DT_NS 5000000LL /* 200 Hz */
#define FEED 25             /* > the detector's window of 20 */

static void ins_config(se23_ins_config_t *cfg, int zupt, se23_real_t zaru_after)
{
    memset(cfg, 0, sizeof *cfg);
    cfg->noise = c.noise;
    cfg->gyro_range = SE23_R(30);
    cfg->accel_range = SE23_R(150);
    cfg->lat = SE23_R(0.8);
    cfg->earth_rotation = 1;
    cfg->bias_states = 1;
    cfg->dt_nominal = SE23_R(0.005);
    cfg->max_gap = SE23_R(0.05);
    cfg->max_outage = SE23_R(10);
    cfg->outage_accel = SE23_R(1);
    cfg->outage_rate = SE23_R(0.05);
    cfg->lever_b = c.lever;
    cfg->gnss_gate = SE23_R(30);
    cfg->gate_recover = 5;
    cfg->zupt = zupt;
    cfg->detector.window = 20;
    cfg->detector.sigma_a = SE23_R(0.02);
    cfg->detector.sigma_g = SE23_R(2e-3);
    (void)se23_earth_gravity(cfg->lat, SE23_R(0), &cfg->detector.gravity);
    cfg->detector.threshold = SE23_R(12);
    cfg->zupt_sigma_v = SE23_R(0.01);
    cfg->zaru_sigma_w = SE23_R(1e-3);
    cfg->zaru_after = zaru_after;
}

/* The readings of a body at rest with the filter's state: w = R^T Omega -
 * b_g, f = -R^T g - b_a (measured = true - bias, gauss.h). */
static void rest_sample(se23_vec3_t *w, se23_vec3_t *f)
{
    const se23_gauss_t *g = &ins.g;
    int i;
    for (i = 0; i < 3; ++i) {
        w->v[i] = g->T.R.m[0][i] * ins.model.w_ie_n.v[0] + g->T.R.m[1][i] * ins.model.w_ie_n.v[1] +
                  g->T.R.m[2][i] * ins.model.w_ie_n.v[2] - g->b_g.v[i];
        f->v[i] = -(g->T.R.m[0][i] * ins.model.g_n.v[0] + g->T.R.m[1][i] * ins.model.g_n.v[1] +
                    g->T.R.m[2][i] * ins.model.g_n.v[2]) - g->b_a.v[i];
    }
}

/* The next sample: at rest, or the shared moving sample c.s. */
static se23_ins_verdict_t ins_next(int rest)
{
    se23_vec3_t w = c.s.w_ib_b, f = c.s.f_b;
    if (rest != 0) {
        rest_sample(&w, &f);
    }
    ins_t_ns += INS_DT_NS;
    ins_seq += 1;
    return se23_ins_imu(&ins, ins_t_ns, ins_seq, &w, &f);
}

static void ins_prepare(int zupt, int rest, se23_real_t zaru_after)
{
    se23_ins_config_t cfg;
    se23_gauss_t g;
    int k;
    setup();
    ins_config(&cfg, zupt, zaru_after);
    g = c.g15;
    if (rest != 0) {
        memset(&g.T.v, 0, sizeof g.T.v);
    }
    ins_t_ns = 1000000000LL;
    ins_seq = 0;
    (void)se23_ins_setup(&cfg, &ins);
    (void)se23_ins_init(&ins, ins_t_ns, &g);
    for (k = 0; k < FEED; ++k) {
        (void)ins_next(rest);
    }
}
static void prepare_ins_predict(void) { ins_prepare(0, 0, SE23_R(0)); }
/* ZARU from the first stationary sample on (zaru_after 0), or not within
 * the feed (zaru_after 1 s: a walker's stance, ins.h "Zero-velocity
 * updates"). */
static void prepare_ins_zupt(void) { ins_prepare(1, 1, SE23_R(0)); }
static void prepare_ins_zupt_only(void) { ins_prepare(1, 1, SE23_R(1)); }

/* A fix at the state's time, a little off the antenna's position and
 * velocity (p + R l, v + R (w x l)). */
static void prepare_ins_gnss(void)
{
    se23_gauss_t g;
    se23_vec3_t w, wl;
    int64_t t_ns;
    int i, j;
    ins_prepare(0, 0, SE23_R(0));
    (void)se23_ins_state(&ins, &g, &t_ns);
    memset(&ins_fix, 0, sizeof ins_fix);
    ins_fix.t_ns = t_ns;
    ins_fix.has_vel = 1;
    for (i = 0; i < 3; ++i) {
        w.v[i] = c.s.w_ib_b.v[i] + g.b_g.v[i];
    }
    wl.v[0] = w.v[1] * c.lever.v[2] - w.v[2] * c.lever.v[1];
    wl.v[1] = w.v[2] * c.lever.v[0] - w.v[0] * c.lever.v[2];
    wl.v[2] = w.v[0] * c.lever.v[1] - w.v[1] * c.lever.v[0];
    for (i = 0; i < 3; ++i) {
        ins_fix.p_n.v[i] = g.T.p.v[i] + SE23_R(0.3);
        ins_fix.v_n.v[i] = g.T.v.v[i] - SE23_R(0.05);
        for (j = 0; j < 3; ++j) {
            ins_fix.p_n.v[i] += g.T.R.m[i][j] * c.lever.v[j];
            ins_fix.v_n.v[i] += g.T.R.m[i][j] * wl.v[j];
        }
        ins_fix.sigma_p.v[i] = SE23_R(2);
        ins_fix.sigma_v.v[i] = SE23_R(0.1);
    }
}

/* Filter: one sample, prediction only (detector off). */
static int ins_predict(void)
{
    return (int)ins_next(0);
}
/* Filter: one sample at rest, detector on: prediction, the two rest tests,
 * zero-velocity and zero-rate updates (100 if it was not judged at rest). */
static int ins_zupt(void)
{
    const se23_ins_verdict_t v = ins_next(1);
    if (v != SE23_INS_USED) {
        return (int)v;
    }
    return (ins.status & SE23_INS_ST_STATIONARY) != 0U ? 0 : 100;
}
/* Filter: one GNSS position + velocity fix at the current time, lever arm. */
static int ins_gnss(void)
{
    return (int)se23_ins_gnss(&ins, &ins_fix);
}
/* Filter: the state read out (rotating Earth: the carried state converted
 * to the user's, with its 15 x 15 covariance), as a firmware does per
 * output. */
static int ins_state(void)
{
    static se23_gauss_t out;
    int64_t t_ns;
    return (int)se23_ins_state(&ins, &out, &t_ns);
}

const bench_step_t bench_steps[] = {
    {"STEP mean+cov n=9 (se23_gauss_predict)", setup, step_cov9},
    {"STEP mean+cov n=15 (se23_gauss_predict)", setup, step_cov15},
    {"STEP mean+cov n=15, basic B (se23_gauss_predict)", setup, step_cov15_basic},
    {"STEP preintegration (se23_preint_unc_add, exact B, no classical Jacobians)", setup, step_preint},
    {"UPDATE GNSS position n=15 (se23_meas_pos_nav + se23_kalman_update)", setup, update_gnss15},
    {"UPDATE non-holonomic constraint n=15 (se23_meas_nhc + se23_kalman_update)", setup,
     update_nhc15},
    {"UPDATE non-holonomic constraint n=15, structured (filter's path: se23_nhc_rows + "
     "se23_kalman_nhc)",
     setup, update_nhc15_structured},
    {"FILTER sample n=15, predict only, detector off (se23_ins_imu)", prepare_ins_predict,
     ins_predict},
    {"FILTER sample n=15 at rest, predict + rest tests + ZUPT + ZARU (se23_ins_imu)",
     prepare_ins_zupt, ins_zupt},
    {"FILTER sample n=15 at rest, predict + rest tests + ZUPT, ZARU not due (se23_ins_imu)",
     prepare_ins_zupt_only, ins_zupt},
    {"FILTER GNSS position + velocity fix now, lever arm, n=15 (se23_ins_gnss)", prepare_ins_gnss,
     ins_gnss},
    {"FILTER state read, rotating Earth, n=15 (se23_ins_state)", prepare_ins_predict, ins_state},
};
const int bench_n_steps = (int)(sizeof bench_steps / sizeof bench_steps[0]);
