/* SPDX-License-Identifier: GPL-3.0-or-later */
/* jenkins.c — Jenkins elements (a spring kt in series with a Coulomb slider of bound mun) on
 * rows of J_e as a fricreg_structure's joints: their setters and getters, and their part of
 * each step.
 *
 * Element i sees q_i = (J_e u)_i and pushes back with fe_i = kt_i (q_i - w_i), |fe_i| <= mun_i,
 * by the exact return mapping from its committed slider position (src/joint/slider.h), so the
 * structure gets -J_e^T fe. The force is a function of the displacement with the consistent
 * tangent kt (stick) or 0 (slip).
 *
 * Newmark / HHT-alpha: with the contacts' forces zero (the combination with active contacts is
 * refused), the step's equation K_eff x = b - w J_e^T fe1 (w = 1 + alpha) condenses onto the
 * elements: u1 = u_pred + beta dt^2 x gives
 *   q(fe1) = q0 - c E fe1,   q0 = J_e (u_pred + beta dt^2 K_eff^-1 b),   c = w beta dt^2,
 * E = J_e K_eff^-1 J_e^T (me x me, formed once per factor of K_eff), and Newton solves
 * G(fe1) = fe1 - F(q(fe1)) = 0 on the matrix I + c diag(tangent) E with GSL's pivoted QR, the
 * direction halved until ||G||_2 decreases (the mapping is piecewise linear: a full step can
 * overshoot a kink). Central difference: fe1 = F(J_e u1) at the explicit displacement.
 *
 * Energy: fe = kt (q - w) at both ends of a step, so the trapezoidal work of the elements
 * dq (fe + fe1)/2 is exactly the change of their springs' energy fe^2/(2 kt) plus
 * dw (fe + fe1)/2, which is booked as their dissipation: the balance closes as it does for
 * the contacts. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_linalg.h>

#include "base/matrix_input.h"
#include "base/sparse_ops.h"
#include "joint/slider.h"
#include "structure_internal.h"

#define MAX_ELEMENTS ((size_t)1 << 26)
#define ARMIJO 1e-4 /* sufficient decrease of ||G||_2 */
#define MAX_CUTS 30 /* halvings of one Newton direction */

void fr_elements_free(fricreg_structure *s)
{
    struct fr_elements *e = &s->el;
    double *arrays[] = {e->kt,      e->mun,         e->wc, e->wt,  e->fe,  e->fe1, e->wc_held,
                        e->fe_held, e->dissipation, e->q0, e->g,   e->df,  e->ft,  e->gt,
                        e->tan,     e->E,           e->A,  e->tau, e->norm};
    for (size_t k = 0; k < sizeof arrays / sizeof *arrays; k++)
        free(arrays[k]);
    free(e->perm);
    cholmod_l_free_sparse(&e->Jt, &s->cc);
    *e = (struct fr_elements){0};
}

/* The new elements' arrays into e (zeroed); 0 when out of memory (e then partly filled: the
 * caller frees it). */
static int allocate(struct fr_elements *e, size_t me)
{
    double **arrays[] = {&e->kt,      &e->mun,     &e->wc,          &e->wt,  &e->fe,  &e->fe1,
                         &e->wc_held, &e->fe_held, &e->dissipation, &e->q0,  &e->g,   &e->df,
                         &e->ft,      &e->gt,      &e->tan,         &e->tau, &e->norm};
    for (size_t k = 0; k < sizeof arrays / sizeof *arrays; k++)
        if ((*arrays[k] = calloc(me, sizeof(double))) == NULL)
            return 0;
    e->E = calloc(me * me, sizeof(double));
    e->A = calloc(me * me, sizeof(double));
    e->perm = calloc(me, sizeof *e->perm);
    return e->E != NULL && e->A != NULL && e->perm != NULL;
}

/* Every element moves: no zero column of J_e^T. */
static int check_rows(fricreg_structure *s, const cholmod_sparse *Jt, const char *who)
{
    const SuiteSparse_long *p = Jt->p;
    const double *x = Jt->x;
    for (size_t i = 0; i < Jt->ncol; i++) {
        int moves = 0;
        for (SuiteSparse_long k = p[i]; k < p[i + 1]; k++)
            moves |= x[k] != 0.0;
        if (!moves)
            return fr_fail(s, FRICREG_EINVAL,
                           "%s: row %zu of J_e is zero: element %zu does not move", who, i, i);
    }
    return FRICREG_OK;
}

