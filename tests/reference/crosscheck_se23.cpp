// Cross-check of include/se23/se23.h against the Eigen reference: 10,000
// seeded random inputs per routine plus the edge angles of issue 2. See
// crosscheck.hpp, tools/doc/pages/accuracy.md. Usage: crosscheck_se23 [markdown-file]
#include "crosscheck.hpp"

extern "C" {
#include "se23/se23.h"
}

namespace {

using namespace xc;

constexpr long kN = 10000;
// Bounds: the double build is held to issue 2's 1e-12; float bounds sit just
// above the measured worst case.
constexpr double kD = 1e-12;
constexpr double kF = FLT_EPSILON;

/** Velocity / position part of a random pose or tangent: entries uniform in
 *  [-s, s), s log-uniform in [1e-2, 1e3]. */
Vec3L translation(Rng &rng) { return rng.matrix<3, 1>(rng.log_uniform(1e-2L, 1e3L)); }

/** A random pose with rotation exp(phi), rounded to the build's precision. */
Mat5L random_pose(Rng &rng, const Vec3L &phi)
{
    return rnd(pose5(so3_exp(phi), translation(rng), translation(rng)));
}

Vec9L tangent(const Vec3L &phi, const Vec3L &nu, const Vec3L &rho)
{
    Vec9L xi;
    xi << phi, nu, rho;
    return xi;
}

void check_group_ops(Report &rep, Rng &rng)
{
    Row &ident = rep.row("se23_identity", "exact", 0, 0);
    se23_pose_t I;
    se23_identity(&I);
    rep.add(ident, err_pose(out(I), Mat5L::Identity()), 0);

    Row &comp = rep.row("se23_compose", "block", kD, 3 * kF);
    Row &inv = rep.row("se23_inverse", "block", kD, 2.5 * kF);
    Row &act_row = rep.row("se23_act", "block", kD, 2.5 * kF);
    Row &to5 = rep.row("se23_to_mat5", "exact", 0, 0);
    Row &from5 = rep.row("se23_from_mat5", "exact", 0, 0);
    sweep_rotvecs(rng, kN, kPi, [&](const Vec3L &phi, LD theta) {
        const Mat5L A = random_pose(rng, phi);
        const Mat5L B = random_pose(rng, rnd(Vec3L(rng.axis() * rng.uniform(0, kPi))));
        const se23_pose_t Ac = to_pose(A);
        const se23_pose_t Bc = to_pose(B);
        se23_pose_t AB;
        se23_compose(&Ac, &Bc, &AB);
        rep.add(comp, err_pose(out(AB), compose(A, B)), theta);

        se23_pose_t Ai;
        se23_inverse(&Ac, &Ai);
        rep.add(inv, err_pose(out(Ai), inverse(A)), theta);

        const Vec3L x = rnd(translation(rng));
        const se23_vec3_t xc_in = to_c(x);
        se23_vec3_t y;
        se23_act(&Ac, &xc_in, &y);
        rep.add(act_row, err_block(out(y), act(A, x)), theta);

        se23_mat5_t M;
        se23_to_mat5(&Ac, &M);
        rep.add(to5, err_block(out(M), A), theta);
        const se23_mat5_t Mc = to_c5(A);
        se23_pose_t T;
        const se23_status_t st = se23_from_mat5(&Mc, &T);
        rep.status(from5, st, theta);
        if (st == SE23_OK) {
            rep.add(from5, err_pose(out(T), A), theta);
        }
    });
}

void check_hat_vee(Report &rep, Rng &rng)
{
    Row &hat = rep.row("se23_hat", "exact", 0, 0);
    Row &vee = rep.row("se23_vee", "block", kD, 1 * kF);
    sweep_rotvecs(rng, kN, 2 * kPi, [&](const Vec3L &phi, LD theta) {
        const Vec9L xi = rnd(tangent(phi, translation(rng), translation(rng)));
        const se23_tangent_t xc_in = to_c(xi);
        se23_mat5_t X;
        se23_hat(&xc_in, &X);
        rep.add(hat, err_block(out(X), se23_hat(xi)), theta);
        // vee of a general 5x5 matrix reads the skew part of the 3x3 block.
        const Mat5L M = rnd(Mat5L(se23_hat(xi) + rng.matrix<5, 5>(1 + phi.norm())));
        const se23_mat5_t Mc = to_c5(M);
        se23_tangent_t v;
        se23_vee(&Mc, &v);
        rep.add(vee, err_tangent(out(v), se23_vee(M)), theta);
    });
}

// exp over rotation angles [lo, hi]. Beyond pi, J_l(phi) nears the rank-1
// projection onto the axis (theta -> 2 pi): v = J_l nu then cancels and its
// rounding error is eps |nu|, not eps |v|, for any algorithm. That row
// ("block/in") therefore measures the v and p errors relative to
// max(1, |v|, |nu|) and max(1, |p|, |rho|) (the input scale; ||J_l|| <= 1).
void check_exp(Report &rep, Row &row, Rng &rng, LD lo, LD hi)
{
    auto body = [&](const Vec3L &phi, LD theta) {
        const Vec9L xi = rnd(tangent(phi, translation(rng), translation(rng)));
        const se23_tangent_t xc_in = to_c(xi);
        se23_pose_t T;
        const se23_status_t st = se23_exp(&xc_in, &T);
        rep.status(row, st, theta);
        if (st != SE23_OK) {
            return;
        }
        const Mat5L got = out(T);
        const Mat5L want = se23_exp(xi);
        if (lo == 0) {
            rep.add(row, err_pose(got, want), theta);
            return;
        }
        double e = err_block(got.block<3, 3>(0, 0), want.block<3, 3>(0, 0));
        for (int b = 0; b < 2; ++b) {
            const LD scale = std::max(want.block<3, 1>(0, 3 + b).cwiseAbs().maxCoeff(),
                                      xi.segment<3>(3 + 3 * b).cwiseAbs().maxCoeff());
            e = std::max(e, err_block(Vec3L(got.block<3, 1>(0, 3 + b) / scale),
                                      Vec3L(want.block<3, 1>(0, 3 + b) / scale)));
        }
        rep.add(row, e, theta);
    };
    sweep_range(rng, kN, lo, hi, Spread::uniform, body);
}

// log of T = exp(xi) rounded, rotation angle in [lo, hi] (theta = pi - d with
// d log-uniform when lo > 0).
void check_log(Report &rep, Row &row, Rng &rng, LD lo, LD hi)
{
    auto body = [&](const Vec3L &phi, LD theta) {
        const Mat5L T = rnd(se23_exp(tangent(phi, translation(rng), translation(rng))));
        const se23_pose_t Tc = to_pose(T);
        se23_tangent_t xi;
        const se23_status_t st = se23_log(&Tc, &xi);
        rep.status(row, st, theta);
        if (st == SE23_OK) {
            rep.add(row, err_tangent(out(xi), se23_log(T)), theta);
        }
    };
    sweep_range(rng, kN, lo, hi, Spread::near_pi, body);
}

void check_adjoints(Report &rep, Rng &rng)
{
    Row &ad = rep.row("se23_adjoint", "block", kD, 2 * kF);
    Row &adi = rep.row("se23_adjoint_inv", "block", kD, 2 * kF);
    sweep_rotvecs(rng, kN, kPi, [&](const Vec3L &phi, LD theta) {
        const Mat5L T = random_pose(rng, phi);
        const se23_pose_t Tc = to_pose(T);
        se23_mat9_t A;
        se23_adjoint(&Tc, &A);
        rep.add(ad, err_mat9(out(A), adjoint(T)), theta);
        se23_adjoint_inv(&Tc, &A);
        rep.add(adi, err_mat9(out(A), adjoint_inv(T)), theta);
    });
}

// se23_pose_check against the documented rotation test (rotation_defect).
void check_pose_check(Report &rep, Rng &rng)
{
    Row &row = rep.row("se23_pose_check (decision)", "decision", 0, 0);
    sweep_rotvecs(rng, kN, 2 * kPi, [&](const Vec3L &phi, LD theta) {
        const Mat3L R = near_rotation(rng, phi);
        if (near_rot_tol(R)) {
            return;
        }
        const se23_pose_t Tc = to_pose(pose5(R, translation(rng), translation(rng)));
        const bool accepted = se23_pose_check(&Tc) == SE23_OK;
        rep.add(row, out_flag(accepted) == (rotation_defect(R) <= kRotTol) ? 0 : 1, theta);
    });
}

} // namespace

int main(int argc, char **argv)
{
    Report rep("crosscheck_se23", argc, argv);
    Rng rng(0x5E23'0023ull);

    check_group_ops(rep, rng);
    check_hat_vee(rep, rng);
    check_exp(rep, rep.row("se23_exp", "block", kD, 5 * kF), rng, 0, kPi);
    check_exp(rep, rep.row("se23_exp, pi<t<2pi", "block/in", kD, 7 * kF), rng, kPi, 2 * kPi);
    check_log(rep, rep.row("se23_log", "block", kD, 4 * kF), rng, 0, kPi - 1e-3L);
    check_log(rep, rep.row(std::string("se23_log, ") + kNearPiRange, "block", kD, 5 * kF),
              rng, kPi - 1e-3L, kPi - kNearPi);
    check_adjoints(rep, rng);
    check_pose_check(rep, rng);
    return rep.finish();
}
