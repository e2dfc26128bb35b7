/**
 * @file csv.h
 * @brief Bounded CSV line reading and field parsing for se23-import: never
 *        allocates from what it reads, never trusts a length in the file.
 *
 * Lines end in LF; a CR before the LF (CRLF) is dropped; a UTF-8 byte order
 * mark (EF BB BF) at the start of the file is dropped. A line longer than
 * CSV_LINE_MAX bytes is flagged too long and the rest of it is read and
 * thrown away, so memory stays CSV_LINE_MAX whatever the file holds; a
 * line that goes on for CSV_RUNAWAY_MAX bytes without a line end stops the
 * reading (runaway), so time stays bounded too (/dev/zero, a binary file).
 * Fields are separated by commas; spaces and tabs around a field are not
 * part of it; empty fields at the end of a line (a trailing comma) are not
 * counted. No quoting: a quoted number is text.
 */
#ifndef SE23_IMPORT_CSV_H
#define SE23_IMPORT_CSV_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#define CSV_LINE_MAX 4096 /**< longest line kept [bytes, without the LF] */

/**
 * Longest line read at all [bytes]: 4 MiB, 1024 times CSV_LINE_MAX. An
 * IMU row is about 100 bytes and a line over CSV_LINE_MAX is already junk,
 * skipped as malformed: a damaged stretch of a recording (a garbled burst,
 * a run of NULs after a power loss) up to this size is skipped that way and
 * the rows after it are still read. A file that goes on this long without a
 * line end is not line-based text (a binary file, /dev/zero, an unending
 * stream): reading it to its end would take forever, or a long while for
 * nothing, so the reader stops there (after some 20 ms of reading).
 */
#define CSV_RUNAWAY_MAX (1024L * CSV_LINE_MAX)

typedef struct {
    FILE *f;
    char buf[CSV_LINE_MAX + 1]; /**< the line, NUL-terminated (no LF, no CR) */
    size_t len;                 /**< bytes in buf */
    int64_t lineno;             /**< 1-based number of the line in buf */
    int too_long;               /**< the line had more than CSV_LINE_MAX bytes */
    int has_nul;                /**< the line holds a NUL byte */
    int runaway;                /**< line lineno had no line end within
                                     CSV_RUNAWAY_MAX bytes: reading stopped */
} csv_reader_t;

/** r reads f from its current position; line numbers start at 1. */
void csv_reader_init(csv_reader_t *r, FILE *f);

/**
 * The next line into r: 1, or 0 at the end of the file, a read error or a
 * runaway line (r->runaway set, r->lineno its number; every later call
 * returns 0 too).
 */
int csv_read_line(csv_reader_t *r);

/** A field: [p, p + len) of a line, spaces and tabs trimmed. */
typedef struct {
    const char *p;
    size_t len;
} csv_field_t;

/**
 * Splits line (NUL-terminated) into fields. Stores the first max of them
 * in out (if out is not NULL) and returns how many fields the line has
 * (trailing empty fields not counted; a blank line has 0).
 */
int csv_split(const char *line, csv_field_t *out, int max);

/** Result of parsing a number field. */
typedef enum {
    CSV_NUM_OK = 0,
    CSV_NUM_TEXT,     /**< empty, not a number, or text after it */
    CSV_NUM_NONFINITE /**< NaN, Inf, or out of the double range */
} csv_num_t;

/** The field as a finite double (strtod syntax, the whole field). */
csv_num_t csv_parse_real(csv_field_t fld, double *out);

/**
 * The field as a decimal number [+-]digits[.digits][(e|E)[+-]digits] times
 * 10^unit_exp (9 for seconds, 0 for nanoseconds), rounded to the nearest
 * integer (halves away from zero), exactly: no binary floating point, so
 * 1.7e9 s of Unix time keeps its nanoseconds. Out of the int64 range counts
 * as CSV_NUM_NONFINITE; "nan", "inf" are CSV_NUM_NONFINITE too.
 */
csv_num_t csv_parse_time(csv_field_t fld, int unit_exp, int64_t *out);

#endif /* SE23_IMPORT_CSV_H */
