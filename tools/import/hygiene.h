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
 *
 * The unit checks look for rests (hygiene_rest): the specific force at the
 * first must read about 1 g, else the file is in another unit than the one
 * given (main.c decides and says which); between rests, the gyroscope must
 * explain how the direction of gravity changed (gyrocheck.h).
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

/**
 * A rest: at least HYG_REST_NS and HYG_REST_N samples over which |f| (the
 * specific force's magnitude, any unit) stays within HYG_REST_SPREAD of its
 * mean (max - min <= HYG_REST_SPREAD * mean). At rest |f| is the gravity's
 * 1 g plus noise and vibration, a few percent peak to peak (the x-io walk:
 * 2.2 % over its first 5 s); 10 % leaves room for a vibrating vehicle,
 * while a moving foot or body swings |f| by much more within 0.5 s (the
 * walk: 0.3 to 4.7 g within a stride). The spread is relative, so a rest
 * is found whatever unit the file is read in: it is the check's reference,
 * not its subject. Too tight a spread only leaves a file unchecked, never
 * refused.
 * 0.5 s: recordings usually start with seconds at rest, and a moving body
 * rarely holds |f| that steady that long; 10 samples: a mean of 10
 * readings at least, also at low rates.
 */
#define HYG_REST_NS 500000000 /**< 0.5 s */
#define HYG_REST_N 10
#define HYG_REST_SPREAD 0.1

/** A run of samples over which |f| stays within HYG_REST_SPREAD of its mean. */
typedef struct {
    int64_t t0_ns, t1_ns; /**< first and last time */
    int64_t n;            /**< samples */
    double sum, lo, hi;   /**< of |f| [m/s^2] */
    double f_sum[3];      /**< of the specific force [m/s^2] */
    double w_sum[3];      /**< of the angular rate [rad/s, as converted] */
} hyg_run_t;

/** What a row did to the search for rests. */
typedef enum {
    HYG_MOVING = 0,  /**< no rest */
    HYG_REST_BEGINS, /**< the run became a rest: run holds its first HYG_REST_NS */
    HYG_RESTING,     /**< the rest goes on: run grows */
    HYG_REST_ENDS    /**< the row moved: last holds the rest that ended */
} hyg_rest_event_t;

/** The search for rests, fed the rows in time order (zeroed before). */
typedef struct {
    hyg_run_t run;  /**< the current run of steady |f| */
    hyg_run_t last; /**< the rest that ended last */
    int resting;    /**< run is a rest */
} hyg_rest_t;

/** Adds r (after the rows before it; times increasing) to the search. */
hyg_rest_event_t hygiene_rest(hyg_rest_t *s, const row_t *r);

/** The interval b - a >= 0 from time a to b >= a [ns], saturated at
 *  INT64_MAX (no overflow whatever the times). */
int64_t hygiene_interval(int64_t a, int64_t b);

/** Median of dt[0..n-1] (n >= 1; dt is reordered) [ns]. */
double hygiene_median(int64_t *dt, size_t n);

#endif /* SE23_IMPORT_HYGIENE_H */
