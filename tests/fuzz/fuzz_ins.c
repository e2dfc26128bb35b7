/*
 * libFuzzer target of se23/ins.h, the stateful filter: the input decodes
 * into a configuration (the pedestrian preset, or a flat- or rotating-Earth
 * configuration with decoded overrides) and then a sequence of calls with
 * arbitrary values: init, align, runs of IMU samples (nominal, jittered,
 * lost, repeated, backwards, jumping; at rest, moving or absurd readings;
 * times up to INT64_MAX), GNSS fixes (now, late, early, absurd), factors
 * taken. After every call:
 *  - the verdict is a known one; SE23_INS_FAILED (a library step refused,
 *    "should not" happen for checked inputs, but does for absurd finite
 *    ones: an initial velocity of 1e307 m/s, tools/doc/pages/fuzzing-soak.md) leaves the
 *    state and its time as they were;
 *  - every counter is where it was or above; each se23_ins_imu call ends
 *    in exactly one imu_ counter (imu_missing and imu_seq_jumps aside),
 *    FAILED ones in imu_failed; every fix handed in is in exactly one
 *    gnss_ counter or held (gnss_delayed and gate_resets aside);
 *  - init and align that fail leave the filter as it was but for
 *    init_rejected (the scratch fields meas and work aside);
 *  - with SE23_INS_ST_INITIALISED, se23_ins_state gives SE23_OK (or, for
 *    an absurd state whose user coordinates overflow, SE23_ERR_NONFINITE,
 *    nothing written), a state of the configured dimension whose held and
 *    user forms pass se23_gauss_check but for the known finding of fuzz.h
 *    (a step within its rounding bound, the bound from the configuration's
 *    ranges and the largest variance), and the time of the filter;
 *    without it, SE23_ERR_DIM;
 *  - a factor taken passes se23_preint_unc_check;
 *  - status holds only the documented bits.
 * setup: statuses in the header's set, nothing written on an error.
 */
#include "fuzz.h"

#include "../support/ins_counters.h"
#include "se23/ins.h"

#define ST_ALL 0x1FFU

static const int64_t NS = 1000000000LL;

/* a + b, saturated to [INT64_MIN, INT64_MAX]: the harness itself must not
 * overflow. */
static int64_t sat_add(int64_t a, int64_t b)
{
    if (b > 0 && a > INT64_MAX - b) {
        return INT64_MAX;
    }
    if (b < 0 && a < INT64_MIN - b) {
        return INT64_MIN;
    }
    return a + b;
}

static int64_t fz_i64(fz_t *f)
{
    return (int64_t)fz_u64(f);
}

typedef struct {
    se23_ins_t ins;
    se23_ins_t before; /* copy of the filter before an init or align */
    se23_ins_config_t cfg;
    se23_ins_align_t align;
    int64_t t, seq;    /* time and seq of the last sample generated */
    int64_t dt_ns;     /* nominal interval */
    double d_before;   /* largest variance before the call */
    se23_gauss_t g_before;
    unsigned long failed; /* FAILED verdicts seen */
    uint32_t fixes;       /* se23_ins_gnss calls with a fix */
    int tainted;          /* the known finding of fuzz.h made the state invalid */
} ctx_t;

static ctx_t *C; /* static: two filters do not belong on the stack */

