/* se23-paper-table: reproduces the paper's Table "Higher-order errors for a
 * low-cost IMU (1 deg/s - 100 mg)" (section 4.2).
 *
 * The smooth 3D UAV trajectory of uav.h is sampled at 100 Hz and cut into
 * consecutive preintegrated factors of T = 1 s, 10 s and 60 s, each
 * integrated once at the bias estimate bbar = 0 (rows.h). For every factor,
 * `draws` fresh bias changes db are drawn, the factor is re-integrated with
 * each and compared with the first-order corrections of rows.h. Two draw
 * schemes, one table each:
 *   fixed  |db_g| = 1 deg/s and |db_a| = 100 mg exactly, independent
 *          uniform directions (the paper's "1 deg/s - 100 mg"; default)
 *   gauss  per axis N(0, (1 deg/s)^2) gyro, N(0, (100 mg)^2) accel
 * The velocity (position) RMS is sqrt(mean |DV_corr - DV_reint|^2) (resp.
 * DX) over every factor and draw. The paper's numbers are printed under
 * ours, as printed in the paper. With --check the program fails unless, in
 * the fixed table, the paper's ordering in velocity holds: proposed (basic
 * B_k) <= classical (Forster et al.'s pipeline) at every T, and se23's
 * exact B_k <= basic at T = 1 s (where B_k's O(dt) term is not swamped by
 * the O(db^2) terms that all first-order corrections share); and in
 * position at T = 1 s, the paper's method on the Deltas of its own
 * eq. backtofuture <= on the exact Deltas (the basic B_k has no position
 * block, right for eq. backtofuture, O(dt^2) short for the exact increment).
 *
 * Usage: se23-paper-table [--duration S] [--draws N] [--seed N] [--check]
 *                         [--traj FILE.csv]
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../montecarlo/paper_tool.h"
#include "rows.h"
#include "se23_rng.h"
#include "uav.h"

#define HZ 100.0
#define PI 3.14159265358979323846
#define BIAS_G (PI / 180.0)    /* 1 deg/s [rad/s] */
#define BIAS_A (0.1 * 9.80665) /* 100 mg [m/s^2] */

enum { FIXED, GAUSS, N_SCHEMES };
static const char *const scheme_name[N_SCHEMES] = {
    "fixed magnitude |b_g| = 1 deg/s, |b_a| = 100 mg, uniform directions",
    "per axis N(0, (1 deg/s)^2) gyro, N(0, (100 mg)^2) accel"};

static const char *const row_name[N_ROWS] = {
    "Classical: Forster et al. (Forster Deltas)",
    "Forster Jacobians on exact Deltas",
    "Proposed: exponential, B_k = dt I_{9,6}",
    "Proposed on Deltas of eq. backtofuture",
    "se23: exponential, exact B_k",
    "No correction"};

#define N_T 3
static const int T_sec[N_T] = {1, 10, 60};
/* The paper's Table as printed: velocity RMS [m/s], position RMS [m] at
 * T = 1, 10, 60 s; rows classical, proposed. */
static const char *const paper_cells[2][2 * N_T] = {
    {"6.9e-3", "1.25", "151.5", "0.0016", "3.66", "2405.8"},
    {"9.375e-4", "0.37", "70.5", "0.0015", "2.57", "2126.5"}};

/* One row's RMS errors: vp[0] velocity [m/s], vp[1] position [m], per T. */
typedef struct {
    double vp[2][N_T];
} rms_t;

typedef struct {
    long duration; /* [s] */
    int draws;     /* per factor */
    unsigned long seed;
    int check;
    const char *traj;
} options_t;

#define PROG "se23-paper-table"

static options_t parse(int argc, char **argv)
{
    options_t o = {600, 200, 1, 0, NULL};
    for (int i = 1; i < argc; ++i) {
        const int more = i + 1 < argc;
        if (!strcmp(argv[i], "--duration") && more) {
            o.duration = strtol(argv[++i], NULL, 10);
        } else if (!strcmp(argv[i], "--draws") && more) {
            o.draws = (int)strtol(argv[++i], NULL, 10);
        } else if (!strcmp(argv[i], "--seed") && more) {
            o.seed = strtoul(argv[++i], NULL, 10);
        } else if (!strcmp(argv[i], "--check")) {
            o.check = 1;
        } else if (!strcmp(argv[i], "--traj") && more) {
            o.traj = argv[++i];
        } else {
            paper_usage(PROG " [--duration S] [--draws N] [--seed N] [--check] [--traj FILE.csv]");
        }
    }
    if (o.duration < 60 || o.draws < 1) {
        fprintf(stderr, PROG ": need --duration >= 60 and --draws >= 1\n");
        exit(2);
    }
    return o;
}

static void draw_bias(int scheme, se23t_rng_t *rng, double db[6])
{
    if (scheme == FIXED) {
        se23_vec3_t g, a;
        se23t_random_axis_angle(rng, BIAS_G, &g);
        se23t_random_axis_angle(rng, BIAS_A, &a);
        for (int i = 0; i < 3; ++i) {
            db[i] = g.v[i];
            db[3 + i] = a.v[i];
        }
    } else {
        for (int i = 0; i < 6; ++i) {
            db[i] = (i < 3 ? BIAS_G : BIAS_A) * se23t_normal(rng);
        }
    }
}

static void write_traj(const char *path, long duration)
{
    FILE *fp = fopen(path, "w");
    if (fp == NULL) {
        perror(path);
        exit(2);
    }
    fprintf(fp, "t,x,y,z\n");
    for (long k = 0; k <= duration * 10; ++k) {
        uav_state_t s;
        uav_state((double)k / 10.0, &s);
        fprintf(fp, "%.1f,%.4f,%.4f,%.4f\n", (double)k / 10.0, s.p[0], s.p[1], s.p[2]);
    }
    fclose(fp);
}

