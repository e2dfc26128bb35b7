/**
 * @file ins.h
 * @brief The INS engine of se23-ins, free of LCM: input screening, exact
 *        propagation with the 15-state covariance (se23/gauss.h), GNSS
 *        updates, optional preintegrated factors, and the counters that
 *        account for every input.
 *
 * Time. An IMU sample with timestamp t covers (t_prev, t]: dt is the time
 * since the last accepted sample. The state's time is that of the last
 * accepted sample.
 *
 * Screening of IMU samples, in this order (each rejection counted, the state
 * untouched):
 *   before the initial state            -> n_imu_early
 *   NaN/Inf in omega or accel           -> n_imu_nonfinite
 *   |omega| or |accel| beyond the range -> n_imu_range
 *   t <= t_last and seq == last         -> n_imu_duplicate
 *   t <= t_last and seq <  last         -> n_imu_out_of_order
 *   t <= t_last otherwise               -> n_imu_bad_time
 *   dt > max_gap                        -> n_imu_bad_dt (see "outage")
 * A received sample (whatever its verdict) whose seq exceeds the highest
 * seq seen so far by k + 1 adds k to n_imu_missing (lost in transit, or
 * late); an accepted sample after a gap is held over the whole interval
 * since the last accepted one (zero-order hold across the gap).
 * Outage: when OUTAGE_CONFIRM consecutive samples all have dt > max_gap but
 * are consistent among themselves (consecutive seq, dt <= max_gap between
 * them), the stream really jumped: the state is carried across the outage
 * by holding the last accepted sample, the covariance is inflated by the
 * configured outage dynamics, and n_time_resets counts it (status flag
 * INS_ST_DEGRADED until the next GNSS fix). An outage longer than
 * max_outage marks the filter INS_ST_LOST; it then waits for a new initial
 * state.
 *
 * GNSS fixes are applied when the state time is within half a sample of
 * the fix time (a fix ahead of the state waits in a one-slot buffer), after
 * a chi-square gate on the innovation; invalid, stale or gated fixes are
 * counted in n_gnss_rejected.
 */
#ifndef INS_INS_H
#define INS_INS_H

#include <stdint.h>

#include "se23/earth.h"
#include "se23/gauss.h"
#include "se23/preint.h"

/** Status bits published in nav_state.status. */
enum {
    INS_ST_INITIALISED = 1 << 0, /**< an initial state was received */
    INS_ST_GNSS_AIDED = 1 << 1,  /**< at least one GNSS fix applied */
    INS_ST_DEGRADED = 1 << 2,    /**< carried across an outage since the last fix */
    INS_ST_LOST = 1 << 3,        /**< outage too long: waiting for a new initial state */
    INS_ST_GNSS_GATED = 1 << 4,  /**< the last GNSS fix failed the gate */
    INS_ST_EARTH_RATE = 1 << 5   /**< rotating-Earth model */
};

/** Consecutive consistent over-gap samples that confirm an outage. */
#define INS_OUTAGE_CONFIRM 3

typedef struct {
    int64_t imu_used, imu_nonfinite, imu_range, imu_duplicate, imu_out_of_order;
    int64_t imu_bad_time, imu_bad_dt, imu_missing, imu_early;
    int64_t decode_errors, gnss_used, gnss_rejected, time_resets, filter_errors;
    int64_t init_rejected;
} ins_counters_t;

typedef struct {
    se23_imu_noise_t noise;   /**< IMU noise densities and bias walks */
    double gyro_range;        /**< [rad/s] */
    double accel_range;       /**< [m/s^2] */
    double lat;               /**< latitude of the nav-frame origin [rad] */
    int earth_rotation;       /**< 1: rotating Earth */
    int bias_states;          /**< 1: 15-state filter, 0: 9-state (biases fixed) */
    double dt_nominal;        /**< nominal IMU interval [s] */
    double max_gap;           /**< largest interval bridged by one sample [s] */
    double max_outage;        /**< largest outage carried across [s] */
    double outage_accel;      /**< 1-sigma unknown acceleration during an outage [m/s^2] */
    double outage_rate;       /**< 1-sigma unknown angular rate during an outage [rad/s] */
    double gnss_gate;         /**< chi-square gate on the innovation (<= 0: none) */
    double preint_window;     /**< preintegrated factor length [s] (0: none) */
} ins_config_t;

/** Initial state (user's (R, v, p)) and its 15x15 covariance. */
typedef struct {
    int64_t t_ns;
    double R_nb[9], v_n[3], p_n[3], b_g[3], b_a[3];
    double P[225];
} ins_init_t;

typedef struct {
    int64_t t_ns;
    double p_n[3], v_n[3], sigma_p[3], sigma_v[3];
    int has_vel;
} ins_gnss_t;

/** Preintegrated factor with its covariance and bias Jacobian. */
typedef struct {
    se23_preint_t f;
    se23_mat9_t cov;
    se23_mat9x6_t J;
    int64_t t0_ns, t1_ns, seq0;
    double b_g_lin[3], b_a_lin[3];
} ins_factor_t;

/** Output snapshot (user's state, 15x15 covariance). */
typedef struct {
    int64_t t_ns, seq;
    double R_nb[9], v_n[3], p_n[3], b_g[3], b_a[3];
    double P[225];
    int32_t status;
    double nis_last;
} ins_output_t;

typedef struct {
    ins_config_t cfg;
    se23_earth_model_t model;
    se23_gauss_t g;            /**< carried state (R, v + Omega x p, p) */
    int32_t status;
    int64_t t_ns, seq;         /**< time and seq of the last accepted sample */
    int64_t max_seq_seen;      /**< highest seq received since the initial state */
    se23_imu_sample_t last;    /**< last accepted sample (raw), for holds */
    int have_last;
    int64_t steps_since_norm;
    /* outage detection */
    int streak;
    int64_t streak_t_ns, streak_seq, streak_t0_ns;
    /* GNSS */
    ins_gnss_t pending;
    int have_pending;
    double nis_last;
    /* preintegration */
    ins_factor_t fac;
    int fac_ready;             /**< a finished factor waits in fac_out */
    ins_factor_t fac_out;
    ins_counters_t c;
} ins_t;

/** Sets up the engine (no state yet). Returns 0, or -1 on a bad config. */
int ins_setup(ins_t *ins, const ins_config_t *cfg);

/**
 * (Re)initialises the state. Returns 0, or -1 if the initial state is
 * invalid (non-finite, R not a rotation, P not a covariance): then counted in
 * init_rejected and the current state is kept.
 */
int ins_init(ins_t *ins, const ins_init_t *init);

/** One IMU sample (raw readings). Returns 1 if integrated, 0 if rejected. */
int ins_imu(ins_t *ins, int64_t t_ns, int64_t seq, const double omega[3], const double accel[3]);

/** One GNSS fix. Returns 1 if applied now, 0 if waiting or rejected. */
int ins_gnss(ins_t *ins, const ins_gnss_t *fix);

/** Counts a message that failed to decode. */
void ins_decode_error(ins_t *ins);

/** Snapshot of the user's state. Returns 0, or -1 before initialisation. */
int ins_output(const ins_t *ins, ins_output_t *out);

/** Takes the finished preintegrated factor, if any (returns 1). */
int ins_take_factor(ins_t *ins, ins_factor_t *out);

#endif /* INS_INS_H */
