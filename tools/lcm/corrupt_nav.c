/*
 * se23-corrupt --nav IN.log OUT.log: copies a log (se23-ins's SE23_NAV
 * states, se23-sim's SE23_TRUTH records, anything else as it is) and plants
 * values no INS or simulator produces in whole, well-framed events, which
 * decode: what se23-report's screening (tools/report/logread.h) must keep
 * out of its statistics. From the 10th record of each channel, every 20th
 * gets the next case, in turn:
 *
 *   nav state                                 left out as
 *    0  NaN in p                              non-finite
 *    1  +Inf in v                             non-finite
 *    2  NaN in P                              non-finite
 *    3  R_01 x 2^250 (an exponent corrupted)  not a rotation
 *    4  R's first column negated (det -1)     not a rotation
 *    5  a negative variance                   covariance
 *    6  P_03 changed, P_30 not                covariance
 *    7  a variance corrupted to 1e-300 (its   covariance (a NEES of 1e300
 *       covariances left)                     without the screening)
 *    8  an unknown status bit (0x4000)        status
 *    9  SE23_INS_ST_INITIALISED cleared       status
 *   10  a negative counter                    status
 *   11  t_ns < 0                              status
 *   truth record
 *    0  NaN in p                              non-finite
 *    1  R_11 x 0.9                            not a rotation
 *
 * and prints what se23-report must count: "expect nav <reason> N" and
 * "expect truth <reason> N", reason all, non-finite, rotation, covariance,
 * status.
 */
#define _POSIX_C_SOURCE 200809L
#include "corrupt_nav.h"

#include <lcm/eventlog.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "harness.h"
#include "logfile.h"
#include "se23lcm_nav_state.h"
#include "se23lcm_truth.h"

enum { FIRST = 10, EVERY = 20, N_NAV_CASES = 12, N_TRUTH_CASES = 2 };
enum { R_ALL, R_NONFINITE, R_ROTATION, R_COV, R_STATUS, R_COUNT };

static const int nav_reason[N_NAV_CASES] = {R_NONFINITE, R_NONFINITE, R_NONFINITE, R_ROTATION,
                                            R_ROTATION,  R_COV,       R_COV,       R_COV,
                                            R_STATUS,    R_STATUS,    R_STATUS,    R_STATUS};
static const int truth_reason[N_TRUTH_CASES] = {R_NONFINITE, R_ROTATION};

static void plant_nav(int k, se23lcm_nav_state *m)
{
    switch (k) {
    case 0:
        m->p_n[0] = NAN;
        break;
    case 1:
        m->v_n[2] = INFINITY;
        break;
    case 2:
        m->P[15 * 4 + 7] = NAN;
        break;
    case 3: /* an exponent corrupted */
        m->R_nb[1] = m->R_nb[1] * 0x1p250 + 1e-3;
        break;
    case 4:
        m->R_nb[0] = -m->R_nb[0];
        m->R_nb[3] = -m->R_nb[3];
        m->R_nb[6] = -m->R_nb[6];
        break;
    case 5:
        m->P[16 * 7] = -m->P[16 * 7] - 1e-3;
        break;
    case 6:
        m->P[3] += 1.0 + fabs(m->P[3]);
        break;
    case 7: /* an exponent corrupted: the variance is still > 0, and with its
             * covariances to v the matrix is no covariance */
        m->P[16 * 6] = 1e-300;
        break;
    case 8:
        m->status |= 0x4000;
        break;
    case 9:
        m->status &= ~1;
        break;
    case 10:
        m->n_imu_used = -1;
        break;
    default:
        m->t_ns = -m->t_ns - 1;
        break;
    }
}

static void plant_truth(int k, se23lcm_truth *m)
{
    if (k == 0) {
        m->p_n[1] = NAN;
    } else {
        m->R_nb[4] *= 0.9;
    }
}

static int write_event(lcm_eventlog_t *out, int64_t num, const logfile_event_t *ev,
                       const void *data, int len)
{
    lcm_eventlog_event_t e;
    e.eventnum = num;
    e.timestamp = ev->timestamp;
    e.channellen = (int32_t)strlen(ev->channel);
    e.datalen = len;
    e.channel = (char *)ev->channel; /* LCM's type is not const; only written out */
    e.data = (void *)data;
    return lcm_eventlog_write_event(out, &e);
}

int corrupt_nav(const char *in, const char *out)
{
    static unsigned char buf[4096];
    logfile_t lf;
    logfile_event_t ev;
    lcm_eventlog_t *o;
    int64_t num = 0, n_nav = 0, n_truth = 0, nav[R_COUNT] = {0}, truth[R_COUNT] = {0};
    int next_nav = 0, next_truth = 0, failed = 0, r;
    static const char *const names[R_COUNT] = {"all", "non-finite", "rotation", "covariance",
                                               "status"};
    if (logfile_open(&lf, in, "se23-corrupt") != 0) {
        return 1;
    }
    o = lcm_eventlog_create(out, "w");
    if (o == NULL) {
        fprintf(stderr, "se23-corrupt: cannot open %s\n", out);
        logfile_close(&lf);
        return 1;
    }
    while (!failed && logfile_next(&lf, &ev)) {
        const void *data = ev.data;
        int len = ev.datalen;
        if (strcmp(ev.channel, HARNESS_CH_NAV) == 0) {
            se23lcm_nav_state m;
            if (se23lcm_nav_state_decode(ev.data, 0, ev.datalen, &m) >= 0 && n_nav >= FIRST &&
                (n_nav - FIRST) % EVERY == 0) {
                const int k = next_nav++ % N_NAV_CASES;
                plant_nav(k, &m);
                nav[R_ALL]++;
                nav[nav_reason[k]]++;
                len = se23lcm_nav_state_encode(buf, 0, (int)sizeof buf, &m);
                data = buf;
            }
            n_nav++;
        } else if (strcmp(ev.channel, HARNESS_CH_TRUTH) == 0) {
            se23lcm_truth m;
            if (se23lcm_truth_decode(ev.data, 0, ev.datalen, &m) >= 0 && n_truth >= FIRST &&
                (n_truth - FIRST) % EVERY == 0) {
                const int k = next_truth++ % N_TRUTH_CASES;
                plant_truth(k, &m);
                truth[R_ALL]++;
                truth[truth_reason[k]]++;
                len = se23lcm_truth_encode(buf, 0, (int)sizeof buf, &m);
                data = buf;
            }
            n_truth++;
        }
        failed = len < 0 || write_event(o, num++, &ev, data, len) != 0;
    }
    lcm_eventlog_destroy(o);
    if (failed || lf.bytes_skipped > 0) {
        fprintf(stderr, "se23-corrupt: %s\n",
                failed ? "write failed" : "the input log is already corrupt");
        logfile_close(&lf);
        return 1;
    }
    logfile_close(&lf);
    for (r = 0; r < R_COUNT; r++) {
        printf("expect nav %s %lld\n", names[r], (long long)nav[r]);
    }
    for (r = 0; r < R_COUNT; r++) {
        printf("expect truth %s %lld\n", names[r], (long long)truth[r]);
    }
    return 0;
}
