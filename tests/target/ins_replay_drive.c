/*
 * Drives the navigation filter through one recorded sequence (ins_replay.h):
 * the same code on the target (ins_replay.c, walk_replay.c) and on the host
 * (tools/target/gen_ins_replay.c, gen_walk_replay.c, which write the
 * references); and the copy of the filter's mean-acceleration rest test.
 */
#include <math.h>
#include <string.h>

#include "ins_replay.h"
#include "se23/so3.h"

/* Diagonal of the leading n x n block of P into d (zeros past n). */
static void diag(const se23_real_t *P, int stride, int n, int len, se23_real_t *d)
{
    int i;
    for (i = 0; i < len; ++i) {
        d[i] = i < n ? P[stride * i + i] : (se23_real_t)0;
    }
}

static void put_factor(const se23_ins_factor_t *f, insr_factor_t *o)
{
    int i;
    o->t0_ns = f->t0_ns;
    o->t1_ns = f->t1_ns;
    o->seq0 = f->seq0;
    o->n = f->f.f.n;
    for (i = 0; i < 9; ++i) {
        o->dR[i] = f->f.f.delta.R.m[i / 3][i % 3];
    }
    for (i = 0; i < 3; ++i) {
        o->dV[i] = f->f.f.delta.v.v[i];
        o->dX[i] = f->f.f.delta.p.v[i];
    }
    o->dt = f->f.f.dt;
    static se23_mat9_t P; /* the paper's form: large, static */
    if (se23_preint_unc_cov(&f->f, &P, NULL) != SE23_OK) {
        for (i = 0; i < 81; ++i) {
            P.m[i] = (se23_real_t)NAN; /* fails the comparison */
        }
    }
    diag(P.m, 9, 9, 9, o->P);
}

/* got = the filter's outputs now (but `at`, `factors` and `fac`). */
static int put_state(const se23_ins_t *ins, insr_check_t *got)
{
    static se23_gauss_t g; /* large: static */
    int i;
    if (se23_ins_state(ins, &g, &got->t_ns) != SE23_OK) {
        return 1;
    }
    got->status = ins->status;
    memcpy(got->c, &ins->c, sizeof got->c);
    for (i = 0; i < 9; ++i) {
        got->R[i] = g.T.R.m[i / 3][i % 3];
    }
    for (i = 0; i < 3; ++i) {
        got->v[i] = g.T.v.v[i];
        got->p[i] = g.T.p.v[i];
        got->bg[i] = g.b_g.v[i];
        got->ba[i] = g.b_a.v[i];
    }
    diag(g.P.m, SE23_GAUSS_NMAX, g.n, 15, got->P);
    return 0;
}

/* The first state of the sequence: an alignment request or an init. */
static int start(const insr_seq_t *s, se23_ins_t *ins)
{
    static se23_gauss_t g; /* large: static */
    const insr_start_t *st = &s->start;
    se23_vec3_t phi;
    int i;
    if (st->align != 0) {
        return se23_ins_align(ins, &st->a) != SE23_OK;
    }
    memset(&g, 0, sizeof g);
    g.n = s->cfg.bias_states != 0 ? SE23_GAUSS_N_BIAS : SE23_GAUSS_N_POSE;
    for (i = 0; i < 3; ++i) {
        phi.v[i] = st->phi[i];
    }
    if (se23_so3_exp(&phi, &g.T.R) != SE23_OK) {
        return 1;
    }
    for (i = 0; i < 3; ++i) {
        g.T.v.v[i] = st->v[i];
        g.T.p.v[i] = st->p[i];
        g.b_g.v[i] = st->bg[i];
        g.b_a.v[i] = st->ba[i];
    }
    for (i = 0; i < g.n; ++i) {
        g.P.m[SE23_GAUSS_NMAX * i + i] = st->P[i];
    }
    return se23_ins_init(ins, st->t0_ns, &g) != SE23_OK;
}

