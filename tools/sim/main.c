/*
 * se23-sim: simulated IMU (+ truth, GNSS fixes, initial estimate) over LCM.
 *
 * The vehicle follows an analytic reference trajectory (traj.h). For each
 * IMU interval the true inputs are the reference body rate and specific
 * force at the interval midpoint (including the Earth-rate, Coriolis and
 * centrifugal terms of paper eq. nav:eq_Coriolis), plus a small tracking
 * correction that keeps the truth on the reference over long runs. The
 * truth is then the RK4 solution of the navigation equations with those
 * inputs held constant over the interval (truth.h): exact for the
 * zero-order-hold model, independent of the library. The published sample
 * adds the IMU errors (imu_err.h).
 *
 * GNSS fixes are of an antenna at a body-frame lever arm from the IMU
 * (--lever), and can arrive late (--gnss-latency): a fix keeps the time it
 * refers to but is published after the IMU sample at that time plus the
 * latency, from a small fixed queue. --stationary prepends a rest phase
 * (traj_eval_start).
 *
 * Run with --help for the options.
 */
#define _POSIX_C_SOURCE 200809L
#include <lcm/lcm.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../lcm/harness.h"
#include "imu_err.h"
#include "truth.h"
#include "se23lcm_gnss_fix.h"
#include "se23lcm_imu_sample.h"
#include "se23lcm_nav_state.h"
#include "se23lcm_sim_info.h"
#include "se23lcm_truth.h"
#include "traj.h"

#define DEG_L (3.141592653589793238462643383279502884L / 180.0L)
#define H_MAX 1.25e-3 /* largest RK4 sub-step [s] */
#define GNSS_PENDING_MAX 64 /* fixes waiting for their latency to pass */

typedef struct {
    int scenario;
    double duration;
    double imu_rate;
    int profile;
    int earth;
    double lat_deg;
    double gnss_rate;
    double gnss_sp[3];
    double gnss_sv[3];
    double lever[3];      /* GNSS antenna w.r.t. the IMU, body [m] */
    double gnss_latency;  /* [s] */
    double stationary;    /* rest before the motion [s] */
    int biases;           /* 0: the profile's biases and bias walks left out */
    double truth_rate;
    int64_t seed;
    double init_sigma[3]; /* attitude [deg], velocity [m/s], position [m] */
    const char *url;
    double speed; /* < 0: default */
    int progress;
    int track;
    double accel_misalign[3]; /* accelerometer triad rotation vector [deg] */
    double check_traj;        /* > 0: check the trajectories' derivatives, step [s] */
} sim_opts_t;

static void usage(FILE *f)
{
    fprintf(f,
            "usage: se23-sim [options]\n"
            "  --scenario NAME                 trajectory: static|uav|car|nav|walk|stairs\n"
            "                                  (uav)\n"
            "  --duration S                    length [s] (scenario default:\n"
            "                                  60/60/120/3600/26.8/26.8)\n"
            "  --imu-rate HZ                   100..2000 (200)\n"
            "  --imu perfect|mems|tactical|navigation   error profile (mems)\n"
            "  --earth on|off                  Earth rotation (on)\n"
            "  --lat DEG                       latitude of the origin (45)\n"
            "  --gnss-rate HZ                  GNSS fixes, 0 = none (5)\n"
            "  --gnss-sigma-p X,Y,Z            position noise [m] (1.5,1.5,3)\n"
            "  --gnss-sigma-v X,Y,Z            velocity noise [m/s] (0.1,0.1,0.2)\n"
            "  --lever X,Y,Z                   GNSS antenna position w.r.t. the IMU, body\n"
            "                                  frame FRD [m] (0,0,0)\n"
            "  --gnss-latency S                each fix is published after the IMU sample at\n"
            "                                  its time + S [s] (0); fixes not due by the end\n"
            "                                  of the run are not published\n"
            "  --stationary S                  at rest for S seconds, then a smooth ramp into\n"
            "                                  the scenario's motion [s] (0); the default\n"
            "                                  --duration grows by S\n"
            "  --truth-rate HZ                 truth messages (50)\n"
            "  --seed N                        random seed (1)\n"
            "  --init-sigma DEG,MPS,M          initial attitude/velocity/position error\n"
            "                                  sigma of SE23_INIT (1,0.2,2); 0,0,0: exact\n"
            "  --url URL                       LCM URL (file://sim.log?mode=w)\n"
            "  --speed X                       pacing: 1 real time, 0 flat out\n"
            "                                  (default 0 for file://, else 1)\n"
            "  --no-track                      no tracking correction (tests)\n"
            "  --biases on|off                 the profile's biases and bias walks (on)\n"
            "  --accel-misalign RX,RY,RZ       accelerometer triad rotated against the\n"
            "                                  gyroscope's by this rotation vector, body\n"
            "                                  frame, each within +-10 [deg] (0,0,0)\n"
            "  --progress                      progress line on stderr\n"
            "  --check-traj H                  publish nothing: check every scenario's\n"
            "                                  closed-form v, a and body rate against\n"
            "                                  central differences of step H [s] over its\n"
            "                                  default duration; exit 1 if one is off by\n"
            "                                  more than 1e-5\n");
}

