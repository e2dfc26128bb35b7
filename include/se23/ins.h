/**
 * @file ins.h
 * @brief The navigation filter: raw IMU samples and aiding measurements in,
 *        the user's state (R, v, p, biases), its covariance, a status word
 *        and counters out. Fixed-size, caller-owned, no heap, no globals,
 *        both precisions. Built on gauss.h (prediction), kalman.h (updates),
 *        stationary.h (zero-velocity detection) and align.h (alignment).
 *
 * State. The filter carries a se23_gauss_t in the model's coordinates: the
 * carried T' = (R, v + Omega x p, p) on rotating Earth (imu.h), the user's
 * (R, v, p) on flat Earth. Everything that enters or leaves (init, fixes,
 * se23_ins_state) is in the user's (R, v, p); the conversion stays inside.
 *
 * Time. Timestamps are int64 nanoseconds of the caller's clock, >= 0. An
 * IMU sample stamped t covers (t_prev, t]: dt = t - t_prev, the time since
 * the last accepted sample; the state's time is that of the last accepted
 * sample. Per accepted sample: prediction, the stationary detector, a
 * zero-velocity (and, with bias states, zero-rate) update when the window
 * is stationary, then any GNSS fix due at this time.
 *
 * Screening of IMU samples, in this order; each rejection is counted in
 * its own counter and leaves the state untouched (se23_ins_imu returns the
 * verdict):
 *   a NULL reading                            -> imu_failed
 *   no state yet (not initialised)            -> imu_early
 *   NaN/Inf in a reading                      -> imu_nonfinite
 *   t < 0 or seq < 0                          -> imu_bad_time
 *   an axis of w or f beyond the range        -> imu_range
 *   t <= t_last and seq == last               -> imu_duplicate
 *   t <= t_last and seq <  last               -> imu_out_of_order
 *   t <= t_last otherwise                     -> imu_bad_time (see "Clock")
 *   dt > max_gap                              -> imu_bad_dt (see "Outage")
 * While aligning, a finite in-range sample goes to the alignment (imu_align).
 * A sample that passes is integrated (imu_used), or, if the library's step
 * fails (it should not: setup and init bound what a step sees), refused
 * with the state kept (imu_failed and filter_errors, SE23_INS_FAILED).
 * A received sample (whatever its verdict) within max_gap of the last
 * whose seq exceeds the highest seen by
 * k + 1 adds k to imu_missing, provided k is no more than the samples
 * max_gap can hold (a larger jump is a corrupted seq: imu_seq_jumps); an
 * over-gap sample's seq is judged when an outage is confirmed (the seq
 * skipped before it are lost samples if the time gap could hold them).
 *
 * Lost samples. A sample whose interval dt (at most max_gap) spans
 * n = round(dt / dt_nominal) >= 2 nominal intervals follows n - 1 samples
 * lost in transit. Holding its reading over the whole interval would give
 * the lost samples the value at the gap's end (a swinging foot's rate
 * changes by hundreds of deg/s within the 7.5 ms of three intervals, and
 * the heading error this leaves is never corrected); the filter instead
 * integrates the interval in n equal sub-intervals whose readings are the
 * linear interpolation between the last accepted reading and this one (the
 * lost samples' best estimate from the two that bracket them; both are
 * known when this sample arrives: causal), each held over its sub-interval
 * as a received sample is. At most SE23_INS_GAP_STEPS sub-intervals (a larger
 * n is interpolated more coarsely); none without a reading at the
 * interval's start (the first sample after init, alignment, an outage or
 * a clock step). The preintegrated factor integrates the same
 * sub-intervals.
 *
 * Outage. When SE23_INS_OUTAGE_CONFIRM consecutive samples all have
 * dt > max_gap but agree among themselves (consecutive seq, dt <= max_gap
 * between them), the stream jumped forward: the state is carried across by
 * holding the last accepted sample (at most max_outage, in steps of the
 * model's dt_max), the covariance is inflated by the outage dynamics
 * (outage_rate, outage_accel: 1-sigma unknown rate and acceleration) and
 * time_resets counts it; status SE23_INS_ST_DEGRADED until the next fix.
 * The inflation raises no variance above SE23_INS_P_MAX (one already above
 * is left as it is): a position or velocity known to no better than 1e6 m
 * or m/s is unknown, and the cap keeps the covariance finite for any
 * outage and any number of them (setup bounds outage_accel and
 * outage_rate by the sensor ranges as well).
 * A longer outage sets SE23_INS_ST_LOST: the filter then waits for a new
 * init or alignment.
 *
 * Clock. SE23_INS_OUTAGE_CONFIRM consecutive bad-time samples that agree
 * among themselves (consecutive seq, 0 < dt <= max_gap between them) mean
 * the clock stepped back and stays there: the filter re-bases its time on
 * the new clock (time_resets, status DEGRADED, verdict SE23_INS_OUTAGE),
 * keeping the state; fixes are then judged by the new clock (a pending fix,
 * stamped by the old one, is dropped: gnss_pending_dropped).
 *
 * GNSS. A fix (position, optionally velocity, of an antenna at lever arm
 * l_b: h = p + R l and v + R (w x l), kalman.h) is fused at its own time:
 *  - stamped within half a sample of the state: applied now;
 *  - ahead of the state: held in a one-slot buffer until the state reaches
 *    it; a held fix that is not fused is counted in gnss_pending_dropped
 *    (replaced by a newer one, or dropped by an outage, a clock step, an
 *    init or an alignment: it belongs to the state or the clock that ended);
 *  - in the past, within delay_horizon: the filter restarts from a stored
 *    snapshot older than the fix, replays the stored samples up to the fix
 *    (with the zero-velocity updates they had), applies it and replays to
 *    the present (section "Delayed fixes");
 *  - older than the horizon or than the last fused fix: rejected, counted
 *    in gnss_stale.
 * A fix's time is first moved by gnss_time_offset (the IMU clock minus
 * the GNSS clock: a receiver whose fixes are stamped on another clock, or
 * an IMU logged late).
 * A chi-square gate on the normalised innovation squared (gnss_gate; 0:
 * none) rejects outliers (gnss_gated, SE23_INS_ST_GNSS_GATED). After
 * gate_recover consecutive gated fixes (0: never) the filter trusts the
 * fix over itself: position and velocity are reset to the fix with its
 * covariance and their correlations dropped (gate_resets,
 * SE23_INS_ST_GATE_RESET until the next fix passes the gate).
 *
 * Delayed fixes. The filter keeps the samples of the last 2 * delay_horizon
 * in a ring of SE23_INS_RING entries and two snapshots of the state, taken
 * delay_horizon apart; the older is always at least delay_horizon old, so
 * any fix within the horizon has a snapshot before it. Fusing a fix stamped
 * d seconds late costs the replay of up to d + delay_horizon seconds of
 * samples (prediction and the zero-velocity updates), in that call.
 * Memory: sizeof(se23_ins_t) = 17,992 B + SE23_INS_RING x 72 B in double,
 * 9,240 B + SE23_INS_RING x 48 B in float (27,208 / 15,384 B with the
 * default ring; tools/doc/pages/filter.md; test_ins.c asserts it),
 * the kernels' work areas included (1,512 / 756 B, kept here and not on
 * the stack of the calls);
 * the ring must hold
 * 2 * delay_horizon / dt_nominal + 2 samples (checked by se23_ins_setup).
 * A fix replayed this way equals the same fix applied at
 * its own time (same operations, same order).
 *
 * Zero-velocity updates. With zupt enabled the detector of stationary.h
 * runs on every accepted sample, on the readings as the filter corrects
 * them (w + b_g - R^T Omega, R (f + b_a): at rest only the sensor noise
 * remains, so the detector's sigmas are the noise's; with 9 states the
 * biases stay in and the sigmas must allow for them). Because SHOE takes
 * the gravity direction from the window, a start whose acceleration grows
 * smoothly from zero would pass it; the filter knows where gravity is and
 * also requires the window's mean acceleration R fbar + g to be noise
 * (src/nav/ins_rest.c, accel_nis; the mean's 1-sigma is rest_accel_sigma, or
 * sigma_a / sqrt(W) for white noise: a vibration that the detector's
 * sigma_a must allow averages out of the mean), unless gravity_test_off is
 * set: a
 * foot has no smooth starts (a swing begins with a heel lift at over
 * 100 deg/s, which SHOE's gyro term sees), and a test against the
 * filter's own attitude would keep a filter that missed one stance from
 * every later one. With rest_speed_max > 0 the filter's own speed must
 * also allow rest, |v| <= rest_speed_max (a vehicle's IMU reads the same
 * at rest and cruising at a steady speed on a smooth road; only the filter
 * knows which; no margin for the speed's uncertainty, which a long outage
 * widens past a car's speeds: a missed ZUPT is a lost help, a false one a
 * catastrophe). While the window is stationary, each
 * sample applies v = 0 (nav frame, 1-sigma sqrt(zupt_sigma_v^2 + W
 * (zupt_lever |w|)^2), w = w_meas + b_g: a body at rest that still turns
 * at w about a point zupt_lever away, a foot rolling over its heel or toe,
 * moves at up to zupt_lever |w|, the same in the W samples of a window;
 * applied as the body-frame R^T v = 0, its information, in one update with
 * the ZARU on the filter's own state, src/kalman/kalman_rest.c) and, with bias
 * states, once the rest has lasted zaru_after seconds, w_meas + b_g =
 * R^T Omega (the Earth rate a body at rest senses; zero on flat Earth;
 * 1-sigma zaru_sigma_w per axis, its O(|Omega| |phi|) dependence on the
 * attitude error neglected). The delay keeps ZARU out of short stances in
 * which the body still turns (a foot's, 45-70 ms). Counted in zupt_used /
 * zaru_used.
 *
 * Motion noise. Besides the white noise of "noise", a MEMS sensor in
 * motion errs in proportion to what it measures: scale-factor and
 * cross-axis errors (a relative gyro_scale, accel_scale, about 1 % for
 * consumer parts) and the gyro's g-sensitivity (gyro_g, rad/s per m/s^2).
 * They change with the motion, over about corr_time seconds, so each
 * sample's prediction takes them as white noise over that time: density^2
 * += (gyro_scale^2 |w|^2 + gyro_g^2 |f|^2) corr_time for the gyro and
 * accel_scale^2 |f|^2 corr_time for the accelerometer, w and f the
 * corrected readings. The whole specific force, gravity's part too: a
 * body that turns (a foot pitches through +-60 deg each stride) moves
 * gravity's part between the axes, so its error is no bias. All zero:
 * the white noise alone.
 *
 * Floor. A foot that walks on a level floor is at the same height at
 * every stance: with floor_sigma > 0 the first stationary sample of each
 * stance (after its ZUPT) also applies p_D = floor_d, 1-sigma floor_sigma
 * (one update per stance: a stance's height error is the same in all its
 * samples). A stance begins at a stationary sample after at least
 * floor_swing seconds of motion (a shorter one is the detector's flicker
 * within a stance). The first stance after init or alignment sets floor_d
 * to its own height; a stance more than floor_step above or below the
 * level is on a new level (a stair, a kerb, a landing): floor_d moves
 * there, no update. The stances of a ramp that climbs more than floor_step per
 * stride start a new level each; a gentler one is pulled toward the level
 * it started on. Counted in floor_used / floor_levels.
 *
 * Frame. The nav frame is the origin's NED tangent frame (lat, height):
 * Cartesian and fixed to the Earth, so the Earth rate is one vector in it
 * and the Coriolis and centrifugal terms stay exact however far the
 * vehicle goes. Only gravity depends on the position: with gravity_step >
 * 0 it follows the vehicle (src/nav/ins_gravity.c: the local vertical tilts
 * from the origin's by 0.16 mrad per km), evaluated at the centre of the
 * cube of gravity_step metres the position is in; its direction is right
 * to (d/R)^2 at d from the origin (0.1 mg at 20 km, 0.6 mg at 50 km: the
 * supported range). Positions in the frame are Cartesian: a point's
 * geodetic position is se23_geo_from_ned's (geodetic.h), not the
 * frame's "down" far away.
 *
 * Vehicles. A wheeled vehicle neither slides sideways nor leaves the road:
 * with nhc_sigma > 0, a moving sample (the detector, if on, not at rest)
 * that starts a new nhc_interval (its time and the previous sample's in
 * different multiples of nhc_interval: the same samples in a replay)
 * applies the non-holonomic constraint, lateral and vertical velocity 0 in
 * the vehicle frame, 1-sigma sqrt(nhc_sigma^2 + (nhc_lever |w|)^2)
 * (se23_meas_nhc: the mounting C_bv = exp(mount_bv^) turns the body frame
 * into the vehicle's). The constraint holds at the rear axle; an IMU
 * nhc_lever from it moves sideways at the yaw rate times that in a turn
 * (and up or down at the pitch rate), w = w_meas + b_g. Its error, the
 * sideslip of the tyres and the body's roll and heave on its suspension,
 * stays the same over about a second, so one update per nhc_interval
 * carries what it knows and no more. Counted in nhc_used. The course
 * heading (below) is that of the vehicle's forward axis, C_bv e_1.
 *
 * Alignment. se23_ins_align starts a static alignment: the readings of
 * the first stationary stretch (duration seconds of consecutive stationary
 * detector verdicts, at least one window; motion starts the average again)
 * give roll and pitch (align.h), the gyro bias (its mean reading less the
 * Earth rate, unless gyrocompassing), heading from the caller, from the
 * GNSS course (course_speed > 0: the heading is unknown, 1-sigma 1 rad,
 * status SE23_INS_ST_HEADING_UNKNOWN, and fixes fuse their position only,
 * until the first fix whose horizontal velocity exceeds course_speed sets
 * the heading of the vehicle's forward axis ("Vehicles"; body x when
 * mount_bv is zero) to its course, with 1-sigma sqrt(course_sigma^2 +
 * (sigma_v / speed)^2), and the velocity to the fix; course_headings)
 * or, with gyrocompass set, from the Earth rate the gyro senses; the
 * attitude covariance from the window's statistics, v = 0, p and the bias
 * covariances from the caller. Until then samples are counted imu_early.
 * With measure_noise set, the white-noise densities the filter propagates
 * from then on are the larger of the configured ones and those the rest
 * shows (the std of a sample over the window's axes, x sqrt(dt_nominal)):
 * the data sheet is the floor, what this unit shows at rest the estimate.
 *
 * Validation (types.h): the configuration is checked by se23_ins_setup, an
 * initial state or alignment request by se23_ins_init / se23_ins_align (with
 * se23_gauss_check), every sample and fix where it enters. The filter's own
 * state is trusted. A library step that fails (it should not, for checked
 * inputs) is counted in filter_errors and leaves the state as it was.
 * Physical bounds keep the steps away from overflow: sensor ranges at most
 * SE23_INS_ACCEL_RANGE_MAX and SE23_INS_GYRO_RANGE_MAX, bias estimates
 * within the ranges, positions within SE23_INS_POS_MAX and velocities
 * within SE23_INS_VEL_MAX (states, alignments and fixes), variances of an
 * initial state and of outage inflation at most SE23_INS_P_MAX.
 *
 * Functions index:
 *   se23_ins_setup        check a configuration, empty filter
 *   se23_ins_init         initial state (user's coordinates) and time
 *   se23_ins_align        start a static alignment
 *   se23_ins_imu          one raw IMU sample
 *   se23_ins_gnss         one GNSS fix
 *   se23_ins_state        the user's state, covariance, time and status
 *   se23_ins_take_factor  the last finished preintegrated factor
 *   se23_ins_detector_threshold   the detector threshold for a probability
 *   se23_ins_preset_foot  the pedestrian (foot-mounted) configuration
 *   se23_ins_preset_car   a car's configuration (IMU and GNSS)
 */
