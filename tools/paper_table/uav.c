/* The UAV trajectory of the paper's Table; see uav.h. */
#include "uav.h"

#include <math.h>

#define PI 3.14159265358979323846
#define AX 60.0
#define AY 30.0
#define AZ 10.0
#define H0 50.0
#define WA (2.0 * PI / 80.0)
#define WB (2.0 * PI / 50.0)

/* Position, velocity and acceleration of the figure of eight (NED). */
static void kinematics(double t, double p[3], double v[3], double a[3])
{
    p[0] = AX * sin(WA * t);
    p[1] = AY * sin(2.0 * WA * t);
    p[2] = -H0 - AZ * sin(WB * t);
    v[0] = AX * WA * cos(WA * t);
    v[1] = 2.0 * AY * WA * cos(2.0 * WA * t);
    v[2] = -AZ * WB * cos(WB * t);
    a[0] = -AX * WA * WA * sin(WA * t);
    a[1] = -4.0 * AY * WA * WA * sin(2.0 * WA * t);
    a[2] = AZ * WB * WB * sin(WB * t);
}

void uav_state(double t, uav_state_t *s)
{
    double a[3];
    kinematics(t, s->p, s->v, a);
    /* Euler angles and their rates. */
    const double yaw = atan2(s->v[1], s->v[0]);
    const double yaw_d = (s->v[0] * a[1] - s->v[1] * a[0]) /
                         (s->v[0] * s->v[0] + s->v[1] * s->v[1]);
    const double roll = 0.15 * sin(0.4 * t), roll_d = 0.06 * cos(0.4 * t);
    const double pitch = 0.1 * sin(0.3 * t + 1.0);
    const double pitch_d = 0.03 * cos(0.3 * t + 1.0);
    const double cy = cos(yaw), sy = sin(yaw), cp = cos(pitch), sp = sin(pitch);
    const double cr = cos(roll), sr = sin(roll);
    const double R[3][3] = {
        {cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr},
        {sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr},
        {-sp, cp * sr, cp * cr}};
    s->w_b[0] = roll_d - yaw_d * sp;
    s->w_b[1] = pitch_d * cr + yaw_d * sr * cp;
    s->w_b[2] = -pitch_d * sr + yaw_d * cr * cp;
    const double acc[3] = {a[0], a[1], a[2] - UAV_G}; /* dv/dt - g */
    for (int i = 0; i < 3; ++i) {
        double f = 0.0;
        for (int j = 0; j < 3; ++j) {
            s->R[i][j] = R[i][j];
            f += R[j][i] * acc[j];
        }
        s->f_b[i] = f;
    }
}

void uav_sample(long k, double hz, double w_b[3], double f_b[3])
{
    uav_state_t s;
    uav_state(((double)k + 0.5) / hz, &s);
    for (int i = 0; i < 3; ++i) {
        w_b[i] = s.w_b[i];
        f_b[i] = s.f_b[i];
    }
}
