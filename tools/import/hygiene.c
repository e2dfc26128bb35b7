/* Time checks of se23-import; see hygiene.h. */
#include "hygiene.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define LOST_MAX 1e12 /* samples lost in one gap, at most (no overflow) */

int64_t import_malformed(const import_count_t *c)
{
    return c->bad_columns + c->bad_number + c->bad_nonfinite + c->bad_long;
}

void hygiene_init(hygiene_t *h, double nominal_ns)
{
    memset(h, 0, sizeof *h);
    h->nominal_ns = nominal_ns;
}

static int same_values(const row_t *a, const row_t *b)
{
    /* Exact equality is the point: a logger that repeats a row repeats its
     * text, hence the parsed values. */
    int k, same = 1;
    for (k = 0; k < 3; k++) {
        same &= a->raw_gyro[k] == b->raw_gyro[k] && a->raw_accel[k] == b->raw_accel[k];
    }
    return same;
}

int64_t hygiene_interval(int64_t a, int64_t b)
{
    /* b >= a: the difference only overflows past INT64_MAX */
    return (a < 0 && b > INT64_MAX + a) ? INT64_MAX : b - a;
}

/* Samples lost before an interval of dt_ns. */
static int64_t lost_before(const hygiene_t *h, int64_t dt_ns)
{
    double n;
    if (h->nominal_ns <= 0.0) {
        return 0;
    }
    n = (double)dt_ns / h->nominal_ns - 1.0;
    if (n > LOST_MAX) {
        n = LOST_MAX;
    }
    return n >= 0.5 ? (int64_t)llround(n) : 0;
}

hyg_action_t hygiene_accept(hygiene_t *h, const row_t *r, int64_t *seq)
{
    int64_t lost = 0;
    if (h->have_last && r->t_ns == h->last.t_ns) {
        h->c.dup_time++;
        h->c.dup_same += same_values(r, &h->last);
        return HYG_DUP;
    }
    if (h->have_last && r->t_ns < h->last.t_ns) {
        h->c.backwards++;
        return HYG_BACK;
    }
    if (h->have_last) {
        const int64_t dt = hygiene_interval(h->last.t_ns, r->t_ns);
        lost = lost_before(h, dt);
        if (lost > 0) {
            h->c.gaps++;
            h->c.lost += lost;
            h->c.longest_gap_ns = dt > h->c.longest_gap_ns ? dt : h->c.longest_gap_ns;
        }
    } else {
        h->c.first_t_ns = r->t_ns;
    }
    h->c.seq += 1 + lost;
    h->c.written++;
    h->c.gyro_clipped += r->gyro_clipped;
    h->c.accel_clipped += r->accel_clipped;
    h->c.last_t_ns = r->t_ns;
    h->last = *r;
    h->have_last = 1;
    *seq = h->c.seq;
    return HYG_WRITE;
}

/* The run restarted at r, of |f| = m (no sample in it yet). */
static void run_restart(hyg_run_t *run, const row_t *r, double m)
{
    memset(run, 0, sizeof *run);
    run->t0_ns = r->t_ns;
    run->lo = m;
    run->hi = m;
}

static void run_add(hyg_run_t *run, const row_t *r, double m)
{
    int k;
    run->n++;
    run->sum += m;
    run->lo = fmin(run->lo, m);
    run->hi = fmax(run->hi, m);
    run->t1_ns = r->t_ns;
    for (k = 0; k < 3; k++) {
        run->f_sum[k] += r->accel[k];
        run->w_sum[k] += r->omega[k];
    }
}

/* Whether |f| = m takes the run beyond HYG_REST_SPREAD (or there is none). */
static int run_breaks(const hyg_run_t *run, double m)
{
    const double mean = (run->sum + m) / (double)(run->n + 1);
    return run->n == 0 || fmax(run->hi, m) - fmin(run->lo, m) > HYG_REST_SPREAD * mean;
}

hyg_rest_event_t hygiene_rest(hyg_rest_t *s, const row_t *r)
{
    const double m = sqrt(r->accel[0] * r->accel[0] + r->accel[1] * r->accel[1] +
                          r->accel[2] * r->accel[2]);
    hyg_rest_event_t ev = HYG_MOVING;
    if (!isfinite(m) || run_breaks(&s->run, m)) { /* moving: a run can only start here */
        if (s->resting) {
            s->last = s->run;
            ev = HYG_REST_ENDS;
        }
        s->resting = 0;
        run_restart(&s->run, r, m);
        if (!isfinite(m)) { /* beyond the double range (1e200 in the file): no run */
            return ev;
        }
    }
    run_add(&s->run, r, m);
    if (s->resting) {
        return HYG_RESTING;
    }
    if (s->run.n >= HYG_REST_N && hygiene_interval(s->run.t0_ns, s->run.t1_ns) >= HYG_REST_NS) {
        s->resting = 1;
        return HYG_REST_BEGINS;
    }
    return ev;
}

static int cmp_i64(const void *a, const void *b)
{
    int64_t x = *(const int64_t *)a, y = *(const int64_t *)b;
    return (x > y) - (x < y);
}

double hygiene_median(int64_t *dt, size_t n)
{
    const size_t mid = n / 2;
    qsort(dt, n, sizeof *dt, cmp_i64);
    return n % 2 ? (double)dt[mid] : 0.5 * ((double)dt[mid - 1] + (double)dt[mid]);
}