static int find_scenario(const char *name)
{
    return traj_find(name);
}

static int parse_args(int argc, char **argv, sim_opts_t *o)
{
    const double inf = HUGE_VAL;
    const harness_opt_t opts[] = {
        {"--scenario", HOPT_CHOICE, &o->scenario, 0, 0, find_scenario},
        {"--duration", HOPT_DOUBLE, &o->duration, 1e-3, inf, NULL},
        {"--imu-rate", HOPT_DOUBLE, &o->imu_rate, 100.0, 2000.0, NULL},
        {"--imu", HOPT_CHOICE, &o->profile, 0, 0, harness_imu_profile_find},
        {"--earth", HOPT_CHOICE, &o->earth, 0, 0, harness_on_off},
        {"--lat", HOPT_DOUBLE, &o->lat_deg, -90.0, 90.0, NULL},
        {"--gnss-rate", HOPT_DOUBLE, &o->gnss_rate, 0.0, inf, NULL},
        {"--gnss-sigma-p", HOPT_VEC3, o->gnss_sp, 1e-6, inf, NULL},
        {"--gnss-sigma-v", HOPT_VEC3, o->gnss_sv, 1e-6, inf, NULL},
        {"--lever", HOPT_VEC3, o->lever, -100.0, 100.0, NULL},
        {"--gnss-latency", HOPT_DOUBLE, &o->gnss_latency, 0.0, 60.0, NULL},
        {"--stationary", HOPT_DOUBLE, &o->stationary, 0.0, 86400.0, NULL},
        {"--truth-rate", HOPT_DOUBLE, &o->truth_rate, 1e-3, inf, NULL},
        {"--seed", HOPT_I64, &o->seed, 0, 0, NULL},
        {"--init-sigma", HOPT_VEC3, o->init_sigma, 0.0, inf, NULL},
        {"--url", HOPT_STR, &o->url, 0, 0, NULL},
        {"--speed", HOPT_DOUBLE, &o->speed, 0.0, inf, NULL},
        {"--no-track", HOPT_FLAG, &o->track, 0, 0, NULL},
        {"--biases", HOPT_CHOICE, &o->biases, 0, 0, harness_on_off},
        {"--accel-misalign", HOPT_VEC3, o->accel_misalign, -10.0, 10.0, NULL},
        {"--progress", HOPT_FLAG, &o->progress, 1, 0, NULL},
        {"--check-traj", HOPT_DOUBLE, &o->check_traj, 1e-9, 1.0, NULL},
    };
    o->scenario = TRAJ_UAV;
    o->duration = -1.0;
    o->imu_rate = 200.0;
    o->profile = HARNESS_IMU_MEMS;
    o->biases = 1;
    o->earth = 1;
    o->lat_deg = 45.0;
    o->gnss_rate = 5.0;
    o->gnss_sp[0] = 1.5;
    o->gnss_sp[1] = 1.5;
    o->gnss_sp[2] = 3.0;
    o->gnss_sv[0] = 0.1;
    o->gnss_sv[1] = 0.1;
    o->gnss_sv[2] = 0.2;
    memset(o->lever, 0, sizeof o->lever);
    memset(o->accel_misalign, 0, sizeof o->accel_misalign);
    o->check_traj = 0.0;
    o->gnss_latency = 0.0;
    o->stationary = 0.0;
    o->truth_rate = 50.0;
    o->seed = 1;
    o->init_sigma[0] = 1.0;
    o->init_sigma[1] = 0.2;
    o->init_sigma[2] = 2.0;
    o->url = "file://sim.log?mode=w";
    o->speed = -1.0;
    o->progress = 0;
    o->track = 1;
    if (harness_parse_opts("se23-sim", argc, argv, opts, (int)(sizeof opts / sizeof opts[0]),
                           usage, NULL, NULL) != 0) {
        return -1;
    }
    if (o->duration < 0.0) {
        o->duration = traj_default_duration((traj_scenario_t)o->scenario) + o->stationary;
    }
    if (o->speed < 0.0) {
        o->speed = (strncmp(o->url, "file://", 7) == 0) ? 0.0 : 1.0;
    }
    return 0;
}