#ifndef SE23_INS_H
#define SE23_INS_H

#include <stdint.h>

#include "se23/earth.h"
#include "se23/gauss.h"
#include "se23/kalman.h"
#include "se23/preint_unc.h"
#include "se23/stationary.h"
#include "se23/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Samples the delayed-fix ring holds (compile-time; see file comment). */
#ifndef SE23_INS_RING
#define SE23_INS_RING 128
#endif

/** Most sub-intervals one sample after lost ones is integrated in (ins.h,
 *  "Lost samples"): bounds the predictions of one call. */
#ifndef SE23_INS_GAP_STEPS
#define SE23_INS_GAP_STEPS 32
#endif

/** Consecutive consistent over-gap samples that confirm an outage. */
#define SE23_INS_OUTAGE_CONFIRM 3

/** Largest variance of an initial state, in any unit (a 1-sigma of 1e6 m,
 *  m/s, rad or rad/s): beyond it, steps would overflow. */
#define SE23_INS_P_MAX SE23_R(1e12)

/** Largest outage a configuration may ask to carry across [s]. */
#define SE23_INS_MAX_OUTAGE SE23_R(600)

/** Largest accelerometer range a configuration may state [m/s^2], about
 *  1,000 g: above the widest-range accelerometers made for navigation
 *  (consumer MEMS 16 g, tactical 40-70 g, high-g parts 200-400 g) and any
 *  sustained vehicle acceleration (a few hundred m/s^2 at most). It bounds
 *  the accelerometer bias (|b_a| <= accel_range) and outage_accel
 *  (<= accel_range + 10 m/s^2: the acceleration f + g of a body whose
 *  specific force the sensor could measure). */
