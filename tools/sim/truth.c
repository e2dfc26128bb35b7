/* RK4 ground truth of the simulator; see truth.h. */
#include "truth.h"

#include <math.h>

typedef struct {
    ld_mat3_t R;
    ld_vec3_t v, p;
} deriv_t;

static deriv_t f_eval(const truth_state_t *x, const truth_env_t *env, const ld_vec3_t *w,
                      const ld_vec3_t *f)
{
    deriv_t d;
    ld_mat3_t W = ld_hat(&env->w_ie_n);
    ld_mat3_t Wb = ld_hat(w);
    ld_mat3_t WR = ld_mul(&W, &x->R);
    ld_mat3_t RWb = ld_mul(&x->R, &Wb);
    ld_vec3_t Rf = ld_mul_v(&x->R, f);
    ld_vec3_t cor = ld_cross(&env->w_ie_n, &x->v);
    ld_vec3_t Wp = ld_cross(&env->w_ie_n, &x->p);
    ld_vec3_t cen = ld_cross(&env->w_ie_n, &Wp);
    int i, j;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            d.R.m[i][j] = RWb.m[i][j] - WR.m[i][j];
        }
        d.v.v[i] = env->g_n.v[i] + Rf.v[i] - 2.0L * cor.v[i] - cen.v[i];
    }
    d.p = x->v;
    return d;
}

/* y = x + h d */
static truth_state_t axpy(const truth_state_t *x, ld_t h, const deriv_t *d)
{
    truth_state_t y;
    int i, j;
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            y.R.m[i][j] = x->R.m[i][j] + h * d->R.m[i][j];
        }
        y.v.v[i] = x->v.v[i] + h * d->v.v[i];
        y.p.v[i] = x->p.v[i] + h * d->p.v[i];
    }
    return y;
}

static void rk4(truth_state_t *x, const truth_env_t *env, const ld_vec3_t *w, const ld_vec3_t *f,
                ld_t h)
{
    deriv_t k1, k2, k3, k4, sum;
    truth_state_t tmp;
    int i, j;
    k1 = f_eval(x, env, w, f);
    tmp = axpy(x, 0.5L * h, &k1);
    k2 = f_eval(&tmp, env, w, f);
    tmp = axpy(x, 0.5L * h, &k2);
    k3 = f_eval(&tmp, env, w, f);
    tmp = axpy(x, h, &k3);
    k4 = f_eval(&tmp, env, w, f);
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            sum.R.m[i][j] = k1.R.m[i][j] + 2.0L * (k2.R.m[i][j] + k3.R.m[i][j]) + k4.R.m[i][j];
        }
        sum.v.v[i] = k1.v.v[i] + 2.0L * (k2.v.v[i] + k3.v.v[i]) + k4.v.v[i];
        sum.p.v[i] = k1.p.v[i] + 2.0L * (k2.p.v[i] + k3.p.v[i]) + k4.p.v[i];
    }
    *x = axpy(x, h / 6.0L, &sum);
}

void truth_step(truth_state_t *x, const truth_env_t *env, const ld_vec3_t *w_ib_b,
                const ld_vec3_t *f_b, ld_t dt, int nsub)
{
    ld_t h = dt / (ld_t)nsub;
    int i;
    for (i = 0; i < nsub; i++) {
        rk4(x, env, w_ib_b, f_b, h);
    }
    x->R = ld_orthonormalize(&x->R);
}

truth_env_t truth_env_ned(ld_t lat, int earth_rotation)
{
    const ld_t we = 7.292115e-5L;      /* WGS-84 Earth rate [rad/s] */
    const ld_t ge = 9.7803253359L;     /* normal gravity at the equator [m/s^2] */
    const ld_t k = 0.00193185265241L;  /* Somigliana constant */
    const ld_t e2 = 0.00669437999013L; /* first eccentricity squared */
    ld_t s2 = sinl(lat) * sinl(lat);
    truth_env_t env;
    env.g_n.v[0] = 0.0L;
    env.g_n.v[1] = 0.0L;
    env.g_n.v[2] = ge * (1.0L + k * s2) / sqrtl(1.0L - e2 * s2);
    env.w_ie_n.v[0] = earth_rotation ? we * cosl(lat) : 0.0L;
    env.w_ie_n.v[1] = 0.0L;
    env.w_ie_n.v[2] = earth_rotation ? -we * sinl(lat) : 0.0L;
    return env;
}
