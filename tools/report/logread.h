/**
 * @file logread.h
 * @brief Reads LCM event logs of the se23 harness into arrays (truth, nav
 *        states, GNSS fixes, run description), decoding each event with the
 *        generated fixed-size types; events that fail to decode are counted,
 *        and so are the bytes of corrupt events skipped (tools/lcm/logfile.h).
 *
 * Screening (log_data_t.screen, se23-report). An event can decode and
 * still hold values no INS or simulator produces (a corrupted log: NaN, a
 * matrix that is no rotation, a negative variance); they would turn the
 * report's statistics into NaN or 1e152. With screen set, each nav state
 * and truth record is checked and, if it fails, counted and left out:
 *  - every real finite (nav: R, v, p, biases, P, NIS, detector statistic);
 *  - R a rotation: every entry of R^T R - I within LOG_ROT_TOL, det R > 0;
 *  - nav P: diagonal >= 0, symmetric (|P_ij - P_ji| <= LOG_COV_TOL s,
 *    s = max_i P_ii) and |P_ij| <= (1 + LOG_COV_TOL) sqrt(P_ii P_jj) +
 *    LOG_COV_TOL s (every 2x2 principal minor >= 0 to rounding: a
 *    variance corrupted towards 0 under its covariances fails);
 *  - nav status and counters: t_ns >= 0, status only the SE23_INS_ST_*
 *    bits (0x1ff) with SE23_INS_ST_INITIALISED (se23-ins publishes only an
 *    initialised state), every counter >= 0.
 * The tolerances hold the float INS's output (R to 1e-5, se23/config.h).
 */
#ifndef REPORT_LOGREAD_H
#define REPORT_LOGREAD_H

#include <stddef.h>
#include <stdint.h>

#include "se23lcm_gnss_fix.h"
#include "se23lcm_nav_state.h"
#include "se23lcm_preint_factor.h"
#include "se23lcm_sim_info.h"
#include "se23lcm_truth.h"

/** Tolerances of the screening (file comment). */
#define LOG_ROT_TOL 1e-4
#define LOG_COV_TOL 1e-4

/** Why a record was left out by the screening. */
typedef enum {
    LOG_OK = 0,
    LOG_BAD_NONFINITE, /**< a NaN or Inf */
    LOG_BAD_ROTATION,  /**< R not a rotation */
    LOG_BAD_COV,       /**< P: negative variance, asymmetric, a minor < 0 */
    LOG_BAD_STATUS,    /**< time, status bits or counters impossible */
    LOG_BAD_COUNT
} log_bad_t;

typedef struct {
    se23lcm_truth *truth;
    size_t n_truth, cap_truth;
    se23lcm_nav_state *nav;
    size_t n_nav, cap_nav;
    se23lcm_gnss_fix *gnss;
    size_t n_gnss, cap_gnss;
    se23lcm_preint_factor *preint;
    size_t n_preint_stored, cap_preint;
    se23lcm_sim_info info;
    int have_info;
    int64_t n_imu;          /**< SE23_IMU events seen */
    int64_t n_preint;       /**< SE23_PREINT factors decoded */
    int64_t n_preint_bad;   /**< factors whose dt or covariance diagonal is wrong */
    int64_t preint_samples; /**< IMU samples covered by the factors */
    int64_t n_events;       /**< all events read */
    int64_t n_decode_errors; /**< events of a known channel that failed to decode */
    int64_t bytes_skipped;   /**< bytes of corrupt events passed over (logfile.h) */
    int64_t corrupt_spans;   /**< places where reading resynchronised */
    int screen;              /**< nonzero: screen nav states and truth (file comment) */
    int64_t nav_rejected[LOG_BAD_COUNT];   /**< nav states left out, per reason ([0]: all) */
    int64_t truth_rejected[LOG_BAD_COUNT]; /**< truth records left out, per reason ([0]: all) */
} log_data_t;

/** Short name of a reason ("non-finite", "not a rotation", ...). */
const char *log_bad_str(log_bad_t why);

/** The screening of one nav state / truth record (file comment). */
log_bad_t log_screen_nav(const se23lcm_nav_state *m);
log_bad_t log_screen_truth(const se23lcm_truth *m);

/**
 * Appends the valid events of the log at path to d. Returns 0, or -1 (after
 * a message) if the file cannot be read; a corrupt log is read past its bad
 * events (d->bytes_skipped).
 */
int log_read(const char *path, log_data_t *d);

/** Sorts truth and nav by time; for equal times keeps the last nav read. */
void log_sort(log_data_t *d);

/** Index of the truth record at exactly t_ns, or -1. */
long log_find_truth(const log_data_t *d, int64_t t_ns);

void log_free(log_data_t *d);

#endif /* REPORT_LOGREAD_H */