static int check_params(fricreg_structure *s, size_t me, const double kt[], const double mun[],
                        const char *who)
{
    if (kt == NULL || mun == NULL)
        return fr_fail(s, FRICREG_ENULL, "%s: kt or mun is NULL", who);
    for (size_t i = 0; i < me; i++) {
        if (!isfinite(kt[i]) || !isfinite(mun[i]))
            return fr_fail(s, FRICREG_ENONFINITE,
                           "%s: element %zu's kt = %g or mun = %g is not finite", who, i, kt[i],
                           mun[i]);
        if (!(kt[i] > 0.0) || !(mun[i] >= 0.0))
            return fr_fail(s, FRICREG_EINVAL,
                           "%s: element %zu needs kt > 0 and mun >= 0 (kt = %g, "
                           "mun = %g)",
                           who, i, kt[i], mun[i]);
    }
    return FRICREG_OK;
}

/* Takes J (me x n, CHOLMOD's, freed here on every path) and installs the elements. */
static int install(fricreg_structure *s, size_t me, cholmod_sparse *J, const double kt[],
                   const double mun[], const char *who)
{
    struct fr_elements e = {0};
    e.me = me;
    e.Jt = cholmod_l_transpose(J, 1, &s->cc);
    cholmod_l_free_sparse(&J, &s->cc);
    int status = e.Jt == NULL || !allocate(&e, me)
                     ? fr_fail(s, FRICREG_ENOMEM, "%s: no memory for %zu elements", who, me)
                     : check_rows(s, e.Jt, who);
    if (status != FRICREG_OK) {
        struct fr_elements old = s->el;
        s->el = e;
        fr_elements_free(s); /* e's, then the structure's own back */
        s->el = old;
        return status;
    }
    memcpy(e.kt, kt, me * sizeof *kt);
    memcpy(e.mun, mun, me * sizeof *mun);
    fr_elements_free(s);
    s->el = e;
    fr_structure_model_changed(s); /* E = J_e K_eff^-1 J_e^T and the equilibrium anew */
    s->omega_valid = 0;            /* the step guard's rates see the sticking springs */
    return FRICREG_OK;
}

static int start_setter(fricreg_structure *s, size_t me, size_t ndof, const char *who)
{
    if (s->running)
        return fr_structure_busy(s, who);
    if (ndof != s->n)
        return fr_fail(s, FRICREG_ESIZE, "%s: ndof = %zu, the structure has %zu", who, ndof, s->n);
    if (me > MAX_ELEMENTS)
        return fr_fail(s, FRICREG_EINVAL, "%s: me = %zu elements exceed 2^26", who, me);
    return FRICREG_OK;
}

static int remove_all(fricreg_structure *s)
{
    fr_elements_free(s);
    fr_structure_model_changed(s);
    s->omega_valid = 0;
    return FRICREG_OK;
}

int fricreg_structure_set_jenkins(fricreg_structure *s, size_t me, size_t ndof, const double Je[],
                                  const double kt[], const double mun[])
{
    const char *who = "set_jenkins";
    if (s == NULL)
        return FRICREG_ENULL;
    int status = start_setter(s, me, ndof, who);
    if (status != FRICREG_OK)
        return status;
    if (me == 0)
        return remove_all(s);
    if (Je == NULL)
        return fr_fail(s, FRICREG_ENULL, "%s: J_e is NULL", who);
    if ((status = check_params(s, me, kt, mun, who)) != FRICREG_OK)
        return status;
    for (size_t k = 0; k < me * ndof; k++)
        if (!isfinite(Je[k]))
            return fr_fail(s, FRICREG_ENONFINITE, "%s: J_e(%zu, %zu) is not finite", who, k / ndof,
                           k % ndof);
    cholmod_sparse *J = NULL;
    status = fr_dense_to_cholmod(me, ndof, Je, 0, &s->cc, &J, &s->err, who);
    return status != FRICREG_OK ? status : install(s, me, J, kt, mun, who);
}

int fricreg_structure_set_jenkins_csr(fricreg_structure *s, size_t me, size_t ndof, int flags,
                                      const int64_t rowptr[], const int64_t colind[],
                                      const double values[], const double kt[], const double mun[])
{
    const char *who = "set_jenkins_csr";
    if (s == NULL)
        return FRICREG_ENULL;
    int status = start_setter(s, me, ndof, who);
    if (status != FRICREG_OK)
        return status;
    if (me == 0)
        return remove_all(s);
    if ((status = check_params(s, me, kt, mun, who)) != FRICREG_OK)
        return status;
    struct fr_compressed a = {me, ndof, 0, flags, rowptr, colind, values};
    cholmod_sparse *J = NULL;
    status = fr_compressed_check(&a, 0, &s->err, who);
    if (status == FRICREG_OK)
        status = fr_compressed_to_cholmod(&a, 0, &s->cc, &J, &s->err, who);
    return status != FRICREG_OK ? status : install(s, me, J, kt, mun, who);
}

