/* The collected loop; see collect.h. */
#include "collect.h"

#include "ring.h"

int run_kernel(bench_fn_t fn, int n)
{
    int bad = 0;
    for (int k = 0; k < n; ++k) {
        bad |= fn(k % BENCH_RING);
    }
    return bad;
}
