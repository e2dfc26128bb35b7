/* The SHOE stationary detector; see stationary.h. The window is positions
 * 0..n-1 of the ring buffer, its statistic kept by the running sums of its
 * two parts (stationary.h, "Running sums"); a pending add works on copies
 * of the sums, so that nothing is stored before the statistic is known to
 * be finite. */
#include "se23/stationary.h"

#include "../base/argcheck.h"
#include "../base/linalg.h"
#include "../base/se23_math.h"

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

/* Sums of an empty part (reference 0). */
static void part_clear(se23_stationary_sums_t *p)
{
    for (int j = 0; j < 3; ++j) {
        p->c.v[j] = SE23_R(0);
        p->sf.v[j] = SE23_R(0);
        p->sw.v[j] = SE23_R(0);
    }
    p->qf = SE23_R(0);
    p->qw = SE23_R(0);
}

/* The terms of one sample (w, f) added to part p (s = 1) or removed from it
 * (s = -1): the same values both ways, so that a removal takes back what
 * the addition put in to the rounding of the sums. 8 additions and 6
 * multiply-adds. */
static void part_acc(se23_stationary_sums_t *p, const se23_vec3_t *w, const se23_vec3_t *f,
                     se23_real_t s)
{
    const se23_real_t e0 = f->v[0] - p->c.v[0];
    const se23_real_t e1 = f->v[1] - p->c.v[1];
    const se23_real_t e2 = f->v[2] - p->c.v[2];
    const se23_real_t qf = (e0 * e0) + (e1 * e1) + (e2 * e2);
    const se23_real_t qw = (w->v[0] * w->v[0]) + (w->v[1] * w->v[1]) + (w->v[2] * w->v[2]);
    p->sf.v[0] += s * e0;
    p->sf.v[1] += s * e1;
    p->sf.v[2] += s * e2;
    p->sw.v[0] += s * w->v[0];
    p->sw.v[1] += s * w->v[1];
    p->sw.v[2] += s * w->v[2];
    p->qf += s * qf;
    p->qw += s * qw;
}

/* fbar of a window of n >= 1 samples, n_o of them in the older part:
 * c_r + (sf_r + sf_o + n_o (c_o - c_r)) / n (the older part's sums are 0
 * when it holds nothing). */
static void window_fbar(const se23_stationary_sums_t *r, const se23_stationary_sums_t *o,
                        int n_o, int n, se23_vec3_t *fbar)
{
    const se23_real_t no = (se23_real_t)n_o;
    const se23_real_t inv = SE23_R(1) / (se23_real_t)n;
    for (int j = 0; j < 3; ++j) {
        const se23_real_t s = r->sf.v[j] + o->sf.v[j] + (no * (o->c.v[j] - r->c.v[j]));
        fbar->v[j] = r->c.v[j] + (s * inv);
    }
}

/* sum over part p (n_p samples) of |f_k - fbar|^2 =
 * sum |f_k - c|^2 - 2 d . sum (f_k - c) + n_p |d|^2, d = fbar - c. */
static se23_real_t part_scatter(const se23_stationary_sums_t *p, int n_p, const se23_vec3_t *fbar)
{
    const se23_real_t d0 = fbar->v[0] - p->c.v[0];
    const se23_real_t d1 = fbar->v[1] - p->c.v[1];
    const se23_real_t d2 = fbar->v[2] - p->c.v[2];
    const se23_real_t ds = (d0 * p->sf.v[0]) + (d1 * p->sf.v[1]) + (d2 * p->sf.v[2]);
    const se23_real_t dd = (d0 * d0) + (d1 * d1) + (d2 * d2);
    return (p->qf - (SE23_R(2) * ds)) + ((se23_real_t)n_p * dd);
}

/* T over a window of n samples, n_o of them in the older part (file comment
 * of stationary.h):
 *   n T = (sum |f_k - fbar|^2 + n (|fbar| - g)^2) / sigma_a^2
 *         + sum |w_k|^2 / sigma_g^2,
 * the sums of squares raised to 0 if they round below it (NaN kept);
 * fbar_out = fbar. */
static se23_real_t statistic(const se23_stationary_t *d, const se23_stationary_sums_t *r,
                             const se23_stationary_sums_t *o, int n_o, int n, se23_vec3_t *fbar_out)
{
    se23_vec3_t fbar;
    window_fbar(r, o, n_o, n, &fbar);
    *fbar_out = fbar;
    se23_real_t sq_f = part_scatter(r, n - n_o, &fbar) + part_scatter(o, n_o, &fbar);
    se23_real_t sw = r->qw + o->qw;
    if (sq_f < SE23_R(0)) {
        sq_f = SE23_R(0);
    }
    if (sw < SE23_R(0)) {
        sw = SE23_R(0);
    }
    const se23_real_t nr = (se23_real_t)n;
    const se23_real_t rad = se23_sqrt(se23_v3_dot(&fbar, &fbar)) - d->cfg.gravity;
    const se23_real_t sa2 = d->cfg.sigma_a * d->cfg.sigma_a;
    const se23_real_t sg2 = d->cfg.sigma_g * d->cfg.sigma_g;
    const se23_real_t acc = sq_f + (nr * (rad * rad));
    return ((acc / sa2) + (sw / sg2)) / nr;
}

