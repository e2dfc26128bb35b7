/* Unit tests of src/cov/preint_classic.c, the classical (Forster et al. 2017)
 * bias Jacobians of a preintegrated factor and their first-order
 * correction: the Jacobians accumulated by se23_preint_unc_add against
 * central differences of the Euler preintegration they are derived for,
 * and se23_preint_classic_apply on Euler Deltas (exact for an accelerometer
 * bias change, second order in a gyro one). Their accuracy on the library's
 * exact Deltas is compared in test_preint_unc.c. */
#include <math.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stddef.h>
#include <string.h>

#include <cmocka.h>

#include "gauss_test.h"
#include "cov/preint_classic.h"
#include "preint_unc_test.h"
#include "se23/preint_unc.h"
#include "se23_test.h"

static void test_preint_classic_step_matches_euler_differences(void **state)
{
    (void)state;
    /* Forster et al.'s Jacobians are the derivatives of the Euler-integrated
     * Deltas (exp(w dt), dt f, dt^2 f/2 per sample): check them against
     * central differences of that preintegration (rotation as
     * log(DR^T DR')). */
    enum { N = HZ };
    se23_preint_unc_t fu;
    make_factor(N, SE23_INPUT_JAC_EXACT, &QUIET, &fu);
    const se23_mat3_t *blk[2][3] = {{&fu.cl.dR_dbg, &fu.cl.dV_dbg, &fu.cl.dX_dbg},
                                    {NULL, &fu.cl.dV_dba, &fu.cl.dX_dba}};
    double worst = 0;
    for (int j = 0; j < 6; ++j) {
        const double h = (j < 3) ? FD_GYRO : FD_ACCEL;
        double e[6] = {0}, rp[9], rm[9];
        gt_m5_t Dp, Dm;
        e[j] = h;
        ref_factor(N, e, 1, &Dp);
        e[j] = -h;
        ref_factor(N, e, 1, &Dm);
        gt_log_between(&Dm, &Dp, rp); /* rotation part: log(DR-^T DR+) */
        for (int i = 0; i < 3; ++i) {
            rm[i] = rp[i] / (2.0 * h);
            rm[3 + i] = (Dp.m[i][3] - Dm.m[i][3]) / (2.0 * h);
            rm[6 + i] = (Dp.m[i][4] - Dm.m[i][4]) / (2.0 * h);
        }
        const int side = j / 3, c = j % 3;
        for (int b = side; b < 3; ++b) { /* dR/dba is zero and not stored */
            double err = 0, scale = 0;
            for (int i = 0; i < 3; ++i) {
                err = fmax(err, fabs((double)blk[side][b]->m[i][c] - rm[3 * b + i]));
                scale = fmax(scale, fabs(rm[3 * b + i]));
            }
            worst = fmax(worst, err / scale);
        }
    }
    print_message("classical Jacobians vs Euler central differences: %.2e\n", worst);
    assert_true(worst < JAC_TOL);
}

/* |a - b| over the velocity and position of two poses, plus the rotation
 * angle between them (small). */
static double pose_gap(const se23_pose_t *a, const se23_pose_t *b)
{
    double ev, ep, er = 0;
    vp_errors(a, b, &ev, &ep);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            er = fmax(er, fabs((double)a->R.m[i][j] - b->R.m[i][j]));
        }
    }
    return ev + ep + er;
}

/* The classical correction of the Euler Deltas at BBAR to BBAR + db, and
 * the Euler re-integration at BBAR + db. */
static void euler_case(const se23_preint_unc_t *fu, int n, const double db[6],
                       se23_pose_t *corr, se23_pose_t *ref)
{
    static const double zero[6] = {0};
    gt_m5_t D0, D1;
    ref_factor(n, zero, 1, &D0);
    ref_factor(n, db, 1, &D1);
    se23_pose_t delta;
    pose_of(&D0, &delta);
    pose_of(&D1, ref);
    se23_vec3_t dbg, dba;
    bias_vecs(db, &dbg, &dba);
    se23_preint_classic_apply(&fu->cl, &delta, &dbg, &dba, corr);
}

static void test_preint_classic_apply_zero_change_is_identity(void **state)
{
    (void)state;
    se23_preint_unc_t fu;
    make_factor(50, SE23_INPUT_JAC_EXACT, &QUIET, &fu);
    const se23_vec3_t zero = {{0, 0, 0}};
    se23_pose_t out;
    se23_preint_classic_apply(&fu.cl, &fu.f.delta, &zero, &zero, &out);
    assert_memory_equal(&out.R, &fu.f.delta.R, sizeof out.R);
    assert_memory_equal(&out.v, &fu.f.delta.v, sizeof out.v);
    assert_memory_equal(&out.p, &fu.f.delta.p, sizeof out.p);
}

static void test_preint_classic_apply_exact_for_accel_bias_on_euler_deltas(void **state)
{
    (void)state;
    /* The Euler Deltas are affine in the accelerometer bias with exactly
     * the classical Jacobians: 2 s, 1 m/s^2 per axis. */
    enum { N = 2 * HZ };
    se23_preint_unc_t fu;
    make_factor(N, SE23_INPUT_JAC_EXACT, &QUIET, &fu);
    const double db[6] = {0, 0, 0, 1.0, -1.0, 1.0};
    se23_pose_t corr, ref;
    euler_case(&fu, N, db, &corr, &ref);
    const double gap = pose_gap(&corr, &ref);
    print_message("classical, accel bias alone, Euler Deltas: %.2e\n", gap);
    assert_true(gap < 20.0 * 400.0 * SE23T_EPS);
}

static void test_preint_classic_apply_error_is_second_order_on_euler_deltas(void **state)
{
    (void)state;
    /* On the Deltas they are derived for, halving the bias change quarters
     * the error of the classical correction. */
    enum { N = 2 * HZ };
    se23_preint_unc_t fu;
    make_factor(N, SE23_INPUT_JAC_EXACT, &QUIET, &fu);
    const double db1[6] = {0.02, -0.015, 0.01, 0.05, 0.03, -0.04};
    double db2[6];
    for (int i = 0; i < 6; ++i) {
        db2[i] = 0.5 * db1[i];
    }
    se23_pose_t c1, r1, c2, r2;
    euler_case(&fu, N, db1, &c1, &r1);
    euler_case(&fu, N, db2, &c2, &r2);
    const double ratio = pose_gap(&c1, &r1) / pose_gap(&c2, &r2);
    print_message("classical on Euler Deltas, error ratio at db and db/2: %.3f\n", ratio);
    assert_true(ratio > 3.8 && ratio < 4.2);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(test_preint_classic_step_matches_euler_differences),
        cmocka_unit_test(test_preint_classic_apply_zero_change_is_identity),
        cmocka_unit_test(test_preint_classic_apply_exact_for_accel_bias_on_euler_deltas),
        cmocka_unit_test(test_preint_classic_apply_error_is_second_order_on_euler_deltas),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
