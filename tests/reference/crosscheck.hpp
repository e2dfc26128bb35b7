/**
 * @file crosscheck.hpp
 * @brief Shared harness of the crosscheck_*.cpp programs: seeded RNG, C <->
 *        Eigen conversions, error measures, and a report that keeps the worst
 *        error per routine, prints a table, writes it as markdown rows and
 *        turns any bound violation into a non-zero exit status.
 *
 * Usage in a program:
 *     xc::Report rep("crosscheck_foo", argc, argv);
 *     xc::Row &r = rep.row("se23_foo", "block", 1e-12, 40 * FLT_EPSILON);
 *     ... rep.add(r, xc::err_block(xc::out(c_result), expected), theta);
 *     return rep.finish();
 *
 * Inputs are drawn in long double, rounded to se23_real_t for the C call, and
 * the reference is evaluated (in long double) at the rounded input, so the
 * measured error is the C routine's own error, not the rounding of its input.
 *
 * Every C result must pass through xc::out(): with SE23_XC_PERTURB=<x> in the
 * environment it returns y (1 + x) + x instead of y, and finish() then
 * succeeds only if EVERY row failed -- the proof that each comparison can
 * fail (tests/check.d/30-reference.sh runs that mode too).
 *
 * argv[1] (or $SE23_XC_OUT): file to which the markdown rows are written.
 */
#ifndef SE23_CROSSCHECK_HPP
#define SE23_CROSSCHECK_HPP

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <string>

#include "reference.hpp"
#include "se23/types.h"

