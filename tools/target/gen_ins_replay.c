/*
 * gen_ins_replay [--corrupt] > ins_replay_data.c
 *
 * The recorded sequences of the navigation-filter replay on the target
 * (tests/target/ins_replay.c, format in tests/target/ins_replay.h), and
 * their reference outputs from the same filter (src/nav/ins*.c, the host's
 * double build, driven by the same tests/target/ins_replay_drive.c).
 *
 * The sequences (deterministic: fixed seeds, no clock):
 *   flat      flat Earth, 15 states, se23_ins_init at t = 0
 *   rotating  rotating Earth (WGS-84 gravity and Earth rate at 0.8 rad),
 *             15 states, static alignment over 0.5 s (se23_ins_align,
 *             heading given, gyro bias measured; fixes before it are early)
 * each 15 s of 200 Hz IMU samples of one motion: at rest for 2 s (tilted,
 * zero-velocity and zero-rate updates from the detector), then an
 * accelerating turn (0.8 m/s^2 along track from rest, 0.15 rad/s yaw rate,
 * a 4 deg roll oscillation, a 1.5 m vertical swing); true biases; white
 * noise (1e-3 rad/s, 1e-2 m/s^2 per sample). GNSS position and velocity of
 * an antenna at a lever arm, 5 Hz, each delivered 100 ms after its time
 * (the delayed-fix path: snapshot and replay); a preintegrated factor every
 * 1 s (flat) / 0.5 s (rotating), taken after every sample.
 *
 * Every input real is rounded to float, so that the host's double run, the
 * float and the double target see exactly the same inputs (the float
 * target's deviation is then its arithmetic alone).
 *
 * The generator refuses to write a reference (exit 1) unless the run keeps
 * away from every decision a rounding could flip: at rest, both of the
 * filter's rest tests (SHOE on the corrected readings, and the window's
 * mean acceleration against its covariance, recomputed from the filter's
 * state by insr_accel_nis and checked against every flag it set) at most half
 * their thresholds; in motion, one of them at least twice its threshold;
 * every fix fused with a NIS (position + velocity, so each part too) below
 * half the gate. Its margins and the filter's error against the truth go to
 * stderr. --corrupt perturbs three reference values (a position of the
 * flat sequence's last checkpoint, a counter of the rotating sequence's
 * fourth, the first detector threshold by 1e-3): the image built from it
 * must fail exactly those 3 checks.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "gen_print.h"
#include "ins_replay.h"
#include "se23/earth.h"
#include "se23/so3.h"
#include "se23_rng.h"

#define RATE 200.0
#define DT_NS 5000000LL
#define N_IMU 3000      /* 15 s */
#define T_MOVE 2.0      /* end of the rest phase [s] */
#define FIX_EVERY 40    /* samples between fixes (5 Hz) */
#define FIX_LATENCY 20  /* samples between a fix's time and its delivery (100 ms) */
#define N_FIX_MAX 80
#define N_CHECK 7
#define SIG_G 1e-3      /* gyro noise of one sample [rad/s] */
#define SIG_A 1e-2      /* accel noise of one sample [m/s^2] */
/* Distance of every decision to its threshold, as a factor: the float
 * build's statistics deviate by < 1e-3 relative, so 2 is generous. */
#define MARGIN 2.0

static const double check_times[N_CHECK] = {1.0, 2.0, 4.0, 7.0, 10.0, 13.0, 15.0};

/* Everything rounded to float (see the file comment). */
static double q(double x)
{
    return (double)(float)x;
}

/* ---- small 3-vector algebra ------------------------------------------- */

typedef struct {
    double m[3][3];
} m3;

static m3 mul(const m3 *a, const m3 *b)
{
    m3 c;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            c.m[i][j] = a->m[i][0] * b->m[0][j] + a->m[i][1] * b->m[1][j] + a->m[i][2] * b->m[2][j];
        }
    }
    return c;
}

static m3 rot(int axis, double a)
{
    m3 r;
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    memset(&r, 0, sizeof r);
    r.m[axis][axis] = 1.0;
    r.m[i][i] = cos(a);
    r.m[j][j] = cos(a);
    r.m[i][j] = -sin(a);
    r.m[j][i] = sin(a);
    return r;
}

