/*
 * se23-drive-synth: a nav log with known errors for testing se23-drive
 * (tools/drive/selftest.sh). Reads the reference (SE23_GNSS_REF) of an
 * import log and its sidecar's outages, and writes SE23_NAV states every
 * 1/--rate s along it (linear between reference epochs, R = I, v from the
 * steps) with the position offset by --bias N,E,D everywhere, plus --drift
 * m/s east times the time since the start of each outage inside it, and
 * P = diag(--sigma^2) (15 states).
 *
 * Expected of se23-drive (lever 0): horizontal error |bias_NE| with GNSS;
 * at an outage's last reference epoch |bias_NE + (0, drift t)|.
 * Exit status: 0 done, 1 unreadable input or write error, 2 usage.
 */
#define _POSIX_C_SOURCE 200809L
#include <lcm/lcm.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "../lcm/harness.h"
#include "../lcm/logfile.h"
#include "drive.h"
#include "se23lcm_gnss_fix.h"
#include "se23lcm_nav_state.h"

#define PROG "se23-drive-synth"

static void usage(FILE *f)
{
    fprintf(f, "usage: se23-drive-synth --out file://NAV?mode=w [--bias N,E,D] [--drift MPS]\n"
               "           [--sigma S] [--rate HZ] [--meta FILE] IMPORT_LOG\n"
               "Nav states along IMPORT_LOG's reference with known errors (file comment).\n");
}

int main(int argc, char **argv)
{
    const char *out = NULL, *meta_p = NULL, *pos[2] = {NULL, NULL};
    double bias[3] = {0, 0, 0}, drift = 0.0, sigma = 0.1, rate = 100.0;
    int n_pos = 0, k;
    const harness_opt_t opts[] = {
        {"--out", HOPT_STR, &out, 0, 0, NULL},
        {"--meta", HOPT_STR, &meta_p, 0, 0, NULL},
        {"--bias", HOPT_VEC3, bias, -1e6, 1e6, NULL},
        {"--drift", HOPT_DOUBLE, &drift, -1e3, 1e3, NULL},
        {"--sigma", HOPT_DOUBLE, &sigma, 1e-6, 1e6, NULL},
        {"--rate", HOPT_DOUBLE, &rate, 1.0, 1e4, NULL},
    };
    const char **pp = calloc((size_t)argc + 1, sizeof *pp);
    se23lcm_gnss_fix *ref = NULL;
    size_t n_ref = 0, cap = 0, i;
    drive_meta_t meta;
    char mbuf[4096];
    logfile_t lf;
    logfile_event_t ev;
    lcm_t *lc;
    int64_t t, step, first_ns, seq = 0;
    if (pp == NULL ||
        harness_parse_opts(PROG, argc, argv, opts, (int)(sizeof opts / sizeof opts[0]), usage, pp,
                           &n_pos) != 0 ||
        n_pos != 1 || out == NULL) {
        usage(stderr);
        return 2;
    }
    pos[0] = pp[0];
    free(pp);
    snprintf(mbuf, sizeof mbuf, "%s.drive", pos[0]);
    if (drive_meta_read(meta_p != NULL ? meta_p : mbuf, &meta) != 0 ||
        logfile_open(&lf, pos[0], PROG) != 0) {
        return 1;
    }
    while (logfile_next(&lf, &ev)) {
        se23lcm_gnss_fix m, *slot;
        if (strcmp(ev.channel, "SE23_GNSS_REF") == 0 &&
            se23lcm_gnss_fix_decode(ev.data, 0, ev.datalen, &m) >= 0 &&
            (n_ref == 0 || m.t_ns > ref[n_ref - 1].t_ns)) {
            slot = drive_push((void **)&ref, &n_ref, &cap, sizeof *slot);
            if (slot == NULL) {
                return 1;
            }
            *slot = m;
        }
    }
    logfile_close(&lf);
    if (n_ref < 2) {
        fprintf(stderr, PROG ": fewer than 2 reference epochs in %s\n", pos[0]);
        return 1;
    }
    lc = lcm_create(out);
    if (lc == NULL) {
        fprintf(stderr, PROG ": cannot open %s\n", out);
        return 1;
    }
    first_ns = llround(meta.first_fix_s * 1e9);
    step = llround(1e9 / rate);
    i = 0;
    for (t = ref[0].t_ns; t <= ref[n_ref - 1].t_ns; t += step) {
        se23lcm_nav_state s;
        double w, t_rel = (double)(t - first_ns) * 1e-9;
        while (i + 2 < n_ref && ref[i + 1].t_ns <= t) {
            i++;
        }
        w = (double)(t - ref[i].t_ns) / (double)(ref[i + 1].t_ns - ref[i].t_ns);
        memset(&s, 0, sizeof s);
        s.t_ns = t;
        s.seq = ++seq;
        s.R_nb[0] = s.R_nb[4] = s.R_nb[8] = 1.0;
        for (k = 0; k < 3; k++) {
            s.p_n[k] = (1.0 - w) * ref[i].p_n[k] + w * ref[i + 1].p_n[k] + bias[k];
            s.v_n[k] = (ref[i + 1].p_n[k] - ref[i].p_n[k]) /
                       ((double)(ref[i + 1].t_ns - ref[i].t_ns) * 1e-9);
        }
        for (k = 0; k < meta.n_outages; k++) {
            const double a = meta.outage[k][0], b = a + meta.outage[k][1];
            if (t_rel >= a && t_rel < b) {
                s.p_n[1] += drift * (t_rel - a);
                s.v_n[1] += drift;
            }
        }
        for (k = 0; k < 15; k++) {
            s.P[16 * k] = sigma * sigma;
        }
        s.status = 0x003; /* initialised, GNSS-aided */
        s.n_imu_used = seq;
        if (se23lcm_nav_state_publish(lc, HARNESS_CH_NAV, &s) != 0) {
            fprintf(stderr, PROG ": cannot write %s\n", out);
            lcm_destroy(lc);
            return 1;
        }
    }
    lcm_destroy(lc);
    free(ref);
    printf(PROG ": %lld nav states\n", (long long)seq);
    return 0;
}
