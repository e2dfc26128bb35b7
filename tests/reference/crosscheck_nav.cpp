// Cross-check of include/se23/imu.h, earth.h and preint.h against the
// independent ground truth of ref_nav.hpp:
//  - the exact increment and Gamma' against augmented-matrix exponentials,
//  - one propagation step (flat and rotating Earth, through the carried
//    state) against RK4 of the continuous equations,
//  - 60 s at 100 Hz on a smooth 3D trajectory, step by step and through one
//    preintegrated factor, against RK4, for flat Earth, the real Earth rate at
//    45 deg and an exaggerated Omega = 0.05 rad/s (issue 3: within 1e-9
//    relative in position and velocity, double build).
// See crosscheck.hpp. Usage: crosscheck_nav [markdown-output-file]
#include "crosscheck.hpp"
#include "ref_nav.hpp"

extern "C" {
#include "se23/earth.h"
#include "se23/imu.h"
#include "se23/preint.h"
}

namespace {

using namespace xc;

constexpr long kN = 2000;
constexpr int kRk4Sub = 8;     // RK4 sub-steps per 100 Hz sample: h = 1.25 ms
constexpr int kRate = 100;     // Hz
constexpr int kSeconds = 60;
const LD kWe = 7.292115e-5L;   // WGS-84 Earth rate [rad/s]

// |got - exp| / scale, the worst entry; NaN counts as infinite.
template <class A, class B> double err_scaled(const A &got, const B &expected, LD scale)
{
    const double r = double((got - expected).cwiseAbs().maxCoeff() / scale);
    return std::isfinite(r) ? r : INFINITY;
}

// The error of a 5x5 pose (R, a, b) with the vector columns measured
// relative to their natural sizes sa and sb (e.g. |f| dt and |f| dt^2).
double err_pose_scaled(const Mat5L &got, const Mat5L &exp, LD sa, LD sb)
{
    return std::max({err_block(got.block<3, 3>(0, 0), exp.block<3, 3>(0, 0)),
                     err_scaled(got.block<3, 1>(0, 3), exp.block<3, 1>(0, 3), sa),
                     err_scaled(got.block<3, 1>(0, 4), exp.block<3, 1>(0, 4), sb)});
}

se23_imu_sample_t sample_c(const Vec3L &w, const Vec3L &f, LD dt)
{
    se23_imu_sample_t s;
    s.w_ib_b = to_c(w);
    s.f_b = to_c(f);
    s.dt = real(dt);
    return s;
}

// Upsilon against expm: rotation angles |w| dt over [0, 3] (edge angles
// included), dt log-uniform over [1e-4, 1] s, |f| up to 20 m/s^2.
void check_increment(Report &rep, Rng &rng)
{
    Row &row = rep.row("imu_increment", "R,dV,dX", 2e-14, 16 * FLT_EPSILON);
    sweep_rotvecs(rng, kN, 3, [&](const Vec3L &phi, LD theta) {
        const LD dt = rnd(rng.log_uniform(1e-4L, 1));
        const Vec3L w = rnd(Vec3L(phi / dt));
        const Vec3L f = rnd(rng.matrix<3, 1>(20));
        const se23_imu_sample_t s = sample_c(w, f, dt);
        se23_pose_t u;
        const se23_status_t st = se23_imu_increment(&s, &u);
        rep.status(row, st, theta);
        if (st == SE23_OK) {
            const LD fn = std::max<LD>(f.norm(), 1e-3L);
            rep.add(row, err_pose_scaled(out(u), upsilon_expm(w, f, dt), fn * dt, fn * dt * dt),
                    theta);
        }
    });
}

// Gamma' against expm: |Omega| t over [0, 3], t log-uniform over
// [1e-4, 3600] s, |g| about 10 m/s^2.
void check_gamma(Report &rep, Rng &rng)
{
    Row &row = rep.row("earth_gamma", "R,Gv,Gx", 2e-14, 16 * FLT_EPSILON);
    sweep_rotvecs(rng, kN, 3, [&](const Vec3L &phi, LD theta) {
        const LD t = rnd(rng.log_uniform(1e-4L, 3600));
        const Vec3L Om = rnd(Vec3L(phi / t));
        const Vec3L g = rnd(Vec3L(rng.matrix<3, 1>(1) + Vec3L(0, 0, 9.8L)));
        const se23_vec3_t gc = to_c(g), oc = to_c(Om);
        se23_pose_t G;
        const se23_status_t st = se23_earth_gamma(&gc, &oc, real(t), &G);
        rep.status(row, st, theta);
        if (st == SE23_OK) {
            const LD gn = g.norm();
            rep.add(row, err_pose_scaled(out(G), gamma_expm(g, Om, t), gn * t, gn * t * t),
                    theta);
        }
    });
}

// A model with gravity g and Earth rate Om, nominal dt.
se23_earth_model_t model_c(const Vec3L &g, const Vec3L &Om, LD dt)
{
    const se23_vec3_t gc = to_c(g), oc = to_c(Om);
    se23_earth_model_t m;
    if (se23_earth_model_init(&gc, &oc, real(dt), real(dt), &m) != SE23_OK) {
        std::printf("model_init failed\n");
        std::exit(2);
    }
    return m;
}

// One C step on the user's state: carried_from_user, step, user_from_carried.
se23_status_t step_user(const se23_earth_model_t &m, const Mat5L &U, const se23_imu_sample_t &s,
                        se23_pose_t *out_user)
{
    se23_pose_t T = to_pose(U), Tc;
    se23_imu_carried_from_user(&m, &T, &Tc);
    const se23_status_t st = se23_imu_step(&m, &Tc, &s, &Tc);
    if (st == SE23_OK) {
        se23_imu_user_from_carried(&m, &Tc, out_user);
    }
    return st;
}

// The three Earth rates of issue 3, NED at 45 deg.
Vec3L earth_rate(int which)
{
    const LD c = std::sqrt(LD(0.5));
    switch (which) {
    case 0:
        return Vec3L::Zero();
    case 1:
        return Vec3L(kWe * c, 0, -kWe * c);
    default:
        return Vec3L(0.05L * 0.6L, 0, -0.05L * 0.8L);
    }
}
const char *const kModelName[] = {"flat", "earth45", "omega0.05"};

// One 100 Hz step from random states against RK4 (one sample, 8 sub-steps).
void check_step(Report &rep, Rng &rng)
{
    for (int which = 0; which < 3; ++which) {
        Row &row = rep.row(std::string("imu_step_") + kModelName[which], "R,v,p", 1e-13,
                           64 * FLT_EPSILON);
        const Vec3L g = rnd(Vec3L(0, 0, 9.80619777L));
        const Vec3L Om = rnd(earth_rate(which));
        const LD dt = rnd(LD(0.01L));
        const se23_earth_model_t m = model_c(g, Om, dt);
        sweep_rotvecs(rng, kN / 4, 0.05L, [&](const Vec3L &phi, LD theta) {
            const Vec3L w = rnd(Vec3L(phi / dt));
            const Vec3L f = rnd(Vec3L(rng.matrix<3, 1>(15) - g));
            const Mat5L U = rnd(pose5(so3_exp(Vec3L(rng.axis() * rng.uniform(0, 3))),
                                      rng.matrix<3, 1>(300), rng.matrix<3, 1>(5000)));
            se23_pose_t got;
            const se23_status_t st = step_user(m, U, sample_c(w, f, dt), &got);
            rep.status(row, st, theta);
            if (st == SE23_OK) {
                rep.add(row, err_pose(out(got), nav_rk4(U, w, f, g, Om, dt, 2 * kRk4Sub)), theta);
            }
        });
    }
}

// The smooth 3D test motion: slow sinusoidal body rates and specific force,
// sampled at the start of each interval (zero-order hold).
void smooth_sample(int k, Vec3L *w, Vec3L *f)
{
    const LD t = LD(k) / kRate;
    *w = rnd(Vec3L(0.3L * std::sin(0.5L * t), 0.2L * std::cos(0.3L * t + 0.4L),
                   0.1L + 0.15L * std::sin(0.7L * t)));
    *f = rnd(Vec3L(1.0L + 0.8L * std::sin(0.4L * t), 0.5L * std::cos(0.6L * t),
                   -9.81L + 0.3L * std::sin(0.9L * t)));
}

// |got - exp| / |exp| of a 3-vector (Euclidean norms).
double err_vec_rel(const Vec3L &got, const Vec3L &exp)
{
    const double r = double((got - exp).norm() / exp.norm());
    return std::isfinite(r) ? r : INFINITY;
}

// 60 s at 100 Hz: step by step and through one factor, against RK4.
void check_trajectories(Report &rep)
{
    for (int which = 0; which < 3; ++which) {
        const std::string name = kModelName[which];
        // Double: issue 3 asks for 1e-9; the measured worst is ~3e-13, so the
        // bound is set 100 times tighter than the issue's. Float: a 60 s
        // factor loses more than steps do, because its Deltas grow as g t and
        // g t^2 / 2 and cancel against Gamma' in the prediction (tools/doc/pages/accuracy.md).
        Row &steps_p = rep.row("60s_steps_" + name + "_p", "rel |p|", 1e-11, 5e-4);
        Row &steps_v = rep.row("60s_steps_" + name + "_v", "rel |v|", 1e-11, 5e-4);
        Row &fac_p = rep.row("60s_factor_" + name + "_p", "rel |p|", 1e-11, 2e-3);
        Row &fac_v = rep.row("60s_factor_" + name + "_v", "rel |v|", 1e-11, 2e-3);
        Row &att = rep.row("60s_steps_" + name + "_R", "block", 1e-12, 5e-5);
        const Vec3L g = rnd(Vec3L(0, 0, 9.80619777L));
        const Vec3L Om = rnd(earth_rate(which));
        const LD dt = rnd(LD(0.01L));
        const se23_earth_model_t m = model_c(g, Om, dt);
        const LD c = std::cos(kPi / 6), s = std::sin(kPi / 6);
        Mat3L R0;
        R0 << c, -s, 0, s, c, 0, 0, 0, 1;
        const Mat5L U0 = rnd(pose5(R0, Vec3L(10, 2, -1), Vec3L(100, -50, 20)));

        Mat5L truth = U0;
        se23_pose_t T = to_pose(U0), Tc, U;
        se23_imu_carried_from_user(&m, &T, &Tc);
        se23_preint_t fac;
        se23_preint_reset(&fac);
        long bad = 0;
        for (int k = 0; k < kSeconds * kRate; ++k) {
            Vec3L w, f;
            smooth_sample(k, &w, &f);
            const se23_imu_sample_t smp = sample_c(w, f, dt);
            bad += (se23_imu_step(&m, &Tc, &smp, &Tc) != SE23_OK);
            bad += (se23_preint_add(&fac, &smp) != SE23_OK);
            truth = nav_rk4(truth, w, f, g, Om, dt, kRk4Sub);
        }
        se23_imu_user_from_carried(&m, &Tc, &U);
        se23_pose_t P;
        bad += (se23_preint_predict(&m, &fac, &T, &P) != SE23_OK);
        rep.status(steps_p, bad ? SE23_ERR_DOMAIN : SE23_OK, Om.norm());
        const Mat5L got = out(U), pred = out(P);
        const Vec3L tp = truth.block<3, 1>(0, 4), tv = truth.block<3, 1>(0, 3);
        rep.add(steps_p, err_vec_rel(got.block<3, 1>(0, 4), tp), Om.norm());
        rep.add(steps_v, err_vec_rel(got.block<3, 1>(0, 3), tv), Om.norm());
        rep.add(fac_p, err_vec_rel(pred.block<3, 1>(0, 4), tp), Om.norm());
        rep.add(fac_v, err_vec_rel(pred.block<3, 1>(0, 3), tv), Om.norm());
        rep.add(att, err_block(got.block<3, 3>(0, 0), truth.block<3, 3>(0, 0)), Om.norm());
        std::printf("  %s: |p| = %.6Lg m, |v| = %.6Lg m/s after %d s\n", name.c_str(), tp.norm(),
                    tv.norm(), kSeconds);
    }
}

} // namespace

int main(int argc, char **argv)
{
    Report rep("crosscheck_nav", argc, argv);
    Rng rng(0x5e23'0003);
    check_increment(rep, rng);
    check_gamma(rep, rng);
    check_step(rep, rng);
    check_trajectories(rep);
    return rep.finish();
}
