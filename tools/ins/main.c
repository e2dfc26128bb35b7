/*
 * se23-ins: the INS node, a thin LCM adapter around the library's filter
 * (se23/ins.h): decodes IMU samples, GNSS fixes and the initial state,
 * calls the filter, and publishes the navigation state with its 15x15
 * covariance and, on request, preintegrated factors. Prints the filter's
 * accounting of every input at the end. No navigation logic lives here.
 *
 * Run with --help for the options.
 */
#define _POSIX_C_SOURCE 200809L
#include <lcm/lcm.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "../lcm/harness.h"
#include "replay.h"
#include "se23/earth.h"
#include "se23/ins.h"
#include "se23/so3.h"
#include "se23lcm_gnss_fix.h"
#include "se23lcm_imu_info.h"
#include "se23lcm_imu_sample.h"
#include "se23lcm_nav_state.h"
#include "se23lcm_preint_factor.h"
#include "se23lcm_sim_info.h"

#define DEG (3.14159265358979323846 / 180.0)
#define DEFAULT_IMU_RATE 200.0 /* [Hz] without --imu-rate and without SE23_IMU_INFO */

/*
 * How far --imu-rate may be from the rate the log carries (SE23_IMU_INFO),
 * relative. The filter integrates each sample over its own timestamps; the
 * nominal rate only scales the per-sample noise (density * sqrt(rate)) and
 * sets lengths counted in samples (detector window, largest gap, delay
 * ring): 1 % changes them by 0.5 to 1 %, which no result shows. A sensor's
 * clock is off its nominal rate by up to a fraction of a percent (the x-io
 * walk: 398.3 Hz measured for a nominal 400, 0.4 %), so the data sheet's
 * rate passes for the measured one; a wrong rate is wrong by more: the
 * smallest mix-up in the corpus, 200 Hz for gaitmap's 204.8 Hz, is 2.3 %,
 * and the usual ones are factors of 2.
 */
#define RATE_TOLERANCE 0.01

/* Exit status when the log's rate cannot be used (main). */
#define EXIT_RATE_REFUSED 5

/* The filter's options as given; the configuration is built from them once
 * the IMU rate is known (configure). */
typedef struct {
    double imu_rate; /* --imu-rate [Hz]; 0: not given */
    double lat_deg, max_gap, gate, horizon, max_outage, preint, lever[3];
    double alpha, zupt_sv, zupt_lever, floor_sigma;
    double mount_deg[3]; /* --mount roll, pitch, yaw of C_bv [deg] */
    double nhc_sigma, gnss_offset, height;
    int64_t recover, window;
    int profile, earth, bias, zupt;
} filter_opts_t;

typedef struct {
    const char *in_url;
    const char *out_url;
    int preset;         /* 0 none, 1 foot, 2 car */
    filter_opts_t f;
    double nav_rate;
    int progress;
    int exit_on_end;
    double idle_timeout; /* live: stop after this long without input [s] */
    const char *ready_file;
} node_opts_t;

typedef struct {
    se23_ins_t ins;
    node_opts_t o;
    lcm_t *out;
    double imu_rate;       /* the filter's nominal rate [Hz] ... */
    const char *rate_from; /* ... from --imu-rate, the log or the default */
    double log_rate;       /* the rate of the log's SE23_IMU_INFO (0: none yet) */
    int rate_refused;      /* the log's rate cannot be used: stop (EXIT_RATE_REFUSED) */
    int started;           /* an input reached the filter: its rate is fixed */
    int64_t nav_every; /* publish when seq % nav_every == 0 */
    int publish_due;
    int ended;
    int initialised;       /* the filter had a state at some point */
    int64_t decode_errors; /* messages that failed to decode (any channel) */
    harness_progress_t pr;
} node_t;

