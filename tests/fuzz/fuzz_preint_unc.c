/*
 * libFuzzer target of se23/preint_unc.h: a factor from reset or
 * reset_classic on decoded biases and kinds (on SE23_OK it passes
 * se23_preint_unc_check: "starts valid"), samples added (on SE23_OK the
 * factor still passes se23_preint_unc_check: "stays valid"; on an error it
 * is unchanged), the corrections (on SE23_OK finite Deltas, Delta R in
 * SO(3), dt and n copied; on an error the sentinel untouched), the paper's
 * form (se23_preint_unc_cov: on SE23_OK finite and exactly symmetric, on
 * an error untouched), and the check, corrections and paper's form of a
 * factor decoded raw (they check what they read).
 */
#include "fuzz.h"

#include "se23/preint_unc.h"
#include "se23/se23.h"

static void noise_of(fz_t *f, se23_imu_noise_t *q)
{
    if (fz_u8(f) < 192) {
        q->gyro_noise = (se23_real_t)fabs((double)fz_mild(f)) * (se23_real_t)1e-3;
        q->accel_noise = (se23_real_t)fabs((double)fz_mild(f)) * (se23_real_t)1e-2;
    } else {
        q->gyro_noise = fz_real(f);
        q->accel_noise = fz_real(f);
    }
    q->gyro_walk = fz_real(f);
    q->accel_walk = fz_real(f);
}

static void bias_of(fz_t *f, se23_vec3_t *b_g, se23_vec3_t *b_a)
{
    if (fz_u8(f) < 64) {
        memset(b_g, 0, sizeof *b_g);
        memset(b_a, 0, sizeof *b_a);
    } else if (fz_u8(f) < 224) {
        fz_vec3_mild(f, b_g);
        fz_vec3_mild(f, b_a);
    } else {
        fz_vec3(f, b_g);
        fz_vec3(f, b_a);
    }
}

static void check_factor(const se23_preint_unc_t *fu, const char *what)
{
    se23_status_t c = se23_preint_unc_check(fu);
    FZ_REQUIRE(c == SE23_OK, "%s: OK but the factor fails se23_preint_unc_check (%d)", what, c);
}

static void one_correct(fz_t *f, const se23_preint_unc_t *fu)
{
    se23_vec3_t b_g, b_a;
    se23_preint_t out;
    se23_status_t st;
    int classic;
    bias_of(f, &b_g, &b_a);
    for (classic = 0; classic < 2; ++classic) {
        fz_fill(&out, sizeof out);
        st = classic ? se23_preint_unc_correct_classic(fu, &b_g, &b_a, &out)
                     : se23_preint_unc_correct(fu, &b_g, &b_a, &out);
        FZ_REQUIRE(fz_status_in(st, 6, SE23_ERR_DOMAIN, SE23_ERR_NONFINITE, SE23_ERR_NOT_ROTATION,
                                SE23_ERR_DT, SE23_ERR_NOT_SYMMETRIC, SE23_ERR_NOT_PSD),
                   "correct%s: %d", classic ? "_classic" : "", st);
        if (st != SE23_OK) {
            FZ_REQUIRE(fz_untouched(&out, sizeof out), "correct%s wrote on error %d",
                       classic ? "_classic" : "", st);
            continue;
        }
        FZ_REQUIRE(FZ_FINITE_OBJ(out.delta) && isfinite(out.dt),
                   "correct%s: OK with a non-finite factor", classic ? "_classic" : "");
        FZ_REQUIRE(fz_is_rot(&out.delta.R), "correct%s: OK but Delta R not a rotation (check %d)",
                   classic ? "_classic" : "", se23_so3_check(&out.delta.R));
        FZ_REQUIRE(memcmp(&out.dt, &fu->f.dt, sizeof out.dt) == 0 && out.n == fu->f.n,
                   "correct%s: dt or n not copied", classic ? "_classic" : "");
    }
}

static void one_cov(const se23_preint_unc_t *fu)
{
    se23_mat9_t P;
    se23_mat9x6_t J;
    int i, j;
    fz_fill(&P, sizeof P);
    fz_fill(&J, sizeof J);
    const se23_status_t st = se23_preint_unc_cov(fu, &P, &J);
    FZ_REQUIRE(fz_status_in(st, 6, SE23_ERR_DOMAIN, SE23_ERR_NONFINITE, SE23_ERR_NOT_ROTATION,
                            SE23_ERR_DT, SE23_ERR_NOT_SYMMETRIC, SE23_ERR_NOT_PSD),
               "cov: %d", st);
    if (st != SE23_OK) {
        FZ_REQUIRE(fz_untouched(&P, sizeof P) && fz_untouched(&J, sizeof J),
                   "cov wrote on error %d", st);
        return;
    }
    FZ_REQUIRE(FZ_FINITE_OBJ(P) && FZ_FINITE_OBJ(J), "cov: OK with a non-finite P or J");
    for (i = 0; i < 9; ++i) {
        for (j = 0; j < i; ++j) {
            FZ_REQUIRE(P.m[9 * i + j] == P.m[9 * j + i], "cov: P not exactly symmetric");
        }
    }
}

