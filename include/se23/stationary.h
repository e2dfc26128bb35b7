/**
 * @file stationary.h
 * @brief Stationary (zero-velocity) detector: the SHOE statistic of Skog et
 *        al., "Zero-velocity detection -- an algorithm evaluation", IEEE
 *        Trans. Biomed. Eng. 57(11), 2010, over a sliding window of the last
 *        W IMU samples.
 *
 * Statistic. Over the window of W samples (w_k, f_k) (raw gyro [rad/s],
 * specific force [m/s^2], body frame), with fbar the window mean of f and
 * u = fbar / |fbar|:
 *   T = (1/W) sum_k [ |f_k - g u|^2 / sigma_a^2 + |w_k|^2 / sigma_g^2 ],
 * the generalised likelihood ratio of "at rest, f = -g_b, w = 0" against
 * "moving", with the unknown gravity direction u estimated by the window.
 * The window is declared stationary when it is full and T < threshold.
 *
 * Computation. Writing f_k - g u = (f_k - fbar) + (|fbar| - g) u, the cross
 * term sums to zero over the window (sum_k (f_k - fbar) = 0), so exactly
 *   sum_k |f_k - g u|^2 = sum_k |f_k - fbar|^2 + W (|fbar| - g)^2.
 * The library evaluates the right-hand side: no division by |fbar| (it is
 * defined in free fall, fbar = 0, where it is the limit of the left-hand
 * side for any u).
 *
 * Running sums, O(1) per sample. The window is held in two parts: the
 * samples written since head last wrapped to 0 (positions 0..head-1, the
 * recent part) and the older ones (the rest of the window). Each part keeps
 * sum (f_k - c), sum |f_k - c|^2, sum w_k and sum |w_k|^2, f about a
 * reference c fixed for the part's cycle (the window's mean when the cycle
 * began; the first sample after a reset), and
 *   sum_part |f_k - fbar|^2 = sum |f_k - c|^2 - 2 d . sum (f_k - c) + n d^2,
 *   d = fbar - c.
 * The recent part only adds; when head wraps it becomes the older part,
 * which then loses the terms of each sample overwritten (computed as they
 * were added) and is empty again W samples later. So no sum lives more than
 * 2 W samples and nothing drifts: a sum's rounding is that of at most 2 W
 * additions. The subtraction above cancels to about 2 W eps times the
 * largest |f_k - c|^2 of the part: in T, about 2 eps (Delta / sigma_a)^2,
 * Delta how far the window's mean moved over those 2 W samples. At rest
 * (the decisions that matter) Delta is of the noise's size and the error is
 * that of the two-pass sums these replaced (test_stationary: the statistic
 * within 146 eps of the definition's in float, as before); after a heel
 * strike of 20 m/s^2 a detector with sigma_a = 0.02 m/s^2 in float can be
 * off by about 0.24 in T, against thresholds of 8-12 (3e-4 with the
 * pedestrian preset's 0.6 m/s^2). A sum of squares that rounds below 0 is
 * taken as 0.
 *
 * Choosing the threshold. Under rest with white noise of the stated
 * per-sample standard deviations (per axis; sigma = density / sqrt(dt)),
 *   W T ~ chi^2 with 6W - 2 degrees of freedom, approximately:
 * 3(W - 1) from the deviations f_k - fbar, 1 from the radial error
 * |fbar| - g of the mean (its two tangential components are absorbed by the
 * estimated direction u), 3W from the gyro samples; the approximation is
 * first order in sigma_a / g. So for a probability alpha of declaring a
 * window at rest as moving, threshold = Q(1 - alpha) / W, Q the quantile of
 * chi^2_{6W-2}; the Wilson-Hilferty approximation gives it within 0.2 %
 * for W >= 5 (0.6 % for W = 2, alpha >= 0.001):
 *   Q(p) ~= k (1 - 2/(9k) + z_p sqrt(2/(9k)))^3,  k = 6W - 2,
 * z_p the standard normal quantile (1.645 for p = 0.95, 2.326 for 0.99).
 *   W     threshold (alpha = 0.05 / 0.01 / 0.001)
 *   5     8.267 / 9.656 / 11.378
 *   10    7.678 / 8.595 / 9.704
 *   20    7.218 / 7.832 / 8.561
 *   32    6.974 / 7.446 / 7.999
 * Real sensors add vibration, bias and quantisation: raise the sigmas to
 * what the device shows at rest (se23_stationary_var gives the sample
 * variances of a window) rather than the threshold.
 *
 * Validation (types.h): the configuration is checked once by
 * se23_stationary_init; every sample is checked on every call (finite).
 * The detector's state is the library's: add checks only that its indices
 * are in range (so that a corrupted state cannot write out of bounds).
 *
 * Functions index:
 *   se23_stationary_init    check a configuration, start with an empty window
 *   se23_stationary_add     push one sample, update the statistic and the flag
 *   se23_stationary_reset   empty the window, keep the configuration
 *   se23_stationary_mean    window means of w and f (for alignment, align.h)
 *   se23_stationary_var     window sample variances of w and f, per axis
 *
 * All functions return a status (reset excepted) and write their outputs
 * only on SE23_OK.
 */
