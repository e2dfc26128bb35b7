/*
 * The checks of a replay's checkpoints and presets, shared by the walk and
 * drive images (walk_replay_check.h).
 */
#include <stdio.h>

#include "walk_replay_check.h"

double rpc_dev(const rpc_groups_t *g, int gr, double a, double b, double thr)
{
    double d = a - b;
    d = d < 0.0 ? -d : d;
    if (g->rel[gr] != 0) {
        double r = b < 0.0 ? -b : b;
        r = (g->rel[gr] == 2 && r < thr) ? thr : r;
        d = r != 0.0 ? d / r : (d != 0.0 ? 1e30 : 0.0);
    }
    return d == d ? d : 1e30;
}

void rpc_note(const rpc_groups_t *g, int gr, double d, int at)
{
    if (d > g->worst[gr]) {
        g->worst[gr] = d;
        g->worst_at[gr] = at;
    }
}

/* Worst deviation (as a fraction of tol) of n reals of group gr; updates
 * the run's worst and *where. */
static double compare(const rpc_groups_t *g, int gr, const se23_real_t *a, const se23_real_t *b,
                      int n, double worst, const char **where, int at)
{
    int i;
    for (i = 0; i < n; ++i) {
        const double d = rpc_dev(g, gr, (double)a[i], (double)b[i], 0.0);
        rpc_note(g, gr, d, at);
        if (d / g->tol[gr] > worst) {
            worst = d / g->tol[gr];
            *where = g->name[gr];
        }
    }
    return worst;
}

int rpc_check_state(const rpc_groups_t *g, int j, const insr_check_t *o, const insr_check_t *ref,
                    double *w, const char **where)
{
    int fails = 0, i;
    *where = "-";
    *w = 0.0;
    if (o->t_ns != ref->t_ns || o->status != ref->status) {
        printf("FAIL sample %d: t %lld ns, status 0x%03x; expected %lld, 0x%03x\n", ref->at,
               (long long)o->t_ns, (unsigned)o->status, (long long)ref->t_ns,
               (unsigned)ref->status);
        ++fails;
    }
    for (i = 0; i < INSR_N_COUNTERS; ++i) {
        if (o->c[i] != ref->c[i]) {
            printf("FAIL sample %d: counter %s = %u, expected %u\n", ref->at, insr_counter_name[i],
                   (unsigned)o->c[i], (unsigned)ref->c[i]);
            ++fails;
        }
    }
    *w = compare(g, RPC_R, o->R, ref->R, 9, *w, where, j);
    *w = compare(g, RPC_V, o->v, ref->v, 3, *w, where, j);
    *w = compare(g, RPC_P, o->p, ref->p, 3, *w, where, j);
    *w = compare(g, RPC_BG, o->bg, ref->bg, 3, *w, where, j);
    *w = compare(g, RPC_BA, o->ba, ref->ba, 3, *w, where, j);
    *w = compare(g, RPC_PD, o->P, ref->P, 15, *w, where, j);
    if (!(*w <= 1.0)) {
        printf("FAIL sample %d: %s beyond its tolerance (%.3g x tol)\n", ref->at, *where, *w);
        ++fails;
    }
    *w = *w < 99.99 ? *w : 99.99;
    return fails != 0;
}

int rpc_check_preset(const char *name, se23_real_t rate_hz, se23_real_t lat, se23_status_t st,
                     const se23_ins_config_t *c, const se23_ins_align_t *a,
                     const se23_ins_config_t *c_ref, const se23_ins_align_t *a_ref, double tol)
{
    double worst = 0.0;
    int bad, same = 1;
    if (st != SE23_OK) {
        printf("FAIL %s(%g, %g) refused\n", name, (double)rate_hz, (double)lat);
        return 1;
    }
    bad = insr_config_diff(c, a, c_ref, a_ref, tol, &worst, &same);
    printf("preset    %s(%g, %.9g) on the target: %s the host's (worst %.2e relative, tol "
           "%.0e)  %s\n",
           name, (double)rate_hz, (double)lat, same ? "identical to" : "close to", worst, tol,
           bad != 0 ? "FAIL" : "ok");
    return bad != 0;
}

void rpc_print_worst(const rpc_groups_t *g)
{
    int j;
    printf("worst deviation over the run (tolerance):\n");
    for (j = 0; j < g->n; ++j) {
        printf("  %-20s %9.2e  (tol %.1e%s: %5.1f%%)\n", g->name[j], g->worst[j], g->tol[j],
               g->rel[j] == 1 ? ", relative" : "", 100.0 * g->worst[j] / g->tol[j]);
    }
}
