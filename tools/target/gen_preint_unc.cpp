// Target vectors of preint_unc.h. Expected values from the definitions in
// long double: Deltas by the augmented exponential (ref_nav.hpp), the
// covariance and exponential-coordinate bias Jacobian of the paper's form
// as dense F_k P F_k^T + B N B^T and F_k J + B_k (F_k = Ad_{Upsilon^-1} F;
// exact B_k by the Frechet derivative of the augmented exponential, as in
// gen_gauss.cpp), stored in the left form by its definition P_left =
// Ad_Delta P Ad_Delta^T, J_left = Ad_Delta J; the classical Jacobians by the
// recursions of the header's file comment, and the corrections
// Delta exp(J db) with the reference SE_2(3) exponential.
// Row layout of se23_preint_unc_t: f (delta, dt, n), b_g, b_a, kind,
// P_left (9x9), J_left (9x6), classical dR/dbg, dV/dbg, dV/dba, dX/dbg,
// dX/dba (3x3 each).
#include "gen_common.hpp"
#include "ref_nav.hpp"

namespace gen {

// From gen_gauss.cpp.
Eigen::Matrix<LD, 9, 6> gen_input_jac(int kind, const Vec3L &w, const Vec3L &f, LD dt);
Mat9L gen_fk(const Mat5L &U, LD dt);
int gen_cov_status(const MatXL &P, const Ctx &c);

namespace {

using Mat96L = Eigen::Matrix<LD, 9, 6>;

struct Unc {
    Mat5L delta;
    LD dt, n;
    Vec3L bg, ba;
    LD kind, classic;
    Mat9L P;  // the left form, P_left
    Mat96L J; // J_left
    Mat3L cl[5]; // dR_dbg, dV_dbg, dV_dba, dX_dbg, dX_dba
};
// Ad_Delta^-1 = F_k with U = Delta, dt = 0: the paper's form of a left-form
// P or J, and back.
Mat9L ad_inv(const Mat5L &delta) { return gen_fk(delta, 0); }
Mat9L ad(const Mat5L &delta) { return gen_fk(Mat5L(delta.inverse()), 0); }
void put_unc(Row &r, const Unc &u)
{
    put_pose(r, u.delta);
    put(r, u.dt);
    put(r, u.n);
    put(r, u.bg);
    put(r, u.ba);
    put(r, u.kind);
    put(r, u.classic);
    put(r, u.P);
    put(r, u.J);
    for (const Mat3L &m : u.cl) put(r, m);
}
Unc read_unc(Rd &rd)
{
    Unc u;
    u.delta = rd.pose();
    u.dt = rd.s();
    u.n = rd.s();
    u.bg = rd.v3();
    u.ba = rd.v3();
    u.kind = rd.s();
    u.classic = rd.s();
    for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 9; ++j) u.P(i, j) = rd.s();
    for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 6; ++j) u.J(i, j) = rd.s();
    for (Mat3L &m : u.cl) m = rd.m3();
    return u;
}
Unc unc_any(Ctx &c, int k)
{
    Unc u;
    u.delta = pose_k(c, k + n_angles());
    u.dt = c.uniform(0, 1);
    u.n = LD(int(c.uniform(0, 100)));
    u.bg = vec3_any(c, 1e-2L);
    u.ba = vec3_any(c, 0.1L);
    u.kind = (k % 3 == 2) ? 1 : 0;
    u.classic = (k % 2) ? 1 : 0;
    MatXL A(9, 9);
    for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 9; ++j) A(i, j) = c.uniform(-1, 1);
    const MatXL P = LD(1e-3) * (A * A.transpose() / LD(9) + LD(0.1) * MatXL::Identity(9, 9));
    u.P = (P + P.transpose()) / 2;
    for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 6; ++j) u.J(i, j) = c.uniform(-1, 1);
    for (Mat3L &m : u.cl)
        for (int i = 0; i < 9; ++i) m(i / 3, i % 3) = c.uniform(-1, 1);
    return u;
}
// Edge rows: unknown kind, NaN in J, Delta R not a rotation, dt < 0,
// P not symmetric, P not PSD, classic flag not 0 or 1.
const int kUncEdges = 7;
void break_unc(Unc &u, int k)
{
    if (k == 6) u.classic = 2;
    if (k == 0) u.kind = 2;
    if (k == 1) u.J(4, 2) = kNaN;
    if (k == 2) u.delta.block<3, 3>(0, 0) *= LD(1.01);
    if (k == 3) u.dt = -0.1L;
    if (k == 4) u.P(0, 3) += LD(0.1) * u.P(0, 0);
    if (k == 5) u.P(6, 6) = -u.P(6, 6);
}
// se23_preint_unc_check, as documented.
int unc_status(const Unc &u, const Ctx &c)
{
    if (u.kind != 0 && u.kind != 1) return SE23_ERR_DOMAIN;
    if (u.classic != 0 && u.classic != 1) return SE23_ERR_DOMAIN;
    Row all;
    put_unc(all, u);
    if (!all_finite(all)) return SE23_ERR_NONFINITE;
    if (!is_rotation(u.delta.block<3, 3>(0, 0), c)) return SE23_ERR_NOT_ROTATION;
    if (u.dt < 0) return SE23_ERR_DT;
    return gen_cov_status(u.P, c);
}
Scale scale_unc()
{
    return scale_concat({{17, scale_blocks({9, 3, 3, 1, 1})},
                         {8, scale_blocks({3, 3, 1, 1})},
                         {81, scale_cov(9)},
                         {54, scale_mat_blocks(9, 6, 3)},
                         {45, scale_blocks({9, 9, 9, 9, 9})}});
}

} // namespace

