/* Validating LCM event-log reader; see logfile.h. */
#define _POSIX_C_SOURCE 200809L
#include "logfile.h"

#include <errno.h>
#include <fcntl.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

static const unsigned char sync_bytes[4] = {0xED, 0xA1, 0xDA, 0x01};

static uint32_t be32(const unsigned char *p)
{
    return (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | (uint32_t)p[3];
}

static int32_t be32s(const unsigned char *p)
{
    uint32_t u = be32(p);
    return u <= INT32_MAX ? (int32_t)u : (int32_t)(u - INT32_MAX - 1) + INT32_MIN;
}

static int64_t be64s(const unsigned char *p)
{
    uint64_t u = (uint64_t)be32(p) << 32 | be32(p + 4);
    return u <= INT64_MAX ? (int64_t)u : (int64_t)(u - INT64_MAX - 1) + INT64_MIN;
}

/* Says why (when why is not NULL); returns 0. */
static int reject(char *why, size_t n, const char *fmt, ...)
{
    va_list ap;
    if (why != NULL) {
        va_start(ap, fmt);
        vsnprintf(why, n, fmt, ap);
        va_end(ap);
    }
    return 0;
}

/*
 * Checks the header of the event at off; on success *end is the offset
 * after it. Otherwise, if why is not NULL, says what is wrong.
 */
static int header_ok(const logfile_t *lf, size_t off, size_t *end, char *why, size_t n)
{
    const unsigned char *p = lf->map + off;
    int32_t cl, dl;
    size_t left = lf->size - off, i;
    if (left < LOGFILE_HEADER) {
        return reject(why, n, "truncated header (%zu bytes left)", left);
    }
    left -= LOGFILE_HEADER;
    cl = be32s(p + 20);
    dl = be32s(p + 24);
    if (be32(p) != LOGFILE_SYNC) {
        return reject(why, n, "no sync word (0x%08lx)", (unsigned long)be32(p));
    }
    if (cl < 1 || cl > LCM_MAX_CHANNEL_NAME_LENGTH || (size_t)cl > left) {
        return reject(why, n, "channel length %ld, %zu bytes left in the file", (long)cl, left);
    }
    left -= (size_t)cl;
    if (dl < 0 || dl > LCM_MAX_MESSAGE_SIZE || (size_t)dl > left) {
        return reject(why, n, "data length %ld, %zu bytes left in the file", (long)dl, left);
    }
    for (i = 0; i < (size_t)cl; i++) {
        if (p[LOGFILE_HEADER + i] < 0x21 || p[LOGFILE_HEADER + i] > 0x7e) {
            return reject(why, n, "channel name not printable");
        }
    }
    *end = off + LOGFILE_HEADER + (size_t)cl + (size_t)dl;
    return 1;
}

/* The end of the file or a sync word (as much of it as the file holds) at end. */
static int followed(const logfile_t *lf, size_t end)
{
    size_t k = lf->size - end < 4 ? lf->size - end : 4;
    return memcmp(lf->map + end, sync_bytes, k) == 0;
}

/* A valid event at off, followed by the end of the file or a sync word. */
static int framed(const logfile_t *lf, size_t off)
{
    size_t end;
    return header_ok(lf, off, &end, NULL, 0) && followed(lf, end);
}

/* Offset of the first framed event in [from, to), or to. */
static size_t next_framed(const logfile_t *lf, size_t from, size_t to)
{
    size_t k;
    for (k = from; k < to; k++) {
        const unsigned char *hit = memchr(lf->map + k, sync_bytes[0], to - k);
        if (hit == NULL) {
            return to;
        }
        k = (size_t)(hit - lf->map);
        if (framed(lf, k)) {
            return k;
        }
    }
    return to;
}

/* The event at off is accepted (logfile.h); *end as for header_ok. */
static int accepted(const logfile_t *lf, size_t off, size_t *end, char *why, size_t n)
{
    if (!header_ok(lf, off, end, why, n)) {
        return 0;
    }
    if (!followed(lf, *end) && next_framed(lf, off + 1, *end) < *end) {
        return reject(why, n, "data length %ld runs into the next event",
                      (long)be32s(lf->map + off + 24));
    }
    return 1;
}

int logfile_open(logfile_t *lf, const char *path, const char *prog)
{
    struct stat st;
    void *m = NULL;
    const char *err = NULL;
    int fd = open(path, O_RDONLY);
    memset(lf, 0, sizeof *lf);
    lf->prog = prog;
    lf->path = path;
    if (fd < 0 || fstat(fd, &st) != 0) {
        err = strerror(errno);
    } else if (!S_ISREG(st.st_mode) || (uintmax_t)st.st_size > SIZE_MAX) {
        err = "not a regular file";
    } else if (st.st_size > 0) {
        m = mmap(NULL, (size_t)st.st_size, PROT_READ, MAP_PRIVATE, fd, 0);
        err = m == MAP_FAILED ? strerror(errno) : NULL;
    }
    if (fd >= 0) {
        close(fd);
    }
    if (err != NULL) {
        fprintf(stderr, "%s: cannot read %s: %s\n", prog, path, err);
        return -1;
    }
    lf->map = m;
    lf->size = m != NULL ? (size_t)st.st_size : 0;
    return 0;
}

int logfile_next(logfile_t *lf, logfile_event_t *ev)
{
    const unsigned char *p;
    size_t end, cl;
    char why[128];
    if (lf->off >= lf->size) {
        return 0;
    }
    if (!accepted(lf, lf->off, &end, why, sizeof why)) {
        size_t next = next_framed(lf, lf->off + 1, lf->size);
        fprintf(stderr, "%s: %s: corrupt event at byte %zu: %s; %zu bytes skipped%s\n", lf->prog,
                lf->path, lf->off, why, next - lf->off,
                next < lf->size ? "" : " (to the end of the file)");
        lf->bytes_skipped += (int64_t)(next - lf->off);
        lf->corrupt_spans++;
        lf->off = next;
        if (!header_ok(lf, lf->off, &end, NULL, 0)) {
            return 0; /* the end of the file */
        }
    }
    p = lf->map + lf->off;
    cl = (size_t)be32s(p + 20);
    ev->offset = lf->off;
    ev->timestamp = be64s(p + 12);
    memcpy(ev->channel, p + LOGFILE_HEADER, cl);
    ev->channel[cl] = '\0';
    ev->data = p + LOGFILE_HEADER + cl;
    ev->datalen = be32s(p + 24);
    lf->off = end;
    return 1;
}

void logfile_close(logfile_t *lf)
{
    if (lf->map != NULL) {
        munmap((void *)lf->map, lf->size);
    }
    memset(lf, 0, sizeof *lf);
}
