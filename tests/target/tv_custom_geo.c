/*
 * Hand-written adapters for the geodetic.h rows of tv_list.h (see tv_custom.c
 * for the contract). An integer travels as two reals hi = floor(x / 2^20),
 * lo = x - 2^20 hi (both exact in float); se23_geo_t as lat, lon, h (6
 * reals). The routines of a frame take its origin: the loader builds the
 * frame with se23_geo_origin (its own vectors check it) and the call
 * returns that status if it failed. An integer output still holding its
 * marker (never written) is reported as two TV_SENTINEL reals.
 */
#include <stdint.h>

#include "tv.h"

#define GEO_SPLIT INT64_C(1048576) /* 2^20 */
#define GEO_MARK64 INT64_MIN
#define GEO_MARK32 INT32_MIN

static int64_t take_int(const se23_real_t **in)
{
    const int64_t hi = (int64_t)(*in)[0];
    const int64_t lo = (int64_t)(*in)[1];
    *in += 2;
    return hi * GEO_SPLIT + lo;
}
static void take_geo(const se23_real_t **in, se23_geo_t *g)
{
    g->lat_e9 = take_int(in);
    g->lon_e9 = take_int(in);
    g->h_mm = (int32_t)take_int(in);
}
static void give_int(se23_real_t **out, int64_t x, int marked)
{
    if (marked != 0) {
        (*out)[0] = TV_SENTINEL;
        (*out)[1] = TV_SENTINEL;
    } else {
        int64_t hi = x / GEO_SPLIT;
        if (hi * GEO_SPLIT > x) {
            --hi; /* floor */
        }
        (*out)[0] = (se23_real_t)hi;
        (*out)[1] = (se23_real_t)(x - hi * GEO_SPLIT);
    }
    *out += 2;
}
static void give_geo(se23_real_t **out, const se23_geo_t *g)
{
    give_int(out, g->lat_e9, g->lat_e9 == GEO_MARK64);
    give_int(out, g->lon_e9, g->lon_e9 == GEO_MARK64);
    give_int(out, (int64_t)g->h_mm, g->h_mm == GEO_MARK32);
}
static void mark_geo(se23_geo_t *g)
{
    g->lat_e9 = GEO_MARK64;
    g->lon_e9 = GEO_MARK64;
    g->h_mm = GEO_MARK32;
}

static struct {
    se23_geo_t origin, fix, out_fix;
    se23_geo_frame_t frame;
    se23_status_t frame_st;
    se23_vec3_t p, out;
} q;

/* The frame at the origin of the next reals of the row. */
static void load_frame(const se23_real_t **in)
{
    take_geo(in, &q.origin);
    q.frame_st = se23_geo_origin(&q.origin, &q.frame);
}

void tv_load_se23_geo_origin(const se23_real_t *in)
{
    take_geo(&in, &q.origin);
    mark_geo(&q.frame.origin);
    tv_fill_sentinel(&q.frame.sin_hi, 9 * sizeof(se23_real_t)); /* sin_hi .. east_rad */
}
int tv_call_se23_geo_origin(void) { return (int)se23_geo_origin(&q.origin, &q.frame); }
/* origin, sin_hi, sin_lo, cos_hi, cos_lo, w0, dn0, h0, north_rad, east_rad */
void tv_store_se23_geo_origin(se23_real_t *out)
{
    const se23_geo_frame_t *f = &q.frame;
    give_geo(&out, &f->origin);
    out[0] = f->sin_hi;
    out[1] = f->sin_lo;
    out[2] = f->cos_hi;
    out[3] = f->cos_lo;
    out[4] = f->w0;
    out[5] = f->dn0;
    out[6] = f->h0;
    out[7] = f->north_rad;
    out[8] = f->east_rad;
}

/* origin, fix. */
void tv_load_se23_geo_to_ned(const se23_real_t *in)
{
    load_frame(&in);
    take_geo(&in, &q.fix);
    tv_fill_sentinel(&q.out, sizeof q.out);
}
int tv_call_se23_geo_to_ned(void)
{
    return q.frame_st != SE23_OK ? (int)q.frame_st : (int)se23_geo_to_ned(&q.frame, &q.fix, &q.out);
}
void tv_store_se23_geo_to_ned(se23_real_t *out)
{
    out[0] = q.out.v[0];
    out[1] = q.out.v[1];
    out[2] = q.out.v[2];
}

/* origin, p_n. */
void tv_load_se23_geo_from_ned(const se23_real_t *in)
{
    load_frame(&in);
    q.p.v[0] = in[0];
    q.p.v[1] = in[1];
    q.p.v[2] = in[2];
    mark_geo(&q.out_fix);
}
int tv_call_se23_geo_from_ned(void)
{
    return q.frame_st != SE23_OK ? (int)q.frame_st
                                 : (int)se23_geo_from_ned(&q.frame, &q.p, &q.out_fix);
}
void tv_store_se23_geo_from_ned(se23_real_t *out) { give_geo(&out, &q.out_fix); }

/* origin, p_n. */
void tv_load_se23_geo_down_at(const se23_real_t *in)
{
    tv_load_se23_geo_from_ned(in);
    tv_fill_sentinel(&q.out, sizeof q.out);
}
int tv_call_se23_geo_down_at(void)
{
    return q.frame_st != SE23_OK ? (int)q.frame_st : (int)se23_geo_down_at(&q.frame, &q.p, &q.out);
}
void tv_store_se23_geo_down_at(se23_real_t *out) { tv_store_se23_geo_to_ned(out); }
