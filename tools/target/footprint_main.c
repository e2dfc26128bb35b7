/*
 * Footprint images (make gates-target): what a firmware links of se23,
 * with --gc-sections, when it calls
 *   FOOTPRINT = 1: the per-sample kernels of a 15-state filter of its own
 *                  (se23_gauss_predict, se23_meas_pos_nav, se23_kalman_update);
 *   FOOTPRINT = 2: the library's navigation filter (se23_ins_init,
 *                  se23_ins_imu, se23_ins_gnss);
 *   FOOTPRINT = 0: nothing of se23 (the baseline of newlib's own code).
 * tools/target/footprint.py reads the images' link maps. The images are
 * linked, never run: the arguments are zero, the calls only keep their
 * code in the image.
 */
#include "se23/ins.h"

#if !defined(FOOTPRINT) || FOOTPRINT < 0 || FOOTPRINT > 2
#error "FOOTPRINT must be 0, 1 or 2"
#endif

volatile int footprint_sink;

int main(void)
{
#if FOOTPRINT == 2
    static se23_ins_t ins;
    static se23_gauss_t g;
    static se23_ins_gnss_t fix;
    static se23_vec3_t w_b, f_b;
    footprint_sink = (int)se23_ins_init(&ins, 0, &g);
    footprint_sink += (int)se23_ins_imu(&ins, 1, 1, &w_b, &f_b);
    footprint_sink += (int)se23_ins_gnss(&ins, &fix);
#elif FOOTPRINT == 1
    static se23_earth_model_t model;
    static se23_gauss_t g, out;
    static se23_imu_sample_t s;
    static se23_imu_noise_t noise;
    static se23_meas_t y;
    static se23_vec3_t p_n, lever_b;
    static se23_mat3_t cov;
    footprint_sink = (int)se23_gauss_predict(&model, &g, &s, &noise, SE23_INPUT_JAC_EXACT, &out);
    footprint_sink += (int)se23_meas_pos_nav(&out.T, &p_n, &lever_b, &cov, &y);
    footprint_sink += (int)se23_kalman_update(&out, &y, &g, 0);
#else
    footprint_sink = 0;
#endif
    return 0;
}
