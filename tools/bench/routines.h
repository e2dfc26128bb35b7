/*
 * The library's routines one by one, for the per-routine instruction
 * counts (callgrind): each kernel calls one routine on input i of a ring of
 * BENCH_RING seeded random inputs (rotation vectors with entries up to
 * 2 rad, poses, 200 Hz samples) and returns its status.
 */
#ifndef SE23_BENCH_ROUTINES_H
#define SE23_BENCH_ROUTINES_H

#include "steps.h"

typedef struct {
    const char *name;
    bench_fn_t fn;
} bench_routine_t;

extern const bench_routine_t bench_routines[];
extern const int bench_n_routines;

/* Builds the inputs; returns 0 on success. */
int bench_routines_prepare(void);

#endif /* SE23_BENCH_ROUTINES_H */
