/* SPDX-License-Identifier: GPL-3.0-or-later */
/* monitor.c — the solving calls' monitor and work bound (fricreg_hb_set_monitor,
 * fricreg_hb_set_max_iterations): one hook, fr_hb_tick, at each of the three Newton iterations
 * every solve goes through (newton.c's at one frequency, forced/corrector.c's corrector, the
 * nonlinear modes' in nma/nma_solve.c), so that a call of any size can be watched and stopped. */
#include <inttypes.h>

#include "hb_internal.h"
#include "sparse.h"
#include "monitor.h"
#include "busy.h"

int fricreg_hb_set_monitor(fricreg_hb *hb, fricreg_hb_monitor fn, void *user)
{
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, "set_monitor");
    hb->monitor = fn;
    hb->monitor_user = user;
    return FRICREG_OK;
}

int fricreg_hb_set_max_iterations(fricreg_hb *hb, int64_t total)
{
    if (hb == NULL || hb->busy)
        return fr_hb_refuse(hb, "set_max_iterations");
    if (total < 0)
        return fr_fail(hb, FRICREG_EINVAL, "set_max_iterations: total = %" PRId64 " must be >= 0",
                       total);
    hb->max_iterations = total;
    return FRICREG_OK;
}

void fr_hb_begin(fricreg_hb *hb, int report_omega)
{
    hb->busy = 1;
    hb->report_omega = report_omega;
    hb->stopped = 0;
    hb->call_iterations = 0;
}

int fr_hb_end(fricreg_hb *hb, int status)
{
    hb->busy = 0;
    if (hb->sparse) /* the next call factors afresh: its results are its own */
        fr_hb_sparse_release(hb);
    if (!hb->stopped)
        return status;
    hb->err = hb->stop_err; /* a fallback's or a restored record is not the call's */
    return FRICREG_EWORK;
}

static int stop(fricreg_hb *hb)
{
    hb->stopped = 1;
    hb->stop_err = hb->err;
    return FRICREG_EWORK;
}

double fr_hb_parameter(const fricreg_hb *hb)
{
    return hb->report_omega ? hb->factored_omega : hb->level;
}

int fr_hb_tick(fricreg_hb *hb, const char *fn, double parameter, double residual)
{
    if (hb->stopped) /* a path that went on after the stop ends at its first iterate */
        return FRICREG_EWORK;
    hb->call_iterations++;
    if (hb->max_iterations > 0 && hb->call_iterations > hb->max_iterations) {
        fr_fail(hb, FRICREG_EWORK,
                "%s: the bound of %" PRId64
                " Newton iterations per call was reached (fricreg_hb_set_max_iterations)",
                fn, hb->max_iterations);
        return stop(hb);
    }
    if (hb->monitor != NULL &&
        hb->monitor(hb->monitor_user, hb->call_iterations, parameter, residual) != 0) {
        fr_fail(hb, FRICREG_EWORK, "%s: stopped by the monitor after %" PRId64 " Newton iterations",
                fn, hb->call_iterations);
        return stop(hb);
    }
    return FRICREG_OK;
}