#define SE23_INS_ACCEL_RANGE_MAX SE23_R(1e4)

/** Largest gyro range a configuration may state [rad/s]: above the widest
 *  gyro ranges made (+-20,000 deg/s, 350 rad/s) and the spin of a rifled
 *  shell (300 rev/s, 1,900 rad/s). It bounds the gyro bias
 *  (|b_g| <= gyro_range) and outage_rate (<= gyro_range). */
#define SE23_INS_GYRO_RANGE_MAX SE23_R(1e4)

/** Largest |p| [m] of an initial state, an alignment or a fix: beyond the
 *  Moon's orbit (3.8e8 m), where a navigation frame tied to a latitude
 *  means nothing; with SE23_INS_VEL_MAX and bounded sensor ranges the mean
 *  steps stay far below the largest float for any run (a century at 2e4
 *  m/s^2 reaches 1e23 m). */
#define SE23_INS_POS_MAX SE23_R(1e9)

/** Largest |v| [m/s] of an initial state or a fix: ten times the Earth's
 *  escape velocity (11.2 km/s). */
#define SE23_INS_VEL_MAX SE23_R(1e5)

/** Status bits (se23_ins_t.status). */
#define SE23_INS_ST_INITIALISED 0x001U /**< a state is being propagated */
#define SE23_INS_ST_GNSS_AIDED 0x002U  /**< at least one GNSS fix applied */
#define SE23_INS_ST_DEGRADED 0x004U    /**< carried across an outage since the last fix */
#define SE23_INS_ST_LOST 0x008U        /**< outage too long: waiting for init or alignment */
#define SE23_INS_ST_GNSS_GATED 0x010U  /**< the last GNSS fix failed the gate */
#define SE23_INS_ST_EARTH_RATE 0x020U  /**< rotating-Earth model */
#define SE23_INS_ST_ALIGNING 0x040U    /**< static alignment in progress */
#define SE23_INS_ST_STATIONARY 0x080U  /**< the detector's window is stationary */
#define SE23_INS_ST_GATE_RESET 0x100U  /**< position and velocity were reset to a fix */
#define SE23_INS_ST_HEADING_UNKNOWN 0x200U /**< aligned, heading awaits the GNSS course */

