/* SPDX-License-Identifier: GPL-3.0-or-later */
/* qsma_levels.h — the QSMA model's backbone at the measured levels (qsma_levels.c's comment). */
#ifndef FRICREG_FIT_QSMA_LEVELS_H
#define FRICREG_FIT_QSMA_LEVELS_H

#include "model.h"

/* The backbone at the levels by quasi-static modal analysis (model.h's eval, the driver's values
 * set): FRICREG_OK, or as model.h's eval. */
int fr_fit_qsma_levels(fricreg_fit *fit, int kind, size_t n, const double amp[], double guess[],
                       const struct fr_fit_levels *out, size_t *bad);

#endif
