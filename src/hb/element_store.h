/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element_store.h — the driver's elements (element_store.c), of any kinds together: each
 * element's kind, rows, Jacobian block and sliders (hb_internal.h's tables), installed a block
 * of one kind at a time, all or none; the per-kind setters (elements.c), add_elements
 * (element_types.c) and the clone (hb.c) all go through it. */
#ifndef FRICREG_HB_ELEMENT_STORE_H
#define FRICREG_HB_ELEMENT_STORE_H

#include <stddef.h>

#include "hb_internal.h"

/* me elements of one kind, their arrays the caller's. Element i's rows (kind of them): the
 * first ra from Ja, ra rows an element (row-major, ndof columns), the rest (at most one) row i
 * of Jb; its ns sliders' stiffnesses k[i pstride + s] and slip forces (with a normal law:
 * friction coefficients) phi[i pstride + s]; with a normal law n0[i nstride], kn[i nstride]. */
struct fr_hb_block {
    int kind; /* enum fr_hb_kind */
    /* FR_HB_MARCH: the elements' type (ra its dim rows, no sliders: ns 0), element i's
     * parameters at k + i pstride */
    const fricreg_element_type *type;
    size_t me, ns, ra;
    const double *Ja, *Jb;
    const double *k, *phi;
    size_t pstride;
    const double *n0, *kn;
    size_t nstride;
};

/* The block installed after the elements held (replace: in place of them all), the views set
 * for the rows, and have_elements once the driver's me are there. FRICREG_OK, or
 * FRICREG_ENOMEM with hb unchanged. The caller has checked the block and invalidates. */
int fr_hb_store_add(fricreg_hb *hb, const struct fr_hb_block *blk, int replace);

/* No elements held (the buffers kept). */
void fr_hb_store_clear(fricreg_hb *hb);

/* dst, fresh from fricreg_hb_create with src's n and me (any harmonics), holds src's elements.
 * FRICREG_OK or FRICREG_ENOMEM. */
int fr_hb_store_copy(fricreg_hb *dst, const fricreg_hb *src);

/* The samples of the 3-D contact element's AFT at H harmonics: 64 (2H + 1) rounded up to a
 * power of two, and half as many for the extrapolation (residual.c). */
size_t fr_hb_contact_samples(int harmonics);

/* hb->aft replaced by one with fr_hb_contact_samples(hb->H) samples, and aft_half, half
 * allocated, unless they are there. FRICREG_OK, or FRICREG_ENOMEM with hb unchanged. */
int fr_hb_sampled_aft(fricreg_hb *hb);

#endif
