// Shared pieces of the target vector generator (tools/target/gen_*.cpp):
// precision context and seeded inputs, row building and reading, the
// generator record. See gen_vectors.cpp.
#ifndef SE23_GEN_COMMON_HPP
#define SE23_GEN_COMMON_HPP

#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "reference.hpp"
#include "tv.h"

namespace gen {

using namespace se23ref;
using Row = std::vector<LD>;

constexpr int kRandom = 48; // random vectors per routine, after the edge cases
const LD kPi = 3.141592653589793238462643383279502884L;
const LD kNaN = std::numeric_limits<LD>::quiet_NaN();

// ---- inputs ---------------------------------------------------------------

struct Ctx {
    bool is_float = false;
    std::mt19937_64 rng{0x5E23u};
    // Data behind the last input row that the row itself does not hold
    // (the IMU samples (w, f, dt) a preintegrated factor was built from), for
    // the expected-value function of the same row.
    std::vector<std::array<LD, 7>> samples;
    // The value the target will hold for x.
    LD round(LD x) const
    {
        return is_float ? LD(float(x)) : LD(double(x));
    }
    LD uniform(LD lo, LD hi)
    {
        return lo + (hi - lo) * LD(std::uniform_real_distribution<double>(0.0, 1.0)(rng));
    }
    Vec3L axis()
    {
        std::normal_distribution<double> n;
        Vec3L a;
        do {
            a = Vec3L(LD(n(rng)), LD(n(rng)), LD(n(rng)));
        } while (a.norm() < 1e-3L);
        return a / a.norm();
    }
};

inline void put(Row &r, LD x) { r.push_back(x); }
template <class M> void put(Row &r, const M &m) // row-major
{
    for (int i = 0; i < m.rows(); ++i) {
        for (int j = 0; j < m.cols(); ++j) {
            r.push_back(m(i, j));
        }
    }
}
inline void put_pose(Row &r, const Mat5L &T)
{
    put(r, Mat3L(T.block<3, 3>(0, 0)));
    put(r, Vec3L(T.block<3, 1>(0, 3)));
    put(r, Vec3L(T.block<3, 1>(0, 4)));
}

inline Row rounded(const Ctx &c, Row r)
{
    for (LD &x : r) {
        x = c.round(x);
    }
    return r;
}

// Rotation angles every SO(3) routine is tested at (DESIGN.md section 3).
inline const std::vector<LD> &edge_angles()
{
    static const std::vector<LD> a = {0,    1.17549435e-38L, 1e-8L, 1e-5L, 1e-3L,
                                      1e-1L, 1,              2,     3,     kPi - 1e-6L};
    return a;
}

// k-th rotation vector: the edge angles first, then angles in [0, max_angle).
inline Vec3L phi_k(Ctx &c, int k, LD max_angle = kPi)
{
    const auto &e = edge_angles();
    const LD angle = k < int(e.size()) ? e[size_t(k)] : c.uniform(0, max_angle);
    return c.axis() * angle;
}
inline Vec3L vec3_any(Ctx &c, LD s) { return Vec3L(c.uniform(-s, s), c.uniform(-s, s), c.uniform(-s, s)); }
inline Mat3L rot_k(Ctx &c, int k) { return so3_exp(phi_k(c, k)); }
inline Mat5L pose_k(Ctx &c, int k) { return pose5(rot_k(c, k), vec3_any(c, 10), vec3_any(c, 10)); }

// ---- reading rows ---------------------------------------------------------

struct Rd {
    const Row &r;
    size_t i = 0;
    LD s() { return r.at(i++); }
    Vec3L v3()
    {
        Vec3L v;
        for (int j = 0; j < 3; ++j) v(j) = s();
        return v;
    }
    Vec9L v9()
    {
        Vec9L v;
        for (int j = 0; j < 9; ++j) v(j) = s();
        return v;
    }
    Mat3L m3()
    {
        Mat3L m;
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) m(a, b) = s();
        return m;
    }
    Mat5L m5()
    {
        Mat5L m;
        for (int a = 0; a < 5; ++a)
            for (int b = 0; b < 5; ++b) m(a, b) = s();
        return m;
    }
    Mat5L pose()
    {
        const Mat3L R = m3();
        const Vec3L v = v3();
        const Vec3L p = v3();
        return pose5(R, v, p);
    }
};

inline bool all_finite(const Row &r)
{
    for (LD x : r) {
        if (!std::isfinite(x)) return false;
    }
    return true;
}

// The library's rotation test (so3.h: se23_so3_check): |R^T R - I| entries
// within tol and det > 0. Vectors only use clear cases on either side.
inline bool is_rotation(const Mat3L &R, const Ctx &c)
{
    const LD tol = c.is_float ? 1e-5L : 1e-9L;
    return (R.transpose() * R - Mat3L::Identity()).cwiseAbs().maxCoeff() <= tol &&
           R.determinant() > 0;
}

// ---- generators -----------------------------------------------------------

struct Gen {
    int n_edge; // rows before the random ones (edge and error cases)
    // k-th input row (before rounding)
    std::function<Row(Ctx &, int k)> input;
    // status (se23_status_t) and outputs for an input row
    std::function<int(const Ctx &, const Row &in, Row &out)> expect;
};

inline int n_angles() { return int(edge_angles().size()); }

/** Registers the generators of one group of routines, keyed by function name. */
using Gens = std::map<std::string, Gen>;
void add_lie(Gens &g); // so3.h, se23.h (gen_lie.cpp)
void add_nav(Gens &g); // earth.h, imu.h, preint.h (gen_nav.cpp)

} // namespace gen

#endif // SE23_GEN_COMMON_HPP
