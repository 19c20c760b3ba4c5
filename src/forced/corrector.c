/* SPDX-License-Identifier: GPL-3.0-or-later */
/* corrector.c — the corrector of the pseudo-arclength continuation (H. B. Keller, "Numerical
 * solution of bifurcation and nonlinear eigenvalue problems", 1977; Krack & Gross 2019, Ch. 5)
 * on the scaled unknowns y = (q/qs, p/ws): the bordered system [R_q R_p; d^T], its tangent t
 * from [R_q R_p; d^T] t = [0; 1], and Newton's method on (R) bordered by a hyperplane, with a
 * line search. One file for it because three jobs solve on it: the continuation loop
 * (arclength.c), the bifurcations' bisection (bifurcations.c) and the peak search (peak.c). */
#include <float.h>
#include <math.h>
#include <string.h>

#include "base/line_search.h"
#include "base/newton_loop.h"
#include "corrector.h"
#include "hb/dynamic.h"
#include "hb/residual.h"
#include "hb/monitor.h"
#include "hb/newton_matrix.h"

/* The sign of the determinant of the LU factor in A (order ld, pivots piv2): det A = det A^T,
 * U's diagonal's signs times -1 for each interchange (LAPACK's pivots count from 1). */
double fr_hb_det_sign(const fricreg_hb *hb, size_t ld)
{
    (void)ld;
    return fr_hb_newton_det_sign(hb);
}

/* Residual (scaled) at y into R[nq + 1] (the arclength equation last, when yp is given) and
 * the bordered matrix into A: [R_q, R_p ws/qs; row^T], p = Ω (R_Ω from the factors'
 * derivatives) or λ (R_λ = −ql: the load enters (R) linearly). qt holds the unscaled q, and
 * a level branch's λ is the level in force. */
int fr_hb_bordered(fricreg_hb *hb, const char *fn, const struct fr_hb_branch *b, const double *y,
                   const double *row)
{
    size_t nq = hb->nq, ld = nq + 1;
    double omega = fr_hb_branch_omega(b, y[nq] * b->ws);
    if (!(omega > 0.0))
        return fr_fail(hb, FRICREG_EINVAL, "%s: the branch reached Omega = %g <= 0", fn, omega);
    if (b->level)
        hb->level = y[nq] * b->ws;
    int status = fr_hb_factor(hb, fn, omega, !b->level);
    for (size_t j = 0; j < nq; j++)
        hb->qt[j] = y[j] * b->qs;
    if (status == FRICREG_OK)
        status = fr_hb_residual(hb, fn, hb->qt, hb->R, 1);
    if (status != FRICREG_OK)
        return status;
    if (b->level)
        fr_hb_dlevel(hb, hb->rw);
    else
        fr_hb_domega(hb, hb->rw);
    for (size_t j = 0; j < nq; j++) {
        hb->R[j] /= b->qs;
        hb->rw[j] *= b->ws / b->qs;
    }
    fr_hb_newton_matrix(hb, ld, hb->rw, row);
    return FRICREG_OK;
}

/* The unit tangent into t from the bordered matrix in A (its last row the border d, not yet
 * factored): [R_q R_Ω; d^T] t = [0; 1], so d^T t > 0 orients it along d. */
int fr_hb_tangent(fricreg_hb *hb, const char *fn, double *t)
{
    size_t ld = hb->nq + 1;
    memset(t, 0, ld * sizeof(double));
    t[ld - 1] = 1.0;
    int status = fr_hb_newton_solve(hb, fn, t, t);
    if (status != FRICREG_OK)
        return status;
    double s = sqrt(fr_hb_dot(t, t, ld));
    for (size_t j = 0; j < ld; j++)
        t[j] /= s;
    return FRICREG_OK;
}

/* The corrector's iterate qw evaluated: R (the border's equation g last) and the bordered
 * matrix (bordered), the largest |R_j| r against its bound, |R| in norm; converged when both
 * equations are within their tolerances. */
struct corrector_iterate {
    fricreg_hb *hb;
    const char *fn;
    const struct fr_hb_branch *b;
    const double *anchor, *border, *base; /* base: the iterate the direction dy starts from */
    const struct fr_line_search *ls;
    double g, r, bound, norm, prev; /* prev: |R| at base */
    int converged;
};

