/* SO(3): see so3.h. */
#include "se23/so3.h"

#include "../base/argcheck.h"
#include "../base/linalg.h"
#include "../base/se23_math.h"
#include "so3_series.h"

/* J_l^-1 is refused this close to its singularity at 2 pi. */
#define JL_INV_MARGIN SE23_R(1e-3)
/* se23_so3_normalize repairs at most this much drift, in this many steps. */
#define NORMALIZE_MAX_DRIFT SE23_R(0.1)
#define NORMALIZE_MAX_ITER 6


void se23_so3_hat(const se23_vec3_t *phi, se23_mat3_t *W)
{
    se23_m3_skew(phi, W);
}

void se23_so3_vee(const se23_mat3_t *W, se23_vec3_t *phi)
{
    se23_vec3_t out;
    out.v[0] = SE23_R(0.5) * (W->m[2][1] - W->m[1][2]);
    out.v[1] = SE23_R(0.5) * (W->m[0][2] - W->m[2][0]);
    out.v[2] = SE23_R(0.5) * (W->m[1][0] - W->m[0][1]);
    *phi = out;
}

/* The series functions of so3.h, all of the form a0 I + a1 W + a2 W^2. */
typedef enum {
    SERIES_EXP,    /* I + c1 W + c2 W^2 */
    SERIES_JL,     /* I + c2 W + c3 W^2 */
    SERIES_JR,     /* J_l(-phi) = I - c2 W + c3 W^2 */
    SERIES_JL_INV, /* I - W/2 + e W^2 */
    SERIES_H,      /* I/2 + c3 W + c4 W^2 */
    SERIES_K       /* I/2 + k1 W + k2 W^2 */
} series_t;

/* out = the series `kind` at phi, after the checks every one of them needs. */
static se23_status_t eval_series(series_t kind, const se23_vec3_t *phi,
                                 se23_mat3_t *out)
{
    SE23_CHECK_NOT_NULL(phi);
    SE23_CHECK_NOT_NULL(out);
    const se23_real_t theta2 = se23_v3_dot(phi, phi);
    if (!se23_all_finite(phi->v, 3) || !se23_is_finite(theta2)) {
        return SE23_ERR_NONFINITE; /* |phi|^2 overflows above ~1e154 (double), 2e19 (float) */
    }
    const se23_real_t theta = se23_sqrt(theta2);
    se23_so3_coeffs_t c;
    se23_real_t a0 = SE23_R(1);
    se23_real_t a1;
    se23_real_t a2;
    switch (kind) {
    case SERIES_JL_INV:
        if (theta >= SE23_R(2) * SE23_PI - JL_INV_MARGIN) {
            return SE23_ERR_DOMAIN;
        }
        a1 = SE23_R(-0.5);
        a2 = se23_so3_jl_inv_coeff(theta);
        break;
    case SERIES_K:
        a0 = SE23_R(0.5);
        se23_so3_k_coeffs(theta, &a1, &a2);
        break;
    case SERIES_EXP:
        se23_so3_coeffs(theta, &c);
        a1 = c.c1;
        a2 = c.c2;
        break;
    case SERIES_JL:
    case SERIES_JR:
        se23_so3_coeffs(theta, &c);
        a1 = (kind == SERIES_JL) ? c.c2 : -c.c2;
        a2 = c.c3;
        break;
    default: /* SERIES_H */
        se23_so3_coeffs(theta, &c);
        a0 = SE23_R(0.5);
        a1 = c.c3;
        a2 = c.c4;
        break;
    }
    se23_m3_series(a0, a1, a2, phi, out);
    return SE23_OK;
}

se23_status_t se23_so3_exp(const se23_vec3_t *phi, se23_mat3_t *R)
{
    return eval_series(SERIES_EXP, phi, R);
}

se23_status_t se23_so3_jl(const se23_vec3_t *phi, se23_mat3_t *J)
{
    return eval_series(SERIES_JL, phi, J);
}

se23_status_t se23_so3_jr(const se23_vec3_t *phi, se23_mat3_t *J)
{
    return eval_series(SERIES_JR, phi, J);
}

se23_status_t se23_so3_jl_inv(const se23_vec3_t *phi, se23_mat3_t *Jinv)
{
    return eval_series(SERIES_JL_INV, phi, Jinv);
}

se23_status_t se23_so3_h(const se23_vec3_t *phi, se23_mat3_t *H)
{
    return eval_series(SERIES_H, phi, H);
}

se23_status_t se23_so3_k(const se23_vec3_t *phi, se23_mat3_t *K)
{
    return eval_series(SERIES_K, phi, K);
}

