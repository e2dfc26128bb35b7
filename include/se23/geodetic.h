/**
 * @file geodetic.h
 * @brief WGS-84 geodetic fixes (integer latitude, longitude, height as
 *        receivers send them) to and from the navigation filter's local
 *        Earth-fixed NED tangent frame, without cancellation, so that the
 *        float build keeps millimetres up to 100 km from the origin.
 *
 * Frames. The frame of se23_geo_origin is the tangent frame at the origin:
 * x north, y east, z down along the origin's ellipsoid normal, fixed to the
 * Earth. It is a Cartesian frame: a fix 100 km away is NOT re-levelled at
 * the fix (its "down" is tilted by about 0.16 mrad per km, see
 * se23_geo_down_at). p_n = R_ne (x_e(fix) - x_e(origin)), x_e the ECEF
 * position of WGS-84 (NIMA TR8350.2, 3rd ed.: a = 6378137 m,
 * f = 1/298.257223563, e^2 = f (2 - f)):
 *   x_e = ((N + h) cos lat cos lon, (N + h) cos lat sin lon,
 *          (N (1 - e^2) + h) sin lat),  N = a / sqrt(1 - e^2 sin^2 lat).
 *
 * Numerics. Latitude in radians as a float is good to ~0.5 m only, so the
 * fix's offset from the origin is taken as an integer difference (exact),
 * and only that difference becomes se23_real_t; the ECEF difference is
 * formed from sin/cos of the difference (no large number is subtracted
 * from another) and the leading terms are carried as unevaluated sums of
 * two reals (see src/imu/geodetic.c for the formulas and the error budget).
 *
 * Supported range (both builds; outside it: SE23_ERR_DOMAIN):
 *  - |lat| <= 90 deg, |lon| <= 180 deg, |h| <= SE23_GEO_H_MAX_MM;
 *  - fix minus origin: |dlat| <= SE23_GEO_DLAT_MAX_E9 (2 deg),
 *    |dlon| <= SE23_GEO_DLON_MAX_E9 (10 deg, taken across the antimeridian);
 *  - |north|, |east| <= SE23_GEO_RANGE_M (150 km), |down| <=
 *    SE23_GEO_DOWN_MAX_M. Near the poles (|lat| > ~82 deg) the 10 deg of
 *    longitude is the tighter east-west limit.
 * Accuracy of se23_geo_to_ned against the exact ECEF route (measured by
 * tests/unit/imu/test_geodetic.c and the Eigen cross-check): float build
 * within ~0.6 of the float spacing of the largest component: 0.5 mm within
 * 10 km, 4.8 mm within 100 km (spacing 7.8 mm; tested bounds 1 mm and
 * 6 mm), 7.8 mm within 150 km; double build ~1e-11 m (tested 1e-9 m).
 * These hold whether or not the compiler contracts a * b + c (e.g.
 * -ffp-contract=fast, as the Cortex-M library is built): the exact
 * products are formed with fma, never by splitting (measured on x86-64
 * with -O2 -ffp-contract=fast -mfma: 0.49 / 4.1 / 7.8 mm, double 1.6e-11 m
 * at 150 km; the M4F and M7 target vectors pass with the target's flags).
 * se23_geo_from_ned returns the integer fix within one unit (1e-9 deg,
 * 1 mm) of the exact inverse of p_n in the double build; in float p_n
 * itself carries up to half its spacing (3.9 mm at 100 km, ~70 units of
 * 1e-9 deg).
 *
 * Functions index:
 *   se23_geo_origin     precompute the frame at an origin
 *   se23_geo_to_ned     fix -> position in the frame [m]
 *   se23_geo_from_ned   position in the frame -> fix (integer units)
 *   se23_geo_down_at    the ellipsoid normal ("down") at a point, in the frame
 *
 * All functions return a status and write their outputs only on SE23_OK.
 */
#ifndef SE23_GEODETIC_H
#define SE23_GEODETIC_H

#include <stdint.h>

#include "se23/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Largest |latitude| [1e-9 deg]: 90 deg. */
#define SE23_GEO_LAT_MAX_E9 INT64_C(90000000000)
/** Largest |longitude| [1e-9 deg]: 180 deg. */
#define SE23_GEO_LON_MAX_E9 INT64_C(180000000000)
/** Largest |height| above the ellipsoid [mm]: 100 km. */
#define SE23_GEO_H_MAX_MM INT32_C(100000000)
/** Largest |lat - lat0| [1e-9 deg]: 2 deg. */
#define SE23_GEO_DLAT_MAX_E9 INT64_C(2000000000)
/** Largest |lon - lon0| [1e-9 deg], across the antimeridian: 10 deg. */
#define SE23_GEO_DLON_MAX_E9 INT64_C(10000000000)
/** Largest |north| and |east| of a point of the frame [m]. */
#define SE23_GEO_RANGE_M 150000.0
/** Largest |down| of a point of the frame [m] (two height limits and the curvature drop at the range). */
#define SE23_GEO_DOWN_MAX_M 210000.0

