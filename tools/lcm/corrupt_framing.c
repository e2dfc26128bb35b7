/*
 * se23-corrupt --framing IN.log OUT.log: copies a se23-sim log event by
 * event, writing each event's bytes itself so that it can break them. At the
 * first IMU event from each index below whose predecessor is also an IMU
 * event (so that what reading past it costs is exactly counted):
 *
 *   1000  data length INT32_MAX           the event is lost, its bytes skipped
 *   1500  data length 7 bytes too long    (runs into the next event) lost, skipped
 *   2000  channel length 0                lost, skipped
 *   2500  sync word broken                lost, skipped; the event before it kept
 *   3000  40 stray bytes before it, with  the stray bytes skipped, the event kept
 *         a false sync word among them
 *   3500  data length 5 bytes too short   read short (a decode error), its last
 *                                         5 bytes skipped
 *   end   20 bytes of a header            (a log cut while writing) skipped
 *
 * and prints what se23-ins must count: 5 IMU samples missing (one decode
 * error among them), the rest used, log_skipped_bytes the sum above.
 */
#define _POSIX_C_SOURCE 200809L
#include "corrupt_framing.h"

#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "harness.h"
#include "logfile.h"

typedef enum { C_HUGE, C_LONG, C_NO_CHANNEL, C_SYNC, C_STRAY, C_SHORT, C_COUNT } case_t;

static const int64_t case_from[C_COUNT] = {1000, 1500, 2000, 2500, 3000, 3500};

enum { STRAY_LEN = 40, TAIL_LEN = 20, LONG_BY = 7, SHORT_BY = 5 };

static void put32(unsigned char *p, uint32_t v)
{
    p[0] = (unsigned char)(v >> 24);
    p[1] = (unsigned char)(v >> 16);
    p[2] = (unsigned char)(v >> 8);
    p[3] = (unsigned char)v;
}

/* An event header with the given (possibly false) fields into h. */
static void header(unsigned char h[LOGFILE_HEADER], uint32_t sync, int64_t num, int64_t ts,
                   uint32_t cl, uint32_t dl)
{
    put32(h, sync);
    put32(h + 4, (uint32_t)((uint64_t)num >> 32));
    put32(h + 8, (uint32_t)num);
    put32(h + 12, (uint32_t)((uint64_t)ts >> 32));
    put32(h + 16, (uint32_t)ts);
    put32(h + 20, cl);
    put32(h + 24, dl);
}

/* The event ev written with case c applied (C_COUNT: none); bytes skipped. */
static int64_t write_event(FILE *f, int64_t num, const logfile_event_t *ev, case_t c)
{
    unsigned char h[LOGFILE_HEADER], stray[STRAY_LEN];
    uint32_t sync = LOGFILE_SYNC, cl = (uint32_t)strlen(ev->channel), dl = (uint32_t)ev->datalen;
    int64_t size = LOGFILE_HEADER + (int64_t)cl + ev->datalen, skipped = size;
    switch (c) {
    case C_HUGE:
        dl = INT32_MAX;
        break;
    case C_LONG:
        dl += LONG_BY;
        break;
    case C_NO_CHANNEL:
        cl = 0;
        break;
    case C_SYNC:
        sync ^= 1u;
        break;
    case C_STRAY:
        memset(stray, 0xED, sizeof stray);
        header(stray, LOGFILE_SYNC, num, ev->timestamp, UINT32_MAX, 0); /* a false event */
        fwrite(stray, 1, sizeof stray, f);
        skipped = STRAY_LEN;
        break;
    case C_SHORT:
        dl -= SHORT_BY;
        skipped = SHORT_BY;
        break;
    case C_COUNT:
    default:
        skipped = 0;
        break;
    }
    header(h, sync, num, ev->timestamp, cl, dl);
    fwrite(h, 1, sizeof h, f);
    fwrite(ev->channel, 1, strlen(ev->channel), f);
    fwrite(ev->data, 1, (size_t)ev->datalen, f);
    return skipped;
}

int corrupt_framing(const char *in, const char *out)
{
    logfile_t lf;
    logfile_event_t ev;
    unsigned char h[LOGFILE_HEADER];
    FILE *f;
    int64_t num = 0, n_imu = 0, skipped = 0, lost = 0;
    int prev_imu = 0, next = 0;
    if (logfile_open(&lf, in, "se23-corrupt") != 0) {
        return 1;
    }
    f = fopen(out, "wb");
    if (f == NULL) {
        fprintf(stderr, "se23-corrupt: cannot write %s\n", out);
        logfile_close(&lf);
        return 1;
    }
    while (logfile_next(&lf, &ev)) {
        int imu = strcmp(ev.channel, HARNESS_CH_IMU) == 0;
        case_t c = C_COUNT;
        if (imu && prev_imu && next < C_COUNT && n_imu >= case_from[next]) {
            c = (case_t)next++;
        }
        skipped += write_event(f, num++, &ev, c);
        lost += c != C_COUNT && c != C_STRAY;
        n_imu += imu;
        prev_imu = imu;
    }
    header(h, LOGFILE_SYNC, num, 0, 8, 0);
    fwrite(h, 1, TAIL_LEN, f); /* cut while writing */
    skipped += TAIL_LEN;
    if (fclose(f) != 0 || lf.bytes_skipped > 0 || next < C_COUNT) {
        fprintf(stderr, "se23-corrupt: %s\n",
                lf.bytes_skipped > 0 ? "the input log is already corrupt"
                : next < C_COUNT     ? "the input log is too short"
                                     : "write failed");
        logfile_close(&lf);
        return 1;
    }
    logfile_close(&lf);
    printf("expect imu_used %lld\n", (long long)(n_imu - lost));
    printf("expect imu_missing %lld\n", (long long)lost);
    printf("expect decode_errors 1\n");
    printf("expect log_skipped_bytes %lld\n", (long long)skipped);
    printf("expect imu_bad_dt 0\n");
    printf("expect imu_bad_time 0\n");
    printf("expect imu_out_of_order 0\n");
    printf("expect time_resets 0\n");
    printf("expect filter_errors 0\n");
    return 0;
}
