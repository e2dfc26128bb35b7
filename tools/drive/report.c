/*
 * se23-drive: scores a filter run on a real drive against the drive's
 * reference. Reads the import log (se23-drive-import: SE23_GNSS_REF, the
 * reference antenna positions in NED), its sidecar (the first fix's time
 * and the outages) and the filter's log (se23-ins: SE23_NAV).
 *
 * At every reference epoch the nav state is interpolated linearly in
 * position between the two nav states around it (se23-ins publishes at
 * --nav-rate; at 50-100 Hz a car moves 0.2-0.3 m between them and the
 * curvature error of the straight line is below a millimetre); attitude
 * and covariance are the nearer state's. Inside an outage only nav states
 * before its end are used (the one after it may hold the first fix back):
 * past the last of them the position is carried by its velocity. The
 * antenna estimate is p + R lever, its error e = p_ref - (p + R lever) in
 * NED; with T = That exp(xi), e = R (rho - [lever]x phi) to first order, so
 * its covariance is R (P_rr - S P_pr - P_rp S^T + S P_pp S^T) R^T with
 * S = [lever]x, plus the reference's own sigma per axis (the .pos sigmas,
 * 0 for a reference without them). NEES = e^T C^-1 e, 3 dof.
 *
 * Over the epochs with GNSS (outside every outage): horizontal error
 * median, 95 %, max; the mean NEES and its chi-square 99 % band for that
 * many epochs (Wilson-Hilferty, as tools/lcm/nees-mc.sh, treating the
 * epochs as independent: they are not, the band is a lower bound on the
 * spread); the fraction of epochs whose NEES is beyond chi2(3, 0.99) =
 * 11.345. Per outage: distance along the reference, horizontal error at
 * its last reference epoch, that in % of the distance, NEES there; per
 * outage length the median %.
 *
 * Exit status: 0 done and within every --max-* bound; 1 a bound exceeded
 * or an input unreadable or empty; 2 bad usage.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "../lcm/harness.h"
#include "../lcm/logfile.h"
#include "../report/logread.h"
#include "../report/metrics.h"
#include "drive.h"
#include "se23lcm_gnss_fix.h"

#define PROG "se23-drive"
#define CH_REF "SE23_GNSS_REF"
#define CHI2_3_99 11.3449
#define Z99 2.5758293035489
#define LEN_GROUPS_MAX 16

typedef struct {
    const char *meta, *csv, *plots, *plot_script, *label, *pct_len_s;
    double lever[3], skip, min_dist, max_gap, settle, max_speed;
    double max_h50, max_h95, max_hmax, max_pct, max_beyond;
    int nees_band;
    int n_outages; /* from the command line (-1: the sidecar's) */
    double outage[DRIVE_OUTAGES_MAX][2];
    int n_pct_len;
    double pct_len[LEN_GROUPS_MAX][2];
} opts_t;

typedef struct {
    double t, t_rel;
    double ref[3], est[3], e[3], eh, sig[3], sig_h, nees;
    int outage;     /* index, or -1 (with GNSS), -2 (settling, --settle) */
    double t_in;    /* since the outage's start [s] (NaN outside) */
} row_t2;

typedef struct {
    double start, len, len_scored, dist, err_end, pct, nees_end, err_max;
    int n_epochs, scored;
} outage_t;

