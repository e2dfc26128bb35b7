/*
 * se23-ins: the INS node. Subscribes to IMU samples, GNSS fixes and the
 * initial state over LCM, runs the se23 library (ins.h), and publishes the
 * navigation state with its 15x15 covariance and, on request,
 * preintegrated factors. Prints an accounting of every input at the end.
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
#include "ins.h"
#include "replay.h"
#include "se23lcm_gnss_fix.h"
#include "se23lcm_imu_sample.h"
#include "se23lcm_nav_state.h"
#include "se23lcm_preint_factor.h"
#include "se23lcm_sim_info.h"

#define DEG (3.14159265358979323846 / 180.0)

typedef struct {
    const char *in_url;
    const char *out_url;
    double nav_rate;
    int progress;
    int exit_on_end;
    double idle_timeout; /* live: stop after this long without input [s] */
    const char *ready_file;
} node_opts_t;

typedef struct {
    ins_t ins;
    node_opts_t o;
    lcm_t *out;
    int64_t nav_every; /* publish when seq % nav_every == 0 */
    int publish_due;
    int ended;
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
            "  --imu-rate HZ         nominal IMU rate (200)\n"
            "  --earth on|off        rotating-Earth model (on)\n"
            "  --lat DEG             latitude of the nav-frame origin (45)\n"
            "  --bias-states on|off  15-state filter with bias states (on)\n"
            "  --nav-rate HZ         nav_state output rate (50)\n"
            "  --gate X              chi-square gate on GNSS innovations, 0 = none (30)\n"
            "  --max-gap S           longest interval one sample may bridge (25 samples)\n"
            "  --max-outage S        longest outage carried across (10)\n"
            "  --preint S            publish preintegrated factors of S seconds (0 = off)\n"
            "  --exit-on-end         stop when SE23_SIM_END arrives (live runs)\n"
            "  --idle-timeout S      live runs: stop after S s without input (0 = never)\n"
            "  --ready-file PATH     create PATH once subscribed (scripts wait for it)\n"
            "  --progress            progress line on stderr\n");
}

static int parse_args(int argc, char **argv, node_opts_t *o, ins_config_t *c)
{
    const double inf = HUGE_VAL;
    double rate = 200.0, lat_deg = 45.0, max_gap = -1.0;
    int profile = HARNESS_IMU_MEMS;
    const harness_imu_profile_t *prof;
    const harness_opt_t opts[] = {
        {"--in", HOPT_STR, &o->in_url, 0, 0, NULL},
        {"--out", HOPT_STR, &o->out_url, 0, 0, NULL},
        {"--imu", HOPT_CHOICE, &profile, 0, 0, harness_imu_profile_find},
        {"--imu-rate", HOPT_DOUBLE, &rate, 1.0, 1e5, NULL},
        {"--earth", HOPT_CHOICE, &c->earth_rotation, 0, 0, harness_on_off},
        {"--lat", HOPT_DOUBLE, &lat_deg, -90.0, 90.0, NULL},
        {"--bias-states", HOPT_CHOICE, &c->bias_states, 0, 0, harness_on_off},
        {"--nav-rate", HOPT_DOUBLE, &o->nav_rate, 1e-3, inf, NULL},
        {"--gate", HOPT_DOUBLE, &c->gnss_gate, 0.0, inf, NULL},
        {"--max-gap", HOPT_DOUBLE, &max_gap, 1e-6, 1.0, NULL},
        {"--max-outage", HOPT_DOUBLE, &c->max_outage, 0.0, inf, NULL},
        {"--preint", HOPT_DOUBLE, &c->preint_window, 0.0, inf, NULL},
        {"--idle-timeout", HOPT_DOUBLE, &o->idle_timeout, 0.0, inf, NULL},
        {"--ready-file", HOPT_STR, &o->ready_file, 0, 0, NULL},
        {"--exit-on-end", HOPT_FLAG, &o->exit_on_end, 1, 0, NULL},
        {"--progress", HOPT_FLAG, &o->progress, 1, 0, NULL},
    };
    o->in_url = "file://sim.log?speed=0";
    o->out_url = NULL;
    o->nav_rate = 50.0;
    o->progress = 0;
    o->exit_on_end = 0;
    o->idle_timeout = 0.0;
    o->ready_file = NULL;
    memset(c, 0, sizeof *c);
    c->earth_rotation = 1;
    c->bias_states = 1;
    c->max_outage = 10.0;
    c->outage_accel = 1.0;
    c->outage_rate = 0.05;
    c->gnss_gate = 30.0;
    if (harness_parse_opts("se23-ins", argc, argv, opts, (int)(sizeof opts / sizeof opts[0]),
                           usage, NULL, NULL) != 0) {
        return -1;
    }
    prof = harness_imu_profile(profile);
    if (o->out_url == NULL) {
        o->out_url = strncmp(o->in_url, "file://", 7) == 0 ? "file://ins.log?mode=w" : o->in_url;
    }
    c->noise.gyro_noise = prof->gyro_noise;
    c->noise.accel_noise = prof->accel_noise;
    c->noise.gyro_walk = prof->gyro_bias_rw;
    c->noise.accel_walk = prof->accel_bias_rw;
    c->gyro_range = prof->gyro_range;
    c->accel_range = prof->accel_range;
    c->lat = lat_deg * DEG;
    c->dt_nominal = 1.0 / rate;
    c->max_gap = max_gap > 0.0 ? max_gap : fmin(25.0 / rate, 1.0);
    if (c->max_gap < c->dt_nominal) {
        c->max_gap = c->dt_nominal;
    }
    return 0;
}

