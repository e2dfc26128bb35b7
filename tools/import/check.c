/*
 * se23-importcheck: reads an IMU log (file://, as se23-import writes it)
 * back with the harness's log reader and prints what it holds, one
 * "name value" line each (for tests/check.d/67-import.sh):
 *
 *   samples        SE23_IMU samples decoded
 *   decode_errors  SE23_IMU and SE23_IMU_INFO events that did not decode
 *   other_events   events on other channels
 *   info_events    SE23_IMU_INFO messages before the first sample
 *   info_late      ... after it (se23-import writes one, before)
 *   info_rate_hz, info_rate_source, info_n_intervals  of the last one (%.17g)
 *   seq_missing    sequence numbers skipped (sum of seq steps - 1)
 *   seq_bad        samples whose seq is not above the previous one
 *   time_bad       samples whose t_ns is not above the previous one
 *   first_t_ns, first_seq, first_omega (3), first_accel (3)  (%.17g)
 *   last_t_ns, last_seq
 *
 * Exit status: 0 the log was read (corrupt bytes skipped: 3), 1 it cannot
 * be read, 2 bad usage.
 *
 * usage: se23-importcheck LOG
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../lcm/harness.h"
#include "../lcm/logfile.h"
#include "se23lcm_imu_info.h"
#include "se23lcm_imu_sample.h"

typedef struct {
    int64_t samples, decode_errors, other, seq_missing, seq_bad, time_bad;
    int64_t info_events, info_late;
    se23lcm_imu_sample first, last;
    se23lcm_imu_info info;
} tally_t;

static void usage(FILE *f)
{
    fprintf(f, "usage: se23-importcheck LOG\n"
               "  prints the SE23_IMU samples of LOG: count, sequence and time order,\n"
               "  the first and the last sample; and its SE23_IMU_INFO\n");
}

static void add(tally_t *t, const se23lcm_imu_sample *s)
{
    if (t->samples == 0) {
        t->first = *s;
    } else {
        if (s->seq > t->last.seq) {
            t->seq_missing += s->seq - t->last.seq - 1;
        } else {
            t->seq_bad++;
        }
        t->time_bad += s->t_ns <= t->last.t_ns;
    }
    t->last = *s;
    t->samples++;
}

/* An event of LOG into t. */
static void take(tally_t *t, const logfile_event_t *ev)
{
    se23lcm_imu_sample s;
    if (strcmp(ev->channel, HARNESS_CH_IMU_INFO) == 0) {
        if (se23lcm_imu_info_decode(ev->data, 0, ev->datalen, &t->info) < 0) {
            t->decode_errors++;
        } else {
            t->info_events += t->samples == 0;
            t->info_late += t->samples > 0;
        }
    } else if (strcmp(ev->channel, HARNESS_CH_IMU) != 0) {
        t->other++;
    } else if (se23lcm_imu_sample_decode(ev->data, 0, ev->datalen, &s) < 0) {
        t->decode_errors++;
    } else {
        add(t, &s);
    }
}

static void print3(const char *name, const double v[3])
{
    printf("%s %.17g %.17g %.17g\n", name, v[0], v[1], v[2]);
}

int main(int argc, char **argv)
{
    const char *pos[2] = {NULL, NULL};
    int n_pos = 0;
    logfile_t lf;
    logfile_event_t ev;
    tally_t t;
    if (argc > 2 || harness_parse_opts("se23-importcheck", argc, argv, NULL, 0, usage, pos,
                                       &n_pos) != 0 ||
        n_pos != 1) {
        usage(stderr);
        return 2;
    }
    if (logfile_open(&lf, pos[0], "se23-importcheck") != 0) {
        return 1;
    }
    memset(&t, 0, sizeof t);
    while (logfile_next(&lf, &ev)) {
        take(&t, &ev);
    }
    printf("samples %lld\ndecode_errors %lld\nother_events %lld\n", (long long)t.samples,
           (long long)t.decode_errors, (long long)t.other);
    printf("info_events %lld\ninfo_late %lld\n", (long long)t.info_events,
           (long long)t.info_late);
    printf("info_rate_hz %.17g\ninfo_rate_source %d\ninfo_n_intervals %lld\n", t.info.rate_hz,
           t.info.rate_source, (long long)t.info.n_intervals);
    printf("seq_missing %lld\nseq_bad %lld\ntime_bad %lld\n", (long long)t.seq_missing,
           (long long)t.seq_bad, (long long)t.time_bad);
    printf("first_t_ns %lld\nfirst_seq %lld\n", (long long)t.first.t_ns, (long long)t.first.seq);
    print3("first_omega", t.first.omega);
    print3("first_accel", t.first.accel);
    printf("last_t_ns %lld\nlast_seq %lld\n", (long long)t.last.t_ns, (long long)t.last.seq);
    n_pos = lf.bytes_skipped > 0 ? 3 : 0;
    logfile_close(&lf);
    return n_pos;
}