static void usage(FILE *f)
{
    fprintf(f,
            "usage: se23-ins [options]\n"
            "  --in URL              input LCM URL (file://sim.log?speed=0)\n"
            "  --out URL             output LCM URL (file://ins.log?mode=w for file\n"
            "                        input, else the input URL)\n"
            "  --imu PROFILE         noise model: perfect|mems|tactical|navigation (mems)\n"
            "  --preset foot         the library's pedestrian preset (se23_ins_preset_foot:\n"
            "                        foot-mounted consumer MEMS IMU, ZUPT/ZARU, static\n"
            "                        alignment at the first rest, no GNSS; replaces the\n"
            "                        noise, detector and filter options)\n"
            "  --preset car          the library's car preset (se23_ins_preset_car:\n"
            "                        automotive MEMS IMU with GNSS, non-holonomic\n"
            "                        constraint, ZUPT at stops, alignment at the first\n"
            "                        2 s at rest with the heading from the GNSS course;\n"
            "                        --lever, --mount and --gnss-time-offset apply)\n"
            "  --mount R,P,Y         the IMU's mounting, C_bv = Rz(Y) Ry(P) Rx(R), x_b =\n"
            "                        C_bv x_v from the vehicle frame [deg] (0,0,0)\n"
            "  --nhc-sigma S         1-sigma of the non-holonomic constraint [m/s], 0 = off\n"
            "                        (the car preset's 0.3)\n"
            "  --gnss-time-offset S  added to every fix's time: the IMU clock minus the\n"
            "                        GNSS clock [s] (0)\n"
            "  --imu-rate HZ         nominal IMU rate (the log's SE23_IMU_INFO, written\n"
            "                        by se23-import, else 200); one that differs from the\n"
            "                        log's by more than 1 %% is refused (exit status 5)\n"
            "  --earth on|off        rotating-Earth model (on)\n"
            "  --lat DEG             latitude of the nav-frame origin (45)\n"
            "  --height M            its ellipsoidal height, for gravity (0)\n"
            "  --bias-states on|off  15-state filter with bias states (on)\n"
            "  --nav-rate HZ         nav_state output rate (50)\n"
            "  --gate X              chi-square gate on GNSS innovations, 0 = none (30)\n"
            "  --gate-recover N      reset position/velocity to the fix after N\n"
            "                        consecutive gated fixes, 0 = never (5)\n"
            "  --lever X,Y,Z         GNSS antenna lever arm, body frame [m] (0,0,0)\n"
            "  --delay-horizon S     fuse fixes up to S s late at their own time (0.25,\n"
            "                        or less at rates where the ring of SE23_INS_RING\n"
            "                        samples cannot hold 2 S of them)\n"
            "  --zupt on|off         zero-velocity/-rate updates at rest, from the\n"
            "                        stationary detector (off)\n"
            "  --zupt-window N       detector window [samples] (20)\n"
            "  --zupt-alpha A        detector's false-motion probability at rest (0.01)\n"
            "  --zupt-sigma-v S      1-sigma of v = 0 at rest [m/s] (0.01; the preset's\n"
            "                        with --preset; this option overrides both)\n"
            "  --zupt-lever L        distance [m] from the point a body at rest turns\n"
            "                        about: the ZUPT's 1-sigma grows with the rate (0;\n"
            "                        the preset's 0.2 with --preset; ins.h)\n"
            "  --floor-sigma S       with --preset foot: 1-sigma of the floor level at\n"
            "                        each stance [m] (the preset's: 0, no floor updates;\n"
            "                        0.01 its argued value; ins.h, \"Floor\")\n"
            "  --max-gap S           longest interval one sample may bridge (25 samples)\n"
            "  --max-outage S        longest outage carried across (10)\n"
            "  --preint S            publish preintegrated factors of S seconds (0 = off)\n"
            "  --exit-on-end         stop when SE23_SIM_END arrives (live runs)\n"
            "  --idle-timeout S      live runs: stop after S s without input (0 = never)\n"
            "  --ready-file PATH     create PATH once subscribed (scripts wait for it)\n"
            "  --progress            progress line on stderr\n");
}

/* Standard normal quantile of p in (0.5, 1) (Acklam's rational
 * approximation, relative error below 1.2e-9; enough for a threshold). */
static double normal_quantile(double p)
{
    const double a[] = {-3.969683028665376e+01, 2.209460984245205e+02, -2.759285104469687e+02,
                        1.383577518672690e+02, -3.066479806614716e+01, 2.506628277459239e+00};
    const double b[] = {-5.447609879822406e+01, 1.615858368580409e+02, -1.556989798598866e+02,
                        6.680131188771972e+01, -1.328068155288572e+01};
    const double c[] = {-7.784894002430293e-03, -3.223964580411365e-01, -2.400758277161838e+00,
                        -2.549732539343734e+00, 4.374664141464968e+00, 2.938163982698783e+00};
    const double d[] = {7.784695709041462e-03, 3.224671290700398e-01, 2.445134137142996e+00,
                        3.754408661907416e+00};
    double q, r;
    if (p < 0.97575) {
        q = p - 0.5;
        r = q * q;
        return (((((a[0] * r + a[1]) * r + a[2]) * r + a[3]) * r + a[4]) * r + a[5]) * q /
               (((((b[0] * r + b[1]) * r + b[2]) * r + b[3]) * r + b[4]) * r + 1.0);
    }
    q = sqrt(-2.0 * log(1.0 - p));
    return -(((((c[0] * q + c[1]) * q + c[2]) * q + c[3]) * q + c[4]) * q + c[5]) /
           ((((d[0] * q + d[1]) * q + d[2]) * q + d[3]) * q + 1.0);
}

/*
 * The stationary detector and the rest updates from the IMU profile. The
 * detector sees the readings corrected by the filter (ins.h): its
 * per-sample sigmas are the white noise (density * sqrt(rate)), plus, with
 * 9 states (biases not estimated), the profile's constant bias as if it
 * were noise (stationary.h: raise the sigmas, not the threshold).
 * Threshold: the chi^2_{6W-2} quantile of
 * stationary.h for a false "moving" probability alpha per window
 * (Wilson-Hilferty). ZUPT: v = 0 to 1 cm/s (a vehicle at rest; its own
 * vibration); ZARU: the gyro's per-sample noise.
 */
