/**
 * @file logfile.h
 * @brief Reads LCM event logs (the file:// format of LCM 1.3.1) without
 *        trusting them: the one log reader of se23-ins's file input,
 *        se23-report and se23-corrupt.
 *
 * An event is, big-endian: u32 sync word 0xEDA1DA01, i64 event number,
 * i64 timestamp [us], i32 channel length, i32 data length, the channel name,
 * the data (LOGFILE_HEADER bytes before the name). An event is accepted when
 *  - its sync word is there, the channel length is in
 *    1..LCM_MAX_CHANNEL_NAME_LENGTH, the name printable ASCII, the data length
 *    in 0..LCM_MAX_MESSAGE_SIZE, and the whole event lies within the file;
 *  - and it is framed: the end of the file or the next sync word follows it
 *    (if neither does, it is still accepted when no framed event starts
 *    inside it, i.e. when it is what follows that is broken).
 * Anything else is corrupt: one line on stderr names the file, the byte
 * offset and the reason, and reading goes on at the next framed event (the
 * next sync word that starts a valid event followed by a sync word or the
 * end of the file). The bytes passed over are counted. Nothing is allocated
 * from a length read in the file: the file is mapped, events point into it.
 */
#ifndef SE23_LOGFILE_H
#define SE23_LOGFILE_H

#include <lcm/lcm.h>
#include <stddef.h>
#include <stdint.h>

#define LOGFILE_SYNC 0xEDA1DA01u /**< first word of every event */
#define LOGFILE_HEADER 28        /**< bytes before the channel name */

typedef struct {
    const unsigned char *map; /**< the file, mapped read-only (NULL if empty) */
    size_t size;              /**< file size [bytes] */
    size_t off;               /**< offset of the next event */
    const char *prog;         /**< message prefix */
    const char *path;
    int64_t bytes_skipped;    /**< bytes passed over as corrupt */
    int64_t corrupt_spans;    /**< places where reading had to resynchronise */
} logfile_t;

typedef struct {
    size_t offset;     /**< byte offset of the event in the file */
    int64_t timestamp; /**< [us], as written by the logger */
    char channel[LCM_MAX_CHANNEL_NAME_LENGTH + 1];
    const void *data;  /**< into the mapping, valid until logfile_close */
    int32_t datalen;
} logfile_event_t;

/**
 * Maps the regular file at path for reading. prog prefixes the messages.
 * Returns 0, or -1 after printing why the file cannot be read.
 */
int logfile_open(logfile_t *lf, const char *path, const char *prog);

/** The next valid event into *ev: 1, or 0 at the end of the file. */
int logfile_next(logfile_t *lf, logfile_event_t *ev);

void logfile_close(logfile_t *lf);

#endif /* SE23_LOGFILE_H */
