/* SPDX-License-Identifier: GPL-3.0-or-later */
/* elements.h — the element setters' sizes and AFT workspace (elements.c) that a driver's
 * clone (hb.c) needs too. */
#ifndef FRICREG_HB_ELEMENTS_H
#define FRICREG_HB_ELEMENTS_H

#include <stddef.h>

#include "hb_internal.h"

/* The doubles of sk: me elements of ns sliders, with a normal law (normal) room for one
 * slider's forces and Jacobian at nc coefficients, 2 nc + (2 nc)^2, when ns > 1. */
size_t fr_hb_slider_doubles(size_t me, size_t ns, int normal, size_t nc);

/* The samples of the 3-D contact element's AFT at H harmonics: 64 (2H + 1) rounded up to a
 * power of two, and half as many for the extrapolation (residual.c). */
size_t fr_hb_contact_samples(int harmonics);

/* hb->aft replaced by one with fr_hb_contact_samples(hb->H) samples, and aft_half, half
 * allocated, unless they are there. FRICREG_OK, or FRICREG_ENOMEM with hb unchanged. */
int fr_hb_sampled_aft(fricreg_hb *hb);

#endif
