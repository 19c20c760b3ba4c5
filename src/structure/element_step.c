/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element_step.c — the elements' part of a structure's step (elements.c holds them): their
 * forces at a displacement (the equilibrium, the central difference) and the condensed Newton
 * of Newmark / HHT-alpha, every element evaluated by its type's kernel on the structure's slot
 * arrays (fricreg_element_eval's law, bit for bit).
 *
 * Newmark / HHT-alpha: with the contacts' forces zero (every bound 0; beside contacts of bound
 * > 0 the step is joint_step.c's, one Newton over both forces), the step's equation
 * K_eff x = b - w J^T fe1 (w = 1 + alpha) condenses onto the element coordinates:
 * u1 = u_pred + beta dt^2 x gives
 *   y(fe1) = q0 - c E fe1,   q0 = J (u_pred + beta dt^2 K_eff^-1 b),   c = w beta dt^2,
 * E = J K_eff^-1 J^T (nc x nc, formed once per factor of K_eff), and Newton solves
 * G(fe1) = fe1 - F(y(fe1)) = 0 on the matrix I + c T E (T the elements' block-diagonal
 * consistent tangent) with GSL's pivoted QR, the direction halved until ||G||_2 decreases (the
 * mapping is piecewise linear: a full step can overshoot a kink). The force is a function of
 * the displacement, so the Newton keeps nc unknowns whatever the sliders' count. Central
 * difference: fe1 = F(J u1) at the explicit displacement.
 *
 * The normal law's own row is the structure's: dN/dg = kn while N > 0 strictly (the kernel
 * takes kn at N = 0 too); at N = 0 the Newton takes the open side, as 1.x did. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_linalg.h>

#include "base/line_search.h"
#include "base/newton_loop.h"
#include "base/sparse_ops.h"
#include "joint/element_kind.h"
#include "structure_internal.h"

/* Element i at the coordinates y: its forces into x at its coordinates (x may be NULL), its
 * sliders' trial positions and forces into wt and fs1 from the committed wc, and with tangent
 * its dfe/dy block into tb (the normal row's as the structure takes it). */
static void element_at(struct fr_elements *e, size_t i, const double y[], double x[], int tangent)
{
    const fricreg_element_type *T = e->type[i];
    int dim = T->kind->dim, td = dim - T->kind->normal;
    const double *p = e->params + e->par[i];
    double u[3], f[3], *dfdu = tangent ? e->tb + e->blk[i] : NULL;
    fr_elements_gather(e, i, y, u);
    T->kind->eval(T, p, e->wc + e->slot[i], u, f, dfdu, NULL, e->wt + e->slot[i],
                  e->fs1 + e->slot[i]);
    if (tangent && td < dim) {
        size_t ns = T->ns;
        double kn = p[2 * ns], N = p[2 * ns + 1] + kn * (u[td] - p[2 * ns + 2]);
        dfdu[dim * td + td] = N > 0.0 ? kn : 0.0;
    }
    if (x != NULL)
        fr_elements_scatter(e, i, f, x);
}

/* The forces x[nc] at the coordinates y[nc] from the committed wc (the sliders' trial state as
 * element_at's): the elements', then the normal forces max(0, n0 + kn (g - gap)). */
static void map(struct fr_elements *e, const double y[], double x[])
{
    for (size_t i = 0; i < e->me; i++)
        element_at(e, i, y, x, 0);
}

int fr_elements_tangent_row(const struct fr_elements *e, size_t k, size_t col[3], double val[3])
{
    size_t i = e->owner[k];
    const fricreg_element_type *T = e->type[i];
    size_t dim = (size_t)T->kind->dim, td = dim - (size_t)T->kind->normal;
    const double *b = e->tb + e->blk[i];
    if (k >= e->nt) { /* a normal row: dN/dg alone */
        col[0] = k;
        val[0] = b[dim * td + td];
        return 1;
    }
    size_t a = k - e->at[i];
    int n = 1;
    col[0] = k;
    val[0] = b[dim * a + a];
    for (size_t c = 0; c < td; c++)
        if (c != a) {
            col[n] = e->at[i] + c;
            val[n++] = b[dim * a + c];
        }
    if (td < dim) {
        col[n] = e->normal[i];
        val[n++] = b[dim * a + td];
    }
    return n;
}

