// Target vectors of gauss.h and kalman.h. Expected values from the definitions, in long
// double, with dense matrices (the library uses block structure):
//   F_k = Ad_{U^-1} F (reference adjoint_inv times the 9x9 F),
//   B_k exact = vee(Upsilon^-1 L_j) per input direction j, L_j the Frechet
//     derivative of the 5x5 augmented exponential (reference expm of the
//     10x10 block matrix [[A, dA_j], [0, A]]: its top-right block),
//   Q = B N B^T, covariance steps as dense Phi P Phi^T + noise,
//   the mean of a prediction by RK4 of the navigation equations,
//   carried <-> user errors by M = [[I,0,0],[0,I,-(R^T Omega)^],[0,0,I]] (the
//     exact Jacobian of v = v' - Omega x p under T = Tbar exp(xi)).
//   the Kalman update dense (S, K = P H^T S^-1, Joseph form), measurement
//     Jacobians from h(Tbar exp(xi)) to first order (derived in kalman.h's
//     comments and re-derived for the review of this file).
// Row layouts: se23_gauss_t = T, b_g, b_a, n, P (15x15, zeros outside n x n);
// se23_meas_t = m, z (9), H (9x15), R (9x9), zeros outside the m rows;
// se23_imu_noise_t = gyro_noise, accel_noise, gyro_walk, accel_walk.
#include "gen_common.hpp"
#include "ref_nav.hpp"

