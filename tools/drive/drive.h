/**
 * @file drive.h
 * @brief Real car drives for the se23 harness (issue 35): what
 *        se23-drive-import reads from a drive's files (IMU rows, GNSS fixes,
 *        reference positions, with se23-import's hygiene counters) and the
 *        sidecar text file it writes beside the log for se23-drive (the
 *        report).
 *
 * Times: int64 ns on the source's own timeline (rtklib: GPST as seconds
 * since 1970-01-01 in the Unix style of RTKLIB's time tags; ublox: the
 * files' t_s) until the importer moves them to the log's timeline (t_ns = 0
 * at the earliest record written, a whole second of the source's).
 */
#ifndef SE23_DRIVE_H
#define SE23_DRIVE_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>

#include "../import/csv.h"
#include "../import/hygiene.h"
#include "../import/row.h"
#include "se23/geodetic.h"

#define DRIVE_OUTAGES_MAX 64

/** A GNSS fix or a reference position, as read (geodetic). */
typedef struct {
    int64_t t_ns;     /**< source timeline */
    se23_geo_t geo;   /**< exact from the decimal text: 1e-9 deg, 1e-9 deg, mm */
    double sp[3];     /**< 1-sigma N, E, D [m] (0: not given) */
    double v[3];      /**< velocity NED [m/s] */
    double sv[3];     /**< its 1-sigma [m/s] */
    int has_vel;
    int q;            /**< RTKLIB quality (1 fix, 2 float, ...); 0 for ublox */
} drive_fix_t;

/** A stream of fixes with the counters of its reading. */
typedef struct {
    const char *name; /**< "gnss", "reference", for messages */
    drive_fix_t *fix;
    size_t n, cap;
    import_count_t c;  /**< rows, written, dup_time, backwards, gaps, malformed_* */
    int64_t skipped_q; /**< .pos rows of another quality than wanted */
} drive_fixes_t;

/** The IMU rows, valid ones, in file order. */
typedef struct {
    row_t *row;
    int64_t *lineno;
    size_t n, cap;
    import_count_t c; /**< header, blank, rows, malformed_* (the time checks come later) */
    int64_t skipped_ends; /**< rtklib: the first and last line, skipped as the source does */
} drive_imu_t;

/** Per-row message budget shared by the readers. */
typedef struct {
    int64_t max, shown, suppressed;
} drive_msgs_t;

void drive_msg(drive_msgs_t *m, const char *file, int64_t lineno, const char *fmt, ...)
#if defined(__GNUC__)
    __attribute__((format(printf, 4, 5)))
#endif
    ;

/** Opens path for reading, through `gzip -dc` if it ends in .gz; *is_pipe
 *  says which close to use. NULL (after a message) if it cannot be read. */
FILE *drive_open(const char *path, int *is_pipe);
/** Closes what drive_open opened; -1 if gzip failed. */
int drive_close(FILE *f, int is_pipe);

/** Days from 1970-01-01 to the civil date y-m-d (proleptic Gregorian). */
int64_t drive_days_from_civil(int64_t y, int m, int d);

/** t_ns as "[-]s.nnnnnnnnn" into buf. */
const char *drive_fmt_s(int64_t t_ns, char *buf, size_t n);
/** A 1e-9 quantity as "[-]i.nnnnnnnnn" into buf. */
const char *drive_fmt_e9(int64_t v, char *buf, size_t n);

/** Appends one element; NULL when out of memory. */
void *drive_push(void **arr, size_t *n, size_t *cap, size_t sz);

/**
 * Reads an rtklibexplorer IMU CSV (acc x,y,z [g], gyro x,y,z [deg/s], tick
 * [ms], no header) with map (units, axes) into imu; rows' t_ns are the
 * tick in ns (not yet on the GPST timeline). Skips the first and the last
 * line as the source's converter does. -1 if unreadable.
 */
int drive_read_rtk_imu(const char *path, const row_map_t *map, drive_imu_t *imu,
                       drive_msgs_t *msgs);

/**
 * Maps the IMU rows' ticks to GPST by the RTKLIB time-tag file (README:
 * t = start + (tick - tick_first) (end - start) / (tick_last - tick_first),
 * start the file's open time, end = start + the last record's tick), plus
 * offset_ns. -1 (after a message) if the tag file is not one.
 */
int drive_map_tag(const char *tag_path, drive_imu_t *imu, int64_t offset_ns);

/**
 * Reads an RTKLIB .pos solution (lat/lon/height in degrees): rows of
 * quality 1 or 2 into gnss, rows of quality 1 into ref. -1 if unreadable.
 */
int drive_read_pos(const char *path, drive_fixes_t *gnss, drive_fixes_t *ref,
                   drive_msgs_t *msgs);

/** ublox-drives: imu.csv (t_s, gyro rad/s, accel m/s^2, header) with map. */
int drive_read_ublox_imu(const char *path, const row_map_t *map, drive_imu_t *imu,
                         drive_msgs_t *msgs);
/** ublox-drives: gnss.csv or reference_position.csv (columns by header name). */
int drive_read_ublox_fixes(const char *path, drive_fixes_t *out, drive_msgs_t *msgs);

/** Drops repeated and backward timestamps of s (counted), counts gaps
 *  (intervals over 1.5 times the median); written = what is kept. */
void drive_fix_hygiene(drive_fixes_t *s, drive_msgs_t *msgs);

/** The sidecar (LOG.drive) the importer writes and the report reads. */
typedef struct {
    double first_fix_s;                  /**< the first GNSS fix on the log's timeline [s] */
    int n_outages;
    double outage[DRIVE_OUTAGES_MAX][2]; /**< start after the first fix, length [s] */
} drive_meta_t;

/** Reads the keys the report needs from a sidecar; -1 if unreadable. */
int drive_meta_read(const char *path, drive_meta_t *m);

/** Parses "START,LEN" (seconds, START >= 0, LEN > 0) into out[2]; 0 if ok. */
int drive_parse_outage(const char *s, double out[2]);

/** argv with every "--name=value" after argv[0] split into "--name" "value"
 * (harness_parse_opts takes the separate form; a value may start with '-',
 * e.g. --axes=-x,y,-z): a calloc'd array (free it; the strings are argv's,
 * the '=' overwritten), *argc its length; NULL if out of memory. */
char **drive_split_eq(int *argc, char **argv);

#endif /* SE23_DRIVE_H */
