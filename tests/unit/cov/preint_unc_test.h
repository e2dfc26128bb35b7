/**
 * @file preint_unc_test.h
 * @brief Helpers of the preintegrated-factor tests (test_preint_unc,
 *        test_preint_classic), header-only: a smooth 3D motion sampled at
 *        100 Hz, raw samples of an IMU with a known bias estimate, the factor
 *        of the library, and a double re-integration (exact or Euler
 *        increments) written from the math, independent of the code under
 *        test.
 *
 * Include after <cmocka.h> and gauss_test.h.
 */
#ifndef SE23_PREINT_UNC_TEST_H
#define SE23_PREINT_UNC_TEST_H

#include <math.h>
#include <string.h>

#include "gauss_test.h"
#include "se23/preint_unc.h"
#include "se23_test.h"

#define HZ 100
#define DT (1.0 / HZ)
#define PI 3.14159265358979323846

/* J against central differences, relative to the largest entry of the
 * column. Double: differences good to ~1e-9. Float: J accumulates rounding
 * over 100 samples. */
#if SE23_CFG_DOUBLE
#define JAC_TOL 1e-7
#else
#define JAC_TOL 2e-4
#endif
#define FD_GYRO 1e-5  /* rad/s */
#define FD_ACCEL 0.1  /* m/s^2: the Deltas are affine in the accel bias */

static const se23_imu_noise_t QUIET = {SE23_R(0), SE23_R(0), SE23_R(0), SE23_R(0)};
static const se23_imu_noise_t NOISE = {SE23_R(0.02), SE23_R(0.2), SE23_R(0), SE23_R(0)};

/* A bias estimate and its flat form (dg, da). */
static const double BBAR[6] = {0.01, -0.02, 0.005, 0.1, -0.2, 0.05};

/* Error-free corrected inputs of sample k: smooth 3D motion, every axis
 * turning, specific force dominated by gravity. */
static inline void motion(int k, double w[3], double f[3])
{
    const double t = (k + 0.5) * DT;
    w[0] = 0.3 * sin(0.5 * t) + 0.2;
    w[1] = 0.2 * cos(0.3 * t + 0.4);
    w[2] = 0.1 + 0.15 * sin(0.7 * t);
    f[0] = 1.0 + 0.8 * sin(0.4 * t);
    f[1] = 0.5 * cos(0.6 * t);
    f[2] = -9.81 + 0.3 * sin(0.9 * t);
}

/* The raw sample k of an IMU whose estimate bbar + db corrects it to the
 * motion: reading = motion - bbar - db (gauss.h sensor convention). */
static inline se23_imu_sample_t raw_sample(int k, const double db[6])
{
    double w[3], f[3];
    motion(k, w, f);
    se23_imu_sample_t s;
    for (int i = 0; i < 3; ++i) {
        s.w_ib_b.v[i] = (se23_real_t)(w[i] - BBAR[i] - db[i]);
        s.f_b.v[i] = (se23_real_t)(f[i] - BBAR[3 + i] - db[3 + i]);
    }
    s.dt = SE23_R(DT);
    return s;
}

static inline void bias_vecs(const double b[6], se23_vec3_t *bg, se23_vec3_t *ba)
{
    for (int i = 0; i < 3; ++i) {
        bg->v[i] = (se23_real_t)b[i];
        ba->v[i] = (se23_real_t)b[3 + i];
    }
}

/* fu = the factor of n raw samples (db = 0) at the estimate BBAR, with the
 * classical Jacobians (se23_preint_unc_reset_classic). */
static inline void make_factor(int n, se23_input_jac_kind_t kind,
                        const se23_imu_noise_t *noise, se23_preint_unc_t *fu)
{
    static const double zero[6] = {0};
    se23_vec3_t bg, ba;
    bias_vecs(BBAR, &bg, &ba);
    memset(fu, 0, sizeof *fu); /* padding too: the tests compare bytes */
    assert_int_equal(se23_preint_unc_reset_classic(&bg, &ba, kind, fu), SE23_OK);
    for (int k = 0; k < n; ++k) {
        const se23_imu_sample_t s = raw_sample(k, zero);
        assert_int_equal(se23_preint_unc_add(fu, &s, noise), SE23_OK);
    }
}

/* P and J of fu in the paper's form (se23_preint_unc_cov). */
typedef struct {
    se23_mat9_t P;
    se23_mat9x6_t J;
} paper_form_t;

static inline paper_form_t paper_form(const se23_preint_unc_t *fu)
{
    paper_form_t out;
    assert_int_equal(se23_preint_unc_cov(fu, &out.P, &out.J), SE23_OK);
    return out;
}

/* D = the double re-integration of n samples of corrected inputs
 * motion + e (Phi_dt then the increment, preint.h); exact increments, or
 * Euler ones (exp(w dt), dt f, dt^2 f / 2) when euler. */
static inline void ref_factor(int n, const double e[6], int euler, gt_m5_t *D)
{
    gt_m5_identity(D);
    for (int k = 0; k < n; ++k) {
        double w[3], f[3];
        motion(k, w, f);
        for (int i = 0; i < 3; ++i) {
            w[i] += e[i];
            f[i] += e[3 + i];
        }
        gt_m5_t U;
        if (euler) {
            const double xi[9] = {w[0] * DT, w[1] * DT, w[2] * DT, 0, 0, 0, 0, 0, 0};
            gt_exp(xi, &U);
            for (int i = 0; i < 3; ++i) {
                U.m[i][3] = DT * f[i];
                U.m[i][4] = 0.5 * DT * DT * f[i];
            }
        } else {
            gt_increment(w, f, DT, &U);
        }
        for (int i = 0; i < 3; ++i) {
            D->m[i][4] += DT * D->m[i][3];
        }
        gt_m5_mul(D, &U, D);
    }
}

static inline void pose_of(const gt_m5_t *M, se23_pose_t *T)
{
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            T->R.m[i][j] = (se23_real_t)M->m[i][j];
        }
        T->v.v[i] = (se23_real_t)M->m[i][3];
        T->p.v[i] = (se23_real_t)M->m[i][4];
    }
}

/* |a.v - b.v| and |a.p - b.p|. */
static inline void vp_errors(const se23_pose_t *a, const se23_pose_t *b, double *ev, double *ep)
{
    double sv = 0, sp = 0;
    for (int i = 0; i < 3; ++i) {
        const double dv = (double)a->v.v[i] - b->v.v[i];
        const double dp = (double)a->p.v[i] - b->p.v[i];
        sv += dv * dv;
        sp += dp * dp;
    }
    *ev = sqrt(sv);
    *ep = sqrt(sp);
}


#endif /* SE23_PREINT_UNC_TEST_H */
