/*
 * se23-corrupt: copies a se23-sim log and injects every bad-input case the
 * INS must survive, then prints the counts se23-ins must report:
 *
 *   expect <counter> <value>      (one line per counter of se23-ins's summary)
 *
 * Cases (at fixed IMU sequence numbers; the input needs >= 3400 samples):
 *   an IMU sample before the initial state           -> imu_early
 *   NaN in omega, +Inf in accel                       -> imu_nonfinite (2)
 *   |omega| = 1e3 rad/s                               -> imu_range
 *   a sample sent twice                               -> imu_duplicate
 *   two samples swapped                               -> imu_out_of_order (+1 missing)
 *   a timestamp repeated, a timestamp 10 s backwards  -> imu_bad_time (2)
 *   a timestamp 1000 s ahead (absurd dt)              -> imu_bad_dt
 *   5 samples dropped (gap bridged)                   -> imu_missing (5)
 *   a 2 s outage of every sensor                      -> time_resets (1), imu_bad_dt (3),
 *                                                        imu_missing (400)
 *   truncated IMU, garbage on SE23_IMU, a GNSS fix on SE23_IMU, truncated GNSS
 *                                                     -> decode_errors (4)
 *   a GNSS fix with NaN position, one with sigma < 0  -> gnss_rejected (2)
 *   initial states: NaN in P, a non-rotation R, P not
 *   positive semidefinite                             -> init_rejected (3), state kept
 *
 * usage: se23-corrupt IN.log OUT.log
 *        se23-corrupt --framing IN.log OUT.log   (corrupt_framing.c)
 *        se23-corrupt --nav IN.log OUT.log       (corrupt_nav.c)
 */
#define _POSIX_C_SOURCE 200809L
#include <lcm/eventlog.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "corrupt_framing.h"
#include "corrupt_nav.h"
#include "harness.h"
#include "logfile.h"
#include "se23lcm_gnss_fix.h"
#include "se23lcm_imu_sample.h"
#include "se23lcm_nav_state.h"

enum {
    K_NAN = 500,
    K_INF = 700,
    K_RANGE = 900,
    K_DUP = 1100,
    K_SWAP = 1300,
    K_REPEAT = 1500,
    K_BACK = 1700,
    K_ABSURD = 1900,
    K_GAP = 2100, /* drops K_GAP .. K_GAP + 4 */
    GAP_LEN = 5,
    K_OUTAGE = 2401, /* drops K_OUTAGE .. K_OUTAGE + 399, all channels */
    OUTAGE_LEN = 400,
    OUTAGE_CONFIRM = 3, /* INS_OUTAGE_CONFIRM of tools/ins/ins.h */
    K_BAD_GNSS = 3000,  /* invalid fixes after the first fix past this seq */
    K_GARBAGE = 3200,   /* undecodable messages after this sample */
    K_BAD_INIT = 3300,  /* invalid initial states after this sample */
    K_LAST = 3400       /* samples the input must hold */
};

typedef struct {
    lcm_eventlog_t *out;
    int64_t eventnum;
    int64_t n_imu_in, used, nonfinite, range, dup, ooo, bad_time, bad_dt, missing, early;
    int64_t decode, gnss_rej, resets, init_rej;
    int bad_init_done;
    se23lcm_imu_sample held; /* the first of a swapped pair */
    int64_t prev_t_ns;       /* time of the previous sample of the input */
    int have_held;
    int bad_gnss_done, garbage_done;
} ctx_t;

static void write_raw(ctx_t *c, const char *ch, int64_t ts, const void *data, int len)
{
    lcm_eventlog_event_t ev;
    ev.eventnum = c->eventnum++;
    ev.timestamp = ts;
    ev.channellen = (int32_t)strlen(ch);
    ev.datalen = len;
    ev.channel = (char *)ch;
    ev.data = (void *)data; /* LCM's type is not const; it is only written out */
    if (lcm_eventlog_write_event(c->out, &ev) != 0) {
        fprintf(stderr, "se23-corrupt: write failed\n");
        exit(1);
    }
}

static void write_imu(ctx_t *c, int64_t ts, const se23lcm_imu_sample *m)
{
    unsigned char buf[256];
    int len = se23lcm_imu_sample_encode(buf, 0, (int)sizeof buf, m);
    write_raw(c, HARNESS_CH_IMU, ts, buf, len);
}

static void write_gnss(ctx_t *c, int64_t ts, const se23lcm_gnss_fix *m)
{
    unsigned char buf[512];
    int len = se23lcm_gnss_fix_encode(buf, 0, (int)sizeof buf, m);
    write_raw(c, HARNESS_CH_GNSS, ts, buf, len);
}

