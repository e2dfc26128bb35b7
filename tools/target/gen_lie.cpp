// Target vectors of so3.h and se23.h: inputs at the edge angles and random,
// expected values from the Eigen reference (tests/reference/reference.hpp).
#include "gen_common.hpp"

namespace gen {
namespace {


// A status routine of one phi: edge angles, a NaN row, random angles.
Gen phi_gen(std::function<Mat3L(const Vec3L &)> f, LD max_angle = kPi)
{
    const int n = n_angles();
    return {n + 1,
            [n, max_angle](Ctx &c, int k) {
                Row r;
                put(r, k == n ? Vec3L(kNaN, 0, 0) : phi_k(c, k, max_angle));
                return r;
            },
            [f](const Ctx &, const Row &in, Row &out) {
                if (!all_finite(in)) return int(SE23_ERR_NONFINITE);
                Rd rd{in};
                put(out, f(rd.v3()));
                return int(SE23_OK);
            }};
}

// Rows of a rotation-matrix routine: rotations at the edge angles, then
// error rows (NaN, scaled by 1.01, a reflection), then random rotations.
Row rot_input(Ctx &c, int k)
{
    const int n = n_angles();
    Row r;
    if (k < n || k >= n + 3) {
        put(r, rot_k(c, k));
    } else if (k == n) {
        Mat3L R = rot_k(c, 4);
        R(1, 2) = kNaN;
        put(r, R);
    } else if (k == n + 1) {
        put(r, Mat3L(LD(1.01) * rot_k(c, 7)));
    } else {
        put(r, Mat3L(-rot_k(c, 6)));
    }
    return r;
}

// Status of a rotation routine's input, as documented in so3.h.
int rot_status(const Ctx &c, const Mat3L &R, const Row &in)
{
    if (!all_finite(in)) return SE23_ERR_NONFINITE;
    return is_rotation(R, c) ? SE23_OK : SE23_ERR_NOT_ROTATION;
}

// Rows of a pose routine: rot_input's rotation with random v, p.
Row pose_input(Ctx &c, int k)
{
    Row r = rot_input(c, k);
    put(r, vec3_any(c, 10));
    put(r, vec3_any(c, 10));
    return r;
}

// A check-free routine of one pose: k-th random pose in, out = f(pose).
Gen of_pose(std::function<void(Row &, const Mat5L &)> f)
{
    return {0,
            [](Ctx &c, int k) {
                Row r;
                put_pose(r, pose_k(c, k));
                return r;
            },
            [f](const Ctx &, const Row &in, Row &out) {
                Rd rd{in};
                f(out, rd.pose());
                return int(SE23_OK);
            }};
}

// A check-free routine of an arbitrary n x n matrix (entries in [-s, s]).
Gen of_matrix(int n, LD s, std::function<void(Row &, Rd &)> f)
{
    return {0,
            [n, s](Ctx &c, int) {
                Row r;
                for (int i = 0; i < n * n; ++i) r.push_back(c.uniform(-s, s));
                return r;
            },
            [f](const Ctx &, const Row &in, Row &out) {
                Rd rd{in};
                f(out, rd);
                return int(SE23_OK);
            }};
}

} // namespace

void add_lie(Gens &g)
{
    const int n = n_angles();
    // ---- so3.h
    g["se23_so3_hat"] = {0,
                         [](Ctx &c, int k) {
                             Row r;
                             put(r, phi_k(c, k));
                             return r;
                         },
                         [](const Ctx &, const Row &in, Row &out) {
                             Rd rd{in};
                             put(out, hat3(rd.v3()));
                             return int(SE23_OK);
                         }};
    g["se23_so3_vee"] = of_matrix(3, 2, [](Row &out, Rd &rd) { put(out, vee3(rd.m3())); });
    g["se23_so3_exp"] = phi_gen([](const Vec3L &p) { return so3_exp(p); });
    g["se23_so3_jl"] = phi_gen([](const Vec3L &p) { return jl(p); });
    g["se23_so3_jr"] = phi_gen([](const Vec3L &p) { return jr(p); });
    g["se23_so3_h"] = phi_gen([](const Vec3L &p) { return so3_h(p); });
    g["se23_so3_k"] = phi_gen([](const Vec3L &p) { return so3_k(p); });
    {
        // J_l^-1: domain |phi| < 2 pi - 1e-3; rows past it must be refused.
        Gen j = phi_gen([](const Vec3L &p) { return jl_inv(p); }, LD(2) * kPi - LD(0.5));
        const auto base_in = j.input;
        j.n_edge = n + 3;
        j.input = [base_in, n](Ctx &c, int k) {
            if (k == n + 1 || k == n + 2) {
                Row r;
                put(r, Vec3L(c.axis() * (k == n + 1 ? LD(2) * kPi : LD(7))));
                return r;
            }
            return base_in(c, k);
        };
        const auto base_ex = j.expect;
        j.expect = [base_ex](const Ctx &c, const Row &in, Row &out) {
            Rd rd{in};
            if (all_finite(in) && rd.v3().norm() >= LD(2) * kPi - LD(1e-3)) {
                return int(SE23_ERR_DOMAIN);
            }
            return base_ex(c, in, out);
        };
        g["se23_so3_jl_inv"] = j;
    }
    g["se23_so3_log"] = {n + 3, rot_input, [](const Ctx &c, const Row &in, Row &out) {
                             Rd rd{in};
                             const Mat3L R = rd.m3();
                             const int st = rot_status(c, R, in);
                             if (st == SE23_OK) put(out, so3_log(R));
                             return st;
                         }};
    g["se23_so3_check"] = {n + 3, rot_input, [](const Ctx &c, const Row &in, Row &) {
                               Rd rd{in};
                               return rot_status(c, rd.m3(), in);
                           }};
    g["se23_so3_normalize"] = {
        3,
        [](Ctx &c, int k) {
            // Rotations drifted by up to 1e-3 per entry; errors: NaN, a drift
            // of 0.3 (beyond the documented 0.1), a reflection.
            Mat3L R = rot_k(c, k + 1);
            Row r;
            if (k == 0) R(2, 0) = kNaN;
            if (k == 1) R *= LD(1.3);
            if (k == 2) R = -R;
            if (k >= 3) {
                for (int a = 0; a < 3; ++a)
                    for (int b = 0; b < 3; ++b) R(a, b) += c.uniform(-1e-3L, 1e-3L);
            }
            put(r, R);
            return r;
        },
        [](const Ctx &, const Row &in, Row &out) {
            if (!all_finite(in)) return int(SE23_ERR_NONFINITE);
            Rd rd{in};
            const Mat3L R = rd.m3();
            if ((R.transpose() * R - Mat3L::Identity()).cwiseAbs().maxCoeff() > LD(0.1) ||
                R.determinant() <= 0) {
                return int(SE23_ERR_NOT_ROTATION);
            }
            put(out, polar(R));
            return int(SE23_OK);
        }};
    // ---- se23.h
    g["se23_identity"] = {1, [](Ctx &, int) { return Row(); },
                          [](const Ctx &, const Row &, Row &out) {
                              put_pose(out, Mat5L::Identity());
                              return int(SE23_OK);
                          }};
    g["se23_compose"] = {0,
                         [](Ctx &c, int k) {
                             Row r;
                             put_pose(r, pose_k(c, k));
                             put_pose(r, pose_k(c, k + 3));
                             return r;
                         },
                         [](const Ctx &, const Row &in, Row &out) {
                             Rd rd{in};
                             const Mat5L A = rd.pose();
                             put_pose(out, compose(A, rd.pose()));
                             return int(SE23_OK);
                         }};
    g["se23_inverse"] = of_pose([](Row &out, const Mat5L &T) { put_pose(out, inverse(T)); });
    g["se23_act"] = {0,
                     [](Ctx &c, int k) {
                         Row r;
                         put_pose(r, pose_k(c, k));
                         put(r, vec3_any(c, 10));
                         return r;
                     },
                     [](const Ctx &, const Row &in, Row &out) {
                         Rd rd{in};
                         const Mat5L T = rd.pose();
                         put(out, act(T, rd.v3()));
                         return int(SE23_OK);
                     }};
    g["se23_hat"] = {0,
                     [](Ctx &c, int k) {
                         Row r;
                         put(r, phi_k(c, k));
                         put(r, vec3_any(c, 10));
                         put(r, vec3_any(c, 10));
                         return r;
                     },
                     [](const Ctx &, const Row &in, Row &out) {
                         Rd rd{in};
                         put(out, se23_hat(rd.v9()));
                         return int(SE23_OK);
                     }};
    g["se23_vee"] = of_matrix(5, 5, [](Row &out, Rd &rd) { put(out, se23_vee(rd.m5())); });
    g["se23_to_mat5"] = of_pose([](Row &out, const Mat5L &T) { put(out, T); });
    g["se23_from_mat5"] = {
        4,
        [](Ctx &c, int k) {
            // errors: NaN, R not a rotation, a wrong bottom row (0.01 off)
            Mat5L T = pose_k(c, k + 1);
            if (k == 0) T(0, 4) = kNaN;
            if (k == 1) T.block<3, 3>(0, 0) *= LD(1.01);
            if (k == 2) T(3, 3) += LD(0.01);
            if (k == 3) T(4, 0) = LD(0.01);
            Row r;
            put(r, T);
            return r;
        },
        [](const Ctx &c, const Row &in, Row &out) {
            if (!all_finite(in)) return int(SE23_ERR_NONFINITE);
            Rd rd{in};
            const Mat5L M = rd.m5();
            const int st = rot_status(c, M.block<3, 3>(0, 0), in);
            if (st != SE23_OK) return st;
            Mat5L B = Mat5L::Identity();
            if ((M.block<2, 5>(3, 0) - B.block<2, 5>(3, 0)).cwiseAbs().maxCoeff() > LD(1e-3)) {
                return int(SE23_ERR_DOMAIN);
            }
            put_pose(out, M);
            return int(SE23_OK);
        }};
    g["se23_exp"] = {n + 1,
                     [n](Ctx &c, int k) {
                         Row r;
                         put(r, k == n ? Vec3L(0, kNaN, 0) : phi_k(c, k));
                         put(r, vec3_any(c, 10));
                         put(r, vec3_any(c, 10));
                         return r;
                     },
                     [](const Ctx &, const Row &in, Row &out) {
                         if (!all_finite(in)) return int(SE23_ERR_NONFINITE);
                         Rd rd{in};
                         put_pose(out, se23_exp(rd.v9()));
                         return int(SE23_OK);
                     }};
    g["se23_log"] = {n + 3, pose_input, [](const Ctx &c, const Row &in, Row &out) {
                         Rd rd{in};
                         const Mat5L T = rd.pose();
                         const int st = rot_status(c, T.block<3, 3>(0, 0), in);
                         if (st == SE23_OK) put(out, se23_log(T));
                         return st;
                     }};
    g["se23_adjoint"] = of_pose([](Row &out, const Mat5L &T) { put(out, adjoint(T)); });
    g["se23_adjoint_inv"] = of_pose([](Row &out, const Mat5L &T) { put(out, adjoint_inv(T)); });
    g["se23_pose_check"] = {n + 3, pose_input, [](const Ctx &c, const Row &in, Row &) {
                                Rd rd{in};
                                return rot_status(c, rd.pose().block<3, 3>(0, 0), in);
                            }};
    for (const char *n : {"se23_identity", "se23_compose", "se23_inverse", "se23_exp", "se23_from_mat5"}) {
        g[n].scale = scale_pose();
    }
    // log: the rotation vector is as accurate as R's entries (absolute), not
    // relative to its own size near the identity.
    g["se23_so3_log"].scale = scale_at_least_1();
    g["se23_log"].scale = scale_concat({{3, scale_at_least_1()}, {3, scale_blocks({3})}, {3, scale_blocks({3})}});
    g["se23_vee"].scale = scale_tangent();
    g["se23_adjoint"].scale = scale_mat_blocks(9, 9, 3);
    g["se23_adjoint_inv"].scale = scale_mat_blocks(9, 9, 3);
}

} // namespace gen
