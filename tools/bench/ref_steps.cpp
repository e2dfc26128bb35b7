// The composite steps of the benchmark's Eigen reference (ref.h), written
// densely: full transition matrices and full products, as a desktop filter
// written with Eigen would. Inputs are the se23 structs, read through maps.
#include "ref.h"
#include "ref.hpp"

using namespace bref;

namespace {

template <int N> Mat<N, N> load_cov(const se23_mat15_t &P)
{
    return ConstRowMap<N, N, SE23_GAUSS_NMAX>(P.m);
}

template <int N> void store_cov(const Mat<N, N> &P, se23_mat15_t &out)
{
    RowMap<N, N, SE23_GAUSS_NMAX>(out.m) = P;
}

// Diagonal of N = diag(sg^2/dt I3, sa^2/dt I3), the sample-averaged white
// noise of the gyro and the accelerometer (gauss.h).
Mat<6, 1> white_noise(const se23_imu_noise_t &nz, Real dt)
{
    Mat<6, 1> n;
    n << Mat<3, 1>::Constant(nz.gyro_noise * nz.gyro_noise / dt),
        Mat<3, 1>::Constant(nz.accel_noise * nz.accel_noise / dt);
    return n;
}

Vec3 corrected(const se23_vec3_t &meas, const se23_vec3_t &bias)
{
    return vec3(meas) + vec3(bias);
}

template <int N>
void predict(const se23_earth_model_t &m, const se23_gauss_t &g, const se23_imu_sample_t &s,
             const se23_imu_noise_t &nz, se23_gauss_t &out)
{
    const Real dt = s.dt;
    const Increment inc = increment(corrected(s.w_ib_b, g.b_g), corrected(s.f_b, g.b_a), dt);
    Mat<N, N> Phi = Mat<N, N>::Identity();
    Phi.template topLeftCorner<9, 9>() = transition(inc.U, dt);
    Mat<N, 6> G = Mat<N, 6>::Zero();
    G.template topRows<9>() = inc.B;
    Mat<N, N> Q = G * white_noise(nz, dt).asDiagonal() * G.transpose();
    if constexpr (N == SE23_GAUSS_N_BIAS) {
        Phi.template topRightCorner<9, 6>() = inc.B;
        Q.diagonal().template segment<3>(SE23_IDX_BG).array() += nz.gyro_walk * nz.gyro_walk * dt;
        Q.diagonal().template segment<3>(SE23_IDX_BA).array() += nz.accel_walk * nz.accel_walk * dt;
    }
    const Mat<N, N> P = load_cov<N>(g.P);
    store_cov<N>(Phi * P * Phi.transpose() + Q, out.P);
    store_pose(pose5(m.gamma) * shift(pose5(g.T), dt) * inc.U, out.T);
    out.b_g = g.b_g;
    out.b_a = g.b_a;
    out.n = N;
}

} // namespace

extern "C" void ref_gamma(const se23_vec3_t *g_n, const se23_vec3_t *w_ie_n, se23_real_t dt,
                          se23_pose_t *out)
{
    store_pose(gamma(vec3(*g_n), vec3(*w_ie_n), dt), *out);
}

extern "C" void ref_gauss_predict(const se23_earth_model_t *model, const se23_gauss_t *g,
                                  const se23_imu_sample_t *s, const se23_imu_noise_t *noise,
                                  se23_gauss_t *out)
{
    if (g->n == SE23_GAUSS_N_POSE) {
        predict<SE23_GAUSS_N_POSE>(*model, *g, *s, *noise, *out);
    } else {
        predict<SE23_GAUSS_N_BIAS>(*model, *g, *s, *noise, *out);
    }
}

extern "C" void ref_preint_add(const se23_preint_unc_t *fu, const se23_imu_sample_t *s,
                               const se23_imu_noise_t *noise, se23_preint_unc_t *out)
{
    const Real dt = s->dt;
    const Increment inc = increment(corrected(s->w_ib_b, fu->b_g), corrected(s->f_b, fu->b_a), dt);
    // The left form (preint_unc.h): F the time shear, Bl = Ad_{Delta+} B_k.
    const Mat5 next = shift(pose5(fu->f.delta), dt) * inc.U;
    const Mat9 F = transition(Mat5::Identity(), dt);
    const Mat96 Bl = adjoint(next) * inc.B;
    const Mat9 P = ConstRowMap<9, 9>(fu->P_left.m);
    RowMap<9, 9>(out->P_left.m) =
        F * P * F.transpose() + Bl * white_noise(*noise, dt).asDiagonal() * Bl.transpose();
    RowMap<9, 6>(out->J_left.m) = F * ConstRowMap<9, 6>(fu->J_left.m) + Bl;
    store_pose(next, out->f.delta);
    out->f.dt = fu->f.dt + dt;
    out->f.n = fu->f.n + 1;
    out->b_g = fu->b_g;
    out->b_a = fu->b_a;
    out->kind = fu->kind;
}

extern "C" int ref_gnss_update(const se23_gauss_t *g, const se23_vec3_t *p_n,
                               const se23_vec3_t *lever_b, const se23_mat3_t *cov,
                               se23_gauss_t *out)
{
    using Mat15 = Mat<15, 15>;
    const Mat5 T = pose5(g->T);
    const Mat3 R = T.block<3, 3>(0, 0);
    const Vec3 l = vec3(*lever_b);
    Mat<3, 15> H = Mat<3, 15>::Zero();
    H.block<3, 3>(0, SE23_IDX_PHI) = -R * hat(l);
    H.block<3, 3>(0, SE23_IDX_RHO) = R;
    const Vec3 z = vec3(*p_n) - (T.block<3, 1>(0, 4) + R * l);
    const Mat3 Rn = ConstRowMap<3, 3>(&cov->m[0][0]);
    const Mat15 P = load_cov<15>(g->P);
    const Mat<15, 3> PHt = P * H.transpose();
    const Eigen::LLT<Mat3> S(H * PHt + Rn);
    if (S.info() != Eigen::Success) {
        return 1;
    }
    const Mat<15, 3> K = S.solve(PHt.transpose()).transpose();
    const Mat<15, 1> dx = K * z;
    const Mat15 IKH = Mat15::Identity() - K * H;
    store_cov<15>(IKH * P * IKH.transpose() + K * Rn * K.transpose(), out->P);
    store_pose(T * se23_exp(dx.head<9>()), out->T);
    vec3(out->b_g) = vec3(g->b_g) + dx.segment<3>(SE23_IDX_BG);
    vec3(out->b_a) = vec3(g->b_a) + dx.segment<3>(SE23_IDX_BA);
    out->n = SE23_GAUSS_N_BIAS;
    return 0;
}
