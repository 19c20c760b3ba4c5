/* SPDX-License-Identifier: GPL-3.0-or-later */
/* solve_at.c — one forced response at one frequency, the step every solve, start and
 * continuation of the forced response takes: the shared checks of its arguments, Newton from a
 * guess (hb/newton.c) and, when on, the solution's stability (floquet/). */
#include <math.h>
#include <string.h>

#include "floquet/stability_method.h"
#include "hb/hb_internal.h"
#include "solve_at.h"
#include "hb/dynamic.h"
#include "hb/newton.h"
#include "hb/newton_matrix.h"

/* The arguments every solve shares: omega (named as the caller's header names it), nq, q0. */
int fr_hb_check_start(fricreg_hb *hb, const char *fn, const char *name, double omega, size_t nq,
                      const double *q0)
{
    if (!isfinite(omega))
        return fr_fail(hb, FRICREG_ENONFINITE, "%s: %s = %g", fn, name, omega);
    if (!(omega > 0.0))
        return fr_fail(hb, FRICREG_EINVAL, "%s: %s = %g must be > 0", fn, name, omega);
    if (!hb->have_elements)
        return fr_fail(hb, FRICREG_EINVAL,
                       "%s: %zu of the driver's %zu elements held (fricreg_hb_set_elements, "
                       "fricreg_hb_add_elements)",
                       fn, hb->count, hb->me);
    if (nq != hb->nq)
        return fr_fail(hb, FRICREG_ESIZE,
                       "%s: nq = %zu, the driver has %zu (%zu rows of J times 2H + 1)", fn, nq,
                       hb->nq, hb->m);
    for (size_t j = 0; q0 != NULL && j < nq; j++)
        if (!isfinite(q0[j]))
            return fr_fail(hb, FRICREG_ENONFINITE, "%s: q0[%zu] = %g", fn, j, q0[j]);
    return FRICREG_OK;
}

/* Solves at omega from q0, or from the stuck guess and then the slipping one; the solution in
 * qw (and R, fq, jq at it), with keep its stability (when on) and kept as the driver's last. */
int fr_hb_solve_at(fricreg_hb *hb, const char *fn, double omega, const double *q0, int keep)
{
    fr_hb_newton_forget(hb);
    int status = fr_hb_factor(hb, fn, omega, 0);
    if (status != FRICREG_OK)
        return status;
    for (int attempt = 0; attempt < (q0 ? 1 : 2); attempt++) {
        if (q0 != NULL)
            memcpy(hb->qw, q0, hb->nq * sizeof(double));
        else if ((status = fr_hb_guess(hb, fn, attempt == 0)) != FRICREG_OK)
            continue;
        if ((status = fr_hb_newton(hb, fn)) == FRICREG_OK || hb->stopped)
            break;
    }
    if (!keep)
        return status;
    /* the stability at the solution (the Jacobians jq of its last residual) */
    if (status == FRICREG_OK && fr_hb_stability_on(hb))
        status = fr_hb_stability(hb, fn, omega, fr_hb_stability_record(hb) + 2);
    if (status != FRICREG_OK)
        return status;
    memcpy(hb->qsol, hb->qw, hb->nq * sizeof(double));
    hb->omega_sol = omega;
    hb->level_sol = hb->level;
    hb->have_solution = 1;
    return FRICREG_OK;
}
