/* The gyroscope's unit check of se23-import; see gyrocheck.h. */
#include "gyrocheck.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#define RAD_PER_DEG (3.14159265358979323846 / 180.0)

void gyro_check_init(gyro_check_t *g, double gyro_scale)
{
    memset(g, 0, sizeof *g);
    g->to_rad = 1.0 / gyro_scale;
    g->to_deg = RAD_PER_DEG / gyro_scale;
    g->R_rad = ld_identity();
    g->R_deg = g->R_rad;
}

static double max_abs3(const double v[3])
{
    return fmax(fabs(v[0]), fmax(fabs(v[1]), fabs(v[2])));
}

/* The unit vector of sum (a run's sum of specific forces) into u. */
static void unit(const double sum[3], double u[3])
{
    const double n = sqrt(sum[0] * sum[0] + sum[1] * sum[1] + sum[2] * sum[2]);
    int k;
    for (k = 0; k < 3; k++) {
        u[k] = n > 0.0 ? sum[k] / n : 0.0;
    }
}

/*
 * A segment starts at the end of the rest r: its gravity; the bias, if r is
 * the first rest (a recording starts at rest; a later "rest", |f| steady,
 * may be a steady turn, whose rate is no bias).
 */
static void segment_start(gyro_check_t *g, const hyg_run_t *r)
{
    int k;
    for (k = 0; k < 3 && !g->have_bias; k++) {
        g->bias[k] = r->w_sum[k] / (double)r->n;
    }
    g->have_bias = 1;
    unit(r->f_sum, g->g1);
    g->R_rad = ld_identity();
    g->R_deg = g->R_rad;
    g->in_segment = 1;
}

/* R <- R exp(scale (w - bias) dt): the rotation of the interval dt_s [s]. */
static void turn(ld_mat3_t *R, const double w[3], const double bias[3], double scale, double dt_s)
{
    double phi[3];
    ld_vec3_t v;
    ld_mat3_t E;
    int k;
    for (k = 0; k < 3; k++) {
        phi[k] = scale * (w[k] - bias[k]) * dt_s;
    }
    v = ld_vec3_from(phi);
    E = ld_exp(&v);
    *R = ld_mul(R, &E);
}

/* R^T g1 - g1: the change of the direction of gravity R predicts, into p. */
static void predicted_change(const ld_mat3_t *R, const double g1[3], double p[3])
{
    const ld_vec3_t u = ld_vec3_from(g1);
    const ld_vec3_t q = ld_tmul_v(R, &u);
    int k;
    for (k = 0; k < 3; k++) {
        p[k] = (double)q.v[k] - g1[k];
    }
}

/* The angle between the unit vectors g1 + p and g2 [deg]. */
static double miss_deg(const double g1[3], const double p[3], const double g2[3])
{
    double d = 0.0;
    int k;
    for (k = 0; k < 3; k++) {
        d += (g1[k] + p[k]) * g2[k];
    }
    return acos(fmax(-1.0, fmin(1.0, d))) / RAD_PER_DEG;
}

/* The segment ends at the rest r that begins: weigh both readings. */
static void segment_end(gyro_check_t *g, const hyg_run_t *r)
{
    double g2[3], m[3], p_deg[3], p_rad[3];
    int k;
    unit(r->f_sum, g2);
    predicted_change(&g->R_deg, g->g1, p_deg);
    predicted_change(&g->R_rad, g->g1, p_rad);
    for (k = 0; k < 3; k++) {
        m[k] = g2[k] - g->g1[k];
        g->s_mp += m[k] * p_deg[k];
        g->s_pp += p_deg[k] * p_deg[k];
        g->s_mm += m[k] * m[k];
    }
    g->votes_deg += miss_deg(g->g1, p_deg, g2) <= GYRO_FIT_DEG &&
                    miss_deg(g->g1, p_rad, g2) >= GYRO_MISS_DEG;
    g->segments++;
    g->in_segment = 0;
}

void gyro_check_add(gyro_check_t *g, const row_t *r, hyg_rest_event_t ev, const hyg_rest_t *rest)
{
    const double w = max_abs3(r->omega);
    const double dt_s = g->have_last ? (double)hygiene_interval(g->last_t_ns, r->t_ns) * 1e-9 : 0.0;
    g->over_range += w * g->to_rad > GYRO_RANGE_MAX && w * g->to_deg <= GYRO_RANGE_MAX;
    g->last_t_ns = r->t_ns;
    g->have_last = 1;
    if (ev == HYG_REST_ENDS) {
        segment_start(g, &rest->last);
    }
    if (g->in_segment) {
        turn(&g->R_rad, r->omega, g->bias, g->to_rad, dt_s);
        turn(&g->R_deg, r->omega, g->bias, g->to_deg, dt_s);
    }
    if (ev == HYG_REST_BEGINS && g->in_segment) {
        segment_end(g, &rest->run);
    }
}

void gyro_check_gain(const gyro_check_t *g, double *gain, double *se)
{
    const double dof = 3.0 * (double)g->segments - 1.0; /* 3 components a segment */
    double rss;
    *gain = 0.0;
    *se = 0.0;
    if (g->s_pp <= 0.0 || dof < 1.0) {
        return;
    }
    *gain = g->s_mp / g->s_pp;
    rss = fmax(0.0, g->s_mm - *gain * g->s_mp);
    *se = sqrt(rss / dof / g->s_pp);
}

gyro_unit_t gyro_check_verdict(const gyro_check_t *g)
{
    double gain, se;
    int deg, rad;
    gyro_check_gain(g, &gain, &se);
    deg = g->over_range >= GYRO_OVER_MIN || g->votes_deg >= GYRO_VOTES_MIN;
    rad = g->segments >= GYRO_SEGMENTS_MIN && gain >= GYRO_GAIN_MIN && gain - 3.0 * se > 1.0;
    return deg && rad ? GYRO_CONFLICT : deg ? GYRO_IS_DEG : rad ? GYRO_IS_RAD : GYRO_UNDECIDED;
}

void gyro_check_describe(const gyro_check_t *g, char *buf, size_t n)
{
    double gain, se;
    gyro_check_gain(g, &gain, &se);
    snprintf(buf, n,
             "%lld samples beyond 4000 deg/s if rad/s; %lld rest-to-rest tilt changes, %lld "
             "followed within %.0f deg as deg/s and missed by %.0f deg or more as rad/s, and "
             "%.3g +- %.2g times what deg/s predicts",
             (long long)g->over_range, (long long)g->segments, (long long)g->votes_deg,
             GYRO_FIT_DEG, GYRO_MISS_DEG, gain, se);
}
