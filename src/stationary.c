/* The SHOE stationary detector; see stationary.h. The window is positions
 * 0..n-1 of the ring buffer; a pending add is evaluated with the new sample
 * substituted at position head, so that nothing is stored before the
 * statistic is known to be finite. */
#include "se23/stationary.h"

#include "argcheck.h"
#include "linalg.h"
#include "se23_math.h"

/* A configured sigma: > 0 with sigma^2 and 1/sigma^2 finite. */
static int sigma_ok(se23_real_t sigma)
{
    const se23_real_t var = sigma * sigma;
    return (sigma > SE23_R(0)) && (se23_is_finite(var) != 0) &&
           (se23_is_finite(SE23_R(1) / var) != 0);
}

/* The state's indices in range: 2 <= W <= WMAX, 0 <= count <= W,
 * 0 <= head < W. */
static int state_ok(const se23_stationary_t *d)
{
    const int W = d->cfg.window;
    return (W >= 2) && (W <= SE23_STATIONARY_WMAX) && (d->count >= 0) &&
           (d->count <= W) && (d->head >= 0) && (d->head < W);
}

/* Position i of buf, or x where i == sub (the pending sample). */
static const se23_vec3_t *pick(const se23_vec3_t *buf, int i, int sub,
                               const se23_vec3_t *x)
{
    return (i == sub) ? x : &buf[i];
}

/* mean = (1/n) sum_{i < n} pick(buf, i, sub, x), n >= 1. */
static void window_mean(const se23_vec3_t *buf, int n, int sub,
                        const se23_vec3_t *x, se23_vec3_t *mean)
{
    se23_vec3_t s = {{SE23_R(0), SE23_R(0), SE23_R(0)}};
    for (int i = 0; i < n; ++i) {
        const se23_vec3_t *a = pick(buf, i, sub, x);
        s.v[0] += a->v[0];
        s.v[1] += a->v[1];
        s.v[2] += a->v[2];
    }
    se23_v3_scale(&s, SE23_R(1) / (se23_real_t)n, mean);
}

/* sum_{i < n} (pick(buf, i, sub, x) - mean)_j^2 per axis j. */
static void window_sq_dev(const se23_vec3_t *buf, int n, int sub,
                          const se23_vec3_t *x, const se23_vec3_t *mean,
                          se23_vec3_t *sq)
{
    se23_vec3_t s = {{SE23_R(0), SE23_R(0), SE23_R(0)}};
    for (int i = 0; i < n; ++i) {
        const se23_vec3_t *a = pick(buf, i, sub, x);
        for (int j = 0; j < 3; ++j) {
            const se23_real_t e = a->v[j] - mean->v[j];
            s.v[j] += e * e;
        }
    }
    *sq = s;
}

/* T over the n samples of the window with (w_new, f_new) at position sub
 * (file comment of stationary.h):
 *   n T = (sum |f_k - fbar|^2 + n (|fbar| - g)^2) / sigma_a^2
 *         + sum |w_k|^2 / sigma_g^2. */
static se23_real_t statistic(const se23_stationary_t *d, int n, int sub,
                             const se23_vec3_t *w_new, const se23_vec3_t *f_new)
{
    se23_vec3_t fbar;
    se23_vec3_t sq_f;
    window_mean(d->f, n, sub, f_new, &fbar);
    window_sq_dev(d->f, n, sub, f_new, &fbar, &sq_f);
    se23_real_t sw = SE23_R(0);
    for (int i = 0; i < n; ++i) {
        const se23_vec3_t *w = pick(d->w, i, sub, w_new);
        sw += se23_v3_dot(w, w);
    }
    const se23_real_t nr = (se23_real_t)n;
    const se23_real_t r = se23_sqrt(se23_v3_dot(&fbar, &fbar)) - d->cfg.gravity;
    const se23_real_t sa2 = d->cfg.sigma_a * d->cfg.sigma_a;
    const se23_real_t sg2 = d->cfg.sigma_g * d->cfg.sigma_g;
    const se23_real_t acc = (sq_f.v[0] + sq_f.v[1] + sq_f.v[2]) + nr * (r * r);
    return (acc / sa2 + sw / sg2) / nr;
}

