/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fr_math.h — internal: the constant 2 pi and the whole-cycles count, one home for the files
 * that need them (the exact solver, the systems' periods, the drivers' cycle bookkeeping). */
#ifndef FRICREG_FR_MATH_H
#define FRICREG_FR_MATH_H

#include <math.h>

#define FR_TWO_PI 6.283185307179586 /* 2 pi to the last bit of a double */

/* Whole forcing cycles of `period` within [0, t_end]. The relative 1e-12 lets a t_end that a
 * caller computed as k * period count k cycles despite its rounding. */
static inline double fr_whole_cycles(double t_end, double period)
{
    return floor(t_end / period * (1.0 + 1e-12));
}

#endif
