/* Analytic reference trajectories; see traj.h. */
#include "traj.h"

#include <math.h>
#include <string.h>

#define PI_L 3.141592653589793238462643383279502884L

/* A scalar function of t with its first two derivatives. */
typedef struct {
    ld_t f, d1, d2;
} curve_t;

/* A sin(w t + c) + b */
static curve_t sine(ld_t A, ld_t w, ld_t c, ld_t b, ld_t t)
{
    curve_t s;
    ld_t x = w * t + c;
    s.f = A * sinl(x) + b;
    s.d1 = A * w * cosl(x);
    s.d2 = -A * w * w * sinl(x);
    return s;
}

/* A cos(w t + c) + b */
static curve_t cosine(ld_t A, ld_t w, ld_t c, ld_t b, ld_t t)
{
    return sine(A, w, c + 0.5L * PI_L, b, t);
}

static curve_t constant(ld_t b)
{
    curve_t s = {b, 0.0L, 0.0L};
    return s;
}

/* Position (x, y, z) and Euler angles (roll, pitch, yaw) with their
 * derivatives; only the first derivative of the angles is used. */
typedef struct {
    curve_t pos[3];
    curve_t roll, pitch, yaw;
} traj_raw_t;

static traj_raw_t raw_static(void)
{
    traj_raw_t r;
    r.pos[0] = constant(0.0L);
    r.pos[1] = constant(0.0L);
    r.pos[2] = constant(0.0L);
    r.roll = constant(0.01L);
    r.pitch = constant(-0.02L);
    r.yaw = constant(0.3L);
    return r;
}

static traj_raw_t raw_uav(ld_t t)
{
    const ld_t w = 2.0L * PI_L / 30.0L;
    traj_raw_t r;
    r.pos[0] = sine(20.0L, w, 0.0L, 0.0L, t);
    r.pos[1] = sine(10.0L, 2.0L * w, 0.0L, 0.0L, t);
    r.pos[2] = sine(-3.0L, 0.5L * w, 0.0L, 0.0L, t);
    r.roll = sine(0.2L, 1.3L * w, 0.0L, 0.0L, t);
    r.pitch = sine(0.15L, 0.9L * w, 0.3L, 0.0L, t);
    r.yaw = sine(0.6L, 0.5L * w, 0.0L, 0.0L, t);
    r.yaw.f += 0.05L * t; /* slow turn: heading becomes observable */
    r.yaw.d1 += 0.05L;
    return r;
}

/* Heading along the horizontal velocity: yaw = atan2(vy, vx). */
static curve_t heading_of(const curve_t *x, const curve_t *y)
{
    curve_t s;
    ld_t n2 = x->d1 * x->d1 + y->d1 * y->d1;
    s.f = atan2l(y->d1, x->d1);
    s.d1 = (x->d1 * y->d2 - y->d1 * x->d2) / n2;
    s.d2 = 0.0L; /* not used */
    return s;
}

static traj_raw_t raw_car(ld_t t)
{
    /* figure eight; the speed never vanishes (dx = 0 needs cos(2wt) = -1) */
    const ld_t w = 2.0L * PI_L / 60.0L;
    traj_raw_t r;
    r.pos[0] = sine(100.0L, w, 0.0L, 0.0L, t);
    r.pos[1] = sine(50.0L, 2.0L * w, 0.0L, 0.0L, t);
    r.pos[2] = constant(0.0L);
    r.roll = constant(0.0L);
    r.pitch = sine(0.01L, 5.0L * w, 0.0L, 0.0L, t); /* gentle road grade */
    r.yaw = heading_of(&r.pos[0], &r.pos[1]);
    return r;
}

static traj_raw_t raw_nav(ld_t t)
{
    const ld_t w = 2.0L * PI_L / 1200.0L;
    const ld_t speed = 100.0L;
    const ld_t radius = speed / w;
    traj_raw_t r;
    r.pos[0] = sine(radius, w, 0.0L, 0.0L, t);
    r.pos[1] = cosine(-radius, w, 0.0L, radius, t);
    r.pos[2] = constant(-1000.0L);
    r.roll = constant(atanl(speed * w / 9.8L)); /* coordinated turn */
    r.pitch = constant(0.02L);
    r.yaw = sine(0.0L, 0.0L, 0.0L, 0.0L, t);
    r.yaw.f = w * t;
    r.yaw.d1 = w;
    return r;
}