se23_status_t se23_stationary_init(const se23_stationary_config_t *cfg,
                                   se23_stationary_t *d)
{
    SE23_CHECK_NOT_NULL(cfg);
    SE23_CHECK_NOT_NULL(d);
    if ((se23_is_finite(cfg->sigma_a) == 0) || (se23_is_finite(cfg->sigma_g) == 0) ||
        (se23_is_finite(cfg->gravity) == 0) || (se23_is_finite(cfg->threshold) == 0)) {
        return SE23_ERR_NONFINITE;
    }
    if ((cfg->window < 2) || (cfg->window > SE23_STATIONARY_WMAX)) {
        return SE23_ERR_DIM;
    }
    if ((sigma_ok(cfg->sigma_a) == 0) || (sigma_ok(cfg->sigma_g) == 0) ||
        !(cfg->gravity > SE23_R(0)) || !(cfg->threshold > SE23_R(0))) {
        return SE23_ERR_DOMAIN;
    }
    d->cfg = *cfg;
    for (int i = 0; i < SE23_STATIONARY_WMAX; ++i) {
        for (int j = 0; j < 3; ++j) {
            d->w[i].v[j] = SE23_R(0);
            d->f[i].v[j] = SE23_R(0);
        }
    }
    se23_stationary_reset(d);
    return SE23_OK;
}

se23_status_t se23_stationary_add(se23_stationary_t *d, const se23_vec3_t *w_b,
                                  const se23_vec3_t *f_b, int *stationary)
{
    SE23_CHECK_NOT_NULL(d);
    SE23_CHECK_NOT_NULL(w_b);
    SE23_CHECK_NOT_NULL(f_b);
    if (state_ok(d) == 0) {
        return SE23_ERR_DIM;
    }
    if ((se23_all_finite(w_b->v, 3) == 0) || (se23_all_finite(f_b->v, 3) == 0)) {
        return SE23_ERR_NONFINITE;
    }
    const int W = d->cfg.window;
    const int sub = d->head;
    int n = W;
    if (d->count < W) {
        n = d->count + 1;
    }
    const se23_real_t stat = statistic(d, n, sub, w_b, f_b);
    if (se23_is_finite(stat) == 0) {
        return SE23_ERR_NONFINITE;
    }
    int flag = 0;
    if ((n == W) && (stat < d->cfg.threshold)) {
        flag = 1;
    }
    d->w[sub] = *w_b;
    d->f[sub] = *f_b;
    d->count = n;
    d->head = sub + 1;
    if (d->head == W) {
        d->head = 0;
    }
    d->stat = stat;
    d->stationary = flag;
    if (stationary != NULL) {
        *stationary = flag;
    }
    return SE23_OK;
}

void se23_stationary_reset(se23_stationary_t *d)
{
    d->count = 0;
    d->head = 0;
    d->stat = SE23_R(0);
    d->stationary = 0;
}

/* Shared checks of mean and var: a valid state with a full window. */
static se23_status_t check_full(const se23_stationary_t *d)
{
    if ((state_ok(d) == 0) || (d->count != d->cfg.window)) {
        return SE23_ERR_DIM;
    }
    return SE23_OK;
}

se23_status_t se23_stationary_mean(const se23_stationary_t *d,
                                   se23_vec3_t *w_mean, se23_vec3_t *f_mean)
{
    SE23_CHECK_NOT_NULL(d);
    SE23_CHECK_NOT_NULL(w_mean);
    SE23_CHECK_NOT_NULL(f_mean);
    const se23_status_t st = check_full(d);
    if (st != SE23_OK) {
        return st;
    }
    se23_vec3_t wm;
    se23_vec3_t fm;
    window_mean(d->w, d->count, -1, NULL, &wm);
    window_mean(d->f, d->count, -1, NULL, &fm);
    if ((se23_all_finite(wm.v, 3) == 0) || (se23_all_finite(fm.v, 3) == 0)) {
        return SE23_ERR_NONFINITE;
    }
    *w_mean = wm;
    *f_mean = fm;
    return SE23_OK;
}

se23_status_t se23_stationary_var(const se23_stationary_t *d,
                                  se23_vec3_t *w_var, se23_vec3_t *f_var)
{
    SE23_CHECK_NOT_NULL(d);
    SE23_CHECK_NOT_NULL(w_var);
    SE23_CHECK_NOT_NULL(f_var);
    const se23_status_t st = check_full(d);
    if (st != SE23_OK) {
        return st;
    }
    const int n = d->count;
    const int dof = n - 1;
    const se23_real_t inv = SE23_R(1) / (se23_real_t)dof;
    se23_vec3_t mean;
    se23_vec3_t wv;
    se23_vec3_t fv;
    window_mean(d->w, n, -1, NULL, &mean);
    window_sq_dev(d->w, n, -1, NULL, &mean, &wv);
    window_mean(d->f, n, -1, NULL, &mean);
    window_sq_dev(d->f, n, -1, NULL, &mean, &fv);
    se23_v3_scale(&wv, inv, &wv);
    se23_v3_scale(&fv, inv, &fv);
    if ((se23_all_finite(wv.v, 3) == 0) || (se23_all_finite(fv.v, 3) == 0)) {
        return SE23_ERR_NONFINITE;
    }
    *w_var = wv;
    *f_var = fv;
    return SE23_OK;
}
