/* Preintegrated IMU factor; see preint.h. */
#include "se23/preint.h"

#include "../base/argcheck.h"
#include "../base/linalg.h"
#include "se23/se23.h"
#include "../base/se23_math.h"

/* A factor is valid when its Deltas are a finite extended pose and its
 * Delta t is finite and not negative. */
static se23_status_t check_factor(const se23_preint_t *f)
{
    if (!se23_is_finite(f->dt)) {
        return SE23_ERR_NONFINITE;
    }
    se23_status_t st = se23_pose_check(&f->delta);
    if (st != SE23_OK) {
        return st;
    }
    return (f->dt >= SE23_R(0)) ? SE23_OK : SE23_ERR_DT;
}

void se23_preint_reset(se23_preint_t *f)
{
    se23_identity(&f->delta);
    f->dt = SE23_R(0);
    f->n = 0;
}

void se23_preint_add_increment(se23_preint_t *f, const se23_pose_t *ups,
                               se23_real_t dt)
{
    se23_imu_transition(NULL, &f->delta, ups, dt, &f->delta); /* Gamma = I */
    f->dt += dt;
    f->n += 1u;
}

se23_status_t se23_preint_add(se23_preint_t *f, const se23_imu_sample_t *s)
{
    SE23_CHECK_NOT_NULL(f);
    SE23_CHECK_NOT_NULL(s);
    se23_pose_t ups;
    se23_status_t st = se23_imu_increment(s, &ups);
    if (st != SE23_OK) {
        return st;
    }
    st = check_factor(f);
    if (st != SE23_OK) {
        return st;
    }
    se23_preint_t next = *f;
    se23_preint_add_increment(&next, &ups, s->dt);
    /* Finite Deltas near the largest real can still overflow. */
    if (!se23_pose_finite(&next.delta) || !se23_is_finite(next.dt)) {
        return SE23_ERR_NONFINITE;
    }
    *f = next;
    return SE23_OK;
}

se23_status_t se23_preint_predict_carried(const se23_earth_model_t *model,
                                          const se23_preint_t *f,
                                          const se23_pose_t *Tc_i,
                                          se23_pose_t *Tc_j)
{
    SE23_CHECK_NOT_NULL(model);
    SE23_CHECK_NOT_NULL(f);
    SE23_CHECK_NOT_NULL(Tc_i);
    SE23_CHECK_NOT_NULL(Tc_j);
    se23_status_t st = se23_pose_check(Tc_i);
    if (st != SE23_OK) {
        return st;
    }
    st = check_factor(f);
    if (st != SE23_OK) {
        return st;
    }
    se23_pose_t gamma;
    st = se23_earth_gamma(&model->g_n, &model->w_ie_n, f->dt, &gamma);
    if (st != SE23_OK) {
        return st;
    }
    se23_pose_t next;
    se23_imu_transition(&gamma, Tc_i, &f->delta, f->dt, &next);
    /* Finite inputs can still overflow (a state, Deltas or Delta t near the
     * largest real): refuse instead of returning Inf with SE23_OK. */
    if (!se23_pose_finite(&next)) {
        return SE23_ERR_NONFINITE;
    }
    *Tc_j = next;
    return SE23_OK;
}

se23_status_t se23_preint_predict(const se23_earth_model_t *model,
                                  const se23_preint_t *f, const se23_pose_t *T_i,
                                  se23_pose_t *T_j)
{
    SE23_CHECK_NOT_NULL(model);
    SE23_CHECK_NOT_NULL(T_i);
    SE23_CHECK_NOT_NULL(T_j);
    se23_pose_t Tc;
    se23_imu_carried_from_user(model, T_i, &Tc);
    se23_status_t st = se23_preint_predict_carried(model, f, &Tc, &Tc);
    if (st != SE23_OK) {
        return st;
    }
    se23_pose_t user;
    se23_imu_user_from_carried(model, &Tc, &user);
    if (!se23_pose_finite(&user)) {
        return SE23_ERR_NONFINITE; /* v' - Omega x p overflowed */
    }
    *T_j = user;
    return SE23_OK;
}