int fricreg_structure_get_jenkins_state(const fricreg_structure *s, size_t me, double f[],
                                        double w[], double D[])
{
    if (s == NULL || (f == NULL && w == NULL && D == NULL))
        return FRICREG_ENULL;
    if (me != s->el.me)
        return FRICREG_ESIZE;
    if (me == 0)
        return FRICREG_OK;
    if (f != NULL)
        memcpy(f, s->el.fe, me * sizeof *f);
    if (w != NULL)
        memcpy(w, s->el.wc, me * sizeof *w);
    if (D != NULL)
        memcpy(D, s->el.dissipation, me * sizeof *D);
    return FRICREG_OK;
}

int fr_elements_check_contacts(fricreg_structure *s, const char *who)
{
    if (s->el.me == 0)
        return FRICREG_OK;
    for (size_t i = 0; i < s->m; i++)
        if (s->mun[i] != 0.0)
            return fr_fail(s, FRICREG_EINVAL,
                           "%s: Jenkins elements beside friction contacts are not supported: "
                           "contact %zu has mun = %g (set the contacts' bounds to 0)",
                           who, i, s->mun[i]);
    return FRICREG_OK;
}

/* fe and the trial positions wt at q[me] from the committed wc, and the tangents where tan is
 * not NULL. */
static void map(const struct fr_elements *e, const double q[], double fe[], double tan[])
{
    for (size_t i = 0; i < e->me; i++)
        fr_slider_return(e->kt[i], e->mun[i], 0.0, 1, &q[i], &e->wc[i], &fe[i], &e->wt[i],
                         tan != NULL ? &tan[i] : NULL, NULL);
}

void fr_elements_equilibrium(fricreg_structure *s, gsl_vector *w)
{
    struct fr_elements *e = &s->el;
    if (e->me == 0)
        return;
    fr_csc_mult_t(e->Jt, s->u->data, e->q0);
    map(e, e->q0, e->fe, NULL);
    memcpy(e->wc, e->wt, e->me * sizeof *e->wc); /* idempotent: a returned slider sticks */
    fr_csc_mult_add(e->Jt, -1.0, e->fe, w->data);
}

void fr_elements_explicit(fricreg_structure *s, const gsl_vector *u1, gsl_vector *w)
{
    struct fr_elements *e = &s->el;
    if (e->me == 0)
        return;
    fr_csc_mult_t(e->Jt, u1->data, e->q0);
    map(e, e->q0, e->fe1, NULL);
    fr_csc_mult_add(e->Jt, -1.0, e->fe1, w->data);
}

int fr_elements_compliance(fricreg_structure *s)
{
    struct fr_elements *e = &s->el;
    if (e->me == 0 || e->E_valid)
        return FRICREG_OK;
    size_t me = e->me;
    const SuiteSparse_long *p = e->Jt->p, *ri = e->Jt->i;
    const double *x = e->Jt->x;
    double *col = s->dx->data, *sol = s->xt->data;
    for (size_t j = 0; j < me; j++) {
        memset(col, 0, s->n * sizeof *col);
        for (SuiteSparse_long k = p[j]; k < p[j + 1]; k++)
            col[ri[k]] = x[k];
        fr_cfactor_solve(&s->step, col, sol, &s->cc);
        fr_csc_mult_t(e->Jt, sol, e->E + j * me); /* E is symmetric: column j as row j */
    }
    e->E_valid = 1;
    return FRICREG_OK;
}

/* At the forces f[me]: q = q0 - c E f, the mapping's forces into e->ft's ... G = f - F(q) into
 * g, the tangents into e->tan, the trial sliders into e->wt; returns ||G||_2, *rinf its
 * largest entry (NaN propagates). */
static double evaluate(struct fr_elements *e, double c, const double f[], double g[], double *rinf)
{
    size_t me = e->me;
    double sum = 0.0, big = 0.0;
    for (size_t i = 0; i < me; i++) {
        double q = e->q0[i];
        for (size_t j = 0; j < me; j++)
            q -= c * e->E[i * me + j] * f[j];
        double F;
        fr_slider_return(e->kt[i], e->mun[i], 0.0, 1, &q, &e->wc[i], &F, &e->wt[i], &e->tan[i],
                         NULL);
        g[i] = f[i] - F;
        sum += g[i] * g[i];
        if (!(fabs(g[i]) <= big))
            big = fabs(g[i]);
    }
    *rinf = big;
    return sqrt(sum);
}

/* df = -(I + c diag(tan) E)^-1 g by GSL's QR with column pivoting (its LU allocates in GSL
 * 2.7: a step must not); 0 if the matrix is singular (not expected: diag(tan) E has no
 * negative eigenvalue). */
