/* The rows of the paper's Table; see rows.h. */
#include "rows.h"

#include "../montecarlo/paper_tool.h"
#include "se23/gauss.h"
#include "se23/imu.h"
#include "se23/se23.h"

#define PROG "se23-paper-table"

typedef se23_status_t (*increment_fn)(const se23_imu_sample_t *, se23_pose_t *);

/* Sample k of fa corrected by the bias estimate db. */
static se23_imu_sample_t sample(const factor_t *fa, long k, const double db[6])
{
    se23_imu_sample_t s;
    for (int i = 0; i < 3; ++i) {
        s.w_ib_b.v[i] = fa->wf[k].w[i] + db[i];
        s.f_b.v[i] = fa->wf[k].f[i] + db[3 + i];
    }
    s.dt = fa->dt;
    return s;
}

/* The Deltas of fa's samples corrected by db, with the increment model inc;
 * if J is not NULL, also the bias Jacobian of those Deltas with the paper's
 * B_k = dt I_{9,6}: J+ = Ad_{Upsilon_k^-1} F J + B_k from J = 0. */
static se23_preint_t integrate(const factor_t *fa, const double db[6], increment_fn inc,
                               se23_mat9x6_t *J)
{
    se23_preint_t f;
    se23_preint_reset(&f);
    if (J != NULL) {
        *J = (se23_mat9x6_t){{0}};
    }
    for (long k = 0; k < fa->n; ++k) {
        const se23_imu_sample_t s = sample(fa, k, db);
        se23_pose_t u;
        se23_status_t st = inc(&s, &u);
        if (st != SE23_OK) {
            paper_die(PROG, "increment", st);
        }
        if (J != NULL) {
            se23_mat9x6_t B, FJ;
            st = se23_gauss_input_jac(SE23_INPUT_JAC_BASIC, &s.w_ib_b, &s.f_b, s.dt, &B);
            if (st != SE23_OK) {
                paper_die(PROG, "se23_gauss_input_jac", st);
            }
            se23_gauss_fk_mul(&u, s.dt, J, &FJ);
            for (int i = 0; i < 54; ++i) {
                J->m[i] = FJ.m[i] + B.m[i];
            }
        }
        se23_preint_add_increment(&f, &u, s.dt);
    }
    return f;
}

/* The one reset of the tool's factors, at bbar = 0, with the classical
 * Jacobians (opt-in): fa->ex's are used (se23_preint_unc_correct_classic). */
static void reset(se23_input_jac_kind_t kind, se23_preint_unc_t *fu)
{
    const se23_vec3_t zero = {{0, 0, 0}};
    const se23_status_t st = se23_preint_unc_reset_classic(&zero, &zero, kind, fu);
    if (st != SE23_OK) {
        paper_die(PROG, "se23_preint_unc_reset_classic", st);
    }
}

void factor_build(factor_t *fa, const raw_sample_t *wf, long n, double dt)
{
    static const double no_bias[6] = {0};
    const se23_imu_noise_t quiet = {0, 0, 0, 0};
    fa->wf = wf;
    fa->n = n;
    fa->dt = dt;
    reset(SE23_INPUT_JAC_EXACT, &fa->ex);
    reset(SE23_INPUT_JAC_BASIC, &fa->ba);
    for (long k = 0; k < n; ++k) {
        const se23_imu_sample_t s = sample(fa, k, no_bias);
        se23_status_t st = se23_preint_unc_add(&fa->ex, &s, &quiet);
        if (st == SE23_OK) {
            st = se23_preint_unc_add(&fa->ba, &s, &quiet);
        }
        if (st != SE23_OK) {
            paper_die(PROG, "se23_preint_unc_add", st);
        }
    }
    fa->forster = integrate(fa, no_bias, se23_imu_increment_forster, NULL);
    fa->paper = integrate(fa, no_bias, se23_imu_increment_paper, &fa->paper_J);
}

/* Delta exp(J db): the exponential correction of the Deltas Delta. */
static se23_pose_t exp_correct(const se23_pose_t *delta, const se23_mat9x6_t *J, const double db[6])
{
    se23_tangent_t d;
    for (int i = 0; i < 9; ++i) {
        d.v[i] = 0;
        for (int j = 0; j < 6; ++j) {
            d.v[i] += J->m[6 * i + j] * db[j];
        }
    }
    se23_pose_t E, out;
    const se23_status_t st = se23_exp(&d, &E);
    if (st != SE23_OK) {
        paper_die(PROG, "se23_exp", st);
    }
    se23_compose(delta, &E, &out);
    return out;
}

static void add_error(row_acc_t *a, const se23_pose_t *approx, const se23_pose_t *ref)
{
    for (int i = 0; i < 3; ++i) {
        const double ev = approx->v.v[i] - ref->v.v[i];
        const double ep = approx->p.v[i] - ref->p.v[i];
        a->v2 += ev * ev;
        a->p2 += ep * ep;
    }
    a->n += 1;
}

void factor_score(const factor_t *fa, const double db[6], row_acc_t acc[N_ROWS])
{
    const se23_vec3_t bg = {{db[0], db[1], db[2]}}, ba = {{db[3], db[4], db[5]}};
    const se23_preint_t ref = integrate(fa, db, se23_imu_increment, NULL);
    const se23_preint_t ref_forster = integrate(fa, db, se23_imu_increment_forster, NULL);
    const se23_preint_t ref_paper = integrate(fa, db, se23_imu_increment_paper, NULL);
    se23_preint_t corr[N_ROWS];
    se23_status_t st = se23_preint_unc_correct_classic(&fa->ex, &bg, &ba, &corr[ROW_FORSTER_EXACT]);
    if (st == SE23_OK) {
        st = se23_preint_unc_correct(&fa->ba, &bg, &ba, &corr[ROW_BASIC]);
    }
    if (st == SE23_OK) {
        st = se23_preint_unc_correct(&fa->ex, &bg, &ba, &corr[ROW_EXACT]);
    }
    if (st != SE23_OK) {
        paper_die(PROG, "correction", st);
    }
    corr[ROW_NONE] = fa->ex.f;
    /* Forster et al.'s correction adds J db to Delta V and Delta X whatever
     * the Deltas (and turns Delta R, which the Table does not score): the
     * same offset on their own Deltas. */
    corr[ROW_FORSTER] = fa->forster;
    for (int i = 0; i < 3; ++i) {
        corr[ROW_FORSTER].delta.v.v[i] += corr[ROW_FORSTER_EXACT].delta.v.v[i] - fa->ex.f.delta.v.v[i];
        corr[ROW_FORSTER].delta.p.v[i] += corr[ROW_FORSTER_EXACT].delta.p.v[i] - fa->ex.f.delta.p.v[i];
    }
    corr[ROW_PAPER] = fa->paper;
    corr[ROW_PAPER].delta = exp_correct(&fa->paper.delta, &fa->paper_J, db);
    for (int r = 0; r < N_ROWS; ++r) {
        const se23_preint_t *against = r == ROW_FORSTER ? &ref_forster
                                       : r == ROW_PAPER ? &ref_paper
                                                        : &ref;
        add_error(&acc[r], &corr[r].delta, &against->delta);
    }
}
