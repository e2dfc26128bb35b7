/* se23-montecarlo: the paper's Figure on Monte Carlo clouds (section 3.4)
 * and a consistency check of the concentrated Gaussian on SE_2(3).
 *
 * Scenario (the Figure's): flat Earth, NED, g = (0, 0, 9.81) m/s^2; the
 * initial extended pose is null and known (R = I, p = 0, Sigma_0 = 0) and
 * the IMU moves nominally to the right (+x) at constant speed, level:
 * nominal samples w = 0, f = (0, 0, -g). Noisy samples add white noise of
 * the given densities (per sample std density / sqrt(dt), the mean of
 * white noise over the sample, as in gauss.h).
 *
 * Three descriptions of the endpoint, compared:
 *   true        `runs` noisy propagations with se23_imu_step (exact for
 *               piecewise-constant samples: the noisy equations nav:eq);
 *   exponential Tbar exp(xi), xi ~ N(0, Sigma): Sigma from the library's
 *               Riccati (paper eq. riccati: se23_gauss_cov_propagate with
 *               F_k and the exact B_k of gauss.h, noise B_k N B_k^T);
 *   EKF         (Rbar exp(dtheta), vbar + dv, pbar + dp), (dtheta, dv, dp)
 *               ~ N(0, P) from the standard EKF of ekf.h.
 * For each: the mean NEES of the true endpoints (xi = log(Tbar^-1 T) for
 * the exponential model; (log(Rbar^T R), v - vbar, p - pbar) for the EKF)
 * against the 95% interval of chi^2_9 for that many runs, and the mean
 * offset of each cloud from pbar (its z component is the banana's bend:
 * a tilted IMU under-compensates gravity). Optionally writes the three
 * endpoint clouds and the nominal trajectory to a CSV for plot_clouds.py.
 * Both linearisations describe the same first-order error: the program
 * prints |G Sigma G^T - P| / |P|, G = diag(I, Rbar, Rbar), which is O(dt)
 * (the EKF's Euler discretisation); the clouds differ by the map back to
 * the state only.
 *
 * Defaults (the Figure): 10 s at 100 Hz, 50 m/s, gyro 0.1 rad/s/sqrt(Hz)
 * per axis (tilt sd 18 deg at the end), accel 0.05 m/s^2/sqrt(Hz).
 *
 * Usage: se23-montecarlo [--runs N] [--duration S] [--rate HZ] [--speed M/S]
 *          [--gyro GX,GY,GZ] [--accel A] [--seed N] [--sweep] [--csv FILE]
 *          [--check]
 * --gyro, --accel: noise densities [rad/s/sqrt(Hz)], [m/s^2/sqrt(Hz)].
 * --sweep: also at 1/4, 1/2 and 2 times the densities.
 * --check: exit 1 unless, at the given densities, the exponential
 *          model's mean NEES is inside the interval and the EKF's above it.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "ekf.h"
#include "gauss_test.h"
#include "paper_tool.h"
#include "se23/earth.h"
#include "se23/gauss.h"
#include "se23/imu.h"
#include "se23/se23.h"
#include "se23/so3.h"
#include "se23_rng.h"

#define G 9.81
#define CLOUD_MAX 3000 /* points per cloud written to the CSV */

typedef struct {
    long runs;
    double duration, rate, speed, gyro[3], accel;
    unsigned long seed;
    int sweep, check;
    const char *csv;
} options_t;

typedef struct {
    double nees_exp, nees_ekf, lo, hi;
    double tilt_sd;                   /* sqrt(Sigma_phi_x) [rad] */
    double off[3][3];                 /* mean p - pbar: true, exponential, EKF [m] */
    double lin_diff;                  /* |G Sigma G^T - P| / |P| */
} result_t;

#define PROG "se23-montecarlo"

static void usage(void)
{
    paper_usage(PROG " [--runs N] [--duration S] [--rate HZ] [--speed M/S] "
                "[--gyro GX,GY,GZ] [--accel A] [--seed N] [--sweep] [--csv FILE] [--check]");
}

