/*
 * se23-report: reads LCM logs of a harness run (truth from se23-sim, nav
 * states from se23-ins; one log or several), prints a table of final/RMS/max
 * errors, 3-sigma consistency, NEES and the INS's input accounting, writes
 * a CSV of the per-epoch errors and PNG plots (tools/report/plot.py with
 * Debian's /usr/bin/python3 and python3-matplotlib).
 *
 * With --check the exit status says whether the estimate is consistent
 * (see usage); the harness tests use it.
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "../lcm/harness.h"
#include "logread.h"
#include "metrics.h"
#include "preint_check.h"

#define RAD2DEG (180.0 / 3.14159265358979323846)

typedef struct {
    const char *plots_dir; /* NULL: no CSV, no plots */
    const char *plot_script;
    const char *python;
    int check;
    double check_frac;     /* fraction of epochs within 3 sigma, per component */
    double check_nees_lo, check_nees_hi; /* band on mean NEES / dof */
    double check_max_pos;  /* final position error bound [m] (<= 0: none) */
    double check_preint;   /* factor prediction error bound [m] (<= 0: none) */
    int no_screen;         /* read nav states and truth unscreened (logread.h) */
    int n_logs;
    const char **logs;
} rep_opts_t;

static void usage(FILE *f)
{
    fprintf(f,
            "usage: se23-report [options] LOG...\n"
            "  --plots DIR         write errors.csv and PNG plots to DIR\n"
            "  --plot-script PATH  plotter (tools/report/plot.py; \"\": CSV files only)\n"
            "  --python PATH       interpreter with matplotlib (/usr/bin/python3)\n"
            "  --check             exit 1 unless consistent: each error component\n"
            "                      within 3 sigma in >= --check-frac of the epochs (0.9)\n"
            "                      and mean NEES/dof (9, and 15 with bias states) in\n"
            "                      [--nees-lo, --nees-hi] (0.3, 3)\n"
            "  --max-pos-err M     exit 1 unless the final position error is <= M [m]\n"
            "  --max-preint-err M  exit 1 unless every preintegrated factor predicts the\n"
            "                      truth at its end from the truth at its start within M [m]\n"
            "  --no-screen         keep nav states and truth records with NaN, non-rotations,\n"
            "                      negative variances or impossible status (by default left\n"
            "                      out and counted, exit status 3)\n");
}

static int parse_args(int argc, char **argv, rep_opts_t *o)
{
    const double inf = HUGE_VAL;
    const harness_opt_t opts[] = {
        {"--plots", HOPT_STR, &o->plots_dir, 0, 0, NULL},
        {"--plot-script", HOPT_STR, &o->plot_script, 0, 0, NULL},
        {"--python", HOPT_STR, &o->python, 0, 0, NULL},
        {"--check", HOPT_FLAG, &o->check, 1, 0, NULL},
        {"--check-frac", HOPT_DOUBLE, &o->check_frac, 0.0, 1.0, NULL},
        {"--nees-lo", HOPT_DOUBLE, &o->check_nees_lo, 0.0, inf, NULL},
        {"--nees-hi", HOPT_DOUBLE, &o->check_nees_hi, 0.0, inf, NULL},
        {"--max-pos-err", HOPT_DOUBLE, &o->check_max_pos, 0.0, inf, NULL},
        {"--max-preint-err", HOPT_DOUBLE, &o->check_preint, 0.0, inf, NULL},
        {"--no-screen", HOPT_FLAG, &o->no_screen, 1, 0, NULL},
    };
    memset(o, 0, sizeof *o);
    o->plot_script = "tools/report/plot.py";
    o->python = "/usr/bin/python3";
    o->check_frac = 0.9;
    o->check_nees_lo = 0.3;
    o->check_nees_hi = 3.0;
    o->logs = malloc(sizeof(char *) * (size_t)argc);
    if (o->logs == NULL ||
        harness_parse_opts("se23-report", argc, argv, opts, (int)(sizeof opts / sizeof opts[0]),
                           usage, o->logs, &o->n_logs) != 0) {
        return -1;
    }
    return o->n_logs > 0 ? 0 : -1;
}

/* Statistics of one 3-vector error group over the epochs. */
typedef struct {
    double final_norm, rms, max_norm, final_sigma;
    double frac_in[3]; /* per component, |e| <= 3 sigma */
} group_stats_t;

