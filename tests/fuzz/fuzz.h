/**
 * @file fuzz.h
 * @brief Shared helpers of the libFuzzer targets (tests/fuzz/fuzz_*.c),
 *        header-only: a reader that decodes the fuzzer's bytes into
 *        integers, reals, vectors, rotations, poses and covariances, biased
 *        towards the values that break numerical code (NaN, +-Inf,
 *        denormals, the smallest normal, the largest finite value and its
 *        neighbours, huge and tiny magnitudes, multiples of pi, raw bit
 *        patterns) and towards valid inputs (rotations from the exponential,
 *        PSD covariances A A^T), so that a target reaches the deep paths
 *        too; and the oracle of the contract (types.h): statuses in the
 *        documented set, outputs finite on SE23_OK, rotations through
 *        se23_so3_check, covariances through se23_gauss_check, outputs
 *        pre-filled with a sentinel byte pattern that must survive an error,
 *        aliased calls equal to plain ones bit for bit.
 *
 * An oracle failure prints what failed and aborts: libFuzzer records the
 * input as a crash. The decoder never reads past the input: once the bytes
 * run out every read returns 0 (so a short input still decodes).
 */
#ifndef SE23_FUZZ_H
#define SE23_FUZZ_H

#include <float.h>
#include <math.h>
#include <stdarg.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "se23/earth.h"
#include "se23/gauss.h"
#include "se23/so3.h"
#include "se23/types.h"

#if SE23_CFG_DOUBLE
#define FZ_PREC "double"
#define FZ_MAX DBL_MAX
#define FZ_MIN DBL_MIN
#define FZ_EPS DBL_EPSILON
#define FZ_TRUE_MIN 4.9406564584124654e-324
#define FZ_HUGE_EXP 308
#else
#define FZ_PREC "float"
#define FZ_MAX FLT_MAX
#define FZ_MIN FLT_MIN
#define FZ_EPS FLT_EPSILON
#define FZ_TRUE_MIN 1.40129846e-45f
#define FZ_HUGE_EXP 38
#endif

/** Byte pattern of the outputs that an error must leave untouched. */
#define FZ_SENTINEL 0xA5

/** Where oracle failures are told (a target may point stderr elsewhere). */
static FILE *fz_err_stream;

