/*
 * libFuzzer target of se23/align.h: levelling, the attitude covariance and
 * gyrocompassing, on the readings of a body at rest in a decoded attitude
 * (so that the deep paths are reached) perturbed or replaced by decoded
 * values, with any frame and n. Statuses in the header's set; on SE23_OK R
 * in SO(3) (se23_so3_check), P symmetric PSD (se23_gauss_check of P in an
 * otherwise empty state), yaw in [-pi, pi], 0 <= sigma_yaw <=
 * SE23_ALIGN_YAW_STD_MAX (0: a denormal sigma_w underflows), everything
 * finite; on an error every output still
 * holds the sentinel ("write their outputs only on SE23_OK").
 */
#include "fuzz.h"

#include "se23/align.h"

static void mulT(const se23_mat3_t *R, const double x[3], se23_vec3_t *y)
{
    int i;
    for (i = 0; i < 3; ++i) {
        y->v[i] = (se23_real_t)((double)R->m[0][i] * x[0] + (double)R->m[1][i] * x[1] +
                                (double)R->m[2][i] * x[2]);
    }
}

static void perturb(fz_t *f, se23_vec3_t *v)
{
    uint8_t m = fz_u8(f);
    int i;
    if (m < 96) {
        return;
    }
    if (m < 224) {
        double scale = pow(10.0, -(int)(fz_u8(f) % 12));
        for (i = 0; i < 3; ++i) {
            v->v[i] += (se23_real_t)((double)(int8_t)fz_u8(f) / 128.0 * scale);
        }
        return;
    }
    v->v[fz_u8(f) % 3] = fz_real(f);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_t f;
    int calls = 0;
    fz_init(&f, data, size);
    while (fz_left(&f) && calls++ < 16) {
        se23_mat3_t Rt, R, P;
        se23_vec3_t fm, wm;
        se23_real_t lat, yaw, sigma_yaw, sigma_w, sigma_f, g, yaw_in;
        se23_status_t st;
        uint8_t m = fz_u8(&f);
        se23_frame_t frame = (se23_frame_t)(m < 240 ? (int)(m & 1) : fz_int(&f));
        int n = fz_u8(&f) < 224 ? 1 + fz_u8(&f) : fz_int(&f);
        const double W = SE23_WGS84_OMEGA_E, g0 = 9.80665;
        lat = fz_u8(&f) < 224 ? (se23_real_t)((double)(int16_t)fz_u16(&f) / 32767.0 * 1.5707973)
                              : fz_real(&f);
        fz_rot(&f, &Rt);
        {
            const double cl = cos((double)lat), sl = sin((double)lat);
            const double up[3] = {0.0, 0.0, frame == SE23_FRAME_ENU ? g0 : -g0};
            const double w_ned[3] = {W * cl, 0.0, -W * sl}, w_enu[3] = {0.0, W * cl, W * sl};
            mulT(&Rt, up, &fm);
            mulT(&Rt, frame == SE23_FRAME_ENU ? w_enu : w_ned, &wm);
        }
        perturb(&f, &fm);
        perturb(&f, &wm);
        yaw_in = fz_u8(&f) < 192 ? fz_mild(&f) : fz_real(&f);

        fz_fill(&R, sizeof R);
        st = se23_align_level(frame, &fm, yaw_in, &R);
        FZ_REQUIRE(fz_status_in(st, 2, SE23_ERR_NONFINITE, SE23_ERR_DOMAIN), "level: %d", st);
        if (st != SE23_OK) {
            FZ_REQUIRE(fz_untouched(&R, sizeof R), "level wrote on error %d", st);
        } else {
            FZ_REQUIRE(FZ_FINITE_OBJ(R), "level: OK with a non-finite R");
            FZ_REQUIRE(fz_is_rot(&R), "level: OK but R not a rotation (check %d)",
                       se23_so3_check(&R));
        }

        sigma_w = fz_u8(&f) < 192 ? (se23_real_t)(1 + fz_u8(&f)) * (se23_real_t)1e-7 : fz_real(&f);
        fz_fill(&R, sizeof R);
        fz_fill(&yaw, sizeof yaw);
        fz_fill(&sigma_yaw, sizeof sigma_yaw);
        st = se23_align_gyrocompass(frame, lat, &fm, &wm, sigma_w, n, &R, &yaw, &sigma_yaw);
        FZ_REQUIRE(fz_status_in(st, 3, SE23_ERR_NONFINITE, SE23_ERR_DIM, SE23_ERR_DOMAIN),
                   "gyrocompass: %d", st);
        if (st != SE23_OK) {
            FZ_REQUIRE(fz_untouched(&R, sizeof R) && fz_untouched(&yaw, sizeof yaw) &&
                           fz_untouched(&sigma_yaw, sizeof sigma_yaw),
                       "gyrocompass wrote on error %d", st);
            fz_rot(&f, &R);
            sigma_yaw = fz_u8(&f) < 192 ? (se23_real_t)0.01 : fz_real(&f);
        } else {
            FZ_REQUIRE(FZ_FINITE_OBJ(R), "gyrocompass: OK with a non-finite R");
            FZ_REQUIRE(fz_is_rot(&R), "gyrocompass: OK but R not a rotation (check %d)",
                       se23_so3_check(&R));
            FZ_REQUIRE(isfinite(yaw) && fabs((double)yaw) <= 3.14159265358979323846 *
                                                                 (1.0 + 4.0 * FZ_EPS),
                       "gyrocompass: yaw %g", (double)yaw);
            FZ_REQUIRE(isfinite(sigma_yaw) && sigma_yaw >= 0 &&
                           sigma_yaw <= (se23_real_t)SE23_ALIGN_YAW_STD_MAX,
                       "gyrocompass: sigma_yaw %g", (double)sigma_yaw);
        }

        sigma_f = fz_u8(&f) < 192 ? (se23_real_t)(1 + fz_u8(&f)) * (se23_real_t)1e-4 : fz_real(&f);
        g = fz_u8(&f) < 192 ? (se23_real_t)g0 : fz_real(&f);
        fz_fill(&P, sizeof P);
        st = se23_align_cov(&R, sigma_f, n, g, sigma_yaw, &P);
        FZ_REQUIRE(fz_status_in(st, 4, SE23_ERR_NONFINITE, SE23_ERR_DIM, SE23_ERR_DOMAIN,
                                SE23_ERR_NOT_ROTATION),
                   "cov: %d", st);
        if (st != SE23_OK) {
            FZ_REQUIRE(fz_untouched(&P, sizeof P), "cov wrote on error %d", st);
        } else {
            se23_status_t c = fz_cov_check(&P.m[0][0], 3, 3);
            FZ_REQUIRE(FZ_FINITE_OBJ(P), "cov: OK with a non-finite P");
            FZ_REQUIRE(c == SE23_OK, "cov: OK but P fails the covariance check (%d)", c);
        }
    }
    return 0;
}