/* y = A^T x */
static void mul_t(const m3 *a, const double x[3], double y[3])
{
    for (int i = 0; i < 3; ++i) {
        y[i] = a->m[0][i] * x[0] + a->m[1][i] * x[1] + a->m[2][i] * x[2];
    }
}

static void mul_v(const m3 *a, const double x[3], double y[3])
{
    for (int i = 0; i < 3; ++i) {
        y[i] = a->m[i][0] * x[0] + a->m[i][1] * x[1] + a->m[i][2] * x[2];
    }
}

static void cross(const double a[3], const double b[3], double c[3])
{
    c[0] = a[1] * b[2] - a[2] * b[1];
    c[1] = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
}

/* ---- the truth ---------------------------------------------------------- */

#define DEG (3.14159265358979323846 / 180.0)
static const double PSI0 = 0.6, THETA0 = -3.0 * DEG, PHI0 = 2.0 * DEG;
static const double P0[3] = {120.0, -45.0, -3.0};
static const double ACC = 0.8, OMEGA = 0.15;   /* along-track accel, yaw rate */
static const double ROLL_AMP = 4.0 * DEG, ROLL_W = 1.2;
static const double VERT_AMP = 1.5, VERT_W = 0.4;
static const double BIAS_G[3] = {3e-4, -2e-4, 4e-4}; /* measured = true - bias */
static const double BIAS_A[3] = {0.03, -0.02, 0.01};
static const double LEVER[3] = {0.8, -0.3, -1.2};

typedef struct {
    m3 R;            /* body -> nav */
    double w_nb[3];  /* body rate w.r.t. the nav frame, body frame */
    double v[3], p[3], a[3];
} truth_t;

static void truth(double t, truth_t *o)
{
    const double tau = t > T_MOVE ? t - T_MOVE : 0.0;
    const int moving = t > T_MOVE;
    const double psi = PSI0 + OMEGA * tau;
    const double phi = PHI0 + ROLL_AMP * sin(ROLL_W * tau);
    const double psi_dot = moving ? OMEGA : 0.0;
    const double phi_dot = moving ? ROLL_AMP * ROLL_W * cos(ROLL_W * tau) : 0.0;
    const m3 Rz = rot(2, psi), Ry = rot(1, THETA0), Rx = rot(0, phi);
    const m3 Rzy = mul(&Rz, &Ry);
    const m3 Ryx = mul(&Ry, &Rx);
    const double ez[3] = {0.0, 0.0, psi_dot};
    double c, s, re, im;
    o->R = mul(&Rzy, &Rx);
    /* w_nb = (Ry Rx)^T (0, 0, psi_dot) + (phi_dot, 0, 0) */
    mul_t(&Ryx, ez, o->w_nb);
    o->w_nb[0] += phi_dot;
    /* horizontal: speed ACC tau along the heading psi; position in closed
     * form, p = p0 + ACC e^{i psi0} [tau e^{i w tau} / (i w) + (e^{i w tau} - 1) / w^2] */
    c = cos(OMEGA * tau);
    s = sin(OMEGA * tau);
    re = tau * s / OMEGA + (c - 1.0) / (OMEGA * OMEGA);
    im = -tau * c / OMEGA + s / (OMEGA * OMEGA);
    o->p[0] = P0[0] + ACC * (cos(PSI0) * re - sin(PSI0) * im);
    o->p[1] = P0[1] + ACC * (sin(PSI0) * re + cos(PSI0) * im);
    o->v[0] = ACC * tau * cos(psi);
    o->v[1] = ACC * tau * sin(psi);
    o->a[0] = moving ? ACC * cos(psi) - ACC * tau * OMEGA * sin(psi) : 0.0;
    o->a[1] = moving ? ACC * sin(psi) + ACC * tau * OMEGA * cos(psi) : 0.0;
    /* vertical (NED, down): up by VERT_AMP (1 - cos) */
    o->p[2] = P0[2] - VERT_AMP * (1.0 - cos(VERT_W * tau));
    o->v[2] = -VERT_AMP * VERT_W * sin(VERT_W * tau);
    o->a[2] = moving ? -VERT_AMP * VERT_W * VERT_W * cos(VERT_W * tau) : 0.0;
}