int insr_drive(const insr_seq_t *s, se23_ins_t *ins, insr_check_t *got, insr_hook_t hook,
               void *ctx)
{
    static se23_ins_factor_t fac; /* large: static */
    int bad = 0, factors = 0, next_fix = 0, next_check = 0, k;
    memset(got, 0, sizeof *got * (size_t)s->n_check);
    if (se23_ins_setup(&s->cfg, ins) != SE23_OK) {
        return 1;
    }
    bad += start(s, ins);
    for (k = 0; k < s->n_imu; ++k) {
        const insr_imu_t *m = &s->imu[k];
        se23_vec3_t w, f;
        int i, v;
        for (i = 0; i < 3; ++i) {
            w.v[i] = m->w[i];
            f.v[i] = m->f[i];
        }
        v = (int)se23_ins_imu(ins, m->t_ns, m->seq, &w, &f);
        if (hook != NULL) {
            hook(ctx, ins, k, 0, v);
        }
        while (next_fix < s->n_fix && s->fix[next_fix].at == k) {
            const insr_fix_t *x = &s->fix[next_fix++];
            se23_ins_gnss_t fix;
            memset(&fix, 0, sizeof fix);
            fix.t_ns = x->t_ns;
            for (i = 0; i < 3; ++i) {
                fix.p_n.v[i] = x->p[i];
                fix.sigma_p.v[i] = x->sp[i];
                fix.v_n.v[i] = x->v[i];
                fix.sigma_v.v[i] = x->sv[i];
            }
            fix.has_vel = x->has_vel;
            v = (int)se23_ins_gnss(ins, &fix);
            if (hook != NULL) {
                hook(ctx, ins, k, 1, v);
            }
        }
        if (se23_ins_take_factor(ins, &fac) != 0) {
            ++factors;
        }
        while (next_check < s->n_check && s->check[next_check].at == k) {
            insr_check_t *o = &got[next_check++];
            o->at = k;
            bad += put_state(ins, o);
            o->factors = factors;
            if (factors > 0) {
                put_factor(&fac, &o->fac);
            }
        }
    }
    return bad + (next_check != s->n_check);
}

void insr_flatten(const se23_ins_config_t *c, const se23_ins_align_t *a,
                  se23_real_t r[INSR_FLAT_REALS], int iv[INSR_FLAT_INTS])
{
    const se23_real_t reals[INSR_FLAT_REALS] = {
        c->noise.gyro_noise, c->noise.accel_noise, c->noise.gyro_walk, c->noise.accel_walk,
        c->gyro_range, c->accel_range, c->lat, c->dt_nominal, c->max_gap, c->max_outage,
        c->outage_accel, c->outage_rate, c->lever_b.v[0], c->lever_b.v[1], c->lever_b.v[2],
        c->gnss_gate, c->delay_horizon, c->preint_window, c->detector.sigma_a,
        c->detector.sigma_g, c->detector.gravity, c->detector.threshold, c->zupt_sigma_v,
        c->zaru_sigma_w, c->zaru_after, c->floor_sigma, c->floor_step, c->floor_swing,
        a->p_n.v[0], a->p_n.v[1], a->p_n.v[2], a->sigma_p,
        a->yaw, a->sigma_yaw, a->sigma_v, a->sigma_bg, a->sigma_ba, a->duration,
        a->course_speed, a->course_sigma, c->motion.gyro_scale, c->motion.accel_scale,
        c->motion.gyro_g, c->motion.corr_time, c->zupt_lever, c->rest_speed_max,
        c->mount_bv.v[0], c->mount_bv.v[1], c->mount_bv.v[2], c->nhc_sigma, c->nhc_interval,
        c->gnss_time_offset, c->height, c->gravity_step, c->rest_accel_sigma, c->nhc_lever};
    const int ints[INSR_FLAT_INTS] = {c->earth_rotation, c->bias_states, c->gate_recover,
                                      c->zupt, c->detector.window, a->gyrocompass,
                                      c->gravity_test_off, a->measure_noise};
    memcpy(r, reals, sizeof reals);
    memcpy(iv, ints, sizeof ints);
}

const char *const insr_counter_name[INSR_N_COUNTERS] = {
    "imu_used",       "imu_early",   "imu_align",   "imu_nonfinite",  "imu_range",
    "imu_duplicate",  "imu_out_of_order", "imu_bad_time", "imu_bad_dt", "imu_failed",
    "imu_missing",    "imu_seq_jumps",  "gnss_used",   "gnss_delayed", "gnss_pending_dropped",
    "gnss_nonfinite", "gnss_early",  "gnss_stale",  "gnss_gated",     "gate_resets",
    "gnss_failed",    "course_headings", "zupt_used",  "zaru_used",   "floor_used",
    "floor_levels",   "nhc_used",       "time_resets",    "filter_errors", "init_rejected"};

