/* WGS-84 gravity, Earth rate and the navigation model; see earth.h. */
#include "se23/earth.h"

#include "../base/argcheck.h"
#include "../base/linalg.h"
#include "../base/se23_math.h"
#include "../lie/so3_series.h"
#include "../base/trig.h"

/* |lat| <= pi/2 + slack, lat finite. */
static se23_status_t check_lat(se23_real_t lat)
{
    if (!se23_is_finite(lat)) {
        return SE23_ERR_NONFINITE;
    }
    if (!(se23_fabs(lat) <= SE23_R(0.5) * SE23_PI + SE23_R(SE23_EARTH_LAT_SLACK))) {
        return SE23_ERR_DOMAIN;
    }
    return SE23_OK;
}

se23_status_t se23_earth_gravity(se23_real_t lat, se23_real_t h, se23_real_t *g)
{
    SE23_CHECK_NOT_NULL(g);
    se23_status_t st = check_lat(lat);
    if (st != SE23_OK) {
        return st;
    }
    if (!se23_is_finite(h)) {
        return SE23_ERR_NONFINITE;
    }
    if (!(h >= SE23_R(SE23_EARTH_H_MIN) && h <= SE23_R(SE23_EARTH_H_MAX))) {
        return SE23_ERR_DOMAIN;
    }
    se23_real_t s, c;
    se23_sincos(lat, &s, &c);
    const se23_real_t s2 = s * s;
    const se23_real_t g0 = SE23_R(SE23_WGS84_GAMMA_E) *
                           (SE23_R(1) + SE23_R(SE23_WGS84_K) * s2) /
                           se23_sqrt(SE23_R(1) - SE23_R(SE23_WGS84_E2) * s2);
    const se23_real_t a = SE23_R(SE23_WGS84_A);
    const se23_real_t lin = SE23_R(2) / a *
                            (SE23_R(1) + SE23_R(SE23_WGS84_F) + SE23_R(SE23_WGS84_M) -
                             SE23_R(2) * SE23_R(SE23_WGS84_F) * s2);
    const se23_real_t hr = h / a;
    *g = g0 * (SE23_R(1) - lin * h + SE23_R(3) * hr * hr);
    return SE23_OK;
}

se23_status_t se23_earth_gravity_vec(se23_frame_t frame, se23_real_t lat,
                                     se23_real_t h, se23_vec3_t *g_n)
{
    SE23_CHECK_NOT_NULL(g_n);
    if (frame != SE23_FRAME_NED && frame != SE23_FRAME_ENU) {
        return SE23_ERR_DOMAIN;
    }
    se23_real_t g;
    se23_status_t st = se23_earth_gravity(lat, h, &g);
    if (st != SE23_OK) {
        return st;
    }
    g_n->v[0] = SE23_R(0);
    g_n->v[1] = SE23_R(0);
    g_n->v[2] = (frame == SE23_FRAME_NED) ? g : -g;
    return SE23_OK;
}

se23_status_t se23_earth_rate(se23_frame_t frame, se23_real_t lat,
                              se23_vec3_t *w_ie_n)
{
    SE23_CHECK_NOT_NULL(w_ie_n);
    if (frame != SE23_FRAME_NED && frame != SE23_FRAME_ENU) {
        return SE23_ERR_DOMAIN;
    }
    se23_status_t st = check_lat(lat);
    if (st != SE23_OK) {
        return st;
    }
    const se23_real_t we = SE23_R(SE23_WGS84_OMEGA_E);
    se23_real_t sin_lat, cos_lat;
    se23_sincos(lat, &sin_lat, &cos_lat);
    const se23_real_t north = we * cos_lat;
    const se23_real_t up = we * sin_lat;
    if (frame == SE23_FRAME_NED) {
        w_ie_n->v[0] = north;
        w_ie_n->v[1] = SE23_R(0);
        w_ie_n->v[2] = -up;
    } else {
        w_ie_n->v[0] = SE23_R(0);
        w_ie_n->v[1] = north;
        w_ie_n->v[2] = up;
    }
    return SE23_OK;
}

se23_status_t se23_earth_gamma(const se23_vec3_t *g_n, const se23_vec3_t *w_ie_n,
                               se23_real_t t, se23_pose_t *gamma)
{
    SE23_CHECK_NOT_NULL(g_n);
    SE23_CHECK_NOT_NULL(w_ie_n);
    SE23_CHECK_NOT_NULL(gamma);
    if (!se23_all_finite(g_n->v, 3) || !se23_all_finite(w_ie_n->v, 3) ||
        !se23_is_finite(t)) {
        return SE23_ERR_NONFINITE;
    }
    if (t < SE23_R(0)) {
        return SE23_ERR_DT;
    }
    /* phi = -Omega t: Gamma^R = exp(phi), Gamma^v = t J(phi) g,
     * Gamma^x = t^2 K(phi) g, all from one angle. */
    se23_vec3_t phi;
    se23_v3_scale(w_ie_n, -t, &phi);
    const se23_real_t theta = se23_sqrt(se23_v3_dot(&phi, &phi));
    se23_so3_coeffs_t c;
    se23_so3_coeffs(theta, &c);
    se23_real_t k1;
    se23_real_t k2;
    se23_so3_k_coeffs(theta, &k1, &k2);
    if (!se23_so3_gamma_series(&phi, &c, k1, k2, t, g_n, gamma)) {
        return SE23_ERR_NONFINITE; /* |Omega t|^2 or t^2 g overflowed */
    }
    return SE23_OK;
}

se23_status_t se23_earth_model_init(const se23_vec3_t *g_n,
                                    const se23_vec3_t *w_ie_n, se23_real_t dt,
                                    se23_real_t dt_max,
                                    se23_earth_model_t *model)
{
    SE23_CHECK_NOT_NULL(g_n);
    SE23_CHECK_NOT_NULL(w_ie_n);
    SE23_CHECK_NOT_NULL(model);
    if (!se23_is_finite(dt) || !se23_is_finite(dt_max)) {
        return SE23_ERR_NONFINITE;
    }
    if (!(dt > SE23_R(0) && dt <= dt_max && dt_max <= SE23_R(SE23_CFG_DT_MAX))) {
        return SE23_ERR_DT;
    }
    se23_earth_model_t out;
    se23_status_t st = se23_earth_gamma(g_n, w_ie_n, dt, &out.gamma);
    if (st != SE23_OK) {
        return st;
    }
    out.g_n = *g_n;
    out.w_ie_n = *w_ie_n;
    out.dt = dt;
    out.dt_max = dt_max;
    *model = out;
    return SE23_OK;
}

se23_status_t se23_earth_model_init_wgs84(se23_frame_t frame, se23_real_t lat,
                                          se23_real_t h, se23_real_t dt,
                                          se23_real_t dt_max,
                                          se23_earth_model_t *model)
{
    SE23_CHECK_NOT_NULL(model);
    se23_vec3_t g_n;
    se23_vec3_t w_ie_n;
    se23_status_t st = se23_earth_gravity_vec(frame, lat, h, &g_n);
    if (st != SE23_OK) {
        return st;
    }
    st = se23_earth_rate(frame, lat, &w_ie_n);
    if (st != SE23_OK) {
        return st;
    }
    return se23_earth_model_init(&g_n, &w_ie_n, dt, dt_max, model);
}
