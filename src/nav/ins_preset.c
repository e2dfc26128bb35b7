/* Ready-made configurations of the navigation filter; see ins.h,
 * "Presets". */
#include "se23/ins.h"

#include "../base/argcheck.h"
#include "se23/earth.h"
#include "../base/se23_math.h"

#define DEG (SE23_PI / SE23_R(180))

/* Standard normal quantile at 0.99: a false "moving" verdict in one
 * window of 100 at rest. */
#define Z_099 SE23_R(2.3263479)

se23_real_t se23_ins_detector_threshold(int window, se23_real_t z)
{
    /* chi^2_{6W-2} quantile / W (stationary.h), Wilson-Hilferty */
    const se23_real_t k = (SE23_R(6) * (se23_real_t)window) - SE23_R(2);
    const se23_real_t c = SE23_R(2) / (SE23_R(9) * k);
    const se23_real_t h = (SE23_R(1) - c) + (z * se23_sqrt(c));
    return (k * h * h * h) / (se23_real_t)window;
}

/*
 * What the presets share: the rate and the latitude checked (lat by
 * se23_earth_gravity's rule, earth.h, the one se23_ins_setup applies, so a
 * preset's configuration always passes it), *c zeroed, and a consumer MEMS
 * sensor at rate_hz on 15 states: in-run bias walks of 1e-5 rad/s and
 * 1e-4 m/s^2 per sqrt(s) (a few deg/h and 0.1-0.3 mg over minutes), range
 * 2000 deg/s and 16 g per axis; in motion the class errs by about 1 % of
 * what it measures (sensitivity tolerance and cross-axis sensitivity, each
 * about 1 %) and its gyro by 0.1 deg/s per g (g-sensitivity); lost samples
 * bridged up to 50 ms, outages carried up to 1 s; ZUPT with a detector at
 * lat's gravity. The caller adds the densities, corr_time and the rest.
 */
static se23_status_t consumer_mems(se23_real_t rate_hz, se23_real_t lat, se23_ins_config_t *c)
{
    const se23_ins_config_t none = {0};
    se23_real_t g = SE23_R(0);
    se23_status_t st;
    if (!((rate_hz >= SE23_R(50)) && (rate_hz <= SE23_R(10000)))) {
        return SE23_ERR_DOMAIN;
    }
    st = se23_earth_gravity(lat, SE23_R(0), &g);
    if (st != SE23_OK) {
        return st;
    }
    *c = none;
    c->noise.gyro_walk = SE23_R(1e-5);
    c->noise.accel_walk = SE23_R(1e-4);
    c->motion.gyro_scale = SE23_R(0.01);
    c->motion.accel_scale = SE23_R(0.01);
    c->motion.gyro_g = (SE23_R(0.1) * DEG) / SE23_R(9.80665);
    c->gyro_range = SE23_R(2000) * DEG;
    c->accel_range = SE23_R(16) * SE23_R(9.80665);
    c->lat = lat;
    c->bias_states = 1;
    c->dt_nominal = SE23_R(1) / rate_hz;
    c->max_gap = SE23_R(0.05);
    c->max_outage = SE23_R(1);
    c->zupt = 1;
    c->detector.gravity = g;
    return SE23_OK;
}

/* The detector's window of `seconds` at rate_hz, rounded, within [2,
 * SE23_STATIONARY_WMAX] samples, and its threshold: one false "moving"
 * window in 100 (Z_099). */
static void detector_window(se23_real_t rate_hz, se23_real_t seconds, se23_ins_config_t *c)
{
    const se23_real_t w = (seconds * rate_hz) + SE23_R(0.5);
    if (w < SE23_R(2)) {
        c->detector.window = 2;
    } else if (w > (se23_real_t)SE23_STATIONARY_WMAX) {
        c->detector.window = SE23_STATIONARY_WMAX;
    } else {
        c->detector.window = (int)w;
    }
    c->detector.threshold = se23_ins_detector_threshold(c->detector.window, Z_099);
}