static void garbage(ctx_t *c, int64_t ts, const se23lcm_imu_sample *m)
{
    unsigned char buf[512];
    se23lcm_gnss_fix g;
    int len, i;
    len = se23lcm_imu_sample_encode(buf, 0, (int)sizeof buf, m);
    write_raw(c, HARNESS_CH_IMU, ts, buf, len / 2); /* truncated */
    for (i = 0; i < 100; i++) {
        buf[i] = (unsigned char)(37 * i + 11);
    }
    write_raw(c, HARNESS_CH_IMU, ts, buf, 100); /* garbage */
    memset(&g, 0, sizeof g);
    len = se23lcm_gnss_fix_encode(buf, 0, (int)sizeof buf, &g);
    write_raw(c, HARNESS_CH_IMU, ts, buf, len); /* wrong type (fingerprint) */
    write_raw(c, HARNESS_CH_GNSS, ts, buf, len - 9); /* truncated fix */
    c->decode += 4;
}

/* One IMU sample of the input: applies the case planned for its seq. */
static void on_imu(ctx_t *c, int64_t ts, se23lcm_imu_sample m)
{
    int64_t k = m.seq;
    int64_t prev = c->prev_t_ns;
    c->n_imu_in++;
    c->prev_t_ns = m.t_ns;
    if (c->have_held) { /* second of the swapped pair first, then the held one */
        write_imu(c, ts, &m);
        write_imu(c, ts, &c->held);
        c->have_held = 0;
        c->used++;
        c->ooo++;
        c->missing++;
        return;
    }
    if (k >= K_GAP && k < K_GAP + GAP_LEN) {
        c->missing++;
        return;
    }
    if (k >= K_OUTAGE && k < K_OUTAGE + OUTAGE_LEN) {
        c->missing++;
        return;
    }
    if (k >= K_OUTAGE + OUTAGE_LEN && k < K_OUTAGE + OUTAGE_LEN + OUTAGE_CONFIRM) {
        write_imu(c, ts, &m); /* over the gap: rejected until the outage is confirmed */
        c->bad_dt++;
        if (k == K_OUTAGE + OUTAGE_LEN + OUTAGE_CONFIRM - 1) {
            c->resets++;
        }
        return;
    }
    switch (k) {
    case K_NAN:
        m.omega[0] = NAN;
        c->nonfinite++;
        break;
    case K_INF:
        m.accel[2] = INFINITY;
        c->nonfinite++;
        break;
    case K_RANGE:
        m.omega[1] = 1e3;
        c->range++;
        break;
    case K_DUP:
        write_imu(c, ts, &m);
        c->used++;
        c->dup++;
        break;
    case K_SWAP:
        c->held = m;
        c->have_held = 1;
        return;
    case K_REPEAT:
        m.t_ns = prev; /* the previous sample's time again */
        c->bad_time++;
        break;
    case K_BACK:
        m.t_ns -= 10000000000LL;
        c->bad_time++;
        break;
    case K_ABSURD:
        m.t_ns += 1000000000000LL;
        c->bad_dt++;
        break;
    default:
        c->used++;
        break;
    }
    write_imu(c, ts, &m);
    if (k > K_GARBAGE && !c->garbage_done) {
        garbage(c, ts, &m);
        c->garbage_done = 1;
    }
}

/* Three invalid copies of the initial state init. */
static void bad_inits(ctx_t *c, int64_t ts, const se23lcm_nav_state *init)
{
    unsigned char buf[4096];
    se23lcm_nav_state m;
    int len, k;
    for (k = 0; k < 3; k++) {
        m = *init;
        if (k == 0) {
            m.P[16 * 4] = NAN;
        } else if (k == 1) {
            m.R_nb[0] = 2.0; /* not a rotation */
        } else {
            m.P[16 * 7] = -1.0; /* negative variance */
        }
        len = se23lcm_nav_state_encode(buf, 0, (int)sizeof buf, &m);
        write_raw(c, HARNESS_CH_INIT, ts, buf, len);
    }
    c->init_rej += 3;
}

static void on_gnss(ctx_t *c, int64_t ts, const logfile_event_t *ev, int64_t last_seq)
{
    se23lcm_gnss_fix g;
    if (last_seq >= K_OUTAGE && last_seq < K_OUTAGE + OUTAGE_LEN) {
        return; /* the outage hits every sensor */
    }
    write_raw(c, ev->channel, ts, ev->data, ev->datalen);
    if (last_seq > K_BAD_GNSS && !c->bad_gnss_done &&
        se23lcm_gnss_fix_decode(ev->data, 0, ev->datalen, &g) >= 0) {
        se23lcm_gnss_fix bad = g;
        bad.p_n[1] = NAN;
        write_gnss(c, ts, &bad);
        bad = g;
        bad.sigma_p[2] = -1.0;
        write_gnss(c, ts, &bad);
        c->gnss_rej += 2;
        c->bad_gnss_done = 1;
    }
}

