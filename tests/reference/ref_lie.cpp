// SO(3) and SE_2(3) reference routines from their definitions; see
// reference.hpp for the routes. Templates on the scalar (double, long double);
// the power series are always summed in long double.
#include <cmath>

#include "reference.hpp"

namespace se23ref {
namespace {

template <class S, int N> using MatN = Eigen::Matrix<S, N, N>;
template <class S, int N> using VecN = Eigen::Matrix<S, N, 1>;

template <class S, int N> MatN<S, N> expm_n(const MatN<S, N> &A)
{
    using MX = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;
    return MatN<S, N>(expm(MX(A)));
}

template <class S, int N> MatN<S, N> logm_n(const MatN<S, N> &A)
{
    using MX = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;
    return MatN<S, N>(logm(MX(A)));
}

template <class S> Mat3T<S> hat3_t(const Vec3T<S> &w)
{
    Mat3T<S> W;
    W << S(0), -w(2), w(1), w(2), S(0), -w(0), -w(1), w(0), S(0);
    return W;
}

template <class S> Vec3T<S> vee3_t(const Mat3T<S> &W)
{
    return Vec3T<S>((W(2, 1) - W(1, 2)) / S(2), (W(0, 2) - W(2, 0)) / S(2),
                    (W(1, 0) - W(0, 1)) / S(2));
}

// sum_{n>=0} c(n) A^n in long double, for a matrix whose powers do not grow
// faster than |A|^n: stops once two consecutive terms are negligible.
template <int N, class Coef> MatN<LD, N> power_series(const MatN<LD, N> &A, Coef c)
{
    MatN<LD, N> sum = MatN<LD, N>::Zero();
    MatN<LD, N> P = MatN<LD, N>::Identity();
    int small = 0;
    for (int n = 0; n < 400 && small < 2; ++n) {
        const MatN<LD, N> term = c(n) * P;
        sum += term;
        small = (term.norm() <= 1e-32L * sum.norm()) ? small + 1 : 0;
        P = P * A;
    }
    return sum;
}

LD factorial(int n)
{
    LD f = 1;
    for (int i = 2; i <= n; ++i) {
        f *= LD(i);
    }
    return f;
}

Mat3L jl_ld(const Vec3L &phi)
{
    return power_series<3>(hat3_t<LD>(phi), [](int n) { return 1 / factorial(n + 1); });
}

Mat3L h_ld(const Vec3L &phi)
{
    return power_series<3>(hat3_t<LD>(phi), [](int n) { return 1 / factorial(n + 2); });
}

Mat3L k_ld(const Vec3L &phi)
{
    return power_series<3>(hat3_t<LD>(phi),
                           [](int n) { return 1 / (factorial(n) * LD(n + 2)); });
}

template <class S> Vec3L to_ld(const Vec3T<S> &x) { return x.template cast<LD>(); }

template <class S> Mat5T<S> pose5_t(const Mat3T<S> &R, const Vec3T<S> &v, const Vec3T<S> &p)
{
    Mat5T<S> T = Mat5T<S>::Identity();
    T.template block<3, 3>(0, 0) = R;
    T.template block<3, 1>(0, 3) = v;
    T.template block<3, 1>(0, 4) = p;
    return T;
}

template <class S> Mat5T<S> se23_hat_t(const Vec9T<S> &xi)
{
    Mat5T<S> X = Mat5T<S>::Zero();
    X.template block<3, 3>(0, 0) = hat3_t<S>(xi.template segment<3>(0));
    X.template block<3, 1>(0, 3) = xi.template segment<3>(3);
    X.template block<3, 1>(0, 4) = xi.template segment<3>(6);
    return X;
}

template <class S> Vec9T<S> se23_vee_t(const Mat5T<S> &X)
{
    Vec9T<S> xi;
    xi.template segment<3>(0) = vee3_t<S>(X.template block<3, 3>(0, 0));
    xi.template segment<3>(3) = X.template block<3, 1>(0, 3);
    xi.template segment<3>(6) = X.template block<3, 1>(0, 4);
    return xi;
}

template <class S> Mat9T<S> se23_ad_t(const Vec9T<S> &xi)
{
    const Mat5T<S> X = se23_hat_t<S>(xi);
    Mat9T<S> ad;
    for (int i = 0; i < 9; ++i) {
        const Mat5T<S> E = se23_hat_t<S>(Vec9T<S>::Unit(i));
        ad.col(i) = se23_vee_t<S>(X * E - E * X);
    }
    return ad;
}

Mat9L se23_jr_ld(const Vec9L &xi)
{
    return power_series<9>(Mat9L(-se23_ad_t<LD>(xi)),
                           [](int n) { return 1 / factorial(n + 1); });
}

// Principal logarithm of M in the group (exp, log, vee, Jr given): Eigen's
// logm, then Newton steps x <- x + Jr(x)^-1 vee(logm(exp(x)^-1 M)) until the
// step is at rounding level (at least two, at most eight). logm is accurate
// near the identity, where the residual lives, so the fixed point is accurate
// even where logm(M) itself is not (theta near pi).
template <class S, int N, int D, class Exp, class Vee, class Jr>
VecN<S, D> polished_log(const MatN<S, N> &M, Exp exp_fn, Vee vee_fn, Jr jr_fn)
{
    VecN<S, D> x = vee_fn(logm_n<S, N>(M));
    for (int it = 0; it < 8; ++it) {
        const MatN<S, N> Einv = exp_fn(x).inverse();
        const VecN<S, D> r = vee_fn(logm_n<S, N>(MatN<S, N>(Einv * M)));
        const VecN<S, D> step = jr_fn(x).partialPivLu().solve(r);
        x += step;
        if (it >= 1 && step.norm() <= 8 * Eigen::NumTraits<S>::epsilon() * (1 + x.norm())) {
            break;
        }
    }
    return x;
}

template <class S> Mat9T<S> adjoint_t(const Mat5T<S> &T)
{
    const Mat5T<S> Tinv = T.inverse();
    Mat9T<S> Ad;
    for (int i = 0; i < 9; ++i) {
        Ad.col(i) = se23_vee_t<S>(T * se23_hat_t<S>(Vec9T<S>::Unit(i)) * Tinv);
    }
    return Ad;
}

template <class S> Mat3T<S> polar_t(const Mat3T<S> &M)
{
    Eigen::JacobiSVD<Mat3T<S>> svd(M, Eigen::ComputeFullU | Eigen::ComputeFullV);
    return svd.matrixU() * svd.matrixV().transpose();
}

} // namespace

// ---- SO(3)

Mat3 hat3(const Vec3 &phi) { return hat3_t<double>(phi); }
Mat3L hat3(const Vec3L &phi) { return hat3_t<LD>(phi); }
Vec3 vee3(const Mat3 &W) { return vee3_t<double>(W); }
Vec3L vee3(const Mat3L &W) { return vee3_t<LD>(W); }
Mat3 so3_exp(const Vec3 &phi) { return expm_n<double, 3>(hat3(phi)); }
Mat3L so3_exp(const Vec3L &phi) { return expm_n<LD, 3>(hat3(phi)); }

Mat3 jl(const Vec3 &phi) { return jl_ld(to_ld(phi)).cast<double>(); }
Mat3L jl(const Vec3L &phi) { return jl_ld(phi); }
Mat3 jl_inv(const Vec3 &phi) { return jl_ld(to_ld(phi)).inverse().cast<double>(); }
Mat3L jl_inv(const Vec3L &phi) { return jl_ld(phi).inverse(); }
Mat3 jr(const Vec3 &phi) { return jl_ld(Vec3L(-to_ld(phi))).cast<double>(); }
Mat3L jr(const Vec3L &phi) { return jl_ld(Vec3L(-phi)); }
Mat3 so3_h(const Vec3 &phi) { return h_ld(to_ld(phi)).cast<double>(); }
Mat3L so3_h(const Vec3L &phi) { return h_ld(phi); }
Mat3 so3_k(const Vec3 &phi) { return k_ld(to_ld(phi)).cast<double>(); }
Mat3L so3_k(const Vec3L &phi) { return k_ld(phi); }
Mat3 polar(const Mat3 &M) { return polar_t<double>(M); }
Mat3L polar(const Mat3L &M) { return polar_t<LD>(M); }

template <class S> static Vec3T<S> so3_log_t(const Mat3T<S> &R)
{
    return polished_log<S, 3, 3>(
        R, [](const Vec3T<S> &x) { return so3_exp(x); },
        [](const Mat3T<S> &W) { return vee3(W); },
        [](const Vec3T<S> &x) { return jr(x); });
}
Vec3 so3_log(const Mat3 &R) { return so3_log_t<double>(R); }
Vec3L so3_log(const Mat3L &R) { return so3_log_t<LD>(R); }

// ---- scalar coefficients

LD coef_a(int m, LD t)
{
    if (t < 2) {
        LD sum = 0;
        LD pw = 1;
        for (int k = 0; k < 40; ++k, pw *= -t * t) {
            sum += pw / factorial(2 * k + m);
        }
        return sum;
    }
    // a(1), a(2) closed; a(m) = (1/(m-2)! - a(m-2))/t^2 from the series.
    if (m == 1) {
        return std::sin(t) / t;
    }
    if (m == 2) {
        return (1 - std::cos(t)) / (t * t);
    }
    return (1 / factorial(m - 2) - coef_a(m - 2, t)) / (t * t);
}

LD coef_k1(LD t)
{
    if (t < 2) {
        LD sum = 0;
        LD pw = 1;
        for (int k = 0; k < 40; ++k, pw *= -t * t) {
            sum += pw / (factorial(2 * k + 1) * LD(2 * k + 3));
        }
        return sum;
    }
    return (std::sin(t) - t * std::cos(t)) / (t * t * t);
}

LD coef_k2(LD t)
{
    if (t < 2) {
        LD sum = 0;
        LD pw = 1;
        for (int k = 0; k < 40; ++k, pw *= -t * t) {
            sum += pw / (factorial(2 * k + 2) * LD(2 * k + 4));
        }
        return sum;
    }
    return (t * t / 2 - std::cos(t) - t * std::sin(t) + 1) / (t * t * t * t);
}

LD coef_jinv(LD t)
{
    if (t < 2) {
        // (t/2)cot(t/2) = a(1)/(2 a(2)), so jinv = (2 a(2) - a(1))/(2 a(2) t^2)
        // and 2 a(2) - a(1) = t^2 sum_j (-1)^j t^(2j) (2j+2)/(2j+4)!.
        LD num = 0;
        LD pw = 1;
        for (int j = 0; j < 40; ++j, pw *= -t * t) {
            num += pw * LD(2 * j + 2) / factorial(2 * j + 4);
        }
        return num / (2 * coef_a(2, t));
    }
    const LD h = t / 2;
    return (1 - h * std::cos(h) / std::sin(h)) / (t * t);
}

// ---- SE_2(3)

Mat5 pose5(const Mat3 &R, const Vec3 &v, const Vec3 &p) { return pose5_t<double>(R, v, p); }
Mat5L pose5(const Mat3L &R, const Vec3L &v, const Vec3L &p) { return pose5_t<LD>(R, v, p); }
Mat5 se23_hat(const Vec9 &xi) { return se23_hat_t<double>(xi); }
Mat5L se23_hat(const Vec9L &xi) { return se23_hat_t<LD>(xi); }
Vec9 se23_vee(const Mat5 &X) { return se23_vee_t<double>(X); }
Vec9L se23_vee(const Mat5L &X) { return se23_vee_t<LD>(X); }
Mat5 se23_exp(const Vec9 &xi) { return expm_n<double, 5>(se23_hat(xi)); }
Mat5L se23_exp(const Vec9L &xi) { return expm_n<LD, 5>(se23_hat(xi)); }
Mat9 se23_ad(const Vec9 &xi) { return se23_ad_t<double>(xi); }
Mat9L se23_ad(const Vec9L &xi) { return se23_ad_t<LD>(xi); }
Mat9 se23_jr(const Vec9 &xi) { return se23_jr_ld(xi.cast<LD>()).cast<double>(); }
Mat9L se23_jr(const Vec9L &xi) { return se23_jr_ld(xi); }

template <class S> static Vec9T<S> se23_log_t(const Mat5T<S> &T)
{
    return polished_log<S, 5, 9>(
        T, [](const Vec9T<S> &x) { return se23_exp(x); },
        [](const Mat5T<S> &X) { return se23_vee(X); },
        [](const Vec9T<S> &x) { return se23_jr(x); });
}
Vec9 se23_log(const Mat5 &T) { return se23_log_t<double>(T); }
Vec9L se23_log(const Mat5L &T) { return se23_log_t<LD>(T); }

Mat9 adjoint(const Mat5 &T) { return adjoint_t<double>(T); }
Mat9L adjoint(const Mat5L &T) { return adjoint_t<LD>(T); }
Mat9 adjoint_inv(const Mat5 &T) { return adjoint_t<double>(Mat5(T.inverse())); }
Mat9L adjoint_inv(const Mat5L &T) { return adjoint_t<LD>(Mat5L(T.inverse())); }
Mat5 compose(const Mat5 &A, const Mat5 &B) { return A * B; }
Mat5L compose(const Mat5L &A, const Mat5L &B) { return A * B; }
Mat5 inverse(const Mat5 &T) { return T.inverse(); }
Mat5L inverse(const Mat5L &T) { return T.inverse(); }

template <class S> static Vec3T<S> act_t(const Mat5T<S> &T, const Vec3T<S> &x)
{
    VecN<S, 5> h;
    h << x, S(0), S(1);
    return (T * h).template head<3>();
}
Vec3 act(const Mat5 &T, const Vec3 &x) { return act_t<double>(T, x); }
Vec3L act(const Mat5L &T, const Vec3L &x) { return act_t<LD>(T, x); }

} // namespace se23ref
