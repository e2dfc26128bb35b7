/*
 * libFuzzer target of se23/kalman.h: the measurement models on decoded
 * poses, vectors and covariances (statuses in the header's set; on SE23_OK
 * 1 <= m <= 9 and z, H and R finite in their m rows (the rest is not
 * written, kalman.h); on an error y untouched), and
 * the update of a state that se23_gauss_check accepts (the state is
 * trusted) with a model's measurement or a decoded one (statuses in the
 * header's set; on SE23_OK the state passes se23_gauss_check, the NIS is
 * finite and >= 0; on an error out and nis untouched). update(g, y, g, nis)
 * equals update(g, y, out, nis) bit for bit.
 */
#include "fuzz.h"

#include "se23/kalman.h"

static void cov3_of(fz_t *f, se23_mat3_t *C)
{
    se23_real_t P[9];
    int i, j;
    fz_cov(f, 3, 3, P);
    for (i = 0; i < 3; ++i) {
        for (j = 0; j < 3; ++j) {
            C->m[i][j] = P[3 * i + j];
        }
    }
}

static void check_meas(se23_status_t st, const se23_meas_t *y, const char *what)
{
    int i;
    FZ_REQUIRE(fz_status_in(st, 4, SE23_ERR_NONFINITE, SE23_ERR_NOT_ROTATION,
                            SE23_ERR_NOT_SYMMETRIC, SE23_ERR_NOT_PSD),
               "%s: %d", what, st);
    if (st != SE23_OK) {
        FZ_REQUIRE(fz_untouched(y, sizeof *y), "%s wrote on error %d", what, st);
        return;
    }
    FZ_REQUIRE(y->m >= 1 && y->m <= SE23_MEAS_MMAX, "%s: m = %d", what, y->m);
    FZ_REQUIRE(fz_finite(y->z, y->m) && fz_finite(y->H, y->m * SE23_GAUSS_NMAX),
               "%s: OK with a non-finite z or H in its m rows", what);
    for (i = 0; i < y->m; ++i) {
        FZ_REQUIRE(fz_finite(&y->R[SE23_MEAS_MMAX * i], y->m), "%s: OK with a non-finite R",
                   what);
    }
}

/* A measurement from one of the models at T, or decoded; 0 if none was made. */
static int meas_of(fz_t *f, const se23_pose_t *T, const se23_vec3_t *b_g, se23_meas_t *y)
{
    se23_vec3_t a, b, c;
    se23_mat3_t C;
    se23_status_t st;
    uint8_t op = fz_u8(f) % 6;
    if (op == 5) {
        int i;
        memset(y, 0, sizeof *y);
        y->m = fz_u8(f) < 240 ? 1 + fz_u8(f) % 9 : fz_int(f);
        for (i = 0; i < SE23_MEAS_MMAX; ++i) {
            y->z[i] = fz_u8(f) < 128 ? fz_mild(f) : fz_real(f);
        }
        for (i = 0; i < SE23_MEAS_MMAX * SE23_GAUSS_NMAX; ++i) {
            uint8_t k = fz_u8(f);
            y->H[i] = k < 128 ? 0 : k < 224 ? fz_mild(f) : fz_real(f);
        }
        fz_cov(f, (y->m >= 1 && y->m <= 9) ? y->m : 9, 9, y->R);
        return 1;
    }
    if (fz_u8(f) < 160) {
        fz_vec3_mild(f, &a);
        fz_vec3_mild(f, &b);
        fz_vec3_mild(f, &c);
    } else {
        fz_vec3(f, &a);
        fz_vec3(f, &b);
        fz_vec3(f, &c);
    }
    cov3_of(f, &C);
    fz_fill(y, sizeof *y);
    switch (op) {
    case 0:
        st = se23_meas_pos_nav(T, &a, &b, &C, y);
        check_meas(st, y, "meas_pos_nav");
        break;
    case 1:
        st = se23_meas_vel_nav(T, &a, &C, y);
        check_meas(st, y, "meas_vel_nav");
        break;
    case 2:
        st = se23_meas_vel_nav_lever(T, &a, &b, &c, &C, y);
        check_meas(st, y, "meas_vel_nav_lever");
        break;
    case 3:
        st = se23_meas_vel_body(T, &a, &C, y);
        check_meas(st, y, "meas_vel_body");
        break;
    default:
        st = se23_meas_zero_rate(&a, b_g, &C, y);
        FZ_REQUIRE(st != SE23_ERR_NOT_ROTATION, "meas_zero_rate: %d", st);
        check_meas(st, y, "meas_zero_rate");
        break;
    }
    return st == SE23_OK;
}

/* 1 if column j of the n x n P (stride 15) holds a nonzero. A P that
 * se23_gauss_check accepts differs from a PSD matrix by a dP within the
 * span of its eigenvectors of negative eigenvalue, which lies in the
 * coordinates of those columns: H's entries elsewhere (an exactly known
 * attitude read through H = 1e308) meet no defect. */
