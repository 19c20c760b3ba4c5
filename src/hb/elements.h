/* SPDX-License-Identifier: GPL-3.0-or-later */
/* elements.h — the check of J's rows (elements.c) that fricreg_hb_add_elements
 * (element_types.c) shares with the per-kind setters. */
#ifndef FRICREG_HB_ELEMENTS_H
#define FRICREG_HB_ELEMENTS_H

#include <stddef.h>

#include "hb_internal.h"

/* J's rows[ndof]: every entry finite (FRICREG_ENONFINITE), no row zero (FRICREG_EINVAL), the
 * messages naming fn and the matrix name. */
int fr_hb_check_entries(fricreg_hb *hb, const char *fn, size_t rows, size_t ndof, const double *J,
                        const char *name);

#endif