namespace xc {

using namespace se23ref;
using real = se23_real_t;

constexpr bool kDouble = SE23_CFG_DOUBLE != 0;
/** Machine epsilon of the C build under test. */
constexpr double kEps = kDouble ? DBL_EPSILON : FLT_EPSILON;
constexpr const char *kPrecision = kDouble ? "double" : "float";
constexpr LD kPi = 3.141592653589793238462643383279502884L;

/** Edge-case angles of issue 2 (in the float build each is then rounded). */
constexpr double kEdgeAngles[] = {0.0, FLT_MIN, 1e-8, 1e-5, 1e-3, 0.1, 1.0, 3.0,
                                  3.141592653589793 - 1e-6};

/** The logarithms are also checked at theta = pi - d, d log-uniform in
 *  [kNearPi, 1e-3]. Double goes to 1e-12; float stops at 1e-6 (its spacing
 *  near pi is 2.4e-7, and the rounding of R then blurs the angle anyway). */
constexpr LD kNearPi = kDouble ? 1e-12L : 1e-6L;
constexpr const char *kNearPiRange = kDouble ? "pi-1e-3<t<pi-1e-12" : "pi-1e-3<t<pi-1e-6";

// ---------------------------------------------------------------- RNG

/** splitmix64 (fully specified, so the same seed gives the same inputs on
 *  every platform; std:: distributions are implementation-defined). */
class Rng {
  public:
    explicit Rng(std::uint64_t seed) : s_(seed) {}
    std::uint64_t next()
    {
        std::uint64_t z = (s_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    /** Uniform in [lo, hi). */
    LD uniform(LD lo, LD hi) { return lo + (hi - lo) * LD(next() >> 11) * 0x1.0p-53L; }
    /** log-uniform in [lo, hi), lo > 0. */
    LD log_uniform(LD lo, LD hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }
    LD normal()
    {
        const LD u = uniform(LD(0x1.0p-60L), 1);
        return std::sqrt(-2 * std::log(u)) * std::cos(2 * kPi * uniform(0, 1));
    }
    /** Uniformly distributed unit vector. */
    Vec3L axis()
    {
        Vec3L a;
        do {
            a = Vec3L(normal(), normal(), normal());
        } while (a.norm() < 1e-3L);
        return a / a.norm();
    }
    /** Entries uniform in [-scale, scale). */
    template <int R, int C> Eigen::Matrix<LD, R, C> matrix(LD scale)
    {
        Eigen::Matrix<LD, R, C> m;
        for (int i = 0; i < R * C; ++i) m(i) = uniform(-scale, scale);
        return m;
    }

  private:
    std::uint64_t s_;
};

/** The rotation angle of sample i of n in [0, max]: a quarter log-uniform in
 *  [1e-10, min(1, max)] (small-angle branches), a quarter uniform in
 *  [0, min(2, max)] (branch thresholds), the rest uniform in [0, max]. */
inline LD sample_angle(Rng &rng, long i, LD max)
{
    switch (i % 4) {
    case 0:
        return rng.log_uniform(1e-10L, std::min<LD>(1, max));
    case 1:
        return rng.uniform(0, std::min<LD>(2, max));
    default:
        return rng.uniform(0, max);
    }
}

/** x rounded to the build's precision. */
inline LD rnd(LD x) { return LD(real(x)); }
template <class M> M rnd(const M &x) { return x.unaryExpr([](LD e) { return rnd(e); }); }

/** Calls f(phi, theta) for rotation vectors phi already rounded to the
 *  build's precision (theta = |phi|): first every edge angle in [lo, hi] on
 *  the three coordinate axes and five random axes, then n random axes with
 *  angle(i), i = 0..n-1. */
template <class Angle, class F>
void sweep_rotvecs(Rng &rng, long n, LD lo, LD hi, Angle angle, F f)
{
    const Vec3L axes[3] = {Vec3L::UnitX(), Vec3L::UnitY(), Vec3L::UnitZ()};
    for (double th : kEdgeAngles) {
        if (LD(th) < lo || LD(th) > hi) {
            continue;
        }
        for (int a = 0; a < 8; ++a) {
            const Vec3L phi = rnd(Vec3L((a < 3 ? axes[a] : rng.axis()) * LD(th)));
            f(phi, phi.norm());
        }
    }
    for (long i = 0; i < n; ++i) {
        const Vec3L phi = rnd(Vec3L(rng.axis() * angle(i)));
        f(phi, phi.norm());
    }
}

/** sweep_rotvecs with the angles of sample_angle over [0, max]. */
template <class F> void sweep_rotvecs(Rng &rng, long n, LD max, F f)
{
    sweep_rotvecs(rng, n, 0, max, [&](long i) { return sample_angle(rng, i, max); }, f);
}

/** How sweep_range spreads the angles over [lo, hi] when lo > 0. */
enum class Spread { uniform, near_pi /* pi - d, d log-uniform in [pi-hi, pi-lo] */ };

/** sweep_rotvecs over [lo, hi]: sample_angle if lo == 0, else by `spread`. */
template <class F> void sweep_range(Rng &rng, long n, LD lo, LD hi, Spread spread, F f)
{
    if (lo == 0) {
        sweep_rotvecs(rng, n, hi, f);
    } else if (spread == Spread::near_pi) {
        sweep_rotvecs(
            rng, n, lo, hi, [&](long) { return kPi - rng.log_uniform(kPi - hi, kPi - lo); }, f);
    } else {
        sweep_rotvecs(rng, n, lo, hi, [&](long) { return rng.uniform(lo, hi); }, f);
    }
}

/** exp(phi) (I + E), E with entries uniform in [-drift, drift), rounded. */
inline Mat3L drifted_rotation(Rng &rng, const Vec3L &phi, LD drift)
{
    return rnd(Mat3L(so3_exp(phi) * (Mat3L::Identity() + rng.matrix<3, 3>(drift))));
}

/** SE23_CFG_ROT_TOL as the library sees it. */
const LD kRotTol = LD(real(SE23_CFG_ROT_TOL));

/** The rotation test of so3.h / config.h: R passes iff every
 *  |(R^T R - I)_ij| and |det R - 1| are within SE23_CFG_ROT_TOL; this is the
 *  larger of the two, in long double. */
inline LD rotation_defect(const Mat3L &R)
{
    return std::max((R.transpose() * R - Mat3L::Identity()).cwiseAbs().maxCoeff(),
                    std::fabs(R.determinant() - 1));
}

/** A matrix near exp(phi) whose rotation_defect is log-uniform around the
 *  tolerance: half random drift, half a pure scaling (which moves det most). */
inline Mat3L near_rotation(Rng &rng, const Vec3L &phi)
{
    const LD size = rng.log_uniform(kRotTol / 30, 30 * kRotTol);
    return (rng.next() & 1) ? drifted_rotation(rng, phi, size)
                            : rnd(Mat3L(so3_exp(phi) * (1 + size / 2)));
}

/** True within 5 % of the tolerance, where the rounding of the C computation
 *  may decide either way: decision checks skip those inputs. */
inline bool near_rot_tol(const Mat3L &R)
{
    return std::fabs(rotation_defect(R) - kRotTol) < kRotTol / 20;
}

// ---------------------------------------------------------------- conversions

inline se23_vec3_t to_c(const Vec3L &x)
{
    se23_vec3_t c;
    for (int i = 0; i < 3; ++i) c.v[i] = real(x(i));
    return c;
}
inline se23_mat3_t to_c(const Mat3L &x)
{
    se23_mat3_t c;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) c.m[i][j] = real(x(i, j));
    return c;
}
inline se23_tangent_t to_c(const Vec9L &x)
{
    se23_tangent_t c;
    for (int i = 0; i < 9; ++i) c.v[i] = real(x(i));
    return c;
}
inline se23_mat5_t to_c5(const Mat5L &x)
{
    se23_mat5_t c;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j) c.m[i][j] = real(x(i, j));
    return c;
}
/** The pose (R, v, p) of a 5x5 matrix. */
inline se23_pose_t to_pose(const Mat5L &T)
{
    se23_pose_t c;
    c.R = to_c(Mat3L(T.block<3, 3>(0, 0)));
    c.v = to_c(Vec3L(T.block<3, 1>(0, 3)));
    c.p = to_c(Vec3L(T.block<3, 1>(0, 4)));
    return c;
}

inline Vec3L ld(const se23_vec3_t &c) { return Vec3L(c.v[0], c.v[1], c.v[2]); }
inline Mat3L ld(const se23_mat3_t &c)
{
    Mat3L x;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) x(i, j) = c.m[i][j];
    return x;
}
inline Vec9L ld(const se23_tangent_t &c)
{
    Vec9L x;
    for (int i = 0; i < 9; ++i) x(i) = c.v[i];
    return x;
}
inline Mat5L ld(const se23_mat5_t &c)
{
    Mat5L x;
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j) x(i, j) = c.m[i][j];
    return x;
}
inline Mat9L ld(const se23_mat9_t &c)
{
    Mat9L x;
    for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 9; ++j) x(i, j) = c.m[9 * i + j];
    return x;
}
inline Mat5L ld(const se23_pose_t &c) { return pose5(ld(c.R), ld(c.v), ld(c.p)); }