static void base_config(fz_t *f, se23_ins_config_t *c, se23_ins_align_t *a)
{
    const uint8_t m = fz_u8(f);
    se23_real_t g;
    memset(c, 0, sizeof *c);
    memset(a, 0, sizeof *a);
    if (m < 48) {
        const se23_real_t rate = (m & 1) ? (se23_real_t)(50 + fz_u16(f) % 2000) : 200;
        const se23_real_t lat = (se23_real_t)((double)(int8_t)fz_u8(f) / 128.0);
        if (se23_ins_preset_foot(rate, lat, c, a) == SE23_OK) {
            return;
        }
    }
    (void)se23_earth_gravity(0, 0, &g);
    c->noise.gyro_noise = (se23_real_t)(1e-3 / sqrt(200.0));
    c->noise.accel_noise = (se23_real_t)(1e-2 / sqrt(200.0));
    c->noise.gyro_walk = (se23_real_t)1e-6;
    c->noise.accel_walk = (se23_real_t)1e-5;
    c->gyro_range = 30;
    c->accel_range = 150;
    c->lat = (m & 2) ? (se23_real_t)0.8 : 0;
    c->earth_rotation = (m >> 2) & 1;
    c->bias_states = (m >> 3) & 1;
    c->dt_nominal = (se23_real_t)0.005;
    c->max_gap = (se23_real_t)0.125;
    c->max_outage = 10;
    c->outage_accel = 1;
    c->outage_rate = (se23_real_t)0.05;
    c->gnss_gate = (m & 16) ? 30 : 0;
    c->gate_recover = (m & 16) ? 3 : 0;
    c->delay_horizon = (m & 32) ? (se23_real_t)0.25 : 0;
    c->preint_window = (m & 64) ? (se23_real_t)0.1 : 0;
    c->zupt = (m & 128) ? 1 : 0;
    c->detector.window = 10;
    c->detector.sigma_a = (se23_real_t)1e-2;
    c->detector.sigma_g = (se23_real_t)1e-3;
    c->detector.gravity = g;
    c->detector.threshold = 12;
    c->zupt_sigma_v = (se23_real_t)0.01;
    c->zaru_sigma_w = (se23_real_t)1e-3;
    c->zaru_after = (se23_real_t)0.05;
    c->floor_sigma = (c->zupt && (m & 1)) ? (se23_real_t)0.01 : 0;
    c->floor_step = (se23_real_t)0.05;
    c->floor_swing = (se23_real_t)0.1;
    a->sigma_p = 1;
    a->sigma_yaw = (se23_real_t)0.1;
    a->sigma_v = (se23_real_t)0.1;
    a->sigma_bg = (se23_real_t)1e-3;
    a->sigma_ba = (se23_real_t)1e-2;
    a->duration = (se23_real_t)0.1;
    a->gyrocompass = c->earth_rotation && (m & 1);
}

/* One field of the configuration decoded freely. */
static void override_config(fz_t *f, se23_ins_config_t *c)
{
    se23_real_t *reals[] = {&c->noise.gyro_noise, &c->noise.accel_noise, &c->noise.gyro_walk,
                            &c->noise.accel_walk, &c->gyro_range,        &c->accel_range,
                            &c->lat,              &c->dt_nominal,        &c->max_gap,
                            &c->max_outage,       &c->outage_accel,      &c->outage_rate,
                            &c->lever_b.v[0],     &c->lever_b.v[1],      &c->lever_b.v[2],
                            &c->gnss_gate,        &c->delay_horizon,     &c->preint_window,
                            &c->detector.sigma_a, &c->detector.sigma_g,  &c->detector.gravity,
                            &c->detector.threshold, &c->zupt_sigma_v,    &c->zaru_sigma_w,
                            &c->zaru_after,       &c->floor_sigma,       &c->floor_step,
                            &c->floor_swing};
    int *ints[] = {&c->earth_rotation, &c->bias_states, &c->gate_recover, &c->zupt,
                   &c->detector.window};
    const int n_reals = (int)(sizeof reals / sizeof reals[0]);
    const int n_ints = (int)(sizeof ints / sizeof ints[0]);
    const int k = fz_u8(f) % (n_reals + n_ints);
    if (k < n_reals) {
        const uint8_t m = fz_u8(f);
        *reals[k] = m < 128 ? *reals[k] * (se23_real_t)(1 + fz_u8(f)) / 16 : fz_real(f);
    } else {
        *ints[k - n_reals] = fz_int(f);
    }
}