namespace gen {
namespace {

using Mat15L = Eigen::Matrix<LD, 15, 15>;
using Mat96L = Eigen::Matrix<LD, 9, 6>;
using VecN = Eigen::Matrix<LD, Eigen::Dynamic, 1>;
const int kRk4Steps = 128;

Mat9L fmat(LD dt)
{
    Mat9L F = Mat9L::Identity();
    F.block<3, 3>(6, 3) = dt * Mat3L::Identity();
    return F;
}
Mat9L fk(const Mat5L &U, LD dt) { return adjoint_inv(U) * fmat(dt); }

Mat5L aug(const Vec3L &w, const Vec3L &f, LD dt)
{
    Mat5L A = Mat5L::Zero();
    A.block<3, 3>(0, 0) = hat3(w);
    A.block<3, 1>(0, 3) = f;
    A(3, 4) = 1;
    return dt * A;
}
// B_k of the exact increment (columns: gyro, accel).
Mat96L input_jac_exact(const Vec3L &w, const Vec3L &f, LD dt)
{
    const Mat5L A = aug(w, f, dt);
    const Mat5L U = upsilon_expm(w, f, dt);
    const Mat5L Uinv = U.inverse();
    Mat96L B;
    for (int j = 0; j < 6; ++j) {
        Vec3L dw = Vec3L::Zero(), df = Vec3L::Zero();
        (j < 3 ? dw(j) : df(j - 3)) = 1;
        Mat5L dA = aug(dw, df, dt);
        dA(3, 4) = 0;
        MatXL Z = MatXL::Zero(10, 10);
        Z.block(0, 0, 5, 5) = A;
        Z.block(5, 5, 5, 5) = A;
        Z.block(0, 5, 5, 5) = dA;
        const Mat5L L = expm(Z).block(0, 5, 5, 5);
        B.col(j) = se23_vee(Mat5L(Uinv * L));
    }
    return B;
}
Mat96L input_jac_basic(LD dt)
{
    Mat96L B = Mat96L::Zero();
    B.block<6, 6>(0, 0) = dt * Eigen::Matrix<LD, 6, 6>::Identity();
    return B;
}
Mat9L input_noise(const Mat96L &B, LD sg, LD sa, LD dt)
{
    Eigen::Matrix<LD, 6, 6> N = Eigen::Matrix<LD, 6, 6>::Zero();
    N.diagonal() << sg * sg / dt, sg * sg / dt, sg * sg / dt, sa * sa / dt, sa * sa / dt, sa * sa / dt;
    return B * N * B.transpose();
}

// A random symmetric positive definite n x n matrix (exactly symmetric, so
// that rounding keeps it symmetric), scale s.
MatXL spd(Ctx &c, int n, LD s)
{
    MatXL A(n, n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) A(i, j) = c.uniform(-1, 1);
    MatXL P = s * (A * A.transpose() / LD(n) + LD(0.1) * MatXL::Identity(n, n));
    return (P + P.transpose()) / 2;
}

// ---- gauss rows ---------------------------------------------------------------

struct Gauss {
    Mat5L T;
    Vec3L bg, ba;
    int n;
    Mat15L P; // zeros outside n x n
};
void put_gauss(Row &r, const Gauss &g)
{
    put_pose(r, g.T);
    put(r, g.bg);
    put(r, g.ba);
    put(r, LD(g.n));
    put(r, g.P);
}
Gauss read_gauss(Rd &rd)
{
    Gauss g;
    g.T = rd.pose();
    g.bg = rd.v3();
    g.ba = rd.v3();
    g.n = int(rd.s());
    for (int i = 0; i < 15; ++i)
        for (int j = 0; j < 15; ++j) g.P(i, j) = rd.s();
    return g;
}
Gauss gauss_any(Ctx &c, int k)
{
    Gauss g;
    g.T = pose_k(c, k + n_angles());
    g.bg = vec3_any(c, 1e-2L);
    g.ba = vec3_any(c, 0.1L);
    g.n = (k % 2) ? 9 : 15;
    g.P = Mat15L::Zero();
    g.P.block(0, 0, g.n, g.n) = spd(c, g.n, 1e-2L);
    return g;
}
void put_noise(Row &r, LD sg, LD sa, LD qg, LD qa)
{
    put(r, sg);
    put(r, sa);
    put(r, qg);
    put(r, qa);
}

// Covariance validity as documented in gauss.h (clear cases only).
int cov_status(const MatXL &P, const Ctx &c)
{
    if (!P.allFinite()) return SE23_ERR_NONFINITE;
    const LD tol = c.is_float ? 1e-5L : 1e-9L;
    const LD s = P.diagonal().cwiseAbs().maxCoeff();
    if ((P - P.transpose()).cwiseAbs().maxCoeff() > tol * s) return SE23_ERR_NOT_SYMMETRIC;
    Eigen::SelfAdjointEigenSolver<MatXL> es(P);
    return es.eigenvalues().minCoeff() < -tol * s ? int(SE23_ERR_NOT_PSD) : int(SE23_OK);
}
int gauss_status(const Gauss &g, const Ctx &c)
{
    if (g.n != 9 && g.n != 15) return SE23_ERR_DIM;
    Row all;
    put_pose(all, g.T);
    put(all, g.bg);
    put(all, g.ba);
    if (!all_finite(all)) return SE23_ERR_NONFINITE;
    if (!is_rotation(g.T.block<3, 3>(0, 0), c)) return SE23_ERR_NOT_ROTATION;
    return cov_status(g.P.block(0, 0, g.n, g.n), c);
}
// What a step checks of the state it is handed (types.h, "Validation
// policy"): only n; the rest is trusted.
const int kStateEdges = 1;
int state_status(const Gauss &g)
{
    return (g.n != 9 && g.n != 15) ? int(SE23_ERR_DIM) : int(SE23_OK);
}
// Edge rows of a gauss input: n = 12, NaN in a bias, R not a rotation,
// P not symmetric, P not PSD; of a state a step is handed: n = 12.
const int kGaussEdges = 5;
void break_gauss(Gauss &g, int k)
{
    if (k == 0) g.n = 12;
    if (k == 1) g.bg(1) = kNaN;
    if (k == 2) g.T.block<3, 3>(0, 0) *= LD(1.01);
    if (k == 3) g.P(0, 1) += LD(0.1) * g.P(0, 0);
    if (k == 4) g.P(2, 2) = -g.P(2, 2);
}
void break_state(Gauss &g, int k)
{
    if (k == 0) g.n = 12;
}
// P+ of one sample: Phi P Phi^T + diag(B N B^T, walk), n = 9 or 15.
Mat15L propagate_cov(const Gauss &g, const Mat5L &U, const Mat96L &B, const LD nz[4], LD dt)
{
    MatXL Phi = MatXL::Identity(g.n, g.n);
    Phi.block(0, 0, 9, 9) = fk(U, dt);
    MatXL Qd = MatXL::Zero(g.n, g.n);
    Qd.block(0, 0, 9, 9) = input_noise(B, nz[0], nz[1], dt);
    if (g.n == 15) {
        Phi.block(0, 9, 9, 6) = B;
        for (int i = 0; i < 3; ++i) {
            Qd(9 + i, 9 + i) = nz[2] * nz[2] * dt;
            Qd(12 + i, 12 + i) = nz[3] * nz[3] * dt;
        }
    }
    Mat15L P = Mat15L::Zero();
    P.block(0, 0, g.n, g.n) = Phi * g.P.block(0, 0, g.n, g.n) * Phi.transpose() + Qd;
    return P;
}
// M of the carried -> user error conversion (sign -1: user -> carried).
Mat15L carried_m(const Mat5L &T, const Vec3L &Om, LD sign)
{
    Mat15L M = Mat15L::Identity();
    const Mat3L R = T.block<3, 3>(0, 0);
    M.block<3, 3>(3, 6) = -sign * hat3(Vec3L(R.transpose() * Om));
    return M;
}
void put_model(Ctx &c, Row &r, Vec3L &g, Vec3L &Om, LD dt)
{
    g = Vec3L(0, 0, 9.81L) + vec3_any(c, 0.05L);
    Om = c.axis() * (c.uniform(0, 1) < 0.5 ? LD(SE23_WGS84_OMEGA_E) : LD(0.05));
    put(r, g);
    put(r, Om);
    put(r, dt);
    put(r, LD(0.02));
    put_pose(r, gamma_expm(g, Om, dt));
}

} // namespace

// Shared with gen_preint_unc.cpp.
Eigen::Matrix<LD, 9, 6> gen_input_jac(int kind, const Vec3L &w, const Vec3L &f, LD dt)
{
    return kind == 0 ? input_jac_exact(w, f, dt) : input_jac_basic(dt);
}
Mat9L gen_fk(const Mat5L &U, LD dt) { return fk(U, dt); }
int gen_cov_status(const MatXL &P, const Ctx &c) { return cov_status(P, c); }

void add_gauss(Gens &g)
{
    const auto u_any = [](Ctx &c, LD &dt) {
        dt = c.uniform(1e-3L, 0.02L);
        return upsilon_expm(vec3_any(c, 2), vec3_any(c, 20), dt);
    };
    const auto fk_in = [u_any](Ctx &c, int, Row &r) {
        LD dt;
        put_pose(r, u_any(c, dt));
        put(r, dt);
    };
    g["se23_gauss_fk_apply"] = {0,
                                [fk_in](Ctx &c, int k) {
                                    Row r;
                                    fk_in(c, k, r);
                                    for (int i = 0; i < 9; ++i) r.push_back(c.uniform(-5, 5));
                                    return r;
                                },
                                [](const Ctx &, const Row &in, Row &out) {
                                    Rd rd{in};
                                    const Mat5L U = rd.pose();
                                    const LD dt = rd.s();
                                    put(out, Vec9L(fk(U, dt) * rd.v9()));
                                    return int(SE23_OK);
                                }};
    g["se23_gauss_fk"] = {0,
                          [fk_in](Ctx &c, int k) {
                              Row r;
                              fk_in(c, k, r);
                              return r;
                          },
                          [](const Ctx &, const Row &in, Row &out) {
                              Rd rd{in};
                              const Mat5L U = rd.pose();
                              put(out, fk(U, rd.s()));
                              return int(SE23_OK);
                          }};
    g["se23_gauss_fk_mul"] = {0,
                              [fk_in](Ctx &c, int k) {
                                  Row r;
                                  fk_in(c, k, r);
                                  for (int i = 0; i < 54; ++i) r.push_back(c.uniform(-1, 1));
                                  return r;
                              },
                              [](const Ctx &, const Row &in, Row &out) {
                                  Rd rd{in};
                                  const Mat5L U = rd.pose();
                                  const LD dt = rd.s();
                                  Mat96L X;
                                  for (int i = 0; i < 9; ++i)
                                      for (int j = 0; j < 6; ++j) X(i, j) = rd.s();
                                  put(out, Mat96L(fk(U, dt) * X));
                                  return int(SE23_OK);
                              }};
    g["se23_gauss_input_jac"] = {
        6,
        [](Ctx &c, int k) {
            // edges: basic kind, w = 0, unknown kind 2, dt = 0, dt > max, NaN;
            // then exact and basic alternating
            Row r;
            put(r, LD(k == 0 || (k > 6 && k % 4 == 0) ? 1 : k == 2 ? 2 : 0));
            put(r, k == 1 ? Vec3L(Vec3L::Zero()) : vec3_any(c, 2));
            Vec3L f = vec3_any(c, 20);
            if (k == 5) f(2) = kNaN;
            put(r, f);
            put(r, k == 3 ? LD(0) : k == 4 ? LD(SE23_CFG_DT_MAX) * 2 : c.uniform(1e-3L, 0.02L));
            return r;
        },
        [](const Ctx &, const Row &in, Row &out) {
            if (!all_finite(in)) return int(SE23_ERR_NONFINITE);
            Rd rd{in};
            const LD kind = rd.s();
            const Vec3L w = rd.v3(), f = rd.v3();
            const LD dt = rd.s();
            if (!(dt > 0 && dt <= LD(SE23_CFG_DT_MAX))) return int(SE23_ERR_DT);
            if (kind != 0 && kind != 1) return int(SE23_ERR_DOMAIN);
            put(out, kind == 0 ? input_jac_exact(w, f, dt) : input_jac_basic(dt));
            return int(SE23_OK);
        }};
    g["se23_gauss_input_noise"] = {
        4,
        [](Ctx &c, int k) {
            // edges: negative density, dt = 0, NaN, zero densities
            LD dt = c.uniform(1e-3L, 0.02L);
            Row r;
            put(r, input_jac_exact(vec3_any(c, 2), vec3_any(c, 20), dt));
            put_noise(r, k == 0 ? LD(-1e-3) : k == 3 ? LD(0) : c.uniform(1e-4L, 1e-2L),
                      k == 2 ? kNaN : k == 3 ? LD(0) : c.uniform(1e-3L, 1e-1L), 1e-5L, 1e-4L);
            put(r, k == 1 ? LD(0) : dt);
            return r;
        },
        [](const Ctx &, const Row &in, Row &out) {
            if (!all_finite(in)) return int(SE23_ERR_NONFINITE);
            Rd rd{in};
            Mat96L B;
            for (int i = 0; i < 9; ++i)
                for (int j = 0; j < 6; ++j) B(i, j) = rd.s();
            const LD sg = rd.s(), sa = rd.s();
            rd.s();
            rd.s();
            const LD dt = rd.s();
            if (!(dt > 0 && dt <= LD(SE23_CFG_DT_MAX))) return int(SE23_ERR_DT);
            if (sg < 0 || sa < 0) return int(SE23_ERR_DOMAIN);
            put(out, input_noise(B, sg, sa, dt));
            return int(SE23_OK);
        }};
    g["se23_gauss_cov_propagate"] = {
        6,
        [u_any](Ctx &c, int k) {
            // edges: NaN in S, S not symmetric, S not PSD, Q not PSD, U.R not
            // a rotation, dt = 0
            LD dt;
            Mat5L U = u_any(c, dt);
            MatXL S = spd(c, 9, 1e-2L);
            MatXL Q = input_noise(input_jac_exact(vec3_any(c, 2), vec3_any(c, 20), dt), 1e-3L, 1e-2L, dt);
            if (k == 0) S(4, 4) = kNaN;
            if (k == 1) S(1, 0) += LD(0.1) * S(0, 0);
            if (k == 2) S(5, 5) = -S(5, 5);
            if (k == 3) Q(0, 0) = -LD(0.5) * Q.diagonal().maxCoeff();
            if (k == 4) U.block<3, 3>(0, 0) *= LD(1.01);
            Row r;
            put(r, S);
            put_pose(r, U);
            put(r, k == 5 ? LD(0) : dt);
            put(r, Q);
            return r;
        },
        [](const Ctx &c, const Row &in, Row &out) {
            if (!all_finite(in)) return int(SE23_ERR_NONFINITE);
            Rd rd{in};
            MatXL S(9, 9), Q(9, 9);
            for (int i = 0; i < 81; ++i) S(i / 9, i % 9) = rd.s();
            const Mat5L U = rd.pose();
            const LD dt = rd.s();
            for (int i = 0; i < 81; ++i) Q(i / 9, i % 9) = rd.s();
            int st = cov_status(S, c);
            if (st == SE23_OK) st = cov_status(Q, c);
            if (st == SE23_OK && !is_rotation(U.block<3, 3>(0, 0), c)) st = SE23_ERR_NOT_ROTATION;
            if (st == SE23_OK && !(dt > 0 && dt <= LD(SE23_CFG_DT_MAX))) st = SE23_ERR_DT;
            if (st == SE23_OK) {
                const Mat9L F = fk(U, dt);
                put(out, Mat9L(F * S * F.transpose() + Q));
            }
            return st;
        }};
    g["se23_gauss_check"] = {kGaussEdges,
                             [](Ctx &c, int k) {
                                 Gauss x = gauss_any(c, k);
                                 break_gauss(x, k);
                                 Row r;
                                 put_gauss(r, x);
                                 return r;
                             },
                             [](const Ctx &c, const Row &in, Row &) {
                                 Rd rd{in};
                                 return gauss_status(read_gauss(rd), c);
                             }};
    g["se23_gauss_propagate"] = {
        kStateEdges + 2,
        [u_any](Ctx &c, int k) {
            // edges: n = 12, then dt = 0, a negative density
            Gauss x = gauss_any(c, k);
            break_state(x, k);
            LD dt;
            const Mat5L U = u_any(c, dt);
            Row r;
            put_gauss(r, x);
            put_pose(r, U);
            put(r, input_jac_exact(vec3_any(c, 2), vec3_any(c, 20), dt));
            put_noise(r, k == kStateEdges + 1 ? LD(-1e-3) : LD(1e-3), 1e-2L, 1e-5L, 1e-4L);
            put(r, k == kStateEdges ? LD(0) : dt);
            return r;
        },
        [](const Ctx &, const Row &in, Row &out) {
            Rd rd{in};
            Gauss x = read_gauss(rd);
            int st = state_status(x);
            const Mat5L U = rd.pose();
            Mat96L B;
            for (int i = 0; i < 9; ++i)
                for (int j = 0; j < 6; ++j) B(i, j) = rd.s();
            const LD nz[4] = {rd.s(), rd.s(), rd.s(), rd.s()};
            const LD dt = rd.s();
            if (st == SE23_OK && !(dt > 0 && dt <= LD(SE23_CFG_DT_MAX))) st = SE23_ERR_DT;
            if (st == SE23_OK && (nz[0] < 0 || nz[1] < 0 || nz[2] < 0 || nz[3] < 0)) st = SE23_ERR_DOMAIN;
            if (st != SE23_OK) return st;
            x.P = propagate_cov(x, U, B, nz, dt);
            put_gauss(out, x);
            return int(SE23_OK);
        }};
    g["se23_gauss_predict"] = {
        kStateEdges + 1,
        [](Ctx &c, int k) {
            // edges: n = 12, then a sample with dt = 0; kinds alternate
            Row r;
            Vec3L gv, Om;
            const LD dt = c.uniform(1e-3L, 0.02L);
            put_model(c, r, gv, Om, dt);
            Gauss x = gauss_any(c, k);
            break_state(x, k);
            put_gauss(r, x);
            put(r, vec3_any(c, 2));
            put(r, vec3_any(c, 20));
            put(r, k == kStateEdges ? LD(0) : dt);
            put_noise(r, 1e-3L, 1e-2L, 1e-5L, 1e-4L);
            put(r, LD(k % 3 == 2 ? 1 : 0));
            return r;
        },
        [](const Ctx &, const Row &in, Row &out) {
            Rd rd{in};
            const Vec3L gv = rd.v3(), Om = rd.v3();
            rd.s();
            const LD dt_max = rd.s();
            rd.pose();
            Gauss x = read_gauss(rd);
            const Vec3L w = Vec3L(rd.v3() + x.bg), f = Vec3L(rd.v3() + x.ba);
            const LD dt = rd.s();
            const LD nz[4] = {rd.s(), rd.s(), rd.s(), rd.s()};
            const LD kind = rd.s();
            int st = state_status(x);
            if (st == SE23_OK && !(dt > 0 && dt <= dt_max)) st = SE23_ERR_DT;
            if (st != SE23_OK) return st;
            const Mat5L user = carried_pose(x.T, Om, -1);
            const Mat5L next = nav_rk4(user, w, f, gv, Om, dt, kRk4Steps);
            const Mat5L U = upsilon_expm(w, f, dt);
            x.P = propagate_cov(x, U, kind == 0 ? input_jac_exact(w, f, dt) : input_jac_basic(dt), nz, dt);
            x.T = carried_pose(next, Om, 1);
            put_gauss(out, x);
            return int(SE23_OK);
        }};
    const auto conv = [](LD sign) {
        return Gen{kStateEdges,
                   [](Ctx &c, int k) {
                       Row r;
                       Vec3L gv, Om;
                       put_model(c, r, gv, Om, 0.005L);
                       Gauss x = gauss_any(c, k);
                       break_state(x, k);
                       put_gauss(r, x);
                       return r;
                   },
                   [sign](const Ctx &, const Row &in, Row &out) {
                       Rd rd{in};
                       rd.v3();
                       const Vec3L Om = rd.v3();
                       rd.s();
                       rd.s();
                       rd.pose();
                       Gauss x = read_gauss(rd);
                       const int st = state_status(x);
                       if (st != SE23_OK) return st;
                       const Mat15L M = carried_m(x.T, Om, sign);
                       Mat15L P = Mat15L::Zero();
                       P.block(0, 0, x.n, x.n) =
                           (M * x.P * M.transpose()).block(0, 0, x.n, x.n);
                       x.P = P;
                       x.T = carried_pose(x.T, Om, -sign);
                       put_gauss(out, x);
                       return int(SE23_OK);
                   }};
    };
    g["se23_gauss_from_carried"] = conv(1);
    g["se23_gauss_to_carried"] = conv(-1);
    g["se23_gauss_fk_apply"].scale = scale_tangent();
    g["se23_gauss_fk"].scale = scale_mat_blocks(9, 9, 3);
    g["se23_gauss_fk_mul"].scale = scale_mat_blocks(9, 6, 3);
    g["se23_gauss_input_jac"].scale = scale_mat_blocks(9, 6, 3);
    g["se23_gauss_input_noise"].scale = scale_cov(9);
    g["se23_gauss_cov_propagate"].scale = scale_cov(9);
    const Scale gauss_t = scale_concat({{15, scale_pose()},
                                        {3, scale_blocks({3})},
                                        {3, scale_blocks({3})},
                                        {1, scale_blocks({1})},
                                        {225, scale_cov(15)}});
    for (const char *n : {"se23_gauss_propagate", "se23_gauss_predict", "se23_gauss_from_carried",
                          "se23_gauss_to_carried"}) {
        g[n].scale = gauss_t;
    }
}

namespace {

using Mat915L = Eigen::Matrix<LD, 9, 15>;
using Mat99L = Eigen::Matrix<LD, 9, 9>;

struct Meas {
    int m;
    Vec9L z;
    Mat915L H;
    Mat99L R;
};
void put_meas(Row &r, const Meas &y)
{
    put(r, LD(y.m));
    put(r, y.z);
    put(r, y.H);
    put(r, y.R);
}
Meas read_meas(Rd &rd)
{
    Meas y;
    y.m = int(rd.s());
    y.z = rd.v9();
    for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 15; ++j) y.H(i, j) = rd.s();
    for (int i = 0; i < 9; ++i)
        for (int j = 0; j < 9; ++j) y.R(i, j) = rd.s();
    return y;
}
Meas meas3(const Vec3L &z, const Eigen::Matrix<LD, 3, 15> &H, const Mat3L &R)
{
    Meas y;
    y.m = 3;
    y.z = Vec9L::Zero();
    y.z.head<3>() = z;
    y.H = Mat915L::Zero();
    y.H.block<3, 15>(0, 0) = H;
    y.R = Mat99L::Zero();
    y.R.block<3, 3>(0, 0) = R;
    return y;
}
Scale scale_meas()
{
    return scale_concat({{1, scale_blocks({1})},
                         {9, scale_blocks({9})},
                         {135, scale_mat_blocks(9, 15, 3)},
                         {81, scale_cov(9)}});
}

// Inputs of a measurement model: T, the measured vector (+ lever arm), cov.
// Edges: NaN, T.R not a rotation, cov not symmetric, cov not PSD.
Row meas_model_input(Ctx &c, int k, bool lever)
{
    Mat5L T = pose_k(c, k + n_angles());
    Mat3L cov = Mat3L(spd(c, 3, 1.0L));
    Vec3L x = vec3_any(c, 20);
    if (k == 0) x(1) = kNaN;
    if (k == 1) T.block<3, 3>(0, 0) *= LD(1.01);
    if (k == 2) cov(0, 2) += LD(0.1) * cov(0, 0);
    if (k == 3) cov(1, 1) = -cov(1, 1);
    Row r;
    put_pose(r, T);
    put(r, x);
    if (lever) put(r, vec3_any(c, 1));
    put(r, cov);
    return r;
}
int meas_model_status(const Ctx &c, const Row &in, const Mat5L &T, const Mat3L &cov)
{
    if (!all_finite(in)) return SE23_ERR_NONFINITE;
    if (!is_rotation(T.block<3, 3>(0, 0), c)) return SE23_ERR_NOT_ROTATION;
    return cov_status(cov, c);
}

using Mat315L = Eigen::Matrix<LD, 3, 15>;
const LD kInf = std::numeric_limits<LD>::infinity();

// Largest finite value of the target's precision.
LD real_max(const Ctx &c)
{
    return c.is_float ? LD(std::numeric_limits<float>::max()) : LD(std::numeric_limits<double>::max());
}
// A residual or Jacobian entry the precision cannot hold: the models refuse
// it (SE23_ERR_NONFINITE, kalman.h).
bool overflows(const Ctx &c, const Vec3L &z, const Mat315L &H)
{
    return !(z.cwiseAbs().maxCoeff() <= real_max(c) && H.cwiseAbs().maxCoeff() <= real_max(c));
}

// Inputs of se23_meas_vel_nav_lever: T, w_b, lever_b, v_n, cov. Edges: NaN
// in v_n, T.R not a rotation, cov not symmetric, cov not PSD, Inf in w_b,
// |w_b x lever_b| beyond the precision's range (finite inputs).
Row meas_lever_input(Ctx &c, int k)
{
    Mat5L T = pose_k(c, k + n_angles());
    Mat3L cov = Mat3L(spd(c, 3, 1.0L));
    Vec3L w = vec3_any(c, 2), l = vec3_any(c, 2);
    Vec3L v = vec3_any(c, 20);
    if (k == 0) v(1) = kNaN;
    if (k == 1) T.block<3, 3>(0, 0) *= LD(1.01);
    if (k == 2) cov(0, 2) += LD(0.1) * cov(0, 0);
    if (k == 3) cov(1, 1) = -cov(1, 1);
    if (k == 4) w(2) = kInf;
    if (k == 5) {
        const LD big = c.is_float ? LD(1e30L) : LD(1e200L);
        w = Vec3L(big, 0, 0);
        l = Vec3L(0, big, 0);
    }
    Row r;
    put_pose(r, T);
    put(r, w);
    put(r, l);
    put(r, v);
    put(r, cov);
    return r;
}

// Inputs of se23_meas_zero_rate: w_meas, b_g, cov. Edges: NaN in w_meas, Inf
// in b_g, cov not symmetric, cov not PSD, w_meas + b_g beyond the range.
Row meas_rate_input(Ctx &c, int k)
{
    Mat3L cov = Mat3L(spd(c, 3, 1e-6L));
    Vec3L w = vec3_any(c, 0.05L), b = vec3_any(c, 0.05L);
    if (k == 0) w(0) = kNaN;
    if (k == 1) b(2) = -kInf;
    if (k == 2) cov(0, 2) += LD(0.1) * cov(0, 0);
    if (k == 3) cov(1, 1) = -cov(1, 1);
    if (k == 4) {
        w(1) = LD(0.75) * real_max(c);
        b(1) = w(1);
    }
    Row r;
    put(r, w);
    put(r, b);
    put(r, cov);
    return r;
}

// Inputs of se23_meas_nhc: T, C_bv, sigma. Edges: NaN in T.v, T.R not a
// rotation, C_bv not a rotation, sigma 0, sigma NaN, sigma above
// SE23_MEAS_NHC_SIGMA_MAX, a residual beyond the precision's range (finite
// inputs: v along the vehicle's right axis, |v| > max), sigma at its
// largest. C_bv through the edge angles first.
Row meas_nhc_input(Ctx &c, int k)
{
    Mat5L T = pose_k(c, k + n_angles());
    Mat3L C = rot_k(c, k);
    LD sigma = c.uniform(0.01L, 2);
    if (k == 0) T(1, 3) = kNaN;
    if (k == 1) T.block<3, 3>(0, 0) *= LD(1.01);
    if (k == 2) C *= LD(1.01);
    if (k == 3) sigma = 0;
    if (k == 4) sigma = kNaN;
    if (k == 5) sigma = LD(1000.5);
    if (k == 6) {
        const LD big = LD(0.9L) * real_max(c);
        T.block<3, 3>(0, 0) = Mat3L::Identity();
        T.block<3, 1>(0, 3) = Vec3L(big, big, 0);
        C = so3_exp(Vec3L(0, 0, -kPi / 4)); // right axis (sin 45, cos 45, 0)
    }
    if (k == 7) sigma = 1000;
    Row r;
    put_pose(r, T);
    put(r, C);
    put(r, sigma);
    return r;
}

} // namespace