/** Relative perturbation of C results, from $SE23_XC_PERTURB (0 if unset). */
inline LD perturbation()
{
    static const LD x = [] {
        const char *s = std::getenv("SE23_XC_PERTURB");
        return (s != nullptr) ? LD(std::strtold(s, nullptr)) : LD(0);
    }();
    return x;
}
/** A C result in long double (every C output must come through here). */
template <class C> auto out(const C &c)
{
    auto x = ld(c);
    const LD e = perturbation();
    return decltype(x)(x.unaryExpr([e](LD y) { return y * (1 + e) + e; }));
}
inline LD out(real c) { return LD(c) * (1 + perturbation()) + perturbation(); }
/** A C yes/no result (e.g. "status is SE23_OK"); negated when perturbed. */
inline bool out_flag(bool c) { return (perturbation() != 0) ? !c : c; }

// ---------------------------------------------------------------- errors

/** |got - exp| / |exp| (absolute if exp == 0); NaN counts as infinite. */
inline double err_rel(LD got, LD expected)
{
    const LD d = std::fabs(got - expected);
    const LD r = (expected != 0) ? d / std::fabs(expected) : d;
    return std::isfinite(double(r)) ? double(r) : INFINITY;
}

/** |got - exp| / max(|exp|, floor): relative, but near a zero crossing of
 *  exp relative to the typical size `floor` of the quantity. */
inline double err_rel_floor(LD got, LD expected, LD floor)
{
    const double r = double(std::fabs(got - expected) / std::max(std::fabs(expected), floor));
    return std::isfinite(r) ? r : INFINITY;
}

/** max_ij |got - exp| / max(1, max_ij |exp|): relative for entries above 1,
 *  absolute below. NaN counts as infinite. */
template <class A, class B>
double err_block(const Eigen::MatrixBase<A> &got, const Eigen::MatrixBase<B> &expected)
{
    const LD d = (got - expected).cwiseAbs().maxCoeff();
    const LD s = std::max<LD>(1, expected.cwiseAbs().maxCoeff());
    const double r = double(d / s);
    return (std::isfinite(r) && got.allFinite()) ? r : INFINITY;
}

/** err_block of each 3-block of a 9-vector (phi, nu, rho), worst of the three. */
inline double err_tangent(const Vec9L &got, const Vec9L &expected)
{
    double e = 0;
    for (int b = 0; b < 9; b += 3) {
        e = std::max(e, err_block(got.segment<3>(b), expected.segment<3>(b)));
    }
    return e;
}

/** err_block of R, v, p separately, worst of the three (5x5 pose matrices). */
inline double err_pose(const Mat5L &got, const Mat5L &expected)
{
    double e = err_block(got.block<3, 3>(0, 0), expected.block<3, 3>(0, 0));
    for (int c = 3; c < 5; ++c) {
        e = std::max(e, err_block(got.block<3, 1>(0, c), expected.block<3, 1>(0, c)));
    }
    // The constant rows must be exact.
    return std::max(e, err_block(got.block<2, 5>(3, 0), expected.block<2, 5>(3, 0)));
}