/* One field of the alignment request decoded freely. */
static void override_align(fz_t *f, se23_ins_align_t *a)
{
    se23_real_t *reals[] = {&a->p_n.v[0], &a->p_n.v[1], &a->p_n.v[2], &a->sigma_p, &a->yaw,
                            &a->sigma_yaw, &a->sigma_v, &a->sigma_bg, &a->sigma_ba, &a->duration};
    const int n_reals = (int)(sizeof reals / sizeof reals[0]);
    const int k = fz_u8(f) % (n_reals + 1);
    if (k < n_reals) {
        *reals[k] = fz_real(f);
    } else {
        a->gyrocompass = fz_int(f);
    }
}

/* ---- the invariants --------------------------------------------------- */

#define N_COUNTERS ((int)(sizeof(se23_ins_counters_t) / sizeof(uint32_t)))

/* Every fix handed in is in exactly one gnss_ counter, or held. */
static void check_fixes(const ctx_t *c, const char *what)
{
    const uint32_t held = c->ins.have_pending ? 1u : 0u;
    FZ_REQUIRE(it_gnss_sum(&c->ins.c) + held == c->fixes,
               "%s: %u fixes handed in, %u counted, %u held", what, (unsigned)c->fixes,
               (unsigned)it_gnss_sum(&c->ins.c), (unsigned)held);
}

static void check_counters(const se23_ins_counters_t *was, const se23_ins_counters_t *now,
                           const char *what)
{
    uint32_t a[N_COUNTERS], b[N_COUNTERS];
    int i;
    memcpy(a, was, sizeof a);
    memcpy(b, now, sizeof b);
    for (i = 0; i < N_COUNTERS; ++i) {
        FZ_REQUIRE(b[i] >= a[i], "%s: counter %d went from %u to %u", what, i, (unsigned)a[i],
                   (unsigned)b[i]);
    }
}

/* The known finding's bound (fuzz.h) for whatever one call did: up to
 * SE23_INS_MAX_OUTAGE / dt_max + 1 steps of at most max(max_gap, 1 s) with
 * |f| <= accel_range (cov_step.c's row-sum bound r of one step), and
 * updates whose S is at most (1 + |l|_1)^2 times the largest variance
 * plus a fix's largest sigma^2 (1e12), all with a few eps relative. */
static double ins_bound(const ctx_t *c, double d)
{
    const double dt = fmax((double)c->cfg.max_gap, 1.0), a = (double)c->cfg.accel_range;
    const double l = fabs((double)c->cfg.lever_b.v[0]) + fabs((double)c->cfg.lever_b.v[1]) +
                     fabs((double)c->cfg.lever_b.v[2]);
    const double uv = 1.8 * dt * a, up = 0.9 * dt * dt * a;
    const double b = 6.0 * dt * (1.0 + dt * 1.8 * a * (1.0 + dt));
    const double r = 2.0 * (1.0 + dt + uv + up + b) + 1.0;
    const double e = 32.0 * FZ_EPS + SE23_CFG_COV_TOL;
    return 1e3 * 15.0 * e * (r * r * d + (1.0 + l) * (1.0 + l) * d + 1e12);
}

