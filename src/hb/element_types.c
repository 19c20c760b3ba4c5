/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element_types.c — the driver's elements by fricreg_element.h's types (fricreg_hb.h):
 * fricreg_hb_add_elements, a block of one type beside the elements held, whatever their kinds;
 * fricreg_hb_clear_elements; fricreg_hb_element_count. A type whose kind names one of HB's own
 * AFTs (Jenkins, Iwan, lift-off, 3-D contact) has its parameters read into the layout the
 * per-kind setters fill (element_store.c), so that a model of one type answers as its setter;
 * any other type keeps its parameters and is marched by its eval. */
#include "element_store.h"
#include "elements.h"
#include "joint/element_kind.h"
#include "model.h"
#include "newton_matrix.h"
#include "busy.h"

/* The block of type's elements over J and params (the layouts of fricreg_element.h): by the
 * AFT its kind names, HB's own exact ones or the march of its eval (joint/aft_march.h). */
static void block_of(const fricreg_element_type *type, struct fr_hb_block *blk)
{
    size_t np = fricreg_element_nparams(type);
    static const int kind_of[] = {[FR_ELEMENT_AFT_MARCH] = FR_HB_MARCH,
                                  [FR_ELEMENT_AFT_SLIDERS] = FR_HB_SLIDERS,
                                  [FR_ELEMENT_AFT_LIFTOFF] = FR_HB_LIFTOFF,
                                  [FR_ELEMENT_AFT_CONTACT_3D] = FR_HB_CONTACT_3D};
    int kind = kind_of[type->kind->aft];
    *blk = (struct fr_hb_block){.kind = kind,
                                .type = type,
                                .ns = kind == FR_HB_MARCH ? 0 : type->ns,
                                .ra = (size_t)type->kind->dim,
                                .pstride = np,
                                .nstride = kind == FR_HB_SLIDERS ? 0 : np};
}

/* The block's arrays on J and params. */
static void point_block(struct fr_hb_block *blk, size_t me, const double *J, const double *params)
{
    size_t ns = blk->ns;
    blk->me = me;
    blk->Ja = J;
    blk->k = params;
    blk->phi = params + ns;
    if (blk->kind == FR_HB_LIFTOFF || blk->kind == FR_HB_CONTACT_3D) {
        blk->kn = params + 2 * ns;
        blk->n0 = params + 2 * ns + 1;
    }
}

/* Each element's parameters in range (fricreg_element_explain's message), gap 0 where HB's
 * own AFT runs a normal law (it is n0 + kn g: a gap is not taken, not even as n0 − kn gap,
 * which rounds; a marched law takes its gap as it is). */
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
        if (type->kind->normal && type->kind->aft != FR_ELEMENT_AFT_MARCH && p[np - 1] != 0.0)
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
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, fn);
    if (type == NULL)
        return fr_fail(hb, FRICREG_ENULL, "%s: type is NULL", fn);
    struct fr_hb_block blk;
    block_of(type, &blk);
    if (blk.kind == FR_HB_MARCH && fricreg_element_nstate(type) > 0 &&
        type->kind->slider_tangents == NULL && type->kind->state_tangents == NULL)
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: %s has state but neither slider nor state tangents "
                       "(element_kind.h): the march of harmonic balance chains its Jacobian "
                       "through them",
                       fn, type->kind->name);
    if (me == 0)
        return FRICREG_OK;
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
    int status;
    if ((status = fr_hb_check_entries(hb, fn, me * blk.ra, ndof, J, "J")) != FRICREG_OK ||
        (status = check_params(hb, fn, type, me, params)) != FRICREG_OK)
        return status;
    point_block(&blk, me, J, params);
    if (fr_hb_store_add(hb, &blk, 0) != FRICREG_OK)
        return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for %zu %s elements", fn, me,
                       type->kind->name);
    (void)fr_hb_newton_matrix_room(hb); /* none: the dense LU serves */
    fr_hb_invalidate(hb);
    return FRICREG_OK;
}

int fricreg_hb_clear_elements(fricreg_hb *hb)
{
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, "clear_elements");
    fr_hb_store_clear(hb);
    (void)fr_hb_newton_matrix_room(hb); /* none: the dense LU serves */
    fr_hb_invalidate(hb);
    return FRICREG_OK;
}

size_t fricreg_hb_element_count(const fricreg_hb *hb)
{
    return hb ? hb->count : 0;
}
