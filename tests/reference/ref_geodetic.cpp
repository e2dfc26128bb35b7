// Independent WGS-84 geodetic routes in long double; see ref_geodetic.hpp.
#include "ref_geodetic.hpp"

#include <cmath>

namespace se23ref {

namespace {
const LD kA = 6378137.0L;
const LD kF = 1.0L / 298.257223563L;
const LD kE2 = kF * (2.0L - kF);
} // namespace

Vec3L geo_ecef(LD lat, LD lon, LD h)
{
    const LD s = std::sin(lat);
    const LD n = kA / std::sqrt(1.0L - kE2 * s * s);
    return Vec3L((n + h) * std::cos(lat) * std::cos(lon), (n + h) * std::cos(lat) * std::sin(lon),
                 (n * (1.0L - kE2) + h) * s);
}

Mat3L geo_r_ne(LD lat, LD lon)
{
    const LD sp = std::sin(lat), cp = std::cos(lat), sl = std::sin(lon), cl = std::cos(lon);
    Mat3L r;
    r << -sp * cl, -sp * sl, cp,
         -sl, cl, 0,
         -cp * cl, -cp * sl, -sp;
    return r;
}

Vec3L geo_ned(LD lat0, LD lon0, LD h0, LD lat, LD lon, LD h)
{
    return geo_r_ne(lat0, lon0) * (geo_ecef(lat, lon, h) - geo_ecef(lat0, lon0, h0));
}

Vec3L geo_from_ecef(const Vec3L &x)
{
    const LD p = std::hypot(x(0), x(1));
    const LD lon = std::atan2(x(1), x(0));
    LD lat = std::atan2(x(2), p * (1.0L - kE2));
    LD h = 0;
    for (int k = 0; k < 30; ++k) {
        const LD s = std::sin(lat);
        const LD w = std::sqrt(1.0L - kE2 * s * s);
        const LD n = kA / w;
        h = p * std::cos(lat) + x(2) * s - kA * w;
        lat = std::atan2(x(2), p * (1.0L - kE2 * n / (n + h)));
    }
    return Vec3L(lat, lon, h);
}

} // namespace se23ref