/* Each slider's force is finite (|f_s| <= phi_s N) but the sum of ns of them, or of the
 * sticking sliders' stiffnesses, can overflow (as fricreg_iwan_trial's): FRICREG_ENONFINITE
 * naming the element, as the standalone element does, rather than an infinite force that
 * the friction law or Newton's residual would refuse without saying why. */
static int overflowed(fricreg_structure *s, size_t i, const char *what, double sum, double t)
{
    return fr_fail(s, FRICREG_ENONFINITE,
                   "step: element %zu's sliders sum to a %s of %g at t = %g: the sum of %zu "
                   "sliders overflows (their stiffnesses or slip forces near the double range)",
                   i, what, sum, t, s->el.type[i]->ns);
}

/* map, then FRICREG_ENONFINITE if an element's force x[i] overflowed. */
static int map_checked(fricreg_structure *s, const double y[], double x[], double t)
{
    struct fr_elements *e = &s->el;
    map(e, y, x);
    for (size_t i = 0; i < e->nc; i++)
        if (!isfinite(x[i]))
            return overflowed(s, e->owner[i], "force", x[i], t);
    return FRICREG_OK;
}

int fr_elements_overflow(fricreg_structure *s, double t)
{
    const struct fr_elements *e = &s->el;
    if (e->overflow == 0)
        return FRICREG_OK;
    return overflowed(s, e->overflow - 1, e->overflow_what, e->overflow_sum, t);
}

int fr_elements_equilibrium(fricreg_structure *s, gsl_vector *w)
{
    struct fr_elements *e = &s->el;
    if (e->me == 0)
        return FRICREG_OK;
    fr_csc_mult_t(e->Jt, s->u->data, e->q0);
    int status = map_checked(s, e->q0, e->fe, s->t); /* fe is held by the caller */
    if (status != FRICREG_OK)
        return status;
    size_t bytes = e->nslots * sizeof(double); /* idempotent: sticks */
    memcpy(e->wc, e->wt, bytes);
    memcpy(e->fs, e->fs1, bytes);
    fr_csc_mult_add(e->Jt, -1.0, e->fe, w->data);
    return FRICREG_OK;
}

int fr_elements_explicit(fricreg_structure *s, const gsl_vector *u1, gsl_vector *w, double t)
{
    struct fr_elements *e = &s->el;
    if (e->me == 0)
        return FRICREG_OK;
    fr_csc_mult_t(e->Jt, u1->data, e->q0);
    int status = map_checked(s, e->q0, e->fe1, t);
    if (status != FRICREG_OK)
        return status;
    fr_csc_mult_add(e->Jt, -1.0, e->fe1, w->data);
    return FRICREG_OK;
}

int fr_elements_compliance(fricreg_structure *s, int joint)
{
    struct fr_elements *e = &s->el;
    if (e->me == 0 || (e->E_valid && (!joint || e->joint.valid)))
        return FRICREG_OK;
    size_t nc = e->nc;
    if (joint && !fr_joint_allocate(&e->joint, s->m, nc))
        return fr_fail(s, FRICREG_ENOMEM,
                       "step: no memory for the joint Newton matrix (%zu contacts, %zu element "
                       "coordinates)",
                       s->m, nc);
    const SuiteSparse_long *p = e->Jt->p, *ri = e->Jt->i;
    const double *x = e->Jt->x;
    double *col = s->dx->data, *sol = s->xt->data, *cross = e->joint.dzc;
    for (size_t j = 0; j < nc; j++) {
        memset(col, 0, s->n * sizeof *col);
        for (SuiteSparse_long k = p[j]; k < p[j + 1]; k++)
            col[ri[k]] = x[k];
        fr_cfactor_solve(&s->step, col, sol, &s->cc);
        fr_csc_mult_t(e->Jt, sol, e->E + j * nc); /* E is symmetric: column j as row j */
        if (joint) {                              /* column j of C = J K_eff^-1 J_e^T */
            fr_csc_mult_t(s->Jt, sol, cross);
            for (size_t i = 0; i < s->m; i++)
                e->joint.C[i * nc + j] = cross[i];
        }
    }
    e->E_valid = 1;
    if (joint)
        fr_joint_compliances(s);
    return FRICREG_OK;
}

