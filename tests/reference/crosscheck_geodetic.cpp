// Cross-check of include/se23/geodetic.h against the independent long-double
// routes of ref_geodetic.hpp (plain ECEF difference, fixed-point inverse):
//  - se23_geo_to_ned over random origins (|lat| <= 85 deg, plus 85-89.9 deg
//    with the offsets that 10 deg of longitude allow), fixes at distances
//    log-uniform in [1 m, 150 km] at any azimuth, heights -500 m to 9 km;
//  - se23_geo_from_ned: the fix of the C result's point by the reference's
//    inverse, in integer units (1e-9 deg of latitude, 1e-9 deg of longitude
//    times cos lat, 1 mm);
//  - se23_geo_down_at: the ellipsoid normal at that fix, in the frame's axes.
// See crosscheck.hpp. Usage: crosscheck_geodetic [markdown-output-file]
#include "crosscheck.hpp"
#include "ref_geodetic.hpp"

extern "C" {
#include "se23/geodetic.h"
}

namespace {

using namespace xc;

constexpr long kN = 20000;
constexpr LD kE9 = 1e9L;
const LD kRadPerE9 = kPi / 180e9L;

LD rad(int64_t e9) { return LD(e9) * kRadPerE9; }

// An integer C result in long double, through the same perturbation as out().
LD out_int(int64_t c)
{
    const LD e = perturbation();
    return LD(c) * (1 + e) + e;
}

struct Case {
    se23_geo_t o;
    se23_geo_t fix;
    LD dist;
};

// A random origin and a fix at distance d, azimuth az (integers).
Case draw(Rng &rng, LD lat_max, LD d_max)
{
    Case c;
    const LD lat0 = rng.uniform(-lat_max, lat_max);
    c.o.lat_e9 = std::llround(lat0 * kE9);
    c.o.lon_e9 = std::llround(rng.uniform(-180, 180) * kE9);
    c.o.h_mm = int32_t(std::llround(rng.uniform(-500, 9000) * 1000));
    c.dist = rng.log_uniform(1, d_max);
    const LD az = rng.uniform(0, 2 * kPi);
    const LD r = 6378137.0L;  // only to place the fix; the check uses the real ellipsoid
    const LD clat = std::cos(rad(c.o.lat_e9));
    c.fix = c.o;
    c.fix.lat_e9 += std::llround(c.dist * std::cos(az) / r / kRadPerE9);
    int64_t lon = c.o.lon_e9 + std::llround(c.dist * std::sin(az) / (r * clat) / kRadPerE9);
    if (lon > 180 * int64_t(kE9)) {
        lon -= 360 * int64_t(kE9);
    } else if (lon < -180 * int64_t(kE9)) {
        lon += 360 * int64_t(kE9);
    }
    c.fix.lon_e9 = lon;
    c.fix.h_mm = int32_t(std::llround(rng.uniform(-500, 9000) * 1000));
    return c;
}

// Longitude difference in (-180, 180] deg [1e-9 deg].
LD lon_diff(LD a, LD b)
{
    LD d = a - b;
    while (d > 180e9L) d -= 360e9L;
    while (d <= -180e9L) d += 360e9L;
    return d;
}

bool supported(const Case &c)
{
    const int64_t lon_max = SE23_GEO_DLON_MAX_E9;
    return std::llabs(c.fix.lat_e9) <= SE23_GEO_LAT_MAX_E9 &&
           std::fabs(lon_diff(LD(c.fix.lon_e9), LD(c.o.lon_e9))) <= LD(lon_max) &&
           std::llabs(c.fix.lat_e9 - c.o.lat_e9) <= SE23_GEO_DLAT_MAX_E9;
}

void check(Report &rep, Rng &rng)
{
    // Bounds [m] (double, float): the float output's own spacing is 0.98 mm
    // at 8-16 km (down carries h - h0 up to 9.5 km) and 7.8 mm at 65-131 km.
    Row &near = rep.row("geo_to_ned d<=10km", "abs[m]", 1e-9, 1e-3);
    Row &mid = rep.row("geo_to_ned 10<d<=100km", "abs[m]", 1e-9, 6e-3);
    Row &far = rep.row("geo_to_ned 100<d<=150km", "abs[m]", 1e-9, 1.2e-2);
    Row &inv = rep.row("geo_from_ned", "units", 1.0, 150);
    Row &down = rep.row("geo_down_at", "abs", 1e-12, 4e-7);
    long skipped = 0;
    for (long k = 0; k < kN; ++k) {
        const bool polar = (k % 10) == 9;
        const Case c = polar ? draw(rng, 89.9L, 1.5e4L) : draw(rng, 85, 1.5e5L);
        if (!supported(c)) {
            ++skipped;
            continue;
        }
        se23_geo_frame_t fr;
        se23_vec3_t p;
        Row &row = (c.dist <= 1e4L) ? near : ((c.dist <= 1e5L) ? mid : far);
        se23_status_t st = se23_geo_origin(&c.o, &fr);
        if (st == SE23_OK) {
            st = se23_geo_to_ned(&fr, &c.fix, &p);
        }
        const Vec3L exp = geo_ned(rad(c.o.lat_e9), rad(c.o.lon_e9), c.o.h_mm / 1000.0L,
                                  rad(c.fix.lat_e9), rad(c.fix.lon_e9), c.fix.h_mm / 1000.0L);
        if (st != SE23_OK) {
            // Beyond the range (|north|, |east| <= 150 km) is a refusal, not a failure.
            if (exp.head<2>().cwiseAbs().maxCoeff() > SE23_GEO_RANGE_M) {
                ++skipped;
                continue;
            }
            rep.status(row, st, c.dist);
            continue;
        }
        rep.add(row, double((out(p) - exp).cwiseAbs().maxCoeff()), c.dist);

        // The inverse of the C point, by the reference.
        const Vec3L pc = ld(p);
        const Mat3L rne = geo_r_ne(rad(c.o.lat_e9), rad(c.o.lon_e9));
        const Vec3L x = geo_ecef(rad(c.o.lat_e9), rad(c.o.lon_e9), c.o.h_mm / 1000.0L) +
                        rne.transpose() * pc;
        const Vec3L g = geo_from_ecef(x);
        se23_geo_t back;
        st = se23_geo_from_ned(&fr, &p, &back);
        rep.status(inv, st, c.dist);
        if (st == SE23_OK) {
            const LD lat_e9 = g(0) / kRadPerE9, lon_e9 = g(1) / kRadPerE9, h_mm = g(2) * 1000;
            const LD e_lat = std::fabs(out_int(back.lat_e9) - lat_e9);
            const LD e_lon = std::fabs(lon_diff(out_int(back.lon_e9), lon_e9)) * std::cos(g(0));
            const LD e_h = std::fabs(out_int(back.h_mm) - h_mm);
            rep.add(inv, double(std::max({e_lat, e_lon, e_h})), c.dist);
        }
        se23_vec3_t dn;
        st = se23_geo_down_at(&fr, &p, &dn);
        rep.status(down, st, c.dist);
        if (st == SE23_OK) {
            const Vec3L u(-std::cos(g(0)) * std::cos(g(1)), -std::cos(g(0)) * std::sin(g(1)),
                          -std::sin(g(0)));
            rep.add(down, double((out(dn) - rne * u).cwiseAbs().maxCoeff()), c.dist);
        }
    }
    std::printf("  %ld of %ld draws outside the supported range (skipped)\n", skipped, kN);
}

} // namespace

int main(int argc, char **argv)
{
    Report rep("crosscheck_geodetic", argc, argv);
    Rng rng(0x5e23'0035);
    check(rep, rng);
    return rep.finish();
}
