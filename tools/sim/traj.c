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

static const char *const names[TRAJ_COUNT] = {"static", "uav", "car", "nav"};
static const double durations[TRAJ_COUNT] = {60.0, 60.0, 120.0, 3600.0};
static const double ramps[TRAJ_COUNT] = {1.0, 5.0, 10.0, 60.0};

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
