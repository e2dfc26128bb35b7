/* The navigation filter's gravity as the vehicle moves ("Frame", ins.h).
 *
 * The nav frame is the origin's NED tangent frame: Cartesian and fixed to
 * the Earth, so the Earth rate is the same vector everywhere in it and the
 * Coriolis and centrifugal terms stay exact. Only gravity depends on where
 * the vehicle is: the local vertical tilts from the origin's by the angle
 * the Earth's surface turns through, about 0.16 mrad per km (a gravity
 * error of 1.5 mm/s^2 per km if it were ignored), and it weakens with
 * height. So with gravity_step > 0 the filter re-evaluates the gravity
 * vector whenever its position enters another cube of gravity_step metres,
 * at the cube's centre c:
 *   g_n(c) = g(lat0 + c_N / (M + h0), h0 - c_D) u / |u|,
 *   u = (-c_N / (M + h0), -c_E / (N + h0), 1),
 * M and N the WGS-84 meridian and prime-vertical radii at the origin, g
 * the normal gravity of earth.h. u is the local down of a sphere with the
 * origin's radii of curvature (exact to first order in the offset d; the
 * second-order terms tilt it by at most (d/R)^2: 1e-5 rad, 0.1 mg, at 20
 * km; 6e-5 rad at 50 km). The cube's size bounds what the steps add: 100 m
 * is 16 urad, 0.15 mm/s^2. The cube is a function of the position alone,
 * so a replay (delayed fixes) meets the same gravity at the same place.
 * The gravity gradient's coupling of position errors into velocity (the
 * Schuler loop, period 84 min) is left out of the covariance. */
#include "ins_internal.h"

#include "se23/earth.h"
#include "../base/se23_math.h"
#include "../base/trig.h"

/* The cube of p along one axis: floor(p / step), within +-2^30 (|p| <=
 * SE23_INS_POS_MAX, step >= 1 m). */
static int32_t cube(se23_real_t p, se23_real_t step)
{
    const se23_real_t k = se23_floor(p / step);
    const se23_real_t lim = SE23_R(1073741824);
    if (k > lim) {
        return (int32_t)1073741824;
    }
    if (k < -lim) {
        return -(int32_t)1073741824;
    }
    return (int32_t)k;
}

void se23_ins_gravity_radii(se23_ins_t *ins)
{
    const se23_real_t a = SE23_R(SE23_WGS84_A), e2 = SE23_R(SE23_WGS84_E2);
    se23_real_t s, c;
    se23_sincos(ins->cfg.lat, &s, &c);
    (void)c;
    const se23_real_t w2 = SE23_R(1) - ((e2 * s) * s);
    const se23_real_t w = se23_sqrt(w2);
    ins->grav_rm = ((a * (SE23_R(1) - e2)) / (w2 * w)) + ins->cfg.height;
    ins->grav_rn = (a / w) + ins->cfg.height;
    ins->grav_set = 0;
}

void se23_ins_gravity_follow(se23_ins_t *ins)
{
    const se23_real_t step = ins->cfg.gravity_step;
    const se23_real_t *p = ins->g.T.p.v;
    int32_t k[3];
    se23_real_t c[3], u[3], g = SE23_R(0), un;
    se23_earth_model_t model;
    int i;
    if (step <= SE23_R(0)) {
        return;
    }
    for (i = 0; i < 3; ++i) {
        k[i] = cube(p[i], step);
    }
    if ((ins->grav_set != 0) && (k[0] == ins->grav_cube[0]) && (k[1] == ins->grav_cube[1]) &&
        (k[2] == ins->grav_cube[2])) {
        return;
    }
    for (i = 0; i < 3; ++i) {
        c[i] = ((se23_real_t)k[i] + SE23_R(0.5)) * step;
    }
    u[0] = -c[0] / ins->grav_rm;
    u[1] = -c[1] / ins->grav_rn;
    u[2] = SE23_R(1);
    un = se23_sqrt(((u[0] * u[0]) + (u[1] * u[1])) + SE23_R(1));
    /* outside the latitudes and heights earth.h takes (a position far
     * beyond the supported range): the gravity stays as it was */
    if (se23_earth_gravity(ins->cfg.lat - u[0], ins->cfg.height - c[2], &g) != SE23_OK) {
        return;
    }
    {
        const se23_vec3_t g_n = {{(g * u[0]) / un, (g * u[1]) / un, g / un}};
        if (se23_earth_model_init(&g_n, &ins->model.w_ie_n, ins->model.dt, ins->model.dt_max,
                                  &model) != SE23_OK) {
            return;
        }
    }
    ins->model = model;
    for (i = 0; i < 3; ++i) {
        ins->grav_cube[i] = k[i];
    }
    ins->grav_set = 1;
}
