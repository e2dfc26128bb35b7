/* Covariance checks; see cov_check.h (the factor they use: cov_chol.h). */
#include "cov_check.h"

#include <float.h>

#include "../base/se23_math.h"

/* SE23_COV_ABS_TOL (cov_check.h), added to the PSD shift of the check so that
 * the zero matrix passes, and a matrix of denormal rounding noise around
 * it (a diagonal of -1e-45 in float): twice SE23_CHOL_PIVOT_MIN in float,
 * so that a pivot of TINY plus such a diagonal still reaches it. */
#define TINY SE23_COV_ABS_TOL
/* Above this largest variance the check factors A / 4 (exact: a power of
 * two), so that A_ii + tol s cannot overflow; the tests are scale-free. */
#if SE23_CFG_DOUBLE
#define SCALE_ABOVE SE23_R(DBL_MAX / 4)
#else
#define SCALE_ABOVE SE23_R(FLT_MAX / 4)
#endif

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
    if ((a0[0] < SE23_R(0)) || (a1[1] < SE23_R(0)) || (a2[2] < SE23_R(0))) {
        return SE23_ERR_NOT_PSD; /* a variance is never negative */
    }
    const se23_real_t d0 = a0[0], d1 = a1[1], d2 = a2[2];
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
    return se23_chol3(work) ? SE23_OK : SE23_ERR_NOT_PSD;
}

/* se23_cov_check_work for any n. */
static se23_status_t check_loop(const se23_real_t *A, int n, int stride,
                                se23_real_t *work)
{
    /* Finite: x * 0 is 0 for finite x and NaN for NaN or Inf. */
    se23_real_t bad = SE23_R(0), s = SE23_R(0);
    int neg = 0;
    for (int i = 0; i < n; ++i) {
        const se23_real_t *a = &A[stride * i];
        for (int j = 0; j < n; ++j) {
            bad = se23_fma(a[j], SE23_R(0), bad);
        }
        const se23_real_t d = se23_fabs(a[i]);
        s = (d > s) ? d : s;
        if (a[i] < SE23_R(0)) {
            neg = 1;
        }
    }
    if (!se23_is_finite(bad)) {
        return SE23_ERR_NONFINITE;
    }
    if (neg != 0) {
        return SE23_ERR_NOT_PSD; /* a variance is never negative */
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
    return se23_chol_loop(work, n) ? SE23_OK : SE23_ERR_NOT_PSD;
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
