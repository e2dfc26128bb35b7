/*
 * The benchmark's inputs: a ring of BENCH_RING consecutive moments of a
 * running 15-state filter on rotating Earth (200 Hz MEMS IMU, GNSS), built
 * before anything is measured. Entry i holds the raw IMU sample, the filter
 * state (carried, with its correlated covariance), a GNSS fix near it and a
 * preintegrated factor of i % BENCH_FACTOR_LEN samples. A measured call
 * starts from entry i and writes elsewhere, so every call does the same
 * work on valid inputs whatever was measured before it.
 */
#ifndef SE23_BENCH_RING_H
#define SE23_BENCH_RING_H

#include "se23/earth.h"
#include "se23/gauss.h"
#include "se23/imu.h"
#include "se23/preint_unc.h"

#define BENCH_RING 64
#define BENCH_FACTOR_LEN 40

typedef struct {
    se23_earth_model_t model;     /* WGS-84 NED at 45 deg, dt = 5 ms */
    se23_imu_noise_t noise;       /* MEMS-grade densities and walks */
    se23_vec3_t lever_b;          /* GNSS antenna in the body frame [m] */
    se23_mat3_t gnss_cov;         /* GNSS position noise [m^2] */
    se23_imu_sample_t s[BENCH_RING];  /* raw samples (before bias correction) */
    se23_gauss_t g15[BENCH_RING];     /* state before sample i, n = 15 */
    se23_gauss_t g9[BENCH_RING];      /* the same with n = 9 (its marginal) */
    se23_vec3_t gnss_p[BENCH_RING];   /* GNSS fix at entry i, nav frame [m] */
    se23_preint_unc_t fu[BENCH_RING]; /* factor before sample i */
} bench_ring_t;

/* Fills the ring; returns 0, or the first status that was not SE23_OK. */
int bench_ring_fill(bench_ring_t *r);

#endif /* SE23_BENCH_RING_H */