static options_t parse(int argc, char **argv)
{
    options_t o = {2000, 10.0, 100.0, 50.0, {0.1, 0.1, 0.1}, 0.05, 1, 0, 0, NULL};
    for (int i = 1; i < argc; ++i) {
        const int more = i + 1 < argc;
        if (!strcmp(argv[i], "--runs") && more) {
            o.runs = strtol(argv[++i], NULL, 10);
        } else if (!strcmp(argv[i], "--duration") && more) {
            o.duration = strtod(argv[++i], NULL);
        } else if (!strcmp(argv[i], "--rate") && more) {
            o.rate = strtod(argv[++i], NULL);
        } else if (!strcmp(argv[i], "--speed") && more) {
            o.speed = strtod(argv[++i], NULL);
        } else if (!strcmp(argv[i], "--gyro") && more) {
            if (sscanf(argv[++i], "%lf,%lf,%lf", &o.gyro[0], &o.gyro[1], &o.gyro[2]) != 3) {
                usage();
            }
        } else if (!strcmp(argv[i], "--accel") && more) {
            o.accel = strtod(argv[++i], NULL);
        } else if (!strcmp(argv[i], "--seed") && more) {
            o.seed = strtoul(argv[++i], NULL, 10);
        } else if (!strcmp(argv[i], "--sweep")) {
            o.sweep = 1;
        } else if (!strcmp(argv[i], "--check")) {
            o.check = 1;
        } else if (!strcmp(argv[i], "--csv") && more) {
            o.csv = argv[++i];
        } else {
            usage();
        }
    }
    if (o.runs < 10 || !(o.duration > 0) || !(o.rate > 0) || !(o.gyro[0] > 0) ||
        !(o.gyro[1] > 0) || !(o.gyro[2] > 0) || !(o.accel > 0)) {
        fprintf(stderr, "se23-montecarlo: need runs >= 10 and positive durations, rates, "
                        "densities\n");
        exit(2);
    }
    return o;
}

/* Nominal sample (level, constant velocity) plus noise of per-sample std
 * sd (rng NULL: none). */
static se23_imu_sample_t sample(se23t_rng_t *rng, const double sd[6], double dt)
{
    se23_imu_sample_t s = {{{0, 0, 0}}, {{0, 0, -G}}, dt};
    for (int i = 0; rng != NULL && i < 3; ++i) {
        s.w_ib_b.v[i] += sd[i] * se23t_normal(rng);
        s.f_b.v[i] += sd[3 + i] * se23t_normal(rng);
    }
    return s;
}

/* Q = B diag(n) B^T, n = the per-sample noise variances (gyro x3, accel x3). */
static void input_noise(const se23_mat9x6_t *B, const double n[6], se23_mat9_t *Q)
{
    for (int i = 0; i < 9; ++i) {
        for (int j = 0; j < 9; ++j) {
            double s = 0;
            for (int k = 0; k < 6; ++k) {
                s += B->m[6 * i + k] * n[k] * B->m[6 * j + k];
            }
            Q->m[9 * i + j] = s;
        }
    }
}

static void initial_pose(const options_t *o, se23_pose_t *T)
{
    se23_identity(T);
    T->v.v[0] = o->speed;
}

/* The mean, Sigma (library Riccati) and the EKF P at the endpoint. */
static void nominal(const options_t *o, const se23_earth_model_t *model, const double qg[3],
                    double qa, se23_pose_t *Tbar, se23_mat9_t *Sigma, ekf_t *ekf)
{
    const double dt = 1.0 / o->rate;
    const double n[6] = {qg[0] / dt, qg[1] / dt, qg[2] / dt, qa / dt, qa / dt, qa / dt};
    const long steps = lround(o->duration * o->rate);
    initial_pose(o, Tbar);
    memset(Sigma, 0, sizeof *Sigma);
    memset(ekf, 0, sizeof *ekf);
    for (long k = 0; k < steps; ++k) {
        const se23_imu_sample_t s = sample(NULL, NULL, dt);
        se23_pose_t U;
        se23_mat9x6_t B;
        se23_mat9_t Q;
        se23_status_t st = se23_imu_increment(&s, &U);
        if (st == SE23_OK) {
            st = se23_gauss_input_jac(SE23_INPUT_JAC_EXACT, &s.w_ib_b, &s.f_b, s.dt, &B);
        }
        if (st == SE23_OK) {
            input_noise(&B, n, &Q);
            st = se23_gauss_cov_propagate(Sigma, &U, s.dt, &Q, Sigma);
        }
        ekf_propagate(ekf, Tbar->R.m, s.w_ib_b.v, s.f_b.v, dt, qg, qa);
        if (st == SE23_OK) {
            st = se23_imu_step(model, Tbar, &s, Tbar);
        }
        if (st != SE23_OK) {
            paper_die(PROG, "nominal propagation", st);
        }
    }
}