static void usage(FILE *f)
{
    fprintf(f,
            "usage: se23-drive [options] IMPORT_LOG NAV_LOG\n"
            "Scores the nav states of NAV_LOG (se23-ins, SE23_NAV) against the reference\n"
            "SE23_GNSS_REF of IMPORT_LOG (se23-drive-import) at every reference epoch.\n"
            "  --meta FILE            the importer's sidecar (IMPORT_LOG.drive)\n"
            "  --outage START,LEN     outages [s after the first fix] (repeatable; default:\n"
            "                         the sidecar's, i.e. the ones the importer applied)\n"
            "  --lever X,Y,Z          antenna w.r.t. the IMU, body frame [m] (0,0,0)\n"
            "  --skip S               score from S s after the first fix (0)\n"
            "  --settle S             epochs within S s after an outage's end are neither\n"
            "                         in it nor with GNSS: the filter takes its first fixes\n"
            "                         back (1)\n"
            "  --min-distance M       outages shorter than M m along the reference are not\n"
            "                         scored in %% of distance (10)\n"
            "  --max-ref-speed V      reference steps faster than V m/s are glitches, left\n"
            "                         out of the distances driven (70)\n"
            "  --max-nav-gap S        reference epochs with no nav state within S s are\n"
            "                         skipped (0.5)\n"
            "  --csv FILE             every reference epoch scored, one row each; the\n"
            "                         outages into FILE with .outages.csv for .csv\n"
            "  --plots DIR            the CSVs into DIR and the plots (--plot-script)\n"
            "  --plot-script PATH     (tools/drive/plot_drive.py; \"\" = CSVs only)\n"
            "  --label TEXT           a name for the printout\n"
            "Bounds (exit 1 when exceeded; 0 = no bound):\n"
            "  --max-aided-h50 M      median horizontal error with GNSS [m]\n"
            "  --max-aided-h95 M      its 95th percentile [m]\n"
            "  --max-aided-hmax M     its maximum [m]\n"
            "  --max-outage-pct P     every outage length's median end error [%% of distance]\n"
            "  --max-outage-pct-len LEN:P[,LEN:P...]  the same per outage length [s]\n"
            "  --max-nees-beyond F    fraction of GNSS epochs beyond chi2(3, 0.99)\n"
            "  --nees-band on|off     the mean NEES with GNSS within its 99 %% band (off)\n");
}

static int take_outages(int *argc, char **argv, opts_t *o)
{
    int i, w = 1;
    o->n_outages = -1;
    for (i = 1; i < *argc; i++) {
        const char *v = NULL;
        if (strcmp(argv[i], "--outage") == 0 && i + 1 < *argc) {
            v = argv[++i];
        } else if (strncmp(argv[i], "--outage=", 9) == 0) {
            v = argv[i] + 9;
        }
        if (v == NULL) {
            argv[w++] = argv[i];
            continue;
        }
        if (o->n_outages < 0) {
            o->n_outages = 0;
        }
        if (o->n_outages >= DRIVE_OUTAGES_MAX ||
            drive_parse_outage(v, o->outage[o->n_outages]) != 0) {
            fprintf(stderr, PROG ": bad or too many --outage (START,LEN): %s\n", v);
            return -1;
        }
        o->n_outages++;
    }
    *argc = w;
    return 0;
}

static int parse_pct_len(opts_t *o)
{
    const char *s = o->pct_len_s;
    while (s != NULL && *s != '\0') {
        char *end;
        double a, b;
        a = strtod(s, &end);
        if (end == s || *end != ':') {
            return -1;
        }
        s = end + 1;
        b = strtod(s, &end);
        if (end == s || (*end != ',' && *end != '\0') || o->n_pct_len >= LEN_GROUPS_MAX ||
            !(a > 0) || !(b > 0)) {
            return -1;
        }
        o->pct_len[o->n_pct_len][0] = a;
        o->pct_len[o->n_pct_len][1] = b;
        o->n_pct_len++;
        s = *end == ',' ? end + 1 : end;
    }
    return 0;
}

