/*
 * libFuzzer target of se23/stationary.h: init on a decoded configuration
 * (statuses in the header's set; on SE23_OK an empty detector, on an error
 * the sentinel untouched), then samples pushed (on SE23_OK stat finite and
 * >= 0, the flag 0 or 1 and equal to the detector's, count and head in
 * range; on an error the detector and the flag unchanged), means and
 * variances (on SE23_OK finite, variances >= 0; on an error untouched),
 * resets, and now and then a corrupted window, count or head, which add,
 * mean and var must refuse (SE23_ERR_DIM) without reading or writing out of
 * bounds (AddressSanitizer).
 */
#include "fuzz.h"

#include "se23/stationary.h"

static void check_det(const se23_stationary_t *d, const char *what)
{
    FZ_REQUIRE(d->count >= 0 && d->count <= d->cfg.window && d->head >= 0 &&
                   d->head < d->cfg.window,
               "%s: count %d, head %d, window %d", what, d->count, d->head, d->cfg.window);
    FZ_REQUIRE(isfinite(d->stat) && d->stat >= 0, "%s: stat %g", what, (double)d->stat);
    FZ_REQUIRE(d->stationary == 0 || d->stationary == 1, "%s: stationary %d", what,
               d->stationary);
    FZ_REQUIRE(!d->stationary || (d->count == d->cfg.window && d->stat < d->cfg.threshold),
               "%s: stationary with count %d, stat %g", what, d->count, (double)d->stat);
}

