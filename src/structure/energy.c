/* SPDX-License-Identifier: GPL-3.0-or-later */
/* energy.c — the structure's energy balance, summed step by step with the trapezoidal rule
 * on the displacement increments (Krenk, "Energy conservation in Newmark based time
 * integration algorithms", CMAME 195 (2006)): for average-acceleration Newmark
 * du = dt (v + v1)/2 and dv = dt (a + a1)/2, so du.M(a + a1)/2 = d(v.M v/2) and
 * du.K(u + u1)/2 = d(u.K u/2) exactly, and the balance closes to Newton's tolerance. */
#include <string.h>

#include "base/sparse_ops.h"
#include "structure_internal.h"

/* x^T S x for a symmetric S stored as its upper triangle: no scratch, so that the getters
 * (const, callable from the observer mid-step) may use it. */
static double quadratic_form(const cholmod_sparse *S, const double x[])
{
    const SuiteSparse_long *Sp = S->p, *Si = S->i;
    const double *Sx = S->x;
    double q = 0.0;
    for (size_t j = 0; j < S->ncol; j++)
        for (SuiteSparse_long p = Sp[j]; p < Sp[j + 1]; p++)
            q += ((size_t)Si[p] == j ? 1.0 : 2.0) * Sx[p] * x[Si[p]] * x[j];
    return q;
}

double fr_energy_kinetic(const fricreg_structure *s)
{
    return 0.5 * quadratic_form(s->M, s->v->data);
}

double fr_energy_strain(const fricreg_structure *s)
{
    return 0.5 * quadratic_form(s->K, s->u->data) + fr_elements_strain(s);
}

void fr_energy_reset(fricreg_structure *s)
{
    s->energy.initial = s->energy.input = s->energy.viscous = s->energy.friction = 0.0;
    memset(s->energy.per_contact, 0, s->m * sizeof *s->energy.per_contact);
    s->energy.jenkins = 0.0;
    if (s->el.me > 0)
        memset(s->el.dissipation, 0, s->el.me * sizeof *s->el.dissipation);
}

void fr_energy_start(fricreg_structure *s)
{
    fr_energy_reset(s);
    s->energy.initial = fr_energy_kinetic(s) + fr_energy_strain(s);
}

/* The step from (u, v, p~, f) at t to (u1, v1, p~1, f1); before the state is replaced.
 * Uses s->dx, s->xt and s->mwork as scratch (Newton is done with them). The means of
 * the loads and forces are x/2 + x1/2, not (x + x1)/2: a load and a friction bound near
 * DBL_MAX (holding each other, at rest) made the sum overflow and 0 * Inf a NaN dissipation;
 * halving is exact, so in range the numbers are the same. */
void fr_energy_step(fricreg_structure *s, const gsl_vector *u1, const gsl_vector *v1,
                    const gsl_vector *ptil1, const gsl_vector *f1)
{
    double *du = s->dx->data, *mid = s->xt->data, *dz = s->mwork->data;
    const double *u = s->u->data, *v = s->v->data, *p = s->ptil->data;
    double input = 0.0;
    for (size_t k = 0; k < s->n; k++) {
        du[k] = u1->data[k] - u[k];
        input += du[k] * (0.5 * ptil1->data[k] + 0.5 * p[k]);
        mid[k] = 0.5 * v[k] + 0.5 * v1->data[k];
    }
    s->energy.input += input;
    s->energy.viscous += fr_sym_bilinear(s->Cd, du, mid);

    fr_csc_mult_t(s->Jt, du, dz);
    for (size_t i = 0; i < s->m; i++) {
        double d = -dz[i] * (0.5 * s->f->data[i] + 0.5 * f1->data[i]);
        s->energy.per_contact[i] += d;
        s->energy.friction += d;
    }
    const struct fr_elements *e = &s->el; /* its sliders' slip times the mean force */
    for (size_t i = 0; i < e->me; i++) {
        double d = 0.0; /* a 2-D slider: dw . (f + f1)/2 */
        for (size_t j = e->slot[i]; j < e->slot[i + 1]; j++)
            d += (e->wt[j] - e->wc[j]) * (0.5 * e->fs[j] + 0.5 * e->fs1[j]);
        e->dissipation[i] += d;
        s->energy.jenkins += d;
    }
}