/** Aborts (a libFuzzer crash) unless cond holds. */
#define FZ_REQUIRE(cond, ...)                                                  \
    do {                                                                       \
        if (!(cond)) {                                                         \
            FILE *fz_e_ = fz_err_stream != NULL ? fz_err_stream : stderr;      \
            fprintf(fz_e_, "fuzz oracle (%s build) %s:%d: %s: ", FZ_PREC,      \
                    __FILE__, __LINE__, #cond);                                \
            fprintf(fz_e_, __VA_ARGS__);                                       \
            fprintf(fz_e_, "\n");                                              \
            fflush(fz_e_);                                                     \
            abort();                                                           \
        }                                                                      \
    } while (0)

/** The input being decoded. */
typedef struct {
    const uint8_t *d;
    size_t n, i;
} fz_t;

static inline void fz_init(fz_t *f, const uint8_t *d, size_t n)
{
    f->d = d;
    f->n = n;
    f->i = 0;
}

static inline int fz_left(const fz_t *f)
{
    return f->i < f->n;
}

static inline uint8_t fz_u8(fz_t *f)
{
    return f->i < f->n ? f->d[f->i++] : 0;
}

static inline uint16_t fz_u16(fz_t *f)
{
    uint16_t a = fz_u8(f);
    return (uint16_t)(a | (uint16_t)(fz_u8(f) << 8));
}

static inline uint32_t fz_u32(fz_t *f)
{
    uint32_t a = fz_u16(f);
    return a | (uint32_t)fz_u16(f) << 16;
}

static inline uint64_t fz_u64(fz_t *f)
{
    uint64_t a = fz_u32(f);
    return a | (uint64_t)fz_u32(f) << 32;
}

/** An integer in [lo, hi] (hi - lo < 65536). */
static inline int fz_range(fz_t *f, int lo, int hi)
{
    unsigned span = (unsigned)(hi - lo) + 1u;
    return lo + (int)((span <= 256u ? fz_u8(f) : fz_u16(f)) % span);
}

/** Any int, most often a small one; now and then the extremes. */
static inline int fz_int(fz_t *f)
{
    uint8_t m = fz_u8(f);
    if (m < 200) {
        return (int)(m % 40) - 8;
    }
    switch (m % 4) {
    case 0:
        return INT32_MAX;
    case 1:
        return INT32_MIN;
    default:
        return (int)fz_u32(f);
    }
}

/** Raw bits of the precision. */
static inline se23_real_t fz_raw_real(fz_t *f)
{
    se23_real_t x;
#if SE23_CFG_DOUBLE
    uint64_t u = fz_u64(f);
#else
    uint32_t u = fz_u32(f);
#endif
    memcpy(&x, &u, sizeof x);
    return x;
}

/**
 * A real: most often a moderate value (+-128 in steps of 1/256), else a
 * value scaled by 10^-15..10^15, raw bits, or one of the special values.
 */
static inline se23_real_t fz_real(fz_t *f)
{
    static const double special[] = {
        0.0, -0.0, 1.0, -1.0, 0.5, 2.0, 9.80665, -9.80665, 0.005, 0.01, 1.0 / 3.0,
        3.14159265358979323846, -3.14159265358979323846, 1.57079632679489661923,
        6.28318530717958647692, 6.28318530717958647692 - 1e-3, 1e-3, 1e-6, 1e-9, 1e-12,
        1e3, 1e6, 1e9, 1e12, 1e18, 7.292115e-5};
    uint8_t m = fz_u8(f);
    if (m < 96) {
        return (se23_real_t)((double)(int16_t)fz_u16(f) / 256.0);
    }
    if (m < 128) {
        int e = (int)(fz_u8(f) % 31) - 15;
        return (se23_real_t)((double)(int16_t)fz_u16(f) / 32768.0 * pow(10.0, e));
    }
    if (m < 144) {
        return fz_raw_real(f);
    }
    if (m < 160) {
        /* huge or tiny: 10^(+-k) up to the range of the precision */
        int e = (int)(fz_u8(f) % (2 * FZ_HUGE_EXP + 1)) - FZ_HUGE_EXP;
        return (se23_real_t)((m & 1 ? -1.0 : 1.0) * pow(10.0, e));
    }
    switch (m - 160) {
    case 0:
        return (se23_real_t)NAN;
    case 1:
        return (se23_real_t)-NAN;
    case 2:
        return (se23_real_t)INFINITY;
    case 3:
        return (se23_real_t)-INFINITY;
    case 4:
        return FZ_TRUE_MIN;
    case 5:
        return -FZ_TRUE_MIN;
    case 6:
        return FZ_MIN;
    case 7:
        return FZ_MIN / 2; /* denormal */
    case 8:
        return FZ_MAX;
    case 9:
        return -FZ_MAX;
    case 10:
        return FZ_MAX / 4;
    case 11:
        return (se23_real_t)sqrt((double)FZ_MAX);
    case 12:
        return (se23_real_t)(1.0 / sqrt((double)FZ_MAX));
    case 13:
        return FZ_EPS;
    case 14:
        return 1 + FZ_EPS;
    case 15:
        return 1 - FZ_EPS / 2;
    case 16:
        return (se23_real_t)SE23_CFG_DT_MAX;
    case 17:
        return (se23_real_t)SE23_CFG_DT_MAX * (1 + FZ_EPS);
    default:
        break;
    }
    return (se23_real_t)special[(size_t)(m - 178) % (sizeof special / sizeof special[0])];
}

/** A real that is finite and moderate most of the time. */
static inline se23_real_t fz_mild(fz_t *f)
{
    uint8_t m = fz_u8(f);
    if (m < 224) {
        return (se23_real_t)((double)(int16_t)fz_u16(f) / 1024.0);
    }
    return fz_real(f);
}

/** A time step [s]: mostly nominal-ish, else anything. */
static inline se23_real_t fz_dt(fz_t *f)
{
    uint8_t m = fz_u8(f);
    if (m < 160) {
        return (se23_real_t)((double)(1 + fz_u16(f)) * 1e-5); /* 1e-5 .. 0.66 s */
    }
    if (m < 192) {
        return (se23_real_t)0.005;
    }
    return fz_real(f);
}

static inline void fz_vec3(fz_t *f, se23_vec3_t *v)
{
    int i;
    for (i = 0; i < 3; ++i) {
        v->v[i] = fz_real(f);
    }
}

static inline void fz_vec3_mild(fz_t *f, se23_vec3_t *v)
{
    int i;
    for (i = 0; i < 3; ++i) {
        v->v[i] = fz_mild(f);
    }
}

static inline void fz_mat3_raw(fz_t *f, se23_mat3_t *M)
{
    int i, j;
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            M->m[i][j] = fz_real(f);
        }
    }
}