int main(int argc, char **argv)
{
    static ctx_t c;
    logfile_t in;
    logfile_event_t ev;
    int64_t last_seq = 0;
    int early_done = 0;
    se23lcm_nav_state init;
    int have_init = 0, corrupt = 0;
    if (argc == 4 && strcmp(argv[1], "--framing") == 0) {
        return corrupt_framing(argv[2], argv[3]);
    }
    if (argc == 4 && strcmp(argv[1], "--nav") == 0) {
        return corrupt_nav(argv[2], argv[3]);
    }
    if (argc != 3) {
        fprintf(stderr, "usage: se23-corrupt [--framing | --nav] IN.log OUT.log\n");
        return 2;
    }
    if (logfile_open(&in, argv[1], "se23-corrupt") != 0) {
        return 1;
    }
    c.out = lcm_eventlog_create(argv[2], "w");
    if (c.out == NULL) {
        fprintf(stderr, "se23-corrupt: cannot open %s\n", argv[2]);
        logfile_close(&in);
        return 1;
    }
    while (!corrupt && logfile_next(&in, &ev)) {
        if (!have_init && strcmp(ev.channel, HARNESS_CH_INIT) == 0) {
            have_init = se23lcm_nav_state_decode(ev.data, 0, ev.datalen, &init) >= 0;
        }
        if (have_init && !c.bad_init_done && last_seq > K_BAD_INIT) {
            bad_inits(&c, ev.timestamp, &init);
            c.bad_init_done = 1;
        }
        if (!early_done && strcmp(ev.channel, HARNESS_CH_INIT) == 0) {
            se23lcm_imu_sample e; /* a sample before the initial state */
            memset(&e, 0, sizeof e);
            e.seq = 1;
            e.t_ns = 1;
            write_imu(&c, ev.timestamp, &e);
            c.early++;
            early_done = 1;
        }
        if (strcmp(ev.channel, HARNESS_CH_IMU) == 0) {
            se23lcm_imu_sample m;
            if (se23lcm_imu_sample_decode(ev.data, 0, ev.datalen, &m) < 0) {
                corrupt = 1;
                break;
            }
            last_seq = m.seq;
            on_imu(&c, ev.timestamp, m);
        } else if (strcmp(ev.channel, HARNESS_CH_GNSS) == 0) {
            on_gnss(&c, ev.timestamp, &ev, last_seq);
        } else if (!(strcmp(ev.channel, HARNESS_CH_TRUTH) == 0 && last_seq >= K_OUTAGE &&
                     last_seq < K_OUTAGE + OUTAGE_LEN)) {
            write_raw(&c, ev.channel, ev.timestamp, ev.data, ev.datalen);
        }
    }
    corrupt = corrupt || in.bytes_skipped > 0;
    logfile_close(&in);
    lcm_eventlog_destroy(c.out);
    if (corrupt) {
        fprintf(stderr, "se23-corrupt: the input log is already corrupt\n");
        return 1;
    }
    if (c.n_imu_in < K_LAST) {
        fprintf(stderr, "se23-corrupt: the input has %lld IMU samples, needs %d\n",
                (long long)c.n_imu_in, K_LAST);
        return 1;
    }
    printf("expect imu_used %lld\n", (long long)c.used);
    printf("expect imu_nonfinite %lld\n", (long long)c.nonfinite);
    printf("expect imu_range %lld\n", (long long)c.range);
    printf("expect imu_duplicate %lld\n", (long long)c.dup);
    printf("expect imu_out_of_order %lld\n", (long long)c.ooo);
    printf("expect imu_bad_time %lld\n", (long long)c.bad_time);
    printf("expect imu_bad_dt %lld\n", (long long)c.bad_dt);
    printf("expect imu_missing %lld\n", (long long)c.missing);
    printf("expect imu_early %lld\n", (long long)c.early);
    printf("expect decode_errors %lld\n", (long long)c.decode);
    printf("expect gnss_rejected %lld\n", (long long)c.gnss_rej);
    printf("expect time_resets %lld\n", (long long)c.resets);
    printf("expect filter_errors 0\n");
    printf("expect init_rejected %lld\n", (long long)c.init_rej);
    return 0;
}