/* |G Sigma G^T - P| / |P| (max norms), G = diag(I, Rbar, Rbar): the two
 * linearisations describe the same first-order error. */
static double linear_diff(const se23_pose_t *Tbar, const se23_mat9_t *Sigma, const ekf_t *ekf)
{
    double Gm[81] = {0}, err = 0, scale = 0;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            Gm[9 * i + j] = (i == j);
            Gm[9 * (3 + i) + 3 + j] = Tbar->R.m[i][j];
            Gm[9 * (6 + i) + 6 + j] = Tbar->R.m[i][j];
        }
    }
    for (int i = 0; i < 9; ++i) {
        for (int j = 0; j < 9; ++j) {
            double s = 0;
            for (int a = 0; a < 9; ++a) {
                for (int b = 0; b < 9; ++b) {
                    s += Gm[9 * i + a] * Sigma->m[9 * a + b] * Gm[9 * j + b];
                }
            }
            err = fmax(err, fabs(s - ekf->P[9 * i + j]));
            scale = fmax(scale, fabs(ekf->P[9 * i + j]));
        }
    }
    return err / scale;
}

/* EKF error of T against Tbar: (log(Rbar^T R), v - vbar, p - pbar). */
static void ekf_error(const se23_pose_t *Tbar, const se23_pose_t *T, double e[9])
{
    se23_mat3_t D;
    se23_vec3_t phi;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double s = 0;
            for (int k = 0; k < 3; ++k) {
                s += Tbar->R.m[k][i] * T->R.m[k][j];
            }
            D.m[i][j] = s;
        }
    }
    const se23_status_t st = se23_so3_log(&D, &phi);
    if (st != SE23_OK) {
        paper_die(PROG, "se23_so3_log", st);
    }
    for (int i = 0; i < 3; ++i) {
        e[i] = phi.v[i];
        e[3 + i] = T->v.v[i] - Tbar->v.v[i];
        e[6 + i] = T->p.v[i] - Tbar->p.v[i];
    }
}

static void write_point(FILE *fp, const char *kind, const se23_vec3_t *p)
{
    if (fp != NULL) {
        fprintf(fp, "%s,%.6f,%.6f,%.6f\n", kind, p->v[0], p->v[1], p->v[2]);
    }
}

static result_t run(const options_t *o, double scale, FILE *csv)
{
    const double dt = 1.0 / o->rate;
    se23_earth_model_t model;
    const se23_vec3_t g_n = {{0, 0, G}}, zero = {{0, 0, 0}};
    se23_status_t st = se23_earth_model_init(&g_n, &zero, dt, dt, &model);
    if (st != SE23_OK) {
        paper_die(PROG, "se23_earth_model_init", st);
    }
    double qg[3], sd[6];
    const double qa = scale * scale * o->accel * o->accel;
    for (int i = 0; i < 3; ++i) {
        qg[i] = scale * scale * o->gyro[i] * o->gyro[i];
        sd[i] = sqrt(qg[i] / dt);
        sd[3 + i] = sqrt(qa / dt);
    }
    se23_pose_t Tbar;
    se23_mat9_t Sigma;
    ekf_t ekf;
    nominal(o, &model, qg, qa, &Tbar, &Sigma, &ekf);
    result_t r;
    r.tilt_sd = sqrt(Sigma.m[0]);
    r.lin_diff = linear_diff(&Tbar, &Sigma, &ekf);
    double Ls[81], Le[81];
    if (!gt_chol(Sigma.m, 9, Ls) || !gt_chol(ekf.P, 9, Le)) {
        fprintf(stderr, "se23-montecarlo: a covariance is not positive definite\n");
        exit(2);
    }
    se23t_rng_t rng;
    se23t_rng_seed(&rng, o->seed);
    se23_pose_t Tinv;
    se23_inverse(&Tbar, &Tinv);
    const long steps = lround(o->duration * o->rate);
    double sum_exp = 0, sum_ekf = 0;
    memset(r.off, 0, sizeof r.off);
    for (long run_i = 0; run_i < o->runs; ++run_i) {
        se23_pose_t T;
        initial_pose(o, &T);
        for (long k = 0; k < steps; ++k) {
            const se23_imu_sample_t s = sample(&rng, sd, dt);
            st = se23_imu_step(&model, &T, &s, &T);
            if (st != SE23_OK) {
                paper_die(PROG, "se23_imu_step", st);
            }
        }
        se23_pose_t E;
        se23_tangent_t xi;
        se23_compose(&Tinv, &T, &E);
        st = se23_log(&E, &xi);
        if (st != SE23_OK) {
            paper_die(PROG, "se23_log", st);
        }
        double e[9];
        ekf_error(&Tbar, &T, e);
        sum_exp += gt_nees(Ls, 9, xi.v);
        sum_ekf += gt_nees(Le, 9, e);
        for (int k = 0; k < 3; ++k) {
            r.off[0][k] += (T.p.v[k] - Tbar.p.v[k]) / (double)o->runs;
        }
        if (run_i < CLOUD_MAX) {
            write_point(csv, "true", &T.p);
        }
    }
    r.nees_exp = sum_exp / (double)o->runs;
    r.nees_ekf = sum_ekf / (double)o->runs;
    gt_chi2_mean_interval(9, (int)o->runs, &r.lo, &r.hi);
    /* The two models' clouds, from their own samples. */
    for (long i = 0; i < o->runs; ++i) {
        double x[9];
        se23_tangent_t xi;
        se23_pose_t E, T;
        gt_sample(&rng, Ls, 9, x);
        memcpy(xi.v, x, sizeof x);
        st = se23_exp(&xi, &E);
        if (st != SE23_OK) {
            paper_die(PROG, "se23_exp", st);
        }
        se23_compose(&Tbar, &E, &T);
        gt_sample(&rng, Le, 9, x);
        se23_vec3_t p = Tbar.p;
        for (int k = 0; k < 3; ++k) {
            p.v[k] += x[6 + k];
            r.off[1][k] += (T.p.v[k] - Tbar.p.v[k]) / (double)o->runs;
            r.off[2][k] += x[6 + k] / (double)o->runs;
        }
        if (i < CLOUD_MAX) {
            write_point(csv, "exponential", &T.p);
            write_point(csv, "ekf", &p);
        }
    }
    return r;
}

