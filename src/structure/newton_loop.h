/* SPDX-License-Identifier: GPL-3.0-or-later */
/* newton_loop.h — internal: the one Newton iteration of a structure's implicit step, shared
 * by its three problems: the contacts alone (step_newton.c, for newmark.c and the public
 * fricreg_ctx_solve_step), the elements alone (jenkins.c) and both in one (joint_step.c). Each
 * brings its direction (its tangent's solve) and its line search (base/line_search.h, on its
 * merit from its first trial); the loop, its stopping rules and its counting are here. */
#ifndef FRICREG_NEWTON_LOOP_H
#define FRICREG_NEWTON_LOOP_H

struct fr_newton_loop {
    double tol;   /* converged once the residual's largest entry rinf is within it */
    int max_iter; /* the step's iterations, *iters counted on over calls */
    void *user;
    /* The direction at the iterate: FRICREG_OK, or a status that ends the iteration on the
     * iterate (a singular tangent, an overflowed element, no memory). */
    int (*direction)(void *user);
    /* The line search along the direction: 1 when a trial was accepted (the iterate, *phi and
     * *rinf then the trial's), 0 when none decreased the merit. */
    int (*search)(void *user, double *phi, double *rinf);
    /* After a failed search: the iterate's residual again, *phi and *rinf with it (the last
     * evaluation's by-products were the trials'). */
    void (*restore)(void *user, double *phi, double *rinf);
};

/* Newton from the iterate (evaluated: *phi its merit, *rinf its residual's largest entry)
 * until *rinf <= tol (at least one iteration unless *rinf is exactly 0: a start accepted
 * within the tolerance would leave the step in error by up to tol), *iters reaches max_iter,
 * *phi is not finite, no direction, or the line search stalls (back to the iterate).
 * FRICREG_OK, or the status of the direction that ended it. */
int fr_newton_loop_run(const struct fr_newton_loop *nl, double *phi, double *rinf, int *iters);

#endif