static void publish_nav(node_t *nd)
{
    ins_output_t out;
    se23lcm_nav_state m;
    const ins_counters_t *c = &nd->ins.c;
    nd->publish_due = 0;
    if (ins_output(&nd->ins, &out) != 0) {
        return;
    }
    memset(&m, 0, sizeof m);
    m.t_ns = out.t_ns;
    m.seq = out.seq;
    memcpy(m.R_nb, out.R_nb, sizeof m.R_nb);
    memcpy(m.v_n, out.v_n, sizeof m.v_n);
    memcpy(m.p_n, out.p_n, sizeof m.p_n);
    memcpy(m.b_g, out.b_g, sizeof m.b_g);
    memcpy(m.b_a, out.b_a, sizeof m.b_a);
    memcpy(m.P, out.P, sizeof m.P);
    m.status = out.status;
    m.n_imu_used = c->imu_used;
    m.n_imu_nonfinite = c->imu_nonfinite;
    m.n_imu_range = c->imu_range;
    m.n_imu_duplicate = c->imu_duplicate;
    m.n_imu_out_of_order = c->imu_out_of_order;
    m.n_imu_bad_time = c->imu_bad_time;
    m.n_imu_bad_dt = c->imu_bad_dt;
    m.n_imu_missing = c->imu_missing;
    m.n_imu_early = c->imu_early;
    m.n_decode_errors = c->decode_errors;
    m.n_gnss_used = c->gnss_used;
    m.n_gnss_rejected = c->gnss_rejected;
    m.n_time_resets = c->time_resets;
    m.n_filter_errors = c->filter_errors;
    m.n_init_rejected = c->init_rejected;
    m.nis_last = out.nis_last;
    se23lcm_nav_state_publish(nd->out, HARNESS_CH_NAV, &m);
}

