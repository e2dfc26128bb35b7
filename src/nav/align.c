/* Static alignment: levelling, gyrocompassing, the attitude covariance; see
 * align.h. Angles are carried as (cos, sin) pairs built from unit vectors,
 * so that levelling needs no trigonometry and R is orthonormal to a few
 * epsilons whatever the attitude. */
#include "se23/align.h"

#include "../base/argcheck.h"
#include "../base/linalg.h"
#include "se23/so3.h"
#include "../base/se23_math.h"
#include "../base/trig.h"

/* The (cos, sin) pairs of roll, pitch and yaw. */
typedef struct {
    se23_real_t cr, sr, cp, sp, cy, sy;
} angles_t;

static int frame_ok(se23_frame_t frame)
{
    return (frame == SE23_FRAME_NED) || (frame == SE23_FRAME_ENU);
}

/* Checks f_mean against the band of align.h (f finite); on SE23_OK sets
 * the roll and pitch pairs of a (file comment of align.h). */
static se23_status_t tilt(se23_frame_t frame, const se23_vec3_t *f, angles_t *a)
{
    const se23_real_t norm = se23_sqrt(se23_v3_dot(f, f));
    const se23_real_t g0 = SE23_R(SE23_ALIGN_G0);
    if (!((norm >= SE23_R(SE23_ALIGN_F_MIN) * g0) && (norm <= SE23_R(SE23_ALIGN_F_MAX) * g0))) {
        return SE23_ERR_DOMAIN;
    }
    /* d = s f / |f| = R^T e_z = (-sin pitch, cos pitch sin roll, cos pitch cos roll). */
    const se23_real_t s = (frame == SE23_FRAME_NED) ? SE23_R(-1) : SE23_R(1);
    se23_vec3_t d;
    se23_v3_scale(f, s / norm, &d);
    const se23_real_t ay = se23_fabs(d.v[1]);
    const se23_real_t az = se23_fabs(d.v[2]);
    const se23_real_t m = (ay > az) ? ay : az;
    a->sp = -d.v[0];
    if (m > SE23_R(0)) {
        /* (d_y, d_z) scaled to max 1 first: no underflow near pitch 90 deg. */
        const se23_real_t y = d.v[1] / m;
        const se23_real_t z = d.v[2] / m;
        const se23_real_t len = se23_sqrt(y * y + z * z);
        a->sr = y / len;
        a->cr = z / len;
        a->cp = m * len;
    } else {
        a->sr = SE23_R(0); /* body x vertical: roll set to 0 */
        a->cr = SE23_R(1);
        a->cp = SE23_R(0);
    }
    return SE23_OK;
}

/* R = Rz(yaw) Ry(pitch) Rx(roll). */
static void euler_to_rot(const angles_t *a, se23_mat3_t *R)
{
    const se23_real_t spsr = a->sp * a->sr;
    const se23_real_t spcr = a->sp * a->cr;
    R->m[0][0] = a->cy * a->cp;
    R->m[0][1] = a->cy * spsr - a->sy * a->cr;
    R->m[0][2] = a->cy * spcr + a->sy * a->sr;
    R->m[1][0] = a->sy * a->cp;
    R->m[1][1] = a->sy * spsr + a->cy * a->cr;
    R->m[1][2] = a->sy * spcr - a->cy * a->sr;
    R->m[2][0] = -a->sp;
    R->m[2][1] = a->cp * a->sr;
    R->m[2][2] = a->cp * a->cr;
}

/* Sets the yaw pair of a (its roll and pitch pairs set by tilt) from the
 * mean gyro reading w: w_l = R0 w, R0 = Ry(pitch) Rx(roll), h = the
 * horizontal part of w_l, checked against the band [RATE_MIN, RATE_MAX] x wh
 * (wh = W |cos lat| > 0). */
static se23_status_t heading(se23_frame_t frame, const se23_vec3_t *w,
                             se23_real_t wh, angles_t *a)
{
    se23_mat3_t R0;
    a->cy = SE23_R(1);
    a->sy = SE23_R(0);
    euler_to_rot(a, &R0);
    se23_vec3_t wl;
    se23_m3_mul_v3(&R0, w, &wl);
    const se23_real_t hx = wl.v[0];
    const se23_real_t hy = wl.v[1];
    const se23_real_t hn = se23_sqrt(hx * hx + hy * hy);
    if (!((hn >= SE23_R(SE23_ALIGN_RATE_MIN) * wh) && (hn <= SE23_R(SE23_ALIGN_RATE_MAX) * wh))) {
        return SE23_ERR_DOMAIN;
    }
    /* h / |h| = (cos yaw, -sin yaw) in NED, (sin yaw, cos yaw) in ENU. */
    if (frame == SE23_FRAME_NED) {
        a->cy = hx / hn;
        a->sy = -hy / hn;
    } else {
        a->cy = hy / hn;
        a->sy = hx / hn;
    }
    return SE23_OK;
}

se23_status_t se23_align_level(se23_frame_t frame, const se23_vec3_t *f_mean,
                               se23_real_t yaw, se23_mat3_t *R)
{
    SE23_CHECK_NOT_NULL(f_mean);
    SE23_CHECK_NOT_NULL(R);
    if ((se23_all_finite(f_mean->v, 3) == 0) || (se23_is_finite(yaw) == 0)) {
        return SE23_ERR_NONFINITE;
    }
    if (frame_ok(frame) == 0) {
        return SE23_ERR_DOMAIN;
    }
    angles_t a;
    const se23_status_t st = tilt(frame, f_mean, &a);
    if (st != SE23_OK) {
        return st;
    }
    se23_sincos(yaw, &a.sy, &a.cy);
    euler_to_rot(&a, R);
    return SE23_OK;
}

