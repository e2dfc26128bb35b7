/**
 * @file trig.h
 * @brief Internal: sine and cosine of one angle from one argument
 *        reduction (trig.c), the library's only trigonometric functions
 *        besides atan2.
 */
#ifndef SE23_TRIG_H
#define SE23_TRIG_H

#include "se23/types.h"

/**
 * *s = sin x, *c = cos x, both of the same reduced angle, so that
 * s^2 + c^2 = 1 to rounding at every x (two separate calls reduce twice,
 * with independent errors of up to |x| eps beyond the exact range).
 * Within a few ulp of the correctly rounded values for |x| up to
 * SE23_TRIG_EXACT_MAX; beyond it, the sine and cosine of an angle within
 * |x| eps of x. NaN or infinite x gives NaN in both.
 */
void se23_sincos(se23_real_t x, se23_real_t *s, se23_real_t *c);

/** The largest |x| [rad] that se23_sincos reduces without a fmod first. */
#if SE23_CFG_DOUBLE
#define SE23_TRIG_EXACT_MAX SE23_R(1.5e6)
#else
#define SE23_TRIG_EXACT_MAX SE23_R(400.0)
#endif

#endif /* SE23_TRIG_H */
