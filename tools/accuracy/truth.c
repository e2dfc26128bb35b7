/* Long-double exact propagation from generic matrix exponentials; see truth.h. */
#include "truth.h"

#include <math.h>
#include <string.h>

typedef long double ld;

#define NMAX 7

/* C = A B, n x n row-major. */
static void matmul(int n, const ld *A, const ld *B, ld *C)
{
    ld out[NMAX * NMAX];
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            ld s = 0;
            for (int k = 0; k < n; ++k) {
                s += A[i * n + k] * B[k * n + j];
            }
            out[i * n + j] = s;
        }
    }
    memcpy(C, out, sizeof(ld) * (size_t)(n * n));
}

/* E = exp(A), n <= NMAX: scale to norm <= 1/4, Taylor series until the
 * terms vanish in long double, square back. */
static void expm(int n, const ld *A, ld *E)
{
    ld norm = 0;
    for (int i = 0; i < n; ++i) {
        ld row = 0;
        for (int j = 0; j < n; ++j) {
            row += fabsl(A[i * n + j]);
        }
        norm = fmaxl(norm, row);
    }
    int s = 0;
    while (norm > 0.25L) {
        norm /= 2;
        ++s;
    }
    const ld scale = ldexpl(1, -s);
    ld As[NMAX * NMAX], term[NMAX * NMAX];
    for (int i = 0; i < n * n; ++i) {
        As[i] = A[i] * scale;
        term[i] = (i % (n + 1) == 0) ? 1 : 0;
        E[i] = term[i];
    }
    for (int k = 1; k < 40; ++k) {
        matmul(n, term, As, term);
        ld biggest = 0;
        for (int i = 0; i < n * n; ++i) {
            term[i] /= k;
            E[i] += term[i];
            biggest = fmaxl(biggest, fabsl(term[i]));
        }
        if (biggest < 1e-24L) {
            break;
        }
    }
    for (int i = 0; i < s; ++i) {
        matmul(n, E, E, E);
    }
}

/* Writes x^ into the 3x3 block at (r, c) of an n x n matrix, scaled by s. */
static void put_hat(int n, ld *A, int r, int c, const ld x[3], ld s)
{
    A[(r + 0) * n + c + 1] = -x[2] * s;
    A[(r + 0) * n + c + 2] = x[1] * s;
    A[(r + 1) * n + c + 0] = x[2] * s;
    A[(r + 1) * n + c + 2] = -x[0] * s;
    A[(r + 2) * n + c + 0] = -x[1] * s;
    A[(r + 2) * n + c + 1] = x[0] * s;
}

void acc_truth_gamma(const ld g[3], const ld omega[3], ld dt, acc_pose_t *G)
{
    /* y = (G^v, G^x, 1): y' = [[-Omega^, 0, g], [I, -Omega^, 0], [0, 0, 0]] y. */
    ld A[49] = {0}, E[49];
    put_hat(7, A, 0, 0, omega, -dt);
    put_hat(7, A, 3, 3, omega, -dt);
    for (int i = 0; i < 3; ++i) {
        A[i * 7 + 6] = g[i] * dt;
        A[(3 + i) * 7 + i] = dt;
    }
    expm(7, A, E);
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            G->R[i][j] = E[i * 7 + j];
        }
        G->v[i] = E[i * 7 + 6];
        G->p[i] = E[(3 + i) * 7 + 6];
    }
}

void acc_truth_step(const acc_pose_t *G, const ld w[3], const ld f[3], ld dt, acc_pose_t *T)
{
    /* Upsilon: expm(dt [[w^, f, 0], [0, 0, 1], [0, 0, 0]]) = [[dR, dV, dX], [0, 1, dt], [0, 0, 1]]. */
    ld A[25] = {0}, E[25];
    put_hat(5, A, 0, 0, w, dt);
    for (int i = 0; i < 3; ++i) {
        A[i * 5 + 3] = f[i] * dt;
    }
    A[3 * 5 + 4] = dt;
    expm(5, A, E);
    /* P = Phi_dt(T) Upsilon, then T = G P. */
    acc_pose_t P;
    for (int i = 0; i < 3; ++i) {
        ld rv = 0, rp = 0;
        for (int j = 0; j < 3; ++j) {
            ld r = 0;
            for (int k = 0; k < 3; ++k) {
                r += T->R[i][k] * E[k * 5 + j];
            }
            P.R[i][j] = r;
            rv += T->R[i][j] * E[j * 5 + 3];
            rp += T->R[i][j] * E[j * 5 + 4];
        }
        P.v[i] = rv + T->v[i];
        P.p[i] = rp + T->p[i] + dt * T->v[i];
    }
    for (int i = 0; i < 3; ++i) {
        ld gv = 0, gp = 0;
        for (int j = 0; j < 3; ++j) {
            ld r = 0;
            for (int k = 0; k < 3; ++k) {
                r += G->R[i][k] * P.R[k][j];
            }
            T->R[i][j] = r;
            gv += G->R[i][j] * P.v[j];
            gp += G->R[i][j] * P.p[j];
        }
        T->v[i] = gv + G->v[i];
        T->p[i] = gp + G->p[i];
    }
}

void acc_truth_shift(const ld omega[3], ld sign, acc_pose_t *T)
{
    const ld *p = T->p;
    const ld wxp[3] = {omega[1] * p[2] - omega[2] * p[1], omega[2] * p[0] - omega[0] * p[2],
                       omega[0] * p[1] - omega[1] * p[0]};
    for (int i = 0; i < 3; ++i) {
        T->v[i] += sign * wxp[i];
    }
}