static void publish_factor(node_t *nd, const ins_factor_t *f)
{
    se23lcm_preint_factor m;
    int i, j;
    memset(&m, 0, sizeof m);
    m.t0_ns = f->t0_ns;
    m.t1_ns = f->t1_ns;
    m.seq0 = f->seq0;
    m.n_samples = (int32_t)f->f.n;
    m.dt_s = f->f.dt;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            m.dR[3 * i + j] = f->f.delta.R.m[i][j];
        }
        m.dv[i] = f->f.delta.v.v[i];
        m.dp[i] = f->f.delta.p.v[i];
        m.b_g_lin[i] = f->b_g_lin[i];
        m.b_a_lin[i] = f->b_a_lin[i];
    }
    for (i = 0; i < 81; i++) {
        m.cov[i] = f->cov.m[i];
    }
    for (i = 0; i < 54; i++) {
        m.J_bias[i] = f->J.m[i];
    }
    se23lcm_preint_factor_publish(nd->out, HARNESS_CH_PREINT, &m);
}

static void progress(node_t *nd, int final)
{
    const ins_counters_t *c = &nd->ins.c;
    if (!nd->o.progress) {
        return;
    }
    harness_progress(&nd->pr, final, "se23-ins: t = %7.1f s  samples %lld  rejected %lld  gnss %lld",
                     (double)nd->ins.t_ns * 1e-9, (long long)c->imu_used,
                     (long long)(c->imu_nonfinite + c->imu_range + c->imu_duplicate +
                                 c->imu_out_of_order + c->imu_bad_time + c->imu_bad_dt),
                     (long long)c->gnss_used);
}

static void on_imu(const lcm_recv_buf_t *rb, const char *ch, void *user)
{
    node_t *nd = user;
    se23lcm_imu_sample m;
    (void)ch;
    if (se23lcm_imu_sample_decode(rb->data, 0, (int)rb->data_size, &m) < 0) {
        ins_decode_error(&nd->ins);
        return;
    }
    if (nd->publish_due) { /* the state at t_last, with any fix applied there */
        publish_nav(nd);
    }
    if (ins_imu(&nd->ins, m.t_ns, m.seq, m.omega, m.accel) && nd->ins.seq % nd->nav_every == 0) {
        nd->publish_due = 1;
    }
    {
        ins_factor_t f;
        if (ins_take_factor(&nd->ins, &f)) {
            publish_factor(nd, &f);
        }
    }
    progress(nd, 0);
}

static void on_gnss(const lcm_recv_buf_t *rb, const char *ch, void *user)
{
    node_t *nd = user;
    se23lcm_gnss_fix m;
    ins_gnss_t fix;
    (void)ch;
    if (se23lcm_gnss_fix_decode(rb->data, 0, (int)rb->data_size, &m) < 0) {
        ins_decode_error(&nd->ins);
        return;
    }
    fix.t_ns = m.t_ns;
    memcpy(fix.p_n, m.p_n, sizeof fix.p_n);
    memcpy(fix.v_n, m.v_n, sizeof fix.v_n);
    memcpy(fix.sigma_p, m.sigma_p, sizeof fix.sigma_p);
    memcpy(fix.sigma_v, m.sigma_v, sizeof fix.sigma_v);
    fix.has_vel = m.has_vel != 0;
    ins_gnss(&nd->ins, &fix);
}

static void on_init(const lcm_recv_buf_t *rb, const char *ch, void *user)
{
    node_t *nd = user;
    se23lcm_nav_state m;
    ins_init_t init;
    (void)ch;
    if (se23lcm_nav_state_decode(rb->data, 0, (int)rb->data_size, &m) < 0) {
        ins_decode_error(&nd->ins);
        return;
    }
    init.t_ns = m.t_ns;
    memcpy(init.R_nb, m.R_nb, sizeof init.R_nb);
    memcpy(init.v_n, m.v_n, sizeof init.v_n);
    memcpy(init.p_n, m.p_n, sizeof init.p_n);
    memcpy(init.b_g, m.b_g, sizeof init.b_g);
    memcpy(init.b_a, m.b_a, sizeof init.b_a);
    memcpy(init.P, m.P, sizeof init.P);
    if (ins_init(&nd->ins, &init) == 0) {
        nd->publish_due = 1;
    }
}

