/*
 * Options of the Cortex-M port: square root by the FPU's VSQRT instruction
 * (one instruction; libm's sqrtf adds an errno path and a call). Build the
 * library with -Iport/cortex-m -DSE23_CFG_OPTS_FILE='"se23_port_opts.h"'.
 * The other functions keep newlib's libm. Included by config.h before its
 * defaults, so SE23_CFG_DOUBLE may still be undefined here (default 1).
 * VSQRT of a negative number gives NaN (libm: NaN + errno); the library
 * only takes square roots of sums of squares.
 */
#ifndef SE23_PORT_OPTS_H
#define SE23_PORT_OPTS_H

#if !defined(SE23_CFG_DOUBLE) || SE23_CFG_DOUBLE
#if defined(__ARM_FP) && (__ARM_FP & 8) /* double-precision FPU (fpv5-d16) */
static inline double se23_port_sqrt(double x)
{
    double r;
    __asm__("vsqrt.f64 %P0, %P1" : "=w"(r) : "w"(x));
    return r;
}
#define SE23_SQRT se23_port_sqrt
#endif
#else
#if defined(__ARM_FP) && (__ARM_FP & 4) /* single-precision FPU */
static inline float se23_port_sqrt(float x)
{
    float r;
    __asm__("vsqrt.f32 %0, %1" : "=t"(r) : "t"(x));
    return r;
}
#define SE23_SQRT se23_port_sqrt
#endif
#endif

#endif /* SE23_PORT_OPTS_H */