/* ---- one sequence ------------------------------------------------------- */

typedef struct {
    const char *name;
    int rotating, align;
    double preint_window;
    uint64_t seed;
    insr_imu_t imu[N_IMU];
    insr_fix_t fix[N_FIX_MAX];
    insr_check_t check[N_CHECK], got[N_CHECK];
    insr_seq_t seq;
    /* margins seen by the hook */
    se23_gauss_t prev;   /* the filter's state before the current sample */
    int aligning;        /* the samples still go to the alignment */
    double stat_rest_max, acc_rest_max, move_min, nis_max;
    int n_align, n_rest, n_move, bad;
} gen_seq_t;

static void config(const gen_seq_t *g, se23_ins_config_t *c)
{
    double grav;
    memset(c, 0, sizeof *c);
    c->noise.gyro_noise = q(SIG_G / sqrt(RATE));
    c->noise.accel_noise = q(SIG_A / sqrt(RATE));
    c->noise.gyro_walk = q(1e-6);
    c->noise.accel_walk = q(1e-5);
    c->gyro_range = q(30.0);
    c->accel_range = q(150.0);
    c->lat = q(0.8);
    c->earth_rotation = g->rotating;
    c->bias_states = 1;
    c->dt_nominal = q(1.0 / RATE);
    c->max_gap = q(0.05);
    c->max_outage = q(10.0);
    c->outage_accel = q(1.0);
    c->outage_rate = q(0.05);
    for (int i = 0; i < 3; ++i) {
        c->lever_b.v[i] = q(LEVER[i]);
    }
    c->gnss_gate = q(30.0);
    c->gate_recover = 5;
    c->delay_horizon = q(0.25);
    c->preint_window = q(g->preint_window);
    c->zupt = 1;
    c->detector.window = 20;
    c->detector.sigma_a = q(2.0 * SIG_A); /* raised above the white noise: margin */
    c->detector.sigma_g = q(2.0 * SIG_G);
    (void)se23_earth_gravity(c->lat, 0.0, &grav);
    c->detector.gravity = q(grav);
    c->detector.threshold = q(12.0);
    c->zupt_sigma_v = q(0.01);
    c->zaru_sigma_w = q(1e-3);
    c->zaru_after = q(g->rotating ? 0.25 : 0.0); /* rotating: ZARU after 0.25 s of rest */
}

static void start(const gen_seq_t *g, insr_start_t *s)
{
    truth_t t0;
    m3 E, Rs;
    truth(0.0, &t0);
    memset(s, 0, sizeof *s);
    if (g->align) {
        s->align = 1;
        for (int i = 0; i < 3; ++i) {
            s->a.p_n.v[i] = q(t0.p[i] + (i == 2 ? -0.2 : 0.5));
        }
        s->a.sigma_p = q(2.0);
        s->a.yaw = q(PSI0 + 3.0 * DEG);
        s->a.sigma_yaw = q(5.0 * DEG);
        s->a.gyrocompass = 0;
        s->a.sigma_v = q(0.05);
        s->a.sigma_bg = q(1e-3);
        s->a.sigma_ba = q(0.05);
        s->a.duration = q(0.5);
        return;
    }
    /* init at t = 0: the truth off by (0.5, -0.4, 3) deg (body frame), 1 m */
    {
        const m3 a = rot(0, 0.5 * DEG), b = rot(1, -0.4 * DEG), c = rot(2, 3.0 * DEG);
        const m3 ab = mul(&a, &b);
        E = mul(&ab, &c);
    }
    Rs = mul(&t0.R, &E);
    s->t0_ns = 0;
    {
        /* as a rotation vector: a float-rounded R would not be a rotation
         * to the double build's tolerance */
        se23_mat3_t R;
        se23_vec3_t phi;
        memcpy(R.m, Rs.m, sizeof R.m);
        (void)se23_so3_log(&R, &phi);
        for (int i = 0; i < 3; ++i) {
            s->phi[i] = q(phi.v[i]);
        }
    }
    for (int i = 0; i < 3; ++i) {
        s->p[i] = q(t0.p[i] + (i == 0 ? 1.0 : (i == 1 ? -0.5 : 0.3)));
        s->P[i] = q(i == 2 ? pow(5.0 * DEG, 2) : pow(1.0 * DEG, 2));
        s->P[3 + i] = q(0.01);
        s->P[6 + i] = q(4.0);
        s->P[9 + i] = q(1e-6);
        s->P[12 + i] = q(2.5e-3);
    }
}