static void publish_truth(lcm_t *lc, int64_t t_ns, int64_t seq, const truth_state_t *x,
                          const double b_g[3], const double b_a[3])
{
    se23lcm_truth m;
    memset(&m, 0, sizeof m);
    m.t_ns = t_ns;
    m.seq = seq;
    ld_mat3_to(&x->R, m.R_nb);
    ld_vec3_to(&x->v, m.v_n);
    ld_vec3_to(&x->p, m.p_n);
    memcpy(m.b_g, b_g, sizeof m.b_g);
    memcpy(m.b_a, b_a, sizeof m.b_a);
    se23lcm_truth_publish(lc, HARNESS_CH_TRUTH, &m);
}

/*
 * Initial estimate: That = T exp(-xi0), xi0 = (phi, nu, rho) ~ N(0, P0), so
 * that T = That exp(xi0) (paper eq. error:rep1); biases estimated as 0 with
 * their turn-on sigma. P0 is published with it.
 */
static void publish_init(lcm_t *lc, const sim_opts_t *o, const truth_state_t *x, rng_t *rng)
{
    const harness_imu_profile_t *prof = harness_imu_profile(o->profile);
    double sig[15];
    ld_vec3_t phi, nu, rho, mphi, Jnu, Jrho, dv, dp;
    ld_mat3_t E, J, R;
    se23lcm_nav_state m;
    int i;
    for (i = 0; i < 3; i++) {
        sig[i] = o->init_sigma[0] * (3.14159265358979323846 / 180.0);
        sig[3 + i] = o->init_sigma[1];
        sig[6 + i] = o->init_sigma[2];
        sig[9 + i] = o->biases ? prof->gyro_bias0 : 0.0;
        sig[12 + i] = o->biases ? prof->accel_bias0 : 0.0;
    }
    for (i = 0; i < 3; i++) {
        phi.v[i] = sig[i] * rng_normal(rng);
        nu.v[i] = sig[3 + i] * rng_normal(rng);
        rho.v[i] = sig[6 + i] * rng_normal(rng);
    }
    mphi = ld_scale(&phi, -1.0L);
    E = ld_exp(&mphi);
    J = ld_jl(&mphi);
    Jnu = ld_mul_v(&J, &nu);
    Jrho = ld_mul_v(&J, &rho);
    R = ld_mul(&x->R, &E);
    dv = ld_mul_v(&x->R, &Jnu); /* exp(-xi) = (E, -J(-phi) nu, -J(-phi) rho) */
    dp = ld_mul_v(&x->R, &Jrho);
    memset(&m, 0, sizeof m);
    m.t_ns = 0;
    m.seq = 0;
    ld_mat3_to(&R, m.R_nb);
    for (i = 0; i < 3; i++) {
        m.v_n[i] = (double)(x->v.v[i] - dv.v[i]);
        m.p_n[i] = (double)(x->p.v[i] - dp.v[i]);
    }
    for (i = 0; i < 15; i++) {
        m.P[16 * i] = sig[i] * sig[i];
    }
    se23lcm_nav_state_publish(lc, HARNESS_CH_INIT, &m);
}

/* The --accel-misalign rotation vector in radians. */
static void accel_misalign_rad(const sim_opts_t *o, double rv[3])
{
    int i;
    for (i = 0; i < 3; i++) {
        rv[i] = (double)((ld_t)o->accel_misalign[i] * DEG_L);
    }
}

static void publish_info(lcm_t *lc, const char *ch, const sim_opts_t *o, const truth_env_t *env)
{
    se23lcm_sim_info m;
    memset(&m, 0, sizeof m);
    m.scenario = o->scenario;
    m.imu_profile = o->profile;
    m.earth_rotation = (int8_t)o->earth;
    m.seed = o->seed;
    m.imu_rate_hz = o->imu_rate;
    m.gnss_rate_hz = o->gnss_rate;
    m.duration_s = o->duration;
    m.latitude_rad = o->lat_deg * (3.14159265358979323846 / 180.0);
    ld_vec3_to(&env->g_n, m.g_n);
    ld_vec3_to(&env->w_ie_n, m.w_ie_n);
    memcpy(m.lever_b, o->lever, sizeof m.lever_b);
    m.gnss_latency_s = o->gnss_latency;
    m.stationary_s = o->stationary;
    m.ramp_s = o->stationary > 0.0 ? traj_ramp_duration((traj_scenario_t)o->scenario) : 0.0;
    accel_misalign_rad(o, m.accel_misalign_b);
    se23lcm_sim_info_publish(lc, ch, &m);
}