static void print_cells(const char *name, const char *const cells[2 * N_T])
{
    printf("| %-42s |", name);
    for (int c = 0; c < 2 * N_T; ++c) {
        printf(" %9s |", cells[c]);
    }
    printf("\n");
}

static void print_row(const char *name, const rms_t *r)
{
    char buf[2 * N_T][16];
    const char *cells[2 * N_T];
    for (int c = 0; c < 2 * N_T; ++c) {
        snprintf(buf[c], sizeof buf[c], "%.3g", r->vp[c / N_T][c % N_T]);
        cells[c] = buf[c];
    }
    print_cells(name, cells);
}

static void print_table(int scheme, const rms_t rms[N_ROWS])
{
    static const char *const head[2 * N_T] = {"v 1 s", "v 10 s", "v 60 s",
                                               "p 1 s", "p 10 s", "p 60 s"};
    printf("Biases: %s\n", scheme_name[scheme]);
    printf("| RMS error: velocity [m/s], position [m]    |");
    for (int c = 0; c < 2 * N_T; ++c) {
        printf(" %9s |", head[c]);
    }
    printf("\n|%s|", "--------------------------------------------");
    for (int c = 0; c < 2 * N_T; ++c) {
        printf("%s|", "----------:");
    }
    printf("\n");
    print_row(row_name[ROW_FORSTER], &rms[ROW_FORSTER]);
    print_cells("Classical, paper", paper_cells[0]);
    print_row(row_name[ROW_FORSTER_EXACT], &rms[ROW_FORSTER_EXACT]);
    print_row(row_name[ROW_BASIC], &rms[ROW_BASIC]);
    print_cells("Proposed, paper", paper_cells[1]);
    print_row(row_name[ROW_PAPER], &rms[ROW_PAPER]);
    print_row(row_name[ROW_EXACT], &rms[ROW_EXACT]);
    print_row(row_name[ROW_NONE], &rms[ROW_NONE]);
    printf("\n");
}

/* One line of the check on the velocity (vp 0) or position (vp 1) RMS;
 * returns 1 if a > b. */
static int check_le(const char *what, int vp, int t, double a, double b)
{
    const int ok = a <= b;
    printf("%s T = %2d s: %s RMS %s: %.4g %s %.4g\n", ok ? "ok  " : "FAIL", T_sec[t],
           vp ? "position" : "velocity", what, a, ok ? "<=" : ">", b);
    return !ok;
}

/* The check of the file comment, on the rows of one table. */
static int check_order(const rms_t rms[N_ROWS])
{
    int fail = 0;
    for (int t = 0; t < N_T; ++t) {
        fail |= check_le("proposed (basic B_k) <= classical", 0, t, rms[ROW_BASIC].vp[0][t],
                         rms[ROW_FORSTER].vp[0][t]);
    }
    fail |= check_le("exact B_k <= basic", 0, 0, rms[ROW_EXACT].vp[0][0], rms[ROW_BASIC].vp[0][0]);
    fail |= check_le("proposed on eq. backtofuture Deltas <= on exact Deltas", 1, 0,
                     rms[ROW_PAPER].vp[1][0], rms[ROW_BASIC].vp[1][0]);
    return fail;
}

int main(int argc, char **argv)
{
    const options_t o = parse(argc, argv);
    if (o.traj != NULL) {
        write_traj(o.traj, o.duration);
    }
    const long n_all = (long)((double)o.duration * HZ);
    raw_sample_t *wf = malloc(sizeof *wf * (size_t)n_all);
    if (wf == NULL) {
        return 2;
    }
    for (long k = 0; k < n_all; ++k) {
        uav_sample(k, HZ, wf[k].w, wf[k].f);
    }
    se23t_rng_t rng[N_SCHEMES];
    for (int s = 0; s < N_SCHEMES; ++s) {
        se23t_rng_seed(&rng[s], o.seed + (unsigned long)s);
    }
    static row_acc_t acc[N_SCHEMES][N_T][N_ROWS];
    long factors[N_T];
    for (int t = 0; t < N_T; ++t) {
        const long n = (long)(T_sec[t] * HZ);
        factors[t] = o.duration / T_sec[t];
        for (long w = 0; w < factors[t]; ++w) {
            factor_t fa;
            factor_build(&fa, wf + w * n, n, 1.0 / HZ);
            for (int s = 0; s < N_SCHEMES; ++s) {
                for (int d = 0; d < o.draws; ++d) {
                    double db[6];
                    draw_bias(s, &rng[s], db);
                    factor_score(&fa, db, acc[s][t]);
                }
            }
        }
    }
    free(wf);

    printf("UAV trajectory %ld s at %.0f Hz; factors of 1 s / 10 s / 60 s: %ld / %ld / %ld, "
           "%d fresh bias draws each (seed %lu)\n\n",
           o.duration, HZ, factors[0], factors[1], factors[2], o.draws, o.seed);
    rms_t rms[N_SCHEMES][N_ROWS];
    for (int s = 0; s < N_SCHEMES; ++s) {
        for (int r = 0; r < N_ROWS; ++r) {
            for (int t = 0; t < N_T; ++t) {
                const row_acc_t *a = &acc[s][t][r];
                rms[s][r].vp[0][t] = sqrt(a->v2 / (double)a->n);
                rms[s][r].vp[1][t] = sqrt(a->p2 / (double)a->n);
            }
        }
        print_table(s, rms[s]);
    }
    const int fail = check_order(rms[FIXED]);
    return (o.check && fail) ? 1 : 0;
}
