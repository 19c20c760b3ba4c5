/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element_values.c — a held element's parameter read and set in place (fricreg_hb.h:
 * fricreg_hb_get_element_param, fricreg_hb_set_element_param), in fricreg_element.h's layout of
 * its type, so that a parameter study or a fit moves one value without adding the elements
 * again. HB's own kinds keep their sliders in sk and their normal laws in nl (element_store.c):
 * a slider's k or phi also moves the element's sums there; a marched element's parameters are
 * its type's, checked by the type's own explain. */
#include <math.h>
#include <string.h>

#include "fricreg_element.h"
#include "hb_internal.h"
#include "busy.h"
#include "model.h"

/* Element e's parameter count in its layout (HB's own kinds: k[ns], phi[ns], with a normal law
 * kn, n0, gap). */
static size_t params_of(const fricreg_hb *hb, size_t e)
{
    if (hb->kind[e] == FR_HB_MARCH)
        return fricreg_element_nparams(hb->etype[e]);
    size_t ns = hb->eso[e + 1] - hb->eso[e];
    return hb->kind[e] == FR_HB_SLIDERS ? 2 * ns : 2 * ns + 3;
}

/* Where parameter j of an element of HB's own kinds is kept (NULL: the gap, which HB's normal
 * law has not). */
static double *slot_of(const fricreg_hb *hb, size_t e, size_t j)
{
    size_t ns = hb->eso[e + 1] - hb->eso[e], me = hb->me;
    if (hb->kind[e] == FR_HB_MARCH)
        return hb->ep + hb->epo[e] + j;
    if (j < 2 * ns)
        return hb->sk + (j < ns ? 0 : hb->nsl) + hb->eso[e] + j % ns;
    if (j == 2 * ns)
        return hb->nl + 3 * me + e; /* kn */
    return j == 2 * ns + 1 ? hb->nl + 2 * me + e : NULL;
}

/* The element's name for a message. */
static const char *name_of(const fricreg_hb *hb, size_t e)
{
    static const char *const names[] = {"", "jenkins/iwan", "jenkins_normal/iwan_normal",
                                        "contact_3d"};
    return hb->kind[e] == FR_HB_MARCH ? fricreg_element_name(hb->etype[e]) : names[hb->kind[e]];
}

/* value as parameter j of element e: a marched type's by its explain, HB's own kinds by the
 * per-kind setters' ranges (stiffness > 0, slip force or mu >= 0, kn >= 0, n0 any, gap 0). */
static int check_value(fricreg_hb *hb, const char *fn, size_t e, size_t j, double value)
{
    size_t ns = hb->eso[e + 1] - hb->eso[e];
    if (hb->kind[e] == FR_HB_MARCH) {
        double *p = hb->ep + hb->epo[e], old = p[j];
        char msg[200];
        p[j] = value; /* checked in place, put back: no copy of an Iwan type's 2 ns values */
        int status = fricreg_element_explain(hb->etype[e], p, NULL, NULL, msg, sizeof msg);
        p[j] = old;
        return status == FRICREG_OK
                   ? FRICREG_OK
                   : fr_fail(hb, status, "%s: value = %g as parameter %zu of element %zu (%s): %s",
                             fn, value, j, e, name_of(hb, e), msg);
    }
    if (slot_of(hb, e, j) == NULL)
        return value == 0.0 ? FRICREG_OK
                            : fr_fail(hb, FRICREG_EINVAL,
                                      "%s: value = %g as element %zu's gap (%s): HB's normal "
                                      "law is n0 + kn g without a gap (the preload is n0)",
                                      fn, value, e, name_of(hb, e));
    int positive = j < ns, nonnegative = j < 2 * ns + 1 && !positive;
    if ((positive && !(value > 0.0)) || (nonnegative && !(value >= 0.0)))
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: value = %g as parameter %zu of element %zu (%s) must be %s", fn, value,
                       j, e, name_of(hb, e), positive ? "> 0" : ">= 0");
    return FRICREG_OK;
}

/* The element's sliders' sums in nl (element_store.c's normal_entry), after one moved. */
static void resum(fricreg_hb *hb, size_t e)
{
    double ksum = 0.0, musum = 0.0;
    for (size_t s = hb->eso[e]; s < hb->eso[e + 1]; s++) {
        ksum += hb->sk[s];
        musum += hb->sk[hb->nsl + s];
    }
    hb->nl[e] = ksum;
    hb->nl[hb->me + e] = musum;
}

/* The index's check over the elements first .. first + count - 1, held. */
static int check_index(fricreg_hb *hb, const char *fn, size_t first, size_t count, size_t index)
{
    for (size_t e = first; e < first + count; e++)
        if (index >= params_of(hb, e))
            return fr_fail(hb, FRICREG_EINVAL,
                           "%s: index = %zu: element %zu (%s) has %zu parameters (from 0)", fn,
                           index, e, name_of(hb, e), params_of(hb, e));
    return FRICREG_OK;
}

int fricreg_hb_set_element_param(fricreg_hb *hb, size_t first, size_t count, size_t index,
                                 double value)
{
    static const char fn[] = "set_element_param";
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, fn);
    if (count == 0 || first >= hb->count || count > hb->count - first)
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: first = %zu, count = %zu: not a range of the %zu elements held", fn,
                       first, count, hb->count);
    int status = check_index(hb, fn, first, count, index);
    if (status != FRICREG_OK)
        return status;
    if (!isfinite(value))
        return fr_fail(hb, FRICREG_ENONFINITE, "%s: value = %g", fn, value);
    for (size_t e = first; e < first + count; e++)
        if ((status = check_value(hb, fn, e, index, value)) != FRICREG_OK)
            return status;
    for (size_t e = first; e < first + count; e++) {
        double *slot = slot_of(hb, e, index);
        if (slot == NULL)
            continue; /* the gap, 0 as it was */
        *slot = value;
        if (hb->kind[e] != FR_HB_MARCH)
            resum(hb, e);
    }
    fr_hb_invalidate(hb);
    return FRICREG_OK;
}

int fricreg_hb_get_element_param(fricreg_hb *hb, size_t e, size_t index, double *value)
{
    static const char fn[] = "get_element_param";
    if (hb == NULL)
        return fr_hb_refuse(hb, fn);
    if (value == NULL)
        return fr_fail(hb, FRICREG_ENULL, "%s: value is NULL", fn);
    if (e >= hb->count)
        return fr_fail(hb, FRICREG_EINVAL, "%s: e = %zu: %zu elements are held", fn, e, hb->count);
    int status = check_index(hb, fn, e, 1, index);
    if (status != FRICREG_OK)
        return status;
    const double *slot = slot_of(hb, e, index);
    *value = slot != NULL ? *slot : 0.0;
    return FRICREG_OK;
}
