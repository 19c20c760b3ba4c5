/* SPDX-License-Identifier: GPL-3.0-or-later */
/* model.h — what the model's setters (model.c) share with the element setters (elements.c):
 * the check of a caller's dof count and the mark of a model change. */
#ifndef FRICREG_HB_MODEL_H
#define FRICREG_HB_MODEL_H

#include <stddef.h>

#include "hb_internal.h"

/* A model change: the factors, the kept solution, the branch's and the backbone's unknowns no
 * longer hold. */
void fr_hb_invalidate(fricreg_hb *hb);

/* FRICREG_OK, or FRICREG_ESIZE (message recorded, with fn) when ndof is not the driver's. */
int fr_hb_check_ndof(fricreg_hb *hb, const char *fn, size_t ndof);

#endif
