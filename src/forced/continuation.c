/* SPDX-License-Identifier: GPL-3.0-or-later */
/* continuation.c — the frequency response by pseudo-arclength continuation (H. B. Keller,
 * "Numerical solution of bifurcation and nonlinear eigenvalue problems", 1977; Krack & Gross
 * 2019, Ch. 5): the public entry points fricreg_hb_continue (in Ω) and
 * fricreg_hb_continue_level (in the excitation level λ at a fixed Ω), their checks and starts.
 * The continuation's files, bottom up: corrector.c (the bordered system, its tangent, the
 * corrector), points.c (the points store and its getters), bifurcations.c (located between
 * the points), arclength.c (predictor, step control, the loop), start.c (the start without a
 * guess), peak.c (fricreg_hb_peak); this file on top. */
#include <math.h>

#include "solve_at.h"
#include "arclength.h"
#include "start.h"
#include "hb/monitor.h"
#include "hb/busy.h"

int fricreg_hb_continue(fricreg_hb *hb, double omega0, double omega1, size_t nq, const double q0[])
{
    if (hb == NULL)
        return FRICREG_ENULL;
    const char *fn = "continue";
    if (hb->busy)
        return fr_hb_refuse(hb, fn);
    int status = fr_hb_check_start(hb, fn, "omega0", omega0, nq, q0);
    if (status == FRICREG_OK && !isfinite(omega1))
        status = fr_fail(hb, FRICREG_ENONFINITE, "%s: omega1 = %g", fn, omega1);
    if (status == FRICREG_OK && (!(omega1 > 0.0) || omega1 == omega0))
        status = fr_fail(hb, FRICREG_EINVAL,
                         "%s: omega1 = %g must be > 0 and differ from omega0 = %g", fn, omega1,
                         omega0);
    if (status != FRICREG_OK)
        return status;
    struct fr_error before = hb->err; /* a success keeps it: a failed start is not the call's */
    fr_hb_begin(hb, 1);
    if (q0 == NULL) {
        /* from fricreg_hb_solve's solution without a guess; should that fail, the plain
         * guesses at omega0 once more, for their message */
        status = fr_hb_default_start(hb, fn, omega0);
        if (status == FRICREG_ENOMEM)
            return fr_hb_end(hb, status);
        if (status == FRICREG_OK)
            q0 = hb->qsol;
    }
    struct fr_hb_branch b = {.par = "Omega", .keep = 1};
    status = fr_hb_end(hb, fr_hb_arclength(hb, fn, &b, omega0, omega1, q0));
    if (status == FRICREG_OK)
        hb->err = before;
    return status;
}

int fricreg_hb_continue_level(fricreg_hb *hb, double omega, double level0, double level1, size_t nq,
                              const double q0[])
{
    if (hb == NULL)
        return FRICREG_ENULL;
    const char *fn = "continue_level";
    if (hb->busy)
        return fr_hb_refuse(hb, fn);
    int status = fr_hb_check_start(hb, fn, "omega", omega, nq, q0);
    if (status == FRICREG_OK && (!isfinite(level0) || !isfinite(level1)))
        status = fr_fail(hb, FRICREG_ENONFINITE, "%s: level0 = %g, level1 = %g", fn, level0,
                         level1);
    if (status == FRICREG_OK && (!(level0 >= 0.0) || !(level1 >= 0.0) || level0 == level1))
        status = fr_fail(hb, FRICREG_EINVAL,
                         "%s: level0 = %g and level1 = %g must be >= 0 and differ", fn, level0,
                         level1);
    if (status != FRICREG_OK)
        return status;
    struct fr_hb_branch b = {.level = 1, .omega = omega, .par = "level", .keep = 1};
    fr_hb_begin(hb, 0);
    status = fr_hb_arclength(hb, fn, &b, level0, level1, q0);
    hb->level = 1.0; /* the excitation as set, for the calls to come */
    return fr_hb_end(hb, status);
}