static void samples(gen_seq_t *g, const se23_ins_config_t *c)
{
    se23_vec3_t gv, wv;
    double g_n[3], w_ie[3];
    se23t_rng_t rng;
    (void)se23_earth_gravity_vec(SE23_FRAME_NED, c->lat, 0.0, &gv);
    (void)se23_earth_rate(SE23_FRAME_NED, c->lat, &wv);
    for (int i = 0; i < 3; ++i) {
        g_n[i] = gv.v[i];
        w_ie[i] = g->rotating ? wv.v[i] : 0.0;
    }
    se23t_rng_seed(&rng, g->seed);
    for (int k = 0; k < N_IMU; ++k) {
        /* sample k covers (t_k - dt, t_k]: the truth at its middle */
        const double t = (double)(k + 1) / RATE - 0.5 / RATE;
        truth_t x;
        double fn[3], cor[3], fb[3], wie_b[3];
        truth(t, &x);
        cross(w_ie, x.v, cor);
        for (int i = 0; i < 3; ++i) {
            fn[i] = x.a[i] - g_n[i] + 2.0 * cor[i];
        }
        mul_t(&x.R, fn, fb);
        mul_t(&x.R, w_ie, wie_b);
        g->imu[k].t_ns = (k + 1) * DT_NS;
        g->imu[k].seq = k + 1;
        for (int i = 0; i < 3; ++i) {
            g->imu[k].w[i] = q(x.w_nb[i] + wie_b[i] - BIAS_G[i] + SIG_G * se23t_normal(&rng));
            g->imu[k].f[i] = q(fb[i] - BIAS_A[i] + SIG_A * se23t_normal(&rng));
        }
    }
}

static int fixes(gen_seq_t *g)
{
    se23t_rng_t rng;
    int n = 0;
    se23t_rng_seed(&rng, g->seed + 1000);
    for (int j = 1;; ++j) {
        const int k_fix = j * FIX_EVERY - 1; /* the sample stamped at the fix's time */
        const int at = k_fix + FIX_LATENCY;
        truth_t x;
        double Rl[3], wl[3], Rwl[3];
        insr_fix_t *f = &g->fix[n];
        if (at >= N_IMU) {
            break;
        }
        truth((double)(k_fix + 1) / RATE, &x);
        mul_v(&x.R, LEVER, Rl);
        cross(x.w_nb, LEVER, wl);
        mul_v(&x.R, wl, Rwl);
        f->at = at;
        f->t_ns = (k_fix + 1) * DT_NS;
        f->has_vel = 1;
        for (int i = 0; i < 3; ++i) {
            f->sp[i] = q(i == 2 ? 0.5 : 0.3);
            f->sv[i] = q(i == 2 ? 0.08 : 0.05);
            f->p[i] = q(x.p[i] + Rl[i] + f->sp[i] * se23t_normal(&rng));
            f->v[i] = q(x.v[i] + Rwl[i] + f->sv[i] * se23t_normal(&rng));
        }
        ++n;
    }
    return n;
}

