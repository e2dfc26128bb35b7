/*
 * Target test image: runs every routine of tv_list.h on the target against
 * the reference vectors generated on the host (tv.h), and checks per vector
 *  - the status equals the reference's;
 *  - on SE23_OK, |got - expected| <= tol * eps * scale for every output
 *    real (eps of the build's precision; scale, from the generator, is the
 *    magnitude of the block the real belongs to, see gen_common.hpp);
 *  - on any other status, the outputs are untouched (still TV_SENTINEL).
 * Prints one line per routine (vectors, worst error as a percentage of its
 * tolerance) and one line per failure; exits with the number of failed
 * vectors (capped at TV_EXIT_MAX; 254/255 are the port's assert/fault codes).
 */
#include <float.h>
#include <stdio.h>
#include <string.h>

#include "tv.h"

#if SE23_CFG_DOUBLE
#define TV_EPS DBL_EPSILON
#else
#define TV_EPS FLT_EPSILON
#endif

#define TV_EXIT_MAX 200
/** Largest number of output reals of any routine (a se23_gauss_t + margin). */
#define TV_MAX_OUT 256

/* ---- the checks ------------------------------------------------------------ */

static se23_real_t abs_r(se23_real_t x) { return x < TV_R(0) ? -x : x; }

/* Worst |got - expected| / (tol eps scale) over the row, or a negative value
 * if an output is NaN where a number was expected. tol 0 or scale 0 demand
 * equality. */
static se23_real_t row_error(const se23_real_t *got, const se23_real_t *exp,
                             const float *scale, int n, int tol, int *worst_idx)
{
    se23_real_t worst = TV_R(0);
    int j;
    *worst_idx = 0;
    for (j = 0; j < n; ++j) {
        se23_real_t diff = abs_r(got[j] - exp[j]);
        se23_real_t bound = (se23_real_t)tol * TV_R(TV_EPS) * (se23_real_t)scale[j];
        se23_real_t e;
        if (!(diff == diff)) {
            *worst_idx = j;
            return TV_R(-1);
        }
        e = bound > TV_R(0) ? diff / bound : (diff > TV_R(0) ? TV_R(1e30) : TV_R(0));
        if (e > worst) {
            worst = e;
            *worst_idx = j;
        }
    }
    return worst;
}

static int untouched(const se23_real_t *out, int n)
{
    int j;
    for (j = 0; j < n; ++j) {
        if (!(out[j] == TV_SENTINEL)) {
            return 0;
        }
    }
    return 1;
}

/* Runs one routine's vectors; returns the number of failed vectors. */
static int run_routine(const tv_routine_t *r)
{
    const tv_data_t *d = r->data;
    se23_real_t out[TV_MAX_OUT];
    se23_real_t worst = TV_R(0);
    int fails = 0;
    int k;

    if (d->n_in != r->n_in || d->n_out != r->n_out || r->n_out > TV_MAX_OUT ||
        d->n_vec <= 0) {
        printf("FAIL %s: table shape %d/%d/%d, routine %d/%d\n", r->name,
               d->n_vec, d->n_in, d->n_out, r->n_in, r->n_out);
        return 1;
    }
    for (k = 0; k < d->n_vec; ++k) {
        const se23_real_t *in = d->in != NULL ? d->in + (size_t)k * (size_t)d->n_in : NULL;
        const se23_real_t *exp = d->out + (size_t)k * (size_t)d->n_out;
        int want = d->status[k];
        int st;
        r->load(in);
        st = r->call();
        r->store(out);
        int ok = (st == want);
        if (ok && st == SE23_OK && r->n_out > 0) {
            int j;
            se23_real_t e = row_error(out, exp, d->scale + (size_t)k * (size_t)d->n_out,
                                      r->n_out, r->tol, &j);
            ok = (e >= TV_R(0) && e <= TV_R(1));
            if (!ok) {
                printf("FAIL %s vector %d: out[%d] = %.9g, expected %.17g (%.3g x tol)\n",
                       r->name, k, j, (double)out[j], (double)exp[j], (double)e);
            }
            worst = (e > worst) ? e : worst;
        } else if (!ok) {
            printf("FAIL %s vector %d: status %d, expected %d\n", r->name, k, st, want);
        } else if (st != SE23_OK && !untouched(out, r->n_out)) {
            ok = 0;
            printf("FAIL %s vector %d: status %d but outputs written\n", r->name, k, st);
        }
        fails += ok ? 0 : 1;
    }
    worst = worst < TV_R(99.99) ? worst : TV_R(99.99);
    printf("%-30s %4d vectors  worst %4d%% of tol (%d eps)  %s\n", r->name, d->n_vec,
           (int)(worst * TV_R(100)), r->tol, fails != 0 ? "FAIL" : "ok");
    return fails;
}

/* se23_status_str has no numeric output: every status has its own name. */
static int check_status_str(void)
{
    static const char *const names[] = {
        "SE23_OK", "SE23_ERR_NULL", "SE23_ERR_NONFINITE", "SE23_ERR_NOT_ROTATION",
        "SE23_ERR_DOMAIN", "SE23_ERR_DT", "SE23_ERR_NOT_SYMMETRIC", "SE23_ERR_NOT_PSD",
        "SE23_ERR_DIM"};
    int fails = 0;
    unsigned i;
    for (i = 0; i < sizeof names / sizeof names[0]; ++i) {
        const char *s = se23_status_str((se23_status_t)i);
        if (s == NULL || strcmp(s, names[i]) != 0) {
            printf("FAIL se23_status_str(%u) = %s\n", i, s != NULL ? s : "NULL");
            ++fails;
        }
    }
    printf("%-30s %4u values   %s\n", "se23_status_str", i, fails != 0 ? "FAIL" : "ok");
    return fails;
}

int main(void)
{
    int fails = 0;
    int i;
    printf("se23 target vectors, %s build\n", SE23_CFG_DOUBLE ? "double" : "float");
    for (i = 0; i < tv_n_routines; ++i) {
        fails += run_routine(&tv_routines[i]);
    }
    fails += check_status_str();
    printf("%d failure(s)\n", fails);
    return fails > TV_EXIT_MAX ? TV_EXIT_MAX : fails;
}
