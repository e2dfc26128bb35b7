/*
 * se23-walk: the report of a foot-mounted walk without ground truth, from
 * the INS log se23-ins wrote (nav states at the IMU rate): the loop-closure
 * error of a walk that ends where it started, the distance walked, the
 * stance phases, and a CSV for the plots (tools/walk/plot_walk.py).
 *
 * Definitions (tools/doc/pages/walks.md):
 *  - a stance phase is a run of nav states with the detector's stationary
 *    flag (status bit 0x80), runs closer than --merge seconds merged (the
 *    flag may flicker within one stance);
 *  - the first stance position is the state at alignment (the first nav
 *    state), the last stance position the state at the start of the last
 *    stance phase (the closure is read when the foot comes down), and
 *    also at the last state (a rest must hold the position: the two
 *    differ by what the filter let the foot wander at rest);
 *  - closure error = |p_last - p_first| (3D), and its horizontal and
 *    vertical parts;
 *  - distance walked = the path length through the stance positions;
 *  - the closure's normalised error e^T C^-1 e, C the filter's own
 *    covariance of the last stance position (R P_rhorho R^T): the start
 *    defines the frame, so the first position's variance (1 mm^2) and its
 *    correlation with the last are left out. Chi-square with 3 degrees of
 *    freedom if the filter's covariance is honest about its drift.
 *
 * Run with --help for the options; exit status 1 if --max-closure is given
 * and the 3D closure error exceeds it, or --max-closure-nis and the
 * normalised error exceeds that.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "../lcm/harness.h"
#include "../report/logread.h"
#include "../report/metrics.h"

#define ST_INITIALISED 0x001
#define ST_STATIONARY 0x080

typedef struct {
    const char *csv;
    const char *plots;
    const char *plot_script;
    const char *python;
    double merge;
    double max_closure;
    double max_closure_nis;
} walk_opts_t;

static void usage(FILE *f)
{
    fprintf(f, "usage: se23-walk [options] INS_LOG\n"
               "  --csv PATH          per-state CSV (t, position, velocity, speed, its sigma,\n"
               "                      detector statistic, stance flag, position\n"
               "                      covariance, absolute time [ns])\n"
               "  --plots DIR         CSV and PNG plots into DIR (tools/walk/plot_walk.py)\n"
               "  --plot-script PATH  plotter (tools/walk/plot_walk.py)\n"
               "  --python PATH       interpreter with matplotlib (/usr/bin/python3)\n"
               "  --merge S           stance runs closer than S merge into one phase (0.1)\n"
               "  --max-closure M     exit 1 if the 3D closure error exceeds M metres\n"
               "  --max-closure-nis X exit 1 if the closure's normalised error (3 dof)\n"
               "                      exceeds X\n");
}

static double speed_sigma(const se23lcm_nav_state *m)
{
    /* Var(|v|) ~ u^T R P_nunu R^T u, u = v / |v| (P in the body-frame error) */
    double u[3], Ru[3] = {0.0, 0.0, 0.0}, s = 0.0, n;
    int i, j;
    n = sqrt(m->v_n[0] * m->v_n[0] + m->v_n[1] * m->v_n[1] + m->v_n[2] * m->v_n[2]);
    for (i = 0; i < 3; i++) {
        u[i] = n > 1e-9 ? m->v_n[i] / n : (i == 0);
    }
    for (i = 0; i < 3; i++) { /* R^T u */
        for (j = 0; j < 3; j++) {
            Ru[i] += m->R_nb[3 * j + i] * u[j];
        }
    }
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            s += Ru[i] * m->P[15 * (3 + i) + 3 + j] * Ru[j];
        }
    }
    return sqrt(s > 0.0 ? s : 0.0);
}

