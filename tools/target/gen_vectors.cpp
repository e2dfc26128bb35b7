// gen_vectors: writes the reference vectors of the target test images
// (tests/target/tv.h) as a C source with const tables, for one precision.
//
//   gen_vectors float|double [--corrupt NAME] > tv_data.c
//
// Inputs are seeded random values plus the edge cases of each routine,
// rounded to the build's precision first (so that the target sees exactly the
// input the reference used); expected outputs come from the Eigen reference
// (tests/reference, long double) and expected statuses from the documented
// domain of each routine. --corrupt NAME perturbs one expected output of
// routine NAME far beyond its tolerance: an image built from that file must
// fail exactly one vector (the test of the runner).
//
// The routines are the rows of tests/target/tv_list.h; each must have an
// entry in gens() below, with the same name and row sizes, or this program
// stops with an error.
#include <cmath>
#include <cstdio>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "reference.hpp"
#include "tv.h"

namespace {

using namespace se23ref;
using Row = std::vector<LD>;

constexpr int kRandom = 48; // random vectors per routine, after the edge cases
const LD kPi = 3.141592653589793238462643383279502884L;
const LD kNaN = std::numeric_limits<LD>::quiet_NaN();

// ---- inputs ---------------------------------------------------------------

struct Ctx {
    bool is_float;
    std::mt19937_64 rng{0x5E23u};
    // The value the target will hold for x.
    LD round(LD x) const
    {
        return is_float ? LD(float(x)) : LD(double(x));
    }
    LD uniform(LD lo, LD hi)
    {
        return lo + (hi - lo) * LD(std::uniform_real_distribution<double>(0.0, 1.0)(rng));
    }
    Vec3L axis()
    {
        std::normal_distribution<double> n;
        Vec3L a;
        do {
            a = Vec3L(LD(n(rng)), LD(n(rng)), LD(n(rng)));
        } while (a.norm() < 1e-3L);
        return a / a.norm();
    }
};

template <class M> void put(Row &r, const M &m) // row-major
{
    for (int i = 0; i < m.rows(); ++i) {
        for (int j = 0; j < m.cols(); ++j) {
            r.push_back(m(i, j));
        }
    }
}
void put_pose(Row &r, const Mat5L &T)
{
    put(r, Mat3L(T.block<3, 3>(0, 0)));
    put(r, Vec3L(T.block<3, 1>(0, 3)));
    put(r, Vec3L(T.block<3, 1>(0, 4)));
}

Row rounded(const Ctx &c, Row r)
{
    for (LD &x : r) {
        x = c.round(x);
    }
    return r;
}

// Rotation angles every SO(3) routine is tested at (DESIGN.md section 3).
const std::vector<LD> &edge_angles()
{
    static const std::vector<LD> a = {0,    1.17549435e-38L, 1e-8L, 1e-5L, 1e-3L,
                                      1e-1L, 1,              2,     3,     kPi - 1e-6L};
    return a;
}

// k-th rotation vector: the edge angles first, then angles in [0, max_angle).
Vec3L phi_k(Ctx &c, int k, LD max_angle = kPi)
{
    const auto &e = edge_angles();
    const LD angle = k < int(e.size()) ? e[size_t(k)] : c.uniform(0, max_angle);
    return c.axis() * angle;
}
Vec3L vec3_any(Ctx &c, LD s) { return Vec3L(c.uniform(-s, s), c.uniform(-s, s), c.uniform(-s, s)); }
Mat3L rot_k(Ctx &c, int k) { return so3_exp(phi_k(c, k)); }
Mat5L pose_k(Ctx &c, int k) { return pose5(rot_k(c, k), vec3_any(c, 10), vec3_any(c, 10)); }

// ---- reading rows ---------------------------------------------------------

struct Rd {
    const Row &r;
    size_t i = 0;
    LD s() { return r.at(i++); }
    Vec3L v3()
    {
        Vec3L v;
        for (int j = 0; j < 3; ++j) v(j) = s();
        return v;
    }
    Vec9L v9()
    {
        Vec9L v;
        for (int j = 0; j < 9; ++j) v(j) = s();
        return v;
    }
    Mat3L m3()
    {
        Mat3L m;
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) m(a, b) = s();
        return m;
    }
    Mat5L m5()
    {
        Mat5L m;
        for (int a = 0; a < 5; ++a)
            for (int b = 0; b < 5; ++b) m(a, b) = s();
        return m;
    }
    Mat5L pose()
    {
        const Mat3L R = m3();
        const Vec3L v = v3();
        const Vec3L p = v3();
        return pose5(R, v, p);
    }
};