typedef enum { G_POS, G_VEL, G_ATT, G_BG, G_BA, G_COUNT } group_t;

static void group_vec(const epoch_t *e, group_t g, const double **err, const double **sig)
{
    switch (g) {
    case G_POS:
        *err = e->dp;
        *sig = e->sp;
        break;
    case G_VEL:
        *err = e->dv;
        *sig = e->sv;
        break;
    case G_ATT:
        *err = e->dth;
        *sig = e->sth;
        break;
    case G_BG:
    case G_BA:
    default:
        *err = NULL;
        *sig = g == G_BG ? e->sbg : e->sba;
        break;
    }
}

static group_stats_t group_stats(const epoch_t *ep, size_t n, group_t g)
{
    group_stats_t s;
    double sum2 = 0.0;
    size_t i, in[3] = {0, 0, 0};
    int k;
    memset(&s, 0, sizeof s);
    for (i = 0; i < n; i++) {
        const double *err, *sig;
        double e[3], nn;
        group_vec(&ep[i], g, &err, &sig);
        for (k = 0; k < 3; k++) {
            if (g == G_BG) {
                e[k] = ep[i].bg_true[k] - ep[i].bg_est[k];
            } else if (g == G_BA) {
                e[k] = ep[i].ba_true[k] - ep[i].ba_est[k];
            } else {
                e[k] = err[k];
            }
            if (fabs(e[k]) <= 3.0 * sig[k]) {
                in[k]++;
            }
        }
        nn = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
        sum2 += nn;
        if (sqrt(nn) > s.max_norm) {
            s.max_norm = sqrt(nn);
        }
        if (i + 1 == n) {
            s.final_norm = sqrt(nn);
            s.final_sigma = sqrt(sig[0] * sig[0] + sig[1] * sig[1] + sig[2] * sig[2]);
        }
    }
    if (n > 0) {
        s.rms = sqrt(sum2 / (double)n);
        for (k = 0; k < 3; k++) {
            s.frac_in[k] = (double)in[k] / (double)n;
        }
    }
    return s;
}

/* The simulator's scenarios by number (tools/sim/traj.h). */
static const char *const scen_names[] = {"static", "uav", "car", "nav", "walk", "stairs"};
#define N_SCEN ((int)(sizeof scen_names / sizeof scen_names[0]))

static void print_header(const log_data_t *d)
{
    if (d->have_info) {
        const se23lcm_sim_info *i = &d->info;
        const harness_imu_profile_t *p = harness_imu_profile(i->imu_profile);
        printf("se23 report: scenario %s, %.0f s, IMU %s at %.0f Hz, Earth rotation %s, "
               "GNSS %.3g Hz, seed %lld\n",
               (i->scenario >= 0 && i->scenario < N_SCEN) ? scen_names[i->scenario] : "?",
               i->duration_s, p ? p->name : "?", i->imu_rate_hz, i->earth_rotation ? "on" : "off",
               i->gnss_rate_hz, (long long)i->seed);
    } else {
        printf("se23 report (no SE23_SIM_INFO in the logs)\n");
    }
}

static void print_row(const char *name, const group_stats_t *s, double scale, const char *fmt)
{
    char line[256];
    snprintf(line, sizeof line, "  %%-18s %s %s %s %s   %%5.1f%%%% %%5.1f%%%% %%5.1f%%%%\n", fmt, fmt,
             fmt, fmt);
    printf(line, name, s->final_norm * scale, s->rms * scale, s->max_norm * scale,
           s->final_sigma * scale, 100.0 * s->frac_in[0], 100.0 * s->frac_in[1],
           100.0 * s->frac_in[2]);
}

static void write_csv(const char *path, const epoch_t *ep, size_t n)
{
    FILE *f = fopen(path, "w");
    size_t i;
    int k;
    if (f == NULL) {
        fprintf(stderr, "se23-report: cannot write %s\n", path);
        return;
    }
    fprintf(f, "t,ptN,ptE,ptD,peN,peE,peD,dpN,dpE,dpD,spN,spE,spD,dvN,dvE,dvD,svN,svE,svD,"
               "dthN,dthE,dthD,sthN,sthE,sthD,bgt1,bgt2,bgt3,bge1,bge2,bge3,sbg1,sbg2,sbg3,"
               "bat1,bat2,bat3,bae1,bae2,bae3,sba1,sba2,sba3,nees9,nees15,status\n");
    for (i = 0; i < n; i++) {
        const epoch_t *e = &ep[i];
        const double *groups[15] = {e->p_true, e->p_est, e->dp,      e->sp,     e->dv,
                                    e->sv,     e->dth,   e->sth,     e->bg_true, e->bg_est,
                                    e->sbg,    e->ba_true, e->ba_est, e->sba,   NULL};
        fprintf(f, "%.6f", e->t);
        for (k = 0; groups[k] != NULL; k++) {
            fprintf(f, ",%.9g,%.9g,%.9g", groups[k][0], groups[k][1], groups[k][2]);
        }
        fprintf(f, ",%.6g,%.6g,%d\n", e->nees9, e->nees15, e->status);
    }
    fclose(f);
}