static void check_state(ctx_t *c, const char *what)
{
    se23_gauss_t out;
    int64_t t;
    se23_status_t st;
    const uint32_t status = c->ins.status;
    FZ_REQUIRE((status & ~ST_ALL) == 0U, "%s: status 0x%x", what, (unsigned)status);
    fz_fill(&out, sizeof out);
    fz_fill(&t, sizeof t);
    st = se23_ins_state(&c->ins, &out, &t);
    if ((status & SE23_INS_ST_INITIALISED) == 0U) {
        FZ_REQUIRE(st == SE23_ERR_DIM, "%s: state of an uninitialised filter: %d", what, st);
        FZ_REQUIRE(fz_untouched(&out, sizeof out) && fz_untouched(&t, sizeof t),
                   "%s: state wrote on error", what);
        return;
    }
    if (st == SE23_ERR_NONFINITE) { /* the user's state would overflow (ins.h) */
        FZ_REQUIRE(fz_untouched(&out, sizeof out) && fz_untouched(&t, sizeof t),
                   "%s: state wrote on error", what);
        if (!c->tainted) {
            c->tainted = !fz_check_cov_step(&c->ins.g, ins_bound(c, c->d_before), what);
        }
        return;
    }
    FZ_REQUIRE(st == SE23_OK, "%s: state of an initialised filter: %d", what, st);
    FZ_REQUIRE(out.n == (c->ins.cfg.bias_states ? 15 : 9), "%s: state of dimension %d", what,
               out.n);
    if (!c->tainted) {
        const double d = fmax(fz_max_diag(out.P.m, out.n, 15), c->d_before);
        /* after the known finding the filter's state is not valid: it is
         * trusted, so only crashes, UB and the bookkeeping are judged until
         * the next init or alignment */
        c->tainted = !fz_check_cov_step(&out, ins_bound(c, d), what) ||
                     !fz_check_cov_step(&c->ins.g, ins_bound(c, d), what);
    }
    FZ_REQUIRE(t == c->ins.t_ns && t >= 0, "%s: state time %lld, filter %lld", what, (long long)t,
               (long long)c->ins.t_ns);
}

/* Remembers the largest variance before a call (for ins_bound). */
static void note_before(ctx_t *c)
{
    c->d_before = 0.0;
    if ((c->ins.status & SE23_INS_ST_INITIALISED) != 0U) {
        c->d_before = fz_max_diag(c->ins.g.P.m, c->ins.g.n == 9 ? 9 : 15, 15);
    }
}

/* The filter as it was but for init_rejected (and the scratch). */
static void check_unchanged(ctx_t *c, const char *what)
{
    FZ_REQUIRE(c->ins.c.init_rejected == c->before.c.init_rejected + 1u ||
                   c->before.c.init_rejected == UINT32_MAX,
               "%s: init_rejected %u -> %u", what, (unsigned)c->before.c.init_rejected,
               (unsigned)c->ins.c.init_rejected);
    c->before.c.init_rejected = c->ins.c.init_rejected;
    memcpy(&c->before.meas, &c->ins.meas, sizeof c->ins.meas);
    memcpy(&c->before.work, &c->ins.work, sizeof c->ins.work);
    FZ_REQUIRE(memcmp(&c->before, &c->ins, sizeof c->ins) == 0, "%s: refused, but the filter changed",
               what);
}

/* ---- the calls -------------------------------------------------------- */

static void do_setup(fz_t *f, ctx_t *c)
{
    int k, n = fz_u8(f) < 160 ? 0 : 1 + fz_u8(f) % 4;
    se23_status_t st;
    base_config(f, &c->cfg, &c->align);
    for (k = 0; k < n; ++k) {
        override_config(f, &c->cfg);
    }
    fz_fill(&c->ins, sizeof c->ins);
    st = se23_ins_setup(&c->cfg, &c->ins);
    FZ_REQUIRE(fz_status_in(st, 4, SE23_ERR_NONFINITE, SE23_ERR_DOMAIN, SE23_ERR_DT, SE23_ERR_DIM),
               "setup: %d", st);
    if (st != SE23_OK) {
        FZ_REQUIRE(fz_untouched(&c->ins, sizeof c->ins), "setup wrote on error %d", st);
        fz_t none;
        fz_init(&none, NULL, 0);
        base_config(&none, &c->cfg, &c->align); /* the plain flat-Earth one */
        st = se23_ins_setup(&c->cfg, &c->ins);
        FZ_REQUIRE(st == SE23_OK, "setup of the base configuration: %d", st);
    }
    c->dt_ns = (int64_t)((double)c->cfg.dt_nominal * 1e9);
    if (c->dt_ns < 1) {
        c->dt_ns = 1;
    }
    check_state(c, "setup");
}

