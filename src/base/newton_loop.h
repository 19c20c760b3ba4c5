/* SPDX-License-Identifier: GPL-3.0-or-later */
/* newton_loop.h — internal: the one Newton iteration of the library's implicit problems: a
 * structure's step (the contacts alone, step_newton.c, also for the public
 * fricreg_ctx_solve_step; the elements alone, jenkins.c; both in one, joint_step.c) and
 * harmonic balance's three (hb/newton.c at a frequency, forced/corrector.c on the arclength,
 * nma/nma_solve.c for a nonlinear mode). Each brings its direction (its tangent's solve), its
 * line search (base/line_search.h, on its merit) and its measure of the residual; the loop,
 * its stopping rules and its counting are here. */
#ifndef FRICREG_NEWTON_LOOP_H
#define FRICREG_NEWTON_LOOP_H

struct fr_newton_loop {
    double tol;   /* converged once the residual's measure rinf is within it */
    int max_iter; /* the iterations, *iters counted on over calls */
    /* 0: an iterate whose rinf is exactly 0 is converged without an iteration (a structure's
     * step); 1: at least one iteration whatever the start (harmonic balance, whose iteration
     * counts are reported from it). */
    int at_least_one;
    void *user;
    /* The direction at the iterate: FRICREG_OK, or a status that ends the iteration on the
     * iterate (a singular tangent, an overflowed element, no memory). */
    int (*direction)(void *user);
    /* The line search along the direction: *accepted 1 when a trial was accepted (the iterate,
     * *phi and *rinf then the trial's), 0 when none decreased the merit; FRICREG_OK, or a
     * status that ends the iteration (a failed evaluation, a search its caller calls failed). */
    int (*search)(void *user, double *phi, double *rinf, int *accepted);
    /* After a search that accepted nothing: the iterate's residual again, *phi and *rinf with
     * it (the last evaluation's by-products were the trials'). NULL where a search that
     * accepts nothing returns a failure instead (harmonic balance's). */
    void (*restore)(void *user, double *phi, double *rinf);
    /* NULL, or called at each iterate not converged, before the bound on iterations is
     * applied, with its rinf: a status other than FRICREG_OK ends the iteration with it (a
     * monitor's stop, a deadline). */
    int (*progress)(void *user, double rinf);
    /* NULL, or the caller's own test of convergence after an iteration, in place of
     * rinf <= tol (harmonic balance's: each equation within its own bound). */
    int (*converged)(void *user);
};

/* Newton from the iterate (evaluated: *phi its merit, *rinf its residual's measure) until
 * *rinf <= tol (or converged) after at least one iteration (none from an exact 0 unless at_least_one: a start
 * accepted within the tolerance would leave the step in error by up to tol), *iters reaches
 * max_iter, *phi is not finite, no direction, or the line search stalls (back to the iterate).
 * FRICREG_OK (the caller judges *rinf and *iters), or the status of the direction, the search
 * or the progress that ended it. */
int fr_newton_loop_run(const struct fr_newton_loop *nl, double *phi, double *rinf, int *iters);

#endif