/*
 * A foot-mounted IMU on a walk (tools/doc/pages/walks.md, its simulated twin):
 * WALK_REST s at rest, WALK_STRIDES strides around a circle that they
 * close exactly, then at rest again. A stride of WALK_PERIOD s is a stance
 * (the foot flat and still) then a swing of WALK_SWING s in which, with
 * u = swing time / WALK_SWING in [0, 1],
 *   the arc length grows by WALK_STRIDE m as the minimum-jerk step
 *     m(u) = 10 u^3 - 15 u^4 + 6 u^5,
 *   the foot rises WALK_HEIGHT m at most as 64 u^3 (1 - u)^3,
 *   the foot pitches toe down, then toe up, by WALK_PITCH rad at most as
 *     -u^3 (1 - u)^3 (1 - 2 u) / 0.0037190 (the bump's largest value),
 * all three with zero first and second derivatives at u = 0 and 1, so the
 * foot stops dead at each stance. The heading follows the circle's tangent.
 * The stairs scenario is the same walk on a stepped path: each of the first
 * WALK_STRIDES / 2 swings also climbs STAIRS_RISE m as m(u), each of the
 * others descends as much, so every stance is on a new level and the last
 * is on the first's.
 */
#define WALK_REST 5.0L
#define WALK_STRIDES 16
#define WALK_PERIOD 1.05L
#define WALK_SWING 0.9L
#define WALK_STRIDE 1.4L
#define WALK_HEIGHT 0.12L
#define WALK_PITCH 0.5L /* rad, ~29 deg */
#define STAIRS_RISE 0.15L

/* With its u-derivatives: 64 u^3 (1 - u)^3 (peak 1 at u = 1/2), or if odd
 * u^3 (1 - u)^3 (1 - 2 u) scaled to a peak of 1 (at u = 0.2113). */
static curve_t walk_bump(ld_t u, int odd)
{
    const ld_t a = u * (1.0L - u), da = 1.0L - 2.0L * u, dda = -2.0L;
    curve_t c;
    /* b = a^3: b' = 3 a^2 a', b'' = 6 a a'^2 + 3 a^2 a'' */
    const ld_t b = a * a * a, db = 3.0L * a * a * da, ddb = 6.0L * a * da * da + 3.0L * a * a * dda;
    if (odd == 0) {
        c.f = 64.0L * b;
        c.d1 = 64.0L * db;
        c.d2 = 64.0L * ddb;
    } else {
        const ld_t k = 1.0L / 0.0037190381L;
        c.f = k * b * da;
        c.d1 = k * (db * da + b * -2.0L);
        c.d2 = k * (ddb * da + 2.0L * db * -2.0L);
    }
    return c;
}

/* The walk with a climb of rise [m] per stride in its first half, a
 * descent as large in its second (0: level). */
