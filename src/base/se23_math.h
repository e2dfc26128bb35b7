/**
 * @file se23_math.h
 * @brief Internal: one wrapper per libm function, so that the float build
 *        calls only the float functions (sinf, ...) and never promotes to
 *        double. Ports may override any wrapper by defining SE23_SQRT etc.
 *        (e.g. to a CMSIS-DSP or hardware instruction).
 */
#ifndef SE23_MATH_H
#define SE23_MATH_H

#include <float.h>
#include <math.h>

#include "se23/types.h"

#if SE23_CFG_DOUBLE
#define SE23_LIBM(fn) fn
#else
#define SE23_LIBM(fn) fn##f
#endif

#ifndef SE23_SQRT
#define SE23_SQRT SE23_LIBM(sqrt)
#endif
#ifndef SE23_FMOD
#define SE23_FMOD SE23_LIBM(fmod)
#endif
#ifndef SE23_ATAN2
#define SE23_ATAN2 SE23_LIBM(atan2)
#endif
#ifndef SE23_FABS
#define SE23_FABS SE23_LIBM(fabs)
#endif
#ifndef SE23_FLOOR
#define SE23_FLOOR SE23_LIBM(floor)
#endif

static inline se23_real_t se23_sqrt(se23_real_t x) { return SE23_SQRT(x); }
static inline se23_real_t se23_fmod(se23_real_t x, se23_real_t y) { return SE23_FMOD(x, y); }
static inline se23_real_t se23_atan2(se23_real_t y, se23_real_t x) { return SE23_ATAN2(y, x); }
static inline se23_real_t se23_fabs(se23_real_t x) { return SE23_FABS(x); }
static inline se23_real_t se23_floor(se23_real_t x) { return SE23_FLOOR(x); }

/** a b + c with one rounding where the FPU fuses it (M4F single, M7
 *  double: one instruction; the library's ISO C build never contracts
 *  a * b + c by itself), a * b + c elsewhere (x86-64 without -mfma would
 *  call libm). */
#if SE23_CFG_DOUBLE
#if defined(FP_FAST_FMA) || defined(__FP_FAST_FMA)
#define SE23_FAST_FMA 1
#endif
#else
#if defined(FP_FAST_FMAF) || defined(__FP_FAST_FMAF)
#define SE23_FAST_FMA 1
#endif
#endif
static inline se23_real_t se23_fma(se23_real_t a, se23_real_t b, se23_real_t c)
{
#ifdef SE23_FAST_FMA
    return SE23_LIBM(fma)(a, b, c);
#else
    return a * b + c;
#endif
}

/** Nonzero if x is neither NaN nor infinite (C99 type-generic isfinite). */
static inline int se23_is_finite(se23_real_t x) { return isfinite(x) != 0; }

/** Machine epsilon of se23_real_t. */
#if SE23_CFG_DOUBLE
#define SE23_EPSILON DBL_EPSILON
#else
#define SE23_EPSILON FLT_EPSILON
#endif

/** A rotation whose |R^T R - I| is at most this counts as orthonormal: the
 *  re-orthonormalisation is a no-op below it. */
#define SE23_NORMALIZE_DONE (SE23_R(4) * SE23_EPSILON)

/** pi in the build's precision. */
#define SE23_PI SE23_R(3.14159265358979323846)

#endif /* SE23_MATH_H */