static int parse_args(int argc, char **argv, opts_t *o, const char **imp, const char **nav)
{
    const double inf = HUGE_VAL;
    const char **pos = calloc((size_t)argc + 1, sizeof *pos);
    int n_pos = 0, rc;
    const harness_opt_t opts[] = {
        {"--meta", HOPT_STR, &o->meta, 0, 0, NULL},
        {"--lever", HOPT_VEC3, o->lever, -100.0, 100.0, NULL},
        {"--skip", HOPT_DOUBLE, &o->skip, 0.0, 1e7, NULL},
        {"--settle", HOPT_DOUBLE, &o->settle, 0.0, 1e4, NULL},
        {"--max-ref-speed", HOPT_DOUBLE, &o->max_speed, 1.0, 1e6, NULL},
        {"--min-distance", HOPT_DOUBLE, &o->min_dist, 0.0, 1e9, NULL},
        {"--max-nav-gap", HOPT_DOUBLE, &o->max_gap, 1e-3, 1e3, NULL},
        {"--csv", HOPT_STR, &o->csv, 0, 0, NULL},
        {"--plots", HOPT_STR, &o->plots, 0, 0, NULL},
        {"--plot-script", HOPT_STR, &o->plot_script, 0, 0, NULL},
        {"--label", HOPT_STR, &o->label, 0, 0, NULL},
        {"--max-aided-h50", HOPT_DOUBLE, &o->max_h50, 0.0, inf, NULL},
        {"--max-aided-h95", HOPT_DOUBLE, &o->max_h95, 0.0, inf, NULL},
        {"--max-aided-hmax", HOPT_DOUBLE, &o->max_hmax, 0.0, inf, NULL},
        {"--max-outage-pct", HOPT_DOUBLE, &o->max_pct, 0.0, inf, NULL},
        {"--max-outage-pct-len", HOPT_STR, &o->pct_len_s, 0, 0, NULL},
        {"--max-nees-beyond", HOPT_DOUBLE, &o->max_beyond, 0.0, 1.0, NULL},
        {"--nees-band", HOPT_CHOICE, &o->nees_band, 0, 0, harness_on_off},
    };
    if (pos == NULL) {
        return -1;
    }
    o->min_dist = 10.0;
    o->max_gap = 0.5;
    o->settle = 1.0;
    o->max_speed = 70.0;
    o->plot_script = "tools/drive/plot_drive.py";
    rc = take_outages(&argc, argv, o);
    if (rc == 0) {
        rc = harness_parse_opts(PROG, argc, argv, opts, (int)(sizeof opts / sizeof opts[0]),
                                usage, pos, &n_pos);
    }
    if (rc == 0 && n_pos != 2) {
        fprintf(stderr, PROG ": give IMPORT_LOG and NAV_LOG\n");
        rc = -1;
    }
    if (rc == 0 && parse_pct_len(o) != 0) {
        fprintf(stderr, PROG ": bad value for --max-outage-pct-len (LEN:P[,LEN:P...]): %s\n",
                o->pct_len_s);
        rc = -1;
    }
    if (rc == 0) {
        *imp = pos[0];
        *nav = pos[1];
    }
    free(pos);
    return rc;
}

/* The reference epochs of the import log, in time order. */
static int read_ref(const char *path, se23lcm_gnss_fix **out, size_t *n)
{
    logfile_t lf;
    logfile_event_t ev;
    size_t cap = 0;
    int64_t bad = 0;
    *out = NULL;
    *n = 0;
    if (logfile_open(&lf, path, PROG) != 0) {
        return -1;
    }
    while (logfile_next(&lf, &ev)) {
        se23lcm_gnss_fix m, *slot;
        if (strcmp(ev.channel, CH_REF) != 0) {
            continue;
        }
        if (se23lcm_gnss_fix_decode(ev.data, 0, ev.datalen, &m) < 0 ||
            !isfinite(m.p_n[0] + m.p_n[1] + m.p_n[2])) {
            bad++;
            continue;
        }
        if (*n > 0 && m.t_ns <= (*out)[*n - 1].t_ns) {
            bad++;
            continue;
        }
        slot = drive_push((void **)out, n, &cap, sizeof *slot);
        if (slot == NULL) {
            logfile_close(&lf);
            return -1;
        }
        *slot = m;
    }
    logfile_close(&lf);
    if (bad > 0) {
        fprintf(stderr, PROG ": %s: %lld reference events undecodable or out of order, "
                        "skipped\n", path, (long long)bad);
    }
    return 0;
}

/* Index of the last nav state at or before t_ns (-1: none). */
static long nav_at_or_before(const log_data_t *d, int64_t t_ns)
{
    long lo = 0, hi = (long)d->n_nav - 1, r = -1;
    while (lo <= hi) {
        const long mid = lo + (hi - lo) / 2;
        if (d->nav[mid].t_ns <= t_ns) {
            r = mid;
            lo = mid + 1;
        } else {
            hi = mid - 1;
        }
    }
    return r;
}

