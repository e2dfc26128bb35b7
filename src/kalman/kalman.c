/* Kalman update in exponential coordinates; see kalman.h.
 *
 * Structure. Only the 3-column blocks of H (phi, nu, rho, b_g, b_a) that
 * hold a nonzero in the m rows take part: a runtime scan of H (fused with
 * its finiteness check, 4 m n operations) keeps se23_meas_t dense and
 * general. The covariance work (C = P H^T, S, its Cholesky factor, the
 * gain and P+ = P - U U^T, with the operation count and the argument for
 * that form) and the retraction are in kalman_halves.c.
 *
 * Validation (types.h): the measurement is the caller's and is checked on
 * every call (m; z and H finite; R symmetric PSD, m x m); the state g is
 * trusted (n must be 9 or 15; se23_gauss_check only with
 * SE23_CFG_DEEP_CHECKS).
 *
 * Order. Everything that can fail is decided before the first store: the
 * covariance half stores P+ last, after its checks (its work arrays are
 * then released); the mean half cannot fail (kalman_halves.h: the
 * correction is bounded and the mean within range, checked here). So the
 * retraction, whose sin/cos may take newlib's large-argument reduction,
 * never shares the stack with the covariance's work arrays. */
#include "se23/kalman.h"

#include "../base/argcheck.h"
#include "kalman_nhc.h"
#include "kalman_halves.h"
#include "kalman_rest.h"
#include "../base/linalg.h"
#include "../base/se23_math.h"

enum { S = SE23_GAUSS_NMAX, M = SE23_MEAS_MMAX };

/* Scans the first n columns of H in rows 0..m-1 once: returns 0 if an
 * entry is not finite (x * 0 is 0 for finite x, NaN for NaN or Inf, and
 * never overflows), else sets bit b of *mask for each 3-column block b
 * with a nonzero (a sum of magnitudes is > 0 exactly when one is). */
static int scan_h(const se23_meas_t *y, int n, unsigned *mask)
{
    se23_real_t bad = SE23_R(0);
    unsigned found = 0u;
    for (int b = 0; b < n / 3; ++b) {
        se23_real_t mag = SE23_R(0);
        for (int r = 0; r < y->m; ++r) {
            const se23_real_t *h = &y->H[S * r + 3 * b];
            mag += se23_fabs(h[0]) + se23_fabs(h[1]) + se23_fabs(h[2]);
            bad = se23_fma(h[0], SE23_R(0), bad);
            bad = se23_fma(h[1], SE23_R(0), bad);
            bad = se23_fma(h[2], SE23_R(0), bad);
        }
        if (mag > SE23_R(0)) {
            found |= 1u << (unsigned)b;
        }
    }
    *mask = found;
    return se23_is_finite(bad);
}

/* The caller's measurement: 1 <= m <= 9, z and the first n columns of H
 * finite, R a valid covariance; mask from scan_h. O(m n + m^3). */
static se23_status_t check_meas(const se23_meas_t *y, int n, unsigned *mask)
{
    const int m = y->m;
    if (m < 1 || m > M) {
        return SE23_ERR_DIM;
    }
    if (!se23_all_finite(y->z, m) || !scan_h(y, n, mask)) {
        return SE23_ERR_NONFINITE;
    }
    return se23_meas_cov_check(y->R, m, M);
}

/* What both updates check before the covariance half: n, the caller's
 * measurement (mask from scan_h), the mean's range. */
static se23_status_t update_check(const se23_gauss_t *g, const se23_meas_t *y,
                                  unsigned *mask)
{
    if (g->n != SE23_GAUSS_N_POSE && g->n != SE23_GAUSS_N_BIAS) {
        return SE23_ERR_DIM;
    }
#if SE23_CFG_DEEP_CHECKS
    se23_status_t st = se23_gauss_check(g);
    if (st == SE23_OK) {
        st = check_meas(y, g->n, mask);
    }
#else
    se23_status_t st = check_meas(y, g->n, mask);
#endif
    if (st == SE23_OK && !se23_kalman_mean_in_range(g)) {
        st = SE23_ERR_NONFINITE;
    }
    return st;
}

