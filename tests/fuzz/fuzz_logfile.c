/*
 * libFuzzer target of the tools' LCM log reader (tools/lcm/logfile.c): the
 * input is written as a log file (a memfd, opened by its /proc path: a
 * regular file the reader maps like any other) and read to the end; every
 * event is decoded with each of the generated LCM types, as se23-ins and
 * se23-report decode the events of their channels (a hostile log may put
 * any bytes on any channel, so every type meets every event). Oracle (logfile.h): no
 * crash, no out-of-bounds read (AddressSanitizer); every event starts with
 * the sync word, lies within the file after the previous one, has a
 * printable channel of 1..LCM_MAX_CHANNEL_NAME_LENGTH bytes and a data
 * length in 0..LCM_MAX_MESSAGE_SIZE, its data pointer in the mapping; a
 * decoder that succeeds consumed no more than the data length; and the
 * events and the bytes skipped add up to the file.
 *
 * The reader's one line per corrupt span goes to stderr; the target points
 * stderr at /dev/null (FUZZ_LOG_STDERR=1 keeps it). libFuzzer and the
 * sanitizers write to file descriptor 2 directly, which stays open.
 */
#define _GNU_SOURCE
#include <sys/mman.h>
#include <unistd.h>

#include "fuzz.h"
#include "logfile.h"
#include "se23lcm_gnss_fix.h"
#include "se23lcm_imu_sample.h"
#include "se23lcm_nav_state.h"
#include "se23lcm_preint_factor.h"
#include "se23lcm_sim_info.h"
#include "se23lcm_truth.h"

static int log_fd = -1;
static char log_path[64];

int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerInitialize(int *argc, char ***argv)
{
    (void)argc;
    (void)argv;
    log_fd = memfd_create("fuzz_logfile", 0);
    if (log_fd < 0) {
        perror("memfd_create");
        abort();
    }
    snprintf(log_path, sizeof log_path, "/proc/self/fd/%d", log_fd);
    if (getenv("FUZZ_LOG_STDERR") == NULL) {
        FILE *null = fopen("/dev/null", "w");
        if (null != NULL) {
            fz_err_stream = stderr;
            stderr = null;
        }
    }
    return 0;
}

/* Decodes the event with every type (tools/ins/main.c, tools/report/logread.c). */
static void decode_all(const logfile_event_t *ev)
{
    const int len = ev->datalen;
    int r;
    {
        se23lcm_imu_sample m;
        r = se23lcm_imu_sample_decode(ev->data, 0, len, &m);
        FZ_REQUIRE(r < 0 || (r <= len && r == se23lcm_imu_sample_encoded_size(&m)),
                   "imu_sample decoded %d of %d bytes", r, len);
    }
    {
        se23lcm_gnss_fix m;
        r = se23lcm_gnss_fix_decode(ev->data, 0, len, &m);
        FZ_REQUIRE(r < 0 || (r <= len && r == se23lcm_gnss_fix_encoded_size(&m)),
                   "gnss_fix decoded %d of %d bytes", r, len);
    }
    {
        se23lcm_nav_state m;
        r = se23lcm_nav_state_decode(ev->data, 0, len, &m);
        FZ_REQUIRE(r < 0 || (r <= len && r == se23lcm_nav_state_encoded_size(&m)),
                   "nav_state decoded %d of %d bytes", r, len);
    }
    {
        se23lcm_preint_factor m;
        r = se23lcm_preint_factor_decode(ev->data, 0, len, &m);
        FZ_REQUIRE(r < 0 || (r <= len && r == se23lcm_preint_factor_encoded_size(&m)),
                   "preint_factor decoded %d of %d bytes", r, len);
    }
    {
        se23lcm_sim_info m;
        r = se23lcm_sim_info_decode(ev->data, 0, len, &m);
        FZ_REQUIRE(r < 0 || (r <= len && r == se23lcm_sim_info_encoded_size(&m)),
                   "sim_info decoded %d of %d bytes", r, len);
    }
    {
        se23lcm_truth m;
        r = se23lcm_truth_decode(ev->data, 0, len, &m);
        FZ_REQUIRE(r < 0 || (r <= len && r == se23lcm_truth_encoded_size(&m)),
                   "truth decoded %d of %d bytes", r, len);
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    logfile_t lf;
    logfile_event_t ev;
    size_t done = 0, end = 0, in_events = 0;
    FZ_REQUIRE(ftruncate(log_fd, 0) == 0, "ftruncate");
    while (done < size) {
        const ssize_t w = pwrite(log_fd, data + done, size - done, (off_t)done);
        FZ_REQUIRE(w > 0, "pwrite");
        done += (size_t)w;
    }
    FZ_REQUIRE(logfile_open(&lf, log_path, "fuzz_logfile") == 0, "logfile_open of a regular file");
    FZ_REQUIRE(lf.size == size, "mapped %zu of %zu bytes", lf.size, size);
    while (logfile_next(&lf, &ev)) {
        const size_t cl = strlen(ev.channel);
        const unsigned char *p = lf.map + ev.offset;
        size_t i;
        FZ_REQUIRE(ev.offset >= end && ev.offset < size, "event at %zu after %zu", ev.offset, end);
        FZ_REQUIRE(memcmp(p, "\xED\xA1\xDA\x01", 4) == 0, "event at %zu: no sync word", ev.offset);
        FZ_REQUIRE(cl >= 1 && cl <= LCM_MAX_CHANNEL_NAME_LENGTH, "channel of %zu bytes", cl);
        for (i = 0; i < cl; ++i) {
            FZ_REQUIRE(ev.channel[i] >= 0x21 && ev.channel[i] <= 0x7e, "channel not printable");
        }
        FZ_REQUIRE(ev.datalen >= 0 && ev.datalen <= LCM_MAX_MESSAGE_SIZE, "data length %ld",
                   (long)ev.datalen);
        FZ_REQUIRE((const unsigned char *)ev.data == p + LOGFILE_HEADER + cl,
                   "data pointer off the event");
        end = ev.offset + LOGFILE_HEADER + cl + (size_t)ev.datalen;
        FZ_REQUIRE(end <= size, "event at %zu ends at %zu, past the file (%zu)", ev.offset, end,
                   size);
        FZ_REQUIRE(lf.off == end, "reader at %zu after an event ending at %zu", lf.off, end);
        in_events += end - ev.offset;
        decode_all(&ev);
    }
    FZ_REQUIRE(lf.bytes_skipped >= 0 && (size_t)lf.bytes_skipped + in_events == size,
               "%zu bytes in events + %lld skipped != %zu", in_events, (long long)lf.bytes_skipped,
               size);
    FZ_REQUIRE((lf.bytes_skipped == 0) == (lf.corrupt_spans == 0), "%lld bytes skipped in %lld spans",
               (long long)lf.bytes_skipped, (long long)lf.corrupt_spans);
    logfile_close(&lf);
    return 0;
}
