/* SPDX-License-Identifier: GPL-3.0-or-later */
/* line_search.h — the one backtracking line search of the library's Newton iterations:
 * fricreg_structure's steps (the contacts' Newton, the elements', both in one), the public
 * fricreg_ctx_solve_step, harmonic balance and the 2-D contacts' projected Newton.
 *
 * Trials at alpha = alpha0, alpha0/2, alpha0/4, ..., at most max_halvings halvings after the
 * first, each judged by the caller, which moves its own state to the trial point when it
 * accepts it (J. Nocedal & S. J. Wright, Numerical Optimization, 2nd ed., 2006, Alg. 3.1 with
 * the contraction 1/2). The judgement is mostly Armijo's sufficient decrease, in one of the two
 * forms below; what differs between the callers is the merit, the first trial (the full step,
 * or a slipping contact's stop) and how many halvings a direction is worth. */
#ifndef FRICREG_LINE_SEARCH_H
#define FRICREG_LINE_SEARCH_H

#include <stdint.h>

/* Armijo's c1, every caller's: the fraction of the first-order decrease a step must achieve. */
#define FR_ARMIJO 1e-4

struct fr_line_search {
    double armijo;     /* c1 */
    int max_halvings;  /* halvings after the first trial before the search gives up (0: one) */
    int64_t *rejected; /* counts the rejected trials (NULL: not counted) */
};

/* One trial at the step alpha: sets *accept (and on acceptance moves the caller's state to
 * the trial point); FRICREG_OK, or an error that ends the search. */
typedef int (*fr_line_trial)(void *user, double alpha, int *accept);

/* The trials from alpha0 until one is accepted (*accepted = 1) or max_halvings halvings are
 * spent (*accepted = 0). FRICREG_OK, or the error of the trial that returned one. */
int fr_line_search(const struct fr_line_search *ls, double alpha0, fr_line_trial trial, void *user,
                   int *accepted);

/* Armijo's condition for a merit phi whose first-order decrease along the direction is phi
 * itself (|R| along a Newton direction; the callers' squared merits too, with their own c1):
 * phi_t <= (1 - c1 alpha) phi0. */
int fr_armijo_decrease(const struct fr_line_search *ls, double phi0, double phi_t, double alpha);

/* Armijo's condition on a change with its first-order estimate slope (along a projection arc,
 * where the decrease is not the merit's): slope < 0 and change <= c1 slope. */
int fr_armijo_holds(const struct fr_line_search *ls, double change, double slope);

#endif
