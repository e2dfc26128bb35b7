/* Shared helpers of the se23 LCM harness; see harness.h. */
#define _POSIX_C_SOURCE 200809L
#include "harness.h"

#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#define DEG (3.14159265358979323846 / 180.0)
#define G0 9.80665
#define PER_SQRT_HOUR (1.0 / 60.0) /* x/sqrt(h) = x/60 per sqrt(s) */

/*
 * Typical figures (1 sigma). Gyro ARW deg/sqrt(h) * DEG/60 gives
 * rad/s/sqrt(Hz); accel VRW m/s/sqrt(h) / 60 gives m/s^2/sqrt(Hz).
 */
static const harness_imu_profile_t profiles[HARNESS_IMU_COUNT] = {
    {"perfect", 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 2000.0 * DEG, 16.0 * G0},
    /* consumer/UAV MEMS: ARW 0.3 deg/sqrt(h), VRW 0.1 m/s/sqrt(h),
     * turn-on bias 0.05 deg/s and 5 mg, bias instability as random walk. */
    {"mems", 0.3 * DEG * PER_SQRT_HOUR, 0.1 * PER_SQRT_HOUR, 0.05 * DEG, 5e-3 * G0,
     2e-5, 2e-4, 2000.0 * DEG, 16.0 * G0},
    /* tactical grade: ARW 0.1 deg/sqrt(h), bias 1 deg/h, 1 mg */
    {"tactical", 0.1 * DEG * PER_SQRT_HOUR, 0.05 * PER_SQRT_HOUR, 1.0 * DEG / 3600.0, 1e-3 * G0,
     1e-7, 1e-5, 1000.0 * DEG, 20.0 * G0},
    /* navigation grade: ARW 0.002 deg/sqrt(h), bias 0.01 deg/h, 50 ug */
    {"navigation", 0.002 * DEG * PER_SQRT_HOUR, 0.01 * PER_SQRT_HOUR, 0.01 * DEG / 3600.0,
     50e-6 * G0, 1e-10, 1e-7, 400.0 * DEG, 20.0 * G0},
};

const harness_imu_profile_t *harness_imu_profile(int index)
{
    if (index < 0 || index >= HARNESS_IMU_COUNT) {
        return NULL;
    }
    return &profiles[index];
}

int harness_imu_profile_find(const char *name)
{
    int i;
    for (i = 0; i < HARNESS_IMU_COUNT; i++) {
        if (strcmp(name, profiles[i].name) == 0) {
            return i;
        }
    }
    return -1;
}

int harness_parse_double(const char *s, double *out)
{
    char *end = NULL;
    double x;
    errno = 0;
    x = strtod(s, &end);
    if (errno != 0 || end == s || *end != '\0' || !isfinite(x)) {
        return -1;
    }
    *out = x;
    return 0;
}

int harness_parse_i64(const char *s, int64_t *out)
{
    char *end = NULL;
    long long x;
    errno = 0;
    x = strtoll(s, &end, 10);
    if (errno != 0 || end == s || *end != '\0') {
        return -1;
    }
    *out = (int64_t)x;
    return 0;
}

int harness_parse_vec3(const char *s, double out[3])
{
    char buf[128];
    char *parts[3];
    char *cur;
    double tmp[3];
    int i;
    if (strlen(s) >= sizeof buf) {
        return -1;
    }
    strcpy(buf, s);
    cur = buf;
    for (i = 0; i < 3; i++) {
        char *comma = strchr(cur, ',');
        parts[i] = cur;
        if (i < 2) {
            if (comma == NULL) {
                return -1;
            }
            *comma = '\0';
            cur = comma + 1;
        } else if (comma != NULL) {
            return -1;
        }
    }
    for (i = 0; i < 3; i++) {
        if (harness_parse_double(parts[i], &tmp[i]) != 0) {
            return -1;
        }
    }
    memcpy(out, tmp, sizeof tmp);
    return 0;
}

int harness_on_off(const char *value)
{
    if (strcmp(value, "on") == 0) {
        return 1;
    }
    return strcmp(value, "off") == 0 ? 0 : -1;
}

