/**
 * @file ins_internal.h
 * @brief Internal: the parts of the navigation filter (ins.h) shared
 *        between its sources:
 *          ins.c         setup, init, state output, sample screening
 *          ins_outage.c  over-gap samples, outage carry-across
 *          ins_rest.c    the rest decision: stationary detector and the
 *                        filter's own gravity test
 *          ins_step.c    one accepted sample: prediction, zero-velocity
 *                        updates, preintegrated factor
 *          ins_gap.c     lost samples: sub-intervals, interpolated
 *                        readings, the prediction over them
 *          ins_aid.c     measurement updates in the user's coordinates,
 *                        GNSS gate and gate recovery
 *          ins_delay.c   sample ring, snapshots, delayed fixes
 *          ins_align.c   static alignment, heading from the GNSS course
 *          ins_gravity.c gravity that follows the position
 */
#ifndef SE23_INS_INTERNAL_H
#define SE23_INS_INTERNAL_H

#include "se23/ins.h"
#include "se23/kalman.h"

/** Nanoseconds per second, in the build's precision. */
#define SE23_INS_NS SE23_R(1e9)

/** Index of P's (row, col) in a se23_mat15_t. */
static inline int se23_ins_idx(int row, int col)
{
    return (SE23_GAUSS_NMAX * row) + col;
}

/** c += 1, saturating. */
void se23_ins_count(uint32_t *c);

/** c += k (k >= 0), saturating. */
void se23_ins_count_add(uint32_t *c, int64_t k);

/** Drops the pending fix, if any, counting it in gnss_pending_dropped
 *  (ins.h, "GNSS": every fix ends in one gnss_ counter). */
void se23_ins_drop_pending(se23_ins_t *ins);

/** Nonzero if |x| <= max (max >= 0 and max^2 finite); zero for a NaN or a
 *  |x|^2 that overflows. */
static inline int se23_ins_norm_within(const se23_vec3_t *x, se23_real_t max)
{
    const se23_real_t n2 = (x->v[0] * x->v[0]) + (x->v[1] * x->v[1]) + (x->v[2] * x->v[2]);
    return (n2 <= (max * max)) ? 1 : 0;
}

/** Half the nominal sample interval [ns]: the tolerance of "now". */
int64_t se23_ins_half_sample_ns(const se23_ins_t *ins);

/**
 * Starts propagating from the model-coordinate state g at time t_ns, seq 0:
 * clears the outage, GNSS (a pending fix is dropped, counted), ring and
 * factor bookkeeping.
 */
void se23_ins_start(se23_ins_t *ins, int64_t t_ns, const se23_gauss_t *g);

/**
 * One prediction of the state through raw sample s; the state is kept on
 * failure (counted in filter_errors). Returns 1 on success.
 */
int se23_ins_predict(se23_ins_t *ins, const se23_imu_sample_t *s);

/**
 * The prediction over sample s after the reading ins->last, in
 * se23_ins_gap_steps sub-intervals (ins_gap.c); on a failure the state is
 * restored (ins->work holds the copy). Returns 1 on success.
 */
int se23_ins_predict_interval(se23_ins_t *ins, const se23_imu_sample_t *s);

/**
 * The whole step of an accepted sample at time t_ns: prediction, then the
 * rest updates the detector called for (rest, SE23_INS_REST_*). Used live and by the replay.
 * Returns 1 on success (the state then is at t_ns).
 */
int se23_ins_step(se23_ins_t *ins, int64_t t_ns, const se23_imu_sample_t *s, int rest);

/**
 * The sub-intervals sample s is integrated in after the reading prev
 * (ins.h, "Lost samples"): 1, or round(s->dt / dt_nominal) up to
 * SE23_INS_GAP_STEPS when s follows lost samples and prev is a reading.
 */
int se23_ins_gap_steps(const se23_ins_t *ins, const se23_imu_sample_t *prev,
                       const se23_imu_sample_t *s);

/** u = sub-interval j (1..n) of s after prev: the reading interpolated
 *  linearly at its end, dt = s->dt / n (u = s but for dt when j = n). */
void se23_ins_gap_sample(const se23_imu_sample_t *prev, const se23_imu_sample_t *s, int j,
                         int n, se23_imu_sample_t *u);

/** Adds an accepted live sample (after the reading prev) to the
 *  preintegrated factor, in the prediction's sub-intervals. */
void se23_ins_factor_add(se23_ins_t *ins, const se23_imu_sample_t *prev,
                         const se23_imu_sample_t *s);

/** Restarts the preintegrated factor at the current state. */
void se23_ins_factor_reset(se23_ins_t *ins);

/**
 * The rest updates sample s (dt_ns after the last accepted one) calls for:
 * SE23_INS_REST_NONE (moving, or no ZUPT configured), SE23_INS_REST_ZUPT,
 * or SE23_INS_REST_ZARU once the rest has lasted zaru_after; with floor
 * updates, SE23_INS_REST_FLOOR added when a stance begins; moving,
 * SE23_INS_REST_NHC when the sample starts a new nhc_interval. Feeds the
 * detector (ins_rest.c). The replay applies the same updates after the
 * same samples (the ring keeps the verdict).
 */