static int in_support(const se23_real_t *P, int n, int j)
{
    int i;
    for (i = 0; i < n; ++i) {
        if (P[15 * i + j] != 0) {
            return 1;
        }
    }
    return 0;
}

/* The bound of the known finding (fuzz.h) for the update of g with y:
 *  - rounding (src/kalman/kalman_halves.c): P+ is the exact Schur complement of a
 *    matrix within g (M_ii M_jj)^1/2 of M = [[S, C^T], [C, P]],
 *    g = (m + 1) eps / (1 - (m + 1) eps): a perturbation of at most
 *    e = g (n + m) max_i M_ii, which reaches P+ directly and through
 *    S^-1 and C (K dS K^T, K dC^T): (1 + |K|)^2 e (here 4 times that);
 *  - forming C = P H^T and S = H C + R (n-term sums, gn = (n + 1) eps /
 *    (1 - (n + 1) eps)): |dC| <= gn |P| |H|^T and |dS| <= gn (|H| |C| +
 *    |R| + |H| |P| |H|^T), entrywise, which M's diagonal does not bound
 *    when H's entries cancel over correlated states; they reach P+ as
 *    dC K^T + K dC^T - K dS K^T, added to e;
 *  - the inputs' own tolerance: P and R are accepted when PSD within
 *    SE23_CFG_COV_TOL of their largest variance, and P+ = (I - K H) P
 *    (I - K H)^T + K R K^T carries a defect dP, dR of that size as
 *    (I - K H) dP (I - K H)^T + K dR K^T: |(I - K H) E|_F^2 tol s_P n
 *    (E the support of P, in_support) +
 *    |K|_F^2 tol s_R m (K = C S^-1 in long double; S from R's upper
 *    triangle, as the update reads it). */