static int64_t time_of(fz_t *f, ctx_t *c)
{
    const uint8_t m = fz_u8(f);
    if (m < 200) {
        return sat_add(c->t, c->dt_ns + (int64_t)(int8_t)fz_u8(f) * 1000);
    }
    if (m < 212) {
        return sat_add(c->t, (int64_t)(2 + fz_u16(f) % 400) * c->dt_ns);
    }
    if (m < 220) {
        return c->t;
    }
    if (m < 230) {
        return sat_add(c->t, -(int64_t)(1 + fz_u8(f)) * c->dt_ns);
    }
    if (m < 240) {
        return sat_add(c->t, (int64_t)fz_u32(f) * 1000);
    }
    if (m < 248) {
        return INT64_MAX - (int64_t)fz_u16(f) * c->dt_ns;
    }
    return fz_i64(f);
}

static void do_init(fz_t *f, ctx_t *c)
{
    se23_gauss_t g;
    se23_status_t st;
    int64_t t;
    const uint8_t m = fz_u8(f);
    const int n = c->cfg.bias_states ? 15 : 9;
    memset(&g, 0, sizeof g);
    if (m < 200) {
        int i;
        g.n = n;
        fz_pose(f, &g.T);
        for (i = 0; i < n; ++i) {
            const se23_real_t s = fz_u8(f) < 224 ? (se23_real_t)(1 + fz_u8(f)) * (se23_real_t)1e-3
                                                 : fz_real(f);
            g.P.m[16 * i] = s * s;
        }
    } else {
        fz_gauss(f, &g);
    }
    t = fz_u8(f) < 200 ? (c->t > 0 ? c->t : 0) : time_of(f, c);
    memcpy(&c->before, &c->ins, sizeof c->ins);
    note_before(c);
    st = se23_ins_init(&c->ins, t, &g);
    FZ_REQUIRE(fz_status_in(st, 7, SE23_ERR_DIM, SE23_ERR_DT, SE23_ERR_NONFINITE,
                            SE23_ERR_NOT_ROTATION, SE23_ERR_NOT_SYMMETRIC, SE23_ERR_NOT_PSD,
                            SE23_ERR_DOMAIN),
               "init: %d", st);
    if (st != SE23_OK) {
        check_unchanged(c, "init");
    } else {
        FZ_REQUIRE((c->ins.status & SE23_INS_ST_INITIALISED) != 0U, "init: OK, not initialised");
        c->tainted = 0;
        c->t = t;
        c->seq = fz_u8(f) < 224 ? 0 : fz_i64(f);
    }
    check_counters(&c->before.c, &c->ins.c, "init");
    check_fixes(c, "init");
    check_state(c, "init");
}

static void do_align(fz_t *f, ctx_t *c)
{
    se23_ins_align_t a = c->align;
    se23_status_t st;
    int k, n = fz_u8(f) < 192 ? 0 : 1 + fz_u8(f) % 3;
    for (k = 0; k < n; ++k) {
        override_align(f, &a);
    }
    memcpy(&c->before, &c->ins, sizeof c->ins);
    note_before(c);
    st = se23_ins_align(&c->ins, &a);
    FZ_REQUIRE(fz_status_in(st, 2, SE23_ERR_DOMAIN, SE23_ERR_NONFINITE), "align: %d", st);
    if (st != SE23_OK) {
        check_unchanged(c, "align");
    } else {
        FZ_REQUIRE((c->ins.status & SE23_INS_ST_ALIGNING) != 0U, "align: OK, not aligning");
        c->tainted = 0;
    }
    check_counters(&c->before.c, &c->ins.c, "align");
    check_state(c, "align");
}