static inline void fz_identity3(se23_mat3_t *M)
{
    int i, j;
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            M->m[i][j] = (se23_real_t)(i == j);
        }
    }
}

/**
 * A 3x3 matrix that is most often a rotation (the exponential of a decoded
 * vector), else the identity, a rotation with one entry perturbed, or raw.
 */
static inline void fz_rot(fz_t *f, se23_mat3_t *R)
{
    uint8_t m = fz_u8(f);
    if (m < 176) {
        se23_vec3_t phi;
        fz_vec3_mild(f, &phi);
        if (se23_so3_exp(&phi, R) != SE23_OK) {
            fz_identity3(R);
        }
    } else if (m < 200) {
        fz_identity3(R);
    } else if (m < 232) {
        se23_vec3_t phi;
        fz_vec3_mild(f, &phi);
        if (se23_so3_exp(&phi, R) != SE23_OK) {
            fz_identity3(R);
        }
        if (m & 1) {
            R->m[fz_u8(f) % 3][fz_u8(f) % 3] += fz_real(f);
        } else {
            R->m[fz_u8(f) % 3][fz_u8(f) % 3] *= 1 + (se23_real_t)((int8_t)fz_u8(f)) * FZ_EPS;
        }
    } else {
        fz_mat3_raw(f, R);
    }
}

static inline void fz_pose(fz_t *f, se23_pose_t *T)
{
    fz_rot(f, &T->R);
    if (fz_u8(f) < 200) {
        fz_vec3_mild(f, &T->v);
        fz_vec3_mild(f, &T->p);
    } else {
        fz_vec3(f, &T->v);
        fz_vec3(f, &T->p);
    }
}

/**
 * An n x n covariance at P[stride * i + j]: diagonal, A A^T, a symmetric
 * matrix of arbitrary entries, zero, or n x n raw entries. The rest of the
 * storage is left as it was.
 */
static inline void fz_cov(fz_t *f, int n, int stride, se23_real_t *P)
{
    uint8_t m = fz_u8(f);
    int i, j, k;
    if (m < 96) { /* diagonal */
        for (i = 0; i < n; ++i) {
            for (j = 0; j < n; ++j) {
                P[stride * i + j] = 0;
            }
            P[stride * i + i] = (se23_real_t)fabs((double)(m & 1 ? fz_real(f) : fz_mild(f)));
        }
    } else if (m < 176) { /* A A^T, A lower triangular with decoded entries */
        double A[15][15];
        double scale = pow(10.0, (int)(fz_u8(f) % 13) - 6);
        for (i = 0; i < n; ++i) {
            for (j = 0; j < n; ++j) {
                A[i][j] = j <= i ? (double)(m & 1 ? fz_real(f) : fz_mild(f)) * scale : 0.0;
            }
        }
        for (i = 0; i < n; ++i) {
            for (j = 0; j <= i; ++j) {
                double s = 0.0;
                for (k = 0; k <= j; ++k) {
                    s += A[i][k] * A[j][k];
                }
                P[stride * i + j] = (se23_real_t)s;
                P[stride * j + i] = (se23_real_t)s;
            }
        }
    } else if (m < 208) { /* symmetric, arbitrary */
        for (i = 0; i < n; ++i) {
            for (j = 0; j <= i; ++j) {
                P[stride * i + j] = fz_real(f);
                P[stride * j + i] = P[stride * i + j];
            }
        }
    } else if (m < 224) {
        for (i = 0; i < n; ++i) {
            for (j = 0; j < n; ++j) {
                P[stride * i + j] = 0;
            }
        }
    } else {
        for (i = 0; i < n; ++i) {
            for (j = 0; j < n; ++j) {
                P[stride * i + j] = fz_real(f);
            }
        }
    }
}