static int direction(struct fr_elements *e, double c)
{
    size_t me = e->me;
    for (size_t i = 0; i < me; i++) {
        for (size_t j = 0; j < me; j++)
            e->A[i * me + j] = c * e->tan[i] * e->E[i * me + j];
        e->A[i * me + i] += 1.0;
        e->df[i] = -e->g[i];
    }
    gsl_matrix_view A = gsl_matrix_view_array(e->A, me, me);
    gsl_vector_view tau = gsl_vector_view_array(e->tau, me),
                    norm = gsl_vector_view_array(e->norm, me), b = gsl_vector_view_array(e->df, me);
    gsl_permutation perm = {me, e->perm};
    int signum;
    if (gsl_linalg_QRPT_decomp(&A.matrix, &tau.vector, &perm, &signum, &norm.vector) != GSL_SUCCESS)
        return 0;
    for (size_t i = 0; i < me; i++)
        if (!(fabs(e->A[i * me + i]) > 0.0))
            return 0; /* the solve would call GSL's error handler */
    return gsl_linalg_QRPT_svx(&A.matrix, &tau.vector, &perm, &b.vector) == GSL_SUCCESS;
}

int fr_elements_newmark(fricreg_structure *s, double dt, double scale, gsl_vector *b,
                        int *converged, int *iters)
{
    struct fr_elements *e = &s->el;
    *converged = 1;
    *iters = 0;
    if (e->me == 0)
        return FRICREG_OK;
    size_t me = e->me, n = s->n;
    double w = 1.0 + s->alpha, b2 = s->beta * dt * dt, c = w * b2;
    double *x = s->dx->data;
    fr_cfactor_solve(&s->step, b->data, x, &s->cc);
    for (size_t k = 0; k < n; k++)
        x[k] = s->up->data[k] + b2 * x[k];
    fr_csc_mult_t(e->Jt, x, e->q0);
    for (size_t i = 0; i < me; i++)
        scale = fmax(scale, fabs(e->fe[i]));
    double tol = s->newton_tol * (scale > 0.0 ? scale : 1e-300);

    double *f = e->fe1, rinf, rinf_t;
    memcpy(f, e->fe, me * sizeof *f);
    double phi = evaluate(e, c, f, e->g, &rinf);
    int done = 0;
    while (rinf != 0.0 && (done == 0 || rinf > tol) && *iters < s->newton_max && isfinite(phi)) {
        if (!direction(e, c))
            break;
        ++*iters;
        ++done;
        double lambda = 1.0;
        int accepted = 0;
        for (int cut = 0; cut <= MAX_CUTS && !accepted; cut++) {
            for (size_t i = 0; i < me; i++)
                e->ft[i] = f[i] + lambda * e->df[i];
            double phi_t = evaluate(e, c, e->ft, e->gt, &rinf_t);
            if (phi_t <= (1.0 - ARMIJO * lambda) * phi) {
                memcpy(f, e->ft, me * sizeof *f);
                memcpy(e->g, e->gt, me * sizeof *e->g);
                phi = phi_t;
                rinf = rinf_t;
                accepted = 1;
            } else {
                s->stats[FRICREG_SSTAT_LINE_SEARCH_CUTS]++;
                lambda *= 0.5;
            }
        }
        if (!accepted) {
            phi = evaluate(e, c, f, e->g, &rinf); /* back to f: the best point */
            break;
        }
    }
    if (!isfinite(phi))
        return fr_fail(s, FRICREG_EDIVERGED,
                       "step: the Jenkins elements' residual at t = %g is not finite", s->t + dt);
    *converged = rinf <= tol;
    fr_csc_mult_add(e->Jt, -w, f, b->data);
    return FRICREG_OK;
}

void fr_elements_commit(fricreg_structure *s)
{
    struct fr_elements *e = &s->el;
    if (e->me == 0)
        return; /* no arrays: memcpy may not take NULL */
    memcpy(e->fe, e->fe1, e->me * sizeof *e->fe);
    memcpy(e->wc, e->wt, e->me * sizeof *e->wc);
}

void fr_elements_hold(fricreg_structure *s, int restore)
{
    struct fr_elements *e = &s->el;
    size_t bytes = e->me * sizeof(double);
    if (e->me == 0)
        return;
    memcpy(restore ? e->fe : e->fe_held, restore ? e->fe_held : e->fe, bytes);
    memcpy(restore ? e->wc : e->wc_held, restore ? e->wc_held : e->wc, bytes);
}

void fr_elements_reset(fricreg_structure *s)
{
    struct fr_elements *e = &s->el;
    if (e->me == 0)
        return;
    memset(e->wc, 0, e->me * sizeof *e->wc);
    memset(e->fe, 0, e->me * sizeof *e->fe);
}

double fr_elements_strain(const fricreg_structure *s)
{
    const struct fr_elements *e = &s->el;
    double energy = 0.0;
    for (size_t i = 0; i < e->me; i++)
        energy += 0.5 * e->fe[i] * (e->fe[i] / e->kt[i]);
    return energy;
}
