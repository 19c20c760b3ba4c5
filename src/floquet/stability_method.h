/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stability_method.h — a solution's stability by the method in force (stability_method.c). */
#ifndef FRICREG_HB_STABILITY_METHOD_H
#define FRICREG_HB_STABILITY_METHOD_H

#include "floquet_internal.h"

/* The method that computes the next solution's stability: FRICREG_HB_STABILITY_HILL or
 * FRICREG_HB_STABILITY_MONODROMY (the automatic choice made for the elements set now). */
int fr_hb_stability_in_force(const fricreg_hb *hb);

/* The stability of the solution whose element Jacobians (jq) and coefficients (qjac) are those of
 * the last residual with Jacobians, at omega, into out[2n + 2] as fr_hb_hill, by the method in
 * force. Its errors (messages recorded with fn), and FRICREG_EINVAL where the monodromy was
 * chosen and the elements are not piecewise linear. */
int fr_hb_stability(fricreg_hb *hb, const char *fn, double omega, double *out);

/* The stability's buffers freed (a second call does nothing). */
void fr_hb_stability_free(fricreg_hb *hb);

#endif
