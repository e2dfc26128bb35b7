/* Accuracy of IMU propagation in the build's precision (compiled once per
 * precision, linked with that build of the library): position and velocity
 * errors after 60 s and 1 h against a long-double truth, for a MEMS-grade
 * and a navigation-grade scenario with the Earth rate, with the exact
 * increment (se23_imu_step) and with three first-order increments on the
 * same samples: Forster et al.'s (se23_imu_increment_forster, f dt^2/2, the
 * paper's remark after eq. discrete2 with its 1/2 restored), that remark as
 * printed (f dt^2) and the paper's eq. backtofuture (se23_imu_increment_paper,
 * position 0). Prints markdown table rows; `accuracy header` prints the header
 * first. Run both builds with `make accuracy` (tools/accuracy/accuracy.mk).
 *
 * Every run sees the same samples, rounded to the build's precision, and the
 * truth integrates these rounded samples (and the rounded g, Omega, dt and
 * initial state), so the errors are those of the library's arithmetic and of
 * the increment, not of the input rounding. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "scenario.h"
#include "se23/earth.h"
#include "se23/imu.h"
#include "se23/preint.h"
#include "truth.h"

#define PRECISION (SE23_CFG_DOUBLE ? "double" : "float")

/* The propagations compared with the truth. FACTORS applies the samples
 * through preintegrated factors of FACTOR_HZ^-1 s (se23_preint_add, then
 * se23_preint_predict_carried on the state), the float remedy of
 * tools/doc/pages/propagation.md. */
enum { EXACT, FACTORS, FORSTER, REMARK_PRINTED, PAPER, SENSOR_FREE, N_RUNS };
static const char *const run_name[N_RUNS] = {
    "exact (se23_imu_step)", "exact, through 0.25 s factors (se23_preint)",
    "Forster et al., f dt^2/2 (se23_imu_increment_forster)",
    "paper's remark as printed, f dt^2 (no 1/2)",
    "paper's eq. backtofuture, position 0 (se23_imu_increment_paper)",
    "exact, error-free samples"};
#define FACTOR_HZ 4

#define N_CHECK 2
static const long check_seconds[N_CHECK] = {60, 3600};

typedef struct {
    double pos[N_CHECK]; /* |p - p_truth| [m] */
    double vel[N_CHECK]; /* |v - v_truth| [m/s] */
    double att[N_CHECK]; /* rotation angle of R R_truth^T [rad] */
} errors_t;

static void die(const char *what, se23_status_t st)
{
    fprintf(stderr, "accuracy: %s failed: %s\n", what, se23_status_str(st));
    exit(1);
}

static void to_real3(const ld x[3], se23_vec3_t *out, ld rounded[3])
{
    for (int i = 0; i < 3; ++i) {
        out->v[i] = (se23_real_t)x[i];
        rounded[i] = out->v[i];
    }
}

/* The user's (R, v, p) of the library's carried state against the truth's. */
static void compare(const se23_earth_model_t *m, const se23_pose_t *Tc, const acc_pose_t *truth_c,
                    const ld omega[3], errors_t *e, int at)
{
    se23_pose_t U;
    se23_imu_user_from_carried(m, Tc, &U);
    acc_pose_t t = *truth_c;
    acc_truth_shift(omega, -1, &t);
    ld dp = 0, dv = 0;
    for (int i = 0; i < 3; ++i) {
        dp += ((ld)U.p.v[i] - t.p[i]) * ((ld)U.p.v[i] - t.p[i]);
        dv += ((ld)U.v.v[i] - t.v[i]) * ((ld)U.v.v[i] - t.v[i]);
    }
    e->pos[at] = (double)sqrtl(dp);
    e->vel[at] = (double)sqrtl(dv);
    /* Small angle: |vee of the skew part of R R_truth^T|. */
    ld D[3][3];
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            D[i][j] = 0;
            for (int k = 0; k < 3; ++k) {
                D[i][j] += (ld)U.R.m[i][k] * t.R[j][k];
            }
        }
    }
    const ld a0 = (D[2][1] - D[1][2]) / 2, a1 = (D[0][2] - D[2][0]) / 2, a2 = (D[1][0] - D[0][1]) / 2;
    e->att[at] = (double)sqrtl(a0 * a0 + a1 * a1 + a2 * a2);
}

/* One step of the first-order increment of run r (FORSTER, REMARK_PRINTED
 * or PAPER): the remark as printed is Forster's increment with the position
 * doubled. */
static void first_order_step(const se23_earth_model_t *m, const se23_imu_sample_t *s, int r,
                             se23_pose_t *Tc)
{
    se23_pose_t u;
    const se23_status_t st =
        r == PAPER ? se23_imu_increment_paper(s, &u) : se23_imu_increment_forster(s, &u);
    if (st != SE23_OK) {
        die(run_name[r], st);
    }
    if (r == REMARK_PRINTED) {
        for (int i = 0; i < 3; ++i) {
            u.p.v[i] *= SE23_R(2);
        }
    }
    se23_imu_transition(&m->gamma, Tc, &u, s->dt, Tc);
}