/* The mean half, after a covariance half that succeeded (cannot fail). */
static void update_finish(const se23_gauss_t *g, const se23_real_t *dx, se23_real_t q,
                          se23_gauss_t *out, se23_real_t *nis)
{
    se23_kalman_retract(g, dx, out);
    if (nis != NULL) {
        *nis = q;
    }
}

/* Not a wrapper of se23_kalman_update_work on purpose: here the work area lives
 * only in se23_kalman_cov's frame, which has returned before the retraction
 * (se23_exp -> sincos) runs, so the two never stack. As a wrapper holding the
 * work area in this frame the call measured 1,304 B on M4F (make gates-target),
 * over the 1,024 B budget. */
se23_status_t se23_kalman_update(const se23_gauss_t *g, const se23_meas_t *y,
                                 se23_gauss_t *out, se23_real_t *nis)
{
    SE23_CHECK_NOT_NULL(g);
    SE23_CHECK_NOT_NULL(y);
    SE23_CHECK_NOT_NULL(out);
    unsigned mask = 0u;
    se23_real_t dx[S], q;
    se23_status_t st = update_check(g, y, &mask);
    if (st == SE23_OK) {
        st = se23_kalman_cov(g, y, mask, dx, &q, out->P.m);
    }
    if (st == SE23_OK) {
        update_finish(g, dx, q, out, nis);
    }
    return st;
}

se23_status_t se23_kalman_update_work(const se23_gauss_t *g, const se23_meas_t *y,
                                      se23_kalman_work_t *w, se23_gauss_t *out,
                                      se23_real_t *nis)
{
    SE23_CHECK_NOT_NULL(g);
    SE23_CHECK_NOT_NULL(y);
    SE23_CHECK_NOT_NULL(w);
    SE23_CHECK_NOT_NULL(out);
    unsigned mask = 0u;
    se23_real_t dx[S], q;
    se23_status_t st = update_check(g, y, &mask);
    if (st == SE23_OK) {
        st = se23_kalman_cov_work(g, y, mask, w, dx, &q, out->P.m);
    }
    if (st == SE23_OK) {
        update_finish(g, dx, q, out, nis);
    }
    return st;
}

/* What the rest update checks of the state before its covariance half:
 * the mean's range (and with SE23_CFG_DEEP_CHECKS se23_gauss_check). */
static se23_status_t rest_check(const se23_gauss_t *g)
{
#if SE23_CFG_DEEP_CHECKS
    const se23_status_t st = se23_gauss_check(g);
    if (st != SE23_OK) {
        return st;
    }
#endif
    return (se23_kalman_mean_in_range(g) != 0) ? SE23_OK : SE23_ERR_NONFINITE;
}

/* As se23_kalman_update: the covariance half's frame (its factors in wk)
 * has returned before the retraction runs. */
se23_status_t se23_kalman_rest(const se23_gauss_t *g, const se23_rest_meas_t *y,
                               se23_kalman_work_t *wk, se23_gauss_t *out, se23_real_t *nis)
{
    se23_real_t dx[S], q;
    se23_status_t st = rest_check(g);
    if (st == SE23_OK) {
        st = se23_kalman_rest_cov(g, y, wk, dx, &q, out->P.m);
    }
    if (st == SE23_OK) {
        update_finish(g, dx, q, out, nis);
    }
    return st;
}

se23_status_t se23_kalman_nhc(const se23_gauss_t *g, const se23_nhc_meas_t *y,
                              se23_kalman_work_t *wk, se23_gauss_t *out, se23_real_t *nis)
{
    se23_real_t dx[S], q;
    se23_status_t st = rest_check(g);
    if (st == SE23_OK) {
        st = se23_kalman_nhc_cov(g, y, wk, dx, &q, out->P.m);
    }
    if (st == SE23_OK) {
        update_finish(g, dx, q, out, nis);
    }
    return st;
}
