/*
 * libFuzzer target of se23/gauss.h. Unchecked products (fk_apply, fk,
 * fk_mul): no crash, in place equal to out of place. Checked functions:
 * statuses in the header's set; on SE23_OK finite outputs, covariances
 * symmetric PSD (se23_gauss_check: Q of input_noise, S_next of
 * cov_propagate, the states of propagate, predict, from/to_carried); on an
 * error the sentinel untouched. Every aliasing the header allows ("All
 * functions accept outputs that alias inputs") equals the plain call bit for
 * bit. States handed to the functions that trust them (propagate, predict,
 * from/to_carried) are the ones se23_gauss_check accepts (types.h,
 * "Validation policy").
 */
#include "fuzz.h"

#include "se23/gauss.h"

static void noise_of(fz_t *f, se23_imu_noise_t *q)
{
    if (fz_u8(f) < 192) {
        q->gyro_noise = (se23_real_t)fabs((double)fz_mild(f)) * (se23_real_t)1e-3;
        q->accel_noise = (se23_real_t)fabs((double)fz_mild(f)) * (se23_real_t)1e-2;
        q->gyro_walk = (se23_real_t)fabs((double)fz_mild(f)) * (se23_real_t)1e-5;
        q->accel_walk = (se23_real_t)fabs((double)fz_mild(f)) * (se23_real_t)1e-4;
    } else {
        q->gyro_noise = fz_real(f);
        q->accel_noise = fz_real(f);
        q->gyro_walk = fz_real(f);
        q->accel_walk = fz_real(f);
    }
}

static se23_input_jac_kind_t kind_of(fz_t *f)
{
    uint8_t m = fz_u8(f);
    return (se23_input_jac_kind_t)(m < 248 ? (int)(m & 1) : fz_int(f));
}

static void one_fk(fz_t *f)
{
    se23_pose_t U;
    se23_real_t dt = fz_dt(f);
    se23_tangent_t x, y, t;
    se23_mat9x6_t X, Y, Z;
    se23_mat9_t F;
    int i;
    fz_pose(f, &U);
    for (i = 0; i < 9; ++i) {
        x.v[i] = fz_real(f);
    }
    se23_gauss_fk_apply(&U, dt, &x, &y);
    t = x;
    se23_gauss_fk_apply(&U, dt, &t, &t);
    FZ_REQUIRE(FZ_SAME(t, y), "fk_apply(x, x) differs from fk_apply(x, y)");
    se23_gauss_fk(&U, dt, &F);
    for (i = 0; i < 54; ++i) {
        X.m[i] = fz_u8(f) < 128 ? 0 : fz_real(f);
    }
    se23_gauss_fk_mul(&U, dt, &X, &Y);
    Z = X;
    se23_gauss_fk_mul(&U, dt, &Z, &Z);
    FZ_REQUIRE(FZ_SAME(Z, Y), "fk_mul(X, X) differs from fk_mul(X, Y)");
}

/* B from input_jac on a decoded sample (or raw 9x6); 1 if B is from the library. */
static int jac_of(fz_t *f, se23_imu_sample_t *s, se23_mat9x6_t *B)
{
    se23_input_jac_kind_t kind = kind_of(f);
    se23_status_t st;
    fz_sample(f, s);
    fz_fill(B, sizeof *B);
    st = se23_gauss_input_jac(kind, &s->w_ib_b, &s->f_b, s->dt, B);
    FZ_REQUIRE(fz_status_in(st, 3, SE23_ERR_NONFINITE, SE23_ERR_DT, SE23_ERR_DOMAIN),
               "input_jac: %d", st);
    if (st != SE23_OK) {
        int i;
        FZ_REQUIRE(fz_untouched(B, sizeof *B), "input_jac wrote on error %d", st);
        for (i = 0; i < 54; ++i) {
            B->m[i] = fz_u8(f) < 160 ? 0 : fz_real(f);
        }
        return 0;
    }
    FZ_REQUIRE(FZ_FINITE_OBJ(*B), "input_jac: OK with a non-finite B");
    return 1;
}

