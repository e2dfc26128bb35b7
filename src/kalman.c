/* Kalman update in exponential coordinates; see kalman.h.
 *
 * Structure. Only the 3-column blocks of H (phi, nu, rho, b_g, b_a) that
 * hold a nonzero in the m rows take part: a runtime scan of H (fused with
 * its finiteness check, 4 m n operations) keeps se23_meas_t dense and
 * general. The covariance work (C = P H^T, S, its Cholesky factor, the
 * gain and P+ = P - U U^T, with the operation count and the argument for
 * that form) is in kalman_cov.c.
 *
 * Validation (types.h): the measurement is the caller's and is checked on
 * every call (m; z and H finite; R symmetric PSD, m x m); the state g is
 * trusted (n must be 9 or 15; se23_gauss_check only with
 * SE23_CFG_DEEP_CHECKS).
 *
 * Order. Everything that can fail is decided before the first store: the
 * covariance is stored first (its work arrays are then released), then the
 * mean is retracted, which cannot fail: the correction is bounded
 * (CORR_MAX) and the mean within MEAN_MAX, so every value stays finite, and
 * R exp(phi^) is within SE23_CFG_ROT_TOL + a few eps of SO(3), which
 * se23_so3_normalize repairs. The retraction (whose sin/cos may take
 * newlib's large-argument reduction) thus never shares the stack with the
 * covariance's work arrays. */
#include "se23/kalman.h"

#include <float.h>

#include "argcheck.h"
#include "kalman_cov.h"
#include "linalg.h"
#include "se23/se23.h"
#include "se23/so3.h"
#include "se23_math.h"

enum { S = SE23_GAUSS_NMAX, M = SE23_MEAS_MMAX, NBLK = SE23_KALMAN_NBLK };

/* |dx_k| <= CORR_MAX: |phi|^2 <= 3 CORR_MAX^2 cannot overflow, and the
 * entries of exp(phi^) and J(phi) (at most 3 in magnitude), so those of
 * R J(phi) nu (at most 27 CORR_MAX), stay far below MEAN_MAX.
 * |mean entry| <= MEAN_MAX: adding such a correction cannot overflow. */
#if SE23_CFG_DOUBLE
#define CORR_MAX SE23_R(1e150)
#define MEAN_MAX (SE23_R(DBL_MAX) / SE23_R(4))
#else
#define CORR_MAX SE23_R(1e18)
#define MEAN_MAX (SE23_R(FLT_MAX) / SE23_R(4))
#endif

/* Scans the first n columns of H in rows 0..m-1 once: returns 0 if an
 * entry is not finite (x * 0 is 0 for finite x, NaN for NaN or Inf, and
 * never overflows), else sets blk[0..*nb-1] to the 3-column blocks with a
 * nonzero (a sum of magnitudes is > 0 exactly when one of them is). */
static int scan_h(const se23_meas_t *y, int n, int blk[NBLK], int *nb)
{
    se23_real_t bad = SE23_R(0);
    int count = 0;
    for (int b = 0; b < n / 3; ++b) {
        se23_real_t mag = SE23_R(0);
        for (int r = 0; r < y->m; ++r) {
            const se23_real_t *h = &y->H[S * r + 3 * b];
            mag += se23_fabs(h[0]) + se23_fabs(h[1]) + se23_fabs(h[2]);
            bad += h[0] * SE23_R(0) + h[1] * SE23_R(0) + h[2] * SE23_R(0);
        }
        if (mag > SE23_R(0)) {
            blk[count] = b;
            ++count;
        }
    }
    *nb = count;
    return se23_is_finite(bad);
}

/* The caller's measurement: 1 <= m <= 9, z and the first n columns of H
 * finite, R a valid covariance; blk, nb from scan_h. O(m n + m^3). */
static se23_status_t check_meas(const se23_meas_t *y, int n, int blk[NBLK],
                                int *nb)
{
    const int m = y->m;
    if (m < 1 || m > M) {
        return SE23_ERR_DIM;
    }
    if (!se23_all_finite(y->z, m) || !scan_h(y, n, blk, nb)) {
        return SE23_ERR_NONFINITE;
    }
    return se23_meas_cov_check(y->R, m, M);
}

/* Nonzero if every entry of the mean (v, p, biases) is within MEAN_MAX
 * (NaN is not). */
static int mean_in_range(const se23_gauss_t *g)
{
    const se23_real_t *parts[4] = {g->T.v.v, g->T.p.v, g->b_g.v, g->b_a.v};
    for (int k = 0; k < 4; ++k) {
        for (int i = 0; i < 3; ++i) {
            if (!(se23_fabs(parts[k][i]) <= MEAN_MAX)) {
                return 0;
            }
        }
    }
    return 1;
}

/* out mean = g mean corrected by dx: T exp(dx_xi), R re-orthonormalised,
 * biases + dx_db (n = 15), n. Cannot fail for the bounded dx of
 * se23_kalman_cov and a mean within MEAN_MAX (file comment). out may alias
 * g. */
static void retract(const se23_gauss_t *g, const se23_real_t *dx,
                    se23_gauss_t *out)
{
    se23_tangent_t xi;
    se23_pose_t E;
    for (int i = 0; i < 9; ++i) {
        xi.v[i] = dx[i];
    }
    (void)se23_exp(&xi, &E);
    se23_compose(&g->T, &E, &out->T);
    /* Each product leaves R about an epsilon further from SO(3); without
     * this an R that passed the rotation test could come back outside it
     * and fail the next call (as in se23_imu_transition). */
    (void)se23_so3_normalize(&out->T.R, &out->T.R);
    if (g->n == SE23_GAUSS_N_BIAS) {
        for (int i = 0; i < 3; ++i) {
            out->b_g.v[i] = g->b_g.v[i] + dx[SE23_IDX_BG + i];
            out->b_a.v[i] = g->b_a.v[i] + dx[SE23_IDX_BA + i];
        }
    } else {
        out->b_g = g->b_g;
        out->b_a = g->b_a;
    }
    out->n = g->n;
}

se23_status_t se23_kalman_update(const se23_gauss_t *g, const se23_meas_t *y,
                                 se23_gauss_t *out, se23_real_t *nis)
{
    SE23_CHECK_NOT_NULL(g);
    SE23_CHECK_NOT_NULL(y);
    SE23_CHECK_NOT_NULL(out);
    if (g->n != SE23_GAUSS_N_POSE && g->n != SE23_GAUSS_N_BIAS) {
        return SE23_ERR_DIM;
    }
    int blk[NBLK], nb = 0;
#if SE23_CFG_DEEP_CHECKS
    se23_status_t st = se23_gauss_check(g);
    if (st == SE23_OK) {
        st = check_meas(y, g->n, blk, &nb);
    }
#else
    se23_status_t st = check_meas(y, g->n, blk, &nb);
#endif
    if (st != SE23_OK) {
        return st;
    }
    if (!mean_in_range(g)) {
        return SE23_ERR_NONFINITE;
    }
    se23_real_t dx[S], q;
    st = se23_kalman_cov(g, y, blk, nb, CORR_MAX, dx, &q, out->P.m);
    if (st != SE23_OK) {
        return st;
    }
    retract(g, dx, out);
    if (nis != NULL) {
        *nis = q;
    }
    return SE23_OK;
}
