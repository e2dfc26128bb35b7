/**
 * @file hygiene.h
 * @brief The time checks of se23-import: repeated and backward timestamps,
 *        gaps (lost samples), sequence numbers, clipping counts.
 *
 * A row is compared with the last row written. Same time: dropped, counted
 * as a repeated timestamp (and as having the same values if all six raw
 * values repeat too). Earlier time: dropped, counted as going backwards.
 * Later time: written with the next sequence number plus the samples lost
 * before it, lost = round(interval / nominal) - 1 when that is >= 1 (a gap),
 * so that a downstream INS counts them as missing.
 */
#ifndef SE23_IMPORT_HYGIENE_H
#define SE23_IMPORT_HYGIENE_H

#include <stddef.h>
#include <stdint.h>

#include "row.h"

/** Every counter of the summary. */
typedef struct {
    int64_t header;              /**< header lines skipped */
    int64_t blank;               /**< blank lines after the header (not rows) */
    int64_t rows;                /**< data rows read */
    int64_t written;             /**< samples written */
    int64_t dup_time;            /**< repeated the previous timestamp: dropped */
    int64_t dup_same;            /**< ... of them with the same values too */
    int64_t backwards;           /**< earlier than the previous row: dropped */
    int64_t gaps;                /**< intervals that lost samples */
    int64_t lost;                /**< samples lost in them */
    int64_t longest_gap_ns;      /**< the longest such interval */
    int64_t gyro_clipped;        /**< samples with a gyro value at its range (kept) */
    int64_t accel_clipped;       /**< samples with an accel value at its range (kept) */
    int64_t bad_columns;         /**< malformed: wrong number of fields */
    int64_t bad_number;          /**< malformed: text in a number field */
    int64_t bad_nonfinite;       /**< malformed: NaN or Inf */
    int64_t bad_long;            /**< malformed: line over CSV_LINE_MAX bytes */
    int64_t first_t_ns, last_t_ns; /**< of the samples written */
    int64_t seq;                 /**< sequence number of the last sample written */
} import_count_t;

/** Rows that were malformed (skipped). */
int64_t import_malformed(const import_count_t *c);

typedef enum { HYG_WRITE = 0, HYG_DUP, HYG_BACK } hyg_action_t;

typedef struct {
    double nominal_ns; /**< nominal interval [ns]; 0: no gap detection */
    int have_last;
    row_t last;        /**< the last row written */
    import_count_t c;
} hygiene_t;

/** h before the first row; nominal_ns as in hygiene_t. */
void hygiene_init(hygiene_t *h, double nominal_ns);

/**
 * Judges the valid row r: counts it, and for HYG_WRITE gives its sequence
 * number in *seq (and remembers r as the last row written).
 */
hyg_action_t hygiene_accept(hygiene_t *h, const row_t *r, int64_t *seq);

/** Median of dt[0..n-1] (n >= 1; dt is reordered) [ns]. */
double hygiene_median(int64_t *dt, size_t n);

#endif /* SE23_IMPORT_HYGIENE_H */