static void write_gnss_csv(const char *path, const log_data_t *d)
{
    FILE *f = fopen(path, "w");
    size_t i;
    if (f == NULL) {
        return;
    }
    fprintf(f, "t,pN,pE,pD\n");
    for (i = 0; i < d->n_gnss; i++) {
        fprintf(f, "%.6f,%.6f,%.6f,%.6f\n", (double)d->gnss[i].t_ns * 1e-9, d->gnss[i].p_n[0],
                d->gnss[i].p_n[1], d->gnss[i].p_n[2]);
    }
    fclose(f);
}

static int make_plots(const rep_opts_t *o, const log_data_t *d)
{
    char cmd[4096], title[256];
    const char *scen = "run";
    if (d->have_info && d->info.scenario >= 0 && d->info.scenario < 4) {
        scen = scen_names[d->info.scenario];
    }
    if (d->have_info) {
        const harness_imu_profile_t *p = harness_imu_profile(d->info.imu_profile);
        snprintf(title, sizeof title, "%s, %s IMU %.0f Hz, Earth rotation %s, GNSS %.3g Hz", scen,
                 p ? p->name : "?", d->info.imu_rate_hz, d->info.earth_rotation ? "on" : "off",
                 d->info.gnss_rate_hz);
    } else {
        snprintf(title, sizeof title, "se23 run");
    }
    snprintf(cmd, sizeof cmd, "'%s' '%s' --dir '%s' --title '%s'", o->python, o->plot_script,
             o->plots_dir, title);
    return system(cmd);
}

