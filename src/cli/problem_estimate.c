/* SPDX-License-Identifier: GPL-3.0-or-later */
/* problem_estimate.c — the companion runs of hold, belt and disk and their estimate
 * (problem_estimate.h). The problems (src/problems/) have no object to carry companions, so the
 * estimate is made here, around their runs, by the library's one decision
 * (base/companion_estimate.c, compiled into the problems as the RK4 is). */
#include "problem_estimate.h"

#include <math.h>
#include <stdio.h>

#include "base/companion_estimate.h"

/* A free slot of w for a warning of `code`, or NULL when w is full. */
static char *slot(struct cli_warnings *w, int code)
{
    if (w->n >= sizeof w->code / sizeof w->code[0])
        return NULL;
    w->code[w->n] = code;
    return w->message[w->n++];
}

void cli_problem_estimate(cli_problem_level run, const void *problem,
                          const struct cli_estimate_options *opt, size_t n,
                          const char *const names[], const double q[], double err[], int kind[],
                          struct cli_warnings *w)
{
    double q2[CLI_ESTIMATE_MAX], q4[CLI_ESTIMATE_MAX];
    int status = run(problem, 1, q2);
    if (status == FRICREG_OK && opt->estimator == FRICREG_ESTIMATE_TWO_COMPANIONS)
        status = run(problem, 2, q4);
    if (status != FRICREG_OK) {
        for (size_t i = 0; i < n; i++)
            err[i] = INFINITY, kind[i] = FRICREG_EST_KIND_BOUND;
        char *m = slot(w, FRICREG_WARN_ERROR_ESTIMATE);
        if (m != NULL)
            snprintf(m, sizeof w->message[0],
                     "no error estimate could be formed (reported as null): a companion run "
                     "failed: %s",
                     fricreg_strerror(status));
        return;
    }
    for (size_t i = 0; i < n; i++) {
        err[i] = fr_companion_estimate(opt->estimator, q[i], q2[i], q4[i], &kind[i]);
        char *m = NULL;
        if (fr_estimate_exceeds(err[i], q[i], opt->answer_rtol, 0.0) && q[i] != 0.0 &&
            (m = slot(w, FRICREG_WARN_ERROR_ESTIMATE)) != NULL)
            snprintf(m, sizeof w->message[0],
                     "the error estimate %.3g of %s %.7g (%s) exceeds twice the answer tolerance "
                     "%.3g of it (the estimate bounds the error at about twice its size): halve "
                     "eps and dt, or raise --answer-rtol",
                     err[i], names[i], q[i], fr_estimate_kind_name(kind[i]), opt->answer_rtol);
    }
}
