/* SPDX-License-Identifier: GPL-3.0-or-later */
/* step_newton.c — the safeguarded Newton iterations of one implicit step in the contact space
 * (step_newton.h), for newmark.c and contact_step.c. */
#include <math.h>
#include <string.h>

#include <gsl/gsl_blas.h>

#include "base/line_search.h"
#include "base/newton_loop.h"
#include "step_newton.h"

void fr_step_combine(const struct fr_compliance_pair *a, double lambda,
                     const struct fr_compliance_pair *b, struct fr_compliance_pair *p)
{
    for (size_t i = 0; i < a->weff->size; i++) {
        p->weff->data[i] = a->weff->data[i] + lambda * b->weff->data[i];
        p->w->data[i] = a->w->data[i] + lambda * b->w->data[i];
    }
}

/* A trial fk + lambda df: its products and residual into ft, at_t, Gt; accepted (search: by
 * Armijo on the merit; plain: whenever its residual is evaluated), they become the iterate's. */
struct step_trial {
    struct fr_step_newton *e;
    const struct fr_line_search *ls;
    int search;
    double *phi, *rinf;
};

static int step_trial(void *user, double lambda, int *accept)
{
    struct step_trial *t = user;
    struct fr_step_newton *e = t->e;
    gsl_vector_memcpy(e->ft, e->fk);
    gsl_blas_daxpy(lambda, e->df, e->ft);
    fr_step_combine(e->at_k, lambda, e->at_df, e->at_t);
    double phi_t, rinf_t;
    *accept = e->residual(e->user, e->ft, e->at_t, e->Gt, &phi_t, &rinf_t) == FRICREG_OK &&
              (!t->search || fr_armijo_decrease(t->ls, *t->phi, phi_t, lambda));
    if (*accept) {
        struct fr_compliance_pair accepted = *e->at_t;
        *e->at_t = *e->at_k;
        *e->at_k = accepted;
        gsl_vector_memcpy(e->fk, e->ft);
        gsl_vector_memcpy(e->G, e->Gt);
        *t->phi = phi_t;
        *t->rinf = rinf_t;
    }
    return FRICREG_OK;
}

/* Backtracking on the merit along df from fk, from the first trial (stops) or the full step;
 * on success fk, its products, G and the context's last evaluation are at the accepted
 * point. Returns 0 if no cut decreased the merit (search) or the full step's residual failed. */
static int line_search(struct fr_step_newton *e, int stops, int search, double *phi, double *rinf)
{
    double lambda = 1.0;
    if (stops)
        lambda = fr_newton_first_stop(e->m, e->zdot->data, e->at_df->weff->data, e->coef, e->eps,
                                      e->mun, e->nm->fz, e->stopped);
    struct fr_line_search ls = {FR_ARMIJO, search ? FR_STEP_HALVINGS : 0, e->cuts};
    struct step_trial t = {e, &ls, search, phi, rinf};
    int accepted;
    fr_line_search(&ls, lambda, step_trial, &t, &accepted); /* the trials cannot fail */
    return accepted;
}

/* The loop's view of one contacts' Newton (newton_loop.h). */
struct step_loop {
    struct fr_step_newton *e;
    int stops, search;
};

static int step_direction(void *user)
{
    struct fr_step_newton *e = ((struct step_loop *)user)->e;
    int status = fr_newton_direction(e->nm, e->ctx, e->coef, e->W, e->Weff, e->G->data, e->df->data,
                                     e->at_df->weff->data, e->cc);
    if (status == FRICREG_OK)
        e->w_product(e->user, e->df->data, e->at_df->w->data);
    return status;
}

static int step_search(void *user, double *phi, double *rinf, int *accepted)
{
    struct step_loop *l = user;
    *accepted = line_search(l->e, l->stops, l->search, phi, rinf);
    return FRICREG_OK;
}

static void step_restore(void *user, double *phi, double *rinf)
{
    struct fr_step_newton *e = ((struct step_loop *)user)->e;
    e->residual(e->user, e->fk, e->at_k, e->G, phi, rinf);
}

int fr_step_newton_iterate(struct fr_step_newton *e, double tol, int stops, int search, double *phi,
                           double *rinf, int *iters)
{
    struct step_loop l = {e, stops, search};
    struct fr_newton_loop nl = {tol,         e->max_iter,  0,    &l,  step_direction,
                                step_search, step_restore, NULL, NULL};
    int status = fr_newton_loop_run(&nl, phi, rinf, iters);
    return status == FRICREG_ENOMEM ? status : FRICREG_OK; /* else a singular tangent */
}