static void one_noise_cov(fz_t *f)
{
    se23_imu_sample_t s;
    se23_mat9x6_t B;
    se23_imu_noise_t q;
    se23_mat9_t Q, S, Sn, t;
    se23_pose_t U;
    se23_real_t dt;
    se23_status_t st, sa;
    (void)jac_of(f, &s, &B);
    noise_of(f, &q);
    dt = fz_u8(f) < 200 ? s.dt : fz_dt(f);
    fz_fill(&Q, sizeof Q);
    st = se23_gauss_input_noise(&B, &q, dt, &Q);
    FZ_REQUIRE(fz_status_in(st, 3, SE23_ERR_NONFINITE, SE23_ERR_DT, SE23_ERR_DOMAIN),
               "input_noise: %d", st);
    if (st != SE23_OK) {
        FZ_REQUIRE(fz_untouched(&Q, sizeof Q), "input_noise wrote on error %d", st);
        fz_cov(f, 9, 9, Q.m);
    } else {
        se23_status_t c = fz_cov_check(Q.m, 9, 9);
        FZ_REQUIRE(FZ_FINITE_OBJ(Q), "input_noise: OK with a non-finite Q");
        FZ_REQUIRE(c == SE23_OK, "input_noise: OK but Q fails the covariance check (%d)", c);
    }
    /* S_next = F S F^T + Q */
    if (fz_u8(f) < 192 && se23_imu_increment(&s, &U) == SE23_OK) {
        /* the increment of the sample */
    } else {
        fz_pose(f, &U);
    }
    fz_cov(f, 9, 9, S.m);
    fz_fill(&Sn, sizeof Sn);
    st = se23_gauss_cov_propagate(&S, &U, dt, &Q, &Sn);
    FZ_REQUIRE(fz_status_in(st, 5, SE23_ERR_NONFINITE, SE23_ERR_NOT_SYMMETRIC, SE23_ERR_NOT_PSD,
                            SE23_ERR_NOT_ROTATION, SE23_ERR_DT),
               "cov_propagate: %d", st);
    t = S;
    sa = se23_gauss_cov_propagate(&t, &U, dt, &Q, &t);
    FZ_REQUIRE(sa == st, "cov_propagate(S, S): status %d, plain %d", sa, st);
    if (st != SE23_OK) {
        FZ_REQUIRE(fz_untouched(&Sn, sizeof Sn), "cov_propagate wrote on error %d", st);
        FZ_REQUIRE(FZ_SAME(t, S), "cov_propagate(S, S) changed S on error %d", st);
    } else {
        const double bound = fz_step_bound(&U, (double)dt, 0.0, 0.0, 0.0, S.m, 9, 9) +
                             9.0 * (32.0 * FZ_EPS + SE23_CFG_COV_TOL) * fz_max_diag(Q.m, 9, 9);
        FZ_REQUIRE(FZ_FINITE_OBJ(Sn), "cov_propagate: OK with a non-finite S_next");
        (void)fz_check_cov_result(fz_cov_check(Sn.m, 9, 9), Sn.m, 9, 9, bound, "cov_propagate");
        FZ_REQUIRE(FZ_SAME(t, Sn), "cov_propagate(S, S) differs from the plain call");
    }
    t = Q;
    sa = se23_gauss_cov_propagate(&S, &U, dt, &t, &t);
    FZ_REQUIRE(sa == st, "cov_propagate(Q, Q): status %d, plain %d", sa, st);
    FZ_REQUIRE(st != SE23_OK ? FZ_SAME(t, Q) : FZ_SAME(t, Sn),
               "cov_propagate with S_next = Q differs from the plain call");
}

/* A state; 1 if se23_gauss_check accepts it (the trusting functions may take it). */
static int state_of(fz_t *f, se23_gauss_t *g)
{
    se23_status_t c;
    fz_gauss(f, g);
    c = se23_gauss_check(g);
    FZ_REQUIRE(fz_status_in(c, 5, SE23_ERR_DIM, SE23_ERR_NONFINITE, SE23_ERR_NOT_ROTATION,
                            SE23_ERR_NOT_SYMMETRIC, SE23_ERR_NOT_PSD),
               "gauss_check: %d", c);
    return c == SE23_OK;
}

static void one_propagate(fz_t *f)
{
    se23_gauss_t g, out, t;
    se23_imu_sample_t s;
    se23_mat9x6_t B;
    se23_imu_noise_t q;
    se23_pose_t U;
    se23_real_t dt;
    se23_status_t st, sa;
    if (!state_of(f, &g)) {
        return;
    }
    (void)jac_of(f, &s, &B);
    noise_of(f, &q);
    if (fz_u8(f) < 192 && se23_imu_increment(&s, &U) == SE23_OK) {
        dt = s.dt;
    } else {
        fz_pose(f, &U);
        dt = fz_dt(f);
    }
    fz_fill(&out, sizeof out);
    st = se23_gauss_propagate(&g, &U, &B, &q, dt, &out);
    FZ_REQUIRE(fz_status_in(st, 5, SE23_ERR_DIM, SE23_ERR_NOT_ROTATION, SE23_ERR_NONFINITE,
                            SE23_ERR_DOMAIN, SE23_ERR_DT),
               "propagate: %d", st);
    t = g;
    sa = se23_gauss_propagate(&t, &U, &B, &q, dt, &t);
    FZ_REQUIRE(sa == st, "propagate(g, g): status %d, plain %d", sa, st);
    if (st != SE23_OK) {
        FZ_REQUIRE(fz_untouched(&out, sizeof out), "propagate wrote on error %d", st);
        FZ_REQUIRE(fz_gauss_same(&t, &g), "propagate(g, g) changed g on error %d", st);
        return;
    }
    {
        const double qm = fmax((double)q.gyro_noise * q.gyro_noise,
                               (double)q.accel_noise * q.accel_noise) / (double)dt;
        const double wm = fmax((double)q.gyro_walk * q.gyro_walk,
                               (double)q.accel_walk * q.accel_walk) * (double)dt;
        (void)fz_check_cov_step(&out, fz_step_bound(&U, (double)dt, fz_rowsum9x6(&B), qm, wm, g.P.m,
                                              g.n, 15),
                          "propagate");
    }
    FZ_REQUIRE(fz_gauss_same(&t, &out), "propagate(g, g) differs from the plain call");
}

