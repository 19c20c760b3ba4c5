/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb_levels.h — the HB model's backbone at the measured levels (hb_levels.c's comment). */
#ifndef FRICREG_FIT_HB_LEVELS_H
#define FRICREG_FIT_HB_LEVELS_H

#include "model.h"

/* The backbone at the levels (model.h's eval, the driver's values set): FRICREG_OK, or as
 * model.h's eval. */
int fr_fit_hb_levels(fricreg_fit *fit, int kind, size_t n, const double amp[], double guess[],
                     const struct fr_fit_levels *out, size_t *bad);

#endif