/** What became of one input (returned by se23_ins_imu and se23_ins_gnss). */
typedef enum {
    SE23_INS_USED = 0,         /**< integrated (sample) or fused (fix) */
    SE23_INS_EARLY = 1,        /**< no state yet */
    SE23_INS_NONFINITE = 2,    /**< NaN/Inf, or a fix's bad sigma, negative time or
                                    absurd position or velocity */
    SE23_INS_RANGE = 3,        /**< beyond the sensor range */
    SE23_INS_DUPLICATE = 4,    /**< same seq as the last sample */
    SE23_INS_OUT_OF_ORDER = 5, /**< older seq */
    SE23_INS_BAD_TIME = 6,     /**< not after the last sample, or t < 0, seq < 0 */
    SE23_INS_BAD_DT = 7,       /**< interval above max_gap (maybe an outage) */
    SE23_INS_OUTAGE = 8,       /**< confirmed an outage: carried across */
    SE23_INS_PENDING = 9,      /**< fix ahead of the state: held */
    SE23_INS_STALE = 10,       /**< fix beyond the delay horizon or older than the last */
    SE23_INS_GATED = 11,       /**< fix failed the chi-square gate */
    SE23_INS_RESET = 12,       /**< fix reset position and velocity (gate recovery) */
    SE23_INS_FAILED = 13       /**< a library step failed; state kept */
} se23_ins_verdict_t;

/** Counters (saturating at UINT32_MAX). Every sample ends in exactly one
 *  imu_ counter but imu_missing and imu_seq_jumps; every fix in one gnss_
 *  counter but gnss_delayed and gate_resets (a reset fix is also gated; a
 *  held fix ends in the counter of its verdict when it is fused, or in
 *  gnss_pending_dropped); a call the library refuses (SE23_INS_FAILED) in
 *  imu_failed / gnss_failed (none with a NULL filter). */
typedef struct {
    uint32_t imu_used;         /**< samples integrated */
    uint32_t imu_early;        /**< no state yet (before init, or aligning) */
    uint32_t imu_align;        /**< taken by the alignment */
    uint32_t imu_nonfinite;    /**< NaN/Inf in a reading */
    uint32_t imu_range;        /**< an axis beyond the sensor range */
    uint32_t imu_duplicate;    /**< not after the last in time, with its seq */
    uint32_t imu_out_of_order; /**< not after the last in time, with an older seq */
    uint32_t imu_bad_time;     /**< t or seq negative, or otherwise not after the last ("Clock") */
    uint32_t imu_bad_dt;       /**< an interval beyond max_gap ("Outage") */
    uint32_t imu_failed;    /**< refused: a NULL reading, or a failed step (that
                             *   also in filter_errors); state kept */
    uint32_t imu_missing;   /**< samples lost in transit (seq gaps) */
    uint32_t imu_seq_jumps; /**< seq jumps too large to be losses */
    uint32_t gnss_used;        /**< fixes fused */
    uint32_t gnss_delayed; /**< of gnss_used: fused late, by replay */
    uint32_t gnss_pending_dropped; /**< held fixes never fused ("GNSS") */
    uint32_t gnss_nonfinite;   /**< NaN/Inf, a time, sigma or value out of bounds */
    uint32_t gnss_early;       /**< before the first state */
    uint32_t gnss_stale;       /**< beyond the horizon, or not after the last fused fix */
    uint32_t gnss_gated;       /**< refused by the chi-square gate */
    uint32_t gate_resets;      /**< of gnss_gated: position and velocity reset to the fix */
    uint32_t gnss_failed;   /**< refused: a NULL fix, or a failed update (that
                             *   also in filter_errors); state kept */
    uint32_t course_headings;  /**< headings set from the GNSS course */
    uint32_t zupt_used;        /**< zero-velocity updates applied */
    uint32_t zaru_used;        /**< zero-rate updates applied */
    uint32_t floor_used;       /**< floor updates applied (one per stance) */
    uint32_t floor_levels;     /**< floor levels set: the first stance, then each new one */
    uint32_t nhc_used;         /**< non-holonomic constraint updates applied */
    uint32_t time_resets;      /**< clock steps, back or forward ("Clock", "Outage") */
    uint32_t filter_errors;    /**< library steps that failed (state kept) */
    uint32_t init_rejected;    /**< refused initial states and alignment requests */
} se23_ins_counters_t;

/** Sensor errors that grow with the motion ("Motion noise"). */
typedef struct {
    se23_real_t gyro_scale;  /**< gyro scale-factor and cross-axis error, relative */
    se23_real_t accel_scale; /**< accelerometer scale-factor and cross-axis error, relative */
    se23_real_t gyro_g;      /**< gyro g-sensitivity [rad/s per m/s^2] */
    se23_real_t corr_time;   /**< how long they stay the same [s] (0: model off) */
} se23_ins_motion_noise_t;

