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
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "gen_common.hpp"

namespace {

using namespace gen;

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

// Error scales, 4 significant digits are plenty: float in both builds.
void print_scales(const char *name, const std::vector<LD> &v)
{
    std::printf("static const float %s_scale[] = {\n", name);
    for (size_t i = 0; i < v.size(); ++i) {
        std::printf("    %.4ef,", double(v[i]));
        if ((i + 1) % 6 == 0 || i + 1 == v.size()) std::printf("\n");
    }
    std::printf("};\n");
}

void emit(Ctx &c, const ListRow &lr, const Gen &g, const std::string &corrupt)
{
    const int n_vec = g.n_edge + g.n_random;
    std::vector<LD> ins, outs, scales;
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
        Row sc = s != SE23_OK ? Row(out.size(), 0)
                 : g.scale_io ? g.scale_io(in, out)
                 : g.scale    ? g.scale(out)
                              : Row(out.size(), max_abs(out, 0, out.size()));
        if (sc.size() != out.size()) {
            throw std::runtime_error(std::string(lr.name) + ": scale row size differs from the output");
        }
        ins.insert(ins.end(), in.begin(), in.end());
        outs.insert(outs.end(), out.begin(), out.end());
        scales.insert(scales.end(), sc.begin(), sc.end());
        st += "    " + std::to_string(s) + ",\n";
    }
    if (corrupt == lr.name && !corrupted) {
        throw std::runtime_error("--corrupt " + corrupt + ": no output to corrupt");
    }
    std::printf("\n/* %s: %d vectors (%d edge/error cases, %d random) */\n", lr.name, n_vec,
                g.n_edge, g.n_random);
    if (!ins.empty()) print_values(lr.name, "in", ins, lr.n_in < 3 ? 1 : 3);
    if (!outs.empty()) {
        print_values(lr.name, "out", outs, 3);
        print_scales(lr.name, scales);
    }
    std::printf("static const signed char %s_st[] = {\n%s};\n", lr.name, st.c_str());
    const std::string name = lr.name;
    std::printf("const tv_data_t tv_data_%s = {%d, %d, %d, %s, %s, %s, %s_st};\n", lr.name, n_vec,
                lr.n_in, lr.n_out, ins.empty() ? "NULL" : (name + "_in").c_str(),
                outs.empty() ? "NULL" : (name + "_out").c_str(),
                outs.empty() ? "NULL" : (name + "_scale").c_str(), lr.name);
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
    Ctx c;
    c.is_float = std::strcmp(argv[1], "float") == 0;
    try {
        Gens g;
        add_lie(g);
        add_nav(g);
        add_gauss(g);
        add_kalman(g);
        add_preint_unc(g);
        add_align(g);
        add_geo(g);
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
