/*
 * libFuzzer target of se23/so3.h. Every input is a sequence of calls; for
 * each: the status in the header's set; on SE23_OK every output finite,
 * exp and normalize give R in SO(3) (se23_so3_check), log |phi| <= pi,
 * jl_inv only below |phi| < 2 pi - 1e-3; on an error the output still holds
 * the sentinel; normalize(R, R) equals normalize(R, Rn) bit for bit ("All
 * functions accept outputs that alias inputs"; the others take and give
 * different types).
 */
#include "fuzz.h"

#include "se23/so3.h"

typedef se23_status_t (*vec_fn)(const se23_vec3_t *, se23_mat3_t *);

static double norm3(const se23_vec3_t *v)
{
    return sqrt((double)v->v[0] * v->v[0] + (double)v->v[1] * v->v[1] +
                (double)v->v[2] * v->v[2]);
}

static void one_vec_fn(fz_t *f, int which)
{
    static const vec_fn fns[] = {se23_so3_exp, se23_so3_jl, se23_so3_jl_inv, se23_so3_jr,
                                 se23_so3_h, se23_so3_k};
    static const char *const names[] = {"exp", "jl", "jl_inv", "jr", "h", "k"};
    se23_vec3_t phi;
    se23_mat3_t M;
    se23_status_t st;
    if (fz_u8(f) < 128) {
        fz_vec3_mild(f, &phi);
    } else {
        fz_vec3(f, &phi);
    }
    fz_fill(&M, sizeof M);
    st = fns[which](&phi, &M);
    if (which == 2) {
        FZ_REQUIRE(fz_status_in(st, 2, SE23_ERR_NONFINITE, SE23_ERR_DOMAIN), "%s: %d", names[which],
                   st);
    } else {
        FZ_REQUIRE(fz_status_in(st, 1, SE23_ERR_NONFINITE), "%s: %d", names[which], st);
    }
    if (st != SE23_OK) {
        FZ_REQUIRE(fz_untouched(&M, sizeof M), "%s wrote on error %d", names[which], st);
        return;
    }
    FZ_REQUIRE(FZ_FINITE_OBJ(M), "%s: OK with a non-finite output", names[which]);
    if (which == 0) {
        FZ_REQUIRE(fz_is_rot(&M), "exp: OK but not a rotation (check %d)", se23_so3_check(&M));
    }
    if (which == 2) {
        FZ_REQUIRE(norm3(&phi) < (2.0 * 3.14159265358979323846 - 1e-3) * (1.0 + 8.0 * FZ_EPS),
                   "jl_inv: OK at |phi| = %.17g", norm3(&phi));
    }
}

static void one_log(fz_t *f)
{
    se23_mat3_t R;
    se23_vec3_t phi;
    se23_status_t st;
    fz_rot(f, &R);
    fz_fill(&phi, sizeof phi);
    st = se23_so3_log(&R, &phi);
    FZ_REQUIRE(fz_status_in(st, 2, SE23_ERR_NONFINITE, SE23_ERR_NOT_ROTATION), "log: %d", st);
    if (st != SE23_OK) {
        FZ_REQUIRE(fz_untouched(&phi, sizeof phi), "log wrote on error %d", st);
        FZ_REQUIRE(se23_so3_check(&R) != SE23_OK, "log refused (%d) a matrix so3_check accepts",
                   st);
        return;
    }
    FZ_REQUIRE(FZ_FINITE_OBJ(phi), "log: OK with a non-finite phi");
    FZ_REQUIRE(norm3(&phi) <= 3.14159265358979323846 * (1.0 + 16.0 * FZ_EPS),
               "log: |phi| = %.17g > pi", norm3(&phi));
}

static void one_check_normalize(fz_t *f)
{
    se23_mat3_t R, Rn, Ra;
    se23_status_t st, sa;
    fz_rot(f, &R);
    st = se23_so3_check(&R);
    FZ_REQUIRE(fz_status_in(st, 2, SE23_ERR_NONFINITE, SE23_ERR_NOT_ROTATION), "check: %d", st);
    if (st == SE23_OK) {
        FZ_REQUIRE(FZ_FINITE_OBJ(R), "check: OK for a non-finite R");
    }
    fz_fill(&Rn, sizeof Rn);
    st = se23_so3_normalize(&R, &Rn);
    FZ_REQUIRE(fz_status_in(st, 2, SE23_ERR_NONFINITE, SE23_ERR_NOT_ROTATION), "normalize: %d",
               st);
    Ra = R;
    sa = se23_so3_normalize(&Ra, &Ra);
    FZ_REQUIRE(sa == st, "normalize: aliased status %d, plain %d", sa, st);
    if (st != SE23_OK) {
        FZ_REQUIRE(fz_untouched(&Rn, sizeof Rn), "normalize wrote on error %d", st);
        FZ_REQUIRE(FZ_SAME(Ra, R), "normalize(R, R) changed R on error %d", st);
        return;
    }
    FZ_REQUIRE(FZ_FINITE_OBJ(Rn), "normalize: OK with a non-finite output");
    FZ_REQUIRE(fz_is_rot(&Rn), "normalize: OK but not a rotation (check %d)",
               se23_so3_check(&Rn));
    FZ_REQUIRE(FZ_SAME(Ra, Rn), "normalize(R, R) differs from normalize(R, Rn)");
}

static void one_hat_vee(fz_t *f)
{
    se23_vec3_t phi, back;
    se23_mat3_t W;
    fz_vec3(f, &phi);
    se23_so3_hat(&phi, &W);
    se23_so3_vee(&W, &back);
    if (FZ_FINITE_OBJ(phi)) {
        int i, j;
        for (i = 0; i < 3; ++i) {
            for (j = 0; j < 3; ++j) {
                FZ_REQUIRE(W.m[i][j] == -W.m[j][i], "hat: not skew at (%d, %d)", i, j);
            }
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_t f;
    int calls = 0;
    fz_init(&f, data, size);
    while (fz_left(&f) && calls++ < 64) {
        uint8_t op = fz_u8(&f) % 9;
        if (op < 6) {
            one_vec_fn(&f, op);
        } else if (op == 6) {
            one_log(&f);
        } else if (op == 7) {
            one_check_normalize(&f);
        } else {
            one_hat_vee(&f);
        }
    }
    return 0;
}
