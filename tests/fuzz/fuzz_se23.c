/*
 * libFuzzer target of se23/se23.h. The void functions promise no checks
 * (NaN in, NaN out): they must not crash, and their aliased calls (compose
 * with AB = A, AB = B, A = B = AB; inverse and act in place) must equal the
 * plain ones bit for bit. The checked ones (from_mat5, exp, log,
 * pose_check): statuses in the header's set, finite outputs and R in SO(3)
 * on SE23_OK, the sentinel untouched on an error.
 */
#include "fuzz.h"

#include "se23/se23.h"

static void one_compose(fz_t *f)
{
    se23_pose_t A, B, AB, t;
    fz_pose(f, &A);
    fz_pose(f, &B);
    se23_compose(&A, &B, &AB);
    t = A;
    se23_compose(&t, &B, &t);
    FZ_REQUIRE(FZ_SAME(t, AB), "compose(A, B, A) differs from compose(A, B, AB)");
    t = B;
    se23_compose(&A, &t, &t);
    FZ_REQUIRE(FZ_SAME(t, AB), "compose(A, B, B) differs from compose(A, B, AB)");
    se23_compose(&A, &A, &AB);
    t = A;
    se23_compose(&t, &t, &t);
    FZ_REQUIRE(FZ_SAME(t, AB), "compose(A, A, A) differs from compose(A, A, AB)");
}

static void one_inverse_act(fz_t *f)
{
    se23_pose_t T, Ti, t;
    se23_vec3_t x, y, z;
    fz_pose(f, &T);
    se23_inverse(&T, &Ti);
    t = T;
    se23_inverse(&t, &t);
    FZ_REQUIRE(FZ_SAME(t, Ti), "inverse(T, T) differs from inverse(T, Ti)");
    fz_vec3(f, &x);
    se23_act(&T, &x, &y);
    z = x;
    se23_act(&T, &z, &z);
    FZ_REQUIRE(FZ_SAME(z, y), "act(T, x, x) differs from act(T, x, y)");
}

static void one_mat5(fz_t *f)
{
    se23_pose_t T, back;
    se23_mat5_t M;
    se23_tangent_t xi;
    se23_status_t st;
    fz_pose(f, &T);
    se23_to_mat5(&T, &M);
    if (fz_u8(f) >= 128) { /* perturb an entry, the bottom rows included */
        M.m[fz_u8(f) % 5][fz_u8(f) % 5] = fz_real(f);
    }
    se23_vee(&M, &xi);
    se23_hat(&xi, &M);
    se23_to_mat5(&T, &M);
    if (fz_u8(f) >= 100) {
        M.m[fz_u8(f) % 5][fz_u8(f) % 5] = fz_real(f);
    }
    fz_fill(&back, sizeof back);
    st = se23_from_mat5(&M, &back);
    FZ_REQUIRE(fz_status_in(st, 3, SE23_ERR_NONFINITE, SE23_ERR_NOT_ROTATION, SE23_ERR_DOMAIN),
               "from_mat5: %d", st);
    if (st != SE23_OK) {
        FZ_REQUIRE(fz_untouched(&back, sizeof back), "from_mat5 wrote on error %d", st);
        return;
    }
    FZ_REQUIRE(FZ_FINITE_OBJ(back), "from_mat5: OK with a non-finite pose");
    FZ_REQUIRE(fz_is_rot(&back.R), "from_mat5: OK but R not a rotation");
}

static void one_exp_log(fz_t *f)
{
    se23_tangent_t xi, back;
    se23_pose_t T;
    se23_status_t st;
    int i;
    for (i = 0; i < 9; ++i) {
        xi.v[i] = fz_u8(f) < 160 ? fz_mild(f) : fz_real(f);
    }
    fz_fill(&T, sizeof T);
    st = se23_exp(&xi, &T);
    FZ_REQUIRE(fz_status_in(st, 1, SE23_ERR_NONFINITE), "exp: %d", st);
    if (st != SE23_OK) {
        FZ_REQUIRE(fz_untouched(&T, sizeof T), "exp wrote on error %d", st);
        fz_pose(f, &T);
    } else {
        FZ_REQUIRE(FZ_FINITE_OBJ(T), "exp: OK with a non-finite pose");
        FZ_REQUIRE(fz_is_rot(&T.R), "exp: OK but R not a rotation (check %d)",
                   se23_so3_check(&T.R));
        if (fz_u8(f) >= 192) {
            fz_pose(f, &T);
        }
    }
    fz_fill(&back, sizeof back);
    st = se23_log(&T, &back);
    FZ_REQUIRE(fz_status_in(st, 2, SE23_ERR_NONFINITE, SE23_ERR_NOT_ROTATION), "log: %d", st);
    if (st != SE23_OK) {
        FZ_REQUIRE(fz_untouched(&back, sizeof back), "log wrote on error %d", st);
        return;
    }
    FZ_REQUIRE(FZ_FINITE_OBJ(back), "log: OK with a non-finite xi");
}

static void one_adjoint_check(fz_t *f)
{
    se23_pose_t T;
    se23_mat9_t Ad, Adi;
    se23_status_t st;
    fz_pose(f, &T);
    se23_adjoint(&T, &Ad);
    se23_adjoint_inv(&T, &Adi);
    st = se23_pose_check(&T);
    FZ_REQUIRE(fz_status_in(st, 2, SE23_ERR_NONFINITE, SE23_ERR_NOT_ROTATION), "pose_check: %d",
               st);
    if (st == SE23_OK) {
        FZ_REQUIRE(FZ_FINITE_OBJ(T) && fz_is_rot(&T.R), "pose_check: OK for an invalid pose");
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_t f;
    int calls = 0;
    fz_init(&f, data, size);
    while (fz_left(&f) && calls++ < 64) {
        switch (fz_u8(&f) % 5) {
        case 0:
            one_compose(&f);
            break;
        case 1:
            one_inverse_act(&f);
            break;
        case 2:
            one_mat5(&f);
            break;
        case 3:
            one_exp_log(&f);
            break;
        default:
            one_adjoint_check(&f);
            break;
        }
    }
    return 0;
}