static void zupt_config(const harness_imu_profile_t *prof, double rate, double lat, int window,
                        double alpha, se23_ins_config_t *c)
{
    const double sg = prof->gyro_noise * sqrt(rate), sa = prof->accel_noise * sqrt(rate);
    const double bias = c->bias_states ? 0.0 : 1.0;
    const double k = 6.0 * window - 2.0, z = normal_quantile(1.0 - alpha);
    const double wh = 1.0 - 2.0 / (9.0 * k) + z * sqrt(2.0 / (9.0 * k));
    se23_real_t g;
    c->detector.window = window;
    c->detector.sigma_a = sqrt(sa * sa + bias * prof->accel_bias0 * prof->accel_bias0);
    c->detector.sigma_g = sqrt(sg * sg + bias * prof->gyro_bias0 * prof->gyro_bias0);
    c->detector.gravity = se23_earth_gravity(lat, 0.0, &g) == SE23_OK ? g : 9.80665;
    c->detector.threshold = k * wh * wh * wh / window;
    c->zupt_sigma_v = 0.01;
    c->zaru_sigma_w = sg > 1e-9 ? sg : 1e-9;
    if (c->detector.sigma_a <= 0.0 || c->detector.sigma_g <= 0.0) { /* the perfect IMU */
        c->detector.sigma_a = 1e-3;
        c->detector.sigma_g = 1e-4;
    }
}

static int preset_find(const char *name)
{
    return strcmp(name, "none") == 0 ? 0
           : strcmp(name, "foot") == 0 ? 1
           : strcmp(name, "car") == 0  ? 2
                                       : -1;
}

static int parse_args(int argc, char **argv, node_opts_t *o)
{
    const double inf = HUGE_VAL;
    filter_opts_t *f = &o->f;
    const harness_opt_t opts[] = {
        {"--in", HOPT_STR, &o->in_url, 0, 0, NULL},
        {"--out", HOPT_STR, &o->out_url, 0, 0, NULL},
        {"--imu", HOPT_CHOICE, &f->profile, 0, 0, harness_imu_profile_find},
        {"--preset", HOPT_CHOICE, &o->preset, 0, 0, preset_find},
        {"--imu-rate", HOPT_DOUBLE, &f->imu_rate, 1.0, 1e5, NULL},
        {"--earth", HOPT_CHOICE, &f->earth, 0, 0, harness_on_off},
        {"--lat", HOPT_DOUBLE, &f->lat_deg, -90.0, 90.0, NULL},
        {"--height", HOPT_DOUBLE, &f->height, -1e4, 1e5, NULL},
        {"--bias-states", HOPT_CHOICE, &f->bias, 0, 0, harness_on_off},
        {"--nav-rate", HOPT_DOUBLE, &o->nav_rate, 1e-3, inf, NULL},
        {"--gate", HOPT_DOUBLE, &f->gate, 0.0, inf, NULL},
        {"--gate-recover", HOPT_I64, &f->recover, 0, 0, NULL},
        {"--lever", HOPT_VEC3, f->lever, -100.0, 100.0, NULL},
        {"--delay-horizon", HOPT_DOUBLE, &f->horizon, 0.0, 10.0, NULL},
        {"--zupt", HOPT_CHOICE, &f->zupt, 0, 0, harness_on_off},
        {"--zupt-window", HOPT_I64, &f->window, 0, 0, NULL},
        {"--zupt-alpha", HOPT_DOUBLE, &f->alpha, 1e-6, 0.5, NULL},
        {"--zupt-sigma-v", HOPT_DOUBLE, &f->zupt_sv, 1e-6, 1e3, NULL},
        {"--zupt-lever", HOPT_DOUBLE, &f->zupt_lever, 0.0, 1.0, NULL},
        {"--floor-sigma", HOPT_DOUBLE, &f->floor_sigma, 0.0, 1e3, NULL},
        {"--mount", HOPT_VEC3, f->mount_deg, -360.0, 360.0, NULL},
        {"--nhc-sigma", HOPT_DOUBLE, &f->nhc_sigma, 0.0, 1e3, NULL},
        {"--gnss-time-offset", HOPT_DOUBLE, &f->gnss_offset, -1.0, 1.0, NULL},
        {"--max-gap", HOPT_DOUBLE, &f->max_gap, 1e-6, 1.0, NULL},
        {"--max-outage", HOPT_DOUBLE, &f->max_outage, 0.0, (double)SE23_INS_MAX_OUTAGE, NULL},
        {"--preint", HOPT_DOUBLE, &f->preint, 0.0, inf, NULL},
        {"--idle-timeout", HOPT_DOUBLE, &o->idle_timeout, 0.0, inf, NULL},
        {"--ready-file", HOPT_STR, &o->ready_file, 0, 0, NULL},
        {"--exit-on-end", HOPT_FLAG, &o->exit_on_end, 1, 0, NULL},
        {"--progress", HOPT_FLAG, &o->progress, 1, 0, NULL},
    };
    memset(o, 0, sizeof *o);
    o->in_url = "file://sim.log?speed=0";
    o->nav_rate = 50.0;
    f->lat_deg = 45.0;
    f->max_gap = -1.0;
    f->gate = 30.0;
    f->horizon = -1.0;
    f->max_outage = 10.0;
    f->alpha = 0.01;
    f->zupt_sv = -1.0;
    f->zupt_lever = -1.0;
    f->floor_sigma = -1.0;
    f->nhc_sigma = -1.0;
    f->recover = 5;
    f->window = 20;
    f->profile = HARNESS_IMU_MEMS;
    f->earth = 1;
    f->bias = 1;
    if (harness_parse_opts("se23-ins", argc, argv, opts, (int)(sizeof opts / sizeof opts[0]),
                           usage, NULL, NULL) != 0) {
        return -1;
    }
    if (f->recover < 0 || f->recover > 1000000) {
        fprintf(stderr, "se23-ins: --gate-recover must be in [0, 1e6]\n");
        return -1;
    }
    if (f->window < 2 || f->window > SE23_STATIONARY_WMAX) {
        fprintf(stderr, "se23-ins: --zupt-window must be in [2, %d]\n", SE23_STATIONARY_WMAX);
        return -1;
    }
    if (f->floor_sigma >= 0.0 && o->preset != 1) {
        fprintf(stderr, "se23-ins: --floor-sigma needs --preset foot (its step and swing)\n");
        return -1;
    }
    if (o->out_url == NULL) {
        o->out_url = strncmp(o->in_url, "file://", 7) == 0 ? "file://ins.log?mode=w" : o->in_url;
    }
    return 0;
}