/* Window mean and variance helpers of se23_stationary_var: the stored
 * samples 0..n-1 of buf. */
static void window_mean(const se23_vec3_t *buf, int n, se23_vec3_t *mean)
{
    se23_vec3_t s = {{SE23_R(0), SE23_R(0), SE23_R(0)}};
    for (int i = 0; i < n; ++i) {
        s.v[0] += buf[i].v[0];
        s.v[1] += buf[i].v[1];
        s.v[2] += buf[i].v[2];
    }
    se23_v3_scale(&s, SE23_R(1) / (se23_real_t)n, mean);
}

/* sum_{i < n} (buf[i] - mean)_j^2 per axis j. */
static void window_sq_dev(const se23_vec3_t *buf, int n, const se23_vec3_t *mean,
                          se23_vec3_t *sq)
{
    se23_vec3_t s = {{SE23_R(0), SE23_R(0), SE23_R(0)}};
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < 3; ++j) {
            const se23_real_t e = buf[i].v[j] - mean->v[j];
            s.v[j] += e * e;
        }
    }
    *sq = s;
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
    /* A NaN or Inf in the sample makes the statistic NaN or Inf (through
     * |w|^2 and f - c): the test of stat below refuses it. */
    const int W = d->cfg.window;
    const int sub = d->head;
    int n = W;
    if (d->count < W) {
        n = d->count + 1;
    }
    /* The older part after this add: none before the window is full, and
     * none once the add completes a cycle (sub = W - 1). */
    const int n_o = n - (sub + 1);
    se23_stationary_sums_t r = d->recent;
    se23_stationary_sums_t o = d->older;
    if (sub == 0) {
        /* A cycle begins: the recent part (the whole window, or nothing
         * after a reset) becomes the older one; the new part's reference is
         * the window's mean, or this sample in an empty window. */
        se23_vec3_t c = *f_b;
        o = r;
        part_clear(&r);
        if (d->count != 0) {
            window_fbar(&o, &r, 0, d->count, &c);
        }
        r.c = c;
    }
    if (n_o == 0) {
        part_clear(&o);
    } else {
        part_acc(&o, &d->w[sub], &d->f[sub], SE23_R(-1));
    }
    part_acc(&r, w_b, f_b, SE23_R(1));
    se23_vec3_t fbar;
    const se23_real_t stat = statistic(d, &r, &o, n_o, n, &fbar);
    if (se23_is_finite(stat) == 0) {
        return SE23_ERR_NONFINITE;
    }
    int flag = 0;
    if ((n == W) && (stat < d->cfg.threshold)) {
        flag = 1;
    }
    d->w[sub] = *w_b;
    d->f[sub] = *f_b;
    d->recent = r;
    d->older = o;
    d->count = n;
    d->head = sub + 1;
    if (d->head == W) {
        d->head = 0;
    }
    d->fbar = fbar;
    d->stat = stat;
    d->stationary = flag;
    if (stationary != NULL) {
        *stationary = flag;
    }
    return SE23_OK;
}

void se23_stationary_reset(se23_stationary_t *d)
{
    part_clear(&d->recent);
    part_clear(&d->older);
    for (int j = 0; j < 3; ++j) {
        d->fbar.v[j] = SE23_R(0);
    }
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
    const se23_real_t inv = SE23_R(1) / (se23_real_t)d->count;
    se23_vec3_t wm;
    const se23_vec3_t fm = d->fbar;
    for (int j = 0; j < 3; ++j) {
        wm.v[j] = (d->recent.sw.v[j] + d->older.sw.v[j]) * inv;
    }
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
    window_mean(d->w, n, &mean);
    window_sq_dev(d->w, n, &mean, &wv);
    window_mean(d->f, n, &mean);
    window_sq_dev(d->f, n, &mean, &fv);
    se23_v3_scale(&wv, inv, &wv);
    se23_v3_scale(&fv, inv, &fv);
    if ((se23_all_finite(wv.v, 3) == 0) || (se23_all_finite(fv.v, 3) == 0)) {
        return SE23_ERR_NONFINITE;
    }
    *w_var = wv;
    *f_var = fv;
    return SE23_OK;
}