static traj_raw_t raw_walk(ld_t t, ld_t rise)
{
    const ld_t radius = WALK_STRIDES * WALK_STRIDE / (2.0L * PI_L);
    const ld_t tw = t - WALK_REST;
    curve_t arc = constant(0.0L), up = constant(0.0L), pitch = constant(0.0L);
    curve_t level = constant(0.0L);
    traj_raw_t r;
    ld_t phi, cphi, sphi;
    if (tw >= (ld_t)WALK_STRIDES * WALK_PERIOD) {
        arc = constant(WALK_STRIDES * WALK_STRIDE);
    } else if (tw > 0.0L) {
        const ld_t k = floorl(tw / WALK_PERIOD);
        const ld_t ts = tw - k * WALK_PERIOD - (WALK_PERIOD - WALK_SWING); /* into the swing */
        const ld_t half = (ld_t)(WALK_STRIDES / 2);
        const ld_t step = k < half ? rise : -rise;
        arc = constant(k * WALK_STRIDE);
        level = constant(rise * (k < half ? k : (ld_t)WALK_STRIDES - k));
        if (ts > 0.0L) {
            const ld_t u = ts / WALK_SWING, w = 1.0L / WALK_SWING;
            const ld_t u2 = u * u;
            /* the minimum-jerk step m(u) and its time derivatives */
            const ld_t m = u2 * u * (10.0L - 15.0L * u + 6.0L * u2);
            const ld_t dm = w * 30.0L * u2 * (1.0L - u) * (1.0L - u);
            const ld_t ddm = w * w * 60.0L * u * (1.0L - u) * (1.0L - 2.0L * u);
            arc.f += WALK_STRIDE * m;
            arc.d1 = WALK_STRIDE * dm;
            arc.d2 = WALK_STRIDE * ddm;
            level.f += step * m;
            level.d1 = step * dm;
            level.d2 = step * ddm;
            up = walk_bump(u, 0);
            pitch = walk_bump(u, 1);
            up.f *= WALK_HEIGHT;
            up.d1 *= WALK_HEIGHT * w;
            up.d2 *= WALK_HEIGHT * w * w;
            pitch.f *= -WALK_PITCH;
            pitch.d1 *= -WALK_PITCH * w;
            pitch.d2 *= -WALK_PITCH * w * w;
        }
    }
    /* on the circle: x = R sin(s/R), y = R (1 - cos(s/R)) (NED, turning right) */
    phi = arc.f / radius;
    cphi = cosl(phi);
    sphi = sinl(phi);
    r.pos[0].f = radius * sphi;
    r.pos[0].d1 = cphi * arc.d1;
    r.pos[0].d2 = cphi * arc.d2 - sphi * arc.d1 * arc.d1 / radius;
    r.pos[1].f = radius * (1.0L - cphi);
    r.pos[1].d1 = sphi * arc.d1;
    r.pos[1].d2 = sphi * arc.d2 + cphi * arc.d1 * arc.d1 / radius;
    r.pos[2].f = -(level.f + up.f);
    r.pos[2].d1 = -(level.d1 + up.d1);
    r.pos[2].d2 = -(level.d2 + up.d2);
    r.roll = constant(0.0L);
    r.pitch = pitch;
    r.yaw.f = phi;
    r.yaw.d1 = arc.d1 / radius;
    r.yaw.d2 = arc.d2 / radius;
    return r;
}

#define WALK_DURATION ((double)(2.0L * WALK_REST + WALK_STRIDES * WALK_PERIOD))
static const char *const names[TRAJ_COUNT] = {"static", "uav", "car", "nav", "walk", "stairs"};
static const double durations[TRAJ_COUNT] = {60.0, 60.0, 120.0, 3600.0, WALK_DURATION,
                                             WALK_DURATION};
static const double ramps[TRAJ_COUNT] = {1.0, 5.0, 10.0, 60.0, 1.0, 1.0};

const char *traj_name(traj_scenario_t s)
{
    return ((int)s >= 0 && (int)s < TRAJ_COUNT) ? names[s] : "?";
}

int traj_find(const char *name)
{
    int i;
    for (i = 0; i < TRAJ_COUNT; i++) {
        if (strcmp(name, names[i]) == 0) {
            return i;
        }
    }
    return -1;
}

double traj_default_duration(traj_scenario_t s)
{
    return ((int)s >= 0 && (int)s < TRAJ_COUNT) ? durations[s] : 0.0;
}

double traj_ramp_duration(traj_scenario_t s)
{
    return ((int)s >= 0 && (int)s < TRAJ_COUNT) ? ramps[s] : 1.0;
}