static void on_end(const lcm_recv_buf_t *rb, const char *ch, void *user)
{
    node_t *nd = user;
    se23lcm_sim_info m;
    (void)ch;
    if (se23lcm_sim_info_decode(rb->data, 0, (int)rb->data_size, &m) < 0) {
        ins_decode_error(&nd->ins);
        return;
    }
    nd->ended = 1;
}

static double cpu_seconds(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void summary(const node_t *nd, int64_t skipped, double cpu_s)
{
    const ins_counters_t *c = &nd->ins.c;
    printf("se23-ins: input accounting\n");
    printf("  imu_used          %lld\n", (long long)c->imu_used);
    printf("  imu_nonfinite     %lld\n", (long long)c->imu_nonfinite);
    printf("  imu_range         %lld\n", (long long)c->imu_range);
    printf("  imu_duplicate     %lld\n", (long long)c->imu_duplicate);
    printf("  imu_out_of_order  %lld\n", (long long)c->imu_out_of_order);
    printf("  imu_bad_time      %lld\n", (long long)c->imu_bad_time);
    printf("  imu_bad_dt        %lld\n", (long long)c->imu_bad_dt);
    printf("  imu_missing       %lld\n", (long long)c->imu_missing);
    printf("  imu_early         %lld\n", (long long)c->imu_early);
    printf("  decode_errors     %lld\n", (long long)c->decode_errors);
    printf("  gnss_used         %lld\n", (long long)c->gnss_used);
    printf("  gnss_rejected     %lld\n", (long long)c->gnss_rejected);
    printf("  time_resets       %lld\n", (long long)c->time_resets);
    printf("  filter_errors     %lld\n", (long long)c->filter_errors);
    printf("  init_rejected     %lld\n", (long long)c->init_rejected);
    printf("  log_skipped_bytes %lld\n", (long long)skipped);
    printf("  status            0x%02x\n", (unsigned)nd->ins.status);
    printf("  cpu_seconds       %.3f\n", cpu_s);
    printf("  samples_per_s     %.0f\n", cpu_s > 0.0 ? (double)c->imu_used / cpu_s : 0.0);
}

static const replay_sub_t subs[] = {
    {HARNESS_CH_IMU, on_imu, 10000},
    {HARNESS_CH_GNSS, on_gnss, 1000},
    {HARNESS_CH_INIT, on_init, 0},
    {HARNESS_CH_SIM_END, on_end, 0},
};
#define N_SUBS ((int)(sizeof subs / sizeof subs[0]))

static int should_stop(void *user)
{
    const node_t *nd = user;
    return harness_stop_requested() || (nd->o.exit_on_end && nd->ended);
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

/*
 * Exit status: 0; 1 if the input or the output cannot be opened; 2 usage or
 * configuration; 3 the input log was corrupt and bytes of it were skipped
 * (log_skipped_bytes in the summary).
 */
int main(int argc, char **argv)
{
    static node_t nd; /* large (ins_t holds covariances): not on the stack */
    ins_config_t cfg;
    lcm_t *in = NULL;
    int64_t skipped = 0;
    double cpu0;

    if (parse_args(argc, argv, &nd.o, &cfg) != 0) {
        usage(stderr);
        return 2;
    }
    if (ins_setup(&nd.ins, &cfg) != 0) {
        fprintf(stderr, "se23-ins: invalid configuration\n");
        return 2;
    }
    harness_progress_init(&nd.pr);
    nd.nav_every = llround(1.0 / (cfg.dt_nominal * nd.o.nav_rate));
    if (nd.nav_every < 1) {
        nd.nav_every = 1;
    }
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
    if (skipped >= 0) {
        publish_nav(&nd); /* the final state */
        progress(&nd, 1);
        summary(&nd, skipped, cpu_seconds() - cpu0);
    }
    if (nd.out != in) {
        lcm_destroy(nd.out);
    }
    if (in != NULL) {
        lcm_destroy(in);
    }
    return skipped < 0 ? 1 : skipped > 0 ? 3 : 0;
}
