/* The reference tables of the replay generators as C; see gen_print.h. */
#include "gen_print.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

void gen_reals(const char *name, const se23_real_t *x, int n)
{
    printf(" .%s = {", name);
    for (int i = 0; i < n; ++i) {
        printf("%s%.17g", i ? ", " : "", (double)x[i]);
    }
    printf("},");
}

void gen_vec(const char *name, const se23_vec3_t *x)
{
    printf(" .%s = {.v = {%.17g, %.17g, %.17g}},", name, x->v[0], x->v[1], x->v[2]);
}

void gen_print_config(const se23_ins_config_t *c)
{
    const se23_imu_noise_t *n = &c->noise;
    const se23_stationary_config_t *d = &c->detector;
    printf("  .cfg = {\n");
    printf("   .noise = {%.17g, %.17g, %.17g, %.17g},\n", n->gyro_noise, n->accel_noise,
           n->gyro_walk, n->accel_walk);
    printf("   .motion = {%.17g, %.17g, %.17g, %.17g},\n", c->motion.gyro_scale,
           c->motion.accel_scale, c->motion.gyro_g, c->motion.corr_time);
    printf("   .gyro_range = %.17g, .accel_range = %.17g, .lat = %.17g, .height = %.17g,\n",
           c->gyro_range, c->accel_range, c->lat, c->height);
    printf("   .gravity_step = %.17g,\n", c->gravity_step);
    printf("   .earth_rotation = %d, .bias_states = %d, .dt_nominal = %.17g, .max_gap = %.17g,\n",
           c->earth_rotation, c->bias_states, c->dt_nominal, c->max_gap);
    printf("   .max_outage = %.17g, .outage_accel = %.17g, .outage_rate = %.17g,\n  ",
           c->max_outage, c->outage_accel, c->outage_rate);
    gen_vec("lever_b", &c->lever_b);
    printf("\n   .gnss_gate = %.17g, .gate_recover = %d, .delay_horizon = %.17g,\n", c->gnss_gate,
           c->gate_recover, c->delay_horizon);
    printf("   .preint_window = %.17g, .zupt = %d,\n", c->preint_window, c->zupt);
    printf("   .detector = {%d, %.17g, %.17g, %.17g, %.17g}, .gravity_test_off = %d,\n",
           d->window, d->sigma_a, d->sigma_g, d->gravity, d->threshold, c->gravity_test_off);
    printf("   .zupt_sigma_v = %.17g, .zupt_lever = %.17g, .zaru_sigma_w = %.17g,\n",
           c->zupt_sigma_v, c->zupt_lever, c->zaru_sigma_w);
    printf("   .rest_speed_max = %.17g, .rest_accel_sigma = %.17g, .zaru_after = %.17g,\n",
           c->rest_speed_max, c->rest_accel_sigma, c->zaru_after);
    printf("   .floor_sigma = %.17g, .floor_step = %.17g, .floor_swing = %.17g,\n  ",
           c->floor_sigma, c->floor_step, c->floor_swing);
    gen_vec("mount_bv", &c->mount_bv);
    printf("\n   .nhc_sigma = %.17g, .nhc_lever = %.17g, .nhc_interval = %.17g,\n",
           c->nhc_sigma, c->nhc_lever, c->nhc_interval);
    printf("   .gnss_time_offset = %.17g},\n", c->gnss_time_offset);
}

void gen_print_align(const se23_ins_align_t *a)
{
    printf("{");
    gen_vec("p_n", &a->p_n);
    printf(" .sigma_p = %.17g, .yaw = %.17g, .sigma_yaw = %.17g, .gyrocompass = %d,\n"
           "         .sigma_v = %.17g, .sigma_bg = %.17g, .sigma_ba = %.17g, .duration = %.17g,\n"
           "         .course_speed = %.17g, .course_sigma = %.17g, .measure_noise = %d},\n",
           a->sigma_p, a->yaw, a->sigma_yaw, a->gyrocompass, a->sigma_v, a->sigma_bg,
           a->sigma_ba, a->duration, a->course_speed, a->course_sigma, a->measure_noise);
}