/* The antenna error's covariance in NED (file comment), into C. */
static void antenna_cov(const se23lcm_nav_state *s, const double L[3], const double sref[3],
                        double C[3][3])
{
    const double S[3][3] = {{0, -L[2], L[1]}, {L[2], 0, -L[0]}, {-L[1], L[0], 0}};
    double Pb[3][3], M[3][3];
    int i, j, k;
    /* Pb = P_rr - S P_pr - P_rp S^T + S P_pp S^T, blocks of P at 6 (rho) and 0 (phi) */
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            double a = s->P[15 * (6 + i) + 6 + j];
            for (k = 0; k < 3; k++) {
                a -= S[i][k] * s->P[15 * k + 6 + j];       /* S P_phi,rho */
                a -= s->P[15 * (6 + i) + k] * S[j][k];     /* P_rho,phi S^T */
            }
            Pb[i][j] = a;
        }
    }
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            double a = 0.0;
            int l;
            for (k = 0; k < 3; k++) {
                for (l = 0; l < 3; l++) {
                    a += S[i][k] * s->P[15 * k + l] * S[j][l];
                }
            }
            Pb[i][j] += a;
        }
    }
    /* C = R Pb R^T + diag(sref^2) */
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            double a = 0.0;
            for (k = 0; k < 3; k++) {
                a += s->R_nb[3 * i + k] * Pb[k][j];
            }
            M[i][j] = a;
        }
    }
    for (i = 0; i < 3; i++) {
        for (j = 0; j < 3; j++) {
            double a = 0.0;
            for (k = 0; k < 3; k++) {
                a += M[i][k] * s->R_nb[3 * j + k];
            }
            C[i][j] = a + (i == j ? sref[i] * sref[i] : 0.0);
        }
    }
}

/*
 * Scores the reference epoch m at t_ns against the nav states; before_ns:
 * use only nav states before it (INT64_MAX: any). 0 and r filled, or -1
 * if no nav state covers it.
 */
static int score(const opts_t *o, const log_data_t *d, const se23lcm_gnss_fix *m,
                 int64_t before_ns, row_t2 *r)
{
    const int64_t t = m->t_ns;
    const int64_t gap = llround(o->max_gap * 1e9);
    long a = nav_at_or_before(d, t);
    const se23lcm_nav_state *sa, *sb = NULL, *near;
    double p[3], C[3][3], w = 0.0, ant[3];
    int k;
    while (a >= 0 && d->nav[a].t_ns >= before_ns) {
        a--;
    }
    if (a < 0 || t - d->nav[a].t_ns > gap) {
        return -1;
    }
    sa = &d->nav[a];
    if ((size_t)(a + 1) < d->n_nav && d->nav[a + 1].t_ns < before_ns && sa->t_ns != t &&
        d->nav[a + 1].t_ns - sa->t_ns <= gap) {
        sb = &d->nav[a + 1];
        w = (double)(t - sa->t_ns) / (double)(sb->t_ns - sa->t_ns);
    }
    if (sb == NULL && sa->t_ns != t && before_ns == INT64_MAX &&
        (size_t)(a + 1) == d->n_nav && t - sa->t_ns > llround(0.05 * 1e9)) {
        return -1; /* past the end of the run */
    }
    for (k = 0; k < 3; k++) {
        p[k] = sb != NULL ? (1.0 - w) * sa->p_n[k] + w * sb->p_n[k]
                          : sa->p_n[k] + sa->v_n[k] * (double)(t - sa->t_ns) * 1e-9;
    }
    near = sb != NULL && w > 0.5 ? sb : sa;
    for (k = 0; k < 3; k++) {
        ant[k] = p[k] + near->R_nb[3 * k] * o->lever[0] + near->R_nb[3 * k + 1] * o->lever[1] +
                 near->R_nb[3 * k + 2] * o->lever[2];
        r->ref[k] = m->p_n[k];
        r->est[k] = ant[k];
        r->e[k] = m->p_n[k] - ant[k];
    }
    antenna_cov(near, o->lever, m->sigma_p, C);
    for (k = 0; k < 3; k++) {
        r->sig[k] = C[k][k] > 0 ? sqrt(C[k][k]) : NAN;
    }
    r->sig_h = C[0][0] + C[1][1] > 0 ? sqrt(C[0][0] + C[1][1]) : NAN;
    r->eh = hypot(r->e[0], r->e[1]);
    r->nees = metrics_nees(&C[0][0], 3, r->e, 3);
    r->t = (double)t * 1e-9;
    return 0;
}

/* Leaves out nav states with a NaN/Inf in R, v, p, P or a negative
 * variance of position or attitude; returns how many. */
