/**
 * @file reference.hpp
 * @brief Independent Eigen reference for SO(3) and SE_2(3), written from the
 *        math (DESIGN.md section 3, paper eqs. exp:map and ad:eq), not from the
 *        C code, for the cross-check programs in this folder.
 *
 * Routes (deliberately different from the closed forms the C library uses):
 *  - exp / log: generic matrix exponential / principal logarithm of the 3x3
 *    or 5x5 matrix (Eigen unsupported/Eigen/MatrixFunctions). The logarithm is
 *    then polished by two Newton steps on the group,
 *    x <- x + Jr(x)^-1 vee(logm(exp(x)^-1 M)), because Eigen's logm loses
 *    accuracy near theta = pi (TOOLCHAIN.md); the residual is the logm of a
 *    matrix near the identity, where logm is accurate.
 *  - J_l, J_r, H, K: their defining power series sum_n c_n phi^^n, summed in
 *    long double until the terms vanish; J_l^-1 by LU inversion of J_l.
 *  - the scalar coefficients: alternating Taylor series in long double for
 *    theta < 2, long-double closed forms above.
 *  - Adjoint: dense 9x9 built column by column from its definition
 *    Ad_T xi = vee(T xi^ T^-1); adjoint of the inverse = adjoint of the
 *    Eigen-inverted 5x5 matrix.
 *  - compose / inverse / act: 5x5 matrix product, 5x5 LU inverse, and the
 *    5x5 matrix applied to the homogeneous point (x, 0, 1).
 *
 * Every function comes in double and in long double (x86-64 80-bit extended),
 * so that the cross-checks can hold the expected value more accurately than
 * the double build computes it. Only ref_matfun.cpp includes MatrixFunctions
 * (it takes ~20 s to compile); other ref_*.cpp files use expm()/logm().
 *
 * Conventions as the library: pose T = (R, v, p) as the 5x5 matrix
 * [[R, v, p], [0, 1, 0], [0, 0, 1]]; tangent xi = (phi, nu, rho);
 * xi^ = [[phi^, nu, rho], [0, 0, 0], [0, 0, 0]].
 */
#ifndef SE23_REFERENCE_HPP
#define SE23_REFERENCE_HPP

#include <Eigen/Dense>

