/* IMU error model and RNG of the simulator; see imu_err.h. */
#include "imu_err.h"

#include <math.h>

static uint64_t splitmix64(uint64_t *x)
{
    uint64_t z = (*x += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

static uint64_t rotl(uint64_t x, int k)
{
    return (x << k) | (x >> (64 - k));
}

static uint64_t next_u64(rng_t *r)
{
    uint64_t *s = r->s;
    uint64_t result = rotl(s[1] * 5, 7) * 9;
    uint64_t t = s[1] << 17;
    s[2] ^= s[0];
    s[3] ^= s[1];
    s[1] ^= s[2];
    s[0] ^= s[3];
    s[2] ^= t;
    s[3] = rotl(s[3], 45);
    return result;
}

void rng_seed(rng_t *r, uint64_t seed)
{
    int i;
    for (i = 0; i < 4; i++) {
        r->s[i] = splitmix64(&seed);
    }
    r->has_spare = 0;
    r->spare = 0.0;
}

double rng_uniform(rng_t *r)
{
    return ((double)(next_u64(r) >> 11) + 0.5) * (1.0 / 9007199254740992.0);
}

double rng_normal(rng_t *r)
{
    double u, v, s;
    if (r->has_spare) {
        r->has_spare = 0;
        return r->spare;
    }
    do { /* Marsaglia's polar method */
        u = 2.0 * rng_uniform(r) - 1.0;
        v = 2.0 * rng_uniform(r) - 1.0;
        s = u * u + v * v;
    } while (s >= 1.0 || s == 0.0);
    s = sqrt(-2.0 * log(s) / s);
    r->spare = v * s;
    r->has_spare = 1;
    return u * s;
}

void imu_err_init(imu_err_t *e, const harness_imu_profile_t *prof, uint64_t seed)
{
    int i;
    e->prof = *prof;
    rng_seed(&e->rng, seed);
    for (i = 0; i < 3; i++) {
        e->b_g[i] = prof->gyro_bias0 * rng_normal(&e->rng);
    }
    for (i = 0; i < 3; i++) {
        e->b_a[i] = prof->accel_bias0 * rng_normal(&e->rng);
    }
    e->accel_rot = ld_identity();
}

void imu_err_misalign_accel(imu_err_t *e, const double rotvec[3])
{
    const ld_vec3_t phi = ld_vec3_from(rotvec);
    e->accel_rot = ld_exp(&phi); /* exactly I for a zero rotation */
}

void imu_err_apply(imu_err_t *e, const double w_true[3], const double f_true[3], double dt,
                   double w_meas[3], double f_meas[3])
{
    double sg = e->prof.gyro_noise / sqrt(dt);
    double sa = e->prof.accel_noise / sqrt(dt);
    double rg = e->prof.gyro_bias_rw * sqrt(dt);
    double ra = e->prof.accel_bias_rw * sqrt(dt);
    const ld_vec3_t f = ld_vec3_from(f_true);
    const ld_vec3_t mf = ld_mul_v(&e->accel_rot, &f);
    int i;
    for (i = 0; i < 3; i++) {
        w_meas[i] = w_true[i] - e->b_g[i] - sg * rng_normal(&e->rng);
        f_meas[i] = (double)mf.v[i] - e->b_a[i] - sa * rng_normal(&e->rng);
    }
    for (i = 0; i < 3; i++) {
        e->b_g[i] += rg * rng_normal(&e->rng);
        e->b_a[i] += ra * rng_normal(&e->rng);
    }
}
