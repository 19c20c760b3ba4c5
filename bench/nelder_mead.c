/* SPDX-License-Identifier: GPL-3.0-or-later */
/* nelder_mead.c — the fit benches' Nelder-Mead baseline (nelder_mead.h). */
#include <math.h>

#include "nelder_mead.h"

long bench_nelder_mead(gsl_multimin_function *F, const double start[], double step, double target,
                       long budget, const long *evals, double *best)
{
    size_t n = F->n;
    gsl_multimin_fminimizer *nm = gsl_multimin_fminimizer_alloc(gsl_multimin_fminimizer_nmsimplex2,
                                                                n);
    gsl_vector *x = gsl_vector_alloc(n), *steps = gsl_vector_alloc(n);
    for (size_t j = 0; j < n; j++)
        gsl_vector_set(x, j, start[j]);
    *best = INFINITY;
    while (*evals<budget && * best> target) {
        gsl_vector_set_all(steps, step);
        gsl_multimin_fminimizer_set(nm, F, x, steps);
        for (int it = 0; it < 20000 && *evals < budget; it++) {
            if (gsl_multimin_fminimizer_iterate(nm) != GSL_SUCCESS)
                break;
            if (nm->fval <= target || gsl_multimin_fminimizer_size(nm) < 1e-12)
                break;
        }
        if (nm->fval < *best)
            *best = nm->fval;
        gsl_vector_memcpy(x, nm->x); /* restart from the best vertex */
    }
    gsl_vector_free(x);
    gsl_vector_free(steps);
    gsl_multimin_fminimizer_free(nm);
    return *evals;
}
