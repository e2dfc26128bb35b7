/* Covariance checks and the packed Cholesky factor; see cov.h. */
#include "cov.h"

#include <float.h>

#include "se23_math.h"

/* A pivot must exceed PIVOT_EPS A_jj ... */
#define PIVOT_EPS (SE23_R(16) * SE23_EPSILON)
/* ... and be at least the smallest normal number: below it the pivot has
 * lost relative precision and 1 / sqrt(pivot) may overflow. */
#if SE23_CFG_DOUBLE
#define PIVOT_MIN DBL_MIN
#else
#define PIVOT_MIN FLT_MIN
#endif
/* SE23_COV_ABS_TOL (cov.h), added to the PSD shift of the check so that
 * the zero matrix passes, and a matrix of denormal rounding noise around
 * it (a diagonal of -1e-45 in float): twice PIVOT_MIN in float, so that a
 * pivot of TINY plus such a diagonal still reaches PIVOT_MIN. */
#define TINY SE23_COV_ABS_TOL
/* Above this largest variance the check factors A / 4 (exact: a power of
 * two), so that A_ii + tol s cannot overflow; the tests are scale-free. */
#if SE23_CFG_DOUBLE
#define SCALE_ABOVE SE23_R(DBL_MAX / 4)
#else
#define SCALE_ABOVE SE23_R(FLT_MAX / 4)
#endif

/* A pivot d of the factorisation is usable against its diagonal entry a. */
static int pivot_ok(se23_real_t d, se23_real_t a)
{
    return (d > (PIVOT_EPS * a)) && (d >= PIVOT_MIN) && se23_is_finite(d);
}

/* se23_cov_chol_packed for n = 3, the shape of every measurement model's
 * noise and innovation covariance: the loops below unrolled, the same
 * operations in the same order (bit-identical results; test_cov checks
 * it against the leading block of a 4 x 4 factor). 3 multiply-adds,
 * 3 multiplies, 3 square roots and divisions. */
static int chol3(se23_real_t *L)
{
    const se23_real_t d0 = L[0];
    if (!pivot_ok(d0, L[0])) {
        return 0;
    }
    const se23_real_t i0 = SE23_R(1) / se23_sqrt(d0);
    const se23_real_t l10 = L[1] * i0, l20 = L[3] * i0;
    const se23_real_t d1 = se23_fma(-l10, l10, L[2]);
    if (!pivot_ok(d1, L[2])) {
        return 0;
    }
    const se23_real_t i1 = SE23_R(1) / se23_sqrt(d1);
    const se23_real_t l21 = se23_fma(-l20, l10, L[4]) * i1;
    const se23_real_t d2 = se23_fma(-l21, l21, se23_fma(-l20, l20, L[5]));
    if (!pivot_ok(d2, L[5])) {
        return 0;
    }
    L[0] = i0;
    L[1] = l10;
    L[2] = i1;
    L[3] = l20;
    L[4] = l21;
    L[5] = SE23_R(1) / se23_sqrt(d2);
    return 1;
}

/* se23_cov_chol_packed for any n. */
static int chol_loop(se23_real_t *L, int n)
{
    se23_real_t *lj = L; /* row j; row j + 1 starts j + 1 entries later */
    for (int j = 0; j < n; ++j) {
        se23_real_t d = lj[j];
        for (int k = 0; k < j; ++k) {
            d = se23_fma(-lj[k], lj[k], d);
        }
        if (!pivot_ok(d, lj[j])) {
            return 0;
        }
        const se23_real_t inv = SE23_R(1) / se23_sqrt(d);
        lj[j] = inv;
        se23_real_t *li = &lj[j + 1];
        for (int i = j + 1; i < n; ++i) {
            se23_real_t s = li[j];
            for (int k = 0; k < j; ++k) {
                s = se23_fma(-li[k], lj[k], s);
            }
            li[j] = s * inv;
            li = &li[i + 1];
        }
        lj = &lj[j + 1];
    }
    return 1;
}

int se23_cov_chol_packed(se23_real_t *L, int n)
{
    return (n == 3) ? chol3(L) : chol_loop(L, n);
}