static int in_range(double x, const harness_opt_t *o)
{
    return x >= o->lo && x <= o->hi;
}

/* Stores value into the option's destination; returns 0 if it is valid. */
static int set_value(const harness_opt_t *o, const char *value)
{
    double x, v3[3];
    int64_t k;
    int idx;
    switch (o->kind) {
    case HOPT_DOUBLE:
        if (harness_parse_double(value, &x) != 0 || !in_range(x, o)) {
            return -1;
        }
        *(double *)o->dst = x;
        return 0;
    case HOPT_I64:
        if (harness_parse_i64(value, &k) != 0) {
            return -1;
        }
        *(int64_t *)o->dst = k;
        return 0;
    case HOPT_STR:
        *(const char **)o->dst = value;
        return 0;
    case HOPT_VEC3:
        if (harness_parse_vec3(value, v3) != 0 || !in_range(v3[0], o) || !in_range(v3[1], o) ||
            !in_range(v3[2], o)) {
            return -1;
        }
        memcpy(o->dst, v3, sizeof v3);
        return 0;
    case HOPT_CHOICE:
        idx = o->find(value);
        if (idx < 0) {
            return -1;
        }
        *(int *)o->dst = idx;
        return 0;
    case HOPT_FLAG:
    default:
        return -1;
    }
}

int harness_parse_opts(const char *prog, int argc, char **argv, const harness_opt_t *opt, int n,
                       void (*usage)(FILE *), const char **pos, int *n_pos)
{
    int i, j;
    if (n_pos != NULL) {
        *n_pos = 0;
    }
    for (i = 1; i < argc; i++) {
        const char *a = argv[i];
        const harness_opt_t *o = NULL;
        if (strcmp(a, "--help") == 0 || strcmp(a, "-h") == 0) {
            usage(stdout);
            exit(0);
        }
        if (a[0] != '-' && pos != NULL) {
            pos[(*n_pos)++] = a;
            continue;
        }
        for (j = 0; j < n && o == NULL; j++) {
            if (strcmp(a, opt[j].name) == 0) {
                o = &opt[j];
            }
        }
        if (o == NULL) {
            fprintf(stderr, "%s: unknown option or argument %s\n", prog, a);
            return -1;
        }
        if (o->kind == HOPT_FLAG) {
            *(int *)o->dst = (int)o->lo;
            continue;
        }
        if (i + 1 >= argc) {
            fprintf(stderr, "%s: %s needs a value\n", prog, a);
            return -1;
        }
        if (set_value(o, argv[++i]) != 0) {
            fprintf(stderr, "%s: bad value for %s: %s\n", prog, a, argv[i]);
            return -1;
        }
    }
    return 0;
}

static volatile sig_atomic_t stop_flag = 0;

static void on_stop_signal(int sig)
{
    (void)sig;
    stop_flag = 1;
}

void harness_catch_stop_signals(void)
{
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_stop_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
}

int harness_stop_requested(void)
{
    return stop_flag != 0;
}

int64_t harness_now_ns(void)
{
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (int64_t)ts.tv_sec * 1000000000LL + (int64_t)ts.tv_nsec;
}

void harness_sleep_until_ns(int64_t t_ns)
{
    struct timespec ts;
    ts.tv_sec = (time_t)(t_ns / 1000000000LL);
    ts.tv_nsec = (long)(t_ns % 1000000000LL);
    while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, NULL) == EINTR) {
    }
}

void harness_progress_init(harness_progress_t *p)
{
    p->tty = isatty(fileno(stderr));
    p->last_ns = harness_now_ns();
}

void harness_progress(harness_progress_t *p, int final, const char *fmt, ...)
{
    const int64_t now = harness_now_ns();
    va_list ap;
    if (!final && now - p->last_ns < (p->tty ? 200000000LL : 10000000000LL)) {
        return;
    }
    p->last_ns = now;
    if (p->tty) {
        fputc('\r', stderr);
    }
    va_start(ap, fmt);
    vfprintf(stderr, fmt, ap);
    va_end(ap);
    if (final || !p->tty) {
        fputc('\n', stderr);
    }
}
