/* SPDX-License-Identifier: GPL-3.0-or-later */
/* nma_stuck.c — the elements at rest, where a backbone starts (nma_internal.h): each row of J's
 * stiffness with its elements stuck (the lift-off element's kt, or kn on its normal row, when
 * closed by N0 > 0; an Iwan element's sliders of positive slip force, with lift-off when closed) and the amplitude at which
 * it first slips or opens. Used by the dense linear mode (nma_linear.c) and the sparse one
 * (nma_sparse_mode.c) alike. */
#include <math.h>
#include <string.h>

#include "joint/element_kind.h"
#include "nma_internal.h"

/* The element whose rows hold row r of J. */
static size_t element_of_row(const fricreg_hb *hb, size_t r)
{
    size_t e = 0;
    while (hb->erow[e + 1] <= r)
        e++;
    return e;
}

void fr_hb_nma_row(const fricreg_hb *hb, size_t r, double *k, double *limit)
{
    size_t e = element_of_row(hb, r), rows = fr_hb_rows_of(hb, e);
    *k = 0.0;
    *limit = INFINITY;
    double scale = 1.0;               /* a slider's slip force per unit of phi */
    if (hb->kind[e] == FR_HB_MARCH) { /* its elastic stiffness, no slip limit known */
        const fricreg_element_type *type = hb->etype[e];
        double kr[3];
        type->kind->elastic(type, hb->ep + hb->epo[e], kr);
        *k = kr[r - hb->erow[e]];
        return;
    }
    const double *ks, *phi;
    size_t ns = fr_hb_sliders(hb, e, &ks, &phi);
    if (hb->kind[e] != FR_HB_SLIDERS) { /* kt, mu, n0, kn: closed at rest when N0 > 0 */
        size_t me = hb->me;
        double kt = hb->nl[e], mu = hb->nl[me + e], n0 = hb->nl[2 * me + e],
               kn = hb->nl[3 * me + e];
        if (!(n0 > 0.0))
            return;
        if (r - hb->erow[e] == rows - 1) { /* the normal row */
            *k = kn;
            *limit = kn > 0.0 ? n0 / kn : INFINITY;
            return;
        }
        if (hb->kind[e] == FR_HB_CONTACT_3D || ns == 1) { /* one slider: kt, mu */
            *k = mu > 0.0 ? kt : 0.0;
            *limit = mu > 0.0 ? mu * n0 / kt : INFINITY;
            return;
        }
        scale = n0; /* Iwan sliders: phi holds mu */
    }
    for (size_t s = 0; s < ns; s++)
        if (phi[s] > 0.0) { /* a slider of slip force 0 carries nothing */
            *k += ks[s];
            *limit = fmin(*limit, scale * phi[s] / ks[s]);
        }
}

double fr_hb_nma_row_dk(const fricreg_hb *hb, size_t e, size_t j, size_t sr)
{
    if (hb->kind[e] == FR_HB_MARCH) { /* its elastic stiffness, linear in the parameters */
        const fricreg_element_type *type = hb->etype[e];
        size_t np = fricreg_element_nparams(type);
        double unit[2 * FRICREG_ELEMENT_MAX_SLIDERS + 3], kr[3];
        if (j >= np)
            return 0.0;
        memset(unit, 0, np * sizeof *unit);
        unit[j] = 1.0;
        type->kind->elastic(type, unit, kr);
        return kr[sr];
    }
    const double *ks, *phi;
    size_t ns = fr_hb_sliders(hb, e, &ks, &phi), rows = fr_hb_rows_of(hb, e);
    if (hb->kind[e] != FR_HB_SLIDERS) { /* closed at rest when N0 > 0: kt (or k_s), kn */
        if (!(hb->nl[2 * hb->me + e] > 0.0))
            return 0.0;
        if (sr == rows - 1) /* the normal row: kn */
            return j == 2 * ns ? 1.0 : 0.0;
    }
    return j < ns && phi[j] > 0.0 ? 1.0 : 0.0; /* a slider of positive slip force (or mu) */
}