/* The first of element i's sums that is not finite at its last evaluation into x: its force
 * ("force"), its tangent ("tangent") or dfe/dg ("df/dg"), recorded in e->overflow unless an
 * earlier element's was. */
static void record_overflow(struct fr_elements *e, size_t i, const double x[])
{
    const fricreg_element_type *T = e->type[i];
    size_t dim = (size_t)T->kind->dim, td = dim - (size_t)T->kind->normal;
    const double *b = e->tb + e->blk[i];
    const char *what = NULL;
    double sum = 0.0;
    for (size_t a = 0; a < td && what == NULL; a++) {
        size_t k = e->at[i] + a;
        if (!isfinite(x[k]))
            what = "force", sum = x[k];
        for (size_t c = 0; c < dim && what == NULL; c++)
            if (!isfinite(b[dim * a + c]))
                what = c < td ? "tangent" : "df/dg", sum = b[dim * a + c];
    }
    if (what != NULL && e->overflow == 0) {
        e->overflow = i + 1;
        e->overflow_what = what;
        e->overflow_sum = sum;
    }
}

double fr_elements_residual(struct fr_elements *e, const double f[], double g[], double *rinf)
{
    size_t nc = e->nc;
    struct fr_sumsq sum = {0.0, 0.0};
    double big = 0.0;
    e->overflow = 0;
    for (size_t i = 0; i < e->me; i++) {
        element_at(e, i, e->y, e->fy, 1);
        record_overflow(e, i, e->fy);
    }
    for (size_t i = 0; i < nc; i++)
        g[i] = f[i] - e->fy[i];
    for (size_t i = 0; i < nc; i++) {
        fr_sumsq_add(&sum, g[i]);
        if (!(fabs(g[i]) <= big))
            big = fabs(g[i]);
    }
    *rinf = big;
    return fr_sumsq_root(&sum);
}

/* At the forces f[nc]: the coordinates y = q0 - c E f, then fr_elements_residual. */
static double evaluate(struct fr_elements *e, double c, const double f[], double g[], double *rinf)
{
    size_t nc = e->nc;
    for (size_t i = 0; i < nc; i++) {
        double q = e->q0[i];
        for (size_t j = 0; j < nc; j++)
            q -= c * e->E[i * nc + j] * f[j];
        e->y[i] = q;
    }
    return fr_elements_residual(e, f, g, rinf);
}

/* df = -(I + c T E)^-1 g, T the tangent's rows (fr_elements_tangent_row), by GSL's QR with
 * column pivoting (its LU allocates in GSL 2.7: a step must not); 0 if the matrix is singular. */
static int direction(struct fr_elements *e, double c)
{
    size_t nc = e->nc;
    for (size_t i = 0; i < nc; i++) {
        size_t col[3];
        double val[3];
        int n = fr_elements_tangent_row(e, i, col, val);
        for (size_t j = 0; j < nc; j++)
            e->A[i * nc + j] = c * val[0] * e->E[col[0] * nc + j];
        for (int r = 1; r < n; r++)
            for (size_t j = 0; j < nc; j++)
                e->A[i * nc + j] += c * val[r] * e->E[col[r] * nc + j];
        e->A[i * nc + i] += 1.0;
        e->df[i] = -e->g[i];
    }
    gsl_matrix_view A = gsl_matrix_view_array(e->A, nc, nc);
    gsl_vector_view tau = gsl_vector_view_array(e->tau, nc),
                    norm = gsl_vector_view_array(e->norm, nc), b = gsl_vector_view_array(e->df, nc);
    gsl_permutation perm = {nc, e->perm};
    int signum;
    if (gsl_linalg_QRPT_decomp(&A.matrix, &tau.vector, &perm, &signum, &norm.vector) != GSL_SUCCESS)
        return 0;
    for (size_t i = 0; i < nc; i++)
        if (!(fabs(e->A[i * nc + i]) > 0.0))
            return 0; /* the solve would call GSL's error handler */
    return gsl_linalg_QRPT_svx(&A.matrix, &tau.vector, &perm, &b.vector) == GSL_SUCCESS;
}

