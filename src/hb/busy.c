/* SPDX-License-Identifier: GPL-3.0-or-later */
/* busy.c — the refusal of every call but the getters made without a driver or from the
 * monitor while a solve is under way (fricreg_hb_set_monitor): one message for the setters, the
 * solves and the outputs. At the bottom of hb/, below the sparse model and the monitor alike. */
#include "hb_internal.h"
#include "busy.h"

int fr_hb_refuse(fricreg_hb *hb, const char *fn)
{
    if (hb == NULL)
        return FRICREG_ENULL;
    return fr_fail(hb, FRICREG_EINVAL,
                   "%s: not allowed from the monitor while a solve is under way (only the "
                   "getters are)",
                   fn);
}
