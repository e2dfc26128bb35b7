/*
 * libFuzzer target of se23/preint.h: a factor from reset or decoded raw
 * (se23_preint_add checks the factor it is handed), a run of samples added
 * (on SE23_OK finite Deltas, Delta R in SO(3), dt and n grown; on an error
 * the factor unchanged), unchecked increments, and the predictions on
 * decoded states (statuses in the header's set; on SE23_OK finite, R in
 * SO(3); the sentinel untouched on an error).
 */
#include "fuzz.h"

#include "se23/preint.h"

static void check_predict(se23_status_t st, const se23_pose_t *Tj, const char *what)
{
    FZ_REQUIRE(fz_status_in(st, 3, SE23_ERR_NONFINITE, SE23_ERR_NOT_ROTATION, SE23_ERR_DT),
               "%s: %d", what, st);
    if (st != SE23_OK) {
        FZ_REQUIRE(fz_untouched(Tj, sizeof *Tj), "%s wrote on error %d", what, st);
        return;
    }
    FZ_REQUIRE(FZ_FINITE_OBJ(*Tj), "%s: OK with a non-finite state", what);
    FZ_REQUIRE(fz_is_rot(&Tj->R), "%s: OK but R not a rotation (check %d)", what,
               se23_so3_check(&Tj->R));
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_t f;
    se23_preint_t fac, before;
    se23_earth_model_t m;
    se23_pose_t Ti, Tj;
    se23_status_t st;
    int k, n;
    fz_init(&f, data, size);
    fz_model(&f, &m);
    if (fz_u8(&f) < 224) {
        se23_preint_reset(&fac);
    } else {
        memset(&fac, 0, sizeof fac);
        fz_pose(&f, &fac.delta);
        fac.dt = fz_real(&f);
        fac.n = fz_u32(&f);
    }
    n = fz_u8(&f) % 48;
    for (k = 0; k < n && fz_left(&f); ++k) {
        se23_imu_sample_t s;
        uint8_t op = fz_u8(&f);
        fz_sample(&f, &s);
        if (op < 16) { /* an unchecked increment: must not crash */
            se23_pose_t U;
            if (se23_imu_increment(&s, &U) == SE23_OK) {
                se23_preint_add_increment(&fac, &U, s.dt);
            }
            continue;
        }
        memcpy(&before, &fac, sizeof fac);
        st = se23_preint_add(&fac, &s);
        FZ_REQUIRE(fz_status_in(st, 3, SE23_ERR_NONFINITE, SE23_ERR_DT, SE23_ERR_NOT_ROTATION),
                   "add: %d", st);
        if (st != SE23_OK) {
            FZ_REQUIRE(memcmp(&fac.delta, &before.delta, sizeof fac.delta) == 0 &&
                           memcmp(&fac.dt, &before.dt, sizeof fac.dt) == 0 && fac.n == before.n,
                       "add changed the factor on error %d", st);
            continue;
        }
        FZ_REQUIRE(FZ_FINITE_OBJ(fac.delta) && isfinite(fac.dt),
                   "add: OK with a non-finite factor");
        FZ_REQUIRE(fz_is_rot(&fac.delta.R), "add: OK but Delta R not a rotation (check %d)",
                   se23_so3_check(&fac.delta.R));
        FZ_REQUIRE(fac.dt >= before.dt && fac.n == before.n + 1u, "add: dt %g -> %g, n %u -> %u",
                   (double)before.dt, (double)fac.dt, (unsigned)before.n, (unsigned)fac.n);
    }
    fz_pose(&f, &Ti);
    fz_fill(&Tj, sizeof Tj);
    check_predict(se23_preint_predict(&m, &fac, &Ti, &Tj), &Tj, "predict");
    fz_fill(&Tj, sizeof Tj);
    check_predict(se23_preint_predict_carried(&m, &fac, &Ti, &Tj), &Tj, "predict_carried");
    return 0;
}