static double update_bound(const se23_gauss_t *g, const se23_meas_t *y)
{
    const int n = g->n, m = y->m;
    const double gam = (m + 1) * FZ_EPS / (1.0 - (m + 1) * FZ_EPS);
    const double sp = fz_max_diag(g->P.m, n, 15), sr = fz_max_diag(y->R, m, 9);
    const long double gn = (n + 1) * FZ_EPS / (1.0L - (n + 1) * FZ_EPS);
    long double C[15][9], Ca[15][9], S[9][9], K[15][9], k2 = 0.0L, a2 = 0.0L;
    long double ca2 = 0.0L, sb2 = 0.0L, sa2 = 0.0L, ef;
    double mx = sp;
    int r, q, i, j;
    for (i = 0; i < n; ++i) { /* C = P H^T, Ca = |P| |H|^T */
        for (r = 0; r < m; ++r) {
            long double c = 0.0L, a = 0.0L;
            for (j = 0; j < n; ++j) {
                c += (long double)g->P.m[15 * i + j] * y->H[15 * r + j];
                a += fabsl((long double)g->P.m[15 * i + j] * y->H[15 * r + j]);
            }
            C[i][r] = c;
            Ca[i][r] = a;
            ca2 += a * a;
        }
    }
    for (r = 0; r < m; ++r) { /* S = H C + R (upper triangle of R) */
        for (q = 0; q < m; ++q) {
            long double x = (long double)y->R[r <= q ? 9 * r + q : 9 * q + r];
            long double b = fabsl(x), h = 0.0L;
            for (j = 0; j < n; ++j) {
                x += (long double)y->H[15 * r + j] * C[j][q];
                b += fabsl((long double)y->H[15 * r + j] * C[j][q]);
                h += fabsl((long double)y->H[15 * r + j]) * Ca[j][q];
            }
            S[r][q] = x;
            sb2 += b * b;
            sa2 += h * h;
        }
        mx = fmax(mx, fabs((double)S[r][r]));
    }
    /* forming C and S: |dC| <= gn Ca, |dS| <= gn (|H| |C| + |R| + |H| Ca) */
    ef = gn * (2.0L * sqrtl(ca2) + sqrtl(sb2) + sqrtl(sa2));
    /* K = C S^-1: Gauss-Jordan on [S | C^T] (K^T = S^-1 C^T, S symmetric) */
    {
        long double A[9][9 + 15];
        for (r = 0; r < m; ++r) {
            for (q = 0; q < m; ++q) {
                A[r][q] = S[r][q];
            }
            for (i = 0; i < n; ++i) {
                A[r][m + i] = C[i][r];
            }
        }
        for (q = 0; q < m; ++q) {
            int piv = q;
            for (r = q + 1; r < m; ++r) {
                if (fabsl(A[r][q]) > fabsl(A[piv][q])) {
                    piv = r;
                }
            }
            /* S singular, or nearly, in the working precision (exact
             * measurements, R = 0, whose rows are dependent): its computed
             * entries are all rounding, yet may pass the pivot rule
             * (16 eps of the computed diagonal, itself cancelled); no
             * accuracy is left to bound */
            if (!(fabsl(A[piv][q]) > 64.0L * FZ_EPS * (long double)mx)) {
                return DBL_MAX;
            }
            for (j = 0; j < m + n; ++j) {
                const long double t = A[q][j];
                A[q][j] = A[piv][j];
                A[piv][j] = t;
            }
            for (r = 0; r < m; ++r) {
                if (r != q) {
                    const long double f = A[r][q] / A[q][q];
                    for (j = 0; j < m + n; ++j) {
                        A[r][j] -= f * A[q][j];
                    }
                }
            }
        }
        for (i = 0; i < n; ++i) {
            for (r = 0; r < m; ++r) {
                K[i][r] = A[r][m + i] / A[r][r];
                k2 += K[i][r] * K[i][r];
            }
        }
    }
    for (j = 0; j < n; ++j) { /* |(I - K H) E|_F^2, E the support of P */
        if (!in_support(g->P.m, n, j)) {
            continue;
        }
        for (i = 0; i < n; ++i) {
            long double x = (i == j) ? 1.0L : 0.0L;
            for (r = 0; r < m; ++r) {
                x -= K[i][r] * y->H[15 * r + j];
            }
            a2 += x * x;
        }
    }
    /* the rounding dM passes through S^-1 as well: K dS K^T, |K|^2 |dS|
     * (src/kalman/kalman_halves.c states only the first term, which does not hold
     * for a nearly singular S: R = 0 and rows that pin a state jointly) */
    {
        const long double b = 4.0L * (gam * (n + m) * mx + ef) * (1.0L + 2.0L * sqrtl(k2) + k2) +
                              SE23_CFG_COV_TOL * (a2 * sp * n + k2 * sr * m);
        return b < (long double)DBL_MAX ? (double)b : DBL_MAX;
    }
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fz_t f;
    se23_gauss_t g, out, t;
    int updates = 0;
    fz_init(&f, data, size);
    fz_gauss(&f, &g);
    if (se23_gauss_check(&g) != SE23_OK) {
        /* only the models: they check everything they read */
        se23_meas_t y;
        while (fz_left(&f) && updates++ < 16) {
            (void)meas_of(&f, &g.T, &g.b_g, &y);
        }
        return 0;
    }
    while (fz_left(&f) && updates++ < 16) {
        se23_meas_t y;
        se23_kalman_work_t w;
        se23_real_t nis, nis_a;
        se23_status_t st, sa;
        const int want_nis = fz_u8(&f) < 224;
        if (!meas_of(&f, &g.T, &g.b_g, &y)) {
            continue;
        }
        fz_fill(&out, sizeof out);
        fz_fill(&nis, sizeof nis);
        st = se23_kalman_update(&g, &y, &out, want_nis ? &nis : NULL);
        FZ_REQUIRE(fz_status_in(st, 5, SE23_ERR_DIM, SE23_ERR_NONFINITE, SE23_ERR_NOT_SYMMETRIC,
                                SE23_ERR_NOT_PSD, SE23_ERR_NULL),
                   "update: %d", st);
        FZ_REQUIRE(st != SE23_ERR_NULL, "update: SE23_ERR_NULL without a NULL argument");
        /* In place, and with a work area of fuzzed bytes: the same call. */
        memcpy(&t, &g, sizeof g);
        fz_fill(&nis_a, sizeof nis_a);
        fz_fill(&w, sizeof w);
        sa = se23_kalman_update_work(&t, &y, &w, &t, want_nis ? &nis_a : NULL);
        FZ_REQUIRE(sa == st, "update(g, g): status %d, plain %d", sa, st);
        if (st != SE23_OK) {
            FZ_REQUIRE(fz_untouched(&out, sizeof out) && fz_untouched(&nis, sizeof nis),
                       "update wrote on error %d", st);
            FZ_REQUIRE(fz_gauss_same(&t, &g), "update(g, g) changed g on error %d", st);
            continue;
        }
        if (!fz_check_cov_step(&out, update_bound(&g, &y), "update")) {
            return 0; /* the known finding: not a state to go on with */
        }
        if (want_nis) {
            FZ_REQUIRE(isfinite(nis) && nis >= 0, "update: OK with NIS %g", (double)nis);
            FZ_REQUIRE(memcmp(&nis, &nis_a, sizeof nis) == 0, "update(g, g): another NIS");
        } else {
            FZ_REQUIRE(fz_untouched(&nis, sizeof nis), "update wrote a NIS it was not asked for");
        }
        FZ_REQUIRE(fz_gauss_same(&t, &out), "update(g, g) differs from the plain call");
        memcpy(&g, &out, sizeof g);
    }
    return 0;
}
