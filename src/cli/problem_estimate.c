/* SPDX-License-Identifier: GPL-3.0-or-later */
/* problem_estimate.c — the companion runs of hold, belt and disk and their estimate
 * (problem_estimate.h). The problems (src/problems/) have no object to carry companions, so the
 * estimate is made here, around their runs, by the library's one decision
 * (base/companion_estimate.c, compiled into the problems as the RK4 is). */
#include "problem_estimate.h"

#include <math.h>
#include <stdio.h>

#include "base/companion_estimate.h"

#define TOO_LARGE 0.1 /* an estimate above 10% of its quantity: outside the asymptotic range */

/* A free slot of w for a warning of `code`, or NULL when w is full. */
static char *slot(struct cli_warnings *w, int code)
{
    if (w->n >= sizeof w->code / sizeof w->code[0])
        return NULL;
    w->code[w->n] = code;
    return w->message[w->n++];
}

void cli_problem_estimate(cli_problem_level run, const void *problem, int estimator, size_t n,
                          const char *const names[], int sampled, const double q[], double err[],
                          struct cli_warnings *w)
{
    double q2[CLI_ESTIMATE_MAX], q4[CLI_ESTIMATE_MAX];
    int status = run(problem, 1, q2);
    if (status == FRICREG_OK && estimator == FRICREG_ESTIMATE_TWO_COMPANIONS)
        status = run(problem, 2, q4);
    if (status != FRICREG_OK) {
        for (size_t i = 0; i < n; i++)
            err[i] = INFINITY;
        char *m = slot(w, FRICREG_WARN_ERROR_ESTIMATE);
        if (m != NULL)
            snprintf(m, sizeof w->message[0],
                     "no error estimate could be formed (reported as null): a companion run "
                     "failed: %s",
                     fricreg_strerror(status));
        return;
    }
    for (size_t i = 0; i < n; i++) {
        int outside = 0;
        err[i] = fr_companion_estimate(estimator, q[i], q2[i], q4[i], &outside);
        char *m = NULL;
        if (outside && !sampled && (m = slot(w, FRICREG_WARN_NOT_ASYMPTOTIC)) != NULL)
            snprintf(m, sizeof w->message[0],
                     "error estimate not asymptotic: %s %.7g, %.7g, %.7g at eps, eps/2, eps/4 "
                     "shows no order in eps (the run and its companion may agree on a wrong "
                     "value); its estimate is the safe bound %.3g: halve eps and dt",
                     names[i], q[i], q2[i], q4[i], err[i]);
        else if (!outside && err[i] > TOO_LARGE * fabs(q[i]) && q[i] != 0.0 &&
                 (m = slot(w, FRICREG_WARN_ERROR_ESTIMATE)) != NULL)
            snprintf(m, sizeof w->message[0],
                     "the error estimate of %s, %.3g, is above 10%% of it, %.3g: eps or dt is "
                     "too coarse for the estimate, which may then not bound the error; halve "
                     "them",
                     names[i], err[i], q[i]);
    }
}
