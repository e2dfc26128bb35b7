// Cross-check of include/se23/so3.h and the internal series coefficients
// (src/lie/so3_series.h) against the Eigen reference: 10,000 seeded random inputs
// per routine plus the edge angles of issue 2. See crosscheck.hpp and
// tools/doc/pages/accuracy.md. Usage: crosscheck_so3 [markdown-output-file]
#include "crosscheck.hpp"

extern "C" {
#include "se23/so3.h"
#include "lie/so3_series.h"
}

namespace {

using namespace xc;

constexpr long kN = 10000;
// Bounds: the double build is held to issue 2's 1e-12; float bounds sit just
// above the measured worst case (series coefficients: issue 2's 16 eps).
constexpr double kD = 1e-12;
constexpr double kF = FLT_EPSILON;
constexpr double kCoefF = 16 * kF;

// A matrix-valued C routine phi -> M against its reference over a sweep of
// angles in [lo, hi]; the error is divided by cond(theta) (1: plain).
template <class C, class Ref, class Cond>
void check_mat3_fn(Report &rep, Row &row, Rng &rng, LD lo, LD hi, C c_fn, Ref ref_fn,
                   Cond cond)
{
    auto body = [&](const Vec3L &phi, LD theta) {
        const se23_vec3_t in = to_c(phi);
        se23_mat3_t M;
        const se23_status_t st = c_fn(&in, &M);
        rep.status(row, st, theta);
        if (st == SE23_OK) {
            rep.add(row, err_block(out(M), ref_fn(phi)) / double(cond(theta)), theta);
        }
    };
    sweep_range(rng, kN, lo, hi, Spread::uniform, body);
}

void check_hat_vee(Report &rep, Rng &rng)
{
    Row &hat = rep.row("so3_hat", "exact", 0, 0);
    Row &vee = rep.row("so3_vee", "block", kD, 1 * kF);
    sweep_rotvecs(rng, kN, 2 * kPi, [&](const Vec3L &phi, LD theta) {
        const se23_vec3_t in = to_c(phi);
        se23_mat3_t W;
        se23_so3_hat(&in, &W);
        rep.add(hat, err_block(out(W), hat3(phi)), theta);
        // vee of a general matrix reads its skew part.
        const Mat3L M = rnd(Mat3L(hat3(phi) + rng.matrix<3, 3>(1 + phi.norm())));
        const se23_mat3_t Mc = to_c(M);
        se23_vec3_t v;
        se23_so3_vee(&Mc, &v);
        rep.add(vee, err_block(out(v), vee3(M)), theta);
    });
}

void check_log(Report &rep, Row &row, Rng &rng, LD lo, LD hi)
{
    auto body = [&](const Vec3L &phi, LD theta) {
        const Mat3L R = rnd(so3_exp(phi));
        const se23_mat3_t Rc = to_c(R);
        se23_vec3_t got;
        const se23_status_t st = se23_so3_log(&Rc, &got);
        rep.status(row, st, theta);
        if (st == SE23_OK) {
            rep.add(row, err_block(out(got), so3_log(R)), theta);
        }
    };
    sweep_range(rng, kN, lo, hi, Spread::near_pi, body);
}

void check_normalize(Report &rep, Rng &rng)
{
    Row &row = rep.row("so3_normalize", "block", kD, 4 * kF);
    const LD min_drift = kDouble ? 1e-12L : 1e-6L;
    sweep_rotvecs(rng, kN, 2 * kPi, [&](const Vec3L &phi, LD theta) {
        Mat3L R;
        do {  // stay inside the repairable range (|R^T R - I| <= 0.1)
            R = drifted_rotation(rng, phi, rng.log_uniform(min_drift, 0.04L));
        } while ((R.transpose() * R - Mat3L::Identity()).cwiseAbs().maxCoeff() > 0.09L);
        const se23_mat3_t Rc = to_c(R);
        se23_mat3_t Rn;
        const se23_status_t st = se23_so3_normalize(&Rc, &Rn);
        rep.status(row, st, theta);
        if (st == SE23_OK) {
            rep.add(row, err_block(out(Rn), polar(R)), theta);
        }
    });
}

// so3_check against the documented contract (see rotation_defect).
void check_rotation_test(Report &rep, Rng &rng)
{
    Row &row = rep.row("so3_check (decision)", "decision", 0, 0);
    sweep_rotvecs(rng, kN, 2 * kPi, [&](const Vec3L &phi, LD theta) {
        const Mat3L R = near_rotation(rng, phi);
        const bool expected = rotation_defect(R) <= kRotTol;
        if (!near_rot_tol(R)) {
            const se23_mat3_t Rc = to_c(R);
            rep.add(row, out_flag(se23_so3_check(&Rc) == SE23_OK) == expected ? 0 : 1, theta);
        }
    });
}

void check_coefficients(Report &rep, Rng &rng)
{
    const char *names[7] = {"series c1", "series c2", "series c3", "series c4",
                            "series k1", "series k2", "series e (J^-1)"};
    Row *rows[7];
    for (int i = 0; i < 7; ++i) rows[i] = &rep.row(names[i], "rel", kD, kCoefF);
    Row &beyond = rep.row("series c1..k2, pi<t<2pi", "rel*", kD, kCoefF);
    Row &e_beyond = rep.row("series e, pi<t<2pi-2e-3", "rel", kD, kCoefF);

    auto one = [&](LD t_in) {
        const real t = real(t_in);
        const LD theta = t;
        se23_so3_coeffs_t c;
        se23_so3_coeffs(t, &c);
        real k1;
        real k2;
        se23_so3_k_coeffs(t, &k1, &k2);
        const LD got[6] = {out(c.c1), out(c.c2), out(c.c3), out(c.c4), out(k1), out(k2)};
        const LD want[6] = {coef_a(1, theta), coef_a(2, theta), coef_a(3, theta),
                            coef_a(4, theta), coef_k1(theta),   coef_k2(theta)};
        // Beyond pi c1 and k1 cross zero: there the error is relative to
        // max(|c(theta)|, |c(0)|) ("rel*").
        const LD at0[6] = {1, 0.5L, 1 / 6.0L, 1 / 24.0L, 1 / 3.0L, 1 / 8.0L};
        const LD e_got = (theta < 2 * kPi - 2e-3L) ? out(se23_so3_jl_inv_coeff(t)) : 0;
        if (theta <= kPi) {
            for (int i = 0; i < 6; ++i) rep.add(*rows[i], err_rel(got[i], want[i]), theta);
            rep.add(*rows[6], err_rel(e_got, coef_jinv(theta)), theta);
        } else {
            for (int i = 0; i < 6; ++i) {
                rep.add(beyond, err_rel_floor(got[i], want[i], at0[i]), theta);
            }
            if (theta < 2 * kPi - 2e-3L) {
                rep.add(e_beyond, err_rel(e_got, coef_jinv(theta)), theta);
            }
        }
    };
    for (double th : kEdgeAngles) one(th);
    for (long i = 0; i < kN; ++i) one(sample_angle(rng, i, kPi));
    for (long i = 0; i < kN; ++i) one(rng.uniform(kPi, 2 * kPi));
}

} // namespace

