/**
 * @file row.h
 * @brief One CSV row of se23-import to one IMU sample: column mapping,
 *        units, axis remapping, range (clipping) flags.
 *
 * Columns are numbered from 1 on the command line (as in cut and awk) and
 * stored 0-based here. The axis map is a signed permutation applied to both
 * sensors after the unit conversion: out[i] = sign[i] * in[perm[i]].
 * The accelerometer is then rotated by accel_rot (the identity unless
 * --accel-misalign gives the small rotation of its triad against the
 * gyroscope's).
 */
#ifndef SE23_IMPORT_ROW_H
#define SE23_IMPORT_ROW_H

#include <stdint.h>

#include "csv.h"

#define ROW_COLS_MAX 1024 /**< highest column number accepted */

typedef struct {
    int time_col;          /**< 0-based; -1: no time column (the caller times the rows) */
    int gyro_col[3];       /**< 0-based */
    int accel_col[3];      /**< 0-based */
    int time_exp;          /**< the time unit is 10^time_exp ns (s 9, ms 6, us 3, ns 0) */
    double gyro_scale;     /**< input unit -> rad/s */
    double accel_scale;    /**< input unit -> m/s^2 */
    int perm[3];           /**< output axis i is input axis perm[i] ... */
    double sign[3];        /**< ... times sign[i] (+1 or -1) */
    double accel_rot[9];   /**< accel = accel_rot * (mapped accel), row-major */
    double gyro_range;     /**< |raw| >= this is clipped, input units; 0: off */
    double accel_range;    /**< |raw| >= this is clipped, input units; 0: off */
} row_map_t;

/** What a row is. */
typedef enum {
    ROW_OK = 0,
    ROW_BLANK,    /**< nothing but blanks: not a data row */
    ROW_COLUMNS,  /**< wrong number of fields */
    ROW_TEXT,     /**< a mapped field is not a number (or the line has a NUL) */
    ROW_NONFINITE, /**< a mapped field is NaN, Inf, or out of range */
    ROW_OVERFLOW   /**< finite in the file, not once converted (1e308 g) */
} row_status_t;

typedef struct {
    int64_t t_ns;
    double raw_gyro[3], raw_accel[3]; /**< as in the file (input units and axes) */
    double omega[3];                  /**< [rad/s], output axes */
    double accel[3];                  /**< [m/s^2], output axes */
    int gyro_clipped, accel_clipped;  /**< some |raw| reached its range */
} row_t;

/** Details of a rejected row (for the message). */
typedef struct {
    int nfields;    /**< fields on the line */
    int bad_col;    /**< 0-based column of the bad field, or -1 */
    csv_field_t bad; /**< that field */
} row_why_t;

/**
 * Parses line into *out. ncols: fields a row must have (0: any number,
 * as long as every mapped column is there). why (may be NULL) says what
 * was wrong. Every converted value (omega, accel: after the units, the
 * axes and the misalignment) is finite for ROW_OK; for ROW_OVERFLOW, why
 * names the largest raw value of the triad that is not. The time needs no
 * such check: csv_parse_time converts exactly, within int64. Without a
 * time column (time_col -1) out->t_ns is 0: the caller sets it.
 */
row_status_t row_parse(const row_map_t *m, const char *line, int ncols, row_t *out,
                       row_why_t *why);

/** Fields a row needs at least: the highest mapped column (from 1). */
int row_cols_needed(const row_map_t *m);

/** Fields of line (csv_split), for the column count of a header. */
int row_count_fields(const char *line);

/** 1 if some mapped field of line is not a number at all (a header line). */
int row_is_header(const row_map_t *m, const char *line);

/** Parses "a,b,c" (1..ROW_COLS_MAX) into 0-based col[3]; 0 on success. */
int row_parse_cols(const char *s, int col[3]);

/**
 * Parses an axis map "x,-y,-z", "y,x,-z", ... (each of x, y, z once, each
 * with an optional + or -) into perm, sign; 0 on success.
 */
int row_parse_axes(const char *s, int perm[3], double sign[3]);

/** Largest angle --accel-misalign accepts [deg]: a triad misalignment,
 *  not an axis change (that is --axes). */
#define ROW_MISALIGN_MAX_DEG 10.0

/**
 * Parses a rotation vector "rx,ry,rz" in degrees (each finite, the angle
 * at most ROW_MISALIGN_MAX_DEG) into the rotation R = exp(r^), row-major
 * (the harness's ld_exp, tools/lcm/ldmath.h); 0 on success, R untouched
 * otherwise.
 */
int row_parse_misalign(const char *s, double R[9]);

#endif /* SE23_IMPORT_ROW_H */
