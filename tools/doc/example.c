/* The README's five-minute example: the navigation filter (se23/ins.h) in a
 * car's firmware, a 100 Hz IMU and GNSS fixes. The README quotes this file;
 * it compiles with -std=c99 -Wall -Wextra -Wpedantic -Werror -Iinclude
 * -Iport in both precisions. */
#include <stdint.h>
#include <string.h>

#include "se23/geodetic.h"
#include "se23/ins.h"

static se23_ins_t ins;          /* 27 kB in double, 15 kB in float: static, not on a stack */
static se23_geo_frame_t frame;  /* the nav frame: NED at the first fix */

/* Setup and init: the car preset, this car's installation, a known start. */
int nav_start(int64_t t0_ns, const se23_geo_t *origin)
{
    se23_ins_config_t cfg;
    se23_ins_align_t align;
    se23_gauss_t g0;
    int i;

    if (se23_geo_origin(origin, &frame) != SE23_OK ||
        se23_ins_preset_car(SE23_R(100.0), SE23_R(origin->lat_e9 / 1000) * SE23_R(1.745329251994e-8),
                            &cfg, &align) != SE23_OK) {
        return -1;
    }
    cfg.lever_b.v[0] = SE23_R(0.5);   /* GNSS antenna 0.5 m ahead of the IMU, */
    cfg.lever_b.v[2] = SE23_R(-1.0);  /* 1 m above it (body frame FRD) */
    if (se23_ins_setup(&cfg, &ins) != SE23_OK) {
        return -1;
    }
    /* A known initial state: level, heading north, at rest at the origin
     * (or se23_ins_align(&ins, &align): level from the first 2 s at rest,
     * heading from the GNSS course once the car moves). */
    memset(&g0, 0, sizeof g0);
    g0.T.R.m[0][0] = g0.T.R.m[1][1] = g0.T.R.m[2][2] = SE23_R(1.0);
    g0.n = 15;                                           /* pose + both biases */
    for (i = 0; i < 15; i++) {
        static const se23_real_t sigma[5] = {0.01, 0.1, 0.5, 0.01, 0.1}; /* phi [rad], v [m/s], p [m], b_g [rad/s], b_a [m/s^2] */
        g0.P.m[15 * i + i] = sigma[i / 3] * sigma[i / 3];
    }
    g0.P.m[15 * 2 + 2] = SE23_R(0.1 * 0.1);              /* heading: 0.1 rad */
    return se23_ins_init(&ins, t0_ns, &g0) == SE23_OK ? 0 : -1;
}

/* Per IMU sample: time [ns] at the end of the interval it covers, its
 * sequence number, gyro [rad/s] and specific force [m/s^2] in the body frame. */
void nav_imu(int64_t t_ns, int64_t seq, const se23_real_t gyro[3], const se23_real_t accel[3])
{
    se23_vec3_t w_b, f_b;
    memcpy(w_b.v, gyro, sizeof w_b.v);
    memcpy(f_b.v, accel, sizeof f_b.v);
    if (se23_ins_imu(&ins, t_ns, seq, &w_b, &f_b) != SE23_INS_USED) {
        /* refused (a duplicate, a NaN, a gap too long...): counted in ins.c
         * (se23_ins_counters_t), the state untouched */
    }
}

/* Per GNSS fix, whenever it arrives: stamped with the time it refers to
 * (up to cfg.delay_horizon late is fused at that time). */
void nav_gnss(int64_t t_ns, const se23_geo_t *pos, se23_real_t sigma_h, se23_real_t sigma_v)
{
    se23_ins_gnss_t fix;
    memset(&fix, 0, sizeof fix);
    fix.t_ns = t_ns;
    if (se23_geo_to_ned(&frame, pos, &fix.p_n) != SE23_OK) {
        return;
    }
    fix.sigma_p.v[0] = fix.sigma_p.v[1] = sigma_h;
    fix.sigma_p.v[2] = sigma_v;
    fix.has_vel = 0;                 /* position only */
    (void)se23_ins_gnss(&ins, &fix); /* a verdict, as for a sample */
}

/* Read the state: position [m, NED], velocity [m/s], attitude, biases and
 * their 15x15 covariance, at the time of the last sample. */
int nav_read(se23_vec3_t *p_n, se23_vec3_t *v_n, uint32_t *status)
{
    se23_gauss_t s;
    int64_t t_ns;
    if (se23_ins_state(&ins, &s, &t_ns) != SE23_OK) {
        return -1;                   /* no state yet */
    }
    *p_n = s.T.p;
    *v_n = s.T.v;
    *status = ins.status;            /* SE23_INS_ST_* bits: aided, degraded, lost... */
    return 0;
}
