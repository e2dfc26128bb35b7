// Target vectors of earth.h, imu.h and preint.h. Expected values from the
// reference's own routes (tests/reference/ref_nav.hpp): the exact increment
// and Gamma' from augmented-matrix exponentials, one propagation step and a
// preintegrated prediction from RK4 integration of the continuous navigation
// equations; WGS-84 gravity and Earth rate from their defining formulas
// (NIMA TR8350.2) evaluated in long double. Statuses from each routine's
// documented domain. Row layouts follow the structs (sample = w, f, dt;
// model = g_n, w_ie_n, dt, dt_max, gamma; preint = delta, dt, n).
#include "gen_common.hpp"
#include "ref_nav.hpp"

namespace gen {
namespace {

const LD kDtMax = LD(SE23_CFG_DT_MAX);
const int kRk4Steps = 128; // RK4 sub-steps per sample: error far below double eps

Vec3L omega_any(Ctx &c)
{
    // Earth rate (7.3e-5 rad/s) or a fast-rotating frame (0.05 rad/s) that
    // makes the Coriolis terms visible in float.
    return c.axis() * (c.uniform(0, 1) < 0.5 ? LD(SE23_WGS84_OMEGA_E) : LD(0.05));
}
Vec3L gravity_any(Ctx &c) { return Vec3L(0, 0, 9.81L) + vec3_any(c, 0.05L); }

// ---- rows ------------------------------------------------------------------

void put_sample(Row &r, const Vec3L &w, const Vec3L &f, LD dt)
{
    put(r, w);
    put(r, f);
    put(r, dt);
}
void put_model(Row &r, const Vec3L &g, const Vec3L &Om, LD dt, LD dt_max)
{
    put(r, g);
    put(r, Om);
    put(r, dt);
    put(r, dt_max);
    put_pose(r, gamma_expm(g, Om, dt));
}
struct Sample {
    Vec3L w, f;
    LD dt;
};
Sample sample_any(Ctx &c)
{
    return {vec3_any(c, 2), vec3_any(c, 20), c.uniform(1e-3L, 0.02L)};
}
struct Model {
    Vec3L g, Om;
    LD dt, dt_max;
};
Model read_model(Rd &rd)
{
    Model m;
    m.g = rd.v3();
    m.Om = rd.v3();
    m.dt = rd.s();
    m.dt_max = rd.s();
    rd.pose(); // gamma: the library's input, not needed by the reference
    return m;
}
Sample read_sample(Rd &rd)
{
    Sample s;
    s.w = rd.v3();
    s.f = rd.v3();
    s.dt = rd.s();
    return s;
}
Mat5L rk4(const Mat5L &T, const Sample &s, const Model &m)
{
    return nav_rk4(T, s.w, s.f, m.g, m.Om, s.dt, kRk4Steps);
}
bool sample_ok(const Sample &s, LD dt_max) { return s.dt > 0 && s.dt <= dt_max; }

// ---- WGS-84 (TR8350.2 eqs. 4-1 and 4-3, as documented in earth.h) ---------

LD gravity_wgs84(LD lat, LD h)
{
    const LD s2 = std::sin(lat) * std::sin(lat);
    const LD g0 = LD(SE23_WGS84_GAMMA_E) * (1 + LD(SE23_WGS84_K) * s2) /
                  std::sqrt(1 - LD(SE23_WGS84_E2) * s2);
    const LD a = LD(SE23_WGS84_A);
    return g0 * (1 - 2 / a * (1 + LD(SE23_WGS84_F) + LD(SE23_WGS84_M) - 2 * LD(SE23_WGS84_F) * s2) * h +
                 3 * h * h / (a * a));
}
Vec3L gravity_vec(int frame, LD lat, LD h)
{
    const LD g = gravity_wgs84(lat, h);
    return Vec3L(0, 0, frame == SE23_FRAME_NED ? g : -g);
}
Vec3L earth_rate(int frame, LD lat)
{
    const LD w = LD(SE23_WGS84_OMEGA_E);
    return frame == SE23_FRAME_NED ? Vec3L(w * std::cos(lat), 0, -w * std::sin(lat))
                                   : Vec3L(0, w * std::cos(lat), w * std::sin(lat));
}
int lat_h_status(LD lat, LD h)
{
    if (!std::isfinite(lat) || !std::isfinite(h)) return SE23_ERR_NONFINITE;
    if (std::fabs(lat) > kPi / 2 + LD(SE23_EARTH_LAT_SLACK) || h < LD(SE23_EARTH_H_MIN) ||
        h > LD(SE23_EARTH_H_MAX)) {
        return SE23_ERR_DOMAIN;
    }
    return SE23_OK;
}
int model_status(const Row &in, LD dt, LD dt_max)
{
    if (!all_finite(in)) return SE23_ERR_NONFINITE;
    return (dt > 0 && dt <= dt_max && dt_max <= kDtMax) ? int(SE23_OK) : int(SE23_ERR_DT);
}
// k-th (frame, lat, h): the edge rows, then random. Edge rows: the poles, a
// latitude past the pole, heights at both limits and past them, NaN, an
// unknown frame (2).
std::array<LD, 3> geo_k(Ctx &c, int k)
{
    static const std::array<std::array<LD, 3>, 9> edge = {{{0, 0, 0},
                                                           {1, kPi / 2, 0},
                                                           {0, -kPi / 2, 1e5L},
                                                           {1, 0.7L, -1e4L},
                                                           {0, kPi / 2 + 1e-3L, 0},
                                                           {1, 0.3L, 1.01e5L},
                                                           {0, 0.3L, -1.01e4L},
                                                           {1, kNaN, 0},
                                                           {2, 0.3L, 0}}};
    if (k < int(edge.size())) return edge[size_t(k)];
    return {LD(c.uniform(0, 1) < 0.5 ? 0 : 1), c.uniform(-kPi / 2, kPi / 2), c.uniform(-1e3L, 1e4L)};
}
const int kGeoEdges = 9;
bool frame_ok(LD frame) { return frame == 0 || frame == 1; }

// ---- preintegrated factors ---------------------------------------------------

// A factor as the library holds it: random Delta (or accumulated from
// samples, recorded in c.samples), dt, n.
Mat5L accumulate(Ctx &c, LD &dt_sum)
{
    c.samples.clear();
    Mat5L delta = Mat5L::Identity();
    dt_sum = 0;
    const int n = 1 + int(c.uniform(0, 12));
    for (int i = 0; i < n; ++i) {
        const Sample s = sample_any(c);
        c.samples.push_back({s.w(0), s.w(1), s.w(2), s.f(0), s.f(1), s.f(2), s.dt});
        delta = phi_t(delta, s.dt) * upsilon_expm(s.w, s.f, s.dt);
        dt_sum += s.dt;
    }
    return delta;
}

} // namespace

void add_nav(Gens &g)
{
    // ---- earth.h
    g["se23_earth_gravity"] = {kGeoEdges,
                               [](Ctx &c, int k) {
                                   const auto x = geo_k(c, k);
                                   return Row{x[1], x[2]};
                               },
                               [](const Ctx &, const Row &in, Row &out) {
                                   const int st = lat_h_status(in[0], in[1]);
                                   if (st == SE23_OK) put(out, gravity_wgs84(in[0], in[1]));
                                   return st;
                               }};
    g["se23_earth_gravity_vec"] = {kGeoEdges,
                                   [](Ctx &c, int k) {
                                       const auto x = geo_k(c, k);
                                       return Row{x[0], x[1], x[2]};
                                   },
                                   [](const Ctx &, const Row &in, Row &out) {
                                       int st = lat_h_status(in[1], in[2]);
                                       if (st == SE23_OK && !frame_ok(in[0])) st = SE23_ERR_DOMAIN;
                                       if (st == SE23_OK) put(out, gravity_vec(int(in[0]), in[1], in[2]));
                                       return st;
                                   }};
    g["se23_earth_rate"] = {kGeoEdges,
                            [](Ctx &c, int k) {
                                const auto x = geo_k(c, k);
                                return Row{x[0], x[1]};
                            },
                            [](const Ctx &, const Row &in, Row &out) {
                                int st = lat_h_status(in[1], 0);
                                if (st == SE23_OK && !frame_ok(in[0])) st = SE23_ERR_DOMAIN;
                                if (st == SE23_OK) put(out, earth_rate(int(in[0]), in[1]));
                                return st;
                            }};
    g["se23_earth_gamma"] = {4,
                             [](Ctx &c, int k) {
                                 // edges: t = 0 (identity), Omega = 0 (flat), t < 0, NaN
                                 Row r;
                                 put(r, gravity_any(c));
                                 put(r, k == 1 ? Vec3L(Vec3L::Zero()) : omega_any(c));
                                 put(r, k == 0 ? LD(0) : k == 2 ? LD(-0.01) : k == 3 ? kNaN
                                                                                   : c.uniform(0, 2));
                                 return r;
                             },
                             [](const Ctx &, const Row &in, Row &out) {
                                 if (!all_finite(in)) return int(SE23_ERR_NONFINITE);
                                 Rd rd{in};
                                 const Vec3L gv = rd.v3(), Om = rd.v3();
                                 const LD t = rd.s();
                                 if (t < 0) return int(SE23_ERR_DT);
                                 put_pose(out, gamma_expm(gv, Om, t));
                                 return int(SE23_OK);
                             }};
    g["se23_earth_model_init"] = {
        4,
        [](Ctx &c, int k) {
            // edges: dt = 0, dt > dt_max, dt_max > SE23_CFG_DT_MAX, NaN
            Row r;
            put(r, gravity_any(c));
            put(r, omega_any(c));
            const LD dt = k == 0 ? LD(0) : k == 1 ? LD(0.03) : c.uniform(1e-3L, 0.02L);
            put(r, k == 3 ? kNaN : dt);
            put(r, k == 2 ? kDtMax * 2 : LD(0.02));
            return r;
        },
        [](const Ctx &, const Row &in, Row &out) {
            Rd rd{in};
            const Vec3L gv = rd.v3(), Om = rd.v3();
            const LD dt = rd.s(), dt_max = rd.s();
            const int st = model_status(in, dt, dt_max);
            if (st == SE23_OK) put_model(out, gv, Om, dt, dt_max);
            return st;
        }};
    g["se23_earth_model_init_wgs84"] = {
        kGeoEdges + 1,
        [](Ctx &c, int k) {
            const auto x = geo_k(c, k);
            return Row{x[0], x[1], x[2], k == kGeoEdges ? LD(0.05) : c.uniform(1e-3L, 0.02L), 0.02L};
        },
        [](const Ctx &, const Row &in, Row &out) {
            int st = lat_h_status(in[1], in[2]);
            if (st == SE23_OK && !frame_ok(in[0])) st = SE23_ERR_DOMAIN;
            if (st == SE23_OK) st = model_status(in, in[3], in[4]);
            if (st == SE23_OK) {
                put_model(out, gravity_vec(int(in[0]), in[1], in[2]), earth_rate(int(in[0]), in[1]),
                          in[3], in[4]);
            }
            return st;
        }};
    // ---- imu.h
    const auto increment_input = [](Ctx &c, int k) {
        // edges: w = 0, |w dt| tiny, dt = 0, dt < 0, dt > SE23_CFG_DT_MAX, NaN
        Sample s = sample_any(c);
        if (k == 0) s.w = Vec3L::Zero();
        if (k == 1) s.w = c.axis() * LD(1e-7);
        if (k == 2) s.dt = 0;
        if (k == 3) s.dt = -0.01L;
        if (k == 4) s.dt = kDtMax * 1.5L;
        if (k == 5) s.f(1) = kNaN;
        if (k == 6) { s.w = c.axis() * LD(3); s.dt = 0.9L; } // |w dt| = 2.7 rad
        Row r;
        put_sample(r, s.w, s.f, s.dt);
        return r;
    };
    const auto increment_status = [](const Row &in) {
        if (!all_finite(in)) return int(SE23_ERR_NONFINITE);
        return in[6] > 0 && in[6] <= kDtMax ? int(SE23_OK) : int(SE23_ERR_DT);
    };
    g["se23_imu_increment"] = {7, increment_input, [increment_status](const Ctx &, const Row &in, Row &out) {
                                   const int st = increment_status(in);
                                   Rd rd{in};
                                   const Sample s = read_sample(rd);
                                   if (st == SE23_OK) put_pose(out, upsilon_expm(s.w, s.f, s.dt));
                                   return st;
                               }};
    // (exp(w dt), dt f, pos_coeff dt^2 f): Forster et al.'s model (1/2) and
    // the paper's eq. backtofuture (0).
    const auto first_order = [increment_input, increment_status](LD pos_coeff) {
        const auto expect = [increment_status, pos_coeff](const Ctx &, const Row &in, Row &out) {
            const int st = increment_status(in);
            Rd rd{in};
            const Sample s = read_sample(rd);
            if (st == SE23_OK) {
                put_pose(out, pose5(so3_exp(Vec3L(s.w * s.dt)), Vec3L(s.dt * s.f),
                                    Vec3L(pos_coeff * s.dt * s.dt * s.f)));
            }
            return st;
        };
        return Gen{7, increment_input, expect};
    };
    g["se23_imu_increment_forster"] = first_order(LD(0.5));
    g["se23_imu_increment_paper"] = first_order(LD(0));
    g["se23_imu_transition"] = {0,
                                [](Ctx &c, int k) {
                                    const Sample s = sample_any(c);
                                    Row r;
                                    put_pose(r, gamma_expm(gravity_any(c), omega_any(c), s.dt));
                                    put_pose(r, pose_k(c, k + n_angles()));
                                    put_pose(r, upsilon_expm(s.w, s.f, s.dt));
                                    put(r, s.dt);
                                    return r;
                                },
                                [](const Ctx &, const Row &in, Row &out) {
                                    Rd rd{in};
                                    const Mat5L G = rd.pose(), T = rd.pose(), U = rd.pose();
                                    put_pose(out, Mat5L(G * phi_t(T, rd.s()) * U));
                                    return int(SE23_OK);
                                }};
    g["se23_imu_step"] = {
        5,
        [](Ctx &c, int k) {
            // edges: NaN in T, NaN in s, dt = 0, dt > dt_max, T.R not a rotation;
            // one row in three has a jittered dt (Gamma' recomputed).
            const Vec3L gv = gravity_any(c), Om = omega_any(c);
            Sample s = sample_any(c);
            const LD dt_model = (k % 3 == 0) ? c.uniform(1e-3L, 0.02L) : s.dt;
            Mat5L T = pose_k(c, k + n_angles());
            if (k == 0) T(1, 4) = kNaN;
            if (k == 1) s.f(0) = kNaN;
            if (k == 2) s.dt = 0;
            if (k == 3) s.dt = 0.05L;
            if (k == 4) T.block<3, 3>(0, 0) *= LD(1.01);
            Row r;
            put_model(r, gv, Om, dt_model, 0.02L);
            put_pose(r, T);
            put_sample(r, s.w, s.f, s.dt);
            return r;
        },
        [](const Ctx &c, const Row &in, Row &out) {
            if (!all_finite(in)) return int(SE23_ERR_NONFINITE);
            Rd rd{in};
            const Model m = read_model(rd);
            const Mat5L Tc = rd.pose();
            const Sample s = read_sample(rd);
            if (!sample_ok(s, m.dt_max)) return int(SE23_ERR_DT);
            if (!is_rotation(Tc.block<3, 3>(0, 0), c)) return int(SE23_ERR_NOT_ROTATION);
            put_pose(out, carried_pose(rk4(carried_pose(Tc, m.Om, -1), s, m), m.Om, 1));
            return int(SE23_OK);
        }};
    const auto conv_input = [](Ctx &c, int k) {
        Row r;
        put_model(r, gravity_any(c), omega_any(c), 0.005L, 0.02L);
        put_pose(r, pose_k(c, k + n_angles()));
        return r;
    };
    g["se23_imu_carried_from_user"] = {0, conv_input, [](const Ctx &, const Row &in, Row &out) {
                                           Rd rd{in};
                                           const Model m = read_model(rd);
                                           put_pose(out, carried_pose(rd.pose(), m.Om, 1));
                                           return int(SE23_OK);
                                       }};
    g["se23_imu_user_from_carried"] = {0, conv_input, [](const Ctx &, const Row &in, Row &out) {
                                           Rd rd{in};
                                           const Model m = read_model(rd);
                                           put_pose(out, carried_pose(rd.pose(), m.Om, -1));
                                           return int(SE23_OK);
                                       }};
    // ---- preint.h
    g["se23_preint_reset"] = {1, [](Ctx &, int) { return Row(); },
                              [](const Ctx &, const Row &, Row &out) {
                                  put_preint(out, Mat5L::Identity(), 0, 0);
                                  return int(SE23_OK);
                              }};
    const auto factor_row = [](Ctx &c, int k, Row &r) {
        put_preint(r, pose_k(c, k + n_angles()), c.uniform(0, 1), LD(int(c.uniform(0, 100))));
    };
    g["se23_preint_add"] = {
        5,
        [factor_row](Ctx &c, int k) {
            // edges: NaN in f, NaN in s, s.dt = 0, f.dt < 0, f.delta.R not a rotation
            Row r;
            factor_row(c, k, r);
            if (k == 0) r[10] = kNaN;
            if (k == 3) r[15] = -0.1L;
            if (k == 4) {
                for (int i = 0; i < 9; ++i) r[size_t(i)] *= LD(1.01);
            }
            Sample s = sample_any(c);
            if (k == 1) s.w(2) = kNaN;
            if (k == 2) s.dt = 0;
            put_sample(r, s.w, s.f, s.dt);
            return r;
        },
        [](const Ctx &c, const Row &in, Row &out) {
            if (!all_finite(in)) return int(SE23_ERR_NONFINITE);
            Rd rd{in};
            const Mat5L D = rd.pose();
            const LD dt = rd.s(), n = rd.s();
            const Sample s = read_sample(rd);
            if (!sample_ok(s, kDtMax) || dt < 0) return int(SE23_ERR_DT);
            if (!is_rotation(D.block<3, 3>(0, 0), c)) return int(SE23_ERR_NOT_ROTATION);
            put_preint(out, Mat5L(phi_t(D, s.dt) * upsilon_expm(s.w, s.f, s.dt)), dt + s.dt, n + 1);
            return int(SE23_OK);
        }};
    g["se23_preint_add_increment"] = {0,
                                      [factor_row](Ctx &c, int k) {
                                          Row r;
                                          factor_row(c, k, r);
                                          const Sample s = sample_any(c);
                                          put_pose(r, upsilon_expm(s.w, s.f, s.dt));
                                          put(r, s.dt);
                                          return r;
                                      },
                                      [](const Ctx &, const Row &in, Row &out) {
                                          Rd rd{in};
                                          const Mat5L D = rd.pose();
                                          const LD dt = rd.s(), n = rd.s();
                                          const Mat5L U = rd.pose();
                                          const LD t = rd.s();
                                          put_preint(out, Mat5L(phi_t(D, t) * U), dt + t, n + 1);
                                          return int(SE23_OK);
                                      }};
    // Prediction through a factor accumulated from random samples, against
    // RK4 through the same samples; carried == 1: on carried states.
    const auto predict = [](int carried_states) {
        return Gen{
            4,
            [](Ctx &c, int k) {
                // edges: NaN in T_i, T_i.R not a rotation, f.delta.R not a
                // rotation, f.dt < 0
                Row r;
                put_model(r, gravity_any(c), omega_any(c), 0.005L, 0.02L);
                LD dt = 0;
                Mat5L D = accumulate(c, dt);
                Mat5L T = pose_k(c, k + n_angles());
                if (k == 0) T(2, 3) = kNaN;
                if (k == 1) T.block<3, 3>(0, 0) *= LD(1.01);
                if (k == 2) D.block<3, 3>(0, 0) *= LD(1.01);
                if (k == 3) dt = -dt;
                put_preint(r, D, dt, LD(c.samples.size()));
                put_pose(r, T);
                return r;
            },
            [carried_states](const Ctx &c, const Row &in, Row &out) {
                if (!all_finite(in)) return int(SE23_ERR_NONFINITE);
                Rd rd{in};
                const Model m = read_model(rd);
                const Mat5L D = rd.pose();
                const LD dt = rd.s();
                rd.s();
                Mat5L T = rd.pose();
                if (!is_rotation(T.block<3, 3>(0, 0), c) || !is_rotation(D.block<3, 3>(0, 0), c)) {
                    return int(SE23_ERR_NOT_ROTATION);
                }
                if (dt < 0) return int(SE23_ERR_DT);
                if (carried_states) T = carried_pose(T, m.Om, -1);
                for (const auto &x : c.samples) {
                    T = rk4(T, Sample{Vec3L(x[0], x[1], x[2]), Vec3L(x[3], x[4], x[5]), x[6]}, m);
                }
                put_pose(out, carried_states ? carried_pose(T, m.Om, 1) : T);
                return int(SE23_OK);
            }};
    };
    g["se23_preint_predict"] = predict(0);
    g["se23_preint_predict_carried"] = predict(1);
    for (const char *n : {"se23_earth_gamma", "se23_imu_increment", "se23_imu_increment_forster",
                          "se23_imu_increment_paper", "se23_imu_transition", "se23_imu_step",
                          "se23_imu_carried_from_user", "se23_imu_user_from_carried",
                          "se23_preint_predict", "se23_preint_predict_carried"}) {
        g[n].scale = scale_pose();
    }
    g["se23_earth_model_init"].scale = scale_model();
    g["se23_earth_model_init_wgs84"].scale = scale_model();
    for (const char *n : {"se23_preint_reset", "se23_preint_add", "se23_preint_add_increment"}) {
        g[n].scale = scale_blocks({9, 3, 3, 1, 1});
    }
}

} // namespace gen
