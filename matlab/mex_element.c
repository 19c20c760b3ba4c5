/* SPDX-License-Identifier: GPL-3.0-or-later */
/* mex_element.c — element types by name (mex_element.h). */
#include <stdio.h>

#include "mex_args.h"
#include "mex_element.h"

const fricreg_element_type *mexe_member(const fricreg_element_type *first, size_t nparams)
{
    const fricreg_element_type *second = fricreg_element_sliders(first, 2);
    size_t one = fricreg_element_nparams(first), per;
    if (second == NULL) /* not a family */
        return nparams == one ? first : NULL;
    per = fricreg_element_nparams(second) - one;
    if (nparams < one || (nparams - one) % per != 0)
        return NULL;
    return fricreg_element_sliders(first, (nparams - one) / per + 1);
}

const fricreg_element_type *mexe_first(const mxArray *a, const char *cmd)
{
    char name[64], list[256] = "";
    const fricreg_element_type *first;
    mexa_string(a, cmd, "name", name, sizeof name);
    first = fricreg_element_lookup(name);
    if (first != NULL)
        return first;
    for (size_t i = 0; i < fricreg_element_count(); i++) {
        mexa_append(list, sizeof list, i ? ", " : "");
        mexa_append(list, sizeof list, fricreg_element_name(fricreg_element_at(i)));
    }
    mexa_error("fricreg:EINVAL", "%s: '%s' is not an element type (one of %s) (FRICREG_EINVAL)",
               cmd, name, list);
    return NULL;
}

void mexe_bad_params(const fricreg_element_type *first, const char *cmd, const char *what,
                     size_t rows, size_t cols)
{
    const fricreg_element_type *second = fricreg_element_sliders(first, 2);
    size_t one = fricreg_element_nparams(first);
    char takes[96];
    if (second == NULL)
        snprintf(takes, sizeof takes, "%lu", (unsigned long)one);
    else /* a family: one slider's count plus the rest per slider */
        snprintf(takes, sizeof takes, "%lu + %lu (ns - 1) for ns = 1..%d sliders",
                 (unsigned long)one, (unsigned long)(fricreg_element_nparams(second) - one),
                 FRICREG_ELEMENT_MAX_SLIDERS);
    mexa_error("fricreg:size", "%s: %s, %s taking nparams = %s; not %dx%d", cmd, what,
               fricreg_element_name(first), takes, (int)rows, (int)cols);
}
