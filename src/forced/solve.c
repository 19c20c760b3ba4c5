/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solve.c — fricreg_hb_solve: one periodic solution at a fixed Omega, Newton (newton.c) from
 * the caller's guess, or without one start.c's default start (the branch in the
 * excitation level from the linear regime, the plain guesses, the branch in Omega from a
 * nearby frequency). Above both. */
#include <string.h>

#include "solve_at.h"
#include "hb/hb_internal.h"
#include "start.h"
#include "hb/monitor.h"
#include "hb/busy.h"

int fricreg_hb_solve(fricreg_hb *hb, double omega, size_t nq, const double q0[], double q[])
{
    if (hb == NULL)
        return FRICREG_ENULL;
    if (q == NULL)
        return fr_fail(hb, FRICREG_ENULL, "solve: q is NULL");
    if (hb->busy)
        return fr_hb_refuse(hb, "solve");
    struct fr_error before = hb->err; /* a success keeps it: a first guess's failure is not
                                         the call's */
    int status = fr_hb_check_start(hb, "solve", "omega", omega, nq, q0);
    if (status != FRICREG_OK)
        return status;
    fr_hb_begin(hb, 0); /* Ω is fixed: the monitor sees the level of the start's branch */
    if (q0 != NULL)
        status = fr_hb_solve_at(hb, "solve", omega, q0, 1);
    else
        status = fr_hb_default_start(hb, "solve", omega);
    if ((status = fr_hb_end(hb, status)) == FRICREG_OK) {
        memcpy(q, hb->qsol, nq * sizeof(double));
        hb->err = before;
    }
    return status;
}
