/* The standard EKF covariance step; see ekf.h. */
#include "ekf.h"

#include <string.h>

static void skew(const double a[3], double S[3][3])
{
    S[0][0] = 0;
    S[0][1] = -a[2];
    S[0][2] = a[1];
    S[1][0] = a[2];
    S[1][1] = 0;
    S[1][2] = -a[0];
    S[2][0] = -a[1];
    S[2][1] = a[0];
    S[2][2] = 0;
}

void ekf_propagate(ekf_t *e, double R[3][3], const double w[3],
                   const double f[3], double dt, const double qg[3], double qa)
{
    double Phi[81] = {0}, W[3][3], Fx[3][3], tmp[81], out[81];
    skew(w, W);
    skew(f, Fx);
    for (int i = 0; i < 9; ++i) {
        Phi[9 * i + i] = 1.0;
    }
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double rf = 0;
            for (int k = 0; k < 3; ++k) {
                rf += R[i][k] * Fx[k][j];
            }
            Phi[9 * i + j] -= dt * W[i][j];    /* -w^ */
            Phi[9 * (3 + i) + j] = -dt * rf;   /* -R f^ */
        }
        Phi[9 * (6 + i) + 3 + i] = dt;         /* dp += dv dt */
    }
    for (int i = 0; i < 9; ++i) { /* tmp = Phi P */
        for (int j = 0; j < 9; ++j) {
            double s = 0;
            for (int k = 0; k < 9; ++k) {
                s += Phi[9 * i + k] * e->P[9 * k + j];
            }
            tmp[9 * i + j] = s;
        }
    }
    for (int i = 0; i < 9; ++i) { /* out = tmp Phi^T */
        for (int j = 0; j < 9; ++j) {
            double s = 0;
            for (int k = 0; k < 9; ++k) {
                s += tmp[9 * i + k] * Phi[9 * j + k];
            }
            out[9 * i + j] = s;
        }
    }
    for (int i = 0; i < 3; ++i) { /* G diag(qg, qa) G^T dt */
        out[9 * i + i] += qg[i] * dt;
        for (int j = 0; j < 3; ++j) {
            double s = 0;
            for (int k = 0; k < 3; ++k) {
                s += R[i][k] * R[j][k];
            }
            out[9 * (3 + i) + 3 + j] += qa * s * dt;
        }
    }
    memcpy(e->P, out, sizeof out);
}