void add_preint_unc(Gens &g)
{
    const auto reset = [](LD classic) {
        return Gen{2,
                   [](Ctx &c, int k) {
                       // edges: unknown kind, NaN bias
                       Row r;
                       Vec3L bg = vec3_any(c, 1e-2L);
                       if (k == 1) bg(0) = kNaN;
                       put(r, bg);
                       put(r, vec3_any(c, 0.1L));
                       put(r, LD(k == 0 ? 2 : k % 2));
                       return r;
                   },
                   [classic](const Ctx &, const Row &in, Row &out) {
                       if (!all_finite(in)) return int(SE23_ERR_NONFINITE);
                       if (in[6] != 0 && in[6] != 1) return int(SE23_ERR_DOMAIN);
                       Unc u;
                       u.delta = Mat5L::Identity();
                       u.dt = u.n = 0;
                       u.bg = Vec3L(in[0], in[1], in[2]);
                       u.ba = Vec3L(in[3], in[4], in[5]);
                       u.kind = in[6];
                       u.classic = classic;
                       u.P = Mat9L::Zero();
                       u.J = Mat96L::Zero();
                       for (Mat3L &m : u.cl) m = Mat3L::Zero();
                       put_unc(out, u);
                       return int(SE23_OK);
                   }};
    };
    g["se23_preint_unc_reset"] = reset(0);
    g["se23_preint_unc_reset_classic"] = reset(1);
    g["se23_preint_unc_add"] = {
        3,
        [](Ctx &c, int k) {
            // edges: s.dt = 0, a negative density, NaN in s (the factor is
            // trusted: preint_unc.h, "Validation policy" of types.h)
            Unc u = unc_any(c, k);
            Row r;
            put_unc(r, u);
            Vec3L w = vec3_any(c, 2);
            if (k == 2) w(1) = kNaN;
            put(r, w);
            put(r, vec3_any(c, 20));
            put(r, k == 0 ? LD(0) : c.uniform(1e-3L, 0.02L));
            put(r, k == 1 ? LD(-1e-3) : LD(1e-3));
            put(r, 1e-2L);
            put(r, 1e-5L);
            put(r, 1e-4L);
            return r;
        },
        [](const Ctx &, const Row &in, Row &out) {
            Rd rd{in};
            Unc u = read_unc(rd);
            const Vec3L wm = rd.v3(), fm = rd.v3();
            const LD dt = rd.s(), sg = rd.s(), sa = rd.s();
            rd.s();
            rd.s();
            if (!all_finite(in)) return int(SE23_ERR_NONFINITE);
            int st = SE23_OK;
            if (!(dt > 0 && dt <= LD(SE23_CFG_DT_MAX))) st = SE23_ERR_DT;
            if (st == SE23_OK && (sg < 0 || sa < 0)) st = SE23_ERR_DOMAIN;
            if (st != SE23_OK) return st;
            const Vec3L w = wm + u.bg, f = fm + u.ba;
            const Mat5L U = upsilon_expm(w, f, dt);
            const Mat9L F = gen_fk(U, dt);
            const Mat96L B = gen_input_jac(int(u.kind), w, f, dt);
            Eigen::Matrix<LD, 6, 6> N = Eigen::Matrix<LD, 6, 6>::Zero();
            N.diagonal() << sg * sg / dt, sg * sg / dt, sg * sg / dt, sa * sa / dt, sa * sa / dt,
                sa * sa / dt;
            const Mat3L DR = u.delta.block<3, 3>(0, 0), DRk = so3_exp(Vec3L(w * dt));
            const Mat3L fx = hat3(f), Jr = jr(Vec3L(w * dt));
            Mat3L cl[5];
            cl[0] = DRk.transpose() * u.cl[0] + Jr * dt;
            cl[1] = u.cl[1] - DR * fx * u.cl[0] * dt;
            cl[2] = u.cl[2] + DR * dt;
            cl[3] = u.cl[3] + u.cl[1] * dt - DR * fx * u.cl[0] * (dt * dt / 2);
            cl[4] = u.cl[4] + u.cl[2] * dt + DR * (dt * dt / 2);
            const Mat9L Ai = ad_inv(u.delta);
            const Mat9L P = Ai * u.P * Ai.transpose();
            const Mat96L J = Ai * u.J;
            u.delta = phi_t(u.delta, dt) * U;
            u.dt += dt;
            u.n += 1;
            const Mat9L A = ad(u.delta);
            u.P = A * (F * P * F.transpose() + B * N * B.transpose()) * A.transpose();
            u.J = A * (F * J + B);
            if (u.classic != 0)
                for (int i = 0; i < 5; ++i) u.cl[i] = cl[i];
            put_unc(out, u);
            return int(SE23_OK);
        }};
    // A factor alone, with the factor edges.
    const auto factor_in = [](Ctx &c, int k) {
        Unc u = unc_any(c, k);
        break_unc(u, k);
        Row r;
        put_unc(r, u);
        return r;
    };
    g["se23_preint_unc_check"] = {kUncEdges, factor_in,
                                  [](const Ctx &c, const Row &in, Row &) {
                                      Rd rd{in};
                                      return unc_status(read_unc(rd), c);
                                  }};
    // Corrections: a factor, a new bias estimate near the old one; edges:
    // the factor edges, then a NaN bias.
    const auto correct_in = [](Ctx &c, int k) {
        Unc u = unc_any(c, k);
        break_unc(u, k);
        Row r;
        put_unc(r, u);
        Vec3L bg = u.bg + vec3_any(c, 1e-3L);
        if (k == kUncEdges) bg(2) = kNaN;
        put(r, bg);
        put(r, Vec3L(u.ba + vec3_any(c, 1e-2L)));
        return r;
    };
    const auto correct = [](bool classic) {
        return [classic](const Ctx &c, const Row &in, Row &out) {
            Rd rd{in};
            const Unc u = read_unc(rd);
            const Vec3L bg = rd.v3(), ba = rd.v3();
            int st = unc_status(u, c);
            if (st == SE23_OK && !all_finite(in)) st = SE23_ERR_NONFINITE;
            if (st == SE23_OK && classic && u.classic == 0) st = SE23_ERR_DOMAIN;
            if (st != SE23_OK) return st;
            const Vec3L dg = bg - u.bg, da = ba - u.ba;
            if (!classic) {
                Eigen::Matrix<LD, 6, 1> db;
                db << dg, da;
                const Mat96L J = ad_inv(u.delta) * u.J;
                put_preint(out, Mat5L(u.delta * se23_exp(Vec9L(J * db))), u.dt, u.n);
            } else {
                const Mat3L R = u.delta.block<3, 3>(0, 0) * so3_exp(Vec3L(u.cl[0] * dg));
                const Vec3L V = Vec3L(u.delta.block<3, 1>(0, 3)) + u.cl[1] * dg + u.cl[2] * da;
                const Vec3L X = Vec3L(u.delta.block<3, 1>(0, 4)) + u.cl[3] * dg + u.cl[4] * da;
                put_preint(out, pose5(R, V, X), u.dt, u.n);
            }
            return int(SE23_OK);
        };
    };
    g["se23_preint_unc_correct"] = {kUncEdges + 1, correct_in, correct(false)};
    g["se23_preint_unc_correct_classic"] = {kUncEdges + 1, correct_in, correct(true)};
    // The paper's form: the factor edges (the Deltas of unc_any are small:
    // the shear cannot overflow).
    g["se23_preint_unc_cov"] = {kUncEdges, factor_in,
                                [](const Ctx &c, const Row &in, Row &out) {
                                    Rd rd{in};
                                    const Unc u = read_unc(rd);
                                    const int st = unc_status(u, c);
                                    if (st != SE23_OK) return st;
                                    const Mat9L Ai = ad_inv(u.delta);
                                    put(out, Mat9L(Ai * u.P * Ai.transpose()));
                                    put(out, Mat96L(Ai * u.J));
                                    return int(SE23_OK);
                                }};
    g["se23_preint_unc_reset"].scale = scale_unc();
    g["se23_preint_unc_reset_classic"].scale = scale_unc();
    // A reset factor is the identity with zero P and J whatever the biases:
    // 48 random rows of 290 reals cost 2 x 110 kB of the M7 image for nothing.
    g["se23_preint_unc_reset"].n_random = 6;
    g["se23_preint_unc_reset_classic"].n_random = 6;
    g["se23_preint_unc_add"].scale = scale_unc();
    g["se23_preint_unc_correct"].scale = scale_blocks({9, 3, 3, 1, 1});
    g["se23_preint_unc_correct_classic"].scale = scale_blocks({9, 3, 3, 1, 1});
    // 425 reals a row: few random rows, as for reset (the conversion is
    // the same dense products whatever the factor).
    g["se23_preint_unc_cov"].n_random = 8;
    g["se23_preint_unc_cov"].scale =
        scale_concat({{81, scale_cov(9)}, {54, scale_mat_blocks(9, 6, 3)}});
}

} // namespace gen