bool all_finite(const Row &r)
{
    for (LD x : r) {
        if (!std::isfinite(x)) return false;
    }
    return true;
}

// The library's rotation test (so3.h: se23_so3_check): |R^T R - I| entries
// within tol and det > 0. Vectors only use clear cases on either side.
bool is_rotation(const Mat3L &R, const Ctx &c)
{
    const LD tol = c.is_float ? 1e-5L : 1e-9L;
    return (R.transpose() * R - Mat3L::Identity()).cwiseAbs().maxCoeff() <= tol &&
           R.determinant() > 0;
}

// ---- generators -----------------------------------------------------------

struct Gen {
    int n_edge; // rows before the random ones (edge and error cases)
    // k-th input row (before rounding)
    std::function<Row(Ctx &, int k)> input;
    // status (se23_status_t) and outputs for an input row
    std::function<int(const Ctx &, const Row &in, Row &out)> expect;
};

int n_angles() { return int(edge_angles().size()); }

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

std::map<std::string, Gen> gens()
{
    std::map<std::string, Gen> g;
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
    g["se23_so3_vee"] = {0,
                         [](Ctx &c, int) {
                             Row r;
                             for (int i = 0; i < 9; ++i) r.push_back(c.uniform(-2, 2));
                             return r;
                         },
                         [](const Ctx &, const Row &in, Row &out) {
                             Rd rd{in};
                             put(out, vee3(rd.m3()));
                             return int(SE23_OK);
                         }};
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
    g["se23_inverse"] = {0,
                         [](Ctx &c, int k) {
                             Row r;
                             put_pose(r, pose_k(c, k));
                             return r;
                         },
                         [](const Ctx &, const Row &in, Row &out) {
                             Rd rd{in};
                             put_pose(out, inverse(rd.pose()));
                             return int(SE23_OK);
                         }};
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
    g["se23_vee"] = {0,
                     [](Ctx &c, int) {
                         Row r;
                         for (int i = 0; i < 25; ++i) r.push_back(c.uniform(-5, 5));
                         return r;
                     },
                     [](const Ctx &, const Row &in, Row &out) {
                         Rd rd{in};
                         put(out, se23_vee(rd.m5()));
                         return int(SE23_OK);
                     }};
    g["se23_to_mat5"] = {0,
                         [](Ctx &c, int k) {
                             Row r;
                             put_pose(r, pose_k(c, k));
                             return r;
                         },
                         [](const Ctx &, const Row &in, Row &out) {
                             Rd rd{in};
                             put(out, rd.pose());
                             return int(SE23_OK);
                         }};
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
    g["se23_adjoint"] = {0,
                         [](Ctx &c, int k) {
                             Row r;
                             put_pose(r, pose_k(c, k));
                             return r;
                         },
                         [](const Ctx &, const Row &in, Row &out) {
                             Rd rd{in};
                             put(out, adjoint(rd.pose()));
                             return int(SE23_OK);
                         }};
    g["se23_adjoint_inv"] = {0,
                             [](Ctx &c, int k) {
                                 Row r;
                                 put_pose(r, pose_k(c, k));
                                 return r;
                             },
                             [](const Ctx &, const Row &in, Row &out) {
                                 Rd rd{in};
                                 put(out, adjoint_inv(rd.pose()));
                                 return int(SE23_OK);
                             }};
    g["se23_pose_check"] = {n + 3, pose_input, [](const Ctx &c, const Row &in, Row &) {
                                Rd rd{in};
                                return rot_status(c, rd.pose().block<3, 3>(0, 0), in);
                            }};
    return g;
}

// ---- the rows of tv_list.h -------------------------------------------------

struct ListRow {
    const char *name;
    int n_in, n_out;
};

const std::vector<ListRow> &list_rows()
{
#define TV_V0(fn, O, tol) {#fn, 0, TV_REALS(O)},
#define TV_V1(fn, A, O, tol) {#fn, TV_REALS(A), TV_REALS(O)},
#define TV_S1(fn, A, O, tol) {#fn, TV_REALS(A), TV_REALS(O)},
#define TV_V2(fn, A, B, O, tol) {#fn, TV_REALS(A) + TV_REALS(B), TV_REALS(O)},
#define TV_S2(fn, A, B, O, tol) {#fn, TV_REALS(A) + TV_REALS(B), TV_REALS(O)},
#define TV_C1(fn, A, tol) {#fn, TV_REALS(A), 0},
#define TV_CUSTOM(fn, n_in, n_out, tol) {#fn, n_in, n_out},
    static const std::vector<ListRow> rows = {
#include "tv_list.h"
    };
    return rows;
}

