// Ground truth for IMU propagation: RK4 of the continuous navigation
// equations and augmented-matrix exponentials. See ref_nav.hpp.
#include "ref_nav.hpp"

namespace se23ref {

namespace {

struct Nav {
    Mat3L R;
    Vec3L v;
    Vec3L p;
};

Nav axpy(const Nav &x, LD h, const Nav &d)
{
    return Nav{x.R + h * d.R, x.v + h * d.v, x.p + h * d.p};
}

// Right-hand side of paper eq. nav:eq_Coriolis.
Nav rhs(const Nav &x, const Vec3L &w, const Vec3L &f, const Vec3L &g, const Vec3L &Omega)
{
    const Mat3L Wx = hat3(Omega);
    return Nav{Mat3L(-Wx * x.R + x.R * hat3(w)),
               Vec3L(g + x.R * f - 2 * Wx * x.v - Wx * (Wx * x.p)), x.v};
}

} // namespace

Mat5L nav_rk4(const Mat5L &T, const Vec3L &w, const Vec3L &f, const Vec3L &g,
              const Vec3L &Omega, LD dt, int n)
{
    Nav x{T.block<3, 3>(0, 0), T.block<3, 1>(0, 3), T.block<3, 1>(0, 4)};
    const LD h = dt / n;
    for (int i = 0; i < n; ++i) {
        const Nav k1 = rhs(x, w, f, g, Omega);
        const Nav k2 = rhs(axpy(x, h / 2, k1), w, f, g, Omega);
        const Nav k3 = rhs(axpy(x, h / 2, k2), w, f, g, Omega);
        const Nav k4 = rhs(axpy(x, h, k3), w, f, g, Omega);
        x.R += h / 6 * (k1.R + 2 * k2.R + 2 * k3.R + k4.R);
        x.v += h / 6 * (k1.v + 2 * k2.v + 2 * k3.v + k4.v);
        x.p += h / 6 * (k1.p + 2 * k2.p + 2 * k3.p + k4.p);
    }
    return pose5(x.R, x.v, x.p);
}

Mat5L upsilon_expm(const Vec3L &w, const Vec3L &f, LD dt)
{
    MatXL A = MatXL::Zero(5, 5);
    A.block<3, 3>(0, 0) = hat3(w) * dt;
    A.block<3, 1>(0, 3) = f * dt;
    A(3, 4) = dt;
    const MatXL E = expm(A);
    return pose5(Mat3L(E.block<3, 3>(0, 0)), Vec3L(E.block<3, 1>(0, 3)),
                 Vec3L(E.block<3, 1>(0, 4)));
}

Mat5L gamma_expm(const Vec3L &g, const Vec3L &Omega, LD t)
{
    MatXL A = MatXL::Zero(7, 7);
    A.block<3, 3>(0, 0) = -hat3(Omega) * t;
    A.block<3, 1>(0, 6) = g * t;
    A.block<3, 3>(3, 0) = Mat3L::Identity() * t;
    A.block<3, 3>(3, 3) = -hat3(Omega) * t;
    const MatXL E = expm(A);
    return pose5(Mat3L(E.block<3, 3>(0, 0)), Vec3L(E.block<3, 1>(0, 6)),
                 Vec3L(E.block<3, 1>(3, 6)));
}

} // namespace se23ref
