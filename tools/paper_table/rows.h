/**
 * @file rows.h
 * @brief The rows of the paper's Table "Higher-order errors for a low-cost
 *        IMU": one preintegrated factor at the bias estimate bbar = 0, its
 *        first-order corrections to a bias change db, and their errors
 *        against re-integration with db.
 *
 * Rows (each correction is scored against re-integration with the same
 * increment model as its Deltas):
 *   ROW_FORSTER        Forster et al. 2017 as a pipeline: Deltas of their
 *                      discrete model (exp(w dt), f dt, f dt^2/2,
 *                      se23_imu_increment_forster), their Jacobians, scored
 *                      against re-integration with that model
 *   ROW_FORSTER_EXACT  Forster et al.'s Jacobians applied to the exact
 *                      Deltas (se23_preint_unc_correct_classic as is)
 *   ROW_BASIC          Delta exp(J db), J with the paper's B_k = dt I_{9,6}:
 *                      the paper's "Proposed"
 *   ROW_PAPER          the paper's method on its own increment: Deltas of
 *                      eq. backtofuture (exp(w dt), f dt, 0,
 *                      se23_imu_increment_paper), J with B_k = dt I_{9,6}
 *                      and F_k of those increments, scored against
 *                      re-integration with that increment
 *   ROW_EXACT          Delta exp(J db), J with the exact B_k: se23 beyond
 *                      the paper
 *   ROW_NONE           the exact Deltas uncorrected
 * ROW_FORSTER_EXACT, ROW_BASIC, ROW_EXACT and ROW_NONE use the exact
 * increment (se23_imu_increment) for the Deltas and the re-integration.
 */
#ifndef PAPER_ROWS_H
#define PAPER_ROWS_H

#include "se23/preint.h"
#include "se23/preint_unc.h"

enum { ROW_FORSTER, ROW_FORSTER_EXACT, ROW_BASIC, ROW_PAPER, ROW_EXACT, ROW_NONE, N_ROWS };

/** Sums of squared velocity and position errors over n corrections. */
typedef struct {
    double v2; /**< [m^2/s^2] */
    double p2; /**< [m^2] */
    long n;
} row_acc_t;

/** One error-free IMU sample. */
typedef struct {
    double w[3]; /**< angular rate, body [rad/s] */
    double f[3]; /**< specific force, body [m/s^2] */
} raw_sample_t;

/** One factor of n error-free samples, integrated at bbar = 0. */
typedef struct {
    const raw_sample_t *wf; /**< the samples */
    long n;                 /**< number of samples */
    double dt;              /**< sample period [s] */
    se23_preint_unc_t ex;   /**< exact Deltas, J with the exact B_k, classical Jacobians */
    se23_preint_unc_t ba;   /**< exact Deltas, J with the basic B_k */
    se23_preint_t forster;  /**< Deltas of Forster et al.'s discrete model */
    se23_preint_t paper;    /**< Deltas of the paper's eq. backtofuture */
    se23_mat9x6_t paper_J;  /**< their bias Jacobian, B_k = dt I_{9,6} */
} factor_t;

/** fa = the factor of the n samples wf (kept by pointer) of period dt. */
void factor_build(factor_t *fa, const raw_sample_t *wf, long n, double dt);

/**
 * Adds to acc[row] the error of each row's correction of fa to the bias
 * estimate db = (db_g [rad/s], db_a [m/s^2]) against the re-integration of
 * the corrected samples (w + db_g, f + db_a) (sensor convention of
 * preint_unc.h).
 */
void factor_score(const factor_t *fa, const double db[6], row_acc_t acc[N_ROWS]);

#endif /* PAPER_ROWS_H */
