/* Designed motions and IMU sample generation; see scenario.h. */
#include "scenario.h"

#include <math.h>

#define PI_L 3.141592653589793238462643383279502884L
#define DEG (PI_L / 180)
#define WE 7.292115e-5L /* WGS-84 Earth rate [rad/s] */

/* Error models (1 sigma), typical datasheet figures:
 * MEMS (consumer/industrial, e.g. drone autopilot): gyro bias 10 deg/h,
 *   ARW 0.6 deg/sqrt(h), accel bias 1 mg, 150 ug/sqrt(Hz).
 * Navigation grade (~1 nmi/h ring-laser/fibre-optic INS): gyro bias
 *   0.01 deg/h, ARW 0.002 deg/sqrt(h), accel bias 25 ug, 5 ug/sqrt(Hz). */
const acc_grade_t acc_grades[2] = {
    {"MEMS drone 200 Hz", 200, 10 * DEG / 3600, 0.6L * DEG / 60, 9.80665e-3L, 1.5e-3L,
     {40, 0.1L, -20, {2, 0.3L}, {0.2L, 0.9L}, {0.1L, 0.7L}, {0.08L, 0.5L}}},
    {"nav-grade ship 100 Hz", 100, 0.01L * DEG / 3600, 0.002L * DEG / 60, 2.5e-4L, 5e-5L,
     {2000, 0.005L, 0, {0.5L, 0.6L}, {0.02L, 0.2L}, {0.05L, 0.5L}, {0.02L, 0.3L}}},
};

void acc_earth(ld g[3], ld omega[3])
{
    /* WGS-84 Somigliana at 45 deg: gamma_e (1 + k/2) / sqrt(1 - e^2/2). */
    const ld ge = 9.7803253359L, k = 0.00193185265241L, e2 = 0.00669437999013L;
    const ld c = sqrtl(0.5L);
    g[0] = 0;
    g[1] = 0;
    g[2] = ge * (1 + k / 2) / sqrtl(1 - e2 / 2);
    omega[0] = WE * c;
    omega[1] = 0;
    omega[2] = -WE * c;
}

/* Euler angles (yaw, pitch, roll) and their rates at t. */
static void attitude(const acc_motion_t *m, ld t, ld e[3], ld de[3])
{
    e[0] = m->rate * t + PI_L / 2 + m->yaw[0] * sinl(m->yaw[1] * t);
    de[0] = m->rate + m->yaw[0] * m->yaw[1] * cosl(m->yaw[1] * t);
    e[1] = m->pitch[0] * sinl(m->pitch[1] * t + 1);
    de[1] = m->pitch[0] * m->pitch[1] * cosl(m->pitch[1] * t + 1);
    e[2] = m->roll[0] * sinl(m->roll[1] * t);
    de[2] = m->roll[0] * m->roll[1] * cosl(m->roll[1] * t);
}

/* R = Rz(yaw) Ry(pitch) Rx(roll), body to NED. */
static void rotation(const ld e[3], ld R[3][3])
{
    const ld cy = cosl(e[0]), sy = sinl(e[0]), cp = cosl(e[1]), sp = sinl(e[1]);
    const ld cr = cosl(e[2]), sr = sinl(e[2]);
    R[0][0] = cy * cp;
    R[0][1] = cy * sp * sr - sy * cr;
    R[0][2] = cy * sp * cr + sy * sr;
    R[1][0] = sy * cp;
    R[1][1] = sy * sp * sr + cy * cr;
    R[1][2] = sy * sp * cr - cy * sr;
    R[2][0] = -sp;
    R[2][1] = cp * sr;
    R[2][2] = cp * cr;
}

