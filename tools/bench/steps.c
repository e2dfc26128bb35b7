/* The composite steps of the benchmark, library and reference side by side;
 * see steps.h. Rotating Earth, exact input matrix B, 200 Hz samples. */
#include "steps.h"

#include <math.h>
#include <stddef.h>

#include "ref.h"
#include "ring.h"
#include "se23/kalman.h"

static bench_ring_t ring;
/* The ring's model with the reference's own Gamma'(dt). */
static se23_earth_model_t ref_model;
/* Outputs; the steps that produce a state share them. */
static se23_gauss_t out_se23[BENCH_RING], out_eigen[BENCH_RING];
static se23_preint_unc_t fu_se23[BENCH_RING], fu_eigen[BENCH_RING];

int bench_steps_prepare(void)
{
    const int st = bench_ring_fill(&ring);
    ref_model = ring.model;
    ref_gamma(&ring.model.g_n, &ring.model.w_ie_n, ring.model.dt, &ref_model.gamma);
    return st;
}

/* ---- the calls ---------------------------------------------------------- */

static int se23_predict(const se23_gauss_t *g, int i)
{
    return (int)se23_gauss_predict(&ring.model, g, &ring.s[i], &ring.noise,
                                   SE23_INPUT_JAC_EXACT, &out_se23[i]);
}
static int eigen_predict(const se23_gauss_t *g, int i)
{
    ref_gauss_predict(&ref_model, g, &ring.s[i], &ring.noise, &out_eigen[i]);
    return 0;
}
static int se23_predict_n9(int i) { return se23_predict(&ring.g9[i], i); }
static int eigen_predict_n9(int i) { return eigen_predict(&ring.g9[i], i); }
static int se23_predict_n15(int i) { return se23_predict(&ring.g15[i], i); }
static int eigen_predict_n15(int i) { return eigen_predict(&ring.g15[i], i); }

/* The library adds in place: start from a copy of entry i. */
static int se23_preint(int i)
{
    fu_se23[i] = ring.fu[i];
    return (int)se23_preint_unc_add(&fu_se23[i], &ring.s[i], &ring.noise);
}
static int eigen_preint(int i)
{
    ref_preint_add(&ring.fu[i], &ring.s[i], &ring.noise, &fu_eigen[i]);
    return 0;
}

static int se23_gnss(int i)
{
    se23_meas_t y;
    se23_status_t st = se23_meas_pos_nav(&ring.g15[i].T, &ring.gnss_p[i], &ring.lever_b,
                                         &ring.gnss_cov, &y);
    if (st == SE23_OK) {
        st = se23_kalman_update(&ring.g15[i], &y, &out_se23[i], NULL);
    }
    return (int)st;
}
static int eigen_gnss(int i)
{
    return ref_gnss_update(&ring.g15[i], &ring.gnss_p[i], &ring.lever_b, &ring.gnss_cov,
                           &out_eigen[i]);
}

/* ---- diff: relative differences, by block ------------------------------- */

/* max |a - b| / max |b| over a rows x cols block with row stride. */
static double block_diff(const se23_real_t *a, const se23_real_t *b, int rows, int cols,
                         int stride)
{
    double d = 0, s = 0;
    for (int i = 0; i < rows; ++i) {
        for (int j = 0; j < cols; ++j) {
            d = fmax(d, fabs((double)a[stride * i + j] - (double)b[stride * i + j]));
            s = fmax(s, fabs((double)b[stride * i + j]));
        }
    }
    return d == 0 ? 0 : d / s;
}

/* Covariances: max |a_ij - b_ij| / sqrt(b_ii b_jj), in correlation units. */
static double cov_diff(const se23_real_t *a, const se23_real_t *b, int n, int stride)
{
    double worst = 0;
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            const double d = fabs((double)a[stride * i + j] - (double)b[stride * i + j]);
            const double s = sqrt((double)b[stride * i + i] * (double)b[stride * j + j]);
            worst = fmax(worst, d == 0 ? 0 : d / s);
        }
    }
    return worst;
}

static double pose_diff(const se23_pose_t *a, const se23_pose_t *b)
{
    return fmax(block_diff(&a->R.m[0][0], &b->R.m[0][0], 3, 3, 3),
                fmax(block_diff(a->v.v, b->v.v, 1, 3, 3), block_diff(a->p.v, b->p.v, 1, 3, 3)));
}

static double gauss_diff(int i)
{
    const se23_gauss_t *a = &out_se23[i], *b = &out_eigen[i];
    if (a->n != b->n) {
        return INFINITY;
    }
    const double d = fmax(pose_diff(&a->T, &b->T), fmax(block_diff(a->b_g.v, b->b_g.v, 1, 3, 3),
                                                        block_diff(a->b_a.v, b->b_a.v, 1, 3, 3)));
    return fmax(d, cov_diff(a->P.m, b->P.m, a->n, SE23_GAUSS_NMAX));
}

static double factor_diff(int i)
{
    const se23_preint_unc_t *a = &fu_se23[i], *b = &fu_eigen[i];
    if (a->f.n != b->f.n) {
        return INFINITY;
    }
    double d = fmax(pose_diff(&a->f.delta, &b->f.delta), block_diff(&a->f.dt, &b->f.dt, 1, 1, 1));
    d = fmax(d, cov_diff(a->P_left.m, b->P_left.m, 9, 9));
    for (int r = 0; r < 9; r += 3) { /* J by 3x3 blocks: their scales are dt to dt^3 */
        for (int c = 0; c < 6; c += 3) {
            d = fmax(d, block_diff(&a->J_left.m[6 * r + c], &b->J_left.m[6 * r + c], 3, 3, 6));
        }
    }
    return d;
}

const bench_step_t bench_steps[BENCH_N_STEPS] = {
    {"predict_n9", "navigation step, 9 states (`se23_gauss_predict`)", se23_predict_n9,
     eigen_predict_n9, gauss_diff},
    {"predict_n15", "navigation step, 15 states (`se23_gauss_predict`)", se23_predict_n15,
     eigen_predict_n15, gauss_diff},
    {"preint", "preintegration step (`se23_preint_unc_add`)", se23_preint, eigen_preint,
     factor_diff},
    {"gnss_n15", "GNSS position update, 15 states (`se23_meas_pos_nav` + `se23_kalman_update`)",
     se23_gnss, eigen_gnss, gauss_diff},
};