void gen_print_start(const insr_start_t *s)
{
    printf("  .start = {.align = %d,\n   .a = ", s->align);
    gen_print_align(&s->a);
    printf("   .t0_ns = %lldLL,\n  ", (long long)s->t0_ns);
    gen_reals("phi", s->phi, 3);
    gen_reals("v", s->v, 3);
    gen_reals("p", s->p, 3);
    gen_reals("bg", s->bg, 3);
    gen_reals("ba", s->ba, 3);
    printf("\n  ");
    gen_reals("P", s->P, 15);
    printf("},\n");
}

void gen_print_check(const insr_check_t *o)
{
    const insr_factor_t *f = &o->fac;
    printf(" {.at = %d, .t_ns = %lldLL, .status = 0x%03xU,\n  .c = {", o->at, (long long)o->t_ns,
           (unsigned)o->status);
    for (int i = 0; i < INSR_N_COUNTERS; ++i) {
        printf("%s%uU", i ? ", " : "", (unsigned)o->c[i]);
    }
    printf("},\n  .factors = %d,\n  .fac = {.t0_ns = %lldLL, .t1_ns = %lldLL, .seq0 = %lldLL, "
           ".n = %uU,\n  ",
           o->factors, (long long)f->t0_ns, (long long)f->t1_ns, (long long)f->seq0,
           (unsigned)f->n);
    gen_reals("dR", f->dR, 9);
    printf("\n  ");
    gen_reals("dV", f->dV, 3);
    gen_reals("dX", f->dX, 3);
    printf(" .dt = %.17g,\n  ", (double)f->dt);
    gen_reals("P", f->P, 9);
    printf("},\n  ");
    gen_reals("R", o->R, 9);
    printf("\n  ");
    gen_reals("v", o->v, 3);
    gen_reals("p", o->p, 3);
    printf("\n  ");
    gen_reals("bg", o->bg, 3);
    gen_reals("ba", o->ba, 3);
    printf("\n  ");
    gen_reals("P", o->P, 15);
    printf("},\n");
}

void gen_real(se23_real_t x)
{
    char buf[40];
    snprintf(buf, sizeof buf, SE23_CFG_DOUBLE ? "%.17g" : "%.9g", (double)x);
    if ((se23_real_t)strtod(buf, NULL) != x) {
        snprintf(buf, sizeof buf, "%.17g", (double)x);
    }
    fputs(buf, stdout);
}

void gen_real3(const se23_real_t *x)
{
    putchar('{');
    gen_real(x[0]);
    fputs(", ", stdout);
    gen_real(x[1]);
    fputs(", ", stdout);
    gen_real(x[2]);
    putchar('}');
}

void gen_print_imu(const insr_imu_t *imu, int n)
{
    printf("\n/* %d IMU samples: t_ns, seq, gyro [rad/s], specific force [m/s^2] */\n", n);
    printf("static const insr_imu_t imu[%d] = {\n", n);
    for (int k = 0; k < n; ++k) {
        printf(" {%lldLL, %lld, ", (long long)imu[k].t_ns, (long long)imu[k].seq);
        gen_real3(imu[k].w);
        fputs(", ", stdout);
        gen_real3(imu[k].f);
        fputs("},\n", stdout);
    }
    printf("};\n");
}

int gen_checkpoints(const insr_imu_t *imu, int n_imu, const double *times_s, insr_check_t *check,
                    int n)
{
    int j;
    for (j = 0; j < n - 1; ++j) {
        const int64_t t = llround(times_s[j] * 1e9);
        int k = 0;
        while (k < n_imu - 1 && imu[k].t_ns < t) {
            ++k;
        }
        check[j].at = k;
    }
    check[n - 1].at = n_imu - 1;
    for (j = 1; j < n; ++j) {
        if (check[j].at <= check[j - 1].at) {
            return -1;
        }
    }
    return 0;
}
