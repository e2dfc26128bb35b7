/**
 * @file earth.h
 * @brief The Earth as the navigation equations see it: WGS-84 normal gravity,
 *        the Earth rate in a local NED or ENU frame, and the navigation model
 *        (g, Omega, dt) with its state-independent factor Gamma'.
 *
 * Frames. The navigation frame n is a local Earth-fixed tangent frame at
 * geodetic latitude lat: NED (x north, y east, z down) or ENU (x east,
 * y north, z up). The model neglects the transport rate (the frame does not
 * move with the vehicle): Omega = w_ie_n is constant. Gravity g_n is the
 * normal gravity (gravitation plus the centrifugal term at the frame origin),
 * so that the rotating-Earth equations (paper eq. nav:eq_Coriolis) keep only
 * the residual centrifugal term -Omega^ Omega^ p (see the paper's footnote).
 *
 * The navigation model. Between two IMU samples the state-independent part
 * of the dynamics, d/dt Gamma = W' Gamma with W' = [[-Omega^, g, 0], ...],
 * integrates to (DESIGN.md section 3; paper eq. ODE21 with its typos fixed:
 * the rotation block of W' is -Omega^, and the second equation is
 * d/dt Gamma^v = g - Omega^ Gamma^v):
 *   Gamma^R = exp(-Omega^ t),  Gamma^v = t J(-Omega t) g,
 *   Gamma^x = t^2 K(-Omega t) g.
 * With Omega = 0 this is the flat-Earth Gamma = (I, g t, g t^2 / 2) of paper
 * eq. phi2:eq, exactly (the series coefficients at theta = 0 are exact), so
 * one model type serves flat and rotating Earth.
 *
 * Functions index:
 *   se23_earth_gravity          WGS-84 normal gravity magnitude at (lat, h)
 *   se23_earth_gravity_vec      the gravity vector in NED or ENU
 *   se23_earth_rate             the Earth-rate vector in NED or ENU
 *   se23_earth_gamma            Gamma'(t) for any g, Omega and t >= 0
 *   se23_earth_model_init       model (g, Omega, dt, dt_max) + Gamma'(dt)
 *   se23_earth_model_init_wgs84 the same with WGS-84 g and Omega at (lat, h)
 *
 * All functions return a status and write their outputs only on SE23_OK.
 */
#ifndef SE23_EARTH_H
#define SE23_EARTH_H

#include "se23/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/* WGS-84 defining and derived constants (NIMA TR8350.2, 3rd ed., tables
 * 3.1-3.3). Plain double literals: wrap in SE23_R() where used. */
#define SE23_WGS84_A 6378137.0                 /**< semi-major axis [m] */
#define SE23_WGS84_F (1.0 / 298.257223563)     /**< flattening */
#define SE23_WGS84_OMEGA_E 7.292115e-5         /**< Earth rotation rate [rad/s] */
#define SE23_WGS84_GAMMA_E 9.7803253359        /**< normal gravity at the equator [m/s^2] */
#define SE23_WGS84_GAMMA_P 9.8321849378        /**< normal gravity at the poles [m/s^2] */
#define SE23_WGS84_K 0.00193185265241          /**< Somigliana constant b gp/(a ge) - 1 */
#define SE23_WGS84_E2 0.00669437999013         /**< first eccentricity squared */
#define SE23_WGS84_M 0.00344978650684          /**< w^2 a^2 b / GM */

/** Lowest height [m] se23_earth_gravity accepts (its series in h is second order). */
#define SE23_EARTH_H_MIN (-1.0e4)
/** Highest height [m] se23_earth_gravity accepts. */
#define SE23_EARTH_H_MAX 1.0e5
/** Slack [rad] on |lat| <= pi/2, for latitudes converted from degrees. */
#define SE23_EARTH_LAT_SLACK 1e-6

/** Axes of the local navigation frame. */
typedef enum {
    SE23_FRAME_NED = 0, /**< x north, y east, z down */
    SE23_FRAME_ENU = 1  /**< x east, y north, z up */
} se23_frame_t;

/**
 * The navigation model of one IMU stream: constants of the dynamics and the
 * factor Gamma' precomputed for the nominal sample interval. Fill it with
 * se23_earth_model_init*; treat it as read-only afterwards.
 */
typedef struct {
    se23_vec3_t g_n;    /**< gravity in the nav frame [m/s^2] */
    se23_vec3_t w_ie_n; /**< Earth rate Omega in the nav frame [rad/s]; zero = flat Earth */
    se23_real_t dt;     /**< nominal sample interval [s] */
    se23_real_t dt_max; /**< largest sample interval a step accepts [s] */
    se23_pose_t gamma;  /**< Gamma'(dt) = (Gamma^R, Gamma^v, Gamma^x), see file comment */
} se23_earth_model_t;

