// Self-test of the Eigen reference (no C library involved): each reference
// route against a second, independent route, in long double, so that the
// reference's own error (~1e-18) is known to be negligible next to the
// double build's eps (2.2e-16). Usage: selftest_reference [markdown-file]
//   so3_exp (expm)        vs  Rodrigues I + a1 W + a2 W^2 (coef_a)
//   so3_log (polished)    vs  the phi that generated R (|phi| < pi)
//   jl, so3_h (series)    vs  blocks of expm([[W, I], [0, 0]]) and
//                             expm([[W, I, 0], [0, 0, I], [0, 0, 0]])
//   so3_k (series)        vs  J - H (sum (n+1) W^n/(n+2)! = K)
//   jl_inv (LU)           vs  I - W/2 + coef_jinv W^2
//   coef_a, k1, k2, jinv  vs  the matrix routes above (both branches: series
//                             below theta = 2, closed forms above)
//   se23_log (polished)   vs  the xi that generated T
//   adjoint (definition)  vs  [[R,0,0],[v^R,R,0],[p^R,0,R]] (paper eq. ad:eq)
//   se23_jr (series)      vs  central difference of log(exp(xi)^-1 exp(xi +- h e_i))
#include "crosscheck.hpp"

namespace {

using namespace xc;

constexpr long kN = 2000;
constexpr double kRef = 1e-16;  // bound for every row (long double: eps 1.1e-19)

template <int N> Eigen::Matrix<LD, N, N> expm_fixed(const Eigen::Matrix<LD, N, N> &A)
{
    return Eigen::Matrix<LD, N, N>(expm(MatXL(A)));
}

void so3_routes(Report &rep, Rng &rng)
{
    Row &exp_r = rep.row("ref so3_exp vs Rodrigues", "block", kRef, kRef);
    Row &log_r = rep.row("ref so3_log(exp(phi)) vs phi", "block", kRef, kRef);
    Row &jl_r = rep.row("ref jl vs 6x6 expm", "block", kRef, kRef);
    Row &h_r = rep.row("ref so3_h vs 9x9 expm", "block", kRef, kRef);
    Row &k_r = rep.row("ref so3_k vs J - H", "block", kRef, kRef);
    // Near 2 pi the in-plane part of J_l is ~(2 pi - t)/t while the series
    // terms reach ~12: the long-double sum loses ~1e3 ulp before inversion.
    Row &ji_r = rep.row("ref jl_inv vs coef_jinv", "block", 1e-15, 1e-15);
    Row &cj_r = rep.row("ref jl vs coef_a(2), coef_a(3)", "block", kRef, kRef);
    Row &ch_r = rep.row("ref so3_h vs coef_a(3), coef_a(4)", "block", kRef, kRef);
    Row &ck_r = rep.row("ref so3_k vs coef_k1, coef_k2", "block", kRef, kRef);
    sweep_rotvecs(rng, kN, 2 * kPi - 0.1L, [&](const Vec3L &phi, LD t) {
        const Mat3L W = hat3(phi);
        const Mat3L I = Mat3L::Identity();
        rep.add(exp_r, err_block(so3_exp(phi), Mat3L(I + coef_a(1, t) * W + coef_a(2, t) * W * W)),
                t);
        if (t < kPi - 1e-6L) {
            rep.add(log_r, err_block(so3_log(so3_exp(phi)), phi), t);
        }
        Eigen::Matrix<LD, 6, 6> A6 = Eigen::Matrix<LD, 6, 6>::Zero();
        A6.block<3, 3>(0, 0) = W;
        A6.block<3, 3>(0, 3) = I;
        const Mat3L J6 = expm_fixed<6>(A6).block<3, 3>(0, 3);
        rep.add(jl_r, err_block(jl(phi), J6), t);
        Eigen::Matrix<LD, 9, 9> A9 = Eigen::Matrix<LD, 9, 9>::Zero();
        A9.block<3, 3>(0, 0) = W;
        A9.block<3, 3>(0, 3) = I;
        A9.block<3, 3>(3, 6) = I;
        const Mat3L H9 = expm_fixed<9>(A9).block<3, 3>(0, 6);
        rep.add(h_r, err_block(so3_h(phi), H9), t);
        rep.add(k_r, err_block(so3_k(phi), Mat3L(J6 - H9)), t);
        rep.add(ji_r, err_block(jl_inv(phi), Mat3L(I - W / 2 + coef_jinv(t) * W * W)), t);
        const Mat3L W2 = W * W;
        rep.add(cj_r, err_block(J6, Mat3L(I + coef_a(2, t) * W + coef_a(3, t) * W2)), t);
        rep.add(ch_r, err_block(H9, Mat3L(I / 2 + coef_a(3, t) * W + coef_a(4, t) * W2)), t);
        rep.add(ck_r, err_block(so3_k(phi), Mat3L(I / 2 + coef_k1(t) * W + coef_k2(t) * W2)), t);
    });
}

void se23_routes(Report &rep, Rng &rng)
{
    Row &log_r = rep.row("ref se23_log(exp(xi)) vs xi", "block", kRef, kRef);
    Row &ad_r = rep.row("ref adjoint vs eq. ad:eq", "block", kRef, kRef);
    Row &jr_r = rep.row("ref se23_jr vs central diff.", "block", 1e-9, 1e-9);
    long count = 0;
    sweep_rotvecs(rng, kN, kPi - 1e-6L, [&](const Vec3L &phi, LD t) {
        Vec9L xi;
        xi << phi, rng.matrix<3, 1>(10), rng.matrix<3, 1>(100);
        const Mat5L T = se23_exp(xi);
        rep.add(log_r, err_tangent(se23_log(T), xi), t);

        const Mat3L R = T.block<3, 3>(0, 0);
        Mat9L A = Mat9L::Zero();
        A.block<3, 3>(0, 0) = A.block<3, 3>(3, 3) = A.block<3, 3>(6, 6) = R;
        A.block<3, 3>(3, 0) = hat3(Vec3L(T.block<3, 1>(0, 3))) * R;
        A.block<3, 3>(6, 0) = hat3(Vec3L(T.block<3, 1>(0, 4))) * R;
        rep.add(ad_r, err_mat9(adjoint(T), A), t);

        // Central difference (every 8th sample: 18 logs each): truncation
        // O(h^2) and rounding O(eps |xi| / h) leave ~1e-11 at best, so this
        // row's bound is 1e-9; it proves the series is the Jacobian (a wrong
        // sign or block gives O(1)), the Newton polish only needs that.
        if (count++ % 8 != 0) {
            return;
        }
        const LD h = 1e-6L;
        const Mat5L Tinv = inverse(T);
        Mat9L D;
        for (int i = 0; i < 9; ++i) {
            const Vec9L e = Vec9L::Unit(i) * h;
            D.col(i) = (se23_log(Mat5L(Tinv * se23_exp(Vec9L(xi + e)))) -
                        se23_log(Mat5L(Tinv * se23_exp(Vec9L(xi - e))))) / (2 * h);
        }
        rep.add(jr_r, err_mat9(se23_jr(xi), D), t);
    });
}

} // namespace

int main(int argc, char **argv)
{
    Report rep("selftest_reference", argc, argv);
    Rng rng(0x5E23'5E1Full);
    so3_routes(rep, rng);
    se23_routes(rep, rng);
    return rep.finish();
}
