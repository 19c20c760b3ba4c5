/* SPDX-License-Identifier: GPL-3.0-or-later */
/* busy.h — internal: the refusal of a call from the monitor during a solve (busy.c). */
#ifndef FRICREG_HB_BUSY_H
#define FRICREG_HB_BUSY_H

#include "hb_internal.h"

/* FRICREG_EINVAL (message recorded, with fn) for a call from the monitor during a solve. */
int fr_hb_busy(fricreg_hb *hb, const char *fn);

#endif