static void write_csv(const char *path, const log_data_t *d)
{
    FILE *f = fopen(path, "w");
    size_t k;
    if (f == NULL) {
        fprintf(stderr, "se23-walk: cannot write %s\n", path);
        return;
    }
    fprintf(f, "t,pN,pE,pD,vN,vE,vD,speed,sspeed,spN,spE,spD,stat,stance,"
               "cNN,cNE,cND,cEE,cED,cDD,t_ns\n");
    for (k = 0; k < d->n_nav; k++) {
        const se23lcm_nav_state *m = &d->nav[k];
        const double sp = sqrt(m->v_n[0] * m->v_n[0] + m->v_n[1] * m->v_n[1] +
                               m->v_n[2] * m->v_n[2]);
        double C[3][3];
        metrics_nav_cov(m->R_nb, m->P, 6, C); /* position, nav frame */
        fprintf(f,
                "%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6g,%.6g,%.6g,%.6g,%d,"
                "%.6g,%.6g,%.6g,%.6g,%.6g,%.6g,%lld\n",
                (double)(m->t_ns - d->nav[0].t_ns) * 1e-9, m->p_n[0], m->p_n[1], m->p_n[2],
                m->v_n[0], m->v_n[1], m->v_n[2], sp, speed_sigma(m), sqrt(C[0][0]), sqrt(C[1][1]),
                sqrt(C[2][2]), m->detector_stat, (m->status & ST_STATIONARY) != 0, C[0][0],
                C[0][1], C[0][2], C[1][1], C[1][2], C[2][2], (long long)m->t_ns);
    }
    fclose(f);
}

/* The closure from state `first` to state k: e = p_k - p_first, its
 * horizontal and vertical lengths, the filter's covariance C of p_k in
 * the nav frame and the normalised error e^T C^-1 e (the start defines the
 * frame: its 1 mm^2 and its correlation with p_k are left out). */
static void closure(const log_data_t *d, size_t first, size_t k, double e[3], double *h,
                    double *v, double C[3][3], double *nis)
{
    int i;
    for (i = 0; i < 3; i++) {
        e[i] = d->nav[k].p_n[i] - d->nav[first].p_n[i];
    }
    *h = sqrt(e[0] * e[0] + e[1] * e[1]);
    *v = fabs(e[2]);
    metrics_nav_cov(d->nav[k].R_nb, d->nav[k].P, 6, C);
    *nis = metrics_nees(&C[0][0], 3, e, 3);
}

static int plot(const walk_opts_t *o)
{
    char cmd[4096];
    snprintf(cmd, sizeof cmd, "'%s' '%s' --dir '%s'", o->python, o->plot_script, o->plots);
    return system(cmd) == 0 ? 0 : -1;
}