/** Configuration (se23_ins_setup checks every field). */
typedef struct {
    se23_imu_noise_t noise;     /**< IMU noise densities and bias walks */
    se23_ins_motion_noise_t motion; /**< errors in proportion to the motion ("Motion noise") */
    se23_real_t gyro_range;     /**< sensor range per axis, |w_i| [rad/s] */
    se23_real_t accel_range;    /**< sensor range per axis, |f_i| [m/s^2] */
    se23_real_t lat;            /**< latitude of the nav-frame (NED) origin [rad] */
    se23_real_t height;         /**< its ellipsoidal height [m] (gravity; "Frame") */
    se23_real_t gravity_step;   /**< gravity follows the position, re-evaluated in
                                 *   cubes of this size [m] ("Frame"; 0: the origin's
                                 *   gravity everywhere) */
    int earth_rotation;         /**< 1: rotating Earth, 0: flat */
    int bias_states;            /**< 1: 15 states, 0: 9 (biases fixed) */
    se23_real_t dt_nominal;     /**< nominal IMU interval [s] */
    se23_real_t max_gap;        /**< largest interval one sample bridges [s] */
    se23_real_t max_outage;     /**< largest outage carried across [s] */
    se23_real_t outage_accel;   /**< 1-sigma unknown acceleration in an outage [m/s^2] */
    se23_real_t outage_rate;    /**< 1-sigma unknown angular rate in an outage [rad/s] */
    se23_vec3_t lever_b;        /**< GNSS antenna in the body frame [m] */
    se23_real_t gnss_gate;      /**< chi-square gate on the NIS (0: none) */
    int gate_recover;           /**< consecutive gated fixes before a reset (0: never) */
    se23_real_t delay_horizon;  /**< oldest fix fused at its own time [s] (0: none) */
    se23_real_t preint_window;  /**< preintegrated factor length [s] (0: none) */
    int zupt;                   /**< 1: detector and zero-velocity updates */
    se23_stationary_config_t detector; /**< window, noise, threshold (stationary.h) */
    int gravity_test_off;       /**< 1: no mean-acceleration test at rest ("Zero-velocity updates") */
    se23_real_t zupt_sigma_v;   /**< 1-sigma of v = 0 at rest [m/s] */
    se23_real_t rest_accel_sigma; /**< 1-sigma of a window's mean acceleration at rest
                                   *   [m/s^2] in the gravity test ("Zero-velocity
                                   *   updates"; 0: sigma_a / sqrt(window)) */
    se23_real_t rest_speed_max; /**< a stationary window is rest only if the filter's
                                 *   speed is at most this [m/s] ("Zero-velocity
                                 *   updates"; 0: no test) */
    se23_real_t zupt_lever;     /**< distance [m] from the point a body at rest turns
                                 *   about: the ZUPT's 1-sigma grows with the rate
                                 *   ("Zero-velocity updates"; 0: constant) */
    se23_real_t zaru_sigma_w;   /**< 1-sigma of w = 0 at rest [rad/s] (bias states; 0: no ZARU) */
    se23_real_t zaru_after;     /**< rest [s] before ZARU applies (0: at once) */
    se23_real_t floor_sigma;    /**< 1-sigma of "a stance is on the floor level" [m]
                                 *   (0: no floor updates; needs zupt; see "Floor") */
    se23_real_t floor_step;     /**< height change [m] from the level beyond which a
                                 *   stance is on a new level (floor_sigma > 0) */
    se23_real_t floor_swing;    /**< motion [s] that separates two stances (shorter:
                                 *   the detector's flicker within one) */
    se23_vec3_t mount_bv;       /**< the IMU's mounting: rotation vector [rad] of C_bv,
                                 *   x_b = C_bv x_v from the vehicle frame (forward,
                                 *   right, down) to the body (IMU) frame; zero: the IMU
                                 *   axes are the vehicle's ("Vehicles") */
    se23_real_t nhc_sigma;      /**< 1-sigma of the vehicle frame's lateral and
                                 *   vertical velocity [m/s] (non-holonomic constraint,
                                 *   "Vehicles"; 0: off) */
    se23_real_t nhc_lever;      /**< distance [m] the IMU may be from the rear axle:
                                 *   the NHC's 1-sigma grows with the rate ("Vehicles") */
    se23_real_t nhc_interval;   /**< time between two NHC updates [s]: how long the
                                 *   constraint's error (sideslip, suspension) stays
                                 *   the same (nhc_sigma > 0) */
    se23_real_t gnss_time_offset; /**< added to every fix's time [s]: the IMU clock
                                   *   minus the GNSS clock, |.| <= 1 s ("GNSS") */
} se23_ins_config_t;

/** A GNSS fix in the nav frame, stamped with the time it refers to. */
typedef struct {
    int64_t t_ns;              /**< the time it refers to [ns], the caller's clock
                                *   (moved by gnss_time_offset) */
    se23_vec3_t p_n;           /**< antenna position, nav frame [m] */
    se23_vec3_t sigma_p;       /**< its 1-sigma per axis [m] */
    se23_vec3_t v_n;           /**< antenna velocity, nav frame [m/s] */
    se23_vec3_t sigma_v;       /**< its 1-sigma per axis [m/s] */
    int has_vel;               /**< nonzero: v_n, sigma_v are used */
} se23_ins_gnss_t;

/** Static alignment request (se23_ins_align). */
typedef struct {
    se23_vec3_t p_n;          /**< position [m] */
    se23_real_t sigma_p;      /**< its 1-sigma per axis [m] */
    se23_real_t yaw;          /**< heading [rad] (unless gyrocompass) */
    se23_real_t sigma_yaw;    /**< its 1-sigma [rad] */
    int gyrocompass;          /**< nonzero: heading from the sensed Earth rate */
    se23_real_t sigma_v;      /**< 1-sigma of the initial v = 0 [m/s] */
    se23_real_t sigma_bg;     /**< initial gyro bias 1-sigma [rad/s] (bias states) */
    se23_real_t sigma_ba;     /**< initial accel bias 1-sigma [m/s^2] (bias states) */
    se23_real_t duration;     /**< rest averaged [s] (0: one detector window) */
    se23_real_t course_speed; /**< > 0: heading from the GNSS course once the horizontal
                                   speed exceeds this [m/s] (yaw, sigma_yaw unused) */
    se23_real_t course_sigma; /**< 1-sigma of the body heading about the course
                                   (sideslip, crab) [rad] (course_speed > 0) */
    int measure_noise;        /**< nonzero: the noise densities from the rest too,
                                   the configured ones a floor ("Alignment") */
} se23_ins_align_t;

/** Running sums of an alignment: deviations from its first sample (no
 *  cancellation in float). */
typedef struct {
    int n;                    /**< samples summed */
    se23_vec3_t w0;           /**< the first sample's rate [rad/s] */
    se23_vec3_t f0;           /**< the first sample's specific force [m/s^2] */
    se23_vec3_t sw;           /**< sum of w - w0 */
    se23_vec3_t sf;           /**< sum of f - f0 */
    se23_vec3_t sww;          /**< sum of (w - w0)^2, per axis */
    se23_vec3_t sff;          /**< sum of (f - f0)^2, per axis */
} se23_ins_align_sums_t;