/* The report of the logs in d (truth present): 1 if every check passed. */
static int report(const rep_opts_t *o, log_data_t *d)
{
    epoch_t *ep;
    size_t i, n = 0, n_nees9 = 0, n_nees15 = 0, n_in99 = 0;
    double nees9 = 0.0, nees15 = 0.0;
    group_stats_t gs[G_COUNT];
    const se23lcm_nav_state *last;
    int ok = 1, k;

    log_sort(d);
    ep = malloc((d->n_nav + 1) * sizeof *ep);
    if (ep == NULL) {
        return 0;
    }
    for (i = 0; i < d->n_nav; i++) {
        long j = log_find_truth(d, d->nav[i].t_ns);
        if (j >= 0) {
            metrics_epoch(&d->truth[j], &d->nav[i], &ep[n]);
            if (isfinite(ep[n].nees9)) {
                nees9 += ep[n].nees9;
                n_nees9++;
                n_in99 += ep[n].nees9 <= 21.666; /* chi-square 9 dof, 99% */
            }
            if (isfinite(ep[n].nees15)) {
                nees15 += ep[n].nees15;
                n_nees15++;
            }
            n++;
        }
    }
    print_header(d);
    if (n == 0) {
        printf("no nav state matches a truth time (%zu truth, %zu nav states; left out as "
               "corrupt: %lld nav states, %lld truth records)\n",
               d->n_truth, d->n_nav, (long long)d->nav_rejected[0],
               (long long)d->truth_rejected[0]);
        free(ep);
        return 0;
    }
    for (k = 0; k < G_COUNT; k++) {
        gs[k] = group_stats(ep, n, (group_t)k);
    }
    printf("  %zu epochs compared, t = %.2f .. %.2f s\n\n", n, ep[0].t, ep[n - 1].t);
    printf("  %-18s %10s %10s %10s %10s   within 3 sigma (N/E/D)\n", "error", "final", "RMS",
           "max", "sigma");
    print_row("position [m]", &gs[G_POS], 1.0, "%10.3f");
    print_row("velocity [m/s]", &gs[G_VEL], 1.0, "%10.4f");
    print_row("attitude [deg]", &gs[G_ATT], RAD2DEG, "%10.4f");
    print_row("gyro bias [deg/h]", &gs[G_BG], RAD2DEG * 3600.0, "%10.2f");
    print_row("accel bias [mg]", &gs[G_BA], 1000.0 / 9.80665, "%10.3f");
    printf("  (final sigma column: sqrt of the summed axis variances; bias rows: axes 1/2/3)\n\n");
    if (n_nees9 > 0) {
        printf("  mean NEES, pose (9 dof):        %7.2f  (consistent: ~9); "
               "%.1f%% of epochs below chi2(9, 0.99)\n",
               nees9 / (double)n_nees9, 100.0 * (double)n_in99 / (double)n_nees9);
    }
    if (n_nees15 > 0) {
        printf("  mean NEES, pose + biases (15):  %7.2f  (consistent: ~15)\n",
               nees15 / (double)n_nees15);
    }
    last = &d->nav[d->n_nav - 1];
    printf("\n  IMU samples in the log: %lld; integrated %lld, rejected %lld "
           "(non-finite %lld, range %lld, duplicate %lld, out of order %lld, bad time %lld, "
           "bad dt %lld), missing %lld, before init %lld\n",
           (long long)d->n_imu, (long long)last->n_imu_used,
           (long long)(last->n_imu_nonfinite + last->n_imu_range + last->n_imu_duplicate +
                       last->n_imu_out_of_order + last->n_imu_bad_time + last->n_imu_bad_dt),
           (long long)last->n_imu_nonfinite, (long long)last->n_imu_range,
           (long long)last->n_imu_duplicate, (long long)last->n_imu_out_of_order,
           (long long)last->n_imu_bad_time, (long long)last->n_imu_bad_dt,
           (long long)last->n_imu_missing, (long long)last->n_imu_early);
    printf("  GNSS fixes: used %lld, rejected %lld; messages not decoded: %lld (INS), %lld "
           "(report); time resets %lld; library errors %lld; initial states refused %lld; "
           "status 0x%02x\n",
           (long long)last->n_gnss_used, (long long)last->n_gnss_rejected,
           (long long)last->n_decode_errors, (long long)d->n_decode_errors,
           (long long)last->n_time_resets, (long long)last->n_filter_errors,
           (long long)last->n_init_rejected,
           (unsigned)last->status);
    printf("  log bytes skipped as corrupt (report): %lld in %lld places\n",
           (long long)d->bytes_skipped, (long long)d->corrupt_spans);
    printf("  nav states left out as corrupt (report): %lld (non-finite %lld, not a rotation "
           "%lld, covariance %lld, status %lld); truth records: %lld\n",
           (long long)d->nav_rejected[0], (long long)d->nav_rejected[LOG_BAD_NONFINITE],
           (long long)d->nav_rejected[LOG_BAD_ROTATION], (long long)d->nav_rejected[LOG_BAD_COV],
           (long long)d->nav_rejected[LOG_BAD_STATUS], (long long)d->truth_rejected[0]);

    if (d->n_preint > 0) {
        preint_check_t pc;
        preint_check(d, &pc);
        printf("  preintegrated factors: %lld covering %lld IMU samples; %lld malformed\n",
               (long long)d->n_preint, (long long)d->preint_samples, (long long)d->n_preint_bad);
        printf("  factor prediction from the truth (%ld factors): max error %.3g m, %.3g m/s, "
               "%.3g rad\n",
               pc.n_checked, pc.max_pos_err, pc.max_vel_err, pc.max_att_err);
        if (o->check_preint > 0.0) {
            int pass = pc.n_checked > 0 && pc.max_pos_err <= o->check_preint;
            printf("%s: factor prediction error %.3g m, bound %.3g m\n",
                   pass ? "PREINT CHECK PASSED" : "PREINT CHECK FAILED", pc.max_pos_err,
                   o->check_preint);
            ok = ok && pass;
        }
    } else if (o->check_preint > 0.0) {
        printf("PREINT CHECK FAILED: no preintegrated factor in the logs\n");
        ok = 0;
    }
    if (o->plots_dir != NULL) {
        char path[1024];
        mkdir(o->plots_dir, 0777);
        snprintf(path, sizeof path, "%s/errors.csv", o->plots_dir);
        write_csv(path, ep, n);
        snprintf(path, sizeof path, "%s/gnss.csv", o->plots_dir);
        write_gnss_csv(path, d);
        if (o->plot_script[0] == '\0') {
            printf("\n  data: %s/errors.csv, %s/gnss.csv\n", o->plots_dir, o->plots_dir);
        } else if (make_plots(o, d) != 0) {
            fprintf(stderr, "se23-report: plotting failed (needs %s with matplotlib)\n",
                    o->python);
            ok = 0;
        } else {
            printf("\n  plots: %s/{trajectory,errors,biases,nees}.png  (data: %s/errors.csv)\n",
                   o->plots_dir, o->plots_dir);
        }
    }
    if (o->check) {
        const group_t checked[3] = {G_POS, G_VEL, G_ATT};
        double mean9 = n_nees9 ? nees9 / (double)n_nees9 / 9.0 : NAN;
        for (k = 0; k < 3; k++) {
            int c;
            for (c = 0; c < 3; c++) {
                if (gs[checked[k]].frac_in[c] < o->check_frac) {
                    printf("CHECK FAILED: group %d axis %d within 3 sigma in %.1f%% < %.1f%%\n",
                           k, c, 100.0 * gs[checked[k]].frac_in[c], 100.0 * o->check_frac);
                    ok = 0;
                }
            }
        }
        if (!(mean9 >= o->check_nees_lo && mean9 <= o->check_nees_hi)) {
            printf("CHECK FAILED: mean NEES/dof (9) %.3f outside [%.2f, %.2f]\n", mean9,
                   o->check_nees_lo, o->check_nees_hi);
            ok = 0;
        }
        if (n_nees15 > 0 && !(nees15 / (double)n_nees15 / 15.0 >= o->check_nees_lo &&
                              nees15 / (double)n_nees15 / 15.0 <= o->check_nees_hi)) {
            printf("CHECK FAILED: mean NEES/dof (15) %.3f outside [%.2f, %.2f]\n",
                   nees15 / (double)n_nees15 / 15.0, o->check_nees_lo, o->check_nees_hi);
            ok = 0;
        }
        printf("%s\n", ok ? "CHECK PASSED" : "CHECK FAILED");
    }
    if (o->check_max_pos > 0.0) {
        int pass = gs[G_POS].final_norm <= o->check_max_pos;
        printf("%s: final position error %.3g m, bound %.3g m\n",
               pass ? "POSITION CHECK PASSED" : "POSITION CHECK FAILED", gs[G_POS].final_norm,
               o->check_max_pos);
        ok = ok && pass;
    }
    free(ep);
    return ok;
}