int main(int argc, char **argv)
{
    walk_opts_t o = {NULL, NULL, "tools/walk/plot_walk.py", "/usr/bin/python3", 0.1, -1.0, -1.0};
    const harness_opt_t opts[] = {
        {"--csv", HOPT_STR, &o.csv, 0, 0, NULL},
        {"--plots", HOPT_STR, &o.plots, 0, 0, NULL},
        {"--plot-script", HOPT_STR, &o.plot_script, 0, 0, NULL},
        {"--python", HOPT_STR, &o.python, 0, 0, NULL},
        {"--merge", HOPT_DOUBLE, &o.merge, 0.0, 10.0, NULL},
        {"--max-closure", HOPT_DOUBLE, &o.max_closure, 0.0, 1e9, NULL},
        {"--max-closure-nis", HOPT_DOUBLE, &o.max_closure_nis, 0.0, 1e9, NULL},
    };
    const char *pos[2];
    int n_pos = 0, ok = 1;
    log_data_t d;
    size_t k, first = 0, last_start = 0, phases = 0;
    int64_t last_stance_ns = 0;
    int in_stance = 0, have_stance = 0;
    double dist = 0.0, prev[3], e[3], h, v, C[3][3], nis;
    if (harness_parse_opts("se23-walk", argc, argv, opts, (int)(sizeof opts / sizeof opts[0]),
                           usage, pos, &n_pos) != 0 ||
        n_pos != 1) {
        usage(stderr);
        return 2;
    }
    memset(&d, 0, sizeof d);
    if (log_read(pos[0], &d) != 0) {
        log_free(&d);
        return 1;
    }
    log_sort(&d);
    while (first < d.n_nav && !(d.nav[first].status & ST_INITIALISED)) {
        first++;
    }
    if (first == d.n_nav) {
        fprintf(stderr, "se23-walk: no initialised nav state in %s\n", pos[0]);
        log_free(&d);
        return 1;
    }
    memcpy(prev, d.nav[first].p_n, sizeof prev);
    for (k = first; k < d.n_nav; k++) {
        const se23lcm_nav_state *m = &d.nav[k];
        const int st = (m->status & ST_STATIONARY) != 0;
        if (st && !in_stance &&
            (!have_stance || (double)(m->t_ns - last_stance_ns) * 1e-9 > o.merge)) {
            int i;
            double s = 0.0;
            phases++;
            last_start = k;
            for (i = 0; i < 3; i++) {
                s += (m->p_n[i] - prev[i]) * (m->p_n[i] - prev[i]);
                prev[i] = m->p_n[i];
            }
            dist += sqrt(s);
        }
        if (st) {
            last_stance_ns = m->t_ns;
            have_stance = 1;
        }
        in_stance = st;
    }
    closure(&d, first, last_start, e, &h, &v, C, &nis);
    printf("se23-walk: %s\n", pos[0]);
    printf("  walk               %.1f s, %zu nav states\n",
           (double)(d.nav[d.n_nav - 1].t_ns - d.nav[first].t_ns) * 1e-9, d.n_nav - first);
    printf("  stance phases      %zu (runs of the stationary flag, merged within %.2f s)\n",
           phases, o.merge);
    printf("  distance walked    %.2f m (through the stance positions)\n", dist);
    printf("  closure error      %.3f m 3D, %.3f m horizontal, %.3f m vertical\n",
           sqrt(h * h + v * v), h, v);
    printf("  closure read at    t = %.3f s (start of the last stance), %.2f %% of the distance\n",
           (double)(d.nav[last_start].t_ns - d.nav[first].t_ns) * 1e-9,
           dist > 0.0 ? 100.0 * sqrt(h * h + v * v) / dist : 0.0);
    printf("  filter's 1-sigma   %.3f m N, %.3f m E, %.3f m D there; normalised closure "
           "error %.2f (3 dof, 99 %% below 11.34)\n",
           sqrt(C[0][0]), sqrt(C[1][1]), sqrt(C[2][2]), nis);
    {
        double e_end[3], h_end, v_end, C_end[3][3], nis_end;
        closure(&d, first, d.n_nav - 1, e_end, &h_end, &v_end, C_end, &nis_end);
        printf("  at the end         %.3f m 3D, %.3f m horizontal, %.3f m vertical; normalised "
               "error %.2f\n",
               sqrt(h_end * h_end + v_end * v_end), h_end, v_end, nis_end);
    }
    if (o.csv != NULL) {
        write_csv(o.csv, &d);
    }
    if (o.plots != NULL) {
        char path[1024];
        mkdir(o.plots, 0777);
        snprintf(path, sizeof path, "%s/walk.csv", o.plots);
        write_csv(path, &d);
        if (plot(&o) != 0) {
            fprintf(stderr, "se23-walk: plotting failed (needs %s with matplotlib)\n", o.python);
            ok = 0;
        } else {
            printf("  plots              %s/{walk_path,walk_time}.png (data: %s/walk.csv)\n",
                   o.plots, o.plots);
        }
    }
    if (o.max_closure_nis >= 0.0 && !(nis <= o.max_closure_nis)) {
        printf("WALK CHECK FAILED: normalised closure error %.2f above %.2f\n", nis,
               o.max_closure_nis);
        ok = 0;
    }
    if (o.max_closure >= 0.0 && sqrt(h * h + v * v) > o.max_closure) {
        printf("WALK CHECK FAILED: closure %.3f m above %.3f m\n", sqrt(h * h + v * v),
               o.max_closure);
        ok = 0;
    }
    log_free(&d);
    return ok ? 0 : 1;
}
