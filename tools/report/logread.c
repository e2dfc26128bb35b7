/* Reading harness logs; see logread.h. */
#include "logread.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "../lcm/harness.h"
#include "../lcm/logfile.h"

/* Grows *arr (elements of size sz) to hold one more; returns the slot. */
static void *push(void **arr, size_t *n, size_t *cap, size_t sz)
{
    if (*n == *cap) {
        size_t nc = *cap ? 2 * *cap : 1024;
        void *p = realloc(*arr, nc * sz);
        if (p == NULL) {
            return NULL;
        }
        *arr = p;
        *cap = nc;
    }
    return (char *)*arr + (*n)++ * sz;
}

static void decode_event(const logfile_event_t *ev, log_data_t *d)
{
    const char *ch = ev->channel;
    int len = ev->datalen;
    int bad = 0;
    if (strcmp(ch, HARNESS_CH_TRUTH) == 0) {
        se23lcm_truth m;
        bad = se23lcm_truth_decode(ev->data, 0, len, &m) < 0;
        if (!bad) {
            se23lcm_truth *slot = push((void **)&d->truth, &d->n_truth, &d->cap_truth, sizeof m);
            if (slot) {
                *slot = m;
            }
        }
    } else if (strcmp(ch, HARNESS_CH_NAV) == 0) {
        se23lcm_nav_state m;
        bad = se23lcm_nav_state_decode(ev->data, 0, len, &m) < 0;
        if (!bad) {
            se23lcm_nav_state *slot = push((void **)&d->nav, &d->n_nav, &d->cap_nav, sizeof m);
            if (slot) {
                *slot = m;
            }
        }
    } else if (strcmp(ch, HARNESS_CH_GNSS) == 0) {
        se23lcm_gnss_fix m;
        bad = se23lcm_gnss_fix_decode(ev->data, 0, len, &m) < 0;
        if (!bad) {
            se23lcm_gnss_fix *slot = push((void **)&d->gnss, &d->n_gnss, &d->cap_gnss, sizeof m);
            if (slot) {
                *slot = m;
            }
        }
    } else if (strcmp(ch, HARNESS_CH_SIM_INFO) == 0) {
        se23lcm_sim_info m;
        bad = se23lcm_sim_info_decode(ev->data, 0, len, &m) < 0;
        if (!bad) {
            d->info = m;
            d->have_info = 1;
        }
    } else if (strcmp(ch, HARNESS_CH_IMU) == 0) {
        d->n_imu++;
    } else if (strcmp(ch, HARNESS_CH_PREINT) == 0) {
        se23lcm_preint_factor m;
        bad = se23lcm_preint_factor_decode(ev->data, 0, len, &m) < 0;
        if (!bad) {
            int i, ok = fabs((double)(m.t1_ns - m.t0_ns) * 1e-9 - m.dt_s) < 1e-6 && m.dt_s > 0.0;
            for (i = 0; i < 9; i++) {
                ok = ok && m.cov[10 * i] >= 0.0 && isfinite(m.cov[10 * i]);
            }
            se23lcm_preint_factor *slot =
                push((void **)&d->preint, &d->n_preint_stored, &d->cap_preint, sizeof m);
            if (slot) {
                *slot = m;
            }
            d->n_preint++;
            d->n_preint_bad += !ok;
            d->preint_samples += m.n_samples;
        }
    }
    if (bad) {
        d->n_decode_errors++;
    }
}

int log_read(const char *path, log_data_t *d)
{
    logfile_t log;
    logfile_event_t ev;
    if (logfile_open(&log, path, "se23-report") != 0) {
        return -1;
    }
    while (logfile_next(&log, &ev)) {
        d->n_events++;
        decode_event(&ev, d);
    }
    d->bytes_skipped += log.bytes_skipped;
    d->corrupt_spans += log.corrupt_spans;
    logfile_close(&log);
    return 0;
}

static int cmp_truth(const void *a, const void *b)
{
    int64_t x = ((const se23lcm_truth *)a)->t_ns, y = ((const se23lcm_truth *)b)->t_ns;
    return (x > y) - (x < y);
}

/* Nav states with their read order, so that a stable order can be kept. */
typedef struct {
    int64_t t_ns;
    size_t idx;
} navkey_t;

static int cmp_key(const void *a, const void *b)
{
    const navkey_t *x = a, *y = b;
    if (x->t_ns != y->t_ns) {
        return (x->t_ns > y->t_ns) - (x->t_ns < y->t_ns);
    }
    return (x->idx > y->idx) - (x->idx < y->idx);
}

void log_sort(log_data_t *d)
{
    navkey_t *keys;
    se23lcm_nav_state *sorted;
    size_t i, n = 0;
    if (d->n_truth > 0) { /* qsort(NULL, 0, ...) is undefined */
        qsort(d->truth, d->n_truth, sizeof *d->truth, cmp_truth);
    }
    if (d->n_nav == 0) {
        return;
    }
    keys = malloc(d->n_nav * sizeof *keys);
    sorted = malloc(d->n_nav * sizeof *sorted);
    if (keys == NULL || sorted == NULL) {
        free(keys);
        free(sorted);
        return;
    }
    for (i = 0; i < d->n_nav; i++) {
        keys[i].t_ns = d->nav[i].t_ns;
        keys[i].idx = i;
    }
    qsort(keys, d->n_nav, sizeof *keys, cmp_key);
    for (i = 0; i < d->n_nav; i++) {
        if (n > 0 && sorted[n - 1].t_ns == keys[i].t_ns) {
            n--; /* a later state for the same time replaces the earlier */
        }
        sorted[n++] = d->nav[keys[i].idx];
    }
    free(keys);
    free(d->nav);
    d->nav = sorted;
    d->n_nav = n;
    d->cap_nav = n;
}

long log_find_truth(const log_data_t *d, int64_t t_ns)
{
    size_t lo = 0, hi = d->n_truth;
    while (lo < hi) {
        size_t mid = lo + (hi - lo) / 2;
        if (d->truth[mid].t_ns < t_ns) {
            lo = mid + 1;
        } else {
            hi = mid;
        }
    }
    return (lo < d->n_truth && d->truth[lo].t_ns == t_ns) ? (long)lo : -1;
}

void log_free(log_data_t *d)
{
    free(d->truth);
    free(d->nav);
    free(d->gnss);
    free(d->preint);
    memset(d, 0, sizeof *d);
}
