/* SPDX-License-Identifier: GPL-3.0-or-later */
/* busy.h — internal: the refusal of a call without a driver or from the monitor during a solve (busy.c). */
#ifndef FRICREG_HB_BUSY_H
#define FRICREG_HB_BUSY_H

#include "hb_internal.h"

/* The status of a refused call: FRICREG_ENULL for hb NULL (nothing recorded), FRICREG_EINVAL
 * (message recorded, with fn) for a call from the monitor during a solve. Every setter starts
 * `if (hb == NULL || hb->busy) return fr_hb_refuse(hb, fn);`. */
int fr_hb_refuse(fricreg_hb *hb, const char *fn);

#endif