/* The rotation vector of C_bv = Rz(yaw) Ry(pitch) Rx(roll) (--mount,
 * degrees); -1 after a message if the library refuses it. */
static int mount_rotation(const double rpy_deg[3], se23_vec3_t *rv)
{
    const double cr = cos(rpy_deg[0] * DEG), sr = sin(rpy_deg[0] * DEG);
    const double cp = cos(rpy_deg[1] * DEG), sp = sin(rpy_deg[1] * DEG);
    const double cy = cos(rpy_deg[2] * DEG), sy = sin(rpy_deg[2] * DEG);
    const se23_mat3_t C = {{{cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr},
                            {sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr},
                            {-sp, cp * sr, cp * cr}}};
    if (se23_so3_log(&C, rv) != SE23_OK) {
        fprintf(stderr, "se23-ins: --mount %g,%g,%g is not a usable rotation\n", rpy_deg[0],
                rpy_deg[1], rpy_deg[2]);
        return -1;
    }
    return 0;
}

/*
 * The filter's configuration (and the preset's alignment request) from the
 * options at the IMU rate [Hz], which rate_from names; -1 after a message
 * if the preset refuses the rate.
 */
static int build_config(const node_opts_t *o, double rate, const char *rate_from,
                        se23_ins_config_t *c, se23_ins_align_t *align)
{
    const filter_opts_t *f = &o->f;
    const harness_imu_profile_t *prof = harness_imu_profile(f->profile);
    int i;
    memset(c, 0, sizeof *c);
    c->noise.gyro_noise = prof->gyro_noise;
    c->noise.accel_noise = prof->accel_noise;
    c->noise.gyro_walk = prof->gyro_bias_rw;
    c->noise.accel_walk = prof->accel_bias_rw;
    c->gyro_range = prof->gyro_range;
    c->accel_range = prof->accel_range;
    c->lat = f->lat_deg * DEG;
    c->earth_rotation = f->earth;
    c->bias_states = f->bias;
    c->dt_nominal = 1.0 / rate;
    c->max_gap = f->max_gap > 0.0 ? f->max_gap : fmin(25.0 / rate, 1.0);
    if (c->max_gap < c->dt_nominal) {
        c->max_gap = c->dt_nominal;
    }
    c->max_outage = f->max_outage;
    c->outage_accel = 1.0;
    c->outage_rate = 0.05;
    for (i = 0; i < 3; i++) {
        c->lever_b.v[i] = f->lever[i];
    }
    c->gnss_gate = f->gate;
    c->gate_recover = (int)f->recover;
    /* default: 0.25 s, or what the ring holds at this rate */
    c->delay_horizon = f->horizon >= 0.0 ? f->horizon
                                         : fmin(0.25, (SE23_INS_RING - 3) * c->dt_nominal / 2.0);
    c->preint_window = f->preint;
    c->zupt = f->zupt;
    zupt_config(prof, rate, f->lat_deg * DEG, (int)f->window, f->alpha, c);
    if ((o->preset == 1 && se23_ins_preset_foot(rate, f->lat_deg * DEG, c, align) != SE23_OK) ||
        (o->preset == 2 && se23_ins_preset_car(rate, f->lat_deg * DEG, c, align) != SE23_OK)) {
        fprintf(stderr, "se23-ins: --preset %s needs an IMU rate in [50, 10000] Hz, not "
                        "%g Hz (%s)\n", o->preset == 1 ? "foot" : "car", rate, rate_from);
        return -1;
    }
    c->height = f->height;
    if (o->preset != 1) { /* the installation: the foot preset has none */
        if (mount_rotation(f->mount_deg, &c->mount_bv) != 0) {
            return -1;
        }
        c->gnss_time_offset = f->gnss_offset;
        for (i = 0; i < 3; i++) {
            c->lever_b.v[i] = f->lever[i];
        }
    }
    if (f->nhc_sigma >= 0.0) {
        c->nhc_sigma = f->nhc_sigma;
        if (c->nhc_interval <= 0.0) {
            c->nhc_interval = 1.0;
        }
    }
    if (f->zupt_sv > 0.0) {
        c->zupt_sigma_v = f->zupt_sv;
    }
    if (f->zupt_lever >= 0.0) {
        c->zupt_lever = f->zupt_lever;
    }
    if (f->floor_sigma >= 0.0) {
        c->floor_sigma = f->floor_sigma;
    }
    return 0;
}