/** What the detector made of a sample: the updates applied after it, a
 *  level (NONE, ZUPT, ZARU) with the FLOOR flag on the first stationary
 *  sample of a stance when floor updates are configured, or, moving, the
 *  NHC flag when the constraint is due ("Vehicles"). */
enum {
    SE23_INS_REST_NONE = 0,  /**< moving */
    SE23_INS_REST_ZUPT = 1,  /**< stationary: zero velocity */
    SE23_INS_REST_ZARU = 2,  /**< at rest for zaru_after: zero velocity and rate */
    SE23_INS_REST_LEVEL = 3, /**< mask of the level */
    SE23_INS_REST_FLOOR = 4, /**< flag: a stance begins: the floor update too */
    SE23_INS_REST_NHC = 8    /**< flag (moving): the non-holonomic constraint is due */
};

/** A stored state for the replay of delayed fixes. */
typedef struct {
    se23_gauss_t g;           /**< state after the sample at t_ns */
    int64_t t_ns;             /**< that sample's time [ns] */
    se23_imu_sample_t last;   /**< that sample (the rate of the lever arm) */
    se23_real_t floor_d;      /**< the floor level then (se23_ins_t) */
    int floor_set;            /**< floor_set then (se23_ins_t) */
} se23_ins_snapshot_t;

/** One accepted sample as the ring keeps it. */
typedef struct {
    se23_imu_sample_t s;      /**< the sample as accepted */
    int64_t t_ns;             /**< its time [ns] */
    int rest;                 /**< updates applied after it (SE23_INS_REST_*) */
} se23_ins_hist_t;

/** A finished preintegrated factor. */
typedef struct {
    se23_preint_unc_t f;      /**< Deltas, covariance and bias Jacobian (left
                               *   form: se23_preint_unc_cov gives P and J) */
    int64_t t0_ns;            /**< the start of the window it spans [ns] */
    int64_t t1_ns;            /**< the end of that window [ns] */
    int64_t seq0;             /**< seq of the first sample received in it
                               *   (samples lost just before that one are in
                               *   the window too, interpolated: t0_ns is
                               *   where it starts) */
} se23_ins_factor_t;

/** The filter (caller-owned; fields are read-only for the caller). Fields
 *  ordered by alignment (4 bytes of padding in the double build: the
 *  4-byte fields are an odd number of words; none in the float build). */
typedef struct {
    /* ZUPT consistency (two reals: 8 bytes in float, keeping int64 alignment) */
    se23_real_t zupt_nis_last;    /**< NIS (3 dof) of the last ZUPT update computed */
    se23_real_t zupt_nis_sum;     /**< sum of it over the live ZUPTs: over
                                   *   c.zupt_used, about 3 if zupt_sigma_v is the
                                   *   innovations' size */
    /* from cfg */
    /** @var se23_ins_t::half_ns
     *  Half of dt_nominal [ns]: a fix stamped within it of the state is
     *  applied now ("GNSS"). */
    /** @var se23_ins_t::max_gap_ns
     *  max_gap [ns]: the longest interval one sample bridges. */
    int64_t half_ns, max_gap_ns, horizon_ns; /**< delay_horizon [ns] (0: no replay) */
    int64_t zaru_after_ns;        /**< zaru_after */
    int64_t max_missing;          /**< most samples max_gap can hold */
    /* time and sequence */
    /** @var se23_ins_t::t_ns
     *  Time of the state [ns]: of the last accepted sample, or of the init
     *  or alignment if none has been accepted since. */
    int64_t t_ns, seq;            /**< seq of the last accepted sample */
    int64_t max_seq;              /**< highest seq received since init */
    /** @var se23_ins_t::streak_t_ns
     *  Time [ns] of the last over-gap sample of the streak that may confirm
     *  an outage ("Outage"). */
    int64_t streak_t_ns, streak_seq; /**< its seq */
    /** @var se23_ins_t::back_t_ns
     *  Time [ns] of the last bad-time sample of the streak that may confirm
     *  a clock step back ("Clock"). */
    int64_t back_t_ns, back_seq;  /**< its seq */
    int64_t last_fix_ns;          /**< time of the last fused fix (-1: none) */
    int64_t rest_ns;              /**< time the detector has seen rest (0: moving) */
    int64_t move_ns;              /**< time it has seen motion since (0: at rest;
                                   *   saturates at floor_swing_ns) */
    int64_t floor_swing_ns;       /**< floor_swing */
    int64_t nhc_interval_ns;      /**< nhc_interval */
    int64_t gnss_offset_ns;       /**< gnss_time_offset */
    int32_t grav_cube[3];         /**< the cube whose gravity the model holds ("Frame") */
    int grav_set;                 /**< nonzero once grav_cube is set */
    /* structures holding int64 */
    se23_ins_gnss_t pending;      /**< a fix ahead of the state */
    /** @var se23_ins_t::fac
     *  The preintegrated factor being accumulated (preint_window > 0). */
    se23_ins_factor_t fac, fac_out; /**< the last finished factor, until
                                     *   se23_ins_take_factor takes it */
    se23_ins_snapshot_t snap[2];  /**< delayed fixes: the snapshots */
    se23_ins_hist_t ring[SE23_INS_RING]; /**< and the samples since the older */
    /* 4-byte fields */
    uint32_t status;              /**< SE23_INS_ST_* bits */
    int have_last;                /**< nonzero once a sample has been accepted
                                   *   since the init or alignment: last holds a
                                   *   reading */
    /** @var se23_ins_t::streak
     *  Consecutive consistent over-gap samples so far (up to
     *  SE23_INS_OUTAGE_CONFIRM: "Outage"). */
    int streak, back_streak;      /**< consecutive consistent bad-time samples
                                   *   so far (up to SE23_INS_OUTAGE_CONFIRM:
                                   *   "Clock") */
    int have_pending;             /**< nonzero while pending holds a fix */
    int gated_run;                /**< consecutive gated fixes */
    se23_real_t nis_last;         /**< NIS of the last fused fix */
    se23_real_t floor_d;          /**< down position of the floor level [m] ("Floor") */
    int floor_set;                /**< nonzero once a stance has set floor_d */
    /** @var se23_ins_t::ring_head
     *  Index in ring of the oldest entry. */
    int ring_head, ring_count;    /**< number of entries in ring */
    int replaying;                /**< nonzero inside a replay (counters not repeated) */
    int n_snap;                   /**< snapshots held */
    int snap_old;                 /**< index of the older one */
    int fac_ready;                /**< nonzero while fac_out is not taken */
    /* structures of se23_real_t */
    se23_imu_sample_t last;       /**< last accepted sample (raw), for holds */
    se23_ins_align_t align;       /**< the alignment request (se23_ins_align) */
    se23_ins_align_sums_t sums;   /**< the alignment's running sums */
    se23_earth_model_t model;     /**< the Earth model: the origin's gravity, or
                                   *   that of the cube the position is in
                                   *   (gravity_step > 0, "Frame"); Earth rate
                                   *   (zero on flat Earth); dt = dt_nominal;
                                   *   dt_max = SE23_CFG_DT_MAX */
    se23_ins_counters_t c;        /**< the counters */
    se23_ins_config_t cfg;        /**< the configuration (se23_ins_setup) */
    se23_mat3_t C_bv;             /**< the mounting, exp(mount_bv^) */
    /** @var se23_ins_t::grav_rm
     *  Meridian radius of curvature plus height at the origin [m]: a north
     *  position divided by it is the angle [rad] by which the vertical there
     *  tilts from the origin's ("Frame"). */
    se23_real_t grav_rm, grav_rn; /**< prime-vertical radius of curvature plus
                                   *   height at the origin [m]: the same for an
                                   *   east position */
    se23_imu_noise_t noise;       /**< the white noise propagated: cfg.noise, or
                                   *   raised by a measuring alignment */
    se23_stationary_t det;        /**< the stationary detector (zupt set) */
    se23_meas_t meas;             /**< scratch of the updates */
    se23_gauss_t g;               /**< state in the model's coordinates */
    se23_gauss_t work;            /**< scratch of the updates (user's coordinates) */
    /** The kernels' work areas (work.h), here and not on the stack of the
     *  filter calls (tools/doc/pages/filter.md); one kernel call at a
     *  time uses them. */
    union {
        se23_predict_work_t predict; /**< the prediction */
        se23_preint_work_t preint;   /**< the preintegrated factor */
        se23_kalman_work_t kalman;   /**< the updates */
    } kernel;
} se23_ins_t;