static void run_scenario(const acc_grade_t *gr, errors_t err[N_RUNS], double *p_norm)
{
    ld g_l[3], om_l[3], g[3], om[3];
    se23_vec3_t g_c, om_c;
    acc_earth(g_l, om_l);
    to_real3(g_l, &g_c, g);
    to_real3(om_l, &om_c, om);
    const se23_real_t dt_c = (se23_real_t)(1 / gr->rate_hz);
    const ld dt = dt_c;
    se23_earth_model_t m;
    se23_status_t st = se23_earth_model_init(&g_c, &om_c, dt_c, dt_c, &m);
    if (st != SE23_OK) {
        die("se23_earth_model_init", st);
    }
    acc_pose_t G, truth;
    acc_truth_gamma(g, om, dt, &G);

    /* Initial state on the designed motion, rounded; then carried. */
    ld R0[3][3], v0[3], p0[3];
    acc_motion_state(&gr->motion, 0, R0, v0, p0);
    se23_pose_t U0;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            U0.R.m[i][j] = (se23_real_t)R0[i][j];
            truth.R[i][j] = U0.R.m[i][j];
        }
    }
    to_real3(v0, &U0.v, truth.v);
    to_real3(p0, &U0.p, truth.p);
    acc_truth_shift(om, 1, &truth);
    se23_pose_t Tc[N_RUNS];
    se23_imu_carried_from_user(&m, &U0, &Tc[0]);
    for (int r = 1; r < N_RUNS; ++r) {
        Tc[r] = Tc[0];
    }

    acc_sensor_t sensor;
    acc_sensor_init(&sensor, gr, 0x5e23acc0ULL + (uint64_t)gr->rate_hz);
    const long n_total = (long)(check_seconds[N_CHECK - 1] * gr->rate_hz + 0.5L);
    const long per_factor = (long)(gr->rate_hz / FACTOR_HZ + 0.5L);
    se23_preint_t factor;
    se23_preint_reset(&factor);
    int next = 0;
    for (long k = 0; k < n_total; ++k) {
        ld w[3], f[3], wm[3], fm[3], wm_r[3], fm_r[3], dummy[3];
        acc_sample(&sensor, k, w, f, wm, fm);
        se23_imu_sample_t s, s_free;
        to_real3(wm, &s.w_ib_b, wm_r);
        to_real3(fm, &s.f_b, fm_r);
        to_real3(w, &s_free.w_ib_b, dummy);
        to_real3(f, &s_free.f_b, dummy);
        s.dt = s_free.dt = dt_c;

        acc_truth_step(&G, wm_r, fm_r, dt, &truth);
        if ((st = se23_imu_step(&m, &Tc[EXACT], &s, &Tc[EXACT])) != SE23_OK ||
            (st = se23_imu_step(&m, &Tc[SENSOR_FREE], &s_free, &Tc[SENSOR_FREE])) != SE23_OK) {
            die("se23_imu_step", st);
        }
        for (int r = FORSTER; r <= PAPER; ++r) {
            first_order_step(&m, &s, r, &Tc[r]);
        }
        if ((st = se23_preint_add(&factor, &s)) != SE23_OK) {
            die("se23_preint_add", st);
        }
        if ((k + 1) % per_factor == 0) { /* the checkpoints fall on factor ends */
            if ((st = se23_preint_predict_carried(&m, &factor, &Tc[FACTORS], &Tc[FACTORS])) != SE23_OK) {
                die("se23_preint_predict_carried", st);
            }
            se23_preint_reset(&factor);
        }

        if (k + 1 == (long)(check_seconds[next] * gr->rate_hz + 0.5L)) {
            for (int r = 0; r < N_RUNS; ++r) {
                compare(&m, &Tc[r], &truth, om, &err[r], next);
            }
            acc_pose_t t = truth;
            acc_truth_shift(om, -1, &t);
            p_norm[next] = (double)sqrtl(t.p[0] * t.p[0] + t.p[1] * t.p[1] + t.p[2] * t.p[2]);
            ++next;
        }
    }
}

int main(int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "header") == 0) {
        printf("| scenario | build | increment | pos. error 60 s [m] | pos. error 1 h [m] "
               "| vel. error 1 h [m/s] | att. error 1 h [rad] |\n");
        printf("|---|---|---|---:|---:|---:|---:|\n");
    }
    for (int sc = 0; sc < 2; ++sc) {
        errors_t err[N_RUNS];
        double p_norm[N_CHECK];
        run_scenario(&acc_grades[sc], err, p_norm);
        for (int r = 0; r < N_RUNS; ++r) {
            if (r == SENSOR_FREE) {
                /* Its difference to the truth is what the sensor's bias and
                 * noise do (the double build's own error is far below). */
                if (SE23_CFG_DOUBLE) {
                    printf("| %s | (sensor errors) | drift caused by the sensor's bias and noise "
                           "| %.3g | %.3g | %.3g | %.3g |\n",
                           acc_grades[sc].name, err[r].pos[0], err[r].pos[1], err[r].vel[1],
                           err[r].att[1]);
                }
                continue;
            }
            printf("| %s | %s | %s | %.3g | %.3g | %.3g | %.3g |\n", acc_grades[sc].name,
                   PRECISION, run_name[r], err[r].pos[0], err[r].pos[1], err[r].vel[1],
                   err[r].att[1]);
        }
        if (SE23_CFG_DOUBLE) {
            printf("| %s | (scale) | distance from the origin | %.4g | %.4g | | |\n",
                   acc_grades[sc].name, p_norm[0], p_norm[1]);
        }
        fflush(stdout);
    }
    return 0;
}