/* The reference at t [s]: the scenario, after the rest phase if any. */
static traj_point_t ref_eval(const sim_opts_t *o, ld_t t)
{
    return traj_eval_start((traj_scenario_t)o->scenario, (ld_t)o->stationary, t);
}

/*
 * True inputs over [t0, t0 + dt]: the reference body rate and specific
 * force at the midpoint,
 *   w_ib_b = w_nb_b + R^T w_ie_n,
 *   f_b = R^T (a - g + 2 W v + W W p),   W = w_ie_n^,
 * (inverting paper eq. nav:eq_Coriolis), plus a critically damped tracking
 * correction (1 rad/s) on the truth's deviation from the reference at t0.
 */
static void true_inputs(const sim_opts_t *o, const truth_env_t *env, const truth_state_t *x,
                        ld_t t0, ld_t dt, double w_out[3], double f_out[3])
{
    traj_point_t m = ref_eval(o, t0 + 0.5L * dt);
    ld_vec3_t w_ie_b = ld_tmul_v(&m.R, &env->w_ie_n);
    ld_vec3_t w = ld_add(&m.w_nb_b, &w_ie_b);
    ld_vec3_t cor = ld_cross(&env->w_ie_n, &m.v);
    ld_vec3_t Wp = ld_cross(&env->w_ie_n, &m.p);
    ld_vec3_t cen = ld_cross(&env->w_ie_n, &Wp);
    ld_vec3_t fn, f;
    int i;
    for (i = 0; i < 3; i++) {
        fn.v[i] = m.a.v[i] - env->g_n.v[i] + 2.0L * cor.v[i] + cen.v[i];
    }
    f = ld_tmul_v(&m.R, &fn);
    if (o->track) {
        traj_point_t r = ref_eval(o, t0);
        ld_mat3_t E = ld_mul_tn(&x->R, &r.R);
        ld_vec3_t e_R = ld_log(&E);
        ld_vec3_t e_v = ld_sub(&r.v, &x->v);
        ld_vec3_t e_p = ld_sub(&r.p, &x->p);
        ld_vec3_t corr_n, corr_b;
        for (i = 0; i < 3; i++) {
            corr_n.v[i] = 2.0L * e_v.v[i] + e_p.v[i];
        }
        corr_b = ld_tmul_v(&x->R, &corr_n);
        w = ld_add(&w, &e_R);
        f = ld_add(&f, &corr_b);
    }
    ld_vec3_to(&w, w_out);
    ld_vec3_to(&f, f_out);
}

/*
 * The fix at t_ns of the antenna at the lever arm l (body frame) from the
 * IMU, the truth x being at t_ns: position p + R l, velocity
 * v + R (w_nb_b x l), plus the noise. w_nb_b = w_ib_b - R^T w_ie_n is the
 * body rate relative to the nav frame (Earth-fixed NED: no transport rate),
 * w_ib_b the true rate held over the IMU interval ending at t_ns: exactly
 * R^T dR/dt of the truth there (truth.h: dR/dt = -W R + R w_ib_b^). An INS
 * that forms the lever-arm velocity from the bias-corrected gyro w_ib_b
 * (the library's filter) neglects (R^T w_ie_n) x l, at most
 * 7.3e-5 rad/s * |l| (7e-5 m/s for a 1 m lever), far below GNSS noise.
 * The noise is drawn in the same order with or without a lever arm.
 */
static void make_gnss(se23lcm_gnss_fix *m, int64_t t_ns, int64_t seq, const sim_opts_t *o,
                      const truth_env_t *env, const truth_state_t *x, const ld_vec3_t *w_ib_b,
                      rng_t *rng)
{
    ld_vec3_t l = ld_vec3_from(o->lever);
    ld_vec3_t w_ie_b = ld_tmul_v(&x->R, &env->w_ie_n);
    ld_vec3_t w_nb_b = ld_sub(w_ib_b, &w_ie_b);
    ld_vec3_t wxl = ld_cross(&w_nb_b, &l);
    ld_vec3_t dp = ld_mul_v(&x->R, &l);
    ld_vec3_t dv = ld_mul_v(&x->R, &wxl);
    int i;
    memset(m, 0, sizeof *m);
    m->t_ns = t_ns;
    m->seq = seq;
    for (i = 0; i < 3; i++) {
        m->p_n[i] = (double)(x->p.v[i] + dp.v[i]) + o->gnss_sp[i] * rng_normal(rng);
        m->v_n[i] = (double)(x->v.v[i] + dv.v[i]) + o->gnss_sv[i] * rng_normal(rng);
        m->sigma_p[i] = o->gnss_sp[i];
        m->sigma_v[i] = o->gnss_sv[i];
    }
    m->has_vel = 1;
}