/** A geodetic position as receivers send it: integers, no rounding in float. */
typedef struct {
    int64_t lat_e9; /**< latitude [1e-9 deg] (u-blox lat 1e-7 deg + latHp 1e-9 deg; RTKLIB's 7 decimals are exact) */
    int64_t lon_e9; /**< longitude [1e-9 deg] */
    int32_t h_mm;   /**< height above the WGS-84 ellipsoid [mm] */
} se23_geo_t;

/**
 * A local NED tangent frame at an origin, precomputed by se23_geo_origin.
 * Treat it as read-only. sin and cos of the origin latitude are kept as
 * unevaluated sums hi + lo (about twice the working precision).
 */
typedef struct {
    se23_geo_t origin;      /**< the origin, as given */
    se23_real_t sin_hi;     /**< sin(lat0), leading part */
    se23_real_t sin_lo;     /**< sin(lat0) - sin_hi */
    se23_real_t cos_hi;     /**< cos(lat0), leading part (>= 0) */
    se23_real_t cos_lo;     /**< cos(lat0) - cos_hi */
    se23_real_t w0;         /**< sqrt(1 - e^2 sin^2 lat0) */
    se23_real_t dn0;        /**< N(lat0) - a [m] (prime-vertical radius minus the semi-major axis) */
    se23_real_t h0;         /**< origin height [m] */
    se23_real_t north_rad;  /**< M(lat0) + h0 [m/rad]: metres north per radian of latitude */
    se23_real_t east_rad;   /**< (N(lat0) + h0) cos lat0 [m/rad]: metres east per radian of longitude */
} se23_geo_frame_t;

/**
 * frame = the NED tangent frame at origin (sin/cos of its latitude to about
 * twice the working precision, its radii of curvature).
 * @param origin the frame's origin (WGS-84, integer units)
 * @param frame out: the frame (written only on SE23_OK)
 * @return SE23_ERR_NULL, or SE23_ERR_DOMAIN if |lat| > 90 deg,
 *         |lon| > 180 deg or |h| > SE23_GEO_H_MAX_MM.
 */
se23_status_t se23_geo_origin(const se23_geo_t *origin, se23_geo_frame_t *frame);

/**
 * p_n = the position of fix in the frame: R_ne (x_e(fix) - x_e(origin)),
 * north, east, down [m], Cartesian in the origin's tangent frame (not
 * re-levelled at the fix). Exact differences, see the file comment.
 * @param frame the frame (from se23_geo_origin)
 * @param fix the position to convert (WGS-84, integer units)
 * @param p_n out: its position in the frame [m] (written only on SE23_OK)
 * @return SE23_ERR_NULL, or SE23_ERR_DOMAIN if fix is outside the valid
 *         latitudes, longitudes or heights, or beyond the supported offsets
 *         from the origin (file comment).
 */
se23_status_t se23_geo_to_ned(const se23_geo_frame_t *frame, const se23_geo_t *fix,
                              se23_vec3_t *p_n);

/**
 * fix = the geodetic position of the point p_n of the frame, rounded to
 * the integer units; the inverse of se23_geo_to_ned to within one unit
 * (1e-9 deg, 1 mm). A fixed number of corrections, no recursion. The
 * longitude comes back in (-180, 180] deg.
 * @param frame the frame (from se23_geo_origin)
 * @param p_n the point, north, east, down [m]
 * @param fix out: its geodetic position (written only on SE23_OK)
 * @return SE23_ERR_NULL, SE23_ERR_NONFINITE if p_n holds NaN or Inf, or
 *         SE23_ERR_DOMAIN if p_n is beyond SE23_GEO_RANGE_M or
 *         SE23_GEO_DOWN_MAX_M or its fix is beyond the supported range
 *         (e.g. across a pole).
 */
se23_status_t se23_geo_from_ned(const se23_geo_frame_t *frame, const se23_vec3_t *p_n,
                                se23_geo_t *fix);

/**
 * down_n = the direction of "down" (minus the ellipsoid normal) at the
 * point p_n, as a unit vector in the frame's axes: (0, 0, 1) at the origin,
 * tilted by about offset / (R + h) elsewhere (0.16 mrad per km), the tilt
 * the filter's gravity must follow over a long drive. Exact: from the
 * geodetic latitude and longitude of the point (se23_geo_from_ned's),
 * down_n = -(cos lat cos dlon, cos lat sin dlon, sin lat) in the origin's
 * meridian axes, rotated into NED; the direction is good to ~1e-10 rad.
 * @param frame the frame (from se23_geo_origin)
 * @param p_n the point, north, east, down [m]
 * @param down_n out: the unit down vector in the frame (written only on SE23_OK)
 * @return as se23_geo_from_ned.
 */
se23_status_t se23_geo_down_at(const se23_geo_frame_t *frame, const se23_vec3_t *p_n,
                               se23_vec3_t *down_n);

#ifdef __cplusplus
}
#endif

#endif /* SE23_GEODETIC_H */