/* se23_cov_check_work for n = 3 (every measurement model's noise): the
 * loops below unrolled, the same tests on the same values (test_cov
 * checks the statuses against a 4 x 4 matrix around A). */
static se23_status_t check3(const se23_real_t *A, int stride, se23_real_t *work)
{
    const se23_real_t *a0 = A, *a1 = &A[stride], *a2 = &A[2 * stride];
    se23_real_t bad = se23_fma(a0[0], SE23_R(0), se23_fma(a0[1], SE23_R(0), a0[2] * SE23_R(0)));
    bad = se23_fma(a1[0], SE23_R(0), se23_fma(a1[1], SE23_R(0), se23_fma(a1[2], SE23_R(0), bad)));
    bad = se23_fma(a2[0], SE23_R(0), se23_fma(a2[1], SE23_R(0), se23_fma(a2[2], SE23_R(0), bad)));
    if (!se23_is_finite(bad)) {
        return SE23_ERR_NONFINITE;
    }
    const se23_real_t d0 = se23_fabs(a0[0]), d1 = se23_fabs(a1[1]), d2 = se23_fabs(a2[2]);
    const se23_real_t s01 = (d1 > d0) ? d1 : d0;
    const se23_real_t s = (d2 > s01) ? d2 : s01;
    const se23_real_t tol = SE23_R(SE23_CFG_COV_TOL) * s;
    if ((se23_fabs(a1[0] - a0[1]) > tol) || (se23_fabs(a2[0] - a0[2]) > tol) ||
        (se23_fabs(a2[1] - a1[2]) > tol)) {
        return SE23_ERR_NOT_SYMMETRIC;
    }
    const se23_real_t k = (s > SCALE_ABOVE) ? SE23_R(0.25) : SE23_R(1);
    const se23_real_t shift = (k * tol) + TINY;
    work[0] = (k * a0[0]) + shift;
    work[1] = k * a1[0];
    work[2] = (k * a1[1]) + shift;
    work[3] = k * a2[0];
    work[4] = k * a2[1];
    work[5] = (k * a2[2]) + shift;
    return chol3(work) ? SE23_OK : SE23_ERR_NOT_PSD;
}

/* se23_cov_check_work for any n. */
static se23_status_t check_loop(const se23_real_t *A, int n, int stride,
                                se23_real_t *work)
{
    /* Finite: x * 0 is 0 for finite x and NaN for NaN or Inf. */
    se23_real_t bad = SE23_R(0), s = SE23_R(0);
    for (int i = 0; i < n; ++i) {
        const se23_real_t *a = &A[stride * i];
        for (int j = 0; j < n; ++j) {
            bad = se23_fma(a[j], SE23_R(0), bad);
        }
        const se23_real_t d = se23_fabs(a[i]);
        s = (d > s) ? d : s;
    }
    if (!se23_is_finite(bad)) {
        return SE23_ERR_NONFINITE;
    }
    const se23_real_t tol = SE23_R(SE23_CFG_COV_TOL) * s;
    const se23_real_t k = (s > SCALE_ABOVE) ? SE23_R(0.25) : SE23_R(1);
    const se23_real_t shift = (k * tol) + TINY;
    se23_real_t *li = work;
    for (int i = 0; i < n; ++i) {
        const se23_real_t *a = &A[stride * i];
        for (int j = 0; j < i; ++j) {
            if (se23_fabs(a[j] - A[stride * j + i]) > tol) {
                return SE23_ERR_NOT_SYMMETRIC;
            }
            li[j] = k * a[j];
        }
        li[i] = (k * a[i]) + shift;
        li = &li[i + 1];
    }
    return chol_loop(work, n) ? SE23_OK : SE23_ERR_NOT_PSD;
}

se23_status_t se23_cov_check_work(const se23_real_t *A, int n, int stride,
                                  se23_real_t *work)
{
    return (n == 3) ? check3(A, stride, work) : check_loop(A, n, stride, work);
}

se23_status_t se23_cov_check(const se23_real_t *A, int n, int stride)
{
    se23_real_t work[SE23_COV_TRI(SE23_GAUSS_NMAX)];
    return se23_cov_check_work(A, n, stride, work);
}
