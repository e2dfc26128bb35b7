/**
 * @file gyrocheck.h
 * @brief se23-import's check of the gyroscope's unit. A file in rad/s read
 *        as deg/s makes every rate 57.3 times too small, one in deg/s read
 *        as rad/s 57.3 times too large; the check weighs both readings of
 *        the file's numbers against physics and against the accelerometer.
 *
 * Evidence that the numbers are deg/s (so rad/s is 57.3 times too large):
 *  - Range: read as rad/s, GYRO_OVER_MIN samples or more exceed
 *    GYRO_RANGE_MAX (4,000 deg/s, the widest full scale of MEMS
 *    gyroscopes; most stop at 2,000 deg/s), while read as deg/s they are
 *    within it. A foot swings at 5 to 15 rad/s: its deg/s numbers read as
 *    rad/s are 300 to 860 "rad/s". A car turns at 1 rad/s at most: its
 *    deg/s numbers (below 60) stay in range either way; the next test is
 *    the one that sees it.
 *  - Rest to rest: between two rests (hygiene_rest) the gyroscope, less
 *    its mean over the recording's first rest (its bias), must turn the
 *    direction of gravity the accelerometer reads at the one rest into the
 *    one it reads at the next. Read right, it does so within GYRO_FIT_DEG
 *    in most segments: the error is the bias drift, the scale error and a
 *    "rest" that is a steady acceleration (|f| steady within 10 % allows a
 *    car braking at 0.3 g: 17 degrees); the worst seen in the corpus of
 *    real recordings (../shared/data) is 30 degrees. A rate 57.3 times too
 *    large integrates to an arbitrary attitude, GYRO_MISS_DEG or more off
 *    in 85 % of the cases (a random direction is within 45 degrees of a
 *    given one with probability (1 - cos 45 deg) / 2 = 15 %). A segment
 *    that the deg/s reading follows within GYRO_FIT_DEG and the rad/s
 *    reading misses by GYRO_MISS_DEG counts for deg/s; GYRO_VOTES_MIN of
 *    them decide.
 * Evidence that the numbers are rad/s (so deg/s is 57.3 times too small):
 *  - Rest to rest, the other way: a gyroscope 57.3 times too small turns
 *    nothing, so it cannot explain a change of the direction of gravity
 *    between rests. The gain of the measured changes (unit vectors) on the
 *    ones the deg/s reading predicts, by least squares over every segment,
 *    is about 1 when deg/s is right (less when the changes are mostly
 *    noise: a walk on a flat floor, whose every rest has the foot flat) and
 *    about 57 when the numbers are rad/s. It decides for rad/s when it is
 *    at least GYRO_GAIN_MIN (7.6, the geometric mean of 1 and 57.3) and
 *    above 1 by 3 standard errors, over GYRO_SEGMENTS_MIN segments or more
 *    (a car's rests, stops and stretches of steady driving, come every few
 *    seconds on roads of changing grade and camber; a walk on a flat floor
 *    changes no tilt and stays undecided this way).
 * No evidence either way, or evidence both ways: undecided, the file passes.
 * The two readings are not weighed alike: a rate too small predicts "no
 * tilt change", which a walk on a flat floor shows anyway, so fitting the
 * rests better proves nothing for it; it loses only by failing to explain
 * a tilt change.
 */
#ifndef SE23_IMPORT_GYROCHECK_H
#define SE23_IMPORT_GYROCHECK_H

#include <stddef.h>
#include <stdint.h>

#include "../lcm/ldmath.h"
#include "hygiene.h"

#define GYRO_RANGE_MAX (4000.0 * 3.14159265358979323846 / 180.0) /**< [rad/s] */
#define GYRO_OVER_MIN 10      /**< samples beyond it: no glitch */
#define GYRO_FIT_DEG 10.0     /**< a rest-to-rest tilt change followed [deg] ... */
#define GYRO_MISS_DEG 45.0    /**< ... and missed [deg] */
#define GYRO_VOTES_MIN 2      /**< segments that decide for deg/s */
#define GYRO_GAIN_MIN 7.57    /**< sqrt(57.3): the gain that decides for rad/s ... */
#define GYRO_SEGMENTS_MIN 10  /**< ... over this many segments at least */

/** What the file's gyroscope numbers are. */
typedef enum {
    GYRO_UNDECIDED = 0, /**< no evidence */
    GYRO_IS_RAD,        /**< rad/s */
    GYRO_IS_DEG,        /**< deg/s */
    GYRO_CONFLICT       /**< evidence both ways */
} gyro_unit_t;

typedef struct {
    double to_rad, to_deg; /**< the rate as converted [rad/s] to each reading's */
    int64_t over_range;    /**< samples beyond GYRO_RANGE_MAX read as rad/s only */
    int64_t last_t_ns;     /**< the previous row's time */
    int have_last;
    int in_segment;        /**< between a rest that ended and the next */
    double bias[3];        /**< the mean rate over the first rest [rad/s, as converted] */
    int have_bias;
    double g1[3];          /**< the direction of its specific force (unit) */
    ld_mat3_t R_rad, R_deg; /**< the rotation since, in either reading */
    int64_t segments;      /**< rest-to-rest segments closed */
    int64_t votes_deg;     /**< ... followed in deg/s and missed in rad/s */
    double s_mp, s_pp, s_mm; /**< the gain's sums: measured . predicted (deg/s), ... */
} gyro_check_t;

/**
 * g before the first row; gyro_scale: --gyro-unit's factor to rad/s (1 for
 * rad/s, pi/180 for deg/s).
 */
void gyro_check_init(gyro_check_t *g, double gyro_scale);

/** Adds the row r (rows in time order) with what it did to the rests. */
void gyro_check_add(gyro_check_t *g, const row_t *r, hyg_rest_event_t ev, const hyg_rest_t *rest);

/** The gain of the rest-to-rest tilt changes on the deg/s reading's and its
 *  standard error (0, 0 without a segment that predicts a change). */
void gyro_check_gain(const gyro_check_t *g, double *gain, double *se);

/** What the evidence says. */
gyro_unit_t gyro_check_verdict(const gyro_check_t *g);

/** The evidence in words, into buf[n]. */
void gyro_check_describe(const gyro_check_t *g, char *buf, size_t n);

#endif /* SE23_IMPORT_GYROCHECK_H */
