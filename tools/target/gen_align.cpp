// Target vectors of stationary.h and align.h, from references written from
// the definitions, not from the C code:
//  - the SHOE statistic as Skog et al. define it, with the direction
//    u = fbar / |fbar| (the library evaluates the decomposition without u),
//    over a window replayed sample by sample in long double;
//  - levelling by Eigen angle-axis products Rz(yaw) Ry(pitch) Rx(roll) with
//    pitch = asin(-d_x), roll = atan2(d_y, d_z) (the library builds R from
//    unit (cos, sin) pairs, no trigonometry);
//  - the covariance as the dense congruence R^T diag(t^2, t^2, s^2) R;
//  - gyrocompassing by TRIAD (nav z and Earth rate against s f / |f| and
//    w), its yaw read back from R as atan2(R_10, R_00).
// Row layouts as tests/target/tv_list.h and tv_custom.c.
#include <cfloat>
#include <deque>

#include "gen_common.hpp"

namespace gen {
namespace {

const LD kG0 = LD(SE23_ALIGN_G0);
const LD kWe = LD(SE23_WGS84_OMEGA_E);

LD max_real(const Ctx &c) { return c.is_float ? LD(FLT_MAX) : LD(DBL_MAX); }
bool finite_all(std::initializer_list<LD> xs)
{
    for (LD x : xs) {
        if (!std::isfinite(x)) return false;
    }
    return true;
}

// ---- stationary.h ------------------------------------------------------------

struct StCfg {
    LD window, sa, sg, g, thr;
};
struct StSample {
    Vec3L w, f;
};
struct StRow {
    StCfg cfg;
    int k = 0;
    std::vector<StSample> s; // TV_ST_SAMPLES (1 for reset rows)
};

void put_st(Row &r, const StRow &x)
{
    put(r, x.cfg.window);
    put(r, x.cfg.sa);
    put(r, x.cfg.sg);
    put(r, x.cfg.g);
    put(r, x.cfg.thr);
    put(r, LD(x.k));
    for (const auto &s : x.s) {
        put(r, s.w);
        put(r, s.f);
    }
}
StRow read_st(const Row &in, int n_samples)
{
    Rd rd{in};
    StRow x;
    x.cfg = {rd.s(), rd.s(), rd.s(), rd.s(), rd.s()};
    x.k = int(rd.s());
    for (int j = 0; j < n_samples; ++j) {
        const Vec3L w = rd.v3();
        const Vec3L f = rd.v3();
        x.s.push_back({w, f});
    }
    return x;
}

// se23_stationary_init's status, in its documented order.
int st_init_status(const Ctx &c, const StCfg &cfg)
{
    if (!finite_all({cfg.sa, cfg.sg, cfg.g, cfg.thr})) return SE23_ERR_NONFINITE;
    if (cfg.window < 2 || cfg.window > SE23_STATIONARY_WMAX) return SE23_ERR_DIM;
    const auto sigma_ok = [&c](LD s) {
        return s > 0 && s * s < max_real(c) && 1 / (s * s) < max_real(c);
    };
    if (!sigma_ok(cfg.sa) || !sigma_ok(cfg.sg) || !(cfg.g > 0) || !(cfg.thr > 0)) {
        return SE23_ERR_DOMAIN;
    }
    return SE23_OK;
}

// T over the samples of a window, from the definition.
LD shoe(const std::deque<StSample> &win, const StCfg &cfg)
{
    const LD n = LD(win.size());
    Vec3L fbar = Vec3L::Zero();
    for (const auto &s : win) fbar += s.f / n;
    LD t = 0;
    for (const auto &s : win) {
        const Vec3L e = fbar.norm() > 0 ? Vec3L(s.f - cfg.g * fbar / fbar.norm()) : s.f;
        t += e.squaredNorm() / (cfg.sa * cfg.sa) + s.w.squaredNorm() / (cfg.sg * cfg.sg);
    }
    if (!(fbar.norm() > 0)) t += n * cfg.g * cfg.g / (cfg.sa * cfg.sa);
    return t / n;
}

// The detector after init and the adds 0..adds-1 of a row (sample j mod
// the number of samples); status of the last add.
struct StState {
    std::deque<StSample> win;
    int stored = 0; // successful adds
    LD stat = 0;
    int flag = 0;
    int last = SE23_OK;
};
StState st_run(const Ctx &c, const StRow &x, int adds)
{
    StState st;
    const size_t W = size_t(x.cfg.window);
    for (int j = 0; j < adds; ++j) {
        const StSample &s = x.s[size_t(j) % x.s.size()];
        if (!all_finite(Row{s.w(0), s.w(1), s.w(2), s.f(0), s.f(1), s.f(2)})) {
            st.last = SE23_ERR_NONFINITE;
            continue;
        }
        std::deque<StSample> win = st.win;
        win.push_back(s);
        if (win.size() > W) win.pop_front();
        const LD t = shoe(win, x.cfg);
        if (!(t < max_real(c) / 1e6L)) { // far above: the library overflows
            st.last = SE23_ERR_NONFINITE;
            continue;
        }
        st.win = win;
        ++st.stored;
        st.stat = t;
        st.flag = (win.size() == W && t < x.cfg.thr) ? 1 : 0;
        st.last = SE23_OK;
    }
    return st;
}

// A valid random configuration and samples: f = g u0 + noise (+ motion),
// w = bias + noise.
StRow st_random(Ctx &c, int n_samples)
{
    StRow x;
    x.cfg.window = LD(2 + int(c.uniform(0, SE23_STATIONARY_WMAX - 1)));
    x.cfg.sa = c.uniform(0.05L, 0.5L);
    x.cfg.sg = c.uniform(1e-3L, 0.05L);
    x.cfg.g = c.uniform(9.7L, 9.9L);
    x.cfg.thr = 8;
    const Vec3L u0 = c.axis();
    const Vec3L bias = vec3_any(c, 3 * x.cfg.sg);
    const LD motion = c.uniform(0, 1) < 0.5 ? LD(0) : c.uniform(0, 2);
    for (int j = 0; j < n_samples; ++j) {
        const Vec3L f = x.cfg.g * u0 + vec3_any(c, 1.7L * x.cfg.sa) + vec3_any(c, motion);
        const Vec3L w = bias + vec3_any(c, 1.7L * x.cfg.sg) + vec3_any(c, 0.1L * motion);
        x.s.push_back({w, f});
    }
    return x;
}

// A threshold 30 % away from the statistic after the row's adds.
void st_threshold(const Ctx &c, StRow &x, int k)
{
    const StState st = st_run(c, x, x.k);
    if (st.stored > 0) x.cfg.thr = st.stat * (k % 2 ? LD(0.7) : LD(1.4));
}

void put_state(Row &out, const StCfg &cfg, const StState &st)
{
    const size_t W = size_t(cfg.window);
    put(out, cfg.window);
    put(out, cfg.sa);
    put(out, cfg.sg);
    put(out, cfg.g);
    put(out, cfg.thr);
    put(out, LD(std::min(size_t(st.stored), W)));
    put(out, LD(size_t(st.stored) % W));
    put(out, st.stat);
    put(out, LD(st.flag));
}

void add_stationary(Gens &g)
{
    // ---- init: edge rows, then random valid configurations
    g["se23_stationary_init"] = {
        14,
        [](Ctx &c, int k) {
            StRow x = st_random(c, 0);
            const LD tiny = c.is_float ? 1e-20L : 1e-160L;
            const LD huge = c.is_float ? 1e20L : 1e160L;
            switch (k) {
            case 0: x.cfg.sa = kNaN; break;
            case 1: x.cfg.thr = std::numeric_limits<LD>::infinity(); break;
            case 2: x.cfg.window = 1; break;
            case 3: x.cfg.window = SE23_STATIONARY_WMAX + 1; break;
            case 4: x.cfg.sa = 0; break;
            case 5: x.cfg.sg = -0.1L; break;
            case 6: x.cfg.sa = tiny; break;
            case 7: x.cfg.sg = huge; break;
            case 8: x.cfg.g = 0; break;
            case 9: x.cfg.thr = -1; break;
            case 10: x.cfg.window = 2; break;
            case 11: x.cfg.window = SE23_STATIONARY_WMAX; break;
            case 12: x.cfg.g = kNaN; break;
            case 13: x.cfg.window = -4; break;
            default: break;
            }
            Row r;
            put(r, x.cfg.window);
            put(r, x.cfg.sa);
            put(r, x.cfg.sg);
            put(r, x.cfg.g);
            put(r, x.cfg.thr);
            return r;
        },
        [](const Ctx &c, const Row &in, Row &out) {
            Rd rd{in};
            const StCfg cfg{rd.s(), rd.s(), rd.s(), rd.s(), rd.s()};
            const int st = st_init_status(c, cfg);
            if (st == SE23_OK) put_state(out, cfg, StState{});
            return st;
        }};
    // ---- add: the last add of the row's sequence is the call
    g["se23_stationary_add"] = {
        4,
        [](Ctx &c, int k) {
            StRow x = st_random(c, TV_ST_SAMPLES);
            const LD W = x.cfg.window;
            x.k = int(W) + int(c.uniform(0, 9));
            if (k < 3 || c.uniform(0, 1) < 0.2) x.k = 1 + int(c.uniform(0, TV_ST_SAMPLES));
            if (k == 3) x.k = 1; // the first sample
            st_threshold(c, x, k);
            const size_t last = size_t(x.k - 1) % TV_ST_SAMPLES;
            const LD huge = c.is_float ? 1e30L : 1e200L;
            if (k == 0) x.s[last].w(1) = kNaN;
            if (k == 1) x.s[last].f(2) = -std::numeric_limits<LD>::infinity();
            if (k == 2) x.s[last].f(0) = huge; // the statistic overflows
            Row r;
            put_st(r, x);
            return r;
        },
        [](const Ctx &c, const Row &in, Row &out) {
            const StRow x = read_st(in, TV_ST_SAMPLES);
            const StState st = st_run(c, x, x.k);
            if (st.last != SE23_OK) return st.last;
            const size_t W = size_t(x.cfg.window);
            put(out, st.stat);
            put(out, LD(st.flag));
            put(out, LD(st.flag));
            put(out, LD(std::min(size_t(st.stored), W)));
            put(out, LD(size_t(st.stored) % W));
            return int(SE23_OK);
        },
        [](const Row &out) { return Row{std::fabs(out[0]), 0, 0, 0, 0}; }};
    // ---- reset: a detector after k adds of one sample
    g["se23_stationary_reset"] = {
        0,
        [](Ctx &c, int) {
            StRow x = st_random(c, 1);
            x.k = int(c.uniform(0, 40));
            Row r;
            put_st(r, x);
            return r;
        },
        [](const Ctx &, const Row &in, Row &out) {
            const StRow x = read_st(in, 1);
            put_state(out, x.cfg, StState{});
            return int(SE23_OK);
        }};
    // ---- mean and var of the full window (DIM when not full)
    const auto window_input = [](Ctx &c, int k) {
        StRow x = st_random(c, TV_ST_SAMPLES);
        x.k = int(x.cfg.window) + int(c.uniform(0, 9));
        if (k == 0) x.k = int(x.cfg.window) - 1;
        if (k == 1) x.k = int(x.cfg.window);
        Row r;
        put_st(r, x);
        return r;
    };
    const auto window_stats = [](const Ctx &c, const Row &in, Vec3L m[2], Vec3L v[2]) {
        const StRow x = read_st(in, TV_ST_SAMPLES);
        const StState st = st_run(c, x, x.k);
        if (st.win.size() != size_t(x.cfg.window)) return int(SE23_ERR_DIM);
        const LD n = LD(st.win.size());
        m[0] = m[1] = v[0] = v[1] = Vec3L::Zero();
        for (const auto &s : st.win) {
            m[0] += s.w / n;
            m[1] += s.f / n;
        }
        for (const auto &s : st.win) {
            v[0] += Vec3L((s.w - m[0]).array().square().matrix()) / (n - 1);
            v[1] += Vec3L((s.f - m[1]).array().square().matrix()) / (n - 1);
        }
        return int(SE23_OK);
    };
    g["se23_stationary_mean"] = {2, window_input,
                                 [window_stats](const Ctx &c, const Row &in, Row &out) {
                                     Vec3L m[2], v[2];
                                     const int st = window_stats(c, in, m, v);
                                     if (st == SE23_OK) {
                                         put(out, m[0]);
                                         put(out, m[1]);
                                     }
                                     return st;
                                 },
                                 scale_blocks({3, 3})};
    g["se23_stationary_var"] = {2, window_input,
                                [window_stats](const Ctx &c, const Row &in, Row &out) {
                                    Vec3L m[2], v[2];
                                    const int st = window_stats(c, in, m, v);
                                    if (st == SE23_OK) {
                                        put(out, v[0]);
                                        put(out, v[1]);
                                    }
                                    return st;
                                },
                                scale_blocks({1, 1, 1, 1, 1, 1})};
    // Rows of 48 reals (a reset: one fixed output): half the random rows.
    for (const char *n : {"se23_stationary_add", "se23_stationary_reset", "se23_stationary_mean",
                          "se23_stationary_var"}) {
        g[n].n_random = kRandom / 2;
    }
}

// ---- align.h ---------------------------------------------------------------------

LD frame_sign(LD frame) { return frame == SE23_FRAME_NED ? LD(-1) : LD(1); }
bool frame_ok(LD frame) { return frame == SE23_FRAME_NED || frame == SE23_FRAME_ENU; }
bool band_ok(const Vec3L &f)
{
    const LD n = f.norm();
    return n >= LD(SE23_ALIGN_F_MIN) * kG0 && n <= LD(SE23_ALIGN_F_MAX) * kG0;
}

Mat3L euler_zyx(LD roll, LD pitch, LD yaw)
{
    using AA = Eigen::AngleAxis<LD>;
    return Mat3L(AA(yaw, Vec3L::UnitZ()) * AA(pitch, Vec3L::UnitY()) * AA(roll, Vec3L::UnitX()));
}

// R with R^T e_z = s f / |f| and Euler yaw `yaw`.
Mat3L level_ref(LD frame, const Vec3L &f, LD yaw)
{
    const Vec3L d = frame_sign(frame) * f / f.norm();
    const LD dx = std::max(LD(-1), std::min(LD(1), d(0)));
    // Body x vertical (d_y = d_z = 0, of either sign): roll 0, as documented.
    const LD roll = (d(1) == 0 && d(2) == 0) ? LD(0) : std::atan2(d(1), d(2));
    return euler_zyx(roll, std::asin(-dx), yaw);
}

Vec3L earth_rate_n(LD frame, LD lat)
{
    return frame == SE23_FRAME_NED ? Vec3L(kWe * std::cos(lat), 0, -kWe * std::sin(lat))
                                   : Vec3L(0, kWe * std::cos(lat), kWe * std::sin(lat));
}

// TRIAD: R b1 = e_z exactly, R (b1 x b2) along e_z x w_n.
Mat3L triad(const Vec3L &b1, const Vec3L &b2, const Vec3L &w_n)
{
    const Vec3L t1 = b1.normalized();
    const Vec3L t2 = t1.cross(b2).normalized();
    const Vec3L n1 = Vec3L::UnitZ();
    const Vec3L n2 = n1.cross(w_n).normalized();
    Mat3L T, N;
    T << t1, t2, t1.cross(t2);
    N << n1, n2, n1.cross(n2);
    return N * T.transpose();
}

void add_align_only(Gens &g)
{
    g["se23_align_level"] = {
        8,
        [](Ctx &c, int k) {
            LD frame = c.uniform(0, 1) < 0.5 ? 0 : 1;
            Vec3L f = c.axis() * c.uniform(0.6L * kG0, 1.4L * kG0);
            LD yaw = c.uniform(-4, 4);
            switch (k) {
            case 0: f(1) = kNaN; break;
            case 1: yaw = std::numeric_limits<LD>::infinity(); break;
            case 2: frame = 2; break;
            case 3: f = f.normalized() * 0.45L * kG0; break;
            case 4: f = f.normalized() * 1.55L * kG0; break;
            case 5: f = Vec3L::Zero(); break;
            case 6: f = Vec3L(kG0, 0, 0); break; // body x vertical
            case 7: f = Vec3L(0, 0, -kG0); break; // level
            default: break;
            }
            Row r;
            put(r, frame);
            put(r, f);
            put(r, yaw);
            return r;
        },
        [](const Ctx &, const Row &in, Row &out) {
            if (!all_finite(in)) return int(SE23_ERR_NONFINITE);
            Rd rd{in};
            const LD frame = rd.s();
            const Vec3L f = rd.v3();
            const LD yaw = rd.s();
            if (!frame_ok(frame) || !band_ok(f)) return int(SE23_ERR_DOMAIN);
            put(out, level_ref(frame, f, yaw));
            return int(SE23_OK);
        },
        scale_blocks({9})};
    g["se23_align_cov"] = {
        8,
        [](Ctx &c, int k) {
            Mat3L R = rot_k(c, k + n_angles());
            LD sf = c.uniform(1e-3L, 0.5L), n = LD(1 + int(c.uniform(0, 10000)));
            LD gr = c.uniform(9.7L, 9.9L), sy = std::exp(c.uniform(std::log(1e-4L), 0));
            const LD huge = c.is_float ? 1e30L : 1e200L;
            switch (k) {
            case 0: R(2, 1) = kNaN; break;
            case 1: n = 0; break;
            case 2: sf = 0; break;
            case 3: gr = -1; break;
            case 4: sy = 0; break;
            case 5: R *= LD(1.01); break;
            case 6: sf = huge; gr = 1e-10L; break; // tilt^2 overflows
            case 7: sy = huge; break;
            default: break;
            }
            Row r;
            put(r, R);
            put(r, sf);
            put(r, n);
            put(r, gr);
            put(r, sy);
            return r;
        },
        [](const Ctx &c, const Row &in, Row &out) {
            if (!all_finite(in)) return int(SE23_ERR_NONFINITE);
            Rd rd{in};
            const Mat3L R = rd.m3();
            const LD sf = rd.s(), n = rd.s(), gr = rd.s(), sy = rd.s();
            if (n < 1) return int(SE23_ERR_DIM);
            if (!(sf > 0 && gr > 0 && sy > 0)) return int(SE23_ERR_DOMAIN);
            if (!is_rotation(R, c)) return int(SE23_ERR_NOT_ROTATION);
            const LD t2 = sf * sf / (gr * gr * n);
            if (!(t2 < max_real(c) / 1e6L && sy * sy < max_real(c) / 1e6L)) {
                return int(SE23_ERR_NONFINITE);
            }
            const Mat3L P = R.transpose() * Vec3L(t2, t2, sy * sy).asDiagonal() * R;
            put(out, P);
            return int(SE23_OK);
        }};
    g["se23_align_gyrocompass"] = {
        10,
        [](Ctx &c, int k) {
            LD frame = c.uniform(0, 1) < 0.5 ? 0 : 1;
            LD lat = c.uniform(-1.3L, 1.3L);
            const Mat3L R = euler_zyx(c.uniform(-kPi, kPi), c.uniform(-1.3L, 1.3L),
                                      c.uniform(-kPi, kPi));
            const Vec3L gn(0, 0, frame == SE23_FRAME_NED ? 9.81L : -9.81L);
            Vec3L f = R.transpose() * (-gn) + vec3_any(c, 1e-3L);
            Vec3L w = R.transpose() * earth_rate_n(frame, lat) + vec3_any(c, 1e-7L);
            LD n = LD(100 + int(c.uniform(0, 1e5L)));
            LD sw = c.uniform(1e-7L, 1e-5L);
            // sigma_yaw below 0.05 rad
            sw = std::min(sw, 0.05L * std::sqrt(n) * kWe * std::cos(lat));
            switch (k) {
            case 0: lat = kNaN; break;
            case 1: n = 0; break;
            case 2: frame = 2; break;
            case 3: sw = 0; break;
            case 4: lat = kPi / 2 + 1e-3L; break;
            case 5: f *= 0.4L; break;
            case 6: lat = kPi / 2; break; // sigma_yaw unbounded
            case 7: sw = 1e-2L; break; // a MEMS gyro
            case 8: w = Vec3L::Zero(); break;
            case 9: w *= 10; break; // a bias of 10 Earth rates
            default: break;
            }
            Row r;
            put(r, frame);
            put(r, lat);
            put(r, f);
            put(r, w);
            put(r, sw);
            put(r, n);
            return r;
        },
        [](const Ctx &, const Row &in, Row &out) {
            if (!all_finite(in)) return int(SE23_ERR_NONFINITE);
            Rd rd{in};
            const LD frame = rd.s(), lat = rd.s();
            const Vec3L f = rd.v3(), w = rd.v3();
            const LD sw = rd.s(), n = rd.s();
            if (n < 1) return int(SE23_ERR_DIM);
            if (!frame_ok(frame) || !(sw > 0) ||
                !(std::fabs(lat) <= kPi / 2 + LD(SE23_EARTH_LAT_SLACK)) || !band_ok(f)) {
                return int(SE23_ERR_DOMAIN);
            }
            const LD wh = kWe * std::fabs(std::cos(lat));
            const LD sy = sw / (std::sqrt(n) * wh);
            if (!(sy <= LD(SE23_ALIGN_YAW_STD_MAX))) return int(SE23_ERR_DOMAIN);
            const Vec3L b1 = frame_sign(frame) * f / f.norm();
            const LD h = (w - w.dot(b1) * b1).norm();
            if (!(h >= LD(SE23_ALIGN_RATE_MIN) * wh && h <= LD(SE23_ALIGN_RATE_MAX) * wh)) {
                return int(SE23_ERR_DOMAIN);
            }
            const Mat3L R = triad(b1, w, earth_rate_n(frame, lat));
            put(out, R);
            put(out, std::atan2(R(1, 0), R(0, 0)));
            put(out, sy);
            return int(SE23_OK);
        },
        scale_concat({{9, scale_blocks({9})}, {1, scale_at_least_1()}, {1, scale_blocks({1})}})};
}

} // namespace

void add_align(Gens &g)
{
    add_stationary(g);
    add_align_only(g);
}

} // namespace gen