se23_status_t se23_ins_preset_foot(se23_real_t rate_hz, se23_real_t lat,
                                   se23_ins_config_t *cfg, se23_ins_align_t *align)
{
    const se23_ins_align_t no_align = {0};
    se23_ins_config_t c;
    se23_ins_align_t a = no_align;
    se23_status_t st;
    SE23_CHECK_NOT_NULL(cfg);
    SE23_CHECK_NOT_NULL(align);
    st = consumer_mems(rate_hz, lat, &c);
    if (st != SE23_OK) {
        return st;
    }
    /* The sensor (consumer_mems): data-sheet densities of the Bosch
     * BMI160 / TDK ICM-20602 class an NGIMU-like unit carries, gyro 0.007
     * deg/s/sqrt(Hz), accelerometer 180 ug/sqrt(Hz). Flat Earth: the Earth
     * rate (0.004 deg/s) is below the gyro's noise over a walk. A stride's
     * rates (5-10 rad/s) and accelerations (2-10 g) keep their sign for
     * about a quarter of a 0.4 s swing: corr_time 0.1 s (ins.h, "Motion
     * noise"). Lost samples: a lost sample or twenty, not a swing. */
    c.noise.gyro_noise = SE23_R(0.007) * DEG;
    c.noise.accel_noise = SE23_R(180e-6) * SE23_R(9.80665);
    c.motion.corr_time = SE23_R(0.1);
    c.earth_rotation = 0;
    c.outage_accel = SE23_R(10); /* a swinging foot: ~1 g, ~5 rad/s */
    c.outage_rate = SE23_R(5);
    c.gnss_gate = SE23_R(0);
    /* The detector: a window of 12.5 ms (the most the detector holds above
     * 2.6 kHz), a quarter of the shortest stance (45-70 ms), so that every
     * stance holds windows wholly inside it. Its sigmas are not the sensor
     * noise but what a foot in stance still shows: it rolls from heel to
     * toe, at 7-13 deg/s at a stroll and about twice that at a brisk walk
     * (sigma_g 20 deg/s), and its sensor, 0.2 m from the point it rolls
     * about, accelerates by that roll's changes (a few rad/s^2 x 0.2 m:
     * sigma_a 0.6 m/s^2); the threshold is the chi^2_{6W-2} quantile for
     * one false "moving" window in 100 at that level of motion. */
    detector_window(rate_hz, SE23_R(0.0125), &c);
    c.detector.sigma_a = SE23_R(0.6);
    c.detector.sigma_g = SE23_R(20) * DEG;
    c.gravity_test_off = 1; /* a foot has no smooth start (ins.h) */
    /* v = 0 to 2 cm/s, plus what the foot's roll gives: its sensor turns
     * at w about the point the foot rolls over, the heel or the ball of
     * the foot, about 0.2 m away (zupt_lever), and moves at up to 0.2 m x
     * |w| (ins.h, "Zero-velocity updates"). That residual motion changes
     * over tens of ms, so it is the same in every sample of a detector
     * window (on the x-io walk the ZUPT innovations' autocorrelation at
     * one window's lag is 0.99): the W updates of a window are one
     * measurement, not W, and each sample's update gets sqrt(W) times the
     * sigma (W updates of variance W s^2 carry the information of one of
     * s^2). */
    c.zupt_sigma_v = SE23_R(0.02) * se23_sqrt((se23_real_t)c.detector.window);
    c.zupt_lever = SE23_R(0.2);
    /* ZARU once the foot has rested 0.5 s (7x the longest stance: in a
     * stance it still turns). A foot under a standing person still turns
     * with the body's postural sway, about 1 deg/s, which changes over
     * about a second: the rate*1 s updates of a second are one measurement
     * of 1 deg/s, each sample's gets 1 deg/s x sqrt(rate * 1 s). */
    c.zaru_sigma_w = DEG * se23_sqrt(rate_hz);
    c.zaru_after = SE23_R(0.5);
    /* The floor (ins.h, "Floor") is off: on a recording that loses its
     * stances (a run, a stumble) the drift of a swing passes for a new
     * level. A caller who knows the walk stays on level floors may set
     * floor_sigma (the values below: indoor floors are flat within about
     * +-1 cm over a room, DIN 18202 / ACI 117 tolerances, a sigma of 0.4
     * cm, and the foot's pose when the detector first calls it still
     * varies by a few degrees of pitch about a contact point ~0.1 m away,
     * 0.5 cm: 0.65 cm in quadrature, floor_sigma 1 cm). A new level is a
     * stance more than half the lowest stair riser or kerb (10 cm) off the
     * level: 5 cm. Two stances are at least 0.2 s of motion apart (a swing
     * lasts 0.3-0.5 s even running); less is the detector's flicker in
     * one. */
    c.floor_sigma = SE23_R(0);
    c.floor_step = SE23_R(0.05);
    c.floor_swing = SE23_R(0.2);
    /* Alignment: the first half second at rest (a walker may stand for
     * less than a second before the first step; half a second of the
     * class's noise levels the frame to 0.3 mrad and finds the gyro bias
     * to 0.01 deg/s); the start defines the frame (position 0, heading 0:
     * no magnetometer, no GNSS). Turn-on biases of the class: 1 deg/s, 5
     * mg. */
    a.sigma_p = SE23_R(1e-3);
    a.yaw = SE23_R(0);
    a.sigma_yaw = SE23_R(1e-3);
    a.sigma_v = SE23_R(0.01);
    a.sigma_bg = DEG;
    a.sigma_ba = SE23_R(5e-3) * SE23_R(9.80665);
    a.duration = SE23_R(0.5);
    a.measure_noise = 1; /* what this unit shows at rest, the data sheet a floor */
    *cfg = c;
    *align = a;
    return SE23_OK;
}

