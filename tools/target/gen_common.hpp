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

// Error scale of every output real: the target accepts |got - expected| <=
// tol * eps * scale. Expected values are compared with the magnitude of the
// block they belong to (a rotation with its rotation, a position with its
// position, a covariance entry with sqrt(P_ii P_jj)), so that a small block
// next to a large one is still checked to its own precision.
using Scale = std::function<Row(const Row &out)>;

struct Gen {
    int n_edge; // rows before the random ones (edge and error cases)
    // k-th input row (before rounding)
    std::function<Row(Ctx &, int k)> input;
    // status (se23_status_t) and outputs for an input row
    std::function<int(const Ctx &, const Row &in, Row &out)> expect;
    // error scales of an output row; empty: the largest |expected| of the row
    Scale scale = nullptr;
    // instead of scale, when the error of an output is relative to an input
    // too (an update out = in + d that cancels): scales from (in, out)
    std::function<Row(const Row &in, const Row &out)> scale_io = nullptr;
    // random rows after the edge rows. Fewer than kRandom where more would
    // only spend the M7 image's flash (4 MiB, double tables): outputs that
    // are a fixed function of a few inputs, or long input rows.
    int n_random = kRandom;
};

inline LD max_abs(const Row &r, size_t from, size_t n)
{
    LD m = 0;
    for (size_t i = from; i < from + n; ++i) m = std::max(m, std::fabs(r[i]));
    return m;
}
// Contiguous blocks of the given lengths, each scaled by its largest entry.
inline Scale scale_blocks(std::vector<int> lens)
{
    return [lens](const Row &out) {
        Row s;
        size_t at = 0;
        for (int n : lens) {
            const LD m = max_abs(out, at, size_t(n));
            s.insert(s.end(), size_t(n), m);
            at += size_t(n);
        }
        return s;
    };
}
// A rows x cols row-major matrix in b x b blocks, each scaled by its largest entry.
inline Scale scale_mat_blocks(int rows, int cols, int b)
{
    return [rows, cols, b](const Row &out) {
        Row s(out.size(), 0);
        for (int bi = 0; bi < rows; bi += b) {
            for (int bj = 0; bj < cols; bj += b) {
                LD m = 0;
                for (int i = bi; i < bi + b; ++i)
                    for (int j = bj; j < bj + b; ++j) m = std::max(m, std::fabs(out[size_t(i * cols + j)]));
                for (int i = bi; i < bi + b; ++i)
                    for (int j = bj; j < bj + b; ++j) s[size_t(i * cols + j)] = m;
            }
        }
        return s;
    };
}
// An n x n covariance, row-major: entry (i, j) scaled by sqrt(P_ii P_jj).
inline Scale scale_cov(int n)
{
    return [n](const Row &out) {
        Row s(out.size(), 0);
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j)
                s[size_t(i * n + j)] = std::sqrt(std::fabs(out[size_t(i * n + i)] * out[size_t(j * n + j)]));
        return s;
    };
}
// Consecutive segments (length, scale of the segment).
inline Scale scale_concat(std::vector<std::pair<int, Scale>> parts)
{
    return [parts](const Row &out) {
        Row s;
        size_t at = 0;
        for (const auto &p : parts) {
            const Row seg(out.begin() + long(at), out.begin() + long(at) + p.first);
            const Row ss = p.second(seg);
            s.insert(s.end(), ss.begin(), ss.end());
            at += size_t(p.first);
        }
        return s;
    };
}
// A block whose error is absolute (of the order of its inputs, about 1): the
// rotation vector of a logarithm, whatever its size.
inline Scale scale_at_least_1()
{
    return [](const Row &out) {
        return Row(out.size(), std::max(LD(1), max_abs(out, 0, out.size())));
    };
}
inline Scale scale_pose() { return scale_blocks({9, 3, 3}); }
inline Scale scale_tangent() { return scale_blocks({3, 3, 3}); }
// se23_earth_model_t: g_n, w_ie_n, dt, dt_max, gamma (R, v, p)
inline Scale scale_model() { return scale_blocks({3, 3, 1, 1, 9, 3, 3}); }

inline int n_angles() { return int(edge_angles().size()); }

// Phi_t(R, v, p) = (R, v, p + t v).
inline Mat5L phi_t(const Mat5L &T, LD t)
{
    Mat5L out = T;
    out.block<3, 1>(0, 4) += t * T.block<3, 1>(0, 3);
    return out;
}
// The carried state (R, v + Om x p, p) of a user state (sign 1), and back (-1).
inline Mat5L carried_pose(const Mat5L &T, const Vec3L &Om, LD sign)
{
    Mat5L out = T;
    out.block<3, 1>(0, 3) += sign * Om.cross(Vec3L(T.block<3, 1>(0, 4)));
    return out;
}
// A se23_preint_t as a row: delta, dt, n.
inline void put_preint(Row &r, const Mat5L &delta, LD dt, LD n)
{
    put_pose(r, delta);
    put(r, dt);
    put(r, n);
}

/** Registers the generators of one group of routines, keyed by function name. */
using Gens = std::map<std::string, Gen>;
void add_lie(Gens &g); // so3.h, se23.h (gen_lie.cpp)
void add_nav(Gens &g); // earth.h, imu.h, preint.h (gen_nav.cpp)
void add_gauss(Gens &g);  // gauss.h (gen_gauss.cpp)
void add_kalman(Gens &g); // kalman.h (gen_gauss.cpp)
void add_preint_unc(Gens &g); // preint_unc.h (gen_preint_unc.cpp)
void add_align(Gens &g); // stationary.h, align.h (gen_align.cpp)
void add_geo(Gens &g); // geodetic.h (gen_geo.cpp)

} // namespace gen

#endif // SE23_GEN_COMMON_HPP
