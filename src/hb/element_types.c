/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element_types.c — the driver's elements by fricreg_element.h's types (fricreg_hb.h):
 * fricreg_hb_add_elements, a block of one type beside the elements held, whatever their kinds;
 * fricreg_hb_clear_elements; fricreg_hb_element_count. The types' parameters are read into
 * the layout the per-kind setters fill (element_store.c), so that one model may mix Jenkins,
 * Iwan, lift-off and 3-D contact elements and a model of one type answers as its setter. */
#include <string.h>

#include "element_store.h"
#include "elements.h"
#include "joint/element_kind.h"
#include "model.h"

/* The block of type's elements over J and params (the layouts of fricreg_element.h), or
 * FRICREG_EINVAL for a type HB does not take. */
static int block_of(fricreg_hb *hb, const char *fn, const fricreg_element_type *type,
                    struct fr_hb_block *blk)
{
    const char *name = type->kind->name;
    size_t ns = type->ns, np = fricreg_element_nparams(type);
    *blk = (struct fr_hb_block){.ns = ns, .ra = (size_t)type->kind->dim, .pstride = np};
    if (strcmp(name, "jenkins") == 0 || strcmp(name, "iwan") == 0) {
        blk->kind = FR_HB_SLIDERS;
        return FRICREG_OK; /* k[ns], then phi[ns] */
    }
    if (strcmp(name, "jenkins_normal") == 0 || strcmp(name, "iwan_normal") == 0)
        blk->kind = FR_HB_LIFTOFF;
    else if (strcmp(name, "contact_3d") == 0)
        blk->kind = FR_HB_CONTACT_3D;
    else
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: HB takes jenkins, iwan, jenkins_normal, iwan_normal and contact_3d "
                       "elements, not %s",
                       fn, name);
    blk->nstride = np; /* k[ns], mu[ns], kn, n0, gap */
    return FRICREG_OK;
}

/* The block's arrays on J and params. */
static void point_block(struct fr_hb_block *blk, size_t me, const double *J, const double *params)
{
    size_t ns = blk->ns;
    blk->me = me;
    blk->Ja = J;
    blk->k = params;
    blk->phi = params + ns;
    if (blk->kind != FR_HB_SLIDERS) {
        blk->kn = params + 2 * ns;
        blk->n0 = params + 2 * ns + 1;
    }
}

/* Each element's parameters in range (fricreg_element_explain's message), gap 0 (HB's normal
 * law is n0 + kn g: a gap is not taken, not even as n0 − kn gap, which rounds). */
static int check_params(fricreg_hb *hb, const char *fn, const fricreg_element_type *type, size_t me,
                        const double *params)
{
    size_t np = fricreg_element_nparams(type);
    const char *name = type->kind->name;
    for (size_t i = 0; i < me; i++) {
        char msg[200];
        const double *p = params + i * np;
        int status = fricreg_element_explain(type, p, NULL, NULL, msg, sizeof msg);
        if (status != FRICREG_OK)
            return fr_fail(hb, status, "%s: element %zu (%s): %s", fn, i, name, msg);
        if (type->kind->normal && p[np - 1] != 0.0)
            return fr_fail(hb, FRICREG_EINVAL,
                           "%s: element %zu (%s): gap = %g: HB's normal law is n0 + kn g without "
                           "a gap (give gap = 0, the preload in n0)",
                           fn, i, name, p[np - 1]);
    }
    return FRICREG_OK;
}

int fricreg_hb_add_elements(fricreg_hb *hb, const fricreg_element_type *type, size_t me,
                            size_t ndof, const double J[], const double params[])
{
    static const char fn[] = "add_elements";
    if (hb == NULL)
        return FRICREG_ENULL;
    if (hb->busy)
        return fr_hb_busy(hb, fn);
    if (type == NULL)
        return fr_fail(hb, FRICREG_ENULL, "%s: type is NULL", fn);
    struct fr_hb_block blk;
    int status = block_of(hb, fn, type, &blk);
    if (status != FRICREG_OK || me == 0)
        return status;
    if (J == NULL || params == NULL)
        return fr_fail(hb, FRICREG_ENULL, "%s: %s is NULL", fn, J == NULL ? "J" : "params");
    if (fr_hb_check_ndof(hb, fn, ndof) != FRICREG_OK)
        return FRICREG_ESIZE;
    if (me > hb->me - hb->count)
        return fr_fail(hb, FRICREG_ESIZE,
                       "%s: %zu elements beside the %zu held: the driver was made for %zu", fn, me,
                       hb->count, hb->me);
    if (blk.ns > FRICREG_HB_MAX_SLIDERS)
        return fr_fail(hb, FRICREG_EINVAL, "%s: %zu sliders an element, at most %d", fn, blk.ns,
                       FRICREG_HB_MAX_SLIDERS);
    if ((status = fr_hb_check_entries(hb, fn, me * blk.ra, ndof, J, "J")) != FRICREG_OK ||
        (status = check_params(hb, fn, type, me, params)) != FRICREG_OK)
        return status;
    point_block(&blk, me, J, params);
    if (fr_hb_store_add(hb, &blk, 0) != FRICREG_OK)
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for %zu %s elements", fn, me,
                       type->kind->name);
    fr_hb_invalidate(hb);
    return FRICREG_OK;
}

int fricreg_hb_clear_elements(fricreg_hb *hb)
{
    if (hb == NULL)
        return FRICREG_ENULL;
    if (hb->busy)
        return fr_hb_busy(hb, "clear_elements");
    fr_hb_store_clear(hb);
    fr_hb_invalidate(hb);
    return FRICREG_OK;
}

size_t fricreg_hb_element_count(const fricreg_hb *hb)
{
    return hb ? hb->count : 0;
}
