/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb.h — internal: the driver's life cycle beyond the public calls: the clone at other harmonics (hb.c). */
#ifndef FRICREG_HB_HB_H
#define FRICREG_HB_HB_H

#include "hb_internal.h"

/* A new driver at harmonics H (1 <= H <= FRICREG_HB_MAX_HARMONICS) with src's model, elements,
 * excitation, Newton's settings, monitor and bound (hb.c); no solution, stability off.
 * FRICREG_OK or FRICREG_ENOMEM. */
int fr_hb_clone(const fricreg_hb *src, int harmonics, fricreg_hb **out);

#endif
