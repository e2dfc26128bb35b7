// Target vectors of geodetic.h (se23_geo_origin, se23_geo_to_ned,
// se23_geo_from_ned, se23_geo_down_at) from a plain long-double route, not
// the library's formulas: WGS-84 ECEF of the fix and of the origin,
//   x_e = ((N + h) cos lat cos lon, (N + h) cos lat sin lon, (N (1 - e^2) + h) sin lat),
// their difference rotated into the origin's NED axes; the inverse by
// iterating lat = atan2(z, p (1 - e^2 N / (N + h))) to convergence. Long
// double (64-bit significand) keeps ECEF coordinates to ~4e-13 m.
//
// Rows (tests/target/tv_list.h, tests/target/tv_custom_geo.c): an integer
// travels as two reals hi = floor(x / 2^20), lo = x - 2^20 hi, both exact
// in float (|hi| < 2^18, 0 <= lo < 2^20); a se23_geo_t as lat, lon, h
// (6 reals). The routines of a frame take its origin and build the frame
// with se23_geo_origin on the target (checked by its own vectors).
#include <cstdint>
#include <stdexcept>

#include "gen_common.hpp"
#include "se23/geodetic.h"

namespace gen {
namespace {

const LD kA = 6378137.0L;
const LD kF = 1.0L / 298.257223563L;
const LD kE2 = kF * (2 - kF);
const LD kRadPerE9 = kPi / 180e9L;
const int64_t kSplit = int64_t(1) << 20;

// The precision of the run, for the scales (Gen::scale_io has no Ctx).
bool g_float = false;
LD eps() { return g_float ? LD(std::numeric_limits<float>::epsilon()) : LD(std::numeric_limits<double>::epsilon()); }

struct Geo {
    int64_t lat, lon, h; // 1e-9 deg, 1e-9 deg, mm
};

void put_int(Row &r, int64_t x)
{
    int64_t hi = x / kSplit;
    if (hi * kSplit > x) --hi; // floor
    put(r, LD(hi));
    put(r, LD(x - hi * kSplit));
}
int64_t read_int(Rd &rd)
{
    const LD hi = rd.s(), lo = rd.s();
    return int64_t(hi) * kSplit + int64_t(lo);
}
void put_geo(Row &r, const Geo &g)
{
    put_int(r, g.lat);
    put_int(r, g.lon);
    put_int(r, g.h);
}
Geo read_geo(Rd &rd)
{
    Geo g;
    g.lat = read_int(rd);
    g.lon = read_int(rd);
    g.h = read_int(rd);
    return g;
}

bool valid(const Geo &g)
{
    return std::llabs(g.lat) <= SE23_GEO_LAT_MAX_E9 && std::llabs(g.lon) <= SE23_GEO_LON_MAX_E9 &&
           std::llabs(g.h) <= SE23_GEO_H_MAX_MM;
}

Vec3L ecef(LD lat, LD lon, LD h)
{
    const LD s = std::sin(lat), c = std::cos(lat);
    const LD N = kA / std::sqrt(1 - kE2 * s * s);
    return Vec3L((N + h) * c * std::cos(lon), (N + h) * c * std::sin(lon), (N * (1 - kE2) + h) * s);
}
Vec3L ecef(const Geo &g) { return ecef(LD(g.lat) * kRadPerE9, LD(g.lon) * kRadPerE9, LD(g.h) * 1e-3L); }

// R_ne: rows the origin's north, east, down axes in ECEF.
Mat3L r_ne(const Geo &o)
{
    const LD la = LD(o.lat) * kRadPerE9, lo = LD(o.lon) * kRadPerE9;
    const LD sl = std::sin(la), cl = std::cos(la), so = std::sin(lo), co = std::cos(lo);
    Mat3L R;
    R << -sl * co, -sl * so, cl, //
        -so, co, 0,              //
        -cl * co, -cl * so, -sl;
    return R;
}

Vec3L to_ned(const Geo &o, const Geo &f) { return r_ne(o) * (ecef(f) - ecef(o)); }

// ECEF -> lat, lon [rad], h [m].
void geodetic(const Vec3L &x, LD &lat, LD &lon, LD &h)
{
    const LD p = std::hypot(x(0), x(1));
    lon = std::atan2(x(1), x(0));
    lat = std::atan2(x(2), p * (1 - kE2));
    for (int k = 0; k < 50; ++k) {
        const LD s = std::sin(lat);
        const LD N = kA / std::sqrt(1 - kE2 * s * s);
        h = p * std::cos(lat) + x(2) * s - kA * std::sqrt(1 - kE2 * s * s);
        lat = std::atan2(x(2), p * (1 - kE2 * N / (N + h)));
    }
    const LD s = std::sin(lat);
    h = p * std::cos(lat) + x(2) * s - kA * std::sqrt(1 - kE2 * s * s);
}

int64_t round_ll(LD x) { return int64_t(std::llround(x)); }

// lon - lon0 in (-180, 180] deg.
int64_t lon_diff(int64_t lon, int64_t lon0)
{
    int64_t d = lon - lon0;
    if (d > SE23_GEO_LON_MAX_E9) d -= 2 * SE23_GEO_LON_MAX_E9;
    if (d <= -SE23_GEO_LON_MAX_E9) d += 2 * SE23_GEO_LON_MAX_E9;
    return d;
}

bool in_range(const Vec3L &p)
{
    return std::fabs(p(0)) <= SE23_GEO_RANGE_M && std::fabs(p(1)) <= SE23_GEO_RANGE_M &&
           std::fabs(p(2)) <= SE23_GEO_DOWN_MAX_M;
}

// The exact inverse of p_n in the frame at o, rounded to integers, and its
// status (geodetic.h: the supported window).
int inverse(const Geo &o, const Vec3L &p, Geo &f, LD &lat, LD &lon)
{
    if (!p.allFinite()) return SE23_ERR_NONFINITE;
    if (!in_range(p)) return SE23_ERR_DOMAIN;
    const Vec3L x = ecef(o) + r_ne(o).transpose() * p;
    LD h;
    geodetic(x, lat, lon, h);
    f.lat = round_ll(lat / kRadPerE9);
    f.lon = round_ll(lon / kRadPerE9);
    if (f.lon <= -SE23_GEO_LON_MAX_E9) f.lon += 2 * SE23_GEO_LON_MAX_E9;
    f.h = round_ll(h * 1e3L);
    if (!valid(f)) return SE23_ERR_DOMAIN;
    if (std::llabs(f.lat - o.lat) > SE23_GEO_DLAT_MAX_E9 ||
        std::llabs(lon_diff(f.lon, o.lon)) > SE23_GEO_DLON_MAX_E9)
        return SE23_ERR_DOMAIN;
    return SE23_OK;
}

int64_t rnd_int(Ctx &c, LD lo, LD hi) { return round_ll(c.uniform(lo, hi)); }

// A random origin: |lat| <= max_lat deg, any longitude, -500 m to 5 km.
// The inverse routines' at most 80 deg, so that 100 km east stays well
// inside the 10 deg of longitude (no vector near a window's edge).
Geo origin_any(Ctx &c, LD max_lat = 89)
{
    return {rnd_int(c, -max_lat * 1e9L, max_lat * 1e9L), rnd_int(c, -180e9L, 180e9L),
            rnd_int(c, -5e5L, 5e6L)};
}
// An offset of up to `range` m north and east (k-th scale: 100 m, 1 km,
// 10 km, 100 km), heights within 2 km: the fix's integers.
Geo fix_near(Ctx &c, const Geo &o, int k)
{
    static const LD ranges[] = {100, 1e3L, 1e4L, 1e5L};
    const LD range = ranges[k % 4];
    const LD lat = LD(o.lat) * kRadPerE9;
    const LD dlat = c.uniform(-range, range) / 6.4e6L / kRadPerE9;
    LD dlon = c.uniform(-range, range) / (6.4e6L * std::cos(lat)) / kRadPerE9;
    dlon = std::max(LD(-9.9e9L), std::min(LD(9.9e9L), dlon));
    Geo f{o.lat + round_ll(dlat), 0, o.h + rnd_int(c, -2e6L, 2e6L)};
    f.lon = lon_diff(o.lon + round_ll(dlon), 0);
    if (std::llabs(f.lat) > SE23_GEO_LAT_MAX_E9) f.lat = o.lat - round_ll(dlat);
    return f;
}
// A point of the frame at up to `range` m (the k-th scale), near the
// ellipsoid surface (the curvature drop) within 2 km.
Vec3L point_near(Ctx &c, int k)
{
    static const LD ranges[] = {100, 1e3L, 1e4L, 1e5L};
    const LD range = ranges[k % 4];
    const LD n = c.uniform(-range, range), e = c.uniform(-range, range);
    return Vec3L(n, e, (n * n + e * e) / (2 * 6.4e6L) + c.uniform(-2e3L, 2e3L));
}

// Origin edges: valid extremes, then the three refusals.
Geo origin_edge(int k)
{
    const int64_t L = SE23_GEO_LAT_MAX_E9, O = SE23_GEO_LON_MAX_E9;
    const int64_t H = SE23_GEO_H_MAX_MM;
    switch (k) {
    case 0: return {0, 0, 0};
    case 1: return {L, O, H};
    case 2: return {-L, -O, -H};
    case 3: return {45500000000, 7123456789, 1};            // r = +0.5 deg exactly
    case 4: return {-45500000001, -7123456789, -1};         // r just past -0.5 deg
    case 5: return {89999999999, 179999999999, 123456789 / 10}; // 1e-9 deg from the pole
    case 6: return {1, -1, 99999999};
    case 7: return {L + 1, 0, 0};
    case 8: return {0, -O - 1, 0};
    case 9: return {0, 0, H + 1};
    default: return {0, 0, 0};
    }
}
const int kOriginEdges = 10;

Row frame_scale(const Row &out)
{
    // origin (exact), sin_hi, sin_lo, cos_hi, cos_lo, w0, dn0, h0, north_rad,
    // east_rad. tol 1 (tv_list.h): the bound is eps * scale.
    Row s(out.size(), 0);
    const LD e = eps();
    // hi: within an ulp of the correctly rounded sin and cos
    s[6] = s[8] = 1;
    // lo: the double-real to ~1e-12 relative in float (geodetic.c; 4.6e-12
    // measured on the M4F without contraction), the
    // reference's long double to ~1e-19 in double
    s[7] = s[9] = (g_float ? 1e-11L : 5e-19L) / e; // measured 4.6e-12, 1.6e-19
    for (size_t i = 10; i < 15; ++i) s[i] = 8 * std::fabs(out[i]);
    // east_rad = (N + h) cos lat: near the pole the absolute error of cos
    s[14] = 8 * std::fabs(out[14]) + (g_float ? 1e-5L : 1e-12L) / e;
    return s;
}

// to_ned: |error| <= 1 mm + 4e-8 |p| (float: the output's half spacing at
// 100 km is 3.9 mm, geodetic.h <= 5 mm), 1e-8 m + 4 eps |p| (double).
Row ned_scale(const Row &out)
{
    const LD m = max_abs(out, 0, 3);
    const LD bound = g_float ? 1e-3L + 4e-8L * m : 1e-8L + 4 * eps() * m;
    return Row(out.size(), bound / eps());
}

// Units [1e-9 deg, 1e-9 deg, mm] se23_geo_from_ned's fix may differ by,
// on the lo reals of its row (0 on the hi reals: exact): one, plus the
// forward route's bound (ned_scale) at the point.
Row fix_units(const Row &in, const Row &out)
{
    const LD pmax = std::max(std::fabs(in[6]), std::max(std::fabs(in[7]), std::fabs(in[8])));
    const LD bound = g_float ? 1e-3L + 4e-8L * pmax : 1e-8L + 4 * eps() * pmax;
    const LD lat = (out[0] * LD(kSplit) + out[1]) * kRadPerE9;
    const LD unit_m = 6.33e6L * kRadPerE9; // 1e-9 deg of the smallest radius of curvature
    Row s(6, 0);
    s[1] = 1.5L + bound / unit_m;
    s[3] = 1.5L + bound / (unit_m * std::max(std::cos(lat), LD(0.05)));
    s[5] = 1.5L + bound / 1e-3L;
    return s;
}

} // namespace

void add_geo(Gens &g)
{
    g["se23_geo_origin"] = {
        kOriginEdges,
        [](Ctx &c, int k) {
            g_float = c.is_float;
            Row r;
            put_geo(r, k < kOriginEdges ? origin_edge(k) : origin_any(c));
            return r;
        },
        [](const Ctx &, const Row &in, Row &out) {
            Rd rd{in};
            const Geo o = read_geo(rd);
            if (!valid(o)) return int(SE23_ERR_DOMAIN);
            const LD lat = LD(o.lat) * kRadPerE9, h = LD(o.h) * 1e-3L;
            const LD s = std::sin(lat), co = std::cos(lat);
            const LD w = std::sqrt(1 - kE2 * s * s), N = kA / w; // N only for east_rad
            put_geo(out, o);
            const LD sh = g_float ? LD(float(s)) : LD(double(s));
            const LD ch = g_float ? LD(float(co)) : LD(double(co));
            put(out, sh);
            put(out, s - sh);
            put(out, ch);
            put(out, co - ch);
            put(out, w);
            put(out, kA * kE2 * s * s / (w * (1 + w))); // N - a, without N's rounding
            put(out, h);
            put(out, kA * (1 - kE2) / (w * w * w) + h);
            put(out, (N + h) * co);
            return int(SE23_OK);
        }};
    g["se23_geo_origin"].scale = frame_scale;
    g["se23_geo_origin"].n_random = 8;

    // Edges: the fix at the origin, across the antimeridian, at 1e-9 deg
    // from the pole, 140 km north (in range), then the refusals: an invalid
    // fix, dlat above 2 deg, dlon above 10 deg, 1.5 deg north (166 km: beyond
    // the range), a height beyond the limit.
    g["se23_geo_to_ned"] = {
        9,
        [](Ctx &c, int k) {
            g_float = c.is_float;
            Geo o = origin_any(c), f = fix_near(c, o, k);
            switch (k) {
            case 0: f = o; break;
            case 1: o = {-33123456789, 179950000000, 12345}; f = {-33100000000, -179980000000, 20000}; break;
            case 2: o = {89999999999, 10000000000, 0}; f = {89990000000, 15000000000, 100}; break;
            case 3: o = {47000000000, 8000000000, 400000}; f = {48260000000, 8000000000, 400000}; break;
            case 4: f.lat = SE23_GEO_LAT_MAX_E9 + 1; break;
            case 5: f.lat = o.lat + (o.lat > 0 ? -1 : 1) * (SE23_GEO_DLAT_MAX_E9 + 1); break;
            case 6: o.lat = 60000000000; f = o; f.lon = lon_diff(o.lon + SE23_GEO_DLON_MAX_E9 + 1, 0); break;
            case 7: o = {10000000000, 20000000000, 0}; f = {11500000000, 20000000000, 0}; break;
            case 8: o.h = SE23_GEO_H_MAX_MM - 1000; f = o; f.h = SE23_GEO_H_MAX_MM + 1; break;
            default: break;
            }
            Row r;
            put_geo(r, o);
            put_geo(r, f);
            return r;
        },
        [](const Ctx &, const Row &in, Row &out) {
            Rd rd{in};
            const Geo o = read_geo(rd), f = read_geo(rd);
            if (!valid(f)) return int(SE23_ERR_DOMAIN);
            if (std::llabs(f.lat - o.lat) > SE23_GEO_DLAT_MAX_E9 ||
                std::llabs(lon_diff(f.lon, o.lon)) > SE23_GEO_DLON_MAX_E9)
                return int(SE23_ERR_DOMAIN);
            const Vec3L p = to_ned(o, f);
            if (!in_range(p)) return int(SE23_ERR_DOMAIN);
            put(out, p);
            return int(SE23_OK);
        }};
    g["se23_geo_to_ned"].scale = ned_scale;

    // Inputs of the inverse routines: origin, p_n. Edges: the origin
    // itself, across the antimeridian, NaN, beyond the range north, below
    // the down range, above the height limit (120 km up), across the pole.
    const auto inv_input = [](Ctx &c, int k) {
        g_float = c.is_float;
        Geo o = origin_any(c, 80);
        Vec3L p = point_near(c, k);
        switch (k) {
        case 0: p = Vec3L::Zero(); break;
        case 1: o = {-33123456789, 179950000000, 12345}; p = Vec3L(-3000, 7000, 5); break;
        case 2: p(1) = kNaN; break;
        case 3: p(0) = 150100; break;
        case 4: p(2) = 210100; break;
        case 5: o.h = 0; p(2) = -120000; break;
        case 6: o = {89500000000, 0, 0}; p = Vec3L(100000, 0, 800); break;
        default: break;
        }
        Row r;
        put_geo(r, o);
        put(r, p);
        return r;
    };
    // The fix within one unit of the exact inverse (geodetic.h) plus what
    // the forward route's error (to_ned's bound above) moves it: in double
    // nothing, in float up to 45 units (5 mm at 100 km; 1e-9 deg of latitude
    // is 0.11 mm). The lo parts within that, the hi parts exact (the
    // generator refuses a vector whose fix lies that close to a hi/lo
    // boundary).
    g["se23_geo_from_ned"] = {7, inv_input, [](const Ctx &, const Row &in, Row &out) {
                                  Rd rd{in};
                                  const Geo o = read_geo(rd);
                                  const Vec3L p = rd.v3();
                                  Geo f;
                                  LD lat, lon;
                                  const int st = inverse(o, p, f, lat, lon);
                                  if (st != SE23_OK) return st;
                                  put_geo(out, f);
                                  const Row tol = fix_units(in, out);
                                  for (size_t i = 1; i < 6; i += 2) {
                                      if (out[i] < tol[i] + 1 || out[i] > LD(kSplit) - tol[i] - 2)
                                          throw std::runtime_error("se23_geo_from_ned: a fix at a hi/lo boundary");
                                  }
                                  return int(SE23_OK);
                              }};
    g["se23_geo_from_ned"].scale_io = [](const Row &in, const Row &out) {
        Row s = fix_units(in, out);
        for (LD &x : s) x /= eps();
        return s;
    };
    // down_n = -(cos lat cos dlon, cos lat sin dlon, sin lat) of the point's
    // fix, in the origin's NED axes: from the exact inverse here.
    g["se23_geo_down_at"] = {7, inv_input, [](const Ctx &, const Row &in, Row &out) {
                                 Rd rd{in};
                                 const Geo o = read_geo(rd);
                                 const Vec3L p = rd.v3();
                                 Geo f;
                                 LD lat, lon;
                                 const int st = inverse(o, p, f, lat, lon);
                                 if (st != SE23_OK) return st;
                                 const Vec3L up(std::cos(lat) * std::cos(lon), std::cos(lat) * std::sin(lon),
                                                std::sin(lat));
                                 put(out, Vec3L(-(r_ne(o) * up)));
                                 return int(SE23_OK);
                             }};
    // A unit vector: float to a few eps, double to 2e-11 (the fix's
    // rounding to 1e-9 deg moves the normal by up to 1.2e-11 rad).
    g["se23_geo_down_at"].scale = [](const Row &out) {
        return Row(out.size(), (g_float ? 4 * eps() : 2e-11L) / eps());
    };
    // Few random rows: the M7 image's flash is nearly full (QEMU's an500
    // runs it no further than ~4,158,000 bytes of text).
    for (const char *n : {"se23_geo_to_ned", "se23_geo_from_ned", "se23_geo_down_at"}) {
        g[n].n_random = 16;
    }
}

} // namespace gen