/* fz_step_bound of the left-form step (preint_unc.h): F the time shear
 * (rows summing to 1 + dt, as a shear of zero translation), Bl = Ad_{Delta+}
 * D Bt with rows summing to at most 2 b (1 + |v+|_1 + |p+|_1), b those of
 * B = D Bt (twice: a rotation's rows sum to below 2), Delta+ = after the
 * sample. */
static double left_bound(const se23_imu_sample_t *s, const se23_preint_unc_t *after,
                         const se23_imu_noise_t *q, const se23_real_t *P_before)
{
    const se23_pose_t *D = &after->f.delta;
    se23_pose_t U;
    double b, qm, wm, t = 1.0;
    int i;
    if (!fz_sample_parts(s, &after->b_g, &after->b_a, after->kind, q, 0, &U, &b, &qm, &wm)) {
        return HUGE_VAL;
    }
    for (i = 0; i < 3; ++i) {
        t += fabs((double)D->v.v[i]) + fabs((double)D->p.v[i]);
    }
    se23_identity(&U);
    return fz_step_bound(&U, (double)s->dt, 4.0 * b * t, qm, wm, P_before, 9, 9);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_t f;
    se23_preint_unc_t fu, before, copy;
    se23_preint_work_t w;
    se23_vec3_t b_g, b_a;
    se23_input_jac_kind_t kind;
    se23_imu_noise_t q;
    se23_status_t st, sa;
    uint8_t m;
    int k, n, classic;
    fz_init(&f, data, size);
    m = fz_u8(&f);
    if (m >= 240) { /* a raw factor: only the functions that check it */
        size_t i;
        memset(&fu, 0, sizeof fu);
        fz_pose(&f, &fu.f.delta);
        fu.f.dt = fz_real(&f);
        fu.f.n = fz_u32(&f);
        fz_vec3(&f, &fu.b_g);
        fz_vec3(&f, &fu.b_a);
        fu.kind = (se23_input_jac_kind_t)fz_int(&f);
        fu.classic = fz_int(&f);
        fz_cov(&f, 9, 9, fu.P_left.m);
        for (i = 0; i < 54; ++i) {
            fu.J_left.m[i] = fz_u8(&f) < 192 ? 0 : fz_real(&f);
        }
        st = se23_preint_unc_check(&fu);
        FZ_REQUIRE(fz_status_in(st, 6, SE23_ERR_DOMAIN, SE23_ERR_NONFINITE, SE23_ERR_NOT_ROTATION,
                                SE23_ERR_DT, SE23_ERR_NOT_SYMMETRIC, SE23_ERR_NOT_PSD),
                   "check: %d", st);
        one_correct(&f, &fu);
        one_cov(&fu);
        return 0;
    }
    bias_of(&f, &b_g, &b_a);
    kind = (se23_input_jac_kind_t)(fz_u8(&f) < 248 ? (m & 1) : fz_int(&f));
    classic = (m >> 1) & 1;
    fz_fill(&fu, sizeof fu);
    st = classic ? se23_preint_unc_reset_classic(&b_g, &b_a, kind, &fu)
                 : se23_preint_unc_reset(&b_g, &b_a, kind, &fu);
    FZ_REQUIRE(fz_status_in(st, 2, SE23_ERR_NONFINITE, SE23_ERR_DOMAIN), "reset: %d", st);
    if (st != SE23_OK) {
        FZ_REQUIRE(fz_untouched(&fu, sizeof fu), "reset wrote on error %d", st);
        return 0;
    }
    check_factor(&fu, classic ? "reset_classic" : "reset");
    noise_of(&f, &q);
    n = fz_u8(&f) % 48;
    for (k = 0; k < n && fz_left(&f); ++k) {
        se23_imu_sample_t s;
        if (fz_u8(&f) < 16) {
            noise_of(&f, &q);
        }
        fz_sample(&f, &s);
        memcpy(&before, &fu, sizeof fu);
        /* The work-area call on a copy, its work area fuzzed bytes: the
         * same status and, on OK, the same factor. */
        memcpy(&copy, &fu, sizeof fu);
        fz_fill(&w, sizeof w);
        sa = se23_preint_unc_add_work(&copy, &s, &q, &w);
        st = se23_preint_unc_add(&fu, &s, &q);
        FZ_REQUIRE(fz_status_in(st, 3, SE23_ERR_NONFINITE, SE23_ERR_DT, SE23_ERR_DOMAIN),
                   "add: %d", st);
        FZ_REQUIRE(sa == st && memcmp(&copy, &fu, sizeof fu) == 0,
                   "add_work: status %d or factor differ from add (%d)", sa, st);
        if (st != SE23_OK) {
            FZ_REQUIRE(memcmp(&fu, &before, sizeof fu) == 0, "add changed the factor on error %d",
                       st);
            continue;
        }
        FZ_REQUIRE(fu.f.n == before.f.n + 1u, "add: n %u -> %u", (unsigned)before.f.n,
                   (unsigned)fu.f.n);
        if (!fz_check_cov_result(se23_preint_unc_check(&fu), fu.P_left.m, 9, 9,
                                 left_bound(&s, &fu, &q, before.P_left.m), "add")) {
            return 0; /* the known finding: not a factor to go on with */
        }
    }
    one_correct(&f, &fu);
    one_cov(&fu);
    return 0;
}