/*
 * Sets the filter up, empty, for the IMU rate [Hz] from rate_from: the
 * configuration, the preset's alignment, the output decimation. Returns 0,
 * or -1 after saying why.
 */
static int configure(node_t *nd, double rate, const char *rate_from)
{
    se23_ins_config_t cfg;
    se23_ins_align_t align;
    se23_status_t st;
    if (build_config(&nd->o, rate, rate_from, &cfg, &align) != 0) {
        return -1;
    }
    if ((st = se23_ins_setup(&cfg, &nd->ins)) != SE23_OK) {
        fprintf(stderr, "se23-ins: invalid configuration at %g Hz (%s%s)\n", rate,
                se23_status_str(st),
                st == SE23_ERR_DIM ? ": --delay-horizon too long for the ring at this rate" : "");
        return -1;
    }
    if (nd->o.preset != 0 && se23_ins_align(&nd->ins, &align) != SE23_OK) {
        fprintf(stderr, "se23-ins: the preset's alignment request was refused\n");
        return -1;
    }
    nd->imu_rate = rate;
    nd->rate_from = rate_from;
    nd->nav_every = llround(1.0 / (cfg.dt_nominal * nd->o.nav_rate));
    if (nd->nav_every < 1) {
        nd->nav_every = 1;
    }
    return 0;
}

/* The LCM message's counters from the filter's (and the adapter's own). */
static void put_counters(const node_t *nd, se23lcm_nav_state *m)
{
    const se23_ins_counters_t *c = &nd->ins.c;
    m->n_imu_used = c->imu_used;
    m->n_imu_nonfinite = c->imu_nonfinite;
    m->n_imu_range = c->imu_range;
    m->n_imu_duplicate = c->imu_duplicate;
    m->n_imu_out_of_order = c->imu_out_of_order;
    m->n_imu_bad_time = c->imu_bad_time;
    m->n_imu_bad_dt = c->imu_bad_dt;
    m->n_imu_missing = c->imu_missing;
    m->n_imu_early = (int64_t)c->imu_early + c->imu_align;
    m->n_decode_errors = nd->decode_errors;
    m->n_gnss_used = c->gnss_used;
    m->n_gnss_rejected = (int64_t)c->gnss_early + c->gnss_nonfinite + c->gnss_stale +
                         c->gnss_gated + c->gnss_pending_dropped;
    m->n_time_resets = c->time_resets;
    m->n_filter_errors = c->filter_errors;
    m->n_init_rejected = c->init_rejected;
}

static void publish_nav(node_t *nd)
{
    static se23_gauss_t g; /* 1.9 kB: off the stack */
    se23lcm_nav_state m;
    int64_t t_ns;
    int i, j;
    nd->publish_due = 0;
    if (se23_ins_state(&nd->ins, &g, &t_ns) != SE23_OK) {
        return;
    }
    memset(&m, 0, sizeof m);
    m.t_ns = t_ns;
    m.seq = nd->ins.seq;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            m.R_nb[3 * i + j] = g.T.R.m[i][j];
        }
        m.v_n[i] = g.T.v.v[i];
        m.p_n[i] = g.T.p.v[i];
        m.b_g[i] = g.b_g.v[i];
        m.b_a[i] = g.b_a.v[i];
    }
    for (i = 0; i < g.n; i++) {
        for (j = 0; j < g.n; j++) {
            m.P[15 * i + j] = g.P.m[SE23_GAUSS_NMAX * i + j];
        }
    }
    m.status = (int32_t)nd->ins.status;
    put_counters(nd, &m);
    m.nis_last = nd->ins.nis_last;
    m.detector_stat = nd->ins.cfg.zupt ? nd->ins.det.stat : 0.0;
    se23lcm_nav_state_publish(nd->out, HARNESS_CH_NAV, &m);
}

static void publish_factor(node_t *nd, const se23_ins_factor_t *f)
{
    se23lcm_preint_factor m;
    int i, j;
    memset(&m, 0, sizeof m);
    m.t0_ns = f->t0_ns;
    m.t1_ns = f->t1_ns;
    m.seq0 = f->seq0;
    m.n_samples = (int32_t)f->f.f.n;
    m.dt_s = f->f.f.dt;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            m.dR[3 * i + j] = f->f.f.delta.R.m[i][j];
        }
        m.dv[i] = f->f.f.delta.v.v[i];
        m.dp[i] = f->f.f.delta.p.v[i];
        m.b_g_lin[i] = f->f.b_g.v[i];
        m.b_a_lin[i] = f->f.b_a.v[i];
    }
    static se23_mat9_t P; /* the paper's form, preint_factor.lcm */
    static se23_mat9x6_t J;
    const se23_status_t st = se23_preint_unc_cov(&f->f, &P, &J);
    if (st != SE23_OK) {
        fprintf(stderr, "se23-ins: factor at t0 %lld ns not published (%s)\n",
                (long long)f->t0_ns, se23_status_str(st));
        return;
    }
    for (i = 0; i < 81; i++) {
        m.cov[i] = P.m[i];
    }
    for (i = 0; i < 54; i++) {
        m.J_bias[i] = J.m[i];
    }
    se23lcm_preint_factor_publish(nd->out, HARNESS_CH_PREINT, &m);
}

