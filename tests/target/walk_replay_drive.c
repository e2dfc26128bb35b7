/*
 * The walk's loop closure as se23-walk computes it (walk_replay.h), from
 * the filter's states after every sample: the same code in the target
 * image (walk_replay.c) and in the host generator
 * (tools/target/gen_walk_replay.c).
 */
#include <math.h>
#include <string.h>

#include "walk_replay.h"

void walk_track_init(walk_track_t *w)
{
    memset(w, 0, sizeof *w);
    w->c.first_at = -1;
    w->c.last_at = -1;
}

int walk_track(walk_track_t *w, const se23_ins_t *ins, int k, int verdict)
{
    static se23_gauss_t g; /* large: static */
    int64_t t_ns;
    int st;
    if (verdict != (int)SE23_INS_USED || (ins->status & SE23_INS_ST_INITIALISED) == 0U) {
        return 1; /* no nav state published */
    }
    st = (ins->status & SE23_INS_ST_STATIONARY) != 0U;
    if (w->c.first_at < 0 || (st && !w->in_stance)) {
        int i;
        if (se23_ins_state(ins, &g, &t_ns) != SE23_OK) {
            return 0;
        }
        if (w->c.first_at < 0) {
            w->c.first_at = k;
            w->c.t_first_ns = t_ns;
            for (i = 0; i < 3; ++i) {
                w->c.p_first[i] = g.T.p.v[i];
                w->prev[i] = (double)g.T.p.v[i];
            }
        }
        if (st && !w->in_stance &&
            (!w->have_stance || (double)(t_ns - w->last_stance_ns) * 1e-9 > WALK_MERGE_S)) {
            double s = 0.0;
            w->c.phases++;
            w->c.last_at = k;
            w->c.t_last_ns = t_ns;
            for (i = 0; i < 3; ++i) {
                const double p = (double)g.T.p.v[i];
                w->c.p_last[i] = g.T.p.v[i];
                s += (p - w->prev[i]) * (p - w->prev[i]);
                w->prev[i] = p;
            }
            w->c.dist += sqrt(s);
        }
    }
    if (st) {
        w->last_stance_ns = ins->t_ns;
        w->have_stance = 1;
    }
    w->in_stance = st;
    return 1;
}

double walk_closure_err(const walk_closure_t *c, int which)
{
    double e[3], h;
    int i;
    for (i = 0; i < 3; ++i) {
        e[i] = (double)c->p_last[i] - (double)c->p_first[i];
    }
    h = sqrt(e[0] * e[0] + e[1] * e[1]);
    return which == 1 ? h : (which == 2 ? fabs(e[2]) : sqrt(h * h + e[2] * e[2]));
}

double walk_nis(const se23_ins_t *ins, const se23_gauss_t *prev, const insr_imu_t *m,
                int verdict)
{
    if ((ins->status & SE23_INS_ST_ALIGNING) != 0U || verdict != (int)SE23_INS_USED ||
        ins->det.count != ins->det.cfg.window || prev->n == 0) {
        return -1.0;
    }
    return insr_accel_nis(ins, prev, m->f);
}