/** A filter state: n most often 9 or 15, any pose, biases, covariance. */
static inline void fz_gauss(fz_t *f, se23_gauss_t *g)
{
    uint8_t m = fz_u8(f);
    memset(g, 0, sizeof *g);
    g->n = m < 120 ? 9 : m < 240 ? 15 : fz_int(f);
    fz_pose(f, &g->T);
    if (fz_u8(f) < 128) {
        memset(&g->b_g, 0, sizeof g->b_g);
        memset(&g->b_a, 0, sizeof g->b_a);
    } else {
        fz_vec3_mild(f, &g->b_g);
        fz_vec3_mild(f, &g->b_a);
    }
    fz_cov(f, (g->n == 9 || g->n == 15) ? g->n : 15, 15, g->P.m);
}

/**
 * A navigation model as the library builds it (the model is trusted once
 * built): se23_earth_model_init on decoded g, Omega, dt, dt_max, or the
 * WGS-84 one at a decoded latitude; a flat-Earth 200 Hz model if the
 * decoded values are refused.
 */
static inline void fz_model(fz_t *f, se23_earth_model_t *m)
{
    uint8_t k = fz_u8(f);
    se23_real_t dt = k & 1 ? fz_dt(f) : (se23_real_t)0.005;
    se23_real_t dt_max = k & 2 ? fz_dt(f) : (se23_real_t)SE23_CFG_DT_MAX;
    se23_status_t st;
    if (k < 128) {
        se23_vec3_t g_n, w;
        fz_vec3_mild(f, &g_n);
        if (fz_u8(f) < 128) {
            memset(&w, 0, sizeof w);
        } else {
            fz_vec3(f, &w);
        }
        st = se23_earth_model_init(&g_n, &w, dt, dt_max, m);
    } else {
        se23_real_t lat = (se23_real_t)((double)(int16_t)fz_u16(f) / 32768.0 * 1.5707963);
        st = se23_earth_model_init_wgs84((se23_frame_t)(k & 4 ? 1 : 0), lat,
                                         (se23_real_t)(int16_t)fz_u16(f), dt, dt_max, m);
    }
    if (st != SE23_OK) {
        const se23_vec3_t g0 = {{0, 0, (se23_real_t)9.80665}}, w0 = {{0, 0, 0}};
        st = se23_earth_model_init(&g0, &w0, (se23_real_t)0.005, (se23_real_t)SE23_CFG_DT_MAX, m);
        FZ_REQUIRE(st == SE23_OK, "the fallback model: %d", st);
    }
}

/** An IMU sample: mostly moderate readings and a plausible dt. */
static inline void fz_sample(fz_t *f, se23_imu_sample_t *s)
{
    if (fz_u8(f) < 160) {
        fz_vec3_mild(f, &s->w_ib_b);
        fz_vec3_mild(f, &s->f_b);
    } else {
        fz_vec3(f, &s->w_ib_b);
        fz_vec3(f, &s->f_b);
    }
    s->dt = fz_dt(f);
}

/* ---- the oracle ------------------------------------------------------- */

static inline int fz_finite(const se23_real_t *x, size_t n)
{
    size_t i;
    for (i = 0; i < n; ++i) {
        if (!isfinite(x[i])) {
            return 0;
        }
    }
    return 1;
}

#define FZ_FINITE_OBJ(obj) fz_finite((const se23_real_t *)(const void *)&(obj), \
                                     sizeof(obj) / sizeof(se23_real_t))

static inline void fz_fill(void *p, size_t n)
{
    memset(p, FZ_SENTINEL, n);
}

/** 1 if the n bytes at p all still hold the sentinel. */
static inline int fz_untouched(const void *p, size_t n)
{
    const unsigned char *c = (const unsigned char *)p;
    size_t i;
    for (i = 0; i < n; ++i) {
        if (c[i] != FZ_SENTINEL) {
            return 0;
        }
    }
    return 1;
}