/**
 * g = WGS-84 normal gravity [m/s^2] at geodetic latitude lat [rad] and
 * ellipsoidal height h [m]: Somigliana's closed form on the ellipsoid,
 *   g0 = gamma_e (1 + k sin^2 lat) / sqrt(1 - e^2 sin^2 lat),
 * and the second-order height correction (TR8350.2 eq. 4-3)
 *   g = g0 (1 - 2/a (1 + f + m - 2 f sin^2 lat) h + 3 h^2 / a^2).
 * @param lat geodetic latitude [rad]
 * @param h ellipsoidal height [m]
 * @param g out: normal gravity [m/s^2] (written only on SE23_OK)
 * @return SE23_ERR_NONFINITE, or SE23_ERR_DOMAIN if |lat| > pi/2 (plus
 *         SE23_EARTH_LAT_SLACK) or h is outside [SE23_EARTH_H_MIN, SE23_EARTH_H_MAX].
 */
se23_status_t se23_earth_gravity(se23_real_t lat, se23_real_t h, se23_real_t *g);

/**
 * g_n = the normal gravity vector in the nav frame: (0, 0, g) in NED,
 * (0, 0, -g) in ENU, g from se23_earth_gravity.
 * @param frame the nav frame's axes
 * @param lat geodetic latitude [rad]
 * @param h ellipsoidal height [m]
 * @param g_n out: the gravity vector (written only on SE23_OK)
 * @return as se23_earth_gravity, or SE23_ERR_DOMAIN for an unknown frame.
 */
se23_status_t se23_earth_gravity_vec(se23_frame_t frame, se23_real_t lat,
                                     se23_real_t h, se23_vec3_t *g_n);

/**
 * w_ie_n = the Earth rate [rad/s] in the nav frame at latitude lat [rad]:
 * w_e (cos lat, 0, -sin lat) in NED, w_e (0, cos lat, sin lat) in ENU,
 * w_e = SE23_WGS84_OMEGA_E.
 * @param frame the nav frame's axes
 * @param lat geodetic latitude [rad]
 * @param w_ie_n out: the Earth rate (written only on SE23_OK)
 * @return SE23_ERR_NONFINITE, or SE23_ERR_DOMAIN for |lat| > pi/2 (plus
 *         slack) or an unknown frame.
 */
se23_status_t se23_earth_rate(se23_frame_t frame, se23_real_t lat,
                              se23_vec3_t *w_ie_n);

/**
 * gamma = Gamma'(t) = (exp(-Omega^ t), t J(-Omega t) g, t^2 K(-Omega t) g),
 * the solution at time t of paper eq. ODE21 (typos fixed, see file comment);
 * Gamma'(0) is the identity. With Omega = 0 it is the flat-Earth
 * Gamma_t = (I, g t, g t^2/2) of eq. phi2:eq. Used for one sample interval
 * (se23_earth_model_init) and for a whole preintegration interval
 * (se23_preint_predict).
 * @param g_n    gravity in the nav frame [m/s^2]
 * @param w_ie_n Earth rate in the nav frame [rad/s]
 * @param t      time [s], t >= 0
 * @param gamma out: Gamma'(t) (written only on SE23_OK)
 * @return SE23_ERR_NONFINITE if an input holds NaN/Inf or Gamma overflows,
 *         SE23_ERR_DT if t < 0.
 */
se23_status_t se23_earth_gamma(const se23_vec3_t *g_n, const se23_vec3_t *w_ie_n,
                               se23_real_t t, se23_pose_t *gamma);

/**
 * model = (g_n, w_ie_n, dt, dt_max, Gamma'(dt)).
 * @param g_n    gravity in the nav frame [m/s^2]
 * @param w_ie_n Earth rate in the nav frame [rad/s]; the zero vector for flat Earth
 * @param dt     nominal sample interval [s], 0 < dt <= dt_max
 * @param dt_max largest interval a step will accept [s] (a longer gap between
 *               samples is refused with SE23_ERR_DT), dt_max <= SE23_CFG_DT_MAX
 * @param model out: the model (written only on SE23_OK)
 * @return SE23_ERR_NONFINITE, or SE23_ERR_DT if the intervals break
 *         0 < dt <= dt_max <= SE23_CFG_DT_MAX.
 */
se23_status_t se23_earth_model_init(const se23_vec3_t *g_n,
                                    const se23_vec3_t *w_ie_n, se23_real_t dt,
                                    se23_real_t dt_max,
                                    se23_earth_model_t *model);

/**
 * model = se23_earth_model_init with WGS-84 normal gravity at (lat [rad], h [m])
 * and the Earth rate at lat, in the given frame.
 * @param frame the nav frame's axes
 * @param lat geodetic latitude of the frame's origin [rad]
 * @param h its ellipsoidal height [m]
 * @param dt nominal sample interval [s]
 * @param dt_max largest interval a step will accept [s]
 * @param model out: the model (written only on SE23_OK)
 * @return the statuses of se23_earth_gravity_vec and se23_earth_model_init.
 */
se23_status_t se23_earth_model_init_wgs84(se23_frame_t frame, se23_real_t lat,
                                          se23_real_t h, se23_real_t dt,
                                          se23_real_t dt_max,
                                          se23_earth_model_t *model);

#ifdef __cplusplus
}
#endif

#endif /* SE23_EARTH_H */
