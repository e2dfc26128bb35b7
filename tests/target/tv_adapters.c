/*
 * The generic adapters of tv_list.h (load/call/store over static storage, see
 * tv.h) and the table of every routine, shared by the target test image
 * (tv_runner.c) and the benchmark image (tools/target/bench_main.c).
 */
#include <string.h>

#include "tv.h"

void tv_fill_sentinel(void *p, size_t bytes)
{
    se23_real_t *r = (se23_real_t *)p;
    size_t i;
    for (i = 0; i < bytes / sizeof(se23_real_t); ++i) {
        r[i] = TV_SENTINEL;
    }
}

/* Storage a (b) for the inputs, o for the output of routine fn. */
#define TV_STORE_O(fn)                                                         \
    static void tv_store_##fn(se23_real_t *out) { memcpy(out, &fn##_o, sizeof fn##_o); }
#define TV_IO1(fn, A, O)                                                       \
    static A fn##_a;                                                           \
    static O fn##_o;                                                           \
    static void tv_load_##fn(const se23_real_t *in)                            \
    {                                                                          \
        memcpy(&fn##_a, in, sizeof fn##_a);                                    \
        tv_fill_sentinel(&fn##_o, sizeof fn##_o);                              \
    }                                                                          \
    TV_STORE_O(fn)
#define TV_IO2(fn, A, B, O)                                                    \
    static A fn##_a;                                                           \
    static B fn##_b;                                                           \
    static O fn##_o;                                                           \
    static void tv_load_##fn(const se23_real_t *in)                            \
    {                                                                          \
        memcpy(&fn##_a, in, sizeof fn##_a);                                    \
        memcpy(&fn##_b, in + TV_REALS(A), sizeof fn##_b);                      \
        tv_fill_sentinel(&fn##_o, sizeof fn##_o);                              \
    }                                                                          \
    TV_STORE_O(fn)

#define TV_V0(fn, O, tol)                                                      \
    static O fn##_o;                                                           \
    static void tv_load_##fn(const se23_real_t *in)                            \
    {                                                                          \
        (void)in;                                                              \
        tv_fill_sentinel(&fn##_o, sizeof fn##_o);                              \
    }                                                                          \
    static int tv_call_##fn(void)                                              \
    {                                                                          \
        fn(&fn##_o);                                                           \
        return SE23_OK;                                                        \
    }                                                                          \
    TV_STORE_O(fn)
#define TV_V1(fn, A, O, tol)                                                   \
    TV_IO1(fn, A, O)                                                           \
    static int tv_call_##fn(void)                                              \
    {                                                                          \
        fn(&fn##_a, &fn##_o);                                                  \
        return SE23_OK;                                                        \
    }
#define TV_S1(fn, A, O, tol)                                                   \
    TV_IO1(fn, A, O)                                                           \
    static int tv_call_##fn(void) { return (int)fn(&fn##_a, &fn##_o); }
#define TV_V2(fn, A, B, O, tol)                                                \
    TV_IO2(fn, A, B, O)                                                        \
    static int tv_call_##fn(void)                                              \
    {                                                                          \
        fn(&fn##_a, &fn##_b, &fn##_o);                                         \
        return SE23_OK;                                                        \
    }
#define TV_S2(fn, A, B, O, tol)                                                \
    TV_IO2(fn, A, B, O)                                                        \
    static int tv_call_##fn(void) { return (int)fn(&fn##_a, &fn##_b, &fn##_o); }
#define TV_C1(fn, A, tol)                                                      \
    static A fn##_a;                                                           \
    static void tv_load_##fn(const se23_real_t *in) { memcpy(&fn##_a, in, sizeof fn##_a); } \
    static int tv_call_##fn(void) { return (int)fn(&fn##_a); }                 \
    static void tv_store_##fn(se23_real_t *out) { (void)out; }
#define TV_CUSTOM(fn, n_in, n_out, tol)
#include "tv_list.h"
#undef TV_V0
#undef TV_V1
#undef TV_S1
#undef TV_V2
#undef TV_S2
#undef TV_C1
#undef TV_CUSTOM

#define TV_ROW(fn, n_in, n_out, tol)                                           \
    {#fn, tv_load_##fn, tv_call_##fn, tv_store_##fn, n_in, n_out, tol, &tv_data_##fn},
#define TV_V0(fn, O, tol) TV_ROW(fn, 0, TV_REALS(O), tol)
#define TV_V1(fn, A, O, tol) TV_ROW(fn, TV_REALS(A), TV_REALS(O), tol)
#define TV_S1(fn, A, O, tol) TV_ROW(fn, TV_REALS(A), TV_REALS(O), tol)
#define TV_V2(fn, A, B, O, tol) TV_ROW(fn, TV_REALS(A) + TV_REALS(B), TV_REALS(O), tol)
#define TV_S2(fn, A, B, O, tol) TV_ROW(fn, TV_REALS(A) + TV_REALS(B), TV_REALS(O), tol)
#define TV_C1(fn, A, tol) TV_ROW(fn, TV_REALS(A), 0, tol)
#define TV_CUSTOM(fn, n_in, n_out, tol) TV_ROW(fn, n_in, n_out, tol)
const tv_routine_t tv_routines[] = {
#include "tv_list.h"
};
const int tv_n_routines = (int)(sizeof tv_routines / sizeof tv_routines[0]);