static void hook(void *ctx, const se23_ins_t *ins, int k, int what, int verdict)
{
    gen_seq_t *g = ctx;
    const int full = ins->det.count == ins->det.cfg.window;
    const double r = ins->det.stat / ins->det.cfg.threshold;
    if (what == 0 && g->aligning) {
        /* an alignment sample: the detector on the raw readings, at rest */
        if (verdict == SE23_INS_USED) {
            g->aligning = 0;
        } else if (verdict != SE23_INS_EARLY) {
            fprintf(stderr, "%s: alignment sample %d: verdict %d\n", g->name, k, verdict);
            g->bad++;
        } else if (full) {
            g->n_align++;
            g->stat_rest_max = r > g->stat_rest_max ? r : g->stat_rest_max;
            if (!ins->det.stationary) {
                fprintf(stderr, "%s: alignment sample %d not at rest\n", g->name, k);
                g->bad++;
            }
        }
    } else if (what == 0) {
        if (verdict != SE23_INS_USED) {
            fprintf(stderr, "%s: sample %d: verdict %d\n", g->name, k, verdict);
            g->bad++;
        }
        /* a live sample with a full window: both rest tests decided */
        if (verdict == SE23_INS_USED && full) {
            const double n = insr_accel_nis(ins, &g->prev, g->imu[k].f) / INSR_ACCEL_TEST_Q;
            const int flag = (ins->status & SE23_INS_ST_STATIONARY) != 0U;
            if (flag != (ins->det.stationary && n < 1.0)) {
                fprintf(stderr, "%s: sample %d: the filter's rest flag %d, the generator's "
                        "copy of its tests %d (update insr_accel_nis)\n", g->name, k, flag,
                        !flag);
                g->bad++;
            }
            if (flag) {
                g->n_rest++;
                g->stat_rest_max = r > g->stat_rest_max ? r : g->stat_rest_max;
                g->acc_rest_max = n > g->acc_rest_max ? n : g->acc_rest_max;
            } else {
                const double m = r > n ? r : n; /* moving: either test fails */
                g->n_move++;
                g->move_min = m < g->move_min ? m : g->move_min;
            }
        }
    } else {
        /* a fix: fused, or early while the filter aligns */
        const int init = (ins->status & SE23_INS_ST_INITIALISED) != 0U;
        if (verdict != (init ? SE23_INS_USED : SE23_INS_EARLY)) {
            fprintf(stderr, "%s: fix at sample %d: verdict %d\n", g->name, k, verdict);
            g->bad++;
        }
        if (init) {
            const double nis = ins->nis_last / ins->cfg.gnss_gate;
            g->nis_max = nis > g->nis_max ? nis : g->nis_max;
        }
    }
    g->prev = ins->g;
}

#define CIDX INSR_CIDX
/* Counter `field` at the last checkpoint of g. */
#define CNT(g, field) ((unsigned)(g)->got[N_CHECK - 1].c[CIDX(field)])

/* The filter against the truth at each checkpoint (stderr: a sanity check
 * of the sequence, not part of the reference). */
static void report(const gen_seq_t *g)
{
    for (int j = 0; j < N_CHECK; ++j) {
        const insr_check_t *o = &g->got[j];
        truth_t x;
        double dp = 0.0, dv = 0.0, tr = 0.0, dbg = 0.0, dba = 0.0;
        truth((double)o->t_ns * 1e-9, &x);
        for (int i = 0; i < 3; ++i) {
            dp += pow(o->p[i] - x.p[i], 2);
            dv += pow(o->v[i] - x.v[i], 2);
            dbg += pow(o->bg[i] - BIAS_G[i], 2);
            dba += pow(o->ba[i] - BIAS_A[i], 2);
            for (int l = 0; l < 3; ++l) {
                tr += x.R.m[l][i] * o->R[3 * l + i];
            }
        }
        fprintf(stderr,
                "%-8s t=%5.2f s  |dp| %.3f m  |dv| %.3f m/s  att %.3f deg  |dbg| %.1e  |dba| "
                "%.1e  factors %d  status 0x%03x\n",
                g->name, (double)o->t_ns * 1e-9, sqrt(dp), sqrt(dv),
                acos(fmin(1.0, (tr - 1.0) / 2.0)) / DEG, sqrt(dbg), sqrt(dba), o->factors,
                (unsigned)o->status);
    }
    fprintf(stderr,
            "%-8s rest tests: %d alignment and %d stationary windows (SHOE <= %.3f x "
            "threshold, mean acceleration NIS <= %.3f x its), %d moving (a test >= %.1f x); "
            "GNSS NIS <= %.3f x gate; counters: used %u zupt %u zaru %u gnss %u delayed %u "
            "align %u gnss_early %u errors %u\n",
            g->name, g->n_align, g->n_rest, g->stat_rest_max, g->acc_rest_max, g->n_move,
            g->move_min, g->nis_max,
            CNT(g, imu_used), CNT(g, zupt_used), CNT(g, zaru_used), CNT(g, gnss_used),
            CNT(g, gnss_delayed), CNT(g, imu_align), CNT(g, gnss_early), CNT(g, filter_errors));
}