static int64_t imu_rejected(const se23_ins_counters_t *c)
{
    return (int64_t)c->imu_nonfinite + c->imu_range + c->imu_duplicate + c->imu_out_of_order +
           c->imu_bad_time + c->imu_bad_dt;
}

static void progress(node_t *nd, int final)
{
    const se23_ins_counters_t *c = &nd->ins.c;
    if (!nd->o.progress) {
        return;
    }
    harness_progress(&nd->pr, final, "se23-ins: t = %7.1f s  samples %lld  rejected %lld  gnss %lld",
                     (double)nd->ins.t_ns * 1e-9, (long long)c->imu_used,
                     (long long)imu_rejected(c), (long long)c->gnss_used);
}

static void on_imu(const lcm_recv_buf_t *rb, const char *ch, void *user)
{
    static se23_ins_factor_t f; /* off the stack */
    node_t *nd = user;
    se23lcm_imu_sample m;
    se23_vec3_t w, a;
    int i;
    (void)ch;
    if (se23lcm_imu_sample_decode(rb->data, 0, (int)rb->data_size, &m) < 0) {
        nd->decode_errors++;
        return;
    }
    nd->started = 1;
    if (nd->publish_due) { /* the state at t_last, with any fix applied there */
        publish_nav(nd);
    }
    for (i = 0; i < 3; i++) {
        w.v[i] = m.omega[i];
        a.v[i] = m.accel[i];
    }
    if (se23_ins_imu(&nd->ins, m.t_ns, m.seq, &w, &a) == SE23_INS_USED &&
        nd->ins.seq % nd->nav_every == 0) {
        nd->publish_due = 1;
    }
    nd->initialised |= (nd->ins.status & SE23_INS_ST_INITIALISED) != 0; /* also aligned */
    if (se23_ins_take_factor(&nd->ins, &f)) {
        publish_factor(nd, &f);
    }
    progress(nd, 0);
}

static void on_gnss(const lcm_recv_buf_t *rb, const char *ch, void *user)
{
    node_t *nd = user;
    se23lcm_gnss_fix m;
    se23_ins_gnss_t fix;
    int i;
    (void)ch;
    if (se23lcm_gnss_fix_decode(rb->data, 0, (int)rb->data_size, &m) < 0) {
        nd->decode_errors++;
        return;
    }
    fix.t_ns = m.t_ns;
    for (i = 0; i < 3; i++) {
        fix.p_n.v[i] = m.p_n[i];
        fix.v_n.v[i] = m.v_n[i];
        fix.sigma_p.v[i] = m.sigma_p[i];
        fix.sigma_v.v[i] = m.sigma_v[i];
    }
    fix.has_vel = m.has_vel != 0;
    nd->started = 1;
    (void)se23_ins_gnss(&nd->ins, &fix);
}

static void on_init(const lcm_recv_buf_t *rb, const char *ch, void *user)
{
    static se23_gauss_t g; /* off the stack */
    node_t *nd = user;
    se23lcm_nav_state m;
    int i, j;
    (void)ch;
    if (se23lcm_nav_state_decode(rb->data, 0, (int)rb->data_size, &m) < 0) {
        nd->decode_errors++;
        return;
    }
    memset(&g, 0, sizeof g);
    g.n = nd->ins.cfg.bias_states ? SE23_GAUSS_N_BIAS : SE23_GAUSS_N_POSE;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            g.T.R.m[i][j] = m.R_nb[3 * i + j];
        }
        g.T.v.v[i] = m.v_n[i];
        g.T.p.v[i] = m.p_n[i];
        g.b_g.v[i] = m.b_g[i];
        g.b_a.v[i] = m.b_a[i];
    }
    for (i = 0; i < g.n; i++) {
        for (j = 0; j < g.n; j++) {
            g.P.m[SE23_GAUSS_NMAX * i + j] = m.P[15 * i + j];
        }
    }
    nd->started = 1;
    if (se23_ins_init(&nd->ins, m.t_ns, &g) == SE23_OK) {
        nd->publish_due = 1;
        nd->initialised = 1;
    }
}

static void on_end(const lcm_recv_buf_t *rb, const char *ch, void *user)
{
    node_t *nd = user;
    se23lcm_sim_info m;
    (void)ch;
    if (se23lcm_sim_info_decode(rb->data, 0, (int)rb->data_size, &m) < 0) {
        nd->decode_errors++;
        return;
    }
    nd->ended = 1;
}

/* How the log's rate was obtained (imu_info.lcm), for messages. */
static const char *rate_source_str(int source)
{
    switch (source) {
    case SE23LCM_IMU_INFO_RATE_MEASURED:
        return "measured from the timestamps by se23-import";
    case SE23LCM_IMU_INFO_RATE_GIVEN:
        return "given to se23-import";
    case SE23LCM_IMU_INFO_RATE_ROW_INDEX:
        return "given to se23-import, times from the row index";
    default:
        return "of unknown origin";
    }
}

/*
 * The log's rate (SE23_IMU_INFO) against the filter's. The filter's rate is
 * fixed once --imu-rate gave it or an input reached the filter: the log's
 * must then agree within RATE_TOLERANCE. Otherwise the filter is set up
 * again, for the log's rate. Returns 0, or -1 after saying why the log's
 * rate is refused.
 */