/**
 * The chi^2_{6W-2} quantile / W of stationary.h for the standard normal
 * quantile z (Wilson-Hilferty): the detector threshold at which a window at
 * rest is called moving with the probability 1 - Phi(z).
 * @param window the detector window W [samples]
 * @param z the standard normal quantile of the false-"moving" probability (2.326 for 1 %)
 * @return the threshold; no checks (window >= 1 and a moderate z are the
 *         caller's: e.g. z = 2.326 for one window in 100).
 */
se23_real_t se23_ins_detector_threshold(int window, se23_real_t z);

/**
 * cfg, align = the pedestrian (foot-mounted) preset for a consumer-MEMS IMU
 * at rate_hz on a foot, latitude lat (for gravity): flat Earth, 15 states,
 * ZUPT at stance, ZARU after 0.5 s at rest, alignment from the first
 * second at rest, no GNSS. Every value and why it was chosen is in
 * src/nav/ins_preset.c. Pass cfg to se23_ins_setup and align to se23_ins_align:
 * a configuration the preset returns always passes se23_ins_setup (both
 * judge lat by se23_earth_gravity's rule).
 * @param rate_hz the IMU rate [Hz], 50 to 10,000 (measure it: se23-import)
 * @param lat latitude [rad], for gravity
 * @param cfg out: the filter configuration (written only on SE23_OK)
 * @param align out: the alignment request (written only on SE23_OK)
 * @return SE23_ERR_NULL; SE23_ERR_DOMAIN unless 50 <= rate_hz <= 10000;
 *         the statuses of se23_earth_gravity (lat: SE23_ERR_DOMAIN if
 *         |lat| > pi/2 + SE23_EARTH_LAT_SLACK). Nothing is written on
 *         error.
 */
se23_status_t se23_ins_preset_foot(se23_real_t rate_hz, se23_real_t lat,
                                   se23_ins_config_t *cfg, se23_ins_align_t *align);

/**
 * cfg, align = the car preset for an automotive-class MEMS IMU at rate_hz
 * in a car with GNSS, latitude lat: rotating Earth, 15 states, the
 * non-holonomic constraint once a second, ZUPT and ZARU at stops (the
 * filter's speed confirming rest), alignment from the first 2 s at rest
 * with the heading from the GNSS course ("Vehicles", src/nav/ins_preset.c for
 * every value). The installation is the caller's: lever_b (the antenna)
 * and mount_bv (the IMU's mounting) are zero here.
 * @param rate_hz the IMU rate [Hz], 50 to 10,000
 * @param lat latitude [rad] of the nav frame's origin
 * @param cfg out: the filter configuration (written only on SE23_OK)
 * @param align out: the alignment request (written only on SE23_OK)
 * @return as se23_ins_preset_foot.
 */
se23_status_t se23_ins_preset_car(se23_real_t rate_hz, se23_real_t lat,
                                  se23_ins_config_t *cfg, se23_ins_align_t *align);

/**
 * ins = an empty filter (no state) for cfg.
 * @param cfg the configuration, copied
 * @param ins out: an empty filter (written only on SE23_OK)
 * @return SE23_ERR_NULL; SE23_ERR_NONFINITE (a non-finite field);
 *         SE23_ERR_DOMAIN (a negative noise, range, sigma or gate;
 *         max_outage above SE23_INS_MAX_OUTAGE; accel_range above
 *         SE23_INS_ACCEL_RANGE_MAX, gyro_range above
 *         SE23_INS_GYRO_RANGE_MAX; outage_accel above accel_range + 10
 *         m/s^2, outage_rate above gyro_range; |lat| > pi/2 +
 *         SE23_EARTH_LAT_SLACK, se23_earth_gravity's rule;
 *         bias_states, earth_rotation, zupt or gravity_test_off not 0/1;
 *         a motion error above 1 (gyro_scale, accel_scale; gyro_g in rad/s
 *         per m/s^2) or corr_time above 1 s; zupt_lever above 1 m);
 *         SE23_ERR_DT
 *         (dt_nominal below 1 ns, max_gap below dt_nominal or above
 *         SE23_CFG_DT_MAX); SE23_ERR_DIM (the ring cannot hold
 *         2 * delay_horizon / dt_nominal + 2 samples); the statuses of
 *         se23_stationary_init when zupt is set. Nothing is written on error.
 */