se23_status_t se23_align_cov(const se23_mat3_t *R, se23_real_t sigma_f, int n,
                             se23_real_t g, se23_real_t sigma_yaw,
                             se23_mat3_t *P)
{
    SE23_CHECK_NOT_NULL(R);
    SE23_CHECK_NOT_NULL(P);
    if ((se23_all_finite(&R->m[0][0], 9) == 0) || (se23_is_finite(sigma_f) == 0) ||
        (se23_is_finite(g) == 0) || (se23_is_finite(sigma_yaw) == 0)) {
        return SE23_ERR_NONFINITE;
    }
    if (n < 1) {
        return SE23_ERR_DIM;
    }
    if (!(sigma_f > SE23_R(0)) || !(g > SE23_R(0)) || !(sigma_yaw > SE23_R(0))) {
        return SE23_ERR_DOMAIN;
    }
    const se23_status_t st = se23_so3_check(R);
    if (st != SE23_OK) {
        return st;
    }
    /* P = t2 I + (y2 - t2) r r^T / |r|^2, r = R^T e_z; upper triangle,
     * mirrored. R is a rotation only to SE23_CFG_ROT_TOL: without the
     * division the variance along r, y2 + (y2 - t2)(|r|^2 - 1), went
     * negative for y2 far below t2. The diagonal is formed without
     * cancellation, P_ii = (t2 (r_j^2 + r_k^2) + y2 r_i^2) / |r|^2: as
     * t2 + (y2 - t2) r_i^2 / |r|^2 it rounded to about -eps t2 for a
     * vertical r when y2 < eps t2 (a tilt 1-sigma beyond any small angle,
     * found by fuzz_align), a negative variance. */
    const se23_real_t tl = sigma_f / g;
    const se23_real_t t2 = tl * tl / (se23_real_t)n;
    const se23_real_t y2 = sigma_yaw * sigma_yaw;
    const se23_vec3_t r = {{R->m[2][0], R->m[2][1], R->m[2][2]}};
    const se23_vec3_t rsq = {{r.v[0] * r.v[0], r.v[1] * r.v[1], r.v[2] * r.v[2]}};
    const se23_real_t rr = rsq.v[0] + rsq.v[1] + rsq.v[2]; /* |rr - 1| <= 3 tol */
    const se23_real_t c = (y2 - t2) / rr;
    se23_mat3_t out;
    for (int i = 0; i < 3; ++i) {
        const se23_real_t others = rsq.v[(i + 1) % 3] + rsq.v[(i + 2) % 3];
        out.m[i][i] = ((t2 * others) + (y2 * rsq.v[i])) / rr;
        for (int j = i + 1; j < 3; ++j) {
            out.m[i][j] = c * r.v[i] * r.v[j];
            out.m[j][i] = out.m[i][j];
        }
    }
    if (se23_all_finite(&out.m[0][0], 9) == 0) {
        return SE23_ERR_NONFINITE;
    }
    *P = out;
    return SE23_OK;
}

se23_status_t se23_align_gyrocompass(se23_frame_t frame, se23_real_t lat,
                                     const se23_vec3_t *f_mean,
                                     const se23_vec3_t *w_mean,
                                     se23_real_t sigma_w, int n, se23_mat3_t *R,
                                     se23_real_t *yaw, se23_real_t *sigma_yaw)
{
    SE23_CHECK_NOT_NULL(f_mean);
    SE23_CHECK_NOT_NULL(w_mean);
    SE23_CHECK_NOT_NULL(R);
    SE23_CHECK_NOT_NULL(yaw);
    SE23_CHECK_NOT_NULL(sigma_yaw);
    if ((se23_is_finite(lat) == 0) || (se23_all_finite(f_mean->v, 3) == 0) ||
        (se23_all_finite(w_mean->v, 3) == 0) || (se23_is_finite(sigma_w) == 0)) {
        return SE23_ERR_NONFINITE;
    }
    if (n < 1) {
        return SE23_ERR_DIM;
    }
    if ((frame_ok(frame) == 0) || !(sigma_w > SE23_R(0)) ||
        !(se23_fabs(lat) <= SE23_R(0.5) * SE23_PI + SE23_R(SE23_EARTH_LAT_SLACK))) {
        return SE23_ERR_DOMAIN;
    }
    angles_t a;
    const se23_status_t st = tilt(frame, f_mean, &a);
    if (st != SE23_OK) {
        return st;
    }
    /* Horizontal Earth rate W |cos lat| and the heading std. */
    se23_real_t sin_lat, cos_lat;
    se23_sincos(lat, &sin_lat, &cos_lat);
    const se23_real_t wh = SE23_R(SE23_WGS84_OMEGA_E) * se23_fabs(cos_lat);
    const se23_real_t denom = se23_sqrt((se23_real_t)n) * wh;
    if (!(sigma_w <= SE23_R(SE23_ALIGN_YAW_STD_MAX) * denom)) {
        return SE23_ERR_DOMAIN;
    }
    const se23_status_t sh = heading(frame, w_mean, wh, &a);
    if (sh != SE23_OK) {
        return sh;
    }
    euler_to_rot(&a, R);
    *yaw = se23_atan2(a.sy, a.cy);
    *sigma_yaw = sigma_w / denom;
    return SE23_OK;
}
