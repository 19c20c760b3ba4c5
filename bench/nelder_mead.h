/* SPDX-License-Identifier: GPL-3.0-or-later */
/* nelder_mead.h — the derivative-free baseline of the fit benches (fit_modal_iwan.c,
 * fit_hb.c): GSL's Nelder-Mead simplex run until it reaches a target cost. */
#ifndef FRICREG_BENCH_NELDER_MEAD_H
#define FRICREG_BENCH_NELDER_MEAD_H

#include <gsl/gsl_multimin.h>

/* GSL's nmsimplex2 on F from start[F->n] with initial steps `step`, restarted from its best
 * vertex (each restart with the same steps) until its cost is at most target or *evals (the
 * count F's function keeps) reaches budget. Returns *evals; *best is the least cost reached. */
long bench_nelder_mead(gsl_multimin_function *F, const double start[], double step, double target,
                       long budget, const long *evals, double *best);

#endif
