/*
 * libFuzzer target of se23/imu.h: the three increments and the checked
 * step (statuses in the header's set; on SE23_OK finite, R in SO(3); the
 * sentinel untouched on an error), the unchecked transition and carried
 * conversions (no crash), and every aliasing the header allows ("All
 * functions accept outputs that alias inputs"): step(T, T), transition with
 * out = T, = ups, = gamma, the conversions in place, equal bit for bit to
 * the plain calls. The model is built by the library (fz_model): trusted.
 */
#include "fuzz.h"

#include "se23/imu.h"

typedef se23_status_t (*inc_fn)(const se23_imu_sample_t *, se23_pose_t *);

static void one_increment(fz_t *f, int which)
{
    static const inc_fn fns[] = {se23_imu_increment, se23_imu_increment_forster,
                                 se23_imu_increment_paper};
    se23_imu_sample_t s;
    se23_pose_t U;
    se23_status_t st;
    fz_sample(f, &s);
    fz_fill(&U, sizeof U);
    st = fns[which](&s, &U);
    FZ_REQUIRE(fz_status_in(st, 2, SE23_ERR_NONFINITE, SE23_ERR_DT), "increment %d: %d", which,
               st);
    if (st != SE23_OK) {
        FZ_REQUIRE(fz_untouched(&U, sizeof U), "increment %d wrote on error %d", which, st);
        return;
    }
    FZ_REQUIRE(FZ_FINITE_OBJ(U), "increment %d: OK with a non-finite increment", which);
    FZ_REQUIRE(fz_is_rot(&U.R), "increment %d: OK but R not a rotation (check %d)", which,
               se23_so3_check(&U.R));
}

static void one_step(fz_t *f)
{
    se23_earth_model_t m;
    se23_pose_t T, Tn, Ta;
    se23_imu_sample_t s;
    se23_status_t st, sa;
    int k, n = 1 + fz_u8(f) % 8;
    fz_model(f, &m);
    fz_pose(f, &T);
    for (k = 0; k < n; ++k) {
        fz_sample(f, &s);
        fz_fill(&Tn, sizeof Tn);
        st = se23_imu_step(&m, &T, &s, &Tn);
        FZ_REQUIRE(fz_status_in(st, 3, SE23_ERR_NONFINITE, SE23_ERR_DT, SE23_ERR_NOT_ROTATION),
                   "step: %d", st);
        Ta = T;
        sa = se23_imu_step(&m, &Ta, &s, &Ta);
        FZ_REQUIRE(sa == st, "step: aliased status %d, plain %d", sa, st);
        if (st != SE23_OK) {
            FZ_REQUIRE(fz_untouched(&Tn, sizeof Tn), "step wrote on error %d", st);
            FZ_REQUIRE(FZ_SAME(Ta, T), "step(T, T) changed T on error %d", st);
            return;
        }
        FZ_REQUIRE(FZ_FINITE_OBJ(Tn), "step: OK with a non-finite state");
        FZ_REQUIRE(fz_is_rot(&Tn.R), "step: OK but R not a rotation (check %d)",
                   se23_so3_check(&Tn.R));
        FZ_REQUIRE(FZ_SAME(Ta, Tn), "step(T, T) differs from step(T, Tn)");
        T = Tn;
    }
}

static void one_transition(fz_t *f)
{
    se23_pose_t G, T, U, out, t;
    const int no_gamma = fz_u8(f) < 64;
    se23_real_t dt = fz_dt(f);
    fz_pose(f, &G);
    fz_pose(f, &T);
    fz_pose(f, &U);
    se23_imu_transition(no_gamma ? NULL : &G, &T, &U, dt, &out);
    t = T;
    se23_imu_transition(no_gamma ? NULL : &G, &t, &U, dt, &t);
    FZ_REQUIRE(FZ_SAME(t, out), "transition: out = T differs");
    t = U;
    se23_imu_transition(no_gamma ? NULL : &G, &T, &t, dt, &t);
    FZ_REQUIRE(FZ_SAME(t, out), "transition: out = ups differs");
    if (!no_gamma) {
        t = G;
        se23_imu_transition(&t, &T, &U, dt, &t);
        FZ_REQUIRE(FZ_SAME(t, out), "transition: out = gamma differs");
    }
}

static void one_carried(fz_t *f)
{
    se23_earth_model_t m;
    se23_pose_t T, Tc, t;
    fz_model(f, &m);
    fz_pose(f, &T);
    se23_imu_carried_from_user(&m, &T, &Tc);
    t = T;
    se23_imu_carried_from_user(&m, &t, &t);
    FZ_REQUIRE(FZ_SAME(t, Tc), "carried_from_user in place differs");
    se23_imu_user_from_carried(&m, &Tc, &T);
    t = Tc;
    se23_imu_user_from_carried(&m, &t, &t);
    FZ_REQUIRE(FZ_SAME(t, T), "user_from_carried in place differs");
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_t f;
    int calls = 0;
    fz_init(&f, data, size);
    while (fz_left(&f) && calls++ < 32) {
        uint8_t op = fz_u8(&f) % 6;
        if (op < 3) {
            one_increment(&f, op);
        } else if (op == 3) {
            one_step(&f);
        } else if (op == 4) {
            one_transition(&f);
        } else {
            one_carried(&f);
        }
    }
    return 0;
}
