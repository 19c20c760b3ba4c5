/* SPDX-License-Identifier: GPL-3.0-or-later */
/* changed.c — the one hook every setter calls with what it changed: what was derived from it
 * (the set-up, K_eff, the equilibrium at t) is redone at the next step, and the error
 * estimate's companion either follows the change at the next stepping call
 * (error_estimate.c's fr_estimate_sync) or, where it copied what changed, is made anew. */
#include "structure_internal.h"

void fr_structure_changed(fricreg_structure *s, unsigned what)
{
    if (what & FR_CHANGED_MODEL) {
        s->prepared = 0;
        s->bound_scale = -1.0; /* J may have changed */
    }
    if (what & (FR_CHANGED_MODEL | FR_CHANGED_SCHEME))
        s->step_dt = 0.0; /* K_eff and W_eff are the model's and the scheme's */
    if (what & FR_CHANGED_BOUNDS)
        s->bound_scale = -1.0; /* W is unchanged: only the equilibrium at t is recomputed */
    if (what & (FR_CHANGED_MODEL | FR_CHANGED_BOUNDS | FR_CHANGED_LAW))
        s->ready = 0;
    if (what & FR_CHANGES_RECOPIED)
        s->estimate_state = FR_ESTIMATE_NONE; /* the companion, if any, is stale */
    else
        s->companion_pending |= what;
}