void add_kalman(Gens &g)
{
    g["se23_meas_pos_nav"] = {4, [](Ctx &c, int k) { return meas_model_input(c, k, true); },
                              [](const Ctx &c, const Row &in, Row &out) {
                                  Rd rd{in};
                                  const Mat5L T = rd.pose();
                                  const Vec3L p_n = rd.v3(), l = rd.v3();
                                  const Mat3L cov = rd.m3();
                                  const int st = meas_model_status(c, in, T, cov);
                                  if (st != SE23_OK) return st;
                                  const Mat3L R = T.block<3, 3>(0, 0);
                                  Eigen::Matrix<LD, 3, 15> H = Eigen::Matrix<LD, 3, 15>::Zero();
                                  H.block<3, 3>(0, 0) = -R * hat3(l);
                                  H.block<3, 3>(0, 6) = R;
                                  const Vec3L h = Vec3L(T.block<3, 1>(0, 4)) + R * l;
                                  put_meas(out, meas3(Vec3L(p_n - h), H, cov));
                                  return int(SE23_OK);
                              }};
    g["se23_meas_vel_nav"] = {4, [](Ctx &c, int k) { return meas_model_input(c, k, false); },
                              [](const Ctx &c, const Row &in, Row &out) {
                                  Rd rd{in};
                                  const Mat5L T = rd.pose();
                                  const Vec3L v_n = rd.v3();
                                  const Mat3L cov = rd.m3();
                                  const int st = meas_model_status(c, in, T, cov);
                                  if (st != SE23_OK) return st;
                                  Eigen::Matrix<LD, 3, 15> H = Eigen::Matrix<LD, 3, 15>::Zero();
                                  H.block<3, 3>(0, 3) = T.block<3, 3>(0, 0);
                                  put_meas(out, meas3(Vec3L(v_n - Vec3L(T.block<3, 1>(0, 3))), H, cov));
                                  return int(SE23_OK);
                              }};
    g["se23_meas_vel_body"] = {4, [](Ctx &c, int k) { return meas_model_input(c, k, false); },
                               [](const Ctx &c, const Row &in, Row &out) {
                                   Rd rd{in};
                                   const Mat5L T = rd.pose();
                                   const Vec3L v_b = rd.v3();
                                   const Mat3L cov = rd.m3();
                                   const int st = meas_model_status(c, in, T, cov);
                                   if (st != SE23_OK) return st;
                                   const Mat3L R = T.block<3, 3>(0, 0);
                                   const Vec3L h = R.transpose() * Vec3L(T.block<3, 1>(0, 3));
                                   Eigen::Matrix<LD, 3, 15> H = Eigen::Matrix<LD, 3, 15>::Zero();
                                   H.block<3, 3>(0, 0) = hat3(h);
                                   H.block<3, 3>(0, 3) = Mat3L::Identity();
                                   put_meas(out, meas3(Vec3L(v_b - h), H, cov));
                                   return int(SE23_OK);
                               }};
    // h = v + R (w x l), w = w_b + db_g; to first order in (phi, nu, db_g)
    // with R = Rbar exp(phi^), v = vbar + Rbar nu: Rbar phi^ u = -Rbar u^ phi
    // (u = w_b x l), Rbar (db_g x l) = -Rbar l^ db_g.
    g["se23_meas_vel_nav_lever"] = {6, meas_lever_input, [](const Ctx &c, const Row &in, Row &out) {
                                        Rd rd{in};
                                        const Mat5L T = rd.pose();
                                        const Vec3L w = rd.v3(), l = rd.v3(), v_n = rd.v3();
                                        const Mat3L cov = rd.m3();
                                        const int st = meas_model_status(c, in, T, cov);
                                        if (st != SE23_OK) return st;
                                        const Mat3L R = T.block<3, 3>(0, 0);
                                        const Vec3L u = w.cross(l);
                                        const Vec3L h = Vec3L(T.block<3, 1>(0, 3)) + R * u;
                                        Mat315L H = Mat315L::Zero();
                                        H.block<3, 3>(0, 0) = -R * hat3(u);
                                        H.block<3, 3>(0, 3) = R;
                                        H.block<3, 3>(0, 9) = -R * hat3(l);
                                        const Vec3L z = v_n - h;
                                        if (overflows(c, z, H)) return int(SE23_ERR_NONFINITE);
                                        put_meas(out, meas3(z, H, cov));
                                        return int(SE23_OK);
                                    }};
    // y = 0 (true rate at rest), h = w_meas + b_g, H = [0, 0, 0, I, 0].
    g["se23_meas_zero_rate"] = {5, meas_rate_input, [](const Ctx &c, const Row &in, Row &out) {
                                    Rd rd{in};
                                    const Vec3L w = rd.v3(), b = rd.v3();
                                    const Mat3L cov = rd.m3();
                                    if (!all_finite(in)) return int(SE23_ERR_NONFINITE);
                                    const int st = cov_status(cov, c);
                                    if (st != SE23_OK) return st;
                                    Mat315L H = Mat315L::Zero();
                                    H.block<3, 3>(0, 9) = Mat3L::Identity();
                                    const Vec3L z = -(w + b);
                                    if (overflows(c, z, H)) return int(SE23_ERR_NONFINITE);
                                    put_meas(out, meas3(z, H, cov));
                                    return int(SE23_OK);
                                }};
    // h_r = c_r . u, u = R^T v, c_r the columns 1 and 2 of C_bv (right,
    // down); with R = Rbar exp(phi^), v = vbar + Rbar nu: u + u^ phi + nu to
    // first order, so H_r = [(c_r x u)^T, c_r^T, 0, 0, 0], z_r = 0 - h_r.
    g["se23_meas_nhc"] = {8, meas_nhc_input, [](const Ctx &c, const Row &in, Row &out) {
                              Rd rd{in};
                              const Mat5L T = rd.pose();
                              const Mat3L C = rd.m3();
                              const LD sigma = rd.s();
                              Row pose;
                              put_pose(pose, T);
                              if (!all_finite(pose)) return int(SE23_ERR_NONFINITE);
                              if (!is_rotation(T.block<3, 3>(0, 0), c)) return int(SE23_ERR_NOT_ROTATION);
                              if (!is_rotation(C, c)) return int(SE23_ERR_NOT_ROTATION);
                              if (!(sigma > 0 && sigma <= 1000)) return int(SE23_ERR_DOMAIN);
                              const Vec3L u = T.block<3, 3>(0, 0).transpose() * Vec3L(T.block<3, 1>(0, 3));
                              Vec3L z = Vec3L::Zero();
                              Mat315L H = Mat315L::Zero();
                              for (int r = 0; r < 2; ++r) {
                                  const Vec3L cr = C.col(r + 1);
                                  z(r) = -cr.dot(u);
                                  H.block<1, 3>(r, 0) = cr.cross(u).transpose();
                                  H.block<1, 3>(r, 3) = cr.transpose();
                              }
                              if (overflows(c, z, H)) return int(SE23_ERR_NONFINITE);
                              put(out, LD(2));
                              put(out, z(0));
                              put(out, z(1));
                              put(out, Eigen::Matrix<LD, 2, 15>(H.topRows<2>()));
                              for (const LD x : {sigma * sigma, LD(0), LD(0), sigma * sigma}) put(out, x);
                              return int(SE23_OK);
                          }};
    g["se23_kalman_update"] = {
        kGaussEdges + 4,
        [](Ctx &c, int k) {
            // edges (the state is trusted, types.h: only n and an overflowing
            // mean are refused): n = 12, NaN in a bias, NaN in H, R not
            // symmetric, P = 0 with a denormal R (D3: S below the pivot
            // floor), then m = 0, m = 10, NaN in z, R not PSD
            Gauss x = gauss_any(c, k);
            if (k <= 1) break_gauss(x, k);
            Meas y;
            y.m = 1 + int(c.uniform(0, 9));
            y.z = Vec9L::Zero();
            y.H = Mat915L::Zero();
            y.R = Mat99L::Zero();
            for (int i = 0; i < y.m; ++i) {
                y.z(i) = c.uniform(-0.3L, 0.3L);
                for (int j = 0; j < x.n; ++j) y.H(i, j) = c.uniform(-1, 1);
            }
            y.R.block(0, 0, y.m, y.m) = spd(c, y.m, 1e-2L);
            if (k == 2) y.H(0, 4) = kNaN;
            if (k == 3) y.R(0, y.m - 1) += LD(0.1) * y.R(0, 0) + LD(1e-3);
            if (k == 4) {
                x.P = Mat15L::Zero();
                y.R = Mat99L::Zero();
                for (int i = 0; i < y.m; ++i) y.R(i, i) = c.is_float ? LD(1e-40) : LD(1e-310);
            }
            if (k == kGaussEdges) y.m = 0;
            if (k == kGaussEdges + 1) y.m = 10;
            if (k == kGaussEdges + 2) y.z(0) = kNaN;
            if (k == kGaussEdges + 3) y.R(0, 0) = -y.R(0, 0);
            Row r;
            put_gauss(r, x);
            put_meas(r, y);
            return r;
        },
        [](const Ctx &c, const Row &in, Row &out) {
            Rd rd{in};
            Gauss x = read_gauss(rd);
            const Meas y = read_meas(rd);
            // The state is trusted (kalman.h): only n is checked, and a
            // mean that a correction could overflow (here: NaN) refused.
            if (x.n != 9 && x.n != 15) return int(SE23_ERR_DIM);
            if (y.m < 1 || y.m > 9) return int(SE23_ERR_DIM);
            const int n = x.n, m = y.m;
            const MatXL H = y.H.block(0, 0, m, n), R = y.R.block(0, 0, m, m);
            const VecN z = y.z.head(m);
            if (!H.allFinite() || !z.allFinite() || !R.allFinite()) return int(SE23_ERR_NONFINITE);
            int st = cov_status(R, c);
            if (st != SE23_OK) return st;
            Row mean;
            put_pose(mean, x.T);
            put(mean, x.bg);
            put(mean, x.ba);
            if (!all_finite(mean)) return int(SE23_ERR_NONFINITE);
            const MatXL P = x.P.block(0, 0, n, n);
            const MatXL S = H * P * H.transpose() + R;
            // S must be positive definite with pivots above the smallest
            // normal number (kalman.h); the clear case of the edge above.
            const LD smallest = c.is_float ? LD(1.17549435e-38L) : LD(2.2250738585072014e-308L);
            if (Eigen::SelfAdjointEigenSolver<MatXL>(S).eigenvalues().minCoeff() < smallest)
                return int(SE23_ERR_NOT_PSD);
            const MatXL K = P * H.transpose() * S.inverse();
            const VecN dx = K * z;
            const MatXL IKH = MatXL::Identity(n, n) - K * H;
            Mat15L Pn = Mat15L::Zero();
            Pn.block(0, 0, n, n) = IKH * P * IKH.transpose() + K * R * K.transpose();
            x.P = Pn;
            x.T = Mat5L(x.T * se23_exp(Vec9L(dx.head(9))));
            if (n == 15) {
                x.bg += dx.segment(9, 3);
                x.ba += dx.segment(12, 3);
            }
            put_gauss(out, x);
            put(out, LD((z.transpose() * S.inverse() * z)(0, 0)));
            return int(SE23_OK);
        }};
    for (const char *n : {"se23_meas_pos_nav", "se23_meas_vel_nav", "se23_meas_vel_body",
                          "se23_meas_vel_nav_lever", "se23_meas_zero_rate"}) {
        g[n].scale = scale_meas();
    }
    // z and the rows' c_r x u are dot and cross products with u = R^T v:
    // their rounding is relative to |v|, whatever cancels (z is 0 for a car
    // that keeps to its constraint).
    // Row m, z (2), H (2 x 15, each 2 x 3 block scaled by its largest
    // entry), R (2 x 2).
    // a fixed function of a few inputs: 16 random rows spare the M7 image's flash
    g["se23_meas_nhc"].n_random = 16;
    g["se23_meas_nhc"].scale_io = [](const Row &in, const Row &out) {
        const LD v = std::sqrt(in[9] * in[9] + in[10] * in[10] + in[11] * in[11]);
        Row s = scale_concat({{1, scale_blocks({1})}, {2, scale_blocks({2})}, {30, scale_blocks({30})},
                              {4, scale_cov(2)}})(out);
        s[1] = s[2] = std::max(s[1], v);
        for (size_t b = 0; b < 5; ++b) {
            LD m = 0;
            for (size_t r = 0; r < 2; ++r)
                for (size_t j = 3 * b; j < 3 * b + 3; ++j) m = std::max(m, std::fabs(out[3 + 15 * r + j]));
            if (b == 0) m = std::max(m, v);
            for (size_t r = 0; r < 2; ++r)
                for (size_t j = 3 * b; j < 3 * b + 3; ++j) s[3 + 15 * r + j] = m;
        }
        return s;
    };
    const Scale update_out = scale_concat({{TV_GAUSS_REALS - 225, scale_concat({{15, scale_pose()},
                                                                               {3, scale_blocks({3})},
                                                                               {3, scale_blocks({3})},
                                                                               {1, scale_blocks({1})}})},
                                           {225, scale_cov(15)},
                                           {1, scale_blocks({1})}});
    // The mean's vectors are sums v+ = v + d: their rounding is relative to
    // the operands, |v| and |d| <= |v| + |v+|, not to |v+| alone (a bias
    // correction can cancel most of the bias). Each of the blocks v, p,
    // b_g, b_a (reals 9..20, the same place in the input row) is scaled by
    // the larger of its input and output magnitudes.
    g["se23_kalman_update"].scale_io = [update_out](const Row &in, const Row &out) {
        Row s = update_out(out);
        for (size_t at = 9; at < 21; at += 3) {
            const LD m = max_abs(in, at, 3);
            for (size_t i = at; i < at + 3; ++i) s[i] = std::max(s[i], m);
        }
        return s;
    };
}

} // namespace gen