/* Position, velocity, acceleration on the circle with heave. */
static void translation(const acc_motion_t *m, ld t, ld p[3], ld v[3], ld a[3])
{
    const ld c = cosl(m->rate * t), s = sinl(m->rate * t);
    const ld A = m->heave[0], w = m->heave[1];
    p[0] = m->radius * c;
    p[1] = m->radius * s;
    p[2] = m->z0 + A * sinl(w * t);
    v[0] = -m->radius * m->rate * s;
    v[1] = m->radius * m->rate * c;
    v[2] = A * w * cosl(w * t);
    a[0] = -m->radius * m->rate * m->rate * c;
    a[1] = -m->radius * m->rate * m->rate * s;
    a[2] = -A * w * w * sinl(w * t);
}

void acc_motion_state(const acc_motion_t *m, ld t, ld R[3][3], ld v[3], ld p[3])
{
    ld e[3], de[3], a[3];
    attitude(m, t, e, de);
    rotation(e, R);
    translation(m, t, p, v, a);
}

static void cross(const ld a[3], const ld b[3], ld c[3])
{
    const ld x = a[1] * b[2] - a[2] * b[1], y = a[2] * b[0] - a[0] * b[2];
    c[2] = a[0] * b[1] - a[1] * b[0];
    c[0] = x;
    c[1] = y;
}

static uint64_t next_u64(uint64_t *state)
{
    uint64_t z = (*state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

/* Standard normal (Box-Muller). */
static ld normal(uint64_t *state)
{
    const ld u1 = ((ld)(next_u64(state) >> 11) + 1) * 0x1.0p-53L;
    const ld u2 = (ld)(next_u64(state) >> 11) * 0x1.0p-53L;
    return sqrtl(-2 * logl(u1)) * cosl(2 * PI_L * u2);
}

void acc_sensor_init(acc_sensor_t *s, const acc_grade_t *grade, uint64_t seed)
{
    s->grade = grade;
    s->rng = seed;
    for (int i = 0; i < 3; ++i) {
        s->bias_g[i] = grade->gyro_bias * ((next_u64(&s->rng) & 1) ? 1 : -1);
        s->bias_a[i] = grade->accel_bias * ((next_u64(&s->rng) & 1) ? 1 : -1);
    }
}

void acc_sample(acc_sensor_t *s, long k, ld w[3], ld f[3], ld w_meas[3], ld f_meas[3])
{
    const acc_grade_t *gr = s->grade;
    const ld t = ((ld)k + 0.5L) / gr->rate_hz;
    ld g[3], om[3], e[3], de[3], R[3][3], p[3], v[3], a[3];
    acc_earth(g, om);
    attitude(&gr->motion, t, e, de);
    rotation(e, R);
    translation(&gr->motion, t, p, v, a);
    /* w_nb_b from the ZYX Euler rates. */
    const ld sp = sinl(e[1]), cp = cosl(e[1]), sr = sinl(e[2]), cr = cosl(e[2]);
    const ld wnb[3] = {de[2] - de[0] * sp, de[1] * cr + de[0] * cp * sr,
                       -de[1] * sr + de[0] * cp * cr};
    /* R f = a - g + 2 Omega x v + Omega x (Omega x p). */
    ld wv[3], wp[3], wwp[3], fn[3];
    cross(om, v, wv);
    cross(om, p, wp);
    cross(om, wp, wwp);
    for (int i = 0; i < 3; ++i) {
        fn[i] = a[i] - g[i] + 2 * wv[i] + wwp[i];
    }
    const ld sg = gr->gyro_arw * sqrtl(gr->rate_hz), sa = gr->accel_vrw * sqrtl(gr->rate_hz);
    for (int i = 0; i < 3; ++i) {
        w[i] = wnb[i] + R[0][i] * om[0] + R[1][i] * om[1] + R[2][i] * om[2];
        f[i] = R[0][i] * fn[0] + R[1][i] * fn[1] + R[2][i] * fn[2];
        w_meas[i] = w[i] + s->bias_g[i] + sg * normal(&s->rng);
        f_meas[i] = f[i] + s->bias_a[i] + sa * normal(&s->rng);
    }
}