#ifndef SE23_STATIONARY_H
#define SE23_STATIONARY_H

#include "se23/types.h"

#ifdef __cplusplus
extern "C" {
#endif

/** Largest window [samples]. */
#define SE23_STATIONARY_WMAX 32

/** Detector configuration. */
typedef struct {
    int window;            /**< W [samples], 2 <= W <= SE23_STATIONARY_WMAX */
    se23_real_t sigma_a;   /**< accelerometer noise std of one sample, per axis [m/s^2] */
    se23_real_t sigma_g;   /**< gyro noise std of one sample, per axis [rad/s] */
    se23_real_t gravity;   /**< gravity magnitude g [m/s^2] (e.g. se23_earth_gravity) */
    se23_real_t threshold; /**< stationary when T < threshold (see file comment) */
} se23_stationary_config_t;

/** Running sums over one part of the window (file comment, "Running
 *  sums"): f about the part's reference c. */
typedef struct {
    se23_vec3_t c;  /**< reference: the first f of the part's cycle [m/s^2] */
    se23_vec3_t sf; /**< sum of f_k - c [m/s^2] */
    se23_vec3_t sw; /**< sum of w_k [rad/s] */
    se23_real_t qf; /**< sum of |f_k - c|^2 [m^2/s^4] */
    se23_real_t qw; /**< sum of |w_k|^2 [rad^2/s^2] */
} se23_stationary_sums_t;

/**
 * Detector state: the configuration and a ring buffer of the last samples.
 * Positions 0..count-1 of w and f hold the window (in no particular order);
 * head is the position the next sample overwrites (the oldest once full).
 * Fill with se23_stationary_init; treat as read-only afterwards.
 */
typedef struct {
    se23_stationary_config_t cfg;        /**< checked configuration */
    se23_vec3_t w[SE23_STATIONARY_WMAX]; /**< gyro samples w_b [rad/s] */
    se23_vec3_t f[SE23_STATIONARY_WMAX]; /**< specific-force samples f_b [m/s^2] */
    se23_stationary_sums_t recent;       /**< sums over positions 0..head-1 */
    se23_stationary_sums_t older;        /**< sums over the rest of the window */
    int count;                           /**< samples held, 0..W */
    int head;                            /**< next position to write, 0..W-1 */
    se23_vec3_t fbar;       /**< mean of f over the samples held (0 when empty): the fbar of stat */
    se23_real_t stat;       /**< T over the samples held (0 when empty); the SHOE statistic once full */
    int stationary;         /**< 1 if the window is full and stat < threshold, else 0 */
} se23_stationary_t;

/**
 * d = an empty detector with configuration cfg (every field of d written;
 * the sample buffers zeroed).
 * @param cfg the configuration
 * @param d out: the detector (written only on SE23_OK)
 * @return SE23_ERR_NULL; SE23_ERR_NONFINITE if a real of cfg is NaN or Inf;
 *         SE23_ERR_DIM unless 2 <= cfg->window <= SE23_STATIONARY_WMAX;
 *         SE23_ERR_DOMAIN unless sigma_a, sigma_g > 0 with sigma^2 and
 *         1/sigma^2 finite (about 1e-19 < sigma < 1e19 in float),
 *         gravity > 0 and threshold > 0. Checked in this order.
 */
se23_status_t se23_stationary_init(const se23_stationary_config_t *cfg,
                                   se23_stationary_t *d);

/**
 * Pushes one sample into the window (replacing the oldest once full), sets
 * d->stat to T over the samples now held (the SHOE statistic once the
 * window is full; over the n < W samples held, the same formula with n in
 * place of W) and d->stationary to 1 if the window is full and
 * d->stat < threshold, else 0.
 * @param d          detector from se23_stationary_init, updated in place
 * @param w_b        raw gyro sample [rad/s], body frame
 * @param f_b        raw specific-force sample [m/s^2], body frame
 * @param stationary if not NULL, receives d->stationary
 * @return SE23_ERR_NULL (d, w_b or f_b); SE23_ERR_DIM if the state's
 *         window, count or head is out of range (a corrupted state);
 *         SE23_ERR_NONFINITE if a sample component is NaN or Inf, or the
 *         statistic would overflow (huge samples, tiny sigmas). On error
 *         nothing is written: d (the sample is not stored) and *stationary.
 */
se23_status_t se23_stationary_add(se23_stationary_t *d, const se23_vec3_t *w_b,
                                  const se23_vec3_t *f_b, int *stationary);

/**
 * Empties the window (count, head, fbar, stat, stationary and the running
 * sums = 0); keeps d->cfg. The stored samples are not read again before
 * they are overwritten.
 * @param d the detector
 */
void se23_stationary_reset(se23_stationary_t *d);

/**
 * w_mean, f_mean = the means of the W samples of the full window, the
 * inputs of static alignment (align.h; N = W samples averaged), from the
 * running sums: f_mean is d->fbar, the fbar of d->stat.
 * @param d a detector with a full window
 * @param w_mean out: the gyro mean [rad/s] (written only on SE23_OK)
 * @param f_mean out: the specific-force mean [m/s^2] (written only on SE23_OK)
 * @return SE23_ERR_NULL; SE23_ERR_DIM if the window is not full (or the
 *         state's window or count is out of range); SE23_ERR_NONFINITE if
 *         a mean overflows.
 */
se23_status_t se23_stationary_mean(const se23_stationary_t *d,
                                   se23_vec3_t *w_mean, se23_vec3_t *f_mean);

/**
 * w_var, f_var = the unbiased sample variances of the W samples of the full
 * window, per axis: var_i = sum_k (x_k,i - xbar_i)^2 / (W - 1), two-pass (no
 * cancellation). At rest, sqrt(f_var_i) estimates sigma_a (and the
 * sigma_f of se23_align_cov) and sqrt(w_var_i) estimates sigma_g, both
 * including vibration and quantisation.
 * @param d a detector with a full window
 * @param w_var out: the gyro variances [(rad/s)^2] (written only on SE23_OK)
 * @param f_var out: the specific-force variances [(m/s^2)^2] (written only on SE23_OK)
 * @return as se23_stationary_mean.
 */
se23_status_t se23_stationary_var(const se23_stationary_t *d,
                                  se23_vec3_t *w_var, se23_vec3_t *f_var);

#ifdef __cplusplus
}
#endif

#endif /* SE23_STATIONARY_H */