/** err_block of each 3x3 block of a 9x9 matrix, worst of the nine. */
inline double err_mat9(const Mat9L &got, const Mat9L &expected)
{
    double e = 0;
    for (int i = 0; i < 9; i += 3)
        for (int j = 0; j < 9; j += 3)
            e = std::max(e, err_block(got.block<3, 3>(i, j), expected.block<3, 3>(i, j)));
    return e;
}

// ---------------------------------------------------------------- report

/** One routine (or one input range of it): worst error against its bound. */
struct Row {
    std::string name;
    std::string norm;  // which error measure (for the table)
    double bound = 0;  // for this build's precision
    long samples = 0;
    long bad_status = 0;
    long over = 0;     // samples whose error exceeds the bound
    double worst = 0;
    LD worst_theta = 0;
};

class Report {
  public:
    Report(const char *program, int argc, char **argv) : program_(program)
    {
        const char *env = std::getenv("SE23_XC_OUT");
        path_ = (argc > 1) ? argv[1] : (env != nullptr ? env : "");
    }

    /** Declares a routine with its bound in the double and in the float build. */
    Row &row(const std::string &name, const std::string &norm, double bound_double,
             double bound_float)
    {
        rows_.push_back(Row());
        Row &r = rows_.back();
        r.name = name;
        r.norm = norm;
        r.bound = kDouble ? bound_double : bound_float;
        return r;
    }

    /** Records one comparison; theta is the rotation angle of the input. */
    void add(Row &r, double err, LD theta)
    {
        r.samples++;
        r.over += (err <= r.bound) ? 0 : 1;
        if (!(err <= r.worst)) {  // also takes NaN
            r.worst = std::isnan(err) ? INFINITY : err;
            r.worst_theta = theta;
        }
    }

    /** A C call that should have succeeded returned status st. */
    void status(Row &r, se23_status_t st, LD theta)
    {
        if (st != SE23_OK) {
            r.bad_status++;
            if (r.bad_status <= 3) {
                std::printf("  %s: unexpected %s at theta = %.17Lg\n", r.name.c_str(),
                            se23_status_str(st), theta);
            }
            add(r, INFINITY, theta);
        }
    }

    /** Prints the table, writes the markdown rows, returns the exit status. */
    int finish() const
    {
        const bool perturbed = perturbation() != 0;
        std::printf("%s, %s build (eps = %.3g)%s\n", program_.c_str(), kPrecision, kEps,
                    perturbed ? ", C results PERTURBED" : "");
        std::printf("%-34s %-8s %7s %10s %8s %8s %6s  %-12s %s\n", "routine", "error", "samples",
                    "worst", "/eps", "bound", "over", "worst at t", "result");
        int failed = 0;
        for (const Row &r : rows_) {
            const bool ok = r.worst <= r.bound && r.bad_status == 0 && r.samples > 0;
            failed += ok ? 0 : 1;
            const std::string in_eps = worst_in_eps(r);
            std::printf("%-34s %-8s %7ld %10.3e %8s %8.1e %6ld  %-12.7Lg %s\n", r.name.c_str(),
                        r.norm.c_str(), r.samples, r.worst, in_eps.c_str(), r.bound, r.over,
                        r.worst_theta, ok ? "ok" : "FAIL");
        }
        const int n = int(rows_.size());
        if (perturbed) {
            std::printf("perturbation detected by %d of %d rows\n", failed, n);
            return (failed == n && n > 0) ? 0 : 1;
        }
        write_markdown();
        std::printf("%d of %d rows within bounds\n", n - failed, n);
        return failed == 0 ? 0 : 1;
    }

  private:
    /** The worst error in units of eps ("-" for decisions: right or wrong). */
    static std::string worst_in_eps(const Row &r)
    {
        char buf[32] = "-";
        if (r.norm != "decision") {
            std::snprintf(buf, sizeof buf, "%.2f", std::min(r.worst / kEps, 1e9));
        }
        return buf;
    }

    void write_markdown() const
    {
        if (path_.empty()) {
            return;
        }
        std::FILE *f = std::fopen(path_.c_str(), "w");
        if (f == nullptr) {
            std::perror(path_.c_str());
            std::exit(2);
        }
        for (const Row &r : rows_) {
            std::fprintf(f, "| %s | %s | %s | %ld | %.2e | %s | %.3g | %ld |\n", r.name.c_str(),
                         kPrecision, r.norm.c_str(), r.samples, r.worst,
                         worst_in_eps(r).c_str(), r.bound, r.over);
        }
        std::fclose(f);
    }

    std::string program_;
    std::string path_;
    std::deque<Row> rows_;  // deque: references returned by row() stay valid
};

} // namespace xc

#endif // SE23_CROSSCHECK_HPP
