/* SPDX-License-Identifier: GPL-3.0-or-later */
/* count_calls.c — what the patched ccx asks of fricreg, counted from outside (LD_PRELOAD): every
 * fricreg_element_eval passes through here to the library's own, and at exit one line goes to
 * the file $FRICREG_CCX_COUNTS: the calls, those that slid (the slider moved), and those on the
 * stick/slip border (k|u - w| within 1e-9 of a bound > 0, where rounding decides between stick
 * and slip: tests/calculix/README.md). Built by build.sh; a test helper, not part of the library. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "fricreg_element.h"

typedef int eval_fn(const fricreg_element_type *, const double *, const double *, const double *,
                    double *, double *, double *, double *);

static unsigned long calls, slid, border;

static void report(void)
{
    const char *path = getenv("FRICREG_CCX_COUNTS");
    FILE *out = path != NULL ? fopen(path, "w") : NULL;
    if (out == NULL)
        return;
    fprintf(out, "calls %lu slid %lu border %lu\n", calls, slid, border);
    fclose(out);
}

int fricreg_element_eval(const fricreg_element_type *type, const double params[],
                         const double state_in[], const double u[], double f[], double dfdu[],
                         double dfdp[], double state_out[])
{
    static eval_fn *real;
    if (real == NULL) {
        *(void **)&real = dlsym(RTLD_NEXT, "fricreg_element_eval");
        atexit(report);
    }
    double w[3] = {0.0, 0.0, 0.0}, d2 = 0.0;
    int dim = fricreg_element_dim(type);
    for (int a = 0; a < dim && a < 3; a++) {
        w[a] = state_in[a];
        d2 += (u[a] - w[a]) * (u[a] - w[a]);
    }
    int status = real(type, params, state_in, u, f, dfdu, dfdp, state_out);
    calls++;
    if (status == FRICREG_OK && dim == 3 && fricreg_element_nparams(type) == 2) {
        double trial = params[0] * sqrt(d2), bound = params[1];
        slid += state_out[0] != w[0] || state_out[1] != w[1] || state_out[2] != w[2];
        border += bound > 0.0 && fabs(trial - bound) <= 1e-9 * bound;
    }
    return status;
}
