/*
 * The checks the real-data replays share (walk_replay.c, drive_replay.c):
 * the filter's outputs at a checkpoint against the host's (the time, the
 * status word and every counter exactly; R, v, p, the biases and the
 * diagonal of P within tolerances), the worst deviation of each group of
 * quantities over the run, and a preset computed on the target against the
 * configuration replayed.
 */
#ifndef SE23_WALK_REPLAY_CHECK_H
#define SE23_WALK_REPLAY_CHECK_H

#include "ins_replay.h"

/** The state's groups, the first of every replay's table. */
enum { RPC_R, RPC_V, RPC_P, RPC_BG, RPC_BA, RPC_PD, RPC_N_STATE };

/** A replay's groups of compared quantities (n >= RPC_N_STATE). */
typedef struct {
    int n;
    const char *const *name;
    const double *tol;   /**< largest deviation accepted */
    const int *rel;      /**< 0 absolute, 1 relative, 2 relative to the larger of the
                              reference and the test's threshold */
    double *worst;       /**< worst deviation over the run, per group */
    int *worst_at;       /**< ... at this sample or checkpoint */
} rpc_groups_t;

/** Deviation of a from the reference b in group gr (NaN: 1e30); thr: the
 *  threshold of a rel 2 group. */
double rpc_dev(const rpc_groups_t *g, int gr, double a, double b, double thr);

/** Takes deviation d of group gr at sample or checkpoint at into the
 *  run's worst. */
void rpc_note(const rpc_groups_t *g, int gr, double d, int at);

/**
 * Checkpoint j: o against ref. The time, status and counters exactly (a
 * FAIL line each); the state's groups within their tolerances (one FAIL
 * line for the worst). *w = the worst deviation as a fraction of its
 * tolerance, *where its group. Returns 1 if anything failed, else 0.
 */
int rpc_check_state(const rpc_groups_t *g, int j, const insr_check_t *o, const insr_check_t *ref,
                    double *w, const char **where);

/**
 * A preset (name) computed on the target with status st into (c, a)
 * against the configuration replayed: integers exactly, reals to tol
 * relative; one line. Returns 1 if it failed.
 */
int rpc_check_preset(const char *name, se23_real_t rate_hz, se23_real_t lat, se23_status_t st,
                     const se23_ins_config_t *c, const se23_ins_align_t *a,
                     const se23_ins_config_t *c_ref, const se23_ins_align_t *a_ref, double tol);

/** "worst deviation over the run" with every group's worst and tolerance. */
void rpc_print_worst(const rpc_groups_t *g);

#endif /* SE23_WALK_REPLAY_CHECK_H */