static void one_predict(fz_t *f)
{
    se23_earth_model_t m;
    se23_gauss_t g, out, t;
    se23_imu_noise_t q;
    se23_input_jac_kind_t kind;
    int k, n;
    fz_model(f, &m);
    if (!state_of(f, &g)) {
        return;
    }
    noise_of(f, &q);
    kind = kind_of(f);
    n = 1 + fz_u8(f) % 16;
    for (k = 0; k < n && fz_left(f); ++k) {
        se23_imu_sample_t s;
        se23_predict_work_t w;
        se23_status_t st, sa;
        fz_sample(f, &s);
        fz_fill(&out, sizeof out);
        st = se23_gauss_predict(&m, &g, &s, &q, kind, &out);
        FZ_REQUIRE(fz_status_in(st, 4, SE23_ERR_DIM, SE23_ERR_DOMAIN, SE23_ERR_NONFINITE,
                                SE23_ERR_DT),
                   "predict: %d", st);
        /* In place, and with a work area of fuzzed bytes: the same call. */
        t = g;
        fz_fill(&w, sizeof w);
        sa = se23_gauss_predict_work(&m, &t, &s, &q, kind, &w, &t);
        FZ_REQUIRE(sa == st, "predict(g, g): status %d, plain %d", sa, st);
        if (st != SE23_OK) {
            FZ_REQUIRE(fz_untouched(&out, sizeof out), "predict wrote on error %d", st);
            FZ_REQUIRE(fz_gauss_same(&t, &g), "predict(g, g) changed g on error %d", st);
            continue;
        }
        FZ_REQUIRE(fz_gauss_same(&t, &out), "predict(g, g) differs from the plain call");
        if (!fz_check_cov_step(&out,
                               fz_sample_bound(&s, &g.b_g, &g.b_a, kind, &q, g.n == 15, g.P.m,
                                               g.n, 15),
                               "predict")) {
            return; /* the known finding: not a state to go on with */
        }
        g = out;
    }
}

static void one_carried(fz_t *f)
{
    se23_earth_model_t m;
    se23_gauss_t g, out, t;
    int dir;
    fz_model(f, &m);
    if (!state_of(f, &g)) {
        return; /* trusted: only n is checked */
    }
    for (dir = 0; dir < 2; ++dir) {
        se23_status_t st, sa;
        fz_fill(&out, sizeof out);
        st = dir ? se23_gauss_to_carried(&m, &g, &out) : se23_gauss_from_carried(&m, &g, &out);
        FZ_REQUIRE(fz_status_in(st, 5, SE23_ERR_DIM, SE23_ERR_NONFINITE, SE23_ERR_NOT_ROTATION,
                                SE23_ERR_NOT_SYMMETRIC, SE23_ERR_NOT_PSD),
                   "%s_carried: %d", dir ? "to" : "from", st);
        t = g;
        sa = dir ? se23_gauss_to_carried(&m, &t, &t) : se23_gauss_from_carried(&m, &t, &t);
        FZ_REQUIRE(sa == st, "%s_carried(g, g): status %d, plain %d", dir ? "to" : "from", sa, st);
        if (st != SE23_OK) {
            FZ_REQUIRE(fz_untouched(&out, sizeof out), "%s_carried wrote on error %d",
                       dir ? "to" : "from", st);
            FZ_REQUIRE(fz_gauss_same(&t, &g), "%s_carried(g, g) changed g on error", dir ? "to" : "from");
            return;
        }
        {
            const double a = fabs((double)m.w_ie_n.v[0]) + fabs((double)m.w_ie_n.v[1]) +
                             fabs((double)m.w_ie_n.v[2]);
            const double r = 1.0 + 2.0 * a; /* |R^T Omega|_1 <= 2 |Omega|_1 */
            if (!fz_check_cov_step(&out,
                                   (double)g.n * (32.0 * FZ_EPS + SE23_CFG_COV_TOL) * r * r *
                                       fz_max_diag(g.P.m, g.n, 15),
                                   dir ? "to_carried" : "from_carried")) {
                return;
            }
        }
        FZ_REQUIRE(fz_gauss_same(&t, &out), "%s_carried(g, g) differs from the plain call",
                   dir ? "to" : "from");
        g = out;
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_t f;
    int calls = 0;
    fz_init(&f, data, size);
    while (fz_left(&f) && calls++ < 16) {
        switch (fz_u8(&f) % 5) {
        case 0:
            one_fk(&f);
            break;
        case 1:
            one_noise_cov(&f);
            break;
        case 2:
            one_propagate(&f);
            break;
        case 3:
            one_predict(&f);
            break;
        default:
            one_carried(&f);
            break;
        }
    }
    return 0;
}
