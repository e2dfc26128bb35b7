/* Interleaved batch timing; see timing.h. */
#define _POSIX_C_SOURCE 199309L
#include "timing.h"

#include <stdlib.h>
#include <time.h>

static double now_ns(void)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec * 1e9 + (double)t.tv_nsec;
}

/* ns per call of one batch; *bad |= the calls' results. */
static double batch(bench_fn_t fn, int n, int *bad)
{
    const double t0 = now_ns();
    for (int i = 0; i < n; ++i) {
        *bad |= fn(i);
    }
    return (now_ns() - t0) / n;
}

static int cmp_double(const void *x, const void *y)
{
    const double a = *(const double *)x, b = *(const double *)y;
    return (a > b) - (a < b);
}

/* Nearest-rank percentiles of the sorted rounds. */
static void stats(double *t, int rounds, bench_stats_t *s)
{
    qsort(t, (size_t)rounds, sizeof *t, cmp_double);
    s->min = t[0];
    s->p10 = t[(rounds - 1) / 10];
    s->median = t[(rounds - 1) / 2];
    s->p90 = t[(rounds - 1) - (rounds - 1) / 10];
}

int bench_time_pair(bench_fn_t a, bench_fn_t b, int n, int rounds, bench_stats_t *sa,
                    bench_stats_t *sb, bench_stats_t *ratio)
{
    static double ta[BENCH_MAX_ROUNDS], tb[BENCH_MAX_ROUNDS], tr[BENCH_MAX_ROUNDS];
    int bad = 0;
    if (rounds < 1 || rounds > BENCH_MAX_ROUNDS) {
        return 1;
    }
    for (int r = -BENCH_WARMUP_ROUNDS; r < rounds; ++r) {
        double x, y;
        if (r % 2 == 0) {
            x = batch(a, n, &bad);
            y = batch(b, n, &bad);
        } else {
            y = batch(b, n, &bad);
            x = batch(a, n, &bad);
        }
        if (r >= 0) {
            ta[r] = x;
            tb[r] = y;
            tr[r] = x / y;
        }
    }
    stats(ta, rounds, sa);
    stats(tb, rounds, sb);
    stats(tr, rounds, ratio);
    return bad;
}
