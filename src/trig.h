/**
 * @file trig.h
 * @brief Internal: sine and cosine in the build's precision with a small,
 *        bounded frame: a Cody-Waite reduction by pi/2 and Taylor
 *        polynomials, no Payne-Hanek table (newlib's reduction holds
 *        416 B of frame on Cortex-M4F, 700 B on M7, for arguments an
 *        inertial filter never produces).
 *
 * Accuracy (tests/unit/test_trig.c, against long double):
 *  - |x| <= SE23_TRIG_REDUCE_MAX (400 rad float, 1.5e6 rad double): the
 *    reduction is exact to a few units of 2^-p of pi/4, so the error is
 *    about one ulp of 1;
 *  - beyond, x is first brought into (-2 pi, 2 pi) by an exact fmod by
 *    the nearest representable 2 pi: the result is the sine of an angle
 *    within |x| eps/2 of x (backward stable), and sin^2 + cos^2 = 1 to
 *    rounding still holds;
 *  - NaN or infinite x gives NaN, as C99 sin does.
 */
#ifndef SE23_TRIG_H
#define SE23_TRIG_H

#include "se23/types.h"

#if SE23_CFG_DOUBLE
#define SE23_TRIG_REDUCE_MAX SE23_R(1.5e6)
#else
#define SE23_TRIG_REDUCE_MAX SE23_R(400.0)
#endif

se23_real_t se23_trig_sin(se23_real_t x);
se23_real_t se23_trig_cos(se23_real_t x);

#endif /* SE23_TRIG_H */
