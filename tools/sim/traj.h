/**
 * @file traj.h
 * @brief Analytic reference trajectories of the simulator (closed forms in
 *        t, with closed-form first and second derivatives).
 *
 * Frames: nav = NED (origin at the start point), body = FRD. Attitude comes
 * from ZYX Euler angles (yaw, pitch, roll) given with their rates.
 */
#ifndef SIM_TRAJ_H
#define SIM_TRAJ_H

#include "../lcm/ldmath.h"

typedef enum {
    TRAJ_STATIC = 0, /**< at rest, level-ish, fixed heading */
    TRAJ_UAV = 1,    /**< smooth 3D figure-eight flight, 30 s loop, ~5 m/s, rolling/pitching */
    TRAJ_CAR = 2,    /**< planar figure-eight, 60 s loop, ~10 m/s, heading along the velocity */
    TRAJ_NAV = 3,    /**< aircraft in a 100 m/s coordinated turn, 20 min per circle */
    TRAJ_WALK = 4,   /**< foot-mounted IMU: 16 strides of 1.4 m closing a circle, at rest
                          5 s before and after (traj.c) */
    TRAJ_STAIRS = 5, /**< the walk on a stepped path: 8 strides up a 0.15 m riser
                          each, 8 down (traj.c) */
    TRAJ_COUNT = 6
} traj_scenario_t;

/** The reference state at one instant. */
typedef struct {
    ld_vec3_t p;      /**< position, nav [m] */
    ld_vec3_t v;      /**< velocity dp/dt, nav [m/s] */
    ld_vec3_t a;      /**< acceleration d2p/dt2, nav [m/s^2] */
    ld_mat3_t R;      /**< attitude body -> nav */
    ld_vec3_t w_nb_b; /**< angular rate of body w.r.t. nav, body frame [rad/s] */
} traj_point_t;

/** Name ("static", "uav", "car", "nav", "walk", "stairs") of a scenario. */
const char *traj_name(traj_scenario_t s);

/** Scenario called name, or -1. */
int traj_find(const char *name);

/** Default duration of a scenario [s]. */
double traj_default_duration(traj_scenario_t s);

/** The reference state of scenario s at time t [s]. */
traj_point_t traj_eval(traj_scenario_t s, ld_t t);

/**
 * Length [s] of the ramp that takes scenario s from rest into its motion
 * (traj_eval_start): 5 s uav, 10 s car, 60 s nav (peak accelerations about
 * 2.2, 2.8 and 3.1 m/s^2 during the ramp), 1 s static (nothing moves).
 */
double traj_ramp_duration(traj_scenario_t s);

/**
 * Scenario s after a stationary start of rest [s]. None of the scenarios
 * starts at rest (uav ~6 m/s, car ~15 m/s, nav 100 m/s at t = 0), so the
 * scenario runs on a warped clock tau(t):
 *   t < rest:                      tau = 0, at rest at the scenario's initial pose;
 *   rest <= t < rest + ramp:       tau' = u^3 (10 - 15 u + 6 u^2), u = (t - rest) / ramp,
 *                                  tau = ramp u^4 (5/2 - 3 u + u^2);
 *   t >= rest + ramp:              tau' = 1, tau = t - rest - ramp/2,
 * ramp = traj_ramp_duration(s). The state is the scenario's at tau with the
 * chain rule: v = P'(tau) tau', a = P''(tau) tau'^2 + P'(tau) tau'',
 * w_nb_b = W(tau) tau'. The path and the attitude history are the
 * scenario's (the car still heads along its velocity); tau' rises from 0 to
 * 1 and tau'' is 0 at both ends of the ramp, so position, attitude,
 * velocity, body rate and acceleration are continuous and the vehicle
 * starts from rest smoothly. rest <= 0 gives traj_eval(s, t) exactly.
 */
traj_point_t traj_eval_start(traj_scenario_t s, ld_t rest, ld_t t);

/**
 * The largest difference, over n instants spread evenly over [0, duration],
 * between scenario s's closed-form derivatives and central differences of
 * step h [s] of the quantity they differentiate: |v - dp/dt|,
 * |a - dv/dt| and |w_nb_b - vee(R^T dR/dt)| (out[0..2]); for se23-sim
 * --check-traj.
 */
void traj_check_derivatives(traj_scenario_t s, ld_t duration, long n, ld_t h, ld_t out[3]);

#endif /* SIM_TRAJ_H */