static size_t screen_nav(log_data_t *d)
{
    size_t i, w = 0;
    for (i = 0; i < d->n_nav; i++) {
        const se23lcm_nav_state *s = &d->nav[i];
        int k, ok = 1;
        for (k = 0; k < 9 && ok; k++) {
            ok = isfinite(s->R_nb[k]);
        }
        for (k = 0; k < 3 && ok; k++) {
            ok = isfinite(s->p_n[k]) && isfinite(s->v_n[k]) && s->P[16 * k] >= 0.0 &&
                 s->P[16 * (6 + k)] >= 0.0;
        }
        for (k = 0; k < 225 && ok; k++) {
            ok = isfinite(s->P[k]);
        }
        if (ok) {
            d->nav[w++] = *s;
        }
    }
    i = d->n_nav - w;
    d->n_nav = w;
    return i;
}

static int cmp_d(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* The q-quantile (0..1) of x[0..n-1] (sorted in place; nearest rank). */
static double quantile(double *x, size_t n, double q)
{
    size_t k;
    if (n == 0) {
        return NAN;
    }
    qsort(x, n, sizeof *x, cmp_d);
    k = (size_t)ceil(q * (double)n);
    return x[k > 0 ? k - 1 : 0];
}

static double median(double *x, size_t n)
{
    if (n == 0) {
        return NAN;
    }
    qsort(x, n, sizeof *x, cmp_d);
    return n % 2 ? x[n / 2] : 0.5 * (x[n / 2 - 1] + x[n / 2]);
}

/* Outages file name for --csv FILE: FILE with .outages.csv for .csv. */
static char *outages_name(const char *csv)
{
    const size_t n = strlen(csv);
    char *s = malloc(n + 16);
    if (s == NULL) {
        return NULL;
    }
    strcpy(s, csv);
    if (n > 4 && strcmp(s + n - 4, ".csv") == 0) {
        s[n - 4] = '\0';
    }
    strcat(s, ".outages.csv");
    return s;
}

static int write_csv(const char *path, const row_t2 *rows, size_t n, const outage_t *out,
                     int n_out)
{
    FILE *f = fopen(path, "w");
    char *op = outages_name(path);
    size_t i;
    int k;
    if (f == NULL || op == NULL) {
        fprintf(stderr, PROG ": cannot write %s\n", path);
        free(op);
        if (f != NULL) {
            fclose(f);
        }
        return -1;
    }
    fprintf(f, "t_s,t_rel_s,ref_n,ref_e,ref_d,est_n,est_e,est_d,err_n,err_e,err_d,err_h,sig_n,"
               "sig_e,sig_d,sig_h,nees3,outage,t_in_outage_s\n");
    for (i = 0; i < n; i++) {
        const row_t2 *r = &rows[i];
        fprintf(f, "%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.4f,%.5f,%.5f,%.5f,"
                   "%.5f,%.4g,%d,%.4f\n",
                r->t, r->t_rel, r->ref[0], r->ref[1], r->ref[2], r->est[0], r->est[1], r->est[2],
                r->e[0], r->e[1], r->e[2], r->eh, r->sig[0], r->sig[1], r->sig[2], r->sig_h,
                r->nees, r->outage, r->t_in);
    }
    fclose(f);
    f = fopen(op, "w");
    if (f == NULL) {
        fprintf(stderr, PROG ": cannot write %s\n", op);
        free(op);
        return -1;
    }
    fprintf(f, "index,start_s,len_s,len_scored_s,dist_m,err_end_h_m,err_end_pct,nees_end,"
               "err_max_h_m,epochs\n");
    for (k = 0; k < n_out; k++) {
        fprintf(f, "%d,%.3f,%.3f,%.3f,%.3f,%.4f,%.4f,%.4g,%.4f,%d\n", k, out[k].start,
                out[k].len, out[k].len_scored, out[k].dist, out[k].err_end, out[k].pct,
                out[k].nees_end, out[k].err_max, out[k].n_epochs);
    }
    fclose(f);
    free(op);
    return 0;
}

int main(int argc, char **argv)
{
    opts_t o;
    const char *imp = NULL, *navp = NULL;
    drive_meta_t meta;
    char *mp = NULL;
    log_data_t d;
    se23lcm_gnss_fix *ref = NULL;
    size_t n_jumps = 0, n_settle = 0, n_nav_bad = 0, n_ref = 0, i, n_rows = 0, n_aided = 0;
    size_t n_beyond = 0, n_nees = 0, n_uncovered = 0;
    row_t2 *rows = NULL;
    outage_t out[DRIVE_OUTAGES_MAX];
    double *tmp = NULL, (*ol)[2], nees_sum = 0.0;
    int n_out, k, fail = 0;
    int64_t first_ns;
    char **av = drive_split_eq(&argc, argv);
    memset(&o, 0, sizeof o);
    memset(&d, 0, sizeof d);
    if (av == NULL || parse_args(argc, av, &o, &imp, &navp) != 0) {
        usage(stderr);
        return 2;
    }
    if (o.meta == NULL) {
        mp = malloc(strlen(imp) + 8);
        if (mp == NULL) {
            return 1;
        }
        sprintf(mp, "%s.drive", imp);
    }
    if (drive_meta_read(o.meta != NULL ? o.meta : mp, &meta) != 0) {
        free(mp);
        return 1;
    }
    free(mp);
    if (o.n_outages >= 0) {
        n_out = o.n_outages;
        ol = o.outage;
    } else {
        n_out = meta.n_outages;
        ol = meta.outage;
    }
    first_ns = llround(meta.first_fix_s * 1e9);
    /* logread's screening knows the status bits of its day (0x1ff) and
     * would leave out states with newer ones: screened here instead, for
     * what the scoring uses (finite pose and covariance) */
    d.screen = 0;
    if (read_ref(imp, &ref, &n_ref) != 0 || log_read(navp, &d) != 0) {
        free(ref);
        log_free(&d);
        return 1;
    }
    log_sort(&d);
    n_nav_bad = screen_nav(&d);
    if (n_ref == 0 || d.n_nav == 0) {
        fprintf(stderr, PROG ": %s: %s\n", n_ref == 0 ? imp : navp,
                n_ref == 0 ? "no reference epoch (SE23_GNSS_REF)" : "no nav state (SE23_NAV)");
        free(ref);
        log_free(&d);
        return 1;
    }
    rows = calloc(n_ref, sizeof *rows);
    tmp = calloc(n_ref + 1, sizeof *tmp);
    if (rows == NULL || tmp == NULL) {
        return 1;
    }
    memset(out, 0, sizeof out);
    for (k = 0; k < n_out; k++) {
        out[k].start = ol[k][0];
        out[k].len = ol[k][1];
        out[k].err_end = out[k].pct = out[k].nees_end = NAN;
    }
    /* every reference epoch */
    for (i = 0; i < n_ref; i++) {
        const double t_rel = (double)(ref[i].t_ns - first_ns) * 1e-9;
        row_t2 *r = &rows[n_rows];
        int in = -1;
        int64_t before = INT64_MAX;
        if (t_rel < o.skip) {
            continue;
        }
        for (k = 0; k < n_out; k++) {
            const double end = ol[k][0] + ol[k][1];
            if (in == -1 && t_rel >= end && t_rel < end + o.settle) {
                in = -2; /* settling after the outage (--settle) */
            }
        }
        for (k = 0; k < n_out; k++) {
            if (t_rel >= ol[k][0] && t_rel < ol[k][0] + ol[k][1]) {
                in = k;
                before = first_ns + llround((ol[k][0] + ol[k][1]) * 1e9);
            }
        }
        if (score(&o, &d, &ref[i], before, r) != 0) {
            n_uncovered++;
            continue;
        }
        r->t_rel = t_rel;
        r->outage = in;
        r->t_in = in >= 0 ? t_rel - ol[in][0] : NAN;
        n_rows++;
    }
    if (n_rows == 0) {
        fprintf(stderr, PROG ": no reference epoch is covered by a nav state\n");
        return 1;
    }
    /* per outage: distance along the reference, the end */
    for (k = 0; k < n_out; k++) {
        const row_t2 *prev = NULL;
        for (i = 0; i < n_rows; i++) {
            const row_t2 *r = &rows[i];
            if (r->outage != k) {
                continue;
            }
            if (prev != NULL) {
                const double step = hypot(r->ref[0] - prev->ref[0], r->ref[1] - prev->ref[1]);
                if (step <= o.max_speed * (r->t - prev->t)) {
                    out[k].dist += step;
                } else {
                    n_jumps++;
                }
            }
            out[k].err_max = r->eh > out[k].err_max ? r->eh : out[k].err_max;
            out[k].n_epochs++;
            out[k].len_scored = r->t_in;
            out[k].err_end = r->eh;
            out[k].nees_end = r->nees;
            prev = r;
        }
        out[k].scored = out[k].n_epochs >= 2 && out[k].dist >= o.min_dist;
        out[k].pct = out[k].scored ? 100.0 * out[k].err_end / out[k].dist : NAN;
    }
    /* with GNSS */
    for (i = 0; i < n_rows; i++) {
        n_settle += rows[i].outage == -2;
        if (rows[i].outage == -1) {
            tmp[n_aided++] = rows[i].eh;
            if (isfinite(rows[i].nees)) {
                nees_sum += rows[i].nees;
                n_nees++;
                n_beyond += rows[i].nees > CHI2_3_99;
            }
        }
    }
    printf(PROG ": %s%s%s: %zu reference epochs, %zu scored against %zu nav states (%zu not "
           "covered%s), lever %.3f,%.3f,%.3f m\n",
           o.label != NULL ? o.label : "", o.label != NULL ? " " : "", navp, n_ref, n_rows,
           d.n_nav, n_uncovered, o.skip > 0 ? " or skipped" : "", o.lever[0], o.lever[1],
           o.lever[2]);
    if (n_jumps > 0) {
        printf(PROG ": %zu reference steps in outages faster than %.0f m/s (glitches) left out of "
               "the distances\n", n_jumps, o.max_speed);
    }
    if (n_nav_bad > 0) {
        printf(PROG ": %zu nav states left out: a NaN/Inf, or a negative position variance\n",
               n_nav_bad);
    }
    {
        const double h50 = n_aided ? median(tmp, n_aided) : NAN;
        const double h95 = quantile(tmp, n_aided, 0.95);
        const double hmax = n_aided ? tmp[n_aided - 1] : NAN;
        const double kk = 3.0 * (double)n_nees, a = 1.0 - 2.0 / (9.0 * kk),
                     b = sqrt(2.0 / (9.0 * kk));
        const double lo = n_nees ? kk * pow(a - Z99 * b, 3) / (double)n_nees : NAN;
        const double hi = n_nees ? kk * pow(a + Z99 * b, 3) / (double)n_nees : NAN;
        const double mean = n_nees ? nees_sum / (double)n_nees : NAN;
        const double beyond = n_nees ? (double)n_beyond / (double)n_nees : NAN;
        printf(PROG ": with GNSS (%zu epochs outside the outages, %zu settling within %.1f s after "
               "one): horizontal error median %.3f m, 95%% %.3f m, max %.3f m\n",
               n_aided, n_settle, o.settle, h50, h95, hmax);
        printf(PROG ": with GNSS: position NEES (3 dof) mean %.2f, chi2 99%% band of the mean of "
               "%zu epochs [%.2f, %.2f] (%s; epochs taken as independent); %.1f%% of epochs "
               "beyond chi2(3, 0.99) = %.2f (1%% expected)\n",
               mean, n_nees, lo, hi, mean >= lo && mean <= hi ? "inside" : mean < lo ? "BELOW"
                                                                                       : "ABOVE",
               100.0 * beyond, CHI2_3_99);
        if (o.max_h50 > 0 && !(h50 <= o.max_h50)) {
            printf(PROG ": FAIL: median horizontal error with GNSS %.3f m > %.3f m\n", h50,
                   o.max_h50);
            fail = 1;
        }
        if (o.max_h95 > 0 && !(h95 <= o.max_h95)) {
            printf(PROG ": FAIL: 95%% horizontal error with GNSS %.3f m > %.3f m\n", h95,
                   o.max_h95);
            fail = 1;
        }
        if (o.max_hmax > 0 && !(hmax <= o.max_hmax)) {
            printf(PROG ": FAIL: max horizontal error with GNSS %.3f m > %.3f m\n", hmax,
                   o.max_hmax);
            fail = 1;
        }
        if (o.max_beyond > 0 && !(beyond <= o.max_beyond)) {
            printf(PROG ": FAIL: %.1f%% of epochs beyond chi2(3, 0.99) > %.1f%%\n",
                   100.0 * beyond, 100.0 * o.max_beyond);
            fail = 1;
        }
        if (o.nees_band && !(mean >= lo && mean <= hi)) {
            printf(PROG ": FAIL: mean NEES %.2f outside [%.2f, %.2f]\n", mean, lo, hi);
            fail = 1;
        }
    }
    if (n_out > 0) {
        double lens[DRIVE_OUTAGES_MAX];
        int n_lens = 0, j;
        printf(PROG ": outages (start and length in s after the first fix; error at the last "
               "reference epoch inside)\n");
        printf("  %3s %9s %6s %8s %9s %10s %8s %9s\n", "#", "start_s", "len_s", "dist_m",
               "end_err_m", "%_of_dist", "NEES_end", "max_err_m");
        for (k = 0; k < n_out; k++) {
            printf("  %3d %9.2f %6.1f %8.1f %9.3f %10.3f %8.2f %9.3f%s\n", k, out[k].start,
                   out[k].len, out[k].dist, out[k].err_end, out[k].pct, out[k].nees_end,
                   out[k].err_max,
                   out[k].n_epochs < 2 ? "  (not covered)"
                   : !out[k].scored    ? "  (too short a distance: not in the medians)"
                                       : "");
            for (j = 0; j < n_lens && lens[j] != out[k].len; j++) {
            }
            if (j == n_lens) {
                lens[n_lens++] = out[k].len;
            }
        }
        qsort(lens, (size_t)n_lens, sizeof lens[0], cmp_d);
        printf(PROG ": per outage length: median end error in %% of the distance driven\n");
        for (j = 0; j < n_lens; j++) {
            size_t m = 0;
            double med, lim = o.max_pct;
            int q;
            for (k = 0; k < n_out; k++) {
                if (out[k].len == lens[j] && out[k].scored) {
                    tmp[m++] = out[k].pct;
                }
            }
            med = median(tmp, m);
            printf("  %6.1f s: %zu outages scored, median %.3f %%", lens[j], m, med);
            for (k = 0, m = 0; k < n_out; k++) {
                if (out[k].len == lens[j] && out[k].scored) {
                    tmp[m++] = out[k].err_end;
                }
            }
            printf(", median end error %.3f m\n", median(tmp, m));
            for (q = 0; q < o.n_pct_len; q++) {
                if (fabs(o.pct_len[q][0] - lens[j]) < 1e-6) {
                    lim = o.pct_len[q][1];
                }
            }
            if (lim > 0 && isfinite(med) && med > lim) {
                printf(PROG ": FAIL: %.1f s outages: median end error %.3f %% of distance > "
                       "%.3f %%\n", lens[j], med, lim);
                fail = 1;
            }
        }
    }
    if (o.csv != NULL && write_csv(o.csv, rows, n_rows, out, n_out) != 0) {
        fail = 1;
    }
    if (o.plots != NULL) {
        char *p = malloc(strlen(o.plots) + 32);
        if (p == NULL || (mkdir(o.plots, 0777) != 0 && errno != EEXIST)) {
            fprintf(stderr, PROG ": cannot create %s\n", o.plots);
            fail = 1;
        } else {
            sprintf(p, "%s/drive.csv", o.plots);
            if (write_csv(p, rows, n_rows, out, n_out) != 0) {
                fail = 1;
            } else if (o.plot_script != NULL && o.plot_script[0] != '\0') {
                char *cmd = malloc(strlen(o.plot_script) + 2 * strlen(o.plots) + 64 +
                                   (o.label != NULL ? strlen(o.label) : 0));
                if (cmd != NULL) {
                    sprintf(cmd, "/usr/bin/python3 '%s' '%s' '%s'", o.plot_script, o.plots,
                            o.label != NULL ? o.label : "");
                    if (system(cmd) != 0) {
                        fprintf(stderr, PROG ": %s failed\n", o.plot_script);
                        fail = 1;
                    } else {
                        printf(PROG ": plots in %s\n", o.plots);
                    }
                    free(cmd);
                }
            }
        }
        free(p);
    }
    free(rows);
    free(tmp);
    free(ref);
    log_free(&d);
    return fail;
}
