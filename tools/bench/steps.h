/*
 * The composite steps the benchmark compares, each as a pair of calls on
 * ring entry i: the library's and the dense Eigen reference's (ref.h).
 * Each call reads entry i of the input ring and writes its own output
 * ring; it returns 0 on success.
 */
#ifndef SE23_BENCH_STEPS_H
#define SE23_BENCH_STEPS_H

typedef int (*bench_fn_t)(int i);

typedef struct {
    const char *name;  /* command-line name, e.g. "predict_n15" */
    const char *label; /* table row, markdown */
    bench_fn_t se23;
    bench_fn_t eigen;
    /* Largest relative difference between the two outputs at entry i
     * (steps.c, "diff"); call after both ran on i. */
    double (*diff)(int i);
} bench_step_t;

#define BENCH_N_STEPS 4
extern const bench_step_t bench_steps[BENCH_N_STEPS];

/* Builds the input ring and the reference's model; returns 0 on success. */
int bench_steps_prepare(void);

#endif /* SE23_BENCH_STEPS_H */