/*
 * Fixes waiting to be published: a ring in time order (fixes are made in
 * time order and all have the same latency), each due once the IMU sample
 * at its t_ns + latency has been published.
 */
typedef struct {
    se23lcm_gnss_fix fix[GNSS_PENDING_MAX];
    int64_t due_ns[GNSS_PENDING_MAX];
    int head, count;
} gnss_queue_t;

/* Queues m, due at due_ns; -1 if the queue is full. */
static int gnss_push(gnss_queue_t *q, const se23lcm_gnss_fix *m, int64_t due_ns)
{
    int slot;
    if (q->count >= GNSS_PENDING_MAX) {
        return -1;
    }
    slot = (q->head + q->count) % GNSS_PENDING_MAX;
    q->fix[slot] = *m;
    q->due_ns[slot] = due_ns;
    q->count++;
    return 0;
}

/* Publishes, oldest first, every queued fix due at or before t_ns. */
static void gnss_release(gnss_queue_t *q, lcm_t *lc, int64_t t_ns)
{
    while (q->count > 0 && q->due_ns[q->head] <= t_ns) {
        se23lcm_gnss_fix_publish(lc, HARNESS_CH_GNSS, &q->fix[q->head]);
        q->head = (q->head + 1) % GNSS_PENDING_MAX;
        q->count--;
    }
}

static int64_t every(double base_rate, double rate)
{
    int64_t n = llround(base_rate / rate);
    return n < 1 ? 1 : n;
}

/* The progress line: simulated time t out of total [s]. */
static void progress(harness_progress_t *pr, int final, double t, double total)
{
    harness_progress(pr, final, "se23-sim: t = %7.1f / %.1f s", t, total);
}

/* --check-traj: the closed-form derivatives of every scenario against
 * central differences (traj_check_derivatives), 20,000 instants each. */
static int check_trajectories(double h)
{
    int s, ok = 1;
    for (s = 0; s < TRAJ_COUNT; s++) {
        ld_t worst[3];
        traj_check_derivatives((traj_scenario_t)s, (ld_t)traj_default_duration((traj_scenario_t)s),
                               20000, (ld_t)h, worst);
        printf("%-7s max |v - dp/dt| %.2Le m/s, |a - dv/dt| %.2Le m/s^2, |w - vee(R^T dR/dt)| "
               "%.2Le rad/s\n",
               traj_name((traj_scenario_t)s), worst[0], worst[1], worst[2]);
        ok = ok && worst[0] <= 1e-5L && worst[1] <= 1e-5L && worst[2] <= 1e-5L;
    }
    printf(ok ? "TRAJ CHECK PASSED\n" : "TRAJ CHECK FAILED\n");
    return ok ? 0 : 1;
}

