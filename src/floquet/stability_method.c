/* SPDX-License-Identifier: GPL-3.0-or-later */
/* stability_method.c — the stability of periodic solutions (fricreg_hb_set_stability,
 * fricreg_hb_set_stability_method): on or off, and by which method, the exact monodromy of
 * the orbit (monodromy.c) where every element is piecewise linear, of the model condensed onto
 * the elements' dofs (reduction.c) where they touch few, and Hill's method (hill.c) elsewhere,
 * unless chosen; the one entry point of the solves, the points and the bifurcations (the
 * stored points' stability is read in forced/point_stability.c). */
#include <stdlib.h>

#include "monodromy.h"
#include "reduction.h"
#include "stability_method.h"
#include "hb/busy.h"

/* The condensed model pays where the elements touch at most a quarter of the dofs of a model
 * of some size (its order is theirs plus the interior modes in band), up to a size whose dense
 * modes, computed once, take well under a second (O(ndof³)). */
#define CONDENSED_MIN_DOFS 32
#define CONDENSED_AUTO_MAX_DOFS 1024

int fr_hb_stability_in_force(const fricreg_hb *hb)
{
    if (hb->stability_method != FRICREG_HB_STABILITY_AUTO)
        return hb->stability_method;
    if (!fr_hb_monodromy_applies(hb))
        return FRICREG_HB_STABILITY_HILL;
    if (hb->n >= CONDENSED_MIN_DOFS && hb->n <= CONDENSED_AUTO_MAX_DOFS &&
        4 * fr_hb_boundary_dofs(hb) <= hb->n)
        return FRICREG_HB_STABILITY_CONDENSED;
    /* the monodromy is dense in 2n + sliders; past its bound the condensed one, never more
     * (its order at most the monodromy's), up to its own dense bound: Hill's, dense in
     * n (2H + 1), would refuse such a model for its size */
    if (2 * hb->n + hb->nsl <= FRICREG_HB_MAX_MONODROMY)
        return FRICREG_HB_STABILITY_MONODROMY;
    return hb->n <= FR_HB_REDUCTION_MAX_DOFS ? FRICREG_HB_STABILITY_CONDENSED
                                             : FRICREG_HB_STABILITY_HILL;
}

int fr_hb_stability(fricreg_hb *hb, const char *fn, double omega, double *out)
{
    int method = fr_hb_stability_in_force(hb);
    if (method == FRICREG_HB_STABILITY_HILL)
        return fr_hb_hill(hb, fn, omega, out);
    if (!fr_hb_monodromy_applies(hb))
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: stability: the exact monodromy needs piecewise-linear elements (1-D "
                       "Jenkins or Iwan elements, with or without lift-off) all of one kind; these "
                       "are not (a mix, or 3-D contact elements): choose "
                       "FRICREG_HB_STABILITY_HILL or _AUTO",
                       fn);
    return fr_hb_monodromy(hb, fn, omega, method == FRICREG_HB_STABILITY_CONDENSED, out);
}

void fr_hb_stability_free(fricreg_hb *hb)
{
    if (hb->stability == NULL)
        return;
    fr_hb_hill_free(hb);
    fr_hb_monodromy_free(hb);
    fr_hb_reduction_free(hb);
    free(hb->stability->xsol);
    free(hb->stability);
    hb->stability = NULL;
}

int fricreg_hb_set_stability(fricreg_hb *hb, int enable)
{
    static const char fn[] = "set_stability";
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, fn);
    if (enable != 0 && enable != 1)
        return fr_fail(hb, FRICREG_EINVAL, "%s: enable = %d must be 0 or 1", fn, enable);
    if (enable && fr_hb_stability_in_force(hb) == FRICREG_HB_STABILITY_HILL &&
        hb->n * hb->nc > FRICREG_HB_MAX_HILL)
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: ndof (2H + 1) = %zu, Hill's method is limited to %d coefficients%s", fn,
                       hb->n * hb->nc, FRICREG_HB_MAX_HILL,
                       fr_hb_monodromy_applies(hb)
                           ? " (these elements have the exact monodromy, of any order: "
                             "fricreg_hb_set_stability_method FRICREG_HB_STABILITY_MONODROMY "
                             "first)"
                           : "");
    if (enable == fr_hb_stability_on(hb))
        return FRICREG_OK;
    if (enable) {
        /* the last solution's and a trial point's, and the workspace of the method in force:
         * the solves then allocate nothing unless the elements change the method (the
         * condensed method's, whose order depends on Ω, is made and grown by the solves) */
        size_t xw = 4 + 4 * hb->n;
        struct fr_hb_stability *st = calloc(1, sizeof *st);
        double *x = st != NULL ? malloc(2 * xw * sizeof(double)) : NULL;
        if (x == NULL) {
            free(st);
            return fr_fail(hb, FRICREG_ENOMEM, "%s: no memory for the stability of %zu dofs", fn,
                           hb->n);
        }
        *st = (struct fr_hb_stability){.xsol = x, .trial = x + xw};
        hb->stability = st;
        hb->release[FR_HB_PART_STABILITY] = fr_hb_stability_free;
        int method = fr_hb_stability_in_force(hb), status = FRICREG_OK;
        if (method == FRICREG_HB_STABILITY_HILL)
            status = fr_hb_hill_reserve(hb, fn);
        else if (method == FRICREG_HB_STABILITY_MONODROMY)
            status = fr_hb_monodromy_reserve(hb, fn);
        if (status != FRICREG_OK) {
            fr_hb_stability_free(hb);
            return status;
        }
    } else {
        fr_hb_stability_free(hb);
    }
    /* the stored points' and the last solution's extras have no stability (or another width):
     * the points are dropped (their store counts the serial, forced/) */
    hb->have_solution = 0;
    hb->extras_serial++;
    return FRICREG_OK;
}

int fricreg_hb_set_stability_method(fricreg_hb *hb, int method)
{
    static const char fn[] = "set_stability_method";
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, fn);
    if (method != FRICREG_HB_STABILITY_AUTO && method != FRICREG_HB_STABILITY_HILL &&
        method != FRICREG_HB_STABILITY_MONODROMY && method != FRICREG_HB_STABILITY_CONDENSED)
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: method = %d is none of FRICREG_HB_STABILITY_AUTO (0), _HILL (1), "
                       "_MONODROMY (2), _CONDENSED (3)",
                       fn, method);
    hb->stability_method = method;
    return FRICREG_OK;
}

int fricreg_hb_get_stability_method(fricreg_hb *hb, int *method)
{
    if (hb == NULL)
        return FRICREG_ENULL;
    if (method == NULL)
        return fr_fail(hb, FRICREG_ENULL, "get_stability_method: method is NULL");
    *method = fr_hb_stability_in_force(hb);
    return FRICREG_OK;
}
