/*
 * The real foot-mounted walk replayed on the target (walk_replay.c): the
 * x-io walk (tools/data/xio-gait-tracking/short_walk.csv) as se23-import
 * reads it, and the host's run of the filter through it in the build's
 * precision (tools/target/gen_walk_replay.c writes walk_replay_data.c: the
 * float reference for the M4F image, the double one for the M7 image).
 *
 * The sequence is an insr_seq_t (ins_replay.h; no fixes, driven by
 * insr_drive), started by se23_ins_align with se23_ins_preset_foot's
 * request. Besides its checkpoints, the reference holds after every IMU
 * sample k the stance flag and both rest tests' statistics, the walk's
 * loop-closure figures as se23-walk defines them (walk_track below), and
 * the decision of the host's run closest to its threshold.
 */
#ifndef SE23_WALK_REPLAY_H
#define SE23_WALK_REPLAY_H

#include <stdint.h>

#include "ins_replay.h"

/** se23-walk's stance runs closer than this merge into one phase [s]. */
#define WALK_MERGE_S 0.1

/**
 * The loop closure of a walk (se23-walk, tools/walk/main.c): over the nav
 * states se23-ins publishes (the state after every sample the filter used),
 * from the first initialised one (the alignment, "first"); a stance phase
 * starts at a state with the stationary flag whose predecessor has none,
 * unless the last flagged state is at most WALK_MERGE_S before it; "last"
 * is the start of the last phase; distance = the path through the first
 * state and every phase start. Positions as the filter gives them, sums in
 * double.
 */
typedef struct {
    int first_at, last_at;        /**< samples of "first" and "last" (-1: none yet) */
    int64_t t_first_ns, t_last_ns;
    se23_real_t p_first[3], p_last[3];
    int phases;
    double dist;                  /**< [m] */
} walk_closure_t;

/** The running state of walk_track. */
typedef struct {
    walk_closure_t c;
    int in_stance, have_stance;
    int64_t last_stance_ns;
    double prev[3];
} walk_track_t;

/** w before the first sample. */
void walk_track_init(walk_track_t *w);

/**
 * After IMU sample k with the filter's verdict (an insr_hook_t's what = 0):
 * one nav state if the sample was used. Returns 1, or 0 if se23_ins_state
 * failed.
 */
int walk_track(walk_track_t *w, const se23_ins_t *ins, int k, int verdict);

/** |p_last - p_first| [m]: 3D (which 0), horizontal (1), vertical (2). */
double walk_closure_err(const walk_closure_t *c, int which);

/**
 * The mean-acceleration rest test's NIS (insr_accel_nis) of sample k, or
 * -1 where it is not decided: alignment samples, a window not yet full (the
 * samples after the alignment). prev = the filter's state before the
 * sample (ins->g after the previous one). The filter itself evaluates it
 * only where the SHOE test passes; the copy, wherever it is defined.
 */
double walk_nis(const se23_ins_t *ins, const se23_gauss_t *prev, const insr_imu_t *m,
                int verdict);

/** The reference of the walk. */
typedef struct {
    insr_seq_t seq;
    se23_real_t rate_hz, lat;     /**< se23_ins_preset_foot's arguments */
    const uint32_t *stance;       /**< bit k % 32 of word k / 32: SE23_INS_ST_STATIONARY after sample k */
    const se23_real_t *stat;      /**< ins->det.stat after sample k (SHOE) */
    const se23_real_t *nis;       /**< walk_nis after sample k (0 where it is not evaluated) */
    walk_closure_t closure;
    double margin;                /**< relative distance of the closest decision from its threshold */
    int margin_at;                /**< ... at this sample */
    const char *margin_test;      /**< ... of this test */
} walk_ref_t;

extern const walk_ref_t walk_ref;

#endif /* SE23_WALK_REPLAY_H */
