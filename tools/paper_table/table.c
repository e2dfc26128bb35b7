/* se23-paper-table: reproduces the paper's Table "Higher-order errors for a
 * low-cost IMU (1 deg/s - 100 mg)" (section 4.2).
 *
 * The smooth 3D UAV trajectory of uav.h is sampled at 100 Hz. Its samples
 * are cut into consecutive preintegrated factors of T = 1 s, 10 s and 60 s,
 * each integrated once at the bias estimate bbar = 0 (se23_preint_unc_add,
 * once with the exact input matrix B_k and once with the paper's basic
 * dt I_{9,6}). Then, for each of `draws` random biases db (per axis
 * N(0, (1 deg/s)^2) gyro and N(0, (100 mg)^2) accelerometer), every factor
 * is re-integrated from the samples plus db (se23_preint_add) and compared
 * with its three first-order corrections to bhat = db:
 *   classical  Forster et al. 2017 (se23_preint_unc_correct_classic)
 *   basic      Delta exp(J db), J with B_k = dt I_{9,6} (paper eq. biascor)
 *   exact      Delta exp(J db), J with the exact B_k (DESIGN.md)
 * The velocity (position) RMS is sqrt(mean |DV_corr - DV_reint|^2) (resp.
 * DX) over every factor and draw. The paper's numbers are printed under
 * ours. With --check the program fails unless the exact correction is no
 * worse than the classical one in velocity RMS at every T.
 *
 * Usage: se23-paper-table [--duration S] [--draws N] [--seed N] [--check]
 *                         [--traj FILE.csv]
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../montecarlo/paper_tool.h"
#include "se23/preint.h"
#include "se23/preint_unc.h"
#include "se23_rng.h"
#include "uav.h"

#define HZ 100.0
#define PI 3.14159265358979323846
#define SIGMA_G (PI / 180.0)      /* 1 deg/s [rad/s] */
#define SIGMA_A (0.1 * 9.80665)   /* 100 mg [m/s^2] */

enum { CLASSIC, BASIC, EXACT, NONE, N_METHODS };
static const char *const method_name[N_METHODS] = {
    "Classical (Forster et al.), this run",
    "Exponential, basic B_k = dt I_{9,6}, this run",
    "Exponential, exact B_k, this run",
    "No correction, this run"};

#define N_T 3
static const int T_sec[N_T] = {1, 10, 60};
/* The paper's Table: velocity RMS [m/s] and position RMS [m] at T = 1, 10,
 * 60 s; "Proposed" is the exponential correction (basic B_k). */
static const double paper_v[2][N_T] = {{6.9e-3, 1.25, 151.5}, {9.375e-4, 0.37, 70.5}};
static const double paper_p[2][N_T] = {{0.0016, 3.66, 2405.8}, {0.0015, 2.57, 2126.5}};

typedef struct {
    double v2, p2; /* sums of squared errors */
    long n;
} acc_t;

typedef struct {
    long duration; /* [s] */
    int draws;
    unsigned long seed;
    int check;
    const char *traj;
} options_t;

#define PROG "se23-paper-table"

static void usage(void)
{
    paper_usage(PROG " [--duration S] [--draws N] [--seed N] [--check] [--traj FILE.csv]");
}

static options_t parse(int argc, char **argv)
{
    options_t o = {600, 50, 1, 0, NULL};
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
            usage();
        }
    }
    if (o.duration < 60 || o.draws < 1) {
        fprintf(stderr, "se23-paper-table: need --duration >= 60 and --draws >= 1\n");
        exit(2);
    }
    return o;
}

/* Sample k of the trajectory plus the bias change (dbg, dba). */
static se23_imu_sample_t sample(long k, const double db[6])
{
    double w[3], f[3];
    uav_sample(k, HZ, w, f);
    se23_imu_sample_t s;
    for (int i = 0; i < 3; ++i) {
        s.w_ib_b.v[i] = w[i] + db[i];
        s.f_b.v[i] = f[i] + db[3 + i];
    }
    s.dt = 1.0 / HZ;
    return s;
}

static void add_error(acc_t *a, const se23_pose_t *approx, const se23_pose_t *ref)
{
    for (int i = 0; i < 3; ++i) {
        const double ev = approx->v.v[i] - ref->v.v[i];
        const double ep = approx->p.v[i] - ref->p.v[i];
        a->v2 += ev * ev;
        a->p2 += ep * ep;
    }
    a->n += 1;
}

/* The factors of T seconds at bbar = 0, with the exact (ex) and basic (ba)
 * input matrices; nwin factors of n samples. */
static void build_factors(long n, long nwin, se23_preint_unc_t *ex, se23_preint_unc_t *ba)
{
    const se23_vec3_t zero = {{0, 0, 0}};
    const se23_imu_noise_t quiet = {0, 0, 0, 0};
    const double no_bias[6] = {0};
    for (long w = 0; w < nwin; ++w) {
        se23_status_t st = se23_preint_unc_reset(&zero, &zero, SE23_INPUT_JAC_EXACT, &ex[w]);
        if (st == SE23_OK) {
            st = se23_preint_unc_reset(&zero, &zero, SE23_INPUT_JAC_BASIC, &ba[w]);
        }
        for (long k = 0; k < n && st == SE23_OK; ++k) {
            const se23_imu_sample_t s = sample(w * n + k, no_bias);
            st = se23_preint_unc_add(&ex[w], &s, &quiet);
            if (st == SE23_OK) {
                st = se23_preint_unc_add(&ba[w], &s, &quiet);
            }
        }
        if (st != SE23_OK) {
            paper_die(PROG, "se23_preint_unc_add", st);
        }
    }
}

