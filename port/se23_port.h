/**
 * @file se23_port.h
 * @brief The platform contract of se23: everything a platform may provide,
 *        and the only way the library and its target images reach it.
 *
 * 1. Math overrides (optional, read by the library). Every libm call in src/
 *    goes through one wrapper in src/base/se23_math.h, which uses the macros
 *        SE23_SQRT  SE23_ATAN2  SE23_FMOD  SE23_FABS
 *    when they are defined (default: sqrt/atan2/... in the double build,
 *    sqrtf/atan2f/... in the float build). Sine and cosine are the
 *    library's own (src/base/trig.c: one argument reduction for both). A port defines them in its options
 *    header, se23_port_opts.h, and the firmware compiles the library with
 *        -Iport/<name> -DSE23_CFG_OPTS_FILE='"se23_port_opts.h"'
 *    (include/se23/config.h includes that file before its own defaults), or
 *    passes them as -D flags. Each replacement must take and return
 *    se23_real_t and be accurate to about one ulp.
 *
 * 2. Assert hook (optional). SE23_PORT_ASSERT(cond) calls
 *    se23_port_assert_failed() when cond is false; define
 *    SE23_PORT_ASSERT_DISABLE to compile the checks out. Firmware typically
 *    logs and resets there. The library itself reports bad input through
 *    se23_status_t and never asserts on it.
 *
 * 3. Cycle counter (optional). se23_port_cycles_init() / se23_port_cycles()
 *    give a free-running 32-bit counter (DWT CYCCNT on Cortex-M3/M4/M7,
 *    clock_gettime on POSIX); a platform without one returns 0 from
 *    se23_port_cycles_init() and 0 from every read. Differences of two reads
 *    are valid across one wrap (unsigned arithmetic).
 *
 * Ports: port/posix (host), port/cortex-m (the QEMU mps2 boards: startup,
 * linker scripts, semihosting exit), port/template (copy this one to start
 * a new platform).
 */
#ifndef SE23_PORT_H
#define SE23_PORT_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#if defined(__GNUC__)
#define SE23_PORT_NORETURN __attribute__((noreturn))
#else
#define SE23_PORT_NORETURN
#endif

/**
 * Called when SE23_PORT_ASSERT fails; does not return.
 * @param file  source file of the failed check (__FILE__)
 * @param line  source line (__LINE__)
 * @param expr  the condition as text
 */
SE23_PORT_NORETURN void se23_port_assert_failed(const char *file, int line,
                                                const char *expr);

#if defined(SE23_PORT_ASSERT_DISABLE)
#define SE23_PORT_ASSERT(cond) ((void)0)
#else
#define SE23_PORT_ASSERT(cond)                                                 \
    ((cond) ? (void)0 : se23_port_assert_failed(__FILE__, __LINE__, #cond))
#endif

/**
 * Starts the cycle counter.
 * @return 1 if the platform has a counter, 0 if se23_port_cycles() is a stub.
 */
int se23_port_cycles_init(void);

/** Current counter value (core clock cycles, or ns on POSIX), wrapping at 2^32. */
uint32_t se23_port_cycles(void);

#ifdef __cplusplus
}
#endif

#endif /* SE23_PORT_H */
