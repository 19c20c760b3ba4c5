/* SPDX-License-Identifier: GPL-3.0-or-later */
/* busy.c — the refusal of a setter, a run or a checkpoint called without a structure or from the observer or the
 * warning handler while a run is stepping (structure_internal.h): one message for every
 * call, at the bottom of structure/ with the files that call it above. */
#include "structure_internal.h"

int fr_structure_refuse(fricreg_structure *s, const char *who)
{
    if (s == NULL)
        return FRICREG_ENULL;
    return fr_fail(s, FRICREG_EINVAL,
                   "%s: not allowed during a run (called from the observer or the warning "
                   "handler)",
                   who);
}