se23_status_t se23_ins_preset_car(se23_real_t rate_hz, se23_real_t lat,
                                  se23_ins_config_t *cfg, se23_ins_align_t *align)
{
    const se23_ins_align_t no_align = {0};
    se23_ins_config_t c;
    se23_ins_align_t a = no_align;
    se23_status_t st;
    SE23_CHECK_NOT_NULL(cfg);
    SE23_CHECK_NOT_NULL(align);
    st = consumer_mems(rate_hz, lat, &c);
    if (st != SE23_OK) {
        return st;
    }
    /* The sensor (consumer_mems): automotive-grade consumer MEMS, the class
     * a GNSS module with dead reckoning or a telematics unit carries (e.g.
     * Bosch SMI/BMI088, ST ASM330 class): gyro 0.01 deg/s/sqrt(Hz) and
     * accelerometer 150 ug/sqrt(Hz), the upper end of their data sheets (a
     * car's vibration adds to them); the bias walks (10 deg/h and 0.3 mg
     * over 10 min) cover a cabin's temperature change. A car's motions (a
     * turn, a braking) last seconds: corr_time 1 s. Rotating Earth: over a
     * minute's outage the Earth rate (15 deg/h) matters as much as the
     * bias. */
    c.noise.gyro_noise = SE23_R(0.01) * DEG;
    c.noise.accel_noise = SE23_R(150e-6) * SE23_R(9.80665);
    c.motion.corr_time = SE23_R(1);
    c.gravity_step = SE23_R(100); /* gravity follows the car (ins.h, "Frame") */
    c.earth_rotation = 1;
    c.outage_accel = SE23_R(5); /* a car brakes and turns at up to 0.5 g */
    c.outage_rate = SE23_R(0.5);
    /* Fixes a quarter of a second late are fused at their own time, if
     * the ring holds that at this rate. */
    c.delay_horizon = SE23_R(0.25);
    if ((SE23_R(2) * c.delay_horizon * rate_hz) + SE23_R(2) > (se23_real_t)SE23_INS_RING) {
        c.delay_horizon = (((se23_real_t)SE23_INS_RING - SE23_R(2)) / SE23_R(2)) / rate_hz;
    }
    /* The detector, for stops: a car at rest with its engine running
     * vibrates, on a roof bracket by up to a few deg/s and 1 m/s^2 at the
     * sensor (sigma_g 3 deg/s, sigma_a 1.5 m/s^2); a window of 0.3 s (the
     * most the detector holds above 107 Hz) holds several periods of an
     * idling engine (10-30 Hz). So wide a detector
     * also calls a steady cruise on a smooth road rest (the IMU reads the
     * same): the filter's own speed must allow rest too (rest_speed_max
     * 0.5 m/s, a creep). At rest the car rocks on its suspension by a few
     * mm/s, the same over a window: 2 cm/s per window, sqrt(W) per sample
     * (as the foot preset). ZARU after 1 s at rest, 1-sigma 3 deg/s per
     * sample: the idling vibration, white from sample to sample. A pull
     * away from rest is gentle enough (1-3 m/s^2) to pass so wide a
     * detector, so the gravity test decides: the vibration averages out of
     * a window's mean acceleration (an idling engine's 10-30 Hz over 0.3
     * s: to a few % of its amplitude, under 0.1 m/s^2) and a standing car
     * rocks on its suspension by less; with that 1-sigma
     * (rest_accel_sigma 0.1 m/s^2) a car that pulls away is moving within
     * its first window. */
    detector_window(rate_hz, SE23_R(0.3), &c);
    c.detector.sigma_a = SE23_R(1.5);
    c.detector.sigma_g = SE23_R(3) * DEG;
    c.rest_speed_max = SE23_R(0.5);
    c.rest_accel_sigma = SE23_R(0.1);
    c.zupt_sigma_v = SE23_R(0.02) * se23_sqrt((se23_real_t)c.detector.window);
    c.zaru_sigma_w = SE23_R(3) * DEG;
    c.zaru_after = SE23_R(1);
    /* The non-holonomic constraint: the rear tyres' slip angle stays below
     * 1 deg up to 0.3 g of lateral acceleration (0.17 m/s at 10 m/s) and
     * the body heaves on its suspension at a few cm/s: 1-sigma 0.2 m/s at
     * the rear axle. An IMU anywhere in a car is within 2 m of it (a
     * wheelbase is 2.5-3 m): it moves sideways at up to 2 m times the yaw
     * rate (0.6 m/s in a parking-lot turn at 0.3 rad/s), nhc_lever 2 m.
     * These last as long as a manoeuvre, about a second: one update per
     * second. */
    c.nhc_sigma = SE23_R(0.2);
    c.nhc_lever = SE23_R(2);
    c.nhc_interval = SE23_R(1);
    /* Alignment: 2 s at rest (a car may leave its parking space 3 s after
     * power-up); heading from the GNSS course above 3 m/s (10 km/h: the
     * course of a 0.3 m/s-class fix within 3 deg), the car's axis within
     * 3 deg of its course (sideslip and the mount's yaw error). Position
     * from the fixes (1-sigma 10 m until the first). Turn-on biases of
     * the class: 0.5 deg/s and 20 mg. */
    a.sigma_p = SE23_R(10);
    a.sigma_v = SE23_R(0.05);
    a.sigma_bg = SE23_R(0.5) * DEG;
    a.sigma_ba = SE23_R(0.02) * SE23_R(9.80665);
    a.duration = SE23_R(2);
    a.course_speed = SE23_R(3);
    a.course_sigma = SE23_R(3) * DEG;
    *cfg = c;
    *align = a;
    return SE23_OK;
}
