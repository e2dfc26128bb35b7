/*
 * Benchmarked operations beyond the rows of tests/target/tv_list.h: public
 * routines that have no reference vectors yet and composite steps (a full
 * propagation step with covariance). One row per operation in bench_steps.c.
 */
#ifndef SE23_BENCH_STEPS_H
#define SE23_BENCH_STEPS_H

typedef struct {
    const char *name;
    void (*prepare)(void); /* sets the inputs, outside the measured region */
    int (*call)(void);     /* the measured operation; returns its status */
} bench_step_t;

extern const bench_step_t bench_steps[];
extern const int bench_n_steps;

#endif /* SE23_BENCH_STEPS_H */