int main(int argc, char **argv)
{
    Report rep("crosscheck_so3", argc, argv);
    Rng rng(0x5E23'0003ull);
    const auto plain = [](LD) { return LD(1); };
    // J_l^-1 near 2 pi: a relative change eps of phi (e.g. the rounding of
    // theta = |phi|) changes J_l^-1 by eps kappa, kappa = 1 + theta/(2 pi - theta),
    // for any algorithm; that row divides the error by kappa.
    const auto kappa = [](LD t) { return 1 + t / (2 * kPi - t); };

    check_hat_vee(rep, rng);
    check_mat3_fn(rep, rep.row("so3_exp", "block", kD, 6 * kF), rng, 0, 2 * kPi,
                  se23_so3_exp, [](const Vec3L &p) { return so3_exp(p); }, plain);
    check_log(rep, rep.row("so3_log", "block", kD, 3 * kF), rng, 0, kPi - 1e-3L);
    check_log(rep, rep.row(std::string("so3_log, ") + kNearPiRange, "block", kD, 3 * kF),
              rng, kPi - 1e-3L, kPi - kNearPi);
    check_mat3_fn(rep, rep.row("so3_jl", "block", kD, 4 * kF), rng, 0, 2 * kPi, se23_so3_jl,
                  [](const Vec3L &p) { return jl(p); }, plain);
    check_mat3_fn(rep, rep.row("so3_jr", "block", kD, 4 * kF), rng, 0, 2 * kPi, se23_so3_jr,
                  [](const Vec3L &p) { return jr(p); }, plain);
    check_mat3_fn(rep, rep.row("so3_jl_inv", "block", kD, 3 * kF), rng, 0, kPi, se23_so3_jl_inv,
                  [](const Vec3L &p) { return jl_inv(p); }, plain);
    check_mat3_fn(rep, rep.row("so3_jl_inv, pi<t<2pi-2e-3", "block/k", kD, 2 * kF), rng, kPi,
                  2 * kPi - 2e-3L, se23_so3_jl_inv, [](const Vec3L &p) { return jl_inv(p); },
                  kappa);
    check_mat3_fn(rep, rep.row("so3_h", "block", kD, 2 * kF), rng, 0, 2 * kPi, se23_so3_h,
                  [](const Vec3L &p) { return so3_h(p); }, plain);
    check_mat3_fn(rep, rep.row("so3_k", "block", kD, 3 * kF), rng, 0, 2 * kPi, se23_so3_k,
                  [](const Vec3L &p) { return so3_k(p); }, plain);
    check_normalize(rep, rng);
    check_rotation_test(rep, rng);
    check_coefficients(rep, rng);
    return rep.finish();
}