// ---- output ---------------------------------------------------------------

void print_values(const char *name, const char *suffix, const std::vector<LD> &v,
                  int per_line)
{
    std::printf("static const se23_real_t %s_%s[] = {\n", name, suffix);
    for (size_t i = 0; i < v.size(); ++i) {
        const LD x = v[i];
        if (std::isnan(x)) {
            std::printf("    TV_R(NAN),");
        } else if (std::isinf(x)) {
            std::printf("    TV_R(%sINFINITY),", x < 0 ? "-" : "");
        } else {
            std::printf("    TV_R(%.17g),", double(x));
        }
        if ((i + 1) % size_t(per_line) == 0 || i + 1 == v.size()) std::printf("\n");
    }
    std::printf("};\n");
}

void emit(Ctx &c, const ListRow &lr, const Gen &g, const std::string &corrupt)
{
    const int n_vec = g.n_edge + kRandom;
    std::vector<LD> ins, outs;
    std::string st;
    bool corrupted = false;
    for (int k = 0; k < n_vec; ++k) {
        const Row in = rounded(c, g.input(c, k));
        Row out;
        const int s = g.expect(c, in, out);
        if (int(in.size()) != lr.n_in) {
            throw std::runtime_error(std::string(lr.name) + ": input row size differs from tv_list.h");
        }
        if (s == SE23_OK && int(out.size()) != lr.n_out) {
            throw std::runtime_error(std::string(lr.name) + ": output row size differs from tv_list.h");
        }
        out.resize(size_t(lr.n_out), 0);
        if (s == SE23_OK && !corrupted && corrupt == lr.name && lr.n_out > 0) {
            out[0] += LD(1e-3) * (1 + std::fabs(out[0]));
            corrupted = true;
        }
        ins.insert(ins.end(), in.begin(), in.end());
        outs.insert(outs.end(), out.begin(), out.end());
        st += "    " + std::to_string(s) + ",\n";
    }
    if (corrupt == lr.name && !corrupted) {
        throw std::runtime_error("--corrupt " + corrupt + ": no output to corrupt");
    }
    std::printf("\n/* %s: %d vectors (%d edge/error cases, %d random) */\n", lr.name, n_vec,
                g.n_edge, kRandom);
    if (!ins.empty()) print_values(lr.name, "in", ins, lr.n_in < 3 ? 1 : 3);
    if (!outs.empty()) print_values(lr.name, "out", outs, 3);
    std::printf("static const signed char %s_st[] = {\n%s};\n", lr.name, st.c_str());
    std::printf("const tv_data_t tv_data_%s = {%d, %d, %d, %s, %s, %s_st};\n", lr.name, n_vec,
                lr.n_in, lr.n_out, ins.empty() ? "NULL" : (std::string(lr.name) + "_in").c_str(),
                outs.empty() ? "NULL" : (std::string(lr.name) + "_out").c_str(), lr.name);
}

} // namespace

int main(int argc, char **argv)
{
    if (argc < 2 || (std::strcmp(argv[1], "float") != 0 && std::strcmp(argv[1], "double") != 0)) {
        std::fprintf(stderr, "usage: gen_vectors float|double [--corrupt NAME]\n");
        return 2;
    }
    std::string corrupt;
    if (argc == 4 && std::strcmp(argv[2], "--corrupt") == 0) corrupt = argv[3];
    Ctx c{std::strcmp(argv[1], "float") == 0};
    try {
        const auto g = gens();
        const auto &rows = list_rows();
        for (const auto &kv : g) {
            bool listed = false;
            for (const auto &r : rows) listed = listed || kv.first == r.name;
            if (!listed) throw std::runtime_error(kv.first + ": generator without a row in tv_list.h");
        }
        std::printf("/* Generated by tools/target/gen_vectors %s%s%s from the Eigen reference\n"
                    " * (tests/reference); do not edit. */\n#include <math.h>\n\n#include \"tv.h\"\n",
                    argv[1], corrupt.empty() ? "" : " --corrupt ", corrupt.c_str());
        for (const auto &r : rows) {
            const auto it = g.find(r.name);
            if (it == g.end()) throw std::runtime_error(std::string(r.name) + ": no generator (tools/target/gen_vectors.cpp)");
            emit(c, r, it->second, corrupt);
        }
    } catch (const std::exception &e) {
        std::fprintf(stderr, "gen_vectors: %s\n", e.what());
        return 1;
    }
    return 0;
}