static int corrector_evaluate(struct corrector_iterate *c)
{
    fricreg_hb *hb = c->hb;
    size_t nq = hb->nq, ld = nq + 1;
    int status = fr_hb_bordered(hb, c->fn, c->b, hb->qw, c->border);
    if (status != FRICREG_OK)
        return status;
    c->g = 0.0;
    c->r = 0.0;
    for (size_t j = 0; j < ld; j++)
        c->g += c->border[j] * (hb->qw[j] - c->anchor[j]);
    hb->R[nq] = c->g;
    for (size_t j = 0; j < nq; j++)
        c->r = fmax(c->r, fabs(hb->R[j]));
    c->bound = hb->tol * fr_hb_scale(hb, hb->qt) / c->b->qs;
    c->norm = sqrt(fr_hb_dot(hb->R, hb->R, ld));
    c->converged = c->r <= c->bound && fabs(c->g) <= hb->tol;
    return FRICREG_OK;
}

/* A trial base + lambda dy, evaluated into qw; accepted when converged or by Armijo on |R|. */
static int corrector_trial(void *user, double lambda, int *accept)
{
    struct corrector_iterate *c = user;
    fricreg_hb *hb = c->hb;
    for (size_t j = 0; j < hb->nq + 1; j++)
        hb->qw[j] = c->base[j] + lambda * hb->dy[j];
    int status = corrector_evaluate(c);
    *accept = status == FRICREG_OK &&
              (c->converged || fr_armijo_decrease(c->ls, c->prev, c->norm, lambda));
    return status;
}

/* Newton's method on (R) bordered by border^T (y − anchor) = 0 from start into qw, with the
 * backtracking line search on |R| (Armijo's condition, FR_HB_HALVINGS halvings, as newton.c;
 * past them the shortest trial: the iteration bound ends it): at a kink of the branch, where
 * the stick/slip or contact pattern changes, the plain iteration may cycle. *its the
 * iterations, b->delta and b->kappa the first step's length and the second's ratio to it. On
 * success A holds the bordered matrix at qw, unfactored (fr_hb_tangent). */
/* The loop's view of the corrector (base/newton_loop.h): the iterate c's, its iterations it,
 * the largest |R_j| of the iterate before (r_prev), and the status of a failed condition
 * estimate (FRICREG_OK: none), which ends the iteration. */
struct corrector_loop {
    struct corrector_iterate *c;
    struct fr_hb_branch *b; /* delta and kappa written */
    struct fr_line_search *ls;
    int it;
    double r_prev;
    int status;
};

/* A stalled iteration: from the second on, one that did not halve the largest |R_j|. */
#define STALL_ITERATIONS 2
#define STALL_RATIO 0.5
/* The residual's noise floor in units of DBL_EPSILON kappa(D_h) scale (fr_hb_condition):
 * where the Jenkins chain of bench/hb_stability_size.c stalls (300 to 2000 dofs, H = 3 and 7,
 * the default tolerance), its largest |R_j| sits at 0.003 to 0.31 of it (median 0.06). */
#define ROUNDING_FLOOR 1.0

/* Converged within the tolerance; or, where Newton stalls, within the solves' rounding: each
 * Ω of the iteration factors D_h anew, and the solves' forward error, up to u kappa(D_h) of
 * Y_h (fr_hb_condition), moves (R) by as much from one Ω to the next, noise that no iteration
 * lowers. A tolerance below it would fail the continuation ("did not converge") on a model
 * whose D_h is ill-conditioned (large or stiff: a 1000-dof chain at the default 1e-10). Only
 * a stall pays for the condition estimate, so a corrector that converges is unchanged. */
static int corrector_converged(void *user)
{
    struct corrector_loop *l = user;
    struct corrector_iterate *c = l->c;
    int stalled = l->it >= STALL_ITERATIONS && c->r > STALL_RATIO * l->r_prev;
    l->r_prev = c->r;
    if (c->converged || !stalled || !(fabs(c->g) <= c->hb->tol))
        return c->converged;
    double kappa = 0.0;
    l->status = fr_hb_condition(c->hb, c->fn, &kappa);
    if (l->status != FRICREG_OK) /* a failed estimate (no memory for a fresh factor) ends it */
        return 1;
    c->converged = c->r <= ROUNDING_FLOOR * DBL_EPSILON * kappa * (c->bound / c->hb->tol);
    return c->converged;
}

