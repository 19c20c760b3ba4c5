/* SPDX-License-Identifier: GPL-3.0-or-later */
/* forces.c — the forces of a state that every scheme needs (newmark.c, central_difference.c,
 * joint_step.c, structure_ode.c): the net force but friction, the contacts' friction and the
 * acceleration it leaves, the equilibrium at the start of a step, and the norms Newton reads. */
#include <math.h>

#include "base/sparse_ops.h"
#include "structure_internal.h"

double fr_norm_inf(const gsl_vector *x)
{
    double m = 0.0;
    const double *d = x->data; /* the structure's vectors are contiguous */
    for (size_t k = 0; k < x->size; k++) {
        double a = fabs(d[k]);
        if (!(a <= m)) /* NaN propagates */
            m = a;
    }
    return m;
}

int fr_structure_contact_forces(fricreg_structure *s, gsl_vector *f)
{
    int status = fricreg_ctx_eval(s->ctx, s->m, s->zdot->data, s->afree->data, f->data, NULL);
    /* The context's inputs are the structure's own state, from validated data: one that is
     * not finite (or an f_eq beyond range) means the state overflowed, e.g. a finite dt of
     * 1e200 (tests/reliability/test_bad_input.c), which the headers call FRICREG_EDIVERGED. */
    return status == FRICREG_ENONFINITE ? FRICREG_EDIVERGED : status;
}

int fr_structure_motion(fricreg_structure *s, const gsl_vector *w, const gsl_vector *v,
                        gsl_vector *f, gsl_vector *a)
{
    double *y = s->yb->data;
    fr_cfactor_forward(&s->mass, w->data, y, &s->cc);
    fr_cfactor_project(&s->mass, y, s->afree->data, &s->cc); /* J M^-1 w */
    fr_csc_mult_t(s->Jt, v->data, s->zdot->data);
    int status = fr_structure_contact_forces(s, f);
    if (status != FRICREG_OK)
        return status;
    fr_cfactor_lift(&s->mass, 1.0, f->data, y, &s->cc); /* M^-1 (w + J^T f) */
    fr_cfactor_backward(&s->mass, y, a->data, &s->cc);
    return FRICREG_OK;
}

void fr_structure_spread_norms(fricreg_structure *s, double scale, const gsl_vector *G,
                               double *norm2, double *norm_inf)
{
    double *r = s->spread->data;
    const SuiteSparse_long *Jp = s->Jt->p, *Ji = s->Jt->i;
    fr_csc_mult_add(s->Jt, scale, G->data, r);
    struct fr_sumsq sum = {0.0, 0.0};
    double big = 0.0;
    /* Each touched entry once: read and zeroed at its first visit. */
    for (size_t i = 0; i < s->m; i++)
        for (SuiteSparse_long p = Jp[i]; p < Jp[i + 1]; p++) {
            double x = r[Ji[p]];
            r[Ji[p]] = 0.0;
            fr_sumsq_add(&sum, x);
            if (!(fabs(x) <= big)) /* NaN propagates */
                big = fabs(x);
        }
    *norm2 = fr_sumsq_root(&sum);
    *norm_inf = big;
}

/* w = p~ - C v - K u; with Rayleigh's C, p~ - K (u + a1 v) - a0 M v: one pass over K, not
 * two (with a lumped M the second product is a diagonal's). */
void fr_structure_net_force(const fricreg_structure *s, const gsl_vector *ptil, const gsl_vector *u,
                            const gsl_vector *v, gsl_vector *w)
{
    if (!s->rayleigh) {
        fr_sym_mult_pair(ptil->data, s->Cd, -1.0, v->data, s->K, -1.0, u->data, w->data);
        return;
    }
    fr_sym_mult_combined(ptil->data, s->K, -1.0, u->data, -s->a1, v->data, w->data);
    if (s->a0 != 0.0)
        fr_sym_mult(s->M, -s->a0, v->data, 1.0, w->data);
}

int fr_structure_equilibrium(fricreg_structure *s)
{
    fr_structure_effective_load(s, s->t, s->ptil);
    fr_structure_net_force(s, s->ptil, s->u, s->v, s->work);
    int status = fr_elements_equilibrium(s, s->work);
    if (status != FRICREG_OK)
        return status;
    status = fr_structure_motion(s, s->work, s->v, s->f, s->a);
    if (status != FRICREG_OK)
        return fr_fail(s, status, "step: friction at t = %g: %s", s->t, fricreg_ctx_errmsg(s->ctx));
    s->stick_valid = 0; /* bounds, law or model may have changed */
    s->ready = 1;
    return FRICREG_OK;
}