static int build(gen_seq_t *g)
{
    static se23_ins_t ins; /* large: static */
    int n_fix, bad;
    config(g, &g->seq.cfg);
    start(g, &g->seq.start);
    samples(g, &g->seq.cfg);
    n_fix = fixes(g);
    for (int j = 0; j < N_CHECK; ++j) {
        memset(&g->check[j], 0, sizeof g->check[j]);
        g->check[j].at = (int)lround(check_times[j] * RATE) - 1;
    }
    g->seq.name = g->name;
    g->seq.imu = g->imu;
    g->seq.n_imu = N_IMU;
    g->seq.fix = g->fix;
    g->seq.n_fix = n_fix;
    g->seq.check = g->check;
    g->seq.n_check = N_CHECK;
    g->aligning = g->align;
    g->stat_rest_max = 0.0;
    g->acc_rest_max = 0.0;
    g->move_min = 1e300;
    g->nis_max = 0.0;
    bad = insr_drive(&g->seq, &ins, g->got, hook, g);
    report(g);
    if (bad != 0 || g->bad != 0 || ins.c.filter_errors != 0) {
        fprintf(stderr, "%s: %d failed calls, %d unexpected verdicts, %u filter errors\n",
                g->name, bad, g->bad, (unsigned)ins.c.filter_errors);
        return 1;
    }
    if (g->stat_rest_max > 1.0 / MARGIN || g->acc_rest_max > 1.0 / MARGIN ||
        g->move_min < MARGIN ||
        g->nis_max > 1.0 / MARGIN || g->n_rest == 0 || g->n_move == 0) {
        fprintf(stderr, "%s: a decision too close to its threshold\n", g->name);
        return 1;
    }
    return 0;
}

/* ---- output ------------------------------------------------------------- */

static void print_seq(int s, const gen_seq_t *g)
{
    printf("\n/* %s: %d IMU samples, %d fixes, %d checkpoints */\n", g->name, g->seq.n_imu,
           g->seq.n_fix, g->seq.n_check);
    printf("static const insr_imu_t imu%d[%d] = {\n", s, g->seq.n_imu);
    for (int k = 0; k < g->seq.n_imu; ++k) {
        const insr_imu_t *m = &g->imu[k];
        printf(" {%lldLL, %lld, {%.17g, %.17g, %.17g}, {%.17g, %.17g, %.17g}},\n",
               (long long)m->t_ns, (long long)m->seq, m->w[0], m->w[1], m->w[2], m->f[0],
               m->f[1], m->f[2]);
    }
    printf("};\nstatic const insr_fix_t fix%d[%d] = {\n", s, g->seq.n_fix);
    for (int j = 0; j < g->seq.n_fix; ++j) {
        const insr_fix_t *f = &g->fix[j];
        printf(" {%d, %lldLL, {%.17g, %.17g, %.17g}, {%.17g, %.17g, %.17g},\n"
               "  {%.17g, %.17g, %.17g}, {%.17g, %.17g, %.17g}, %d},\n",
               f->at, (long long)f->t_ns, f->p[0], f->p[1], f->p[2], f->sp[0], f->sp[1],
               f->sp[2], f->v[0], f->v[1], f->v[2], f->sv[0], f->sv[1], f->sv[2], f->has_vel);
    }
    printf("};\nstatic const insr_check_t check%d[%d] = {\n", s, g->seq.n_check);
    for (int j = 0; j < g->seq.n_check; ++j) {
        gen_print_check(&g->got[j]);
    }
    printf("};\n");
}

/* The calls of the presets compared on the target, each preset's: valid
 * rates (one above the detector window's clamp; the car's delay horizon
 * is clamped by the ring above 252 Hz) and the two error statuses. The
 * car's rates keep its window's 0.3 rate + 0.5 away from an integer
 * (rates of 5 mod 10 Hz), where float and double could round apart. */
static const double preset_args[][3] = {
    {200.0, 0.8, 0}, {100.0, 0.0, 0}, {1000.0, -0.6, 0}, {4000.0, 1.2, 0}, {20.0, 0.8, 0},
    {200.0, 2.0, 0}, {200.0, 0.8, 1}, {100.0, 0.0, 1},   {1000.0, -0.6, 1}, {4000.0, 1.2, 1},
    {52.0, 0.3, 1},  {20.0, 0.8, 1},  {200.0, -2.0, 1}};