int main(int argc, char **argv)
{
    sim_opts_t o;
    truth_env_t env;
    truth_state_t x;
    traj_point_t r0;
    imu_err_t err;
    rng_t rng_gnss, rng_init;
    lcm_t *lc;
    int64_t dt_ns, n, k, n_truth, n_gnss, wall0, latency_ns, gnss_seq = 0;
    gnss_queue_t gq;
    harness_progress_t pr;
    int nsub;
    double dt;

    if (parse_args(argc, argv, &o) != 0) {
        usage(stderr);
        return 2;
    }
    if (o.check_traj > 0.0) {
        return check_trajectories(o.check_traj);
    }
    dt_ns = llround(1e9 / o.imu_rate);
    dt = (double)dt_ns * 1e-9;
    n = llround(o.duration * 1e9 / (double)dt_ns);
    nsub = (int)ceil(dt / H_MAX - 1e-9);
    n_truth = every(o.imu_rate, o.truth_rate);
    n_gnss = o.gnss_rate > 0.0 ? every(o.imu_rate, o.gnss_rate) : 0;
    latency_ns = llround(o.gnss_latency * 1e9);
    /* fixes pending at once: those made in (t - latency - dt, t], at most
     * ceil((latency + dt) / fix period) */
    if (n_gnss > 0 &&
        (latency_ns + dt_ns + n_gnss * dt_ns - 1) / (n_gnss * dt_ns) > GNSS_PENDING_MAX) {
        fprintf(stderr,
                "se23-sim: --gnss-latency %g s at %g Hz would hold more than %d fixes "
                "pending\n",
                o.gnss_latency, (double)1e9 / (double)(n_gnss * dt_ns), GNSS_PENDING_MAX);
        return 2;
    }
    memset(&gq, 0, sizeof gq);
    lc = lcm_create(o.url);
    if (lc == NULL) {
        fprintf(stderr, "se23-sim: cannot open LCM URL %s\n", o.url);
        return 1;
    }
    harness_catch_stop_signals();

    env = truth_env_ned(o.lat_deg * DEG_L, o.earth);
    {
        harness_imu_profile_t prof = *harness_imu_profile(o.profile);
        if (!o.biases) { /* white noise only (a 9-state filter's model) */
            prof.gyro_bias0 = 0.0;
            prof.accel_bias0 = 0.0;
            prof.gyro_bias_rw = 0.0;
            prof.accel_bias_rw = 0.0;
        }
        imu_err_init(&err, &prof, (uint64_t)o.seed);
        {
            double rv[3];
            accel_misalign_rad(&o, rv);
            imu_err_misalign_accel(&err, rv);
        }
    }
    rng_seed(&rng_gnss, (uint64_t)o.seed ^ 0x5a5a5a5a5a5a5a5aULL);
    rng_seed(&rng_init, (uint64_t)o.seed ^ 0x0123456789abcdefULL);

    r0 = ref_eval(&o, 0.0L);
    x.R = r0.R;
    x.v = r0.v;
    x.p = r0.p;
    publish_info(lc, HARNESS_CH_SIM_INFO, &o, &env);
    publish_init(lc, &o, &x, &rng_init);
    publish_truth(lc, 0, 0, &x, err.b_g, err.b_a);

    wall0 = harness_now_ns();
    harness_progress_init(&pr);
    for (k = 1; k <= n && !harness_stop_requested(); k++) {
        double w_true[3], f_true[3], b_g[3], b_a[3];
        ld_vec3_t w_ld, f_ld;
        se23lcm_imu_sample s;
        int i;
        true_inputs(&o, &env, &x, (ld_t)((k - 1) * dt_ns) * 1e-9L, (ld_t)dt, w_true, f_true);
        for (i = 0; i < 3; i++) { /* the truth uses exactly the published values */
            w_ld.v[i] = (ld_t)w_true[i];
            f_ld.v[i] = (ld_t)f_true[i];
        }
        truth_step(&x, &env, &w_ld, &f_ld, (ld_t)dt, nsub);
        memcpy(b_g, err.b_g, sizeof b_g);
        memcpy(b_a, err.b_a, sizeof b_a);
        memset(&s, 0, sizeof s);
        s.t_ns = k * dt_ns;
        s.seq = k;
        imu_err_apply(&err, w_true, f_true, dt, s.omega, s.accel);
        if (o.speed > 0.0) {
            harness_sleep_until_ns(wall0 + (int64_t)((double)s.t_ns / o.speed));
        }
        se23lcm_imu_sample_publish(lc, HARNESS_CH_IMU, &s);
        if (k % n_truth == 0) {
            publish_truth(lc, s.t_ns, k, &x, b_g, b_a);
        }
        if (n_gnss > 0 && k % n_gnss == 0) {
            se23lcm_gnss_fix g;
            make_gnss(&g, s.t_ns, ++gnss_seq, &o, &env, &x, &w_ld, &rng_gnss);
            if (gnss_push(&gq, &g, s.t_ns + latency_ns) != 0) {
                fprintf(stderr, "se23-sim: GNSS queue full\n"); /* excluded above */
                lcm_destroy(lc);
                return 1;
            }
        }
        gnss_release(&gq, lc, s.t_ns); /* after the sample and its truth */
        if (o.progress) {
            progress(&pr, 0, (double)s.t_ns * 1e-9, (double)n * dt);
        }
    }
    if (o.progress) {
        progress(&pr, 1, (double)(k - 1) * dt, (double)n * dt);
    }
    publish_info(lc, HARNESS_CH_SIM_END, &o, &env);
    lcm_destroy(lc);
    return harness_stop_requested() ? 130 : 0;
}