/*
 * Exit status: 0 every check passed; 1 a check failed, a log cannot be read,
 * or there is nothing to compare; 2 usage; 3 every check passed but bytes of
 * a corrupt log were skipped (tools/lcm/logfile.h) or nav states or truth
 * records that decoded were left out as corrupt (logread.h, "Screening").
 */
int main(int argc, char **argv)
{
    rep_opts_t o;
    log_data_t d;
    int rc = 0, k;

    memset(&d, 0, sizeof d);
    if (parse_args(argc, argv, &o) != 0) {
        usage(stderr);
        free((void *)o.logs);
        return 2;
    }
    d.screen = !o.no_screen; /* NaN, non-rotations, negative variances stay out */
    for (k = 0; k < o.n_logs && rc == 0; k++) {
        rc = log_read(o.logs[k], &d) != 0;
    }
    if (rc == 0 && d.n_truth == 0) {
        fprintf(stderr, "se23-report: no truth in the log%s\n", o.n_logs > 1 ? "s" : "");
        rc = 1;
    }
    if (rc == 0) {
        rc = report(&o, &d) ? 0 : 1;
    }
    if (rc == 0 && d.bytes_skipped > 0) {
        printf("LOG CORRUPT: %lld bytes skipped in %lld places (exit status 3)\n",
               (long long)d.bytes_skipped, (long long)d.corrupt_spans);
        rc = 3;
    }
    if ((rc == 0 || rc == 3) && d.nav_rejected[0] + d.truth_rejected[0] > 0) {
        printf("LOG CORRUPT: %lld nav states and %lld truth records left out (exit status 3)\n",
               (long long)d.nav_rejected[0], (long long)d.truth_rejected[0]);
        rc = 3;
    }
    free((void *)o.logs);
    log_free(&d);
    return rc;
}