static void write_nominal(const options_t *o, FILE *fp)
{
    for (int k = 0; k <= 100; ++k) {
        const se23_vec3_t p = {{o->speed * o->duration * k / 100.0, 0, 0}};
        write_point(fp, "nominal", &p);
    }
}

int main(int argc, char **argv)
{
    const options_t o = parse(argc, argv);
    FILE *csv = NULL;
    if (o.csv != NULL) {
        csv = fopen(o.csv, "w");
        if (csv == NULL) {
            perror(o.csv);
            return 2;
        }
        fprintf(csv, "kind,x,y,z\n");
        write_nominal(&o, csv);
    }
    printf("%ld runs of %.1f s at %.0f Hz, %.1f m/s along +x, level; noise densities gyro "
           "(%g, %g, %g) rad/s/sqrt(Hz), accel %g m/s^2/sqrt(Hz), times `scale`\n\n",
           o.runs, o.duration, o.rate, o.speed, o.gyro[0], o.gyro[1], o.gyro[2], o.accel);
    printf("| scale | tilt sd [deg] | mean NEES exponential | mean NEES EKF | 95%% interval "
           "| mean offset (x, z) true / exponential / EKF [m] | |G S G^T - P|/|P| |\n");
    printf("|---|---|---|---|---|---|---|\n");
    const double scales[4] = {1.0, 0.25, 0.5, 2.0};
    int fail = 0;
    for (int i = 0; i < (o.sweep ? 4 : 1); ++i) {
        const result_t r = run(&o, scales[i], i == 0 ? csv : NULL);
        printf("| %.2f | %.1f | %.3f | %.3f | [%.3f, %.3f] | (%.2f, %.2f) / (%.2f, %.2f) / "
               "(%.2f, %.2f) | %.1e |\n",
               scales[i], r.tilt_sd * 180.0 / 3.14159265358979323846, r.nees_exp, r.nees_ekf,
               r.lo, r.hi, r.off[0][0], r.off[0][2], r.off[1][0], r.off[1][2], r.off[2][0],
               r.off[2][2], r.lin_diff);
        if (i == 0) {
            fail = !(r.nees_exp > r.lo && r.nees_exp < r.hi && r.nees_ekf > r.hi);
        }
    }
    if (csv != NULL) {
        fclose(csv);
    }
    if (o.check) {
        printf("%s: at scale 1, the exponential model's mean NEES must be inside the 95%% "
               "interval and the EKF's above it\n", fail ? "FAIL" : "ok");
    }
    return (o.check && fail) ? 1 : 0;
}