/** 1 if s is SE23_OK or one of the n statuses listed (the header's set). */
static inline int fz_status_in(se23_status_t s, int n, ...)
{
    va_list ap;
    int k, hit = s == SE23_OK;
    va_start(ap, n);
    for (k = 0; k < n; ++k) {
        hit |= (int)s == va_arg(ap, int);
    }
    va_end(ap);
    return hit;
}

static inline int fz_is_rot(const se23_mat3_t *R)
{
    return se23_so3_check(R) == SE23_OK;
}

/** se23_gauss_check of the n x n covariance P (stride) alone, inside an
 *  otherwise trivial state: dimension 9 (n <= 9, zero-padded) or 15. */
static inline se23_status_t fz_cov_check(const se23_real_t *P, int n, int stride)
{
    se23_gauss_t g;
    int i, j;
    memset(&g, 0, sizeof g);
    fz_identity3(&g.T.R);
    g.n = n <= 9 ? 9 : 15;
    for (i = 0; i < n; ++i) {
        for (j = 0; j < n; ++j) {
            g.P.m[15 * i + j] = P[stride * i + j];
        }
    }
    return se23_gauss_check(&g);
}

/** Bitwise equality of two gauss states: the fields, not the padding, and
 *  of P only the leading n x n block (the only one read or written). */
static inline int fz_gauss_same(const se23_gauss_t *a, const se23_gauss_t *b)
{
    int i, n = a->n == 9 ? 9 : 15;
    if (memcmp(&a->T, &b->T, sizeof a->T) != 0 || memcmp(&a->b_g, &b->b_g, sizeof a->b_g) != 0 ||
        memcmp(&a->b_a, &b->b_a, sizeof a->b_a) != 0 || a->n != b->n) {
        return 0;
    }
    for (i = 0; i < n; ++i) {
        if (memcmp(&a->P.m[15 * i], &b->P.m[15 * i], (size_t)n * sizeof a->P.m[0]) != 0) {
            return 0;
        }
    }
    return 1;
}

#define FZ_SAME(a, b) (memcmp(&(a), &(b), sizeof(a)) == 0)

/* ---- the one known open finding -------------------------------------- */

/*
 * A covariance step or update is computed to rounding of its inputs
 * (src/kalman/kalman_halves.c: P+ is the exact Schur complement of a matrix within
 * (m + 1) eps of M = [[S, C^T], [C, P]]; a step Phi P Phi^T + Q likewise
 * within a few eps of |Phi| |P| |Phi|^T), while se23_gauss_check judges
 * the result relative to the result's own largest variance. When a step
 * cancels the variance of a state correlated with a measured one far below
 * the inputs' (the measured state itself is exact since the update's
 * Joseph step, issue 37: a float update with a 1-sigma of 1000 m/s
 * measured to 0.01 m/s no longer fails, tools/doc/pages/fuzzing-soak.md), when exact
 * measurements (R = 0) pin a state through a nearly singular S, or when an
 * input accepted within its own tolerance (an R PSD within 1e-5 of its
 * largest variance) is indefinite at the scale of the others, the result
 * can have negative variances that se23_gauss_check refuses: a contract
 * violation (SE23_OK, P not PSD) left open, reported, not fixed here.
 *
 * So that fuzzing goes on past it, fz_check_cov_step counts such a result
 * as known (and does not abort) when P + shift I is positive semidefinite,
 * shift the caller's bound on that rounding error: the result is then
 * within what the algorithm's own error analysis allows. Anything beyond
 * the bound, or any other status, still aborts. FUZZ_STRICT_PSD=1 in the
 * environment aborts on the known case too (to reproduce it).
 */
static unsigned long fz_known_psd;

static void fz_report_known(void)
{
    if (fz_known_psd != 0) {
        fprintf(fz_err_stream != NULL ? fz_err_stream : stderr,
                "fuzz: known open finding tolerated %lu times: a covariance step "
                "within its rounding bound, refused by se23_gauss_check (tools/doc/pages/"
                "fuzzing-soak.md; FUZZ_STRICT_PSD=1 aborts)\n",
                fz_known_psd);
    }
}

