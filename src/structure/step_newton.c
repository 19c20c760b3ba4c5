/* SPDX-License-Identifier: GPL-3.0-or-later */
/* step_newton.c — the safeguarded Newton iterations of one implicit step in the contact space
 * (step_newton.h), for newmark.c and contact_step.c. */
#include <math.h>
#include <string.h>

#include <gsl/gsl_blas.h>

#include "base/line_search.h"
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

int fr_step_newton_iterate(struct fr_step_newton *e, double tol, int stops, int search, double *phi,
                           double *rinf, int *iters)
{
    int done = 0;
    while (*rinf != 0.0 && (done == 0 || *rinf > tol) && *iters < e->max_iter) {
        if (!isfinite(*phi))
            break;
        int status = fr_newton_direction(e->nm, e->ctx, e->coef, e->W, e->Weff, e->G->data,
                                         e->df->data, e->cc);
        if (status == FRICREG_ENOMEM)
            return status;
        if (status != FRICREG_OK)
            break; /* a singular tangent: the step ends on this iterate, a failure counted */
        ++*iters;
        ++done;
        e->products(e->user, e->df->data, e->at_df);
        if (!line_search(e, stops, search, phi, rinf)) {
            e->residual(e->user, e->fk, e->at_k, e->G, phi, rinf); /* back to fk: the best */
            break;
        }
    }
    return FRICREG_OK;
}
