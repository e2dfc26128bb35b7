/* The navigation filter's delayed fixes: a ring of the accepted samples and
 * two snapshots of the state, delay_horizon apart; see ins.h, "Delayed
 * fixes". */
#include "ins_internal.h"

enum { N = SE23_INS_RING };

/* The snapshot slot k places after the older (k = 0: the older). */
static int slot(const se23_ins_t *ins, int k)
{
    return (ins->snap_old + k) % 2;
}

/* Appends a snapshot of the current state; with two held, it replaces the
 * older. */
static void take_snapshot(se23_ins_t *ins)
{
    int k;
    if (ins->n_snap == 2) {
        k = ins->snap_old;
        ins->snap_old = 1 - ins->snap_old;
    } else {
        k = slot(ins, ins->n_snap);
        ins->n_snap++;
    }
    ins->snap[k].g = ins->g;
    ins->snap[k].t_ns = ins->t_ns;
    ins->snap[k].last = ins->last;
    ins->snap[k].floor_d = ins->floor_d;
    ins->snap[k].floor_set = ins->floor_set;
}

/* Drops the ring entries not after the older snapshot. */
static void trim(se23_ins_t *ins)
{
    const int64_t t0 = ins->snap[ins->snap_old].t_ns;
    while ((ins->ring_count > 0) && (ins->ring[ins->ring_head].t_ns <= t0)) {
        ins->ring_head = (ins->ring_head + 1) % N;
        ins->ring_count--;
    }
}

/* A new snapshot once the newest is delay_horizon old. */
static void keep_apart(se23_ins_t *ins)
{
    const int64_t newest = ins->snap[slot(ins, ins->n_snap - 1)].t_ns;
    if (ins->t_ns - newest >= ins->horizon_ns) {
        take_snapshot(ins);
    }
}

void se23_ins_ring_restart(se23_ins_t *ins)
{
    ins->ring_head = 0;
    ins->ring_count = 0;
    ins->n_snap = 0;
    ins->snap_old = 0;
    if (ins->horizon_ns > 0) {
        take_snapshot(ins);
    }
}

void se23_ins_ring_push(se23_ins_t *ins, const se23_imu_sample_t *s, int rest)
{
    se23_ins_hist_t *e;
    if (ins->horizon_ns <= 0) {
        return;
    }
    if (ins->ring_count == N) {
        /* The stream outran the nominal rate the ring was sized for: start
         * again from here (fixes before now can no longer be placed). */
        se23_ins_ring_restart(ins);
        return;
    }
    e = &ins->ring[(ins->ring_head + ins->ring_count) % N];
    e->s = *s;
    e->t_ns = ins->t_ns;
    e->rest = rest;
    ins->ring_count++;
    keep_apart(ins);
    trim(ins);
}

/* After a fix fused at the current state: it is the only snapshot (later
 * fixes must be after it). */
static void rebase(se23_ins_t *ins, se23_ins_verdict_t v)
{
    if ((v == SE23_INS_USED) || (v == SE23_INS_RESET)) {
        ins->n_snap = 0;
        ins->snap_old = 0;
        take_snapshot(ins);
    }
}

se23_ins_verdict_t se23_ins_fuse_delayed(se23_ins_t *ins, const se23_ins_gnss_t *fix)
{
    const int64_t due = fix->t_ns + ins->half_ns;
    se23_ins_verdict_t v = SE23_INS_STALE;
    int64_t from;
    int pick = -1, fused = 0, k;
    for (k = 0; k < ins->n_snap; ++k) { /* the newest snapshot not after the fix */
        if (ins->snap[slot(ins, k)].t_ns <= due) {
            pick = slot(ins, k);
        }
    }
    if (pick < 0) {
        se23_ins_count(&ins->c.gnss_stale);
        return SE23_INS_STALE;
    }
    from = ins->snap[pick].t_ns;
    ins->g = ins->snap[pick].g;
    ins->t_ns = ins->snap[pick].t_ns;
    ins->last = ins->snap[pick].last;
    ins->floor_d = ins->snap[pick].floor_d;
    ins->floor_set = ins->snap[pick].floor_set;
    /* Replay: the same steps as live (prediction, the rest updates the
     * detector had called for), the fix at its own time. */
    ins->replaying = 1;
    for (k = 0; k < ins->ring_count; ++k) {
        const se23_ins_hist_t *e = &ins->ring[(ins->ring_head + k) % N];
        if (e->t_ns <= from) {
            continue;
        }
        if ((fused == 0) && (e->t_ns > due)) {
            v = se23_ins_fuse_gnss(ins, fix);
            rebase(ins, v);
            fused = 1;
        }
        (void)se23_ins_step(ins, e->t_ns, &e->s, e->rest); /* counted live */
        if ((v == SE23_INS_USED) || (v == SE23_INS_RESET)) {
            keep_apart(ins);
        }
    }
    ins->replaying = 0;
    if (fused == 0) {
        v = se23_ins_fuse_gnss(ins, fix);
        rebase(ins, v);
    }
    trim(ins);
    if (v == SE23_INS_USED) {
        se23_ins_count(&ins->c.gnss_delayed);
    }
    return v;
}