static void do_imu(fz_t *f, ctx_t *c)
{
    const int n = 1 + fz_u8(f) % 64;
    const uint8_t kind = fz_u8(f);
    se23_vec3_t w0, f0;
    int k;
    se23_real_t g;
    (void)se23_earth_gravity(c->cfg.lat, 0, &g);
    fz_vec3_mild(f, &w0);
    fz_vec3_mild(f, &f0);
    for (k = 0; k < n && fz_left(f); ++k) {
        se23_vec3_t w, a;
        se23_ins_counters_t was = c->ins.c;
        se23_ins_verdict_t v;
        int64_t t, seq, t_before;
        const uint8_t sm = fz_u8(f);
        const uint8_t qm = fz_u8(f);
        t = time_of(f, c);
        seq = qm < 224 ? sat_add(c->seq, 1)
              : qm < 232 ? c->seq
              : qm < 240 ? sat_add(c->seq, -1)
              : qm < 248 ? sat_add(c->seq, 1 + fz_u16(f))
                         : fz_i64(f);
        if (kind < 128 && sm < 240) { /* at rest, level, small noise */
            int i;
            for (i = 0; i < 3; ++i) {
                w.v[i] = (se23_real_t)(int8_t)fz_u8(f) * (se23_real_t)1e-5;
                a.v[i] = (se23_real_t)(int8_t)fz_u8(f) * (se23_real_t)1e-4;
            }
            a.v[2] -= g;
        } else if (sm < 224) { /* the run's motion, with a little change */
            int i;
            for (i = 0; i < 3; ++i) {
                w.v[i] = w0.v[i] / 64 + (se23_real_t)(int8_t)fz_u8(f) * (se23_real_t)1e-3;
                a.v[i] = f0.v[i] + (se23_real_t)(int8_t)fz_u8(f) * (se23_real_t)1e-2;
            }
            a.v[2] -= g;
        } else {
            fz_vec3(f, &w);
            fz_vec3(f, &a);
        }
        note_before(c);
        memcpy(&c->g_before, &c->ins.g, sizeof c->ins.g);
        t_before = c->ins.t_ns;
        v = se23_ins_imu(&c->ins, t, seq, &w, &a);
        FZ_REQUIRE(v >= SE23_INS_USED && v <= SE23_INS_FAILED && v != SE23_INS_PENDING &&
                       v != SE23_INS_STALE && v != SE23_INS_GATED && v != SE23_INS_RESET,
                   "imu: verdict %d", (int)v);
        check_counters(&was, &c->ins.c, "imu");
        if (v == SE23_INS_FAILED) { /* "leaves the state as it was" */
            FZ_REQUIRE(fz_gauss_same(&c->g_before, &c->ins.g) && c->ins.t_ns == t_before,
                       "imu: FAILED, but the state changed");
            FZ_REQUIRE(c->ins.c.filter_errors > was.filter_errors,
                       "imu: FAILED, not counted in filter_errors");
            c->failed++;
        }
        FZ_REQUIRE(it_imu_sum(&c->ins.c) == it_imu_sum(&was) + 1u,
                   "imu: the sample ended in %d imu_ counters (verdict %d)",
                   (int)(it_imu_sum(&c->ins.c) - it_imu_sum(&was)), (int)v);
        check_fixes(c, "imu");
        /* USED: integrated (imu_used), or the sample that completed an
         * alignment (imu_align) */
        FZ_REQUIRE(v != SE23_INS_USED || c->ins.c.imu_used == was.imu_used + 1u ||
                       c->ins.c.imu_align == was.imu_align + 1u,
                   "imu: USED but neither imu_used nor imu_align counted");
        check_state(c, "imu");
        c->t = t;
        c->seq = seq;
    }
}