/* se23_ins_counters_t must be exactly the INSR_N_COUNTERS uint32_t named above. */
typedef char insr_counters_are_uint32[(sizeof(se23_ins_counters_t) ==
                                       INSR_N_COUNTERS * sizeof(uint32_t)) ? 1 : -1];

double insr_rel_dev(se23_real_t got, se23_real_t ref)
{
    const double d = (double)got - (double)ref;
    const double a = d < 0.0 ? -d : d;
    const double r = (double)ref < 0.0 ? -(double)ref : (double)ref;
    if (!(a == a)) {
        return 1e30;
    }
    return r > 0.0 ? a / r : (a > 0.0 ? 1e30 : 0.0);
}

int insr_config_diff(const se23_ins_config_t *c, const se23_ins_align_t *a,
                     const se23_ins_config_t *c_ref, const se23_ins_align_t *a_ref,
                     double tol, double *worst, int *same)
{
    se23_real_t r[INSR_FLAT_REALS], rr[INSR_FLAT_REALS];
    int iv[INSR_FLAT_INTS], ir[INSR_FLAT_INTS];
    int bad = 0, i;
    insr_flatten(c, a, r, iv);
    insr_flatten(c_ref, a_ref, rr, ir);
    for (i = 0; i < INSR_FLAT_INTS; ++i) {
        bad += iv[i] != ir[i];
    }
    for (i = 0; i < INSR_FLAT_REALS; ++i) {
        const double d = insr_rel_dev(r[i], rr[i]);
        *same &= r[i] == rr[i];
        *worst = d > *worst ? d : *worst;
        bad += !(d <= tol);
    }
    return bad;
}

double insr_accel_nis(const se23_ins_t *ins, const se23_gauss_t *x, const se23_real_t f_raw[3])
{
    const se23_stationary_t *d = &ins->det;
    const int W = d->cfg.window;
    double R[3][3], f[3], a_n[3] = {0.0, 0.0, 0.0}, a[3], F[3][3], C[3][3], y[3];
    double det, nis = 0.0;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            R[i][j] = x->T.R.m[i][j];
        }
        f[i] = f_raw[i] + x->b_a.v[i];
        for (int k = 0; k < W; ++k) {
            a_n[i] += d->f[k].v[i] / W;
        }
        a_n[i] += ins->model.g_n.v[i];
    }
    for (int i = 0; i < 3; ++i) {
        a[i] = R[0][i] * a_n[0] + R[1][i] * a_n[1] + R[2][i] * a_n[2];
    }
    memset(F, 0, sizeof F);
    F[0][1] = -f[2];
    F[0][2] = f[1];
    F[1][0] = f[2];
    F[1][2] = -f[0];
    F[2][0] = -f[1];
    F[2][1] = f[0];
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double c = (i == j) ? (double)d->cfg.sigma_a * d->cfg.sigma_a / W : 0.0;
            for (int k = 0; k < 3; ++k) {
                for (int l = 0; l < 3; ++l) {
                    c += F[i][k] * x->P.m[SE23_GAUSS_NMAX * k + l] * F[j][l];
                }
                if (x->n == SE23_GAUSS_N_BIAS) {
                    c -= F[i][k] * x->P.m[SE23_GAUSS_NMAX * k + SE23_IDX_BA + j];
                    c -= F[j][k] * x->P.m[SE23_GAUSS_NMAX * k + SE23_IDX_BA + i];
                }
            }
            if (x->n == SE23_GAUSS_N_BIAS) {
                c += x->P.m[SE23_GAUSS_NMAX * (SE23_IDX_BA + i) + SE23_IDX_BA + j];
            }
            C[i][j] = c;
        }
    }
    /* y = C^-1 a by the adjugate */
    det = C[0][0] * (C[1][1] * C[2][2] - C[1][2] * C[2][1]) -
          C[0][1] * (C[1][0] * C[2][2] - C[1][2] * C[2][0]) +
          C[0][2] * (C[1][0] * C[2][1] - C[1][1] * C[2][0]);
    for (int i = 0; i < 3; ++i) {
        const int i1 = (i + 1) % 3, i2 = (i + 2) % 3;
        y[i] = 0.0;
        for (int j = 0; j < 3; ++j) {
            const int j1 = (j + 1) % 3, j2 = (j + 2) % 3;
            y[i] += (C[j1][i1] * C[j2][i2] - C[j1][i2] * C[j2][i1]) * a[j]; /* adj(C)[i][j] */
        }
        nis += a[i] * y[i] / det;
    }
    return nis;
}