static const struct {
    int window;
    double z;
} threshold_args[] = {{20, 2.3263479}, {5, 1.645}, {32, 3.09}, {10, -1.0}, {2, 0.0}};

static void print_presets(int corrupt)
{
    const int n = (int)(sizeof preset_args / sizeof preset_args[0]);
    const int m = (int)(sizeof threshold_args / sizeof threshold_args[0]);
    printf("\n/* se23_ins_preset_foot, se23_ins_preset_car and se23_ins_detector_threshold */\n");
    printf("const insr_preset_t insr_presets[] = {\n");
    for (int i = 0; i < n; ++i) {
        se23_ins_config_t c;
        se23_ins_align_t a;
        const double rate = q(preset_args[i][0]), lat = q(preset_args[i][1]);
        const int car = preset_args[i][2] != 0.0;
        se23_status_t st;
        memset(&c, 0, sizeof c);
        memset(&a, 0, sizeof a);
        st = car ? se23_ins_preset_car(rate, lat, &c, &a) : se23_ins_preset_foot(rate, lat, &c, &a);
        printf(" {%.17g, %.17g, %d,\n", rate, lat, (int)st);
        gen_print_config(&c);
        printf("  .align = ");
        gen_print_align(&a);
        printf("  .car = %d},\n", car);
    }
    printf("};\nconst int insr_n_presets = %d;\n", n);
    printf("const insr_threshold_t insr_thresholds[] = {\n");
    for (int i = 0; i < m; ++i) {
        const double z = q(threshold_args[i].z);
        const double t = se23_ins_detector_threshold(threshold_args[i].window, z);
        printf(" {%d, %.17g, %.17g},\n", threshold_args[i].window, z,
               (corrupt && i == 0) ? t * (1.0 + 1e-3) : t);
    }
    printf("};\nconst int insr_n_thresholds = %d;\n", m);
}

static gen_seq_t seqs[2] = {
    {.name = "flat", .rotating = 0, .align = 0, .preint_window = 1.0, .seed = 2301},
    {.name = "rotating", .rotating = 1, .align = 1, .preint_window = 0.5, .seed = 2302},
};

int main(int argc, char **argv)
{
    const int n = (int)(sizeof seqs / sizeof seqs[0]);
    int corrupt = 0;
    typedef char counters_are_uint32[(sizeof(se23_ins_counters_t) ==
                                      INSR_N_COUNTERS * sizeof(uint32_t)) ? 1 : -1];
    (void)sizeof(counters_are_uint32);
    if (argc == 2 && strcmp(argv[1], "--corrupt") == 0) {
        corrupt = 1;
    } else if (argc != 1) {
        fprintf(stderr, "usage: gen_ins_replay [--corrupt] > ins_replay_data.c\n");
        return 2;
    }
    for (int s = 0; s < n; ++s) {
        if (build(&seqs[s]) != 0) {
            return 1;
        }
    }
    if (corrupt) {
        seqs[0].got[N_CHECK - 1].p[0] += 1.0; /* 1 m: beyond any tolerance */
        seqs[1].got[3].c[CIDX(gnss_delayed)] += 1U;
    }
    printf("/* Generated by tools/target/gen_ins_replay%s from the host's double\n"
           " * build of the filter; do not edit. */\n#include \"ins_replay.h\"\n",
           corrupt ? " --corrupt (three reference values perturbed)" : "");
    for (int s = 0; s < n; ++s) {
        print_seq(s, &seqs[s]);
    }
    printf("\nconst insr_seq_t insr_seqs[] = {\n");
    for (int s = 0; s < n; ++s) {
        printf(" {\"%s\",\n", seqs[s].name);
        gen_print_config(&seqs[s].seq.cfg);
        gen_print_start(&seqs[s].seq.start);
        printf("  imu%d, %d, fix%d, %d, check%d, %d},\n", s, seqs[s].seq.n_imu, s,
               seqs[s].seq.n_fix, s, seqs[s].seq.n_check);
    }
    printf("};\nconst int insr_n_seqs = %d;\n", n);
    print_presets(corrupt);
    return 0;
}
