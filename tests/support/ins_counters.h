/**
 * @file ins_counters.h
 * @brief Helpers of the filter's tests and its fuzz target, header-only:
 *        the sums over the counters an input ends in (ins.h: every sample
 *        in exactly one imu_ counter but imu_missing and imu_seq_jumps,
 *        every fix in one gnss_ counter but gnss_delayed and gate_resets).
 */
#ifndef SE23_INS_COUNTERS_H
#define SE23_INS_COUNTERS_H

#include <stdint.h>

#include "se23/ins.h"

/** Every imu_ counter a sample can end in. */
static inline uint32_t it_imu_sum(const se23_ins_counters_t *c)
{
    return c->imu_used + c->imu_early + c->imu_align + c->imu_nonfinite + c->imu_range +
           c->imu_duplicate + c->imu_out_of_order + c->imu_bad_time + c->imu_bad_dt +
           c->imu_failed;
}

/** Every gnss_ counter a fix can end in. */
static inline uint32_t it_gnss_sum(const se23_ins_counters_t *c)
{
    return c->gnss_used + c->gnss_pending_dropped + c->gnss_nonfinite + c->gnss_early +
           c->gnss_stale + c->gnss_gated + c->gnss_failed;
}

#endif /* SE23_INS_COUNTERS_H */
