/* SPDX-License-Identifier: GPL-3.0-or-later */
/* step_newton.h — internal: the safeguarded Newton iterations of one implicit step in the
 * contact space, shared by fricreg_structure's Newmark/HHT steps (newmark.c) and the public
 * fricreg_ctx_solve_step (contact_step.c).
 *
 * With the step's contact velocities and free accelerations affine in the forces f
 * (newton_matrix.h), Newton solves G(f) = f - F(zdot(f), a_free(f)) = 0, by the structure's
 * one Newton iteration (newton_loop.h). Each iteration: the
 * direction df = -T^-1 G (fr_newton_direction), then a backtracking line search along it,
 * from the first trial (a slipping contact stopped at zdot = 0, fr_newton_first_stop) or the
 * full step, halved at most FR_STEP_HALVINGS times until the caller's merit phi decreases by Armijo's
 * 1e-4; plain (no search): the full step, whatever it gives. The caller supplies the product
 * W x (fr_newton_direction gives W_eff df) and the residual (G, its merit phi and its largest entry rinf), which is
 * where the two callers differ: the structure measures R = w J^T G on its degrees of freedom,
 * fricreg_ctx_solve_step sqrt(G^T W G). */
#ifndef FRICREG_STEP_NEWTON_H
#define FRICREG_STEP_NEWTON_H

#include <stddef.h>
#include <stdint.h>

#include <cholmod.h>
#include <gsl/gsl_vector.h>

#include "fricreg.h"
#include "newton_matrix.h"

/* The halvings of one Newton direction in the structure's steps, contacts and elements alike
 * (base/line_search.h). */
#define FR_STEP_HALVINGS 30

/* W_eff f and W f, [m] each, at one set of contact forces f. */
struct fr_compliance_pair {
    gsl_vector *weff, *w;
};

struct fr_step_newton {
    size_t m;
    double coef;       /* c: zdot(f) = z0 + c W_eff f */
    double eps;        /* the law's eps, for the stops */
    const double *mun; /* [m] the bounds */
    int max_iter;      /* the step's Newton iterations */
    fricreg_ctx *ctx;
    struct fr_newton_matrix *nm;
    const cholmod_sparse *W, *Weff; /* upper triangles, sorted */
    cholmod_common *cc;
    /* The caller's storage: the iterate fk (its products at_k, its residual G), the trial ft
     * (at_t, Gt), the direction df (at_df); accepted trials swap at_k and at_t. */
    gsl_vector *fk, *ft, *df, *G, *Gt;
    struct fr_compliance_pair *at_k, *at_t, *at_df;
    const gsl_vector *zdot; /* the velocities of the last residual */
    unsigned char *stopped; /* [m] the contacts stopped this step */
    int64_t *cuts;          /* counts the line search's halvings (NULL: not counted) */
    void *user;
    void (*w_product)(void *user, const double x[],
                      double w_x[]); /* W x (W_eff x: the direction's) */
    int (*residual)(void *user, const gsl_vector *f, const struct fr_compliance_pair *p,
                    gsl_vector *G, double *phi, double *rinf);
};

/* p = a + lambda b, O(m). */
void fr_step_combine(const struct fr_compliance_pair *a, double lambda,
                     const struct fr_compliance_pair *b, struct fr_compliance_pair *p);

/* Newton iterations from fk (its residual evaluated: G, *phi, *rinf) until rinf <= tol (at
 * least one iteration unless rinf is exactly 0: a guess accepted within the tolerance would
 * leave the step in error by up to tol), *iters (counted on) reaches max_iter, the tangent is
 * singular or the line search stalls (then back to fk, re-evaluated). stops: the first trial
 * stops slipping contacts; search: 0 for plain Newton. FRICREG_OK, or FRICREG_ENOMEM when the
 * dense Newton matrix could not be allocated. */
int fr_step_newton_iterate(struct fr_step_newton *e, double tol, int stops, int search, double *phi,
                           double *rinf, int *iters);

#endif