void fr_elements_bound(const struct fr_elements *e, double f[])
{
    for (size_t i = 0; i < e->me; i++) {
        const fricreg_element_type *T = e->type[i];
        double fi[3];
        fr_elements_gather(e, i, f, fi);
        T->kind->project(T, e->params + e->par[i], fi);
        fr_elements_scatter(e, i, fi, f);
    }
}

/* A trial f + lambda df into ft and its residual gt; accepted by Armijo on ||G||_2, they
 * become f's and g's. */
struct element_trial {
    struct fr_elements *e;
    const struct fr_line_search *ls;
    double c, *f, *phi, *rinf;
};

static int element_trial(void *user, double lambda, int *accept)
{
    struct element_trial *t = user;
    struct fr_elements *e = t->e;
    size_t nc = e->nc;
    for (size_t i = 0; i < nc; i++)
        e->ft[i] = t->f[i] + lambda * e->df[i];
    double rinf_t, phi_t = evaluate(e, t->c, e->ft, e->gt, &rinf_t);
    *accept = fr_armijo_decrease(t->ls, *t->phi, phi_t, lambda);
    if (*accept) {
        memcpy(t->f, e->ft, nc * sizeof *t->f);
        memcpy(e->g, e->gt, nc * sizeof *e->g);
        *t->phi = phi_t;
        *t->rinf = rinf_t;
    }
    return FRICREG_OK;
}

/* The loop's view of the elements' Newton at c (newton_loop.h): the iterate f. */
struct element_loop {
    struct fr_elements *e;
    double c, *f;
    struct fr_line_search ls;
};

static int element_direction(void *user)
{
    struct element_loop *l = user;
    if (l->e->overflow != 0 || !direction(l->e, l->c)) /* none from an infinite tangent */
        return FRICREG_ESINGULAR;
    return FRICREG_OK;
}

static int element_search(void *user, double *phi, double *rinf, int *accepted)
{
    struct element_loop *l = user;
    struct element_trial t = {l->e, &l->ls, l->c, l->f, phi, rinf};
    fr_line_search(&l->ls, 1.0, element_trial, &t, accepted); /* the trials cannot fail */
    return FRICREG_OK;
}

static void element_restore(void *user, double *phi, double *rinf)
{
    struct element_loop *l = user;
    *phi = evaluate(l->e, l->c, l->f, l->e->g, rinf);
}

int fr_elements_newmark(fricreg_structure *s, double dt, double scale, gsl_vector *b,
                        int *converged, int *iters)
{
    struct fr_elements *e = &s->el;
    *converged = 1;
    *iters = 0;
    if (e->me == 0)
        return FRICREG_OK;
    size_t nc = e->nc, n = s->n;
    double w = 1.0 + s->alpha, b2 = s->beta * dt * dt, c = w * b2;
    double *x = s->dx->data;
    fr_cfactor_solve(&s->step, b->data, x, &s->cc);
    for (size_t k = 0; k < n; k++)
        x[k] = s->up->data[k] + b2 * x[k];
    fr_csc_mult_t(e->Jt, x, e->q0);
    for (size_t i = 0; i < nc; i++)
        scale = fmax(scale, fabs(e->fe[i]));
    double tol = s->newton_tol * (scale > 0.0 ? scale : 1e-300);

    double *f = e->fe1, rinf;
    memcpy(f, e->fe, nc * sizeof *f);
    double phi = evaluate(e, c, f, e->g, &rinf);
    struct element_loop l = {
        e, c, f, {FR_ARMIJO, FR_STEP_HALVINGS, &s->stats[FRICREG_SSTAT_LINE_SEARCH_CUTS]}};
    struct fr_newton_loop nl = {
        tol, s->newton_max, 0, &l, element_direction, element_search, element_restore, NULL, NULL};
    fr_newton_loop_run(&nl, &phi, &rinf, iters); /* its end is the step's: judged below */
    if (e->overflow != 0 && !(rinf <= tol))      /* at the last iterate: its force or the tangent */
        return fr_elements_overflow(s, s->t + dt);
    if (!isfinite(phi))
        return fr_fail(s, FRICREG_EDIVERGED, "step: the elements' residual at t = %g is not finite",
                       s->t + dt);
    *converged = rinf <= tol;
    fr_elements_bound(e, f);
    fr_csc_mult_add(e->Jt, -w, f, b->data);
    return FRICREG_OK;
}
