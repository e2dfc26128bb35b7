/* se23-ins's file input; see replay.h. */
#define _POSIX_C_SOURCE 200809L
#include "replay.h"

#include <stdio.h>
#include <string.h>

#include "../lcm/harness.h"
#include "../lcm/logfile.h"

#define PREFIX "file://"

/* Splits url into path (size n) and the replay speed; 0 on success. */
static int parse_url(const char *url, char *path, size_t n, double *speed)
{
    const char *q;
    char opts[256];
    char *opt, *save = NULL;
    size_t len;
    if (strncmp(url, PREFIX, strlen(PREFIX)) != 0) {
        return -1;
    }
    url += strlen(PREFIX);
    q = strchr(url, '?');
    len = q != NULL ? (size_t)(q - url) : strlen(url);
    if (len == 0 || len >= n || (q != NULL && strlen(q + 1) >= sizeof opts)) {
        return -1;
    }
    memcpy(path, url, len);
    path[len] = '\0';
    *speed = 1.0;
    if (q == NULL) {
        return 0;
    }
    strcpy(opts, q + 1);
    for (opt = strtok_r(opts, "&", &save); opt != NULL; opt = strtok_r(NULL, "&", &save)) {
        if (strncmp(opt, "speed=", 6) == 0) {
            if (harness_parse_double(opt + 6, speed) != 0 || *speed < 0.0) {
                return -1;
            }
        } else if (strcmp(opt, "mode=r") != 0) {
            return -1;
        }
    }
    return 0;
}

/* With speed > 0, waits until the event at ts [us] is due (ts0 at wall0). */
static void pace(double speed, int64_t ts0, int64_t wall0, int64_t ts)
{
    double delay_ns = ((double)ts - (double)ts0) * 1e3 / speed;
    if (delay_ns > 0.0) {
        harness_sleep_until_ns(wall0 + (int64_t)(delay_ns < 1e17 ? delay_ns : 1e17));
    }
}

int64_t replay_file(const char *url, const replay_sub_t *subs, int n_subs, void *user,
                    int (*stop)(void *user))
{
    char path[4096];
    double speed;
    logfile_t lf;
    logfile_event_t ev;
    int64_t ts0 = 0, wall0 = 0, skipped;
    int first = 1, k;
    if (parse_url(url, path, sizeof path, &speed) != 0) {
        fprintf(stderr, "se23-ins: unsupported input URL %s (file://PATH[?speed=S])\n", url);
        return -1;
    }
    if (logfile_open(&lf, path, "se23-ins") != 0) {
        return -1;
    }
    while (!stop(user) && logfile_next(&lf, &ev)) {
        lcm_recv_buf_t rb;
        if (speed > 0.0) {
            if (first) {
                ts0 = ev.timestamp;
                wall0 = harness_now_ns();
                first = 0;
            }
            pace(speed, ts0, wall0, ev.timestamp);
        }
        rb.data = (void *)ev.data; /* LCM's type is not const; handlers only decode */
        rb.data_size = (uint32_t)ev.datalen;
        rb.recv_utime = ev.timestamp;
        rb.lcm = NULL;
        for (k = 0; k < n_subs; k++) {
            if (strcmp(ev.channel, subs[k].channel) == 0) {
                subs[k].handler(&rb, ev.channel, user);
            }
        }
    }
    skipped = lf.bytes_skipped;
    logfile_close(&lf);
    return skipped;
}