static void do_gnss(fz_t *f, ctx_t *c)
{
    se23_ins_gnss_t fix;
    se23_ins_counters_t was = c->ins.c;
    se23_ins_verdict_t v;
    se23_gauss_t st;
    int64_t ts;
    const uint8_t m = fz_u8(f);
    memset(&fix, 0, sizeof fix);
    fix.t_ns = m < 96 ? c->t
               : m < 160 ? sat_add(c->t, -(int64_t)(fz_u8(f) % 64) * c->dt_ns)
               : m < 200 ? sat_add(c->t, (int64_t)(1 + fz_u8(f) % 64) * c->dt_ns)
                         : time_of(f, c);
    if (se23_ins_state(&c->ins, &st, &ts) != SE23_OK) {
        memset(&st, 0, sizeof st);
    }
    if (fz_u8(f) < 192) {
        int i;
        for (i = 0; i < 3; ++i) {
            fix.p_n.v[i] = st.T.p.v[i] + (se23_real_t)(int8_t)fz_u8(f) * (se23_real_t)0.05;
            fix.v_n.v[i] = st.T.v.v[i] + (se23_real_t)(int8_t)fz_u8(f) * (se23_real_t)0.01;
            fix.sigma_p.v[i] = (se23_real_t)(1 + fz_u8(f) % 16) * (se23_real_t)0.25;
            fix.sigma_v.v[i] = (se23_real_t)(1 + fz_u8(f) % 16) * (se23_real_t)0.05;
        }
    } else {
        fz_vec3(f, &fix.p_n);
        fz_vec3(f, &fix.v_n);
        fz_vec3(f, &fix.sigma_p);
        fz_vec3(f, &fix.sigma_v);
    }
    fix.has_vel = fz_u8(f) < 240 ? (m & 1) : fz_int(f);
    note_before(c);
    v = se23_ins_gnss(&c->ins, &fix);
    c->fixes++;
    FZ_REQUIRE(v >= SE23_INS_USED && v <= SE23_INS_FAILED && v != SE23_INS_RANGE &&
                   v != SE23_INS_DUPLICATE && v != SE23_INS_OUT_OF_ORDER &&
                   v != SE23_INS_BAD_TIME && v != SE23_INS_BAD_DT && v != SE23_INS_OUTAGE,
               "gnss: verdict %d", (int)v);
    if (v == SE23_INS_FAILED) {
        FZ_REQUIRE(c->ins.c.filter_errors > was.filter_errors,
                   "gnss: FAILED, not counted in filter_errors");
        c->failed++;
    }
    check_counters(&was, &c->ins.c, "gnss");
    check_fixes(c, "gnss");
    check_state(c, "gnss");
}

static void do_factor(ctx_t *c)
{
    se23_ins_factor_t fac;
    if (se23_ins_take_factor(&c->ins, &fac)) {
        se23_status_t st = se23_preint_unc_check(&fac.f);
        FZ_REQUIRE(st == SE23_OK, "take_factor: the factor fails se23_preint_unc_check (%d)", st);
        FZ_REQUIRE(fac.t1_ns >= fac.t0_ns, "take_factor: t0 %lld, t1 %lld",
                   (long long)fac.t0_ns, (long long)fac.t1_ns);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_t f;
    int calls = 0;
    if (C == NULL) {
        C = malloc(sizeof *C);
        FZ_REQUIRE(C != NULL, "malloc");
    }
    memset(C, 0, sizeof *C);
    fz_init(&f, data, size);
    do_setup(&f, C);
    C->t = fz_u8(&f) < 224 ? NS : time_of(&f, C);
    {
        const uint8_t m = fz_u8(&f);
        if (m < 160) {
            do_init(&f, C);
        } else if (m < 200) {
            do_align(&f, C);
        }
    }
    while (fz_left(&f) && calls++ < 128) {
        const uint8_t op = fz_u8(&f);
        if (op < 12) {
            do_init(&f, C);
        } else if (op < 20) {
            do_align(&f, C);
        } else if (op < 200) {
            do_imu(&f, C);
        } else if (op < 248) {
            do_gnss(&f, C);
        } else {
            do_factor(C);
        }
    }
    return 0;
}