static int corrector_progress(void *user, double rinf)
{
    struct corrector_iterate *c = ((struct corrector_loop *)user)->c;
    (void)rinf; /* the monitor's measure: the worse of the two equations against its bound */
    return fr_hb_tick(c->hb, c->fn, fr_hb_parameter(c->hb),
                      fmax(c->r / c->bound, fabs(c->g) / c->hb->tol));
}

/* A corrector whose steps have not fallen tenfold after this many iterations (contracting by
 * more than 0.75 an iteration: at a kink, or a Jacobian that changes faster than the steps),
 * on a branch wanted for its end alone (end_only: the start's), is given up for a shorter
 * step rather than run to max_iter. */
#define SLOW_ITERATIONS 8
#define SLOW_RATIO 0.1

/* Newton's step from qw; its length sets delta (the first) and kappa (the second's ratio). */
static int corrector_direction(void *user)
{
    struct corrector_loop *l = user;
    struct corrector_iterate *c = l->c;
    fricreg_hb *hb = c->hb;
    size_t ld = hb->nq + 1;
    for (size_t j = 0; j < ld; j++)
        hb->dy[j] = -hb->R[j];
    int status = fr_hb_newton_solve(hb, c->fn, hb->dy, hb->dy);
    if (status != FRICREG_OK)
        return status;
    double step = sqrt(fr_hb_dot(hb->dy, hb->dy, ld));
    if (l->it == 0)
        l->b->delta = step;
    else if (l->it == 1 && l->b->delta > 0.0)
        l->b->kappa = step / l->b->delta;
    if (l->b->end_only && l->it >= SLOW_ITERATIONS && step > SLOW_RATIO * l->b->delta)
        return fr_fail(hb, FRICREG_EWORK,
                       "%s: the corrector's steps fell by less than %g in %d iterations", c->fn,
                       1.0 / SLOW_RATIO, l->it);
    l->it++;
    return FRICREG_OK;
}

/* Always on: where no trial decreases |R|, from the shortest (evaluated in qw). */
static int corrector_search(void *user, double *phi, double *rinf, int *accepted)
{
    struct corrector_loop *l = user;
    struct corrector_iterate *c = l->c;
    (void)phi;
    (void)rinf;
    memcpy(fr_hb_vectors(c->hb).yl, c->hb->qw, (c->hb->nq + 1) * sizeof(double));
    c->prev = c->norm;
    int found; /* none: on from the shortest trial, evaluated in qw */
    *accepted = 1;
    return fr_line_search(l->ls, 1.0, corrector_trial, c, &found);
}

int fr_hb_corrector(fricreg_hb *hb, const char *fn, struct fr_hb_branch *b, const double *start,
                    const double *anchor, const double *border, int *its)
{
    size_t ld = hb->nq + 1;
    struct fr_line_search ls = {FR_ARMIJO, FR_HB_HALVINGS, NULL};
    struct corrector_iterate c = {hb, fn, b, anchor, border, fr_hb_vectors(hb).yl, &ls, 0,
                                  0,  0,  0, 0,      0};
    memcpy(hb->qw, start, ld * sizeof(double));
    b->delta = b->kappa = 0.0;
    int status = corrector_evaluate(&c);
    if (status != FRICREG_OK)
        return status;
    struct corrector_loop l = {&c, b, &ls, 0, INFINITY, FRICREG_OK};
    struct fr_newton_loop nl = {1.0,  hb->max_iter,        1,
                                &l,   corrector_direction, corrector_search,
                                NULL, corrector_progress,  corrector_converged};
    double phi = 0.0, rinf = 0.0; /* the loop's measures unused: the iterate's test decides */
    int iters = 0;
    if ((status = fr_newton_loop_run(&nl, &phi, &rinf, &iters)) != FRICREG_OK ||
        (status = l.status) != FRICREG_OK)
        return status;
    if (iters == 0 || !c.converged)
        return fr_fail(hb, FRICREG_EWORK, "%s: the corrector did not converge in %d iterations", fn,
                       iters);
    *its = iters;
    return FRICREG_OK;
}