se23_status_t se23_ins_setup(const se23_ins_config_t *cfg, se23_ins_t *ins);

/**
 * (Re)initialises the state at time t_ns with the user's state g (R, v, p,
 * biases, covariance; g->n must be 15 with bias states, else 9), checked
 * here with se23_gauss_check: the one deep check it gets. The covariance
 * kept is exactly symmetric: g's lower triangle, the one the check proves
 * positive semidefinite, mirrored (the check accepts an asymmetry within
 * its tolerance).
 * A pending fix is dropped (gnss_pending_dropped).
 * @param ins a filter from se23_ins_setup
 * @param t_ns time of the state [ns], >= 0
 * @param g the user's state (R, v, p, biases) and its covariance
 * @return SE23_ERR_NULL, SE23_ERR_DIM (n), SE23_ERR_DT (t_ns < 0), the
 *         statuses of se23_gauss_check, SE23_ERR_DOMAIN (a variance above
 *         SE23_INS_P_MAX, |b_g| above gyro_range, |b_a| above accel_range,
 *         |v| above SE23_INS_VEL_MAX, |p| above SE23_INS_POS_MAX); on
 *         error the filter is unchanged but for init_rejected.
 */
se23_status_t se23_ins_init(se23_ins_t *ins, int64_t t_ns, const se23_gauss_t *g);

/**
 * Starts a static alignment (file comment): the state is set once the
 * detector has seen a->duration seconds (at least a window) of rest. A
 * pending fix is dropped (gnss_pending_dropped).
 * @param ins a filter from se23_ins_setup
 * @param a the alignment request, copied
 * @return SE23_ERR_NULL; SE23_ERR_DOMAIN (detector off in the
 *         configuration, gyrocompass on flat Earth, a sigma <= 0 or above
 *         1e6, duration < 0 or above SE23_INS_MAX_OUTAGE, course_speed < 0,
 *         a course with gyrocompass or with course_sigma outside (0, 3],
 *         |p_n| above SE23_INS_POS_MAX);
 *         SE23_ERR_NONFINITE; on error the filter is unchanged but for
 *         init_rejected.
 */
se23_status_t se23_ins_align(se23_ins_t *ins, const se23_ins_align_t *a);

/**
 * One raw IMU sample (gyro w_b [rad/s], specific force f_b [m/s^2]),
 * screened, then integrated (file comment).
 * @param ins the filter
 * @param t_ns time of the sample, the end of the interval it covers [ns]
 * @param seq its sequence number (+1 per sample; a gap counts lost samples)
 * @param w_b angular rate, body frame [rad/s]
 * @param f_b specific force, body frame [m/s^2]
 * @return SE23_INS_USED; or what became of it: SE23_INS_EARLY,
 *         SE23_INS_NONFINITE, SE23_INS_RANGE, SE23_INS_DUPLICATE,
 *         SE23_INS_OUT_OF_ORDER, SE23_INS_BAD_TIME (also t_ns < 0,
 *         seq < 0), SE23_INS_BAD_DT, SE23_INS_OUTAGE (confirmed a jump or
 *         a clock step), SE23_INS_FAILED (NULL argument, or a library
 *         step failed: state kept), each counted (SE23_INS_FAILED in
 *         imu_failed, but for a NULL ins).
 */
se23_ins_verdict_t se23_ins_imu(se23_ins_t *ins, int64_t t_ns, int64_t seq,
                                const se23_vec3_t *w_b, const se23_vec3_t *f_b);

/**
 * One GNSS fix (file comment, "GNSS").
 * @param ins the filter
 * @param fix the fix, stamped with the time it refers to
 * @return SE23_INS_USED (fused now or at its own time), SE23_INS_PENDING
 *         (ahead of the state: held), SE23_INS_RESET (gate recovery);
 *         SE23_INS_EARLY, SE23_INS_NONFINITE (NaN/Inf, t_ns < 0, a sigma
 *         <= 0 or > 1e6, |p_n| above SE23_INS_POS_MAX, |v_n| above
 *         SE23_INS_VEL_MAX), SE23_INS_STALE (beyond the horizon or not after
 *         the last fused fix), SE23_INS_GATED, SE23_INS_FAILED (NULL
 *         argument or a failed update: state kept), each counted
 *         (SE23_INS_FAILED in gnss_failed, but for a NULL ins; PENDING
 *         when the held fix is fused or dropped).
 */
se23_ins_verdict_t se23_ins_gnss(se23_ins_t *ins, const se23_ins_gnss_t *fix);

/**
 * out = the user's state (R, v, p, biases, covariance); t_ns its time.
 * @param ins the filter
 * @param out out: the state (written only on SE23_OK)
 * @param t_ns out: its time [ns] (written only on SE23_OK)
 * The state is not proved again here (se23_gauss_check is one 15 x 15
 * factorisation, about 7.7 k instructions on a Cortex-M4F, more than a
 * filter step): the filter checks an update that pins a variance before it
 * keeps it, and its covariance steps are PSD to their rounding (gauss.h),
 * so a state can fail the check only by that rounding
 * (tools/doc/pages/fuzzing-soak.md). A caller that hands the state to
 * something that trusts it runs se23_gauss_check on out.
 * @return SE23_ERR_DIM before the first state; SE23_ERR_NONFINITE if
 *         the conversion from the carried state would overflow (rotating
 *         Earth: Omega x p or the covariance's shear beyond the largest
 *         real, only for absurd states, se23_gauss_from_carried); otherwise
 *         SE23_OK. Nothing is written on error.
 */
se23_status_t se23_ins_state(const se23_ins_t *ins, se23_gauss_t *out, int64_t *t_ns);

/**
 * Takes the finished preintegrated factor, if any.
 * @param ins the filter
 * @param out out: the factor (written only when 1 is returned)
 * @return 1 (out written), or 0 (none ready, or a NULL argument).
 */
int se23_ins_take_factor(se23_ins_t *ins, se23_ins_factor_t *out);

#ifdef __cplusplus
}
#endif

#endif /* SE23_INS_H */