static int take_log_rate(node_t *nd, const se23lcm_imu_info *m)
{
    const char *how = rate_source_str(m->rate_source);
    double off;
    if (!(m->rate_hz >= 1.0 && m->rate_hz <= 1e5)) {
        fprintf(stderr, "se23-ins: the log's IMU rate (SE23_IMU_INFO, %s) is %g Hz, outside 1 "
                        "to 1e5 Hz: refused\n", how, m->rate_hz);
        return -1;
    }
    nd->log_rate = m->rate_hz;
    if (nd->o.f.imu_rate <= 0.0 && !nd->started) {
        return configure(nd, m->rate_hz, "SE23_IMU_INFO");
    }
    off = fabs(nd->imu_rate / m->rate_hz - 1.0);
    if (off <= RATE_TOLERANCE) {
        return 0;
    }
    if (nd->o.f.imu_rate > 0.0) {
        fprintf(stderr, "se23-ins: --imu-rate %g Hz contradicts the log's %g Hz", nd->imu_rate,
                m->rate_hz);
    } else {
        fprintf(stderr, "se23-ins: the log's %g Hz comes after inputs the filter took at %g Hz "
                        "(%s) and contradicts it", m->rate_hz, nd->imu_rate, nd->rate_from);
    }
    fprintf(stderr, " (SE23_IMU_INFO, %s) by %.2g %%, more than %g %%: refused\n", how,
            100.0 * off, 100.0 * RATE_TOLERANCE);
    return -1;
}

static void on_info(const lcm_recv_buf_t *rb, const char *ch, void *user)
{
    node_t *nd = user;
    se23lcm_imu_info m;
    (void)ch;
    if (se23lcm_imu_info_decode(rb->data, 0, (int)rb->data_size, &m) < 0) {
        nd->decode_errors++;
        return;
    }
    if (take_log_rate(nd, &m) != 0) {
        nd->rate_refused = 1;
    }
}

static double cpu_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void summary(const node_t *nd, int64_t skipped, double cpu_s)
{
    const se23_ins_counters_t *c = &nd->ins.c;
    const struct {
        const char *name;
        uint32_t n;
    } rows[] = {
        {"imu_used", c->imu_used},
        {"imu_nonfinite", c->imu_nonfinite},
        {"imu_range", c->imu_range},
        {"imu_duplicate", c->imu_duplicate},
        {"imu_out_of_order", c->imu_out_of_order},
        {"imu_bad_time", c->imu_bad_time},
        {"imu_bad_dt", c->imu_bad_dt},
        {"imu_missing", c->imu_missing},
        {"imu_seq_jumps", c->imu_seq_jumps},
        {"imu_early", c->imu_early},
        {"imu_align", c->imu_align},
        {"imu_failed", c->imu_failed},
        {"gnss_used", c->gnss_used},
        {"gnss_delayed", c->gnss_delayed},
        {"gnss_early", c->gnss_early},
        {"gnss_nonfinite", c->gnss_nonfinite},
        {"gnss_stale", c->gnss_stale},
        {"gnss_gated", c->gnss_gated},
        {"gnss_pending_dropped", c->gnss_pending_dropped},
        {"gnss_failed", c->gnss_failed},
        {"gate_resets", c->gate_resets},
        {"course_headings", c->course_headings},
        {"zupt_used", c->zupt_used},
        {"zaru_used", c->zaru_used},
        {"floor_used", c->floor_used},
        {"floor_levels", c->floor_levels},
        {"nhc_used", c->nhc_used},
        {"time_resets", c->time_resets},
        {"filter_errors", c->filter_errors},
        {"init_rejected", c->init_rejected},
    };
    size_t k;
    printf("se23-ins: input accounting\n");
    for (k = 0; k < sizeof rows / sizeof rows[0]; k++) {
        printf("  %-20s %lld\n", rows[k].name, (long long)rows[k].n);
    }
    printf("  %-20s %lld\n", "gnss_rejected",
           (long long)c->gnss_early + c->gnss_nonfinite + c->gnss_stale + c->gnss_gated +
               c->gnss_pending_dropped);
    printf("  %-20s %lld\n", "decode_errors", (long long)nd->decode_errors);
    printf("  %-20s %lld\n", "log_skipped_bytes", (long long)skipped);
    printf("  %-20s %.3f\n", "zupt_nis_mean",
           c->zupt_used > 0U ? (double)nd->ins.zupt_nis_sum / (double)c->zupt_used : 0.0);
    printf("  %-20s 0x%03x\n", "status", (unsigned)nd->ins.status);
    printf("  %-20s %.3f\n", "imu_rate_hz", nd->imu_rate);
    printf("  %-20s %s\n", "imu_rate_from", nd->rate_from);
    printf("  %-20s %.3f\n", "log_imu_rate_hz", nd->log_rate);
    /* the white noise propagated: configured, or measured at the alignment */
    printf("  %-20s %.5f\n", "gyro_noise_dps_rthz", (double)nd->ins.noise.gyro_noise / DEG);
    printf("  %-20s %.1f\n", "accel_noise_ug_rthz",
           (double)nd->ins.noise.accel_noise / 9.80665 * 1e6);
    printf("  %-20s %.3f\n", "cpu_seconds", cpu_s);
    printf("  %-20s %.0f\n", "samples_per_s", cpu_s > 0.0 ? (double)c->imu_used / cpu_s : 0.0);
}