/** 1 if the n x n P (stride) plus shift I has a long-double Cholesky factor
 *  with positive pivots (P read as symmetric from its lower triangle). */
static inline int fz_psd_shifted(const se23_real_t *P, int n, int stride, long double shift)
{
    long double L[15][15];
    int i, j, k;
    for (j = 0; j < n; ++j) {
        long double d = (long double)P[stride * j + j] + shift;
        for (k = 0; k < j; ++k) {
            d -= L[j][k] * L[j][k];
        }
        if (!(d > 0.0L) || !isfinite(d)) {
            return 0;
        }
        L[j][j] = sqrtl(d);
        for (i = j + 1; i < n; ++i) {
            long double x = (long double)P[stride * i + j];
            for (k = 0; k < j; ++k) {
                x -= L[i][k] * L[j][k];
            }
            L[i][j] = x / L[j][j];
        }
    }
    return 1;
}

/** The largest diagonal entry of the n x n P (stride). */
static inline double fz_max_diag(const se23_real_t *P, int n, int stride)
{
    double d = 0.0;
    int i;
    for (i = 0; i < n; ++i) {
        d = fmax(d, fabs((double)P[stride * i + i]));
    }
    return d;
}

/**
 * The oracle of a covariance produced by a step or update, c the status of
 * its check (se23_gauss_check, se23_preint_unc_check): SE23_OK, or the
 * known finding above (SE23_ERR_NOT_PSD, P within `bound`, absolute in the
 * units of P, of positive semidefinite). Returns 1 for SE23_OK, 0 for the
 * known finding: the result is then not a valid state, and must not be
 * handed to a function that trusts its input.
 */
static inline int fz_check_cov_result(se23_status_t c, const se23_real_t *P, int n, int stride,
                                       double bound, const char *what)
{
    static int registered, strict = -1;
    if (c == SE23_OK) {
        return 1;
    }
    if (strict < 0) {
        strict = getenv("FUZZ_STRICT_PSD") != NULL;
    }
    if (c == SE23_ERR_NOT_PSD && !strict) {
        const double s = fz_max_diag(P, n, stride);
        const long double shift = (long double)bound + (long double)SE23_CFG_COV_TOL * s;
        if (isfinite(bound) && fz_psd_shifted(P, n, stride, shift)) {
            if (!registered) {
                registered = 1;
                atexit(fz_report_known);
            }
            fz_known_psd++;
            return 0;
        }
    }
    if (c == SE23_ERR_NOT_PSD) { /* how far from PSD: the shift it needs, to a factor 2 */
        long double hi = 1.0L;
        while (!fz_psd_shifted(P, n, stride, hi) && hi < 1e300L) {
            hi *= 2.0L;
        }
        while (hi > 1e-4900L && fz_psd_shifted(P, n, stride, 0.5L * hi)) {
            hi *= 0.5L;
        }
        fprintf(fz_err_stream != NULL ? fz_err_stream : stderr,
                "fuzz: %s: P needs a shift of %Lg to be PSD (largest variance %g)\n", what, hi,
                fz_max_diag(P, n, stride));
    }
    FZ_REQUIRE(c == SE23_OK, "%s: OK but the result fails its check (%d), rounding bound %g", what,
               c, bound);
    return 1;
}

/** fz_check_cov_result for a state: se23_gauss_check. */
static inline int fz_check_cov_step(const se23_gauss_t *g, double bound, const char *what)
{
    const se23_status_t c = se23_gauss_check(g);
    if (c != SE23_OK && g->n != 9 && g->n != 15) {
        FZ_REQUIRE(c == SE23_OK, "%s: a state of dimension %d", what, g->n);
    }
    return fz_check_cov_result(c, g->P.m, g->n == 9 ? 9 : 15, 15, bound, what);
}

