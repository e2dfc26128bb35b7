/* Reading harness logs; see logread.h. */
#include "logread.h"

#include <math.h>
#include <stdio.h>
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

const char *log_bad_str(log_bad_t why)
{
    static const char *const names[LOG_BAD_COUNT] = {"ok", "non-finite", "not a rotation",
                                                      "covariance", "status"};
    return (why >= LOG_OK && why < LOG_BAD_COUNT) ? names[why] : "?";
}

static int all_finite(const double *x, int n)
{
    int i;
    for (i = 0; i < n; i++) {
        if (!isfinite(x[i])) {
            return 0;
        }
    }
    return 1;
}

/* R (row-major) a rotation: R^T R - I within LOG_ROT_TOL, det R > 0. */
static int is_rotation(const double R[9])
{
    int i, j, k;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            long double s = (i == j) ? -1.0L : 0.0L;
            for (k = 0; k < 3; k++) {
                s += (long double)R[3 * k + i] * R[3 * k + j];
            }
            if (!(fabsl(s) <= LOG_ROT_TOL)) {
                return 0;
            }
        }
    }
    return R[0] * (R[4] * R[8] - R[5] * R[7]) - R[1] * (R[3] * R[8] - R[5] * R[6]) +
               R[2] * (R[3] * R[7] - R[4] * R[6]) >
           0.0;
}

/* P (15x15, finite): diagonal >= 0, symmetric, 2x2 minors >= 0 to rounding. */
static int cov_plausible(const double *P)
{
    double s = 0.0;
    int i, j;
    for (i = 0; i < 15; i++) {
        if (!(P[16 * i] >= 0.0)) {
            return 0;
        }
        s = fmax(s, P[16 * i]);
    }
    for (i = 0; i < 15; i++) {
        for (j = i + 1; j < 15; j++) {
            const double a = P[15 * i + j], b = P[15 * j + i];
            if (fabs(a - b) > LOG_COV_TOL * s ||
                fabs(a) > (1.0 + LOG_COV_TOL) * sqrt(P[16 * i] * P[16 * j]) + LOG_COV_TOL * s) {
                return 0;
            }
        }
    }
    return 1;
}

log_bad_t log_screen_nav(const se23lcm_nav_state *m)
{
    const int64_t counters[] = {m->n_imu_used,        m->n_imu_nonfinite, m->n_imu_range,
                                m->n_imu_duplicate,   m->n_imu_out_of_order,
                                m->n_imu_bad_time,    m->n_imu_bad_dt,    m->n_imu_missing,
                                m->n_imu_early,       m->n_decode_errors, m->n_gnss_used,
                                m->n_gnss_rejected,   m->n_time_resets,   m->n_filter_errors,
                                m->n_init_rejected};
    size_t i;
    if (!all_finite(m->R_nb, 9) || !all_finite(m->v_n, 3) || !all_finite(m->p_n, 3) ||
        !all_finite(m->b_g, 3) || !all_finite(m->b_a, 3) || !all_finite(m->P, 225) ||
        !isfinite(m->nis_last) || !isfinite(m->detector_stat)) {
        return LOG_BAD_NONFINITE;
    }
    if (!is_rotation(m->R_nb)) {
        return LOG_BAD_ROTATION;
    }
    if (!cov_plausible(m->P)) {
        return LOG_BAD_COV;
    }
    if (m->t_ns < 0 || m->seq < 0 || (m->status & ~0x1ff) != 0 || (m->status & 0x001) == 0) {
        return LOG_BAD_STATUS;
    }
    for (i = 0; i < sizeof counters / sizeof counters[0]; i++) {
        if (counters[i] < 0) {
            return LOG_BAD_STATUS;
        }
    }
    return LOG_OK;
}

log_bad_t log_screen_truth(const se23lcm_truth *m)
{
    if (!all_finite(m->R_nb, 9) || !all_finite(m->v_n, 3) || !all_finite(m->p_n, 3) ||
        !all_finite(m->b_g, 3) || !all_finite(m->b_a, 3)) {
        return LOG_BAD_NONFINITE;
    }
    if (!is_rotation(m->R_nb)) {
        return LOG_BAD_ROTATION;
    }
    return (m->t_ns < 0 || m->seq < 0) ? LOG_BAD_STATUS : LOG_OK;
}

/* Counts a record the screening left out; says so for the first few. */
static void left_out(log_data_t *d, int64_t *counts, const char *what, const char *path,
                     const logfile_event_t *ev, int64_t t_ns, log_bad_t why)
{
    enum { SHOWN = 5 };
    counts[0]++;
    counts[why]++;
    if (d->nav_rejected[0] + d->truth_rejected[0] <= SHOWN) {
        fprintf(stderr, "se23-report: %s: %s at byte %zu (t = %.3f s) left out: %s%s\n", path,
                what, ev->offset, (double)t_ns * 1e-9, log_bad_str(why),
                d->nav_rejected[0] + d->truth_rejected[0] == SHOWN ? " (further ones counted only)"
                                                                    : "");
    }
}

static void decode_event(const logfile_event_t *ev, const char *path, log_data_t *d)
{
    const char *ch = ev->channel;
    int len = ev->datalen;
    int bad = 0;
    if (strcmp(ch, HARNESS_CH_TRUTH) == 0) {
        se23lcm_truth m;
        log_bad_t why = LOG_OK;
        bad = se23lcm_truth_decode(ev->data, 0, len, &m) < 0;
        if (!bad && d->screen && (why = log_screen_truth(&m)) != LOG_OK) {
            left_out(d, d->truth_rejected, "truth", path, ev, m.t_ns, why);
        } else if (!bad) {
            se23lcm_truth *slot = push((void **)&d->truth, &d->n_truth, &d->cap_truth, sizeof m);
            if (slot) {
                *slot = m;
            }
        }
    } else if (strcmp(ch, HARNESS_CH_NAV) == 0) {
        se23lcm_nav_state m;
        log_bad_t why = LOG_OK;
        bad = se23lcm_nav_state_decode(ev->data, 0, len, &m) < 0;
        if (!bad && d->screen && (why = log_screen_nav(&m)) != LOG_OK) {
            left_out(d, d->nav_rejected, "nav state", path, ev, m.t_ns, why);
        } else if (!bad) {
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
        decode_event(&ev, path, d);
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