static const replay_sub_t subs[] = {
    {HARNESS_CH_IMU_INFO, on_info, 0},
    {HARNESS_CH_IMU, on_imu, 10000},
    {HARNESS_CH_GNSS, on_gnss, 1000},
    {HARNESS_CH_INIT, on_init, 0},
    {HARNESS_CH_SIM_END, on_end, 0},
};
#define N_SUBS ((int)(sizeof subs / sizeof subs[0]))

static int should_stop(void *user)
{
    const node_t *nd = user;
    return harness_stop_requested() || (nd->o.exit_on_end && nd->ended) || nd->rate_refused;
}

static void ready(const node_t *nd)
{
    if (nd->o.ready_file != NULL) {
        FILE *rf = fopen(nd->o.ready_file, "w");
        if (rf != NULL) {
            fclose(rf);
        }
    }
}

/* Live input from in until a stop, an error or the idle timeout. */
static void run_live(node_t *nd, lcm_t *in)
{
    int64_t last_input;
    int k;
    for (k = 0; k < N_SUBS; k++) {
        lcm_subscription_t *s = lcm_subscribe(in, subs[k].channel, subs[k].handler, nd);
        if (subs[k].queue_capacity > 0) {
            lcm_subscription_set_queue_capacity(s, subs[k].queue_capacity);
        }
    }
    ready(nd);
    last_input = harness_now_ns();
    while (!should_stop(nd)) {
        int rc = lcm_handle_timeout(in, 200);
        if (rc < 0) {
            break;
        }
        if (rc > 0) {
            last_input = harness_now_ns();
        } else if (nd->o.idle_timeout > 0.0 &&
                   (double)(harness_now_ns() - last_input) * 1e-9 > nd->o.idle_timeout) {
            break;
        }
    }
}

/* 1 (after saying why on stderr) if the input ended and the filter never
 * had a state: no navigation came out of the run. */
static int never_initialised(const node_t *nd)
{
    if (nd->initialised) {
        return 0;
    }
    fprintf(stderr, "se23-ins: the input ended and the filter never initialised: %s (%lld IMU "
                    "samples not used)\n",
            nd->o.preset != 0 ? "no rest long enough for the preset's static alignment"
                              : "no initial state (SE23_INIT) accepted",
            (long long)nd->ins.c.imu_early + nd->ins.c.imu_align);
    return 1;
}

/*
 * Exit status: 0; 1 if the input or the output cannot be opened; 2 usage or
 * configuration; 3 the input log was corrupt and bytes of it were skipped
 * (log_skipped_bytes in the summary); 4 the filter never initialised (no
 * initial state accepted, or the preset's alignment never found its rest);
 * 5 (EXIT_RATE_REFUSED) the log's IMU rate (SE23_IMU_INFO) cannot be used:
 * it contradicts --imu-rate, or the rate the filter already ran at, by more
 * than RATE_TOLERANCE, or the configuration refuses it (the run stops there,
 * without a summary).
 */
int main(int argc, char **argv)
{
    static node_t nd; /* large (the filter holds covariances): not on the stack */
    lcm_t *in = NULL;
    int64_t skipped = 0;
    int no_state = 0; /* the filter never initialised */
    double cpu0;

    if (parse_args(argc, argv, &nd.o) != 0) {
        usage(stderr);
        return 2;
    }
    /* the rate until the log's SE23_IMU_INFO, if any, says otherwise */
    if (nd.o.f.imu_rate > 0.0 ? configure(&nd, nd.o.f.imu_rate, "--imu-rate") != 0
                              : configure(&nd, DEFAULT_IMU_RATE, "default") != 0) {
        return 2;
    }
    harness_progress_init(&nd.pr);
    if (strncmp(nd.o.in_url, "file://", 7) != 0) {
        in = lcm_create(nd.o.in_url);
        if (in == NULL) {
            fprintf(stderr, "se23-ins: cannot open %s\n", nd.o.in_url);
            return 1;
        }
    }
    nd.out = in != NULL && strcmp(nd.o.in_url, nd.o.out_url) == 0 ? in : lcm_create(nd.o.out_url);
    if (nd.out == NULL) {
        fprintf(stderr, "se23-ins: cannot open %s\n", nd.o.out_url);
        if (in != NULL) {
            lcm_destroy(in);
        }
        return 1;
    }
    harness_catch_stop_signals();
    cpu0 = cpu_seconds();
    if (in != NULL) {
        run_live(&nd, in);
    } else {
        ready(&nd);
        skipped = replay_file(nd.o.in_url, subs, N_SUBS, &nd, should_stop);
    }
    if (skipped >= 0 && !nd.rate_refused) {
        publish_nav(&nd); /* the final state */
        progress(&nd, 1);
        summary(&nd, skipped, cpu_seconds() - cpu0);
        no_state = never_initialised(&nd);
    }
    if (nd.out != in) {
        lcm_destroy(nd.out);
    }
    if (in != NULL) {
        lcm_destroy(in);
    }
    if (nd.rate_refused) {
        return EXIT_RATE_REFUSED;
    }
    return skipped < 0 ? 1 : skipped > 0 ? 3 : no_state ? 4 : 0;
}
