/*
 * libFuzzer target of se23/earth.h: gravity, gravity vector, Earth rate,
 * Gamma'(t), the model initialisers, with arbitrary (also unknown) frames.
 * Statuses in the header's set; on SE23_OK every output finite, Gamma^R in
 * SO(3), a model with 0 < dt <= dt_max <= SE23_CFG_DT_MAX; on an error the
 * output still holds the sentinel ("write their outputs only on SE23_OK").
 */
#include "fuzz.h"

#include "se23/earth.h"

static se23_real_t lat_of(fz_t *f)
{
    return fz_u8(f) < 192 ? (se23_real_t)((double)(int16_t)fz_u16(f) / 32767.0 * 1.5707973)
                          : fz_real(f);
}

static se23_real_t h_of(fz_t *f)
{
    return fz_u8(f) < 192 ? (se23_real_t)((double)(int16_t)fz_u16(f) * 4.0) : fz_real(f);
}

static se23_frame_t frame_of(fz_t *f)
{
    uint8_t m = fz_u8(f);
    return (se23_frame_t)(m < 240 ? (int)(m & 1) : fz_int(f));
}

static void check_model(const se23_earth_model_t *m, const char *what)
{
    FZ_REQUIRE(FZ_FINITE_OBJ(*m), "%s: OK with a non-finite model", what);
    FZ_REQUIRE(fz_is_rot(&m->gamma.R), "%s: OK but Gamma^R not a rotation (check %d)", what,
               se23_so3_check(&m->gamma.R));
    FZ_REQUIRE(m->dt > 0 && m->dt <= m->dt_max && m->dt_max <= (se23_real_t)SE23_CFG_DT_MAX,
               "%s: OK with dt %g, dt_max %g", what, (double)m->dt, (double)m->dt_max);
}

static void one_gravity(fz_t *f)
{
    se23_real_t lat = lat_of(f), h = h_of(f), g;
    se23_vec3_t v;
    se23_frame_t fr = frame_of(f);
    se23_status_t st;
    fz_fill(&g, sizeof g);
    st = se23_earth_gravity(lat, h, &g);
    FZ_REQUIRE(fz_status_in(st, 2, SE23_ERR_NONFINITE, SE23_ERR_DOMAIN), "gravity: %d", st);
    if (st != SE23_OK) {
        FZ_REQUIRE(fz_untouched(&g, sizeof g), "gravity wrote on error %d", st);
    } else {
        FZ_REQUIRE(isfinite(g) && g > 0, "gravity: OK with g = %g", (double)g);
    }
    fz_fill(&v, sizeof v);
    st = se23_earth_gravity_vec(fr, lat, h, &v);
    FZ_REQUIRE(fz_status_in(st, 2, SE23_ERR_NONFINITE, SE23_ERR_DOMAIN), "gravity_vec: %d", st);
    if (st != SE23_OK) {
        FZ_REQUIRE(fz_untouched(&v, sizeof v), "gravity_vec wrote on error %d", st);
    } else {
        FZ_REQUIRE(FZ_FINITE_OBJ(v), "gravity_vec: OK with a non-finite vector");
    }
    fz_fill(&v, sizeof v);
    st = se23_earth_rate(fr, lat, &v);
    FZ_REQUIRE(fz_status_in(st, 2, SE23_ERR_NONFINITE, SE23_ERR_DOMAIN), "rate: %d", st);
    if (st != SE23_OK) {
        FZ_REQUIRE(fz_untouched(&v, sizeof v), "rate wrote on error %d", st);
    } else {
        FZ_REQUIRE(FZ_FINITE_OBJ(v), "rate: OK with a non-finite vector");
    }
}

static void one_gamma(fz_t *f)
{
    se23_vec3_t g_n, w;
    se23_real_t t;
    se23_pose_t G;
    se23_status_t st;
    if (fz_u8(f) < 128) {
        fz_vec3_mild(f, &g_n);
        fz_vec3_mild(f, &w);
    } else {
        fz_vec3(f, &g_n);
        fz_vec3(f, &w);
    }
    t = fz_u8(f) < 64 ? fz_dt(f) : fz_real(f);
    fz_fill(&G, sizeof G);
    st = se23_earth_gamma(&g_n, &w, t, &G);
    FZ_REQUIRE(fz_status_in(st, 2, SE23_ERR_NONFINITE, SE23_ERR_DT), "gamma: %d", st);
    if (st != SE23_OK) {
        FZ_REQUIRE(fz_untouched(&G, sizeof G), "gamma wrote on error %d", st);
        return;
    }
    FZ_REQUIRE(FZ_FINITE_OBJ(G), "gamma: OK with a non-finite Gamma");
    FZ_REQUIRE(fz_is_rot(&G.R), "gamma: OK but Gamma^R not a rotation (check %d)",
               se23_so3_check(&G.R));
}

static void one_model(fz_t *f)
{
    se23_vec3_t g_n, w;
    se23_real_t dt = fz_dt(f), dt_max = fz_u8(f) < 128 ? (se23_real_t)SE23_CFG_DT_MAX : fz_dt(f);
    se23_earth_model_t m;
    se23_status_t st;
    if (fz_u8(f) < 128) {
        fz_vec3_mild(f, &g_n);
        fz_vec3_mild(f, &w);
    } else {
        fz_vec3(f, &g_n);
        fz_vec3(f, &w);
    }
    fz_fill(&m, sizeof m);
    st = se23_earth_model_init(&g_n, &w, dt, dt_max, &m);
    FZ_REQUIRE(fz_status_in(st, 2, SE23_ERR_NONFINITE, SE23_ERR_DT), "model_init: %d", st);
    if (st != SE23_OK) {
        FZ_REQUIRE(fz_untouched(&m, sizeof m), "model_init wrote on error %d", st);
    } else {
        check_model(&m, "model_init");
    }
    {
        se23_frame_t fr = frame_of(f);
        se23_real_t lat = lat_of(f), h = h_of(f);
        fz_fill(&m, sizeof m);
        st = se23_earth_model_init_wgs84(fr, lat, h, dt, dt_max, &m);
        FZ_REQUIRE(fz_status_in(st, 3, SE23_ERR_NONFINITE, SE23_ERR_DOMAIN, SE23_ERR_DT),
                   "model_init_wgs84: %d", st);
        if (st != SE23_OK) {
            FZ_REQUIRE(fz_untouched(&m, sizeof m), "model_init_wgs84 wrote on error %d", st);
        } else {
            check_model(&m, "model_init_wgs84");
        }
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_t f;
    int calls = 0;
    fz_init(&f, data, size);
    while (fz_left(&f) && calls++ < 32) {
        switch (fz_u8(&f) % 3) {
        case 0:
            one_gravity(&f);
            break;
        case 1:
            one_gamma(&f);
            break;
        default:
            one_model(&f);
            break;
        }
    }
    return 0;
}
