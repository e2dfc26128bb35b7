// SO(3) and SE_2(3) pieces of the benchmark's Eigen reference (ref.hpp),
// from DESIGN.md section 3. With W = th^ and t = |th|, W^3 = -t^2 W, so
// every series used here is a0 I + a1 W + a2 W^2, its coefficients power
// series in t^2, summed to rounding by Horner's rule (|th| <= 1 rad).
#include <array>

#include "ref.hpp"

namespace bref {
namespace {

// The first omitted term of any series below is at most t^20/21! < 2e-20.
constexpr int kTerms = 10;
using Series = std::array<double, kTerms>;

constexpr double factorial(int n)
{
    double r = 1;
    for (int i = 2; i <= n; ++i) {
        r *= i;
    }
    return r;
}

// a_m(t) = sum_k (-t^2)^k / (2k+m)!: a_1 = sin t/t, a_2 = (1 - cos t)/t^2,
// a_3 = (t - sin t)/t^3, a_4 = (t^2/2 + cos t - 1)/t^4.
constexpr Series series_a(int m)
{
    Series c{};
    for (int k = 0; k < kTerms; ++k) {
        c[k] = 1 / factorial(2 * k + m);
    }
    return c;
}

// The coefficients of K(th) = sum_n th^^n / (n! (n+2)):
// k_m(t) = sum_k (-t^2)^k / ((2k+m)! (2k+m+2)), m = 1, 2.
constexpr Series series_k(int m)
{
    Series c{};
    for (int k = 0; k < kTerms; ++k) {
        c[k] = 1 / (factorial(2 * k + m) * (2 * k + m + 2));
    }
    return c;
}

// The series of a'(t)/t for a(t) = sum_k c_k (-t^2)^k.
constexpr Series derivative_over_t(const Series &c)
{
    Series d{};
    for (int j = 0; j + 1 < kTerms; ++j) {
        d[j] = -2.0 * (j + 1) * c[j + 1];
    }
    return d;
}

constexpr Series A1 = series_a(1), A2 = series_a(2), A3 = series_a(3), A4 = series_a(4);
constexpr Series DA2 = derivative_over_t(A2), DA3 = derivative_over_t(A3),
                 DA4 = derivative_over_t(A4);
constexpr Series K1 = series_k(1), K2 = series_k(2);

// An angle th with W = th^, W^2 and t^2.
struct Angle {
    Vec3 th;
    Mat3 W, W2;
    Real t2;
    explicit Angle(const Vec3 &a) : th(a), W(hat(a)), W2(W * W), t2(a.squaredNorm()) {}
    Real sum(const Series &c) const
    {
        Real s = 0;
        for (int k = kTerms - 1; k >= 0; --k) {
            s = Real(c[k]) - t2 * s;
        }
        return s;
    }
    Mat3 form(Real a0, Real a1, Real a2) const
    {
        return a0 * Mat3::Identity() + a1 * W + a2 * W2;
    }
    // d(S(th) f)/d(th) for S = a0 I + a1(t) W + a2(t) W^2, given a1, a2 and
    // d1 = a1'/t, d2 = a2'/t.
    Mat3 derivative(const Vec3 &f, Real a1, Real a2, Real d1, Real d2) const
    {
        const Mat3 dW2f = th.dot(f) * Mat3::Identity() + th * f.transpose() -
                          2 * f * th.transpose();
        return -a1 * hat(f) + a2 * dW2f + (d1 * W * f + d2 * W2 * f) * th.transpose();
    }
};

} // namespace

Mat5 pose5(const se23_pose_t &T)
{
    Mat5 M = Mat5::Identity();
    M.block<3, 3>(0, 0) = ConstRowMap<3, 3>(&T.R.m[0][0]);
    M.block<3, 1>(0, 3) = vec3(T.v);
    M.block<3, 1>(0, 4) = vec3(T.p);
    return M;
}

void store_pose(const Mat5 &T, se23_pose_t &out)
{
    RowMap<3, 3>(&out.R.m[0][0]) = T.block<3, 3>(0, 0);
    vec3(out.v) = T.block<3, 1>(0, 3);
    vec3(out.p) = T.block<3, 1>(0, 4);
}

Increment increment(const Vec3 &w, const Vec3 &f, Real dt)
{
    const Angle a(w * dt);
    const Real a1 = a.sum(A1), a2 = a.sum(A2), a3 = a.sum(A3), a4 = a.sum(A4);
    const Mat3 R = a.form(1, a1, a2), J = a.form(1, a2, a3), H = a.form(Real(0.5), a3, a4);
    const Mat3 Rt = R.transpose();
    Increment inc;
    inc.U = Mat5::Identity();
    inc.U.block<3, 3>(0, 0) = R;
    inc.U.block<3, 1>(0, 3) = dt * J * f;
    inc.U.block<3, 1>(0, 4) = dt * dt * H * f;
    const Real d2 = a.sum(DA2), d3 = a.sum(DA3), d4 = a.sum(DA4);
    inc.B.setZero();
    inc.B.block<3, 3>(0, 0) = dt * a.form(1, -a2, a3); // J_r = J(-th)
    inc.B.block<3, 3>(3, 0) = dt * dt * Rt * a.derivative(f, a2, a3, d2, d3);
    inc.B.block<3, 3>(3, 3) = dt * Rt * J;
    inc.B.block<3, 3>(6, 0) = dt * dt * dt * Rt * a.derivative(f, a3, a4, d3, d4);
    inc.B.block<3, 3>(6, 3) = dt * dt * Rt * H;
    return inc;
}

Mat9 adjoint(const Mat5 &T)
{
    const Mat3 R = T.block<3, 3>(0, 0);
    Mat9 Ad = Mat9::Zero();
    for (int k = 0; k < 3; ++k) {
        Ad.block<3, 3>(3 * k, 3 * k) = R;
    }
    Ad.block<3, 3>(3, 0) = hat(T.block<3, 1>(0, 3)) * R;
    Ad.block<3, 3>(6, 0) = hat(T.block<3, 1>(0, 4)) * R;
    return Ad;
}

Mat9 transition(const Mat5 &U, Real dt)
{
    const Mat3 Rt = U.block<3, 3>(0, 0).transpose();
    Mat9 Ad = Mat9::Zero();
    for (int k = 0; k < 3; ++k) {
        Ad.block<3, 3>(3 * k, 3 * k) = Rt;
    }
    Ad.block<3, 3>(3, 0) = -Rt * hat(U.block<3, 1>(0, 3));
    Ad.block<3, 3>(6, 0) = -Rt * hat(U.block<3, 1>(0, 4));
    Mat9 F = Mat9::Identity();
    F.block<3, 3>(6, 3) = dt * Mat3::Identity();
    return Ad * F;
}

Mat5 shift(const Mat5 &T, Real dt)
{
    Mat5 S = T;
    S.block<3, 1>(0, 4) += dt * T.block<3, 1>(0, 3);
    return S;
}

Mat5 se23_exp(const Vec9 &xi)
{
    const Angle a(xi.head<3>());
    const Real a2 = a.sum(A2);
    const Mat3 J = a.form(1, a2, a.sum(A3));
    Mat5 T = Mat5::Identity();
    T.block<3, 3>(0, 0) = a.form(1, a.sum(A1), a2);
    T.block<3, 1>(0, 3) = J * xi.segment<3>(3);
    T.block<3, 1>(0, 4) = J * xi.segment<3>(6);
    return T;
}

Mat5 gamma(const Vec3 &g, const Vec3 &omega, Real dt)
{
    const Angle a(-omega * dt);
    const Real a2 = a.sum(A2);
    Mat5 G = Mat5::Identity();
    G.block<3, 3>(0, 0) = a.form(1, a.sum(A1), a2);
    G.block<3, 1>(0, 3) = dt * a.form(1, a2, a.sum(A3)) * g;
    G.block<3, 1>(0, 4) = dt * dt * a.form(Real(0.5), a.sum(K1), a.sum(K2)) * g;
    return G;
}

} // namespace bref