/**
 * Bound on the rounding error of Phi P Phi^T + Q (n x n P, stride), Phi =
 * [[F_k, B_k], [0, I]] of the increment U over dt, b the largest absolute
 * row sum of B_k, q the largest noise term (density^2 / dt) and w the
 * largest walk term: per entry a few eps of |Phi| |P| |Phi|^T (rows of Phi
 * sum to at most r, cov_step.c), plus the input's own tolerance carried
 * through Phi: the check admits P + (SE23_CFG_COV_TOL s + 2 FLT_MIN) I
 * (cov_check.h), s its largest variance, so both the relative and the absolute
 * part (a variance of -1e-202 passes; a step with |v| = 1e114 turns it
 * into -5e26), times n for the spectral norm.
 */
static inline double fz_step_bound(const se23_pose_t *U, double dt, double b, double q, double w,
                                   const se23_real_t *P, int n, int stride)
{
    const double g = 1.0 + dt + fabs((double)U->v.v[0]) + fabs((double)U->v.v[1]) +
                     fabs((double)U->v.v[2]) + fabs((double)U->p.v[0]) +
                     fabs((double)U->p.v[1]) + fabs((double)U->p.v[2]);
    const double r = 2.0 * (g + b) + 1.0, d = fz_max_diag(P, n, stride);
    const double e = 32.0 * FZ_EPS;
    return (double)n * (((e + SE23_CFG_COV_TOL) * d + 2.0 * FLT_MIN) * r * r +
                        e * (4.0 * q * b * b + w));
}

/** The largest absolute row sum of a 9x6 B. */
static inline double fz_rowsum9x6(const se23_mat9x6_t *B)
{
    double b = 0.0;
    int i, j;
    for (i = 0; i < 9; ++i) {
        double x = 0.0;
        for (j = 0; j < 6; ++j) {
            x += fabs((double)B->m[6 * i + j]);
        }
        b = fmax(b, x);
    }
    return b;
}

/**
 * The parts of fz_step_bound for the sample s of a state with biases b_g,
 * b_a: the increment U and the largest row sum b of the input matrix at the
 * corrected inputs (what se23_gauss_predict and se23_preint_unc_add use),
 * the largest noise term q and, with walks, walk term w. Returns 0 if the
 * library refuses the increment or the input matrix.
 */
static inline int fz_sample_parts(const se23_imu_sample_t *s, const se23_vec3_t *b_g,
                                  const se23_vec3_t *b_a, se23_input_jac_kind_t kind,
                                  const se23_imu_noise_t *q, int walks, se23_pose_t *U,
                                  double *b, double *qm, double *wm)
{
    se23_imu_sample_t c = *s;
    se23_mat9x6_t B;
    int i;
    for (i = 0; i < 3; ++i) {
        c.w_ib_b.v[i] = s->w_ib_b.v[i] + b_g->v[i];
        c.f_b.v[i] = s->f_b.v[i] + b_a->v[i];
    }
    if (se23_imu_increment(&c, U) != SE23_OK ||
        se23_gauss_input_jac(kind, &c.w_ib_b, &c.f_b, c.dt, &B) != SE23_OK) {
        return 0;
    }
    *b = fz_rowsum9x6(&B);
    *qm = fmax((double)q->gyro_noise * q->gyro_noise, (double)q->accel_noise * q->accel_noise) /
          (double)c.dt;
    *wm = walks ? fmax((double)q->gyro_walk * q->gyro_walk, (double)q->accel_walk * q->accel_walk) *
                      (double)c.dt
                : 0.0;
    return 1;
}

/** fz_step_bound for the sample s of a state with biases b_g, b_a
 *  (fz_sample_parts); HUGE_VAL (no tolerance) if the library refuses it. */
static inline double fz_sample_bound(const se23_imu_sample_t *s, const se23_vec3_t *b_g,
                                     const se23_vec3_t *b_a, se23_input_jac_kind_t kind,
                                     const se23_imu_noise_t *q, int walks, const se23_real_t *P,
                                     int n, int stride)
{
    se23_pose_t U;
    double b, qm, wm;
    if (!fz_sample_parts(s, b_g, b_a, kind, q, walks, &U, &b, &qm, &wm)) {
        return HUGE_VAL;
    }
    return fz_step_bound(&U, (double)s->dt, b, qm, wm, P, n, stride);
}

#endif /* SE23_FUZZ_H */