int se23_ins_rest_level(se23_ins_t *ins, const se23_imu_sample_t *s, int64_t dt_ns);

/**
 * The zero-velocity update after raw sample s, the zero-rate update too if
 * rest's level is SE23_INS_REST_ZARU (and ZARU configured), and the floor
 * update if rest has SE23_INS_REST_FLOOR. Returns 1 on success.
 */
int se23_ins_zupt(se23_ins_t *ins, const se23_imu_sample_t *s, int rest);

/**
 * The non-holonomic constraint update (ins.h, "Vehicles") on the state.
 * Returns 1 on success; a failure is counted in filter_errors.
 */
int se23_ins_nhc(se23_ins_t *ins);

/** The origin's radii of curvature (plus its height) for the gravity that
 *  follows the position, and no cube yet (ins_gravity.c). */
void se23_ins_gravity_radii(se23_ins_t *ins);

/** The model's gravity for the cube the state's position is in, if it
 *  changed (ins.h, "Frame"; nothing with gravity_step 0). */
void se23_ins_gravity_follow(se23_ins_t *ins);

/**
 * The rest updates of a stationary sample in place on ins->g (zaru: the
 * ZARU rows too) by the structured update (kalman_rest.h), for the steady
 * state (ins_aid.c); SE23_OK, or the status on which se23_ins_zupt takes
 * its general path, nothing written. External linkage keeps GCC -O2 from
 * inlining it into se23_ins_zupt, whose frame then stays off the stack
 * under the general path's updates and check (make gates-target).
 */
se23_status_t se23_ins_rest_steady(se23_ins_t *ins, const se23_imu_sample_t *s, int zaru);

/**
 * P's rows and columns of block b (first index) zeroed, and its diagonal
 * block set to R^T diag(s^2) R: the covariance, in the body-frame error of
 * gauss.h, of a nav-frame quantity known to 1-sigma s per axis.
 */
void se23_ins_reset_block(se23_gauss_t *g, int b, const se23_vec3_t *s);

/** The antenna's rate term: w = last sample's gyro + bias estimate. */
void se23_ins_body_rate(const se23_ins_t *ins, se23_vec3_t *w);

/**
 * The heading from the GNSS course of fix (speed its horizontal speed) on
 * the user's state in ins->work (ins_align.c); the caller commits it. Out
 * of se23_ins_fuse_gnss's frame: its work is off the stack before the
 * updates that follow.
 */
void se23_ins_course_heading(se23_ins_t *ins, const se23_ins_gnss_t *fix, se23_real_t speed);

/**
 * Gate recovery after gate_recover gated fixes in a row (ins_aid.c):
 * position, and velocity if fix has it, reset to the fix. Returns
 * SE23_INS_RESET or SE23_INS_FAILED. External linkage keeps GCC -O2 from
 * inlining it into se23_ins_fuse_gnss (it inlines a static function
 * called once), whose frame holds the Kalman updates: its work is then
 * not in that frame (make gates-target shows the frames).
 */
se23_ins_verdict_t se23_ins_gate_reset(se23_ins_t *ins, const se23_ins_gnss_t *fix);

/**
 * Fuses fix now, at the current state (gate, gate recovery, counters,
 * status). Returns SE23_INS_USED, SE23_INS_GATED, SE23_INS_RESET or
 * SE23_INS_FAILED.
 */
se23_ins_verdict_t se23_ins_fuse_gnss(se23_ins_t *ins, const se23_ins_gnss_t *fix);

/** Empties the ring and takes the only snapshot at the current state. */
void se23_ins_ring_restart(se23_ins_t *ins);

/**
 * Records an accepted sample (after its step) and keeps the snapshots
 * delay_horizon apart. No-op without a delay horizon.
 */
void se23_ins_ring_push(se23_ins_t *ins, const se23_imu_sample_t *s, int rest);

/**
 * Fuses a fix stamped in the past (within the horizon, after the last
 * fused fix) by replay from a snapshot; SE23_INS_STALE if it cannot be
 * placed.
 */
se23_ins_verdict_t se23_ins_fuse_delayed(se23_ins_t *ins, const se23_ins_gnss_t *fix);

/** An over-gap sample: counted, and maybe the confirmation of an outage. */
se23_ins_verdict_t se23_ins_over_gap(se23_ins_t *ins, int64_t t_ns, int64_t seq);

/** Empties the alignment's running sums. */
void se23_ins_align_reset_sums(se23_ins_t *ins);

/**
 * An alignment sample (the filter is aligning): fed to the detector; the
 * first stationary window sets the state. Returns SE23_INS_USED when the
 * state was set, SE23_INS_EARLY otherwise.
 */
se23_ins_verdict_t se23_ins_align_sample(se23_ins_t *ins, int64_t t_ns,
                                         const se23_imu_sample_t *s);

#endif /* SE23_INS_INTERNAL_H */
