/*
 * Internal to the benchmark's Eigen reference (ref_*.cpp): fixed-size types
 * in the precision of se23_real_t, maps onto the se23 structs, and the
 * SO(3) / SE_2(3) pieces of DESIGN.md section 3 (ref_lie.cpp).
 *
 * Poses are dense 5x5 matrices [[R, v, p], [0, 1, 0], [0, 0, 1]]; tangent
 * vectors are (phi, nu, rho); the 15-dim error appends (db_g, db_a).
 */
#ifndef SE23_BENCH_REF_HPP
#define SE23_BENCH_REF_HPP

#include <Eigen/Dense>

#include "se23/types.h"

namespace bref {

using Real = se23_real_t;
template <int R, int C> using Mat = Eigen::Matrix<Real, R, C>;
using Vec3 = Mat<3, 1>;
using Vec9 = Mat<9, 1>;
using Mat3 = Mat<3, 3>;
using Mat5 = Mat<5, 5>;
using Mat9 = Mat<9, 9>;
using Mat96 = Mat<9, 6>;

/* An R x C row-major block with row stride S inside a flat se23 array. */
template <int R, int C, int S = C>
using RowMap = Eigen::Map<Eigen::Matrix<Real, R, C, Eigen::RowMajor>, Eigen::Unaligned,
                          Eigen::OuterStride<S>>;
template <int R, int C, int S = C>
using ConstRowMap = Eigen::Map<const Eigen::Matrix<Real, R, C, Eigen::RowMajor>,
                               Eigen::Unaligned, Eigen::OuterStride<S>>;

inline Eigen::Map<const Vec3> vec3(const se23_vec3_t &a) { return Eigen::Map<const Vec3>(a.v); }
inline Eigen::Map<Vec3> vec3(se23_vec3_t &a) { return Eigen::Map<Vec3>(a.v); }

/* The 5x5 matrix of a pose, and back. */
Mat5 pose5(const se23_pose_t &T);
void store_pose(const Mat5 &T, se23_pose_t &out);

/* w^, the matrix of w x . */
inline Mat3 hat(const Vec3 &w)
{
    Mat3 W;
    W << 0, -w(2), w(1), w(2), 0, -w(0), -w(1), w(0), 0;
    return W;
}

/* One sample with corrected inputs w [rad/s], f [m/s^2] over dt [s]:
 * U = Upsilon(w, f, dt) = (exp(th^), dt J(th) f, dt^2 H(th) f), th = w dt,
 * and the exact input matrix B = d/d(dg, da) log(U(w, f)^-1 U(w + dg, f + da))
 * at 0: rows (phi, nu, rho) of R^T dR, R^T dv, R^T dp, i.e.
 * [[dt J_r, 0], [dt^2 R^T D_J, dt R^T J], [dt^3 R^T D_H, dt^2 R^T H]] with
 * D_S = d(S(th) f)/d(th). */
struct Increment {
    Mat5 U;
    Mat96 B;
};
Increment increment(const Vec3 &w, const Vec3 &f, Real dt);

/* Ad_T = [[R, 0, 0], [v^ R, R, 0], [p^ R, 0, R]], dense. */
Mat9 adjoint(const Mat5 &T);

/* F_k = Ad_{U^-1} F, F(phi, nu, rho) = (phi, nu, rho + dt nu), dense. */
Mat9 transition(const Mat5 &U, Real dt);

/* Phi_dt(T) = (R, v, p + dt v). */
Mat5 shift(const Mat5 &T, Real dt);

/* exp(xi) = (exp(phi^), J(phi) nu, J(phi) rho). */
Mat5 se23_exp(const Vec9 &xi);

/* Gamma'(dt) for gravity g and Earth rate Omega (DESIGN.md section 3). */
Mat5 gamma(const Vec3 &g, const Vec3 &omega, Real dt);

} // namespace bref

#endif // SE23_BENCH_REF_HPP
