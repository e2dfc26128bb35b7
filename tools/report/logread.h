/**
 * @file logread.h
 * @brief Reads LCM event logs of the se23 harness into arrays (truth, nav
 *        states, GNSS fixes, run description), decoding each event with the
 *        generated fixed-size types; events that fail to decode are counted,
 *        and so are the bytes of corrupt events skipped (tools/lcm/logfile.h).
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
} log_data_t;

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
