/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stability_method.h — a solution's stability by the method in force (stability_method.c). */
#ifndef FRICREG_HB_STABILITY_METHOD_H
#define FRICREG_HB_STABILITY_METHOD_H

#include "floquet_internal.h"

/* Whether stability is on (fricreg_hb_set_stability). */
static inline int fr_hb_stability_on(const fricreg_hb *hb)
{
    return hb->stability != NULL;
}

/* The numbers kept with each stored point and the last solution (XW): 2 for the forced
 * response's (the tangent's parameter component, the determinant's sign), and with stability
 * 2 + 4 n more (stable, the largest |multiplier|, the 2n exponents). */
static inline size_t fr_hb_extras_width(const fricreg_hb *hb)
{
    return fr_hb_stability_on(hb) ? 4 + 4 * hb->n : 2;
}

/* The last solution's record [XW] and a trial point's (stability on): the stability from x[2]
 * on, written by fr_hb_stability(hb, fn, omega, x + 2). */
static inline double *fr_hb_stability_record(const fricreg_hb *hb)
{
    return hb->stability->xsol;
}

static inline double *fr_hb_stability_trial(const fricreg_hb *hb)
{
    return hb->stability->trial;
}

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
