/**
 * @file ref_geodetic.hpp
 * @brief Independent ground truth for include/se23/geodetic.h, written from
 *        the textbook formulas, not from the C code (nor its
 *        cancellation-free forms), in long double:
 *
 *  - geo_ecef: WGS-84 geodetic -> ECEF (NIMA TR8350.2 eq. 4-14),
 *        x = ((N + h) cos lat cos lon, (N + h) cos lat sin lon, (N (1 - e^2) + h) sin lat),
 *        N = a / sqrt(1 - e^2 sin^2 lat), a = 6378137 m, f = 1/298.257223563;
 *  - geo_r_ne: the rotation ECEF -> local NED at (lat, lon);
 *  - geo_ned: R_ne(origin) (x(fix) - x(origin)), the plain difference, whose
 *    cancellation (7e-13 m at 6.4e6 m in 64 bits) long double absorbs;
 *  - geo_from_ecef: ECEF -> geodetic by the classical fixed-point iteration
 *        lat = atan2(z, p (1 - e^2 N / (N + h))),
 *        h = p cos lat + z sin lat - a sqrt(1 - e^2 sin^2 lat),
 *    (p = hypot(x, y); contraction factor ~e^2 near the surface; 30 rounds).
 */
#ifndef SE23_REF_GEODETIC_HPP
#define SE23_REF_GEODETIC_HPP

#include "reference.hpp"

namespace se23ref {

/** ECEF [m] of geodetic latitude, longitude [rad] and height [m]. */
Vec3L geo_ecef(LD lat, LD lon, LD h);

/** Rows: the local north, east and down axes at (lat, lon) in ECEF. */
Mat3L geo_r_ne(LD lat, LD lon);

/** NED [m] of (lat, lon, h) in the tangent frame at (lat0, lon0, h0). */
Vec3L geo_ned(LD lat0, LD lon0, LD h0, LD lat, LD lon, LD h);

/** Geodetic (lat, lon [rad], h [m]) of an ECEF point off the axis. */
Vec3L geo_from_ecef(const Vec3L &x);

} // namespace se23ref

#endif // SE23_REF_GEODETIC_HPP