traj_point_t traj_eval(traj_scenario_t s, ld_t t)
{
    traj_raw_t r;
    traj_point_t pt;
    ld_t cr, sr, cp, sp;
    int i;
    switch (s) {
    case TRAJ_UAV:
        r = raw_uav(t);
        break;
    case TRAJ_CAR:
        r = raw_car(t);
        break;
    case TRAJ_NAV:
        r = raw_nav(t);
        break;
    case TRAJ_WALK:
        r = raw_walk(t, 0.0L);
        break;
    case TRAJ_STAIRS:
        r = raw_walk(t, STAIRS_RISE);
        break;
    case TRAJ_STATIC:
    default:
        r = raw_static();
        break;
    }
    for (i = 0; i < 3; i++) {
        pt.p.v[i] = r.pos[i].f;
        pt.v.v[i] = r.pos[i].d1;
        pt.a.v[i] = r.pos[i].d2;
    }
    pt.R = ld_euler(r.roll.f, r.pitch.f, r.yaw.f);
    cr = cosl(r.roll.f);
    sr = sinl(r.roll.f);
    cp = cosl(r.pitch.f);
    sp = sinl(r.pitch.f);
    /* ZYX Euler kinematics: body rates from angle rates */
    pt.w_nb_b.v[0] = r.roll.d1 - r.yaw.d1 * sp;
    pt.w_nb_b.v[1] = r.pitch.d1 * cr + r.yaw.d1 * sr * cp;
    pt.w_nb_b.v[2] = -r.pitch.d1 * sr + r.yaw.d1 * cr * cp;
    return pt;
}

traj_point_t traj_eval_start(traj_scenario_t s, ld_t rest, ld_t t)
{
    const ld_t ramp = (ld_t)traj_ramp_duration(s);
    ld_t tau, d1, d2; /* tau(t), tau'(t), tau''(t) */
    traj_point_t pt;
    int i;
    if (!(rest > 0.0L)) {
        return traj_eval(s, t);
    }
    if (t <= rest) {
        tau = d1 = d2 = 0.0L;
    } else if (t < rest + ramp) {
        ld_t u = (t - rest) / ramp;
        ld_t u2 = u * u;
        tau = ramp * u2 * u2 * (2.5L - 3.0L * u + u2);
        d1 = u2 * u * (10.0L - 15.0L * u + 6.0L * u2);
        d2 = 30.0L * u2 * (1.0L - u) * (1.0L - u) / ramp;
    } else {
        tau = t - rest - 0.5L * ramp;
        d1 = 1.0L;
        d2 = 0.0L;
    }
    pt = traj_eval(s, tau);
    for (i = 0; i < 3; i++) {
        pt.a.v[i] = pt.a.v[i] * d1 * d1 + pt.v.v[i] * d2;
        pt.v.v[i] *= d1;
        pt.w_nb_b.v[i] *= d1;
    }
    return pt;
}

void traj_check_derivatives(traj_scenario_t s, ld_t duration, long n, ld_t h, ld_t out[3])
{
    long k;
    int i, j;
    out[0] = out[1] = out[2] = 0.0L;
    for (k = 0; k < n; k++) {
        /* off the scenarios' knots (whole and half seconds) */
        const ld_t t = h + (duration - 2.0L * h) * ((ld_t)k + 0.3183L) / (ld_t)n;
        const traj_point_t m = traj_eval(s, t - h), c = traj_eval(s, t), p = traj_eval(s, t + h);
        ld_mat3_t dR, W;
        for (i = 0; i < 3; i++) {
            out[0] = fmaxl(out[0], fabsl(c.v.v[i] - (p.p.v[i] - m.p.v[i]) / (2.0L * h)));
            out[1] = fmaxl(out[1], fabsl(c.a.v[i] - (p.v.v[i] - m.v.v[i]) / (2.0L * h)));
            for (j = 0; j < 3; j++) {
                dR.m[i][j] = (p.R.m[i][j] - m.R.m[i][j]) / (2.0L * h);
            }
        }
        W = ld_mul_tn(&c.R, &dR); /* R^T dR/dt = w^ */
        out[2] = fmaxl(out[2], fabsl(c.w_nb_b.v[0] - W.m[2][1]));
        out[2] = fmaxl(out[2], fabsl(c.w_nb_b.v[1] - W.m[0][2]));
        out[2] = fmaxl(out[2], fabsl(c.w_nb_b.v[2] - W.m[1][0]));
    }
}