/* Errors of the corrections of every factor of T seconds to the bias change
 * db, against re-integration. */
static void score(long n, long nwin, const se23_preint_unc_t *ex,
                  const se23_preint_unc_t *ba, const double db[6], acc_t acc[N_METHODS])
{
    const se23_vec3_t bg = {{db[0], db[1], db[2]}}, bacc = {{db[3], db[4], db[5]}};
    for (long w = 0; w < nwin; ++w) {
        se23_preint_t ref, corr[N_METHODS];
        se23_preint_reset(&ref);
        se23_status_t st = SE23_OK;
        for (long k = 0; k < n && st == SE23_OK; ++k) {
            const se23_imu_sample_t s = sample(w * n + k, db);
            st = se23_preint_add(&ref, &s);
        }
        if (st == SE23_OK) {
            st = se23_preint_unc_correct_classic(&ex[w], &bg, &bacc, &corr[CLASSIC]);
        }
        if (st == SE23_OK) {
            st = se23_preint_unc_correct(&ba[w], &bg, &bacc, &corr[BASIC]);
        }
        if (st == SE23_OK) {
            st = se23_preint_unc_correct(&ex[w], &bg, &bacc, &corr[EXACT]);
        }
        if (st != SE23_OK) {
            paper_die(PROG, "re-integration or correction", st);
        }
        corr[NONE] = ex[w].f;
        for (int m = 0; m < N_METHODS; ++m) {
            add_error(&acc[m], &corr[m].delta, &ref.delta);
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

static void print_row(const char *name, const double v[N_T], const double p[N_T])
{
    printf("| %-46s |", name);
    for (int t = 0; t < N_T; ++t) {
        printf(" %9.3g |", v[t]);
    }
    for (int t = 0; t < N_T; ++t) {
        printf(" %9.3g |", p[t]);
    }
    printf("\n");
}

int main(int argc, char **argv)
{
    const options_t o = parse(argc, argv);
    if (o.traj != NULL) {
        write_traj(o.traj, o.duration);
    }
    double (*db)[6] = malloc(sizeof(double[6]) * (size_t)o.draws);
    if (db == NULL) {
        return 2;
    }
    se23t_rng_t rng; /* the tests' seeded generator (tests/support) */
    se23t_rng_seed(&rng, o.seed);
    for (int d = 0; d < o.draws; ++d) {
        for (int i = 0; i < 6; ++i) {
            db[d][i] = (i < 3 ? SIGMA_G : SIGMA_A) * se23t_normal(&rng);
        }
    }
    double v[N_METHODS][N_T], p[N_METHODS][N_T];
    long factors[N_T];
    for (int t = 0; t < N_T; ++t) {
        const long n = (long)(T_sec[t] * HZ), nwin = o.duration / T_sec[t];
        se23_preint_unc_t *ex = malloc(sizeof *ex * (size_t)nwin);
        se23_preint_unc_t *ba = malloc(sizeof *ba * (size_t)nwin);
        if (ex == NULL || ba == NULL) {
            return 2;
        }
        build_factors(n, nwin, ex, ba);
        acc_t acc[N_METHODS];
        memset(acc, 0, sizeof acc);
        for (int d = 0; d < o.draws; ++d) {
            score(n, nwin, ex, ba, db[d], acc);
        }
        for (int m = 0; m < N_METHODS; ++m) {
            v[m][t] = sqrt(acc[m].v2 / (double)acc[m].n);
            p[m][t] = sqrt(acc[m].p2 / (double)acc[m].n);
        }
        factors[t] = nwin;
        free(ex);
        free(ba);
    }
    free(db);

    printf("UAV trajectory %ld s at %.0f Hz, %d bias draws (seed %lu), factors of "
           "1 s / 10 s / 60 s: %ld / %ld / %ld\n\n",
           o.duration, HZ, o.draws, o.seed, factors[0], factors[1], factors[2]);
    printf("| %-46s | velocity RMS [m/s]            | position RMS [m]              |\n", "");
    printf("| %-46s | %9s | %9s | %9s | %9s | %9s | %9s |\n", "T", "1 s", "10 s", "60 s",
           "1 s", "10 s", "60 s");
    printf("|%s|-----------|-----------|-----------|-----------|-----------|-----------|\n",
           "------------------------------------------------");
    print_row(method_name[CLASSIC], v[CLASSIC], p[CLASSIC]);
    print_row("Classical, paper", paper_v[0], paper_p[0]);
    print_row(method_name[BASIC], v[BASIC], p[BASIC]);
    print_row(method_name[EXACT], v[EXACT], p[EXACT]);
    print_row("Proposed (exponential), paper", paper_v[1], paper_p[1]);
    print_row(method_name[NONE], v[NONE], p[NONE]);

    int fail = 0;
    for (int t = 0; t < N_T; ++t) {
        const int ok = v[EXACT][t] <= v[CLASSIC][t];
        printf("%s T = %2d s: velocity RMS exact %.4g %s classical %.4g\n", ok ? "ok  " : "FAIL",
               T_sec[t], v[EXACT][t], ok ? "<=" : ">", v[CLASSIC][t]);
        fail |= !ok;
    }
    return (o.check && fail) ? 1 : 0;
}