namespace se23ref {

template <class S> using Vec3T = Eigen::Matrix<S, 3, 1>;
template <class S> using Mat3T = Eigen::Matrix<S, 3, 3>;
template <class S> using Vec9T = Eigen::Matrix<S, 9, 1>;
template <class S> using Mat5T = Eigen::Matrix<S, 5, 5>;
template <class S> using Mat9T = Eigen::Matrix<S, 9, 9>;

using Vec3 = Vec3T<double>;
using Mat3 = Mat3T<double>;
using Vec9 = Vec9T<double>;
using Mat5 = Mat5T<double>;
using Mat9 = Mat9T<double>;

using LD = long double;
using Vec3L = Vec3T<LD>;
using Mat3L = Mat3T<LD>;
using Vec9L = Vec9T<LD>;
using Mat5L = Mat5T<LD>;
using Mat9L = Mat9T<LD>;

using MatX = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic>;
using MatXL = Eigen::Matrix<LD, Eigen::Dynamic, Eigen::Dynamic>;

/* ---- generic matrix functions (ref_matfun.cpp, the only MatrixFunctions TU) */

/** exp(A), Eigen's scaling-and-squaring Pade exponential. */
MatX expm(const MatX &A);
MatXL expm(const MatXL &A);
/** The principal logarithm log(A) (Eigen's Schur-Parlett + Pade). */
MatX logm(const MatX &A);
MatXL logm(const MatXL &A);

/* Declares f for double and long double. */
#define SE23REF_BOTH(ret, name, args_d, args_l)                                \
    ret<double> name args_d;                                                   \
    ret<LD> name args_l

/* ---- SO(3) (ref_lie.cpp) ------------------------------------------------ */

/** phi^: the skew matrix with phi^ x = phi cross x. */
SE23REF_BOTH(Mat3T, hat3, (const Vec3 &phi), (const Vec3L &phi));
/** vee of the skew part (W - W^T)/2. */
SE23REF_BOTH(Vec3T, vee3, (const Mat3 &W), (const Mat3L &W));
/** exp(phi^) = expm of the 3x3 skew matrix. */
SE23REF_BOTH(Mat3T, so3_exp, (const Vec3 &phi), (const Vec3L &phi));
/** Principal log (|phi| <= pi): logm + Newton polish (see file comment). */
SE23REF_BOTH(Vec3T, so3_log, (const Mat3 &R), (const Mat3L &R));
/** J_l(phi) = sum_n phi^^n/(n+1)!. */
SE23REF_BOTH(Mat3T, jl, (const Vec3 &phi), (const Vec3L &phi));
/** J_l(phi)^-1 by LU inversion of the series. */
SE23REF_BOTH(Mat3T, jl_inv, (const Vec3 &phi), (const Vec3L &phi));
/** J_r(phi) = sum_n (-phi^)^n/(n+1)!. */
SE23REF_BOTH(Mat3T, jr, (const Vec3 &phi), (const Vec3L &phi));
/** H(phi) = sum_n phi^^n/(n+2)!. */
SE23REF_BOTH(Mat3T, so3_h, (const Vec3 &phi), (const Vec3L &phi));
/** K(phi) = sum_n phi^^n/(n! (n+2)). */
SE23REF_BOTH(Mat3T, so3_k, (const Vec3 &phi), (const Vec3L &phi));
/** The rotation nearest to M in the Frobenius norm: U V^T of the SVD (det > 0 assumed). */
SE23REF_BOTH(Mat3T, polar, (const Mat3 &M), (const Mat3L &M));

/* ---- scalar coefficients of the SO(3) series, long double (ref_lie.cpp) --
 * With W = phi^ and theta = |phi|, W^3 = -theta^2 W, so every series above is
 * a0 I + a1 W + a2 W^2 with these coefficients:
 *   exp: I + a(1) W + a(2) W^2     J_l: I + a(2) W + a(3) W^2
 *   H:   I/2 + a(3) W + a(4) W^2   K:   I/2 + k1 W + k2 W^2
 *   J_l^-1: I - W/2 + jinv W^2                                             */

/** a(m, theta) = sum_k (-1)^k theta^(2k)/(2k+m)!, m >= 1:
 *  a(1) = sin t/t, a(2) = (1-cos t)/t^2, a(3) = (t-sin t)/t^3,
 *  a(4) = (t^2/2+cos t-1)/t^4. */
LD coef_a(int m, LD theta);
/** k1 = (sin t - t cos t)/t^3 = sum_k (-1)^k t^(2k)/((2k+1)!(2k+3)). */
LD coef_k1(LD theta);
/** k2 = (t^2/2 - cos t - t sin t + 1)/t^4 = sum_k (-1)^k t^(2k)/((2k+2)!(2k+4)). */
LD coef_k2(LD theta);
/** jinv = (1 - (t/2) cot(t/2))/t^2 = sum_{n>=1} (-1)^(n+1) B_2n t^(2n-2)/(2n)!
 *  (Bernoulli numbers), valid for t < 2 pi. */
LD coef_jinv(LD theta);

/* ---- SE_2(3) (ref_lie.cpp) ---------------------------------------------- */

/** The 5x5 matrix of (R, v, p). */
SE23REF_BOTH(Mat5T, pose5, (const Mat3 &R, const Vec3 &v, const Vec3 &p),
             (const Mat3L &R, const Vec3L &v, const Vec3L &p));
/** xi^ as a 5x5 matrix. */
SE23REF_BOTH(Mat5T, se23_hat, (const Vec9 &xi), (const Vec9L &xi));
/** vee: skew part of the 3x3 block, then rows 0..2 of columns 3 and 4. */
SE23REF_BOTH(Vec9T, se23_vee, (const Mat5 &X), (const Mat5L &X));
/** exp(xi) = expm of the 5x5 matrix xi^. */
SE23REF_BOTH(Mat5T, se23_exp, (const Vec9 &xi), (const Vec9L &xi));
/** log(T) = vee(logm(T)), Newton-polished; rotation angle <= pi. */
SE23REF_BOTH(Vec9T, se23_log, (const Mat5 &T), (const Mat5L &T));
/** ad_xi eta = vee([xi^, eta^]), dense 9x9 from the commutator. */
SE23REF_BOTH(Mat9T, se23_ad, (const Vec9 &xi), (const Vec9L &xi));
/** Right Jacobian sum_n (-ad_xi)^n/(n+1)!: exp(xi+d) = exp(xi) exp(Jr d) + O(d^2). */
SE23REF_BOTH(Mat9T, se23_jr, (const Vec9 &xi), (const Vec9L &xi));
/** Ad_T, column i = vee(T e_i^ T^-1). */
SE23REF_BOTH(Mat9T, adjoint, (const Mat5 &T), (const Mat5L &T));
/** Ad_{T^-1} = adjoint(inverse(T)). */
SE23REF_BOTH(Mat9T, adjoint_inv, (const Mat5 &T), (const Mat5L &T));
/** A B. */
SE23REF_BOTH(Mat5T, compose, (const Mat5 &A, const Mat5 &B),
             (const Mat5L &A, const Mat5L &B));
/** T^-1 by Eigen's 5x5 LU inverse. */
SE23REF_BOTH(Mat5T, inverse, (const Mat5 &T), (const Mat5L &T));
/** The first three entries of T (x, 0, 1)^T, i.e. R x + p. */
SE23REF_BOTH(Vec3T, act, (const Mat5 &T, const Vec3 &x),
             (const Mat5L &T, const Vec3L &x));

#undef SE23REF_BOTH

} // namespace se23ref

#endif // SE23_REFERENCE_HPP
