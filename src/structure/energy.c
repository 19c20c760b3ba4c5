/* SPDX-License-Identifier: GPL-3.0-or-later */
/* energy.c — the structure's energy balance, summed step by step with the trapezoidal rule
 * on the displacement increments (Krenk, "Energy conservation in Newmark based time
 * integration algorithms", CMAME 195 (2006)): for average-acceleration Newmark
 * du = dt (v + v1)/2 and dv = dt (a + a1)/2, so du.M(a + a1)/2 = d(v.M v/2) and
 * du.K(u + u1)/2 = d(u.K u/2) exactly, and the balance closes to Newton's tolerance. */
#include <string.h>

#include <gsl/gsl_blas.h>

#include "structure_internal.h"

double fr_energy_kinetic(const fricreg_structure *s)
{
    double q = 0.0;
    for (size_t i = 0; i < s->n; i++)
        for (size_t j = 0; j < s->n; j++)
            q += gsl_vector_get(s->v, i) * gsl_matrix_get(s->M, i, j) * gsl_vector_get(s->v, j);
    return 0.5 * q;
}

double fr_energy_strain(const fricreg_structure *s)
{
    double q = 0.0;
    for (size_t i = 0; i < s->n; i++)
        for (size_t j = 0; j < s->n; j++)
            q += gsl_vector_get(s->u, i) * gsl_matrix_get(s->K, i, j) * gsl_vector_get(s->u, j);
    return 0.5 * q;
}

void fr_energy_reset(fricreg_structure *s)
{
    s->energy.initial = s->energy.input = s->energy.viscous = s->energy.friction = 0.0;
    memset(s->energy.per_contact, 0, s->m * sizeof *s->energy.per_contact);
}

void fr_energy_start(fricreg_structure *s)
{
    fr_energy_reset(s);
    s->energy.initial = fr_energy_kinetic(s) + fr_energy_strain(s);
}

/* The step from (u, v, p~, f) at t to (u1, v1, p~1, f1); before the state is replaced.
 * Uses s->dx, s->xt and s->mwork as scratch (Newton is done with them). The means of the
 * loads and forces are x/2 + x1/2, not (x + x1)/2: a load and a friction bound near DBL_MAX
 * (holding each other, at rest) made the sum overflow and 0 * Inf a NaN dissipation; halving
 * is exact, so in range the numbers are the same. */
void fr_energy_step(fricreg_structure *s, const gsl_vector *u1, const gsl_vector *v1,
                    const gsl_vector *ptil1, const gsl_vector *f1)
{
    gsl_vector *du = s->dx, *mid = s->xt;
    gsl_vector_memcpy(du, u1);
    gsl_vector_sub(du, s->u);

    double w;
    gsl_vector_memcpy(mid, ptil1);
    gsl_vector_scale(mid, 0.5);
    gsl_blas_daxpy(0.5, s->ptil, mid);
    gsl_blas_ddot(du, mid, &w);
    s->energy.input += w;

    gsl_vector_memcpy(mid, s->v);
    gsl_vector_add(mid, v1);
    gsl_blas_dgemv(CblasNoTrans, 0.5, s->C, mid, 0.0, s->work);
    gsl_blas_ddot(du, s->work, &w);
    s->energy.viscous += w;

    gsl_blas_dgemv(CblasNoTrans, 1.0, s->J, du, 0.0, s->mwork); /* dz */
    for (size_t i = 0; i < s->m; i++) {
        double d = -gsl_vector_get(s->mwork, i) *
                   (0.5 * gsl_vector_get(s->f, i) + 0.5 * gsl_vector_get(f1, i));
        s->energy.per_contact[i] += d;
        s->energy.friction += d;
    }
}