/* Largest |(R^T R - I)_ij| (the step itself is disabled). */
static se23_real_t orthogonality_error(const se23_mat3_t *R)
{
    se23_mat3_t X = *R;
    return se23_m3_orthonormalize_step(&X, SE23_R(1), SE23_R(0));
}

/* Finite and |R^T R - I| within tol; then the determinant: within tol of 1
 * for a rotation (rejects reflections and uniform scaling), or merely
 * positive for what normalize can repair (its iteration converges for any
 * such matrix with drift below 0.1). */
static se23_status_t check_rotation(const se23_mat3_t *R, se23_real_t tol,
                                    int repairable)
{
    if (!se23_all_finite(&R->m[0][0], 9)) {
        return SE23_ERR_NONFINITE;
    }
    const se23_real_t det = se23_m3_det(R);
    const int det_ok = repairable ? (det > SE23_R(0))
                                  : (se23_fabs(det - SE23_R(1)) <= tol);
    if (!(orthogonality_error(R) <= tol) || !det_ok) {
        return SE23_ERR_NOT_ROTATION;
    }
    return SE23_OK;
}

se23_status_t se23_so3_check(const se23_mat3_t *R)
{
    SE23_CHECK_NOT_NULL(R);
    return check_rotation(R, SE23_R(SE23_CFG_ROT_TOL), 0);
}

se23_status_t se23_so3_log(const se23_mat3_t *R, se23_vec3_t *phi)
{
    SE23_CHECK_NOT_NULL(R);
    SE23_CHECK_NOT_NULL(phi);
    se23_status_t st = check_rotation(R, SE23_R(SE23_CFG_ROT_TOL), 0);
    if (st != SE23_OK) {
        return st;
    }
    /* R - R^T = 2 sin(theta) n^ and trace R = 1 + 2 cos(theta). */
    const se23_vec3_t w = {{R->m[2][1] - R->m[1][2], R->m[0][2] - R->m[2][0],
                            R->m[1][0] - R->m[0][1]}};
    const se23_real_t cos_theta =
        SE23_R(0.5) * (R->m[0][0] + R->m[1][1] + R->m[2][2] - SE23_R(1));
    const se23_real_t sin_theta = SE23_R(0.5) * se23_sqrt(se23_v3_dot(&w, &w));
    const se23_real_t theta = se23_atan2(sin_theta, cos_theta);

    if (cos_theta >= SE23_R(0)) {
        /* theta <= pi/2: phi = theta / (2 sin theta) w, with sin(theta)/theta
         * = c1 from its series, so there is no 0/0 at theta = 0. */
        se23_so3_coeffs_t c;
        se23_so3_coeffs(theta, &c);
        se23_v3_scale(&w, SE23_R(0.5) / c.c1, phi);
        return SE23_OK;
    }
    /* theta > pi/2: w loses relative accuracy as theta -> pi, so take the
     * axis from the symmetric part (R + R^T)/2 = cos(theta) I + (1 - cos) n n^T,
     * using the column of its largest diagonal entry, and the sign from w. */
    int k = 0;
    for (int i = 1; i < 3; ++i) {
        if (R->m[i][i] > R->m[k][k]) {
            k = i;
        }
    }
    se23_vec3_t n;
    for (int i = 0; i < 3; ++i) {
        n.v[i] = (i == k) ? (R->m[k][k] - cos_theta)
                          : SE23_R(0.5) * (R->m[i][k] + R->m[k][i]);
    }
    /* n now holds (1 - cos) n_k n; normalise it and orient it along w. */
    se23_real_t scale = theta / se23_sqrt(se23_v3_dot(&n, &n));
    if (se23_v3_dot(&n, &w) < SE23_R(0)) {
        scale = -scale;
    }
    se23_v3_scale(&n, scale, phi);
    return SE23_OK;
}

se23_status_t se23_so3_normalize(const se23_mat3_t *R, se23_mat3_t *Rn)
{
    SE23_CHECK_NOT_NULL(R);
    SE23_CHECK_NOT_NULL(Rn);
    se23_status_t st = check_rotation(R, NORMALIZE_MAX_DRIFT, 1);
    if (st != SE23_OK) {
        return st;
    }
    /* Newton-Schulz: X <- X (3I - X^T X)/2 converges quadratically to the
     * orthogonal polar factor; from a drift of 0.1 five steps reach double
     * rounding. Stop as soon as the drift is at rounding level. */
    se23_mat3_t X = *R;
    for (int it = 0; it < NORMALIZE_MAX_ITER; ++it) {
        if (se23_m3_orthonormalize_step(&X, SE23_NORMALIZE_DONE, NORMALIZE_MAX_DRIFT) <=
            SE23_NORMALIZE_DONE) {
            break;
        }
    }
    *Rn = X;
    return SE23_OK;
}