static void one_stats(fz_t *f, const se23_stationary_t *d, int valid)
{
    se23_vec3_t a, b;
    int var;
    for (var = 0; var < 2; ++var) {
        se23_status_t st;
        fz_fill(&a, sizeof a);
        fz_fill(&b, sizeof b);
        st = var ? se23_stationary_var(d, &a, &b) : se23_stationary_mean(d, &a, &b);
        FZ_REQUIRE(fz_status_in(st, 2, SE23_ERR_DIM, SE23_ERR_NONFINITE), "%s: %d",
                   var ? "var" : "mean", st);
        if (!valid) {
            FZ_REQUIRE(st == SE23_ERR_DIM, "%s of a corrupted detector: %d", var ? "var" : "mean",
                       st);
        }
        if (st != SE23_OK) {
            FZ_REQUIRE(fz_untouched(&a, sizeof a) && fz_untouched(&b, sizeof b),
                       "%s wrote on error %d", var ? "var" : "mean", st);
            continue;
        }
        FZ_REQUIRE(d->count == d->cfg.window, "%s: OK on a window not full", var ? "var" : "mean");
        FZ_REQUIRE(FZ_FINITE_OBJ(a) && FZ_FINITE_OBJ(b), "%s: OK with a non-finite output",
                   var ? "var" : "mean");
        if (var) {
            int i;
            for (i = 0; i < 3; ++i) {
                FZ_REQUIRE(a.v[i] >= 0 && b.v[i] >= 0, "var: negative variance");
            }
        }
    }
    (void)f;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_t f;
    se23_stationary_config_t cfg;
    se23_stationary_t d, before;
    se23_status_t st;
    int k;
    uint8_t m;
    fz_init(&f, data, size);
    m = fz_u8(&f);
    if (m < 200) {
        cfg.window = 2 + fz_u8(&f) % (SE23_STATIONARY_WMAX - 1);
        cfg.sigma_a = (se23_real_t)(1 + fz_u8(&f)) * (se23_real_t)1e-3;
        cfg.sigma_g = (se23_real_t)(1 + fz_u8(&f)) * (se23_real_t)1e-4;
        cfg.gravity = (se23_real_t)9.80665;
        cfg.threshold = (se23_real_t)(1 + fz_u8(&f) % 32);
        if (m & 1) { /* one field decoded freely */
            switch (fz_u8(&f) % 5) {
            case 0:
                cfg.window = fz_int(&f);
                break;
            case 1:
                cfg.sigma_a = fz_real(&f);
                break;
            case 2:
                cfg.sigma_g = fz_real(&f);
                break;
            case 3:
                cfg.gravity = fz_real(&f);
                break;
            default:
                cfg.threshold = fz_real(&f);
                break;
            }
        }
    } else {
        cfg.window = fz_int(&f);
        cfg.sigma_a = fz_real(&f);
        cfg.sigma_g = fz_real(&f);
        cfg.gravity = fz_real(&f);
        cfg.threshold = fz_real(&f);
    }
    fz_fill(&d, sizeof d);
    st = se23_stationary_init(&cfg, &d);
    FZ_REQUIRE(fz_status_in(st, 3, SE23_ERR_NONFINITE, SE23_ERR_DIM, SE23_ERR_DOMAIN), "init: %d",
               st);
    if (st != SE23_OK) {
        FZ_REQUIRE(fz_untouched(&d, sizeof d), "init wrote on error %d", st);
        return 0;
    }
    FZ_REQUIRE(d.count == 0 && d.head == 0 && d.stat == 0 && d.stationary == 0,
               "init: not an empty detector");
    check_det(&d, "init");
    for (k = 0; k < 256 && fz_left(&f); ++k) {
        uint8_t op = fz_u8(&f);
        if (op < 216) {
            se23_vec3_t w, a;
            int flag;
            const int want = op & 1;
            if (op < 160) { /* near rest: f ~ (0, 0, -g) */
                int i;
                for (i = 0; i < 3; ++i) {
                    w.v[i] = (se23_real_t)(int8_t)fz_u8(&f) * (se23_real_t)1e-4;
                    a.v[i] = (se23_real_t)(int8_t)fz_u8(&f) * (se23_real_t)1e-3;
                }
                a.v[2] -= (se23_real_t)9.80665;
            } else {
                fz_vec3(&f, &w);
                fz_vec3(&f, &a);
            }
            memcpy(&before, &d, sizeof d);
            fz_fill(&flag, sizeof flag);
            st = se23_stationary_add(&d, &w, &a, want ? &flag : NULL);
            FZ_REQUIRE(fz_status_in(st, 2, SE23_ERR_DIM, SE23_ERR_NONFINITE), "add: %d", st);
            FZ_REQUIRE(st != SE23_ERR_DIM, "add: SE23_ERR_DIM on a valid detector");
            if (st != SE23_OK) {
                FZ_REQUIRE(memcmp(&d, &before, sizeof d) == 0 && fz_untouched(&flag, sizeof flag),
                           "add wrote on error %d", st);
                continue;
            }
            check_det(&d, "add");
            if (want) {
                FZ_REQUIRE(flag == d.stationary, "add: flag %d, detector %d", flag, d.stationary);
            }
        } else if (op < 232) {
            one_stats(&f, &d, 1);
        } else if (op < 240) {
            se23_stationary_reset(&d);
            FZ_REQUIRE(d.count == 0 && d.head == 0 && d.stat == 0 && d.stationary == 0,
                       "reset: not empty");
        } else { /* a corrupted state: refused, nothing touched out of bounds */
            se23_stationary_t bad;
            se23_vec3_t w = {{0, 0, 0}}, a = {{0, 0, (se23_real_t)-9.80665}};
            int flag = 7;
            memcpy(&bad, &d, sizeof d);
            switch (fz_u8(&f) % 3) {
            case 0:
                bad.cfg.window = fz_int(&f);
                break;
            case 1:
                bad.count = fz_int(&f);
                break;
            default:
                bad.head = fz_int(&f);
                break;
            }
            if (bad.cfg.window >= 2 && bad.cfg.window <= SE23_STATIONARY_WMAX && bad.count >= 0 &&
                bad.count <= bad.cfg.window && bad.head >= 0 && bad.head < bad.cfg.window) {
                continue; /* still in range */
            }
            memcpy(&before, &bad, sizeof bad);
            st = se23_stationary_add(&bad, &w, &a, &flag);
            FZ_REQUIRE(st == SE23_ERR_DIM, "add on a corrupted state: %d", st);
            FZ_REQUIRE(memcmp(&bad, &before, sizeof bad) == 0 && flag == 7,
                       "add wrote into a corrupted state");
            /* mean and var do not read head */
            one_stats(&f, &bad,
                      bad.cfg.window >= 2 && bad.cfg.window <= SE23_STATIONARY_WMAX &&
                          bad.count >= 0 && bad.count <= bad.cfg.window);
        }
    }
    return 0;
}
