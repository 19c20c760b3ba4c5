/* SPDX-License-Identifier: GPL-3.0-or-later */
/* jenkins.c — Jenkins elements (a spring kt in series with a Coulomb slider of bound mun) and
 * Iwan elements (ns such sliders in parallel) on rows of J_e as a fricreg_structure's joints:
 * their setters and getters, and their part of each step.
 *
 * Element i sees q_i = (J_e u)_i and pushes back with fe_i = sum_s k_s (q_i - w_s),
 * |k_s (q_i - w_s)| <= phi_s, each slider by the exact return mapping from its committed
 * position (src/joint/slider.h), so the structure gets -J_e^T fe. A Jenkins element is one
 * slider (k = kt, phi = mun). The force is a function of the displacement with the consistent
 * tangent sum of the sticking sliders' k: the condensed Newton below keeps me unknowns whatever
 * ns is.
 *
 * With a normal law (set_jenkins_normal, set_iwan_normal) element i also has a row of J_n,
 * g_i = (J_n u)_i, N_i = max(0, n0_i + kn_i g_i) acting as -J_n^T N on the structure, and each
 * slider's bound phi N (phi holding the slider's friction coefficient)
 * (fricreg_jenkins_trial_normal's law; separated, N_i < 0 before the max, the sliders follow
 * q). The coordinates below are then (q, g) and the forces (fe, N): 2 me of them, J = J_e over
 * J_n, and the tangent T gains dfe/dg (slipping) and dN/dg = kn (closed).
 *
 * 2-D elements (set_jenkins_2d; ns = 1, no normal law) have two coordinates each, rows 2i and
 * 2i + 1 of J_e, nc = 2 me, and one 2-D slider returned radially onto its disk by the same
 * slider.h: T is block diagonal, element i's 2x2 block kt I sticking and (mun/|d|)(I - n n^T)
 * slipping, its diagonal in tan and its off-diagonal in tang (fr_elements_partner names the
 * column: the other coordinate of the element). An element moving on one axis has a zero
 * off-diagonal there and is the 1-D element.
 *
 * 3-D contact elements (set_jenkins_2d_normal) are 2-D elements with the normal law: the 2 me
 * tangential coordinates, then the me normal ones (nc = 3 me, J = J_e over J_n), the bound
 * mu max(0, n0 + kn g) and lift-off as in 1-D; a tangential row k has, beside its 2x2 block,
 * dfe/dg = mu kn n (slipping) in tagn[k] at column fr_elements_normal_column, the normal row
 * kn (closed) on its diagonal.
 *
 * Newmark / HHT-alpha: with the contacts' forces zero (every bound 0; beside contacts of bound
 * > 0 the step is joint_step.c's, one Newton over both forces), the step's equation K_eff x = b - w J_e^T fe1 (w = 1 + alpha) condenses onto the
 * elements: u1 = u_pred + beta dt^2 x gives
 *   q(fe1) = q0 - c E fe1,   q0 = J_e (u_pred + beta dt^2 K_eff^-1 b),   c = w beta dt^2,
 * E = J_e K_eff^-1 J_e^T (me x me, formed once per factor of K_eff), and Newton solves
 * G(fe1) = fe1 - F(q(fe1)) = 0 on the matrix I + c T E (T = diag(tangent)) with GSL's
 * pivoted QR, the direction halved until ||G||_2 decreases (the mapping is piecewise linear: a
 * full step can overshoot a kink). Central difference: fe1 = F(J_e u1) at the explicit displacement.
 *
 * Energy: f_s = k_s (q - w_s) at both ends of a step, so a slider's share of the trapezoidal
 * work dq (f_s + f_s1)/2 is exactly the change of its spring's energy f_s^2/(2 k_s) plus
 * dw_s (f_s + f_s1)/2, which is booked as its dissipation: the balance closes as it does for
 * the contacts. A normal spring's dg (N + N1)/2 is the change of N^2/(2 kn) while it stays
 * closed (or open); a step across the kink is not exact. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_linalg.h>

#include "base/line_search.h"
#include "base/matrix_input.h"
#include "base/sparse_ops.h"
#include "joint/slider.h"
#include "base/newton_loop.h"
#include "structure_internal.h"

#define MAX_ELEMENTS ((size_t)1 << 26)

void fr_elements_free(fricreg_structure *s)
{
    struct fr_elements *e = &s->el;
    double *arrays[] = {e->k,           e->phi,  e->n0, e->kn,  e->kstick,  e->wc,      e->wt,
                        e->fs,          e->fs1,  e->fe, e->fe1, e->wc_held, e->fs_held, e->fe_held,
                        e->dissipation, e->q0,   e->y,  e->g,   e->df,      e->ft,      e->gt,
                        e->tan,         e->tang, e->E,  e->A,   e->tau,     e->norm,    e->tagn};
    for (size_t k = 0; k < sizeof arrays / sizeof *arrays; k++)
        free(arrays[k]);
    free(e->perm);
    fr_joint_free(&e->joint);
    cholmod_l_free_sparse(&e->Jt, &s->cc);
    *e = (struct fr_elements){0};
}

/* The new elements' arrays into e (zeroed; e->me, ns, nc, dim, n0 (non-NULL: with a normal
 * law) set); 0 when out of memory (e then partly filled: the caller frees it). */
static int allocate(struct fr_elements *e, int normal_law)
{
    size_t me = e->me, ns = e->ns * (size_t)e->dim, nc = e->nc;
    double **sliders[] = {&e->k,  &e->phi, &e->wc,      &e->wt,
                          &e->fs, &e->fs1, &e->wc_held, &e->fs_held};
    double **coordinates[] = {&e->kstick, &e->fe, &e->fe1, &e->fe_held, &e->q0,  &e->y,   &e->g,
                              &e->df,     &e->ft, &e->gt,  &e->tan,     &e->tau, &e->norm};
    double **normal[] = {&e->n0, &e->kn};
    for (size_t k = 0; k < sizeof sliders / sizeof *sliders; k++)
        if ((*sliders[k] = calloc(me * ns, sizeof(double))) == NULL)
            return 0;
    for (size_t k = 0; k < sizeof coordinates / sizeof *coordinates; k++)
        if ((*coordinates[k] = calloc(nc, sizeof(double))) == NULL)
            return 0;
    for (size_t k = 0; k < sizeof normal / sizeof *normal && normal_law; k++)
        if ((*normal[k] = calloc(me, sizeof(double))) == NULL)
            return 0;
    if ((e->dim == 2 || normal_law) &&
        (e->tang = calloc(e->dim == 2 ? nc : me, sizeof(double))) == NULL)
        return 0;
    if (e->dim == 2 && normal_law && (e->tagn = calloc(nc, sizeof(double))) == NULL)
        return 0;
    e->dissipation = calloc(me, sizeof(double));
    e->E = calloc(nc * nc, sizeof(double));
    e->A = calloc(nc * nc, sizeof(double));
    e->perm = calloc(nc, sizeof *e->perm);
    return e->dissipation != NULL && e->E != NULL && e->A != NULL && e->perm != NULL;
}

/* Every element moves: no zero column of J^T (me of J_e, then J_n's; 2 me of J_e in 2-D). */
static int check_rows(fricreg_structure *s, const cholmod_sparse *Jt, size_t me, int dim,
                      const char *who)
{
    const SuiteSparse_long *p = Jt->p;
    const double *x = Jt->x;
    for (size_t i = 0; i < Jt->ncol; i++) {
        int moves = 0;
        for (SuiteSparse_long k = p[i]; k < p[i + 1]; k++)
            moves |= x[k] != 0.0;
        if (!moves && dim == 2 && i >= 2 * me)
            return fr_fail(s, FRICREG_EINVAL,
                           "%s: row %zu of J_n is zero: element %zu does not move normally", who,
                           i - 2 * me, i - 2 * me);
        if (!moves && dim == 2)
            return fr_fail(s, FRICREG_EINVAL,
                           "%s: row %zu of J_e is zero: element %zu does not move along its "
                           "axis %zu",
                           who, i, i / 2, i % 2);
        if (!moves)
            return fr_fail(s, FRICREG_EINVAL,
                           "%s: row %zu of %s is zero: element %zu does not move", who, i % me,
                           i < me ? "J_e" : "J_n", i % me);
    }
    return FRICREG_OK;
}

/* What a setter attaches: Jenkins elements (ns = 1, kt and mun), Iwan elements (k and phi per
 * slider), or either with a normal law (kt or k, and mu per slider; n0 and kn, J_n). */
enum kind { KIND_JENKINS, KIND_IWAN, KIND_NORMAL, KIND_IWAN_NORMAL };

static int normal_law(enum kind kind)
{
    return kind == KIND_NORMAL || kind == KIND_IWAN_NORMAL;
}

/* k > 0 and phi >= 0, finite, per slider (ns of them per element), named after the kind. */
static int check_params(fricreg_structure *s, size_t me, size_t ns, enum kind kind,
                        const double k[], const double phi[], const char *who)
{
    const char *kn = kind == KIND_IWAN || kind == KIND_IWAN_NORMAL ? "k" : "kt";
    const char *pn = kind == KIND_IWAN ? "phi" : normal_law(kind) ? "mu" : "mun";
    if (k == NULL || phi == NULL)
        return fr_fail(s, FRICREG_ENULL, "%s: %s or %s is NULL", who, kn, pn);
    for (size_t j = 0; j < me * ns; j++) {
        if (!isfinite(k[j]) || !isfinite(phi[j]))
            return fr_fail(s, FRICREG_ENONFINITE,
                           "%s: element %zu's %s = %g or %s = %g (slider %zu) is not finite", who,
                           j / ns, kn, k[j], pn, phi[j], j % ns);
        if (!(k[j] > 0.0) || !(phi[j] >= 0.0))
            return fr_fail(s, FRICREG_EINVAL,
                           "%s: element %zu (slider %zu) needs %s > 0 and %s >= 0 (%s = %g, "
                           "%s = %g)",
                           who, j / ns, j % ns, kn, pn, kn, k[j], pn, phi[j]);
    }
    return FRICREG_OK;
}

/* Takes J (nc x n: J_e, then J_n with a normal law n0, kn (else NULL); J_e of 2 me rows for
 * dim 2; CHOLMOD's, freed here on every path) and installs the elements of ns sliders each. */
static int install(fricreg_structure *s, size_t me, size_t ns, int dim, cholmod_sparse *J,
                   const double k[], const double phi[], const double n0[], const double kn[],
                   const char *who)
{
    struct fr_elements e = {0};
    e.me = me;
    e.ns = ns;
    e.dim = dim;
    e.nc = (size_t)dim * me + (n0 != NULL ? me : 0);
    e.Jt = cholmod_l_transpose(J, 1, &s->cc);
    cholmod_l_free_sparse(&J, &s->cc);
    int status = e.Jt == NULL || !allocate(&e, n0 != NULL)
                     ? fr_fail(s, FRICREG_ENOMEM, "%s: no memory for %zu elements", who, me)
                     : check_rows(s, e.Jt, me, dim, who);
    if (status != FRICREG_OK) {
        struct fr_elements old = s->el;
        s->el = e;
        fr_elements_free(s); /* e's, then the structure's own back */
        s->el = old;
        return status;
    }
    memcpy(e.k, k, me * ns * sizeof *k);
    memcpy(e.phi, phi, me * ns * sizeof *phi);
    for (size_t i = 0; i < me; i++)
        for (size_t j = 0; j < ns; j++)
            for (int a = 0; a < dim; a++)
                e.kstick[i * dim + a] += k[i * ns + j];
    if (n0 != NULL) {
        memcpy(e.n0, n0, me * sizeof *n0);
        memcpy(e.kn, kn, me * sizeof *kn);
        memcpy(e.kstick + (size_t)dim * me, kn, me * sizeof *kn);
    }
    fr_elements_free(s);
    s->el = e;
    fr_structure_changed(s, FR_CHANGED_MODEL); /* E = J_e K_eff^-1 J_e^T and the equilibrium anew */
    fr_structure_rates_stale(s);               /* the rates see the sticking springs */
    return FRICREG_OK;
}

static int start_setter(fricreg_structure *s, size_t me, size_t ns, int dim, size_t ndof,
                        const char *who)
{
    if (s->running)
        return fr_structure_busy(s, who);
    if (ndof != s->n)
        return fr_fail(s, FRICREG_ESIZE, "%s: ndof = %zu, the structure has %zu", who, ndof, s->n);
    if (ns == 0 && me > 0)
        return fr_fail(s, FRICREG_EINVAL, "%s: ns = 0: an Iwan element needs a slider", who);
    if (me > MAX_ELEMENTS / (size_t)dim || (me > 0 && ns > MAX_ELEMENTS / me))
        return fr_fail(s, FRICREG_EINVAL, "%s: me = %zu elements of %zu sliders exceed 2^%d", who,
                       me, ns, dim == 2 ? 25 : 26);
    return FRICREG_OK;
}

static int remove_all(fricreg_structure *s)
{
    fr_elements_free(s);
    fr_structure_changed(s, FR_CHANGED_MODEL);
    fr_structure_rates_stale(s);
    return FRICREG_OK;
}

/* The normal law's n0 finite and kn > 0, finite, and J_n's entries finite. */
static int check_normal(fricreg_structure *s, size_t me, size_t ndof, const double Jn[],
                        const double n0[], const double kn[], const char *who)
{
    if (Jn == NULL || n0 == NULL || kn == NULL)
        return fr_fail(s, FRICREG_ENULL, "%s: %s is NULL", who,
                       Jn == NULL   ? "J_n"
                       : n0 == NULL ? "n0"
                                    : "kn");
    for (size_t i = 0; i < me; i++) {
        if (!isfinite(n0[i]) || !isfinite(kn[i]))
            return fr_fail(s, FRICREG_ENONFINITE,
                           "%s: element %zu's n0 = %g or kn = %g is not finite", who, i, n0[i],
                           kn[i]);
        if (!(kn[i] > 0.0))
            return fr_fail(s, FRICREG_EINVAL, "%s: element %zu needs kn > 0 (kn = %g)", who, i,
                           kn[i]);
    }
    for (size_t j = 0; j < me * ndof; j++)
        if (!isfinite(Jn[j]))
            return fr_fail(s, FRICREG_ENONFINITE, "%s: J_n(%zu, %zu) is not finite", who, j / ndof,
                           j % ndof);
    return FRICREG_OK;
}

/* The dense setters' body; Jn, n0, kn only with a normal law; dim 2: Je has 2 me rows. */
static int set_dense(fricreg_structure *s, size_t me, int dim, size_t ndof, const double Je[],
                     const double Jn[], enum kind kind, size_t ns, const double k[],
                     const double phi[], const double n0[], const double kn[], const char *who)
{
    if (s == NULL)
        return FRICREG_ENULL;
    int status = start_setter(s, me, ns, dim, ndof, who);
    if (status != FRICREG_OK)
        return status;
    if (me == 0)
        return remove_all(s);
    if (Je == NULL)
        return fr_fail(s, FRICREG_ENULL, "%s: J_e is NULL", who);
    if ((status = check_params(s, me, ns, kind, k, phi, who)) != FRICREG_OK)
        return status;
    for (size_t j = 0; j < (size_t)dim * me * ndof; j++)
        if (!isfinite(Je[j]))
            return fr_fail(s, FRICREG_ENONFINITE, "%s: J_e(%zu, %zu) is not finite", who, j / ndof,
                           j % ndof);
    if (normal_law(kind) && (status = check_normal(s, me, ndof, Jn, n0, kn, who)) != FRICREG_OK)
        return status;
    cholmod_sparse *J = NULL;
    if (!normal_law(kind)) {
        status = fr_dense_to_cholmod((size_t)dim * me, ndof, Je, 0, &s->cc, &J, &s->err, who);
        return status != FRICREG_OK ? status : install(s, me, ns, dim, J, k, phi, NULL, NULL, who);
    }
    size_t nt = (size_t)dim * me; /* J_e's rows, then J_n's */
    double *stacked = malloc((nt + me) * ndof * sizeof *stacked);
    if (stacked == NULL)
        return fr_fail(s, FRICREG_ENOMEM, "%s: no memory for %zu elements", who, me);
    memcpy(stacked, Je, nt * ndof * sizeof *stacked);
    memcpy(stacked + nt * ndof, Jn, me * ndof * sizeof *stacked);
    status = fr_dense_to_cholmod(nt + me, ndof, stacked, 0, &s->cc, &J, &s->err, who);
    free(stacked);
    return status != FRICREG_OK ? status : install(s, me, ns, dim, J, k, phi, n0, kn, who);
}

/* The compressed setters' body, as set_dense. */
static int set_csr(fricreg_structure *s, size_t me, int dim, size_t ndof, int flags,
                   const int64_t rowptr[], const int64_t colind[], const double values[],
                   enum kind kind, size_t ns, const double k[], const double phi[], const char *who)
{
    if (s == NULL)
        return FRICREG_ENULL;
    int status = start_setter(s, me, ns, dim, ndof, who);
    if (status != FRICREG_OK)
        return status;
    if (me == 0)
        return remove_all(s);
    if ((status = check_params(s, me, ns, kind, k, phi, who)) != FRICREG_OK)
        return status;
    struct fr_compressed a = {(size_t)dim * me, ndof, 0, flags, rowptr, colind, values};
    cholmod_sparse *J = NULL;
    status = fr_compressed_check(&a, 0, &s->err, who);
    if (status == FRICREG_OK)
        status = fr_compressed_to_cholmod(&a, 0, &s->cc, &J, &s->err, who);
    return status != FRICREG_OK ? status : install(s, me, ns, dim, J, k, phi, NULL, NULL, who);
}

int fr_elements_clone(fricreg_structure *dst, const fricreg_structure *src)
{
    const struct fr_elements *e = &src->el;
    if (e->me == 0)
        return FRICREG_OK;
    cholmod_sparse *J = cholmod_l_transpose(e->Jt, 1, &dst->cc);
    if (J == NULL)
        return fr_fail(dst, FRICREG_ENOMEM, "companion: no memory for %zu elements", e->me);
    return install(dst, e->me, e->ns, e->dim, J, e->k, e->phi, e->n0, e->kn, "companion");
}

int fricreg_structure_set_jenkins(fricreg_structure *s, size_t me, size_t ndof, const double Je[],
                                  const double kt[], const double mun[])
{
    return set_dense(s, me, 1, ndof, Je, NULL, KIND_JENKINS, 1, kt, mun, NULL, NULL, "set_jenkins");
}

int fricreg_structure_set_jenkins_csr(fricreg_structure *s, size_t me, size_t ndof, int flags,
                                      const int64_t rowptr[], const int64_t colind[],
                                      const double values[], const double kt[], const double mun[])
{
    return set_csr(s, me, 1, ndof, flags, rowptr, colind, values, KIND_JENKINS, 1, kt, mun,
                   "set_jenkins_csr");
}

int fricreg_structure_set_jenkins_2d(fricreg_structure *s, size_t me, size_t ndof,
                                     const double Je[], const double kt[], const double mun[])
{
    return set_dense(s, me, 2, ndof, Je, NULL, KIND_JENKINS, 1, kt, mun, NULL, NULL,
                     "set_jenkins_2d");
}

int fricreg_structure_set_jenkins_2d_csr(fricreg_structure *s, size_t me, size_t ndof, int flags,
                                         const int64_t rowptr[], const int64_t colind[],
                                         const double values[], const double kt[],
                                         const double mun[])
{
    return set_csr(s, me, 2, ndof, flags, rowptr, colind, values, KIND_JENKINS, 1, kt, mun,
                   "set_jenkins_2d_csr");
}

int fricreg_structure_set_iwan(fricreg_structure *s, size_t me, size_t ndof, const double Je[],
                               size_t ns, const double k[], const double phi[])
{
    return set_dense(s, me, 1, ndof, Je, NULL, KIND_IWAN, ns, k, phi, NULL, NULL, "set_iwan");
}

int fricreg_structure_set_iwan_csr(fricreg_structure *s, size_t me, size_t ndof, int flags,
                                   const int64_t rowptr[], const int64_t colind[],
                                   const double values[], size_t ns, const double k[],
                                   const double phi[])
{
    return set_csr(s, me, 1, ndof, flags, rowptr, colind, values, KIND_IWAN, ns, k, phi,
                   "set_iwan_csr");
}

int fricreg_structure_set_jenkins_normal(fricreg_structure *s, size_t me, size_t ndof,
                                         const double Je[], const double Jn[], const double kt[],
                                         const double mu[], const double n0[], const double kn[])
{
    return set_dense(s, me, 1, ndof, Je, Jn, KIND_NORMAL, 1, kt, mu, n0, kn, "set_jenkins_normal");
}

int fricreg_structure_set_iwan_normal(fricreg_structure *s, size_t me, size_t ndof,
                                      const double Je[], const double Jn[], size_t ns,
                                      const double k[], const double mu[], const double n0[],
                                      const double kn[])
{
    return set_dense(s, me, 1, ndof, Je, Jn, KIND_IWAN_NORMAL, ns, k, mu, n0, kn,
                     "set_iwan_normal");
}

int fricreg_structure_set_jenkins_2d_normal(fricreg_structure *s, size_t me, size_t ndof,
                                            const double Je[], const double Jn[], const double kt[],
                                            const double mu[], const double n0[], const double kn[])
{
    return set_dense(s, me, 2, ndof, Je, Jn, KIND_NORMAL, 1, kt, mu, n0, kn,
                     "set_jenkins_2d_normal");
}

int fricreg_structure_get_normal_forces(const fricreg_structure *s, size_t me, double N[])
{
    if (s == NULL || N == NULL)
        return FRICREG_ENULL;
    if (me != s->el.me)
        return FRICREG_ESIZE;
    if (me == 0)
        return FRICREG_OK;
    if (s->el.n0 == NULL)
        return FRICREG_EINVAL;
    memcpy(N, s->el.fe + (size_t)s->el.dim * me, me * sizeof *N);
    return FRICREG_OK;
}

int fricreg_structure_get_jenkins_state(const fricreg_structure *s, size_t me, double f[],
                                        double w[], double D[])
{
    if (s == NULL || (f == NULL && w == NULL && D == NULL))
        return FRICREG_ENULL;
    if (me != s->el.me || (w != NULL && me > 0 && s->el.ns != 1))
        return FRICREG_ESIZE;
    if (me > 0 && s->el.dim == 2 && (f != NULL || w != NULL))
        return FRICREG_EINVAL; /* f and w of 2 me: get_jenkins_2d_state */
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

int fricreg_structure_get_jenkins_2d_state(const fricreg_structure *s, size_t me, double f[],
                                           double w[], double D[])
{
    if (s == NULL || (f == NULL && w == NULL && D == NULL))
        return FRICREG_ENULL;
    if (me != s->el.me)
        return FRICREG_ESIZE;
    if (me == 0)
        return FRICREG_OK;
    if (s->el.dim != 2)
        return FRICREG_EINVAL; /* 1-D elements: get_jenkins_state, get_iwan_state */
    if (f != NULL)
        memcpy(f, s->el.fe, 2 * me * sizeof *f);
    if (w != NULL)
        memcpy(w, s->el.wc, 2 * me * sizeof *w);
    if (D != NULL)
        memcpy(D, s->el.dissipation, me * sizeof *D);
    return FRICREG_OK;
}

int fricreg_structure_get_iwan_state(const fricreg_structure *s, size_t me, size_t ns, double f[],
                                     double w[], double D[])
{
    if (s == NULL || (f == NULL && w == NULL && D == NULL))
        return FRICREG_ENULL;
    if (me != s->el.me || (me > 0 && ns != s->el.ns))
        return FRICREG_ESIZE;
    if (me > 0 && s->el.dim == 2)
        return FRICREG_EINVAL; /* 2-D Jenkins elements: get_jenkins_2d_state */
    if (me == 0)
        return FRICREG_OK;
    if (f != NULL)
        memcpy(f, s->el.fe, me * sizeof *f);
    if (w != NULL)
        memcpy(w, s->el.wc, me * ns * sizeof *w);
    if (D != NULL)
        memcpy(D, s->el.dissipation, me * sizeof *D);
    return FRICREG_OK;
}

int fr_elements_joint(const fricreg_structure *s)
{
    if (s->el.me == 0)
        return 0;
    for (size_t i = 0; i < s->m; i++)
        if (s->mun[i] != 0.0)
            return 1;
    return 0;
}

/* Element i at q (and, with a normal law, at the normal displacement gn): its sliders' forces
 * into fs1 and trial positions into wt from the committed wc, separated sliders following q
 * (fricreg_jenkins_trial_normal's lift-off); returns their sum, the sticking sliders' stiffness
 * into *tan and dfe/dg into *tang where not NULL. */
static double element(const struct fr_elements *e, size_t i, double q, double gn, double *tan,
                      double *tang)
{
    double F = 0.0, t = 0.0, tg = 0.0, N = 1.0, dbdg = 0.0;
    if (e->n0 != NULL) {
        N = e->n0[i] + e->kn[i] * gn;
        dbdg = e->kn[i];
    }
    for (size_t j = i * e->ns; j < (i + 1) * e->ns; j++) {
        double tj, gj;
        if (N < 0.0)
            fr_slider_separated(1, &q, &e->fs1[j], &e->wt[j], &tj, &gj);
        else
            fr_slider_return(e->k[j], e->phi[j] * N, e->phi[j] * dbdg, 1, &q, &e->wc[j], &e->fs1[j],
                             &e->wt[j], &tj, &gj);
        F += e->fs1[j];
        t += tj;
        tg += gj;
    }
    if (tan != NULL)
        *tan = t;
    if (tang != NULL)
        *tang = tg;
    return F;
}

/* 2-D element i at q[2] (and, with a normal law, at the normal displacement gn): its force
 * into fs1[2i..] and x[2] (x may be NULL), the trial slider into wt (following q where
 * separated), and, with tan (NULL: none), the 2x2 block's diagonal into tan[0..1], its
 * off-diagonal into tang[0..1] and, with a normal law, dfe/dg into tagn[0..1]. */
static void element_2d(const struct fr_elements *e, size_t i, const double q[2], double gn,
                       double x[2], double *tan, double *tang, double *tagn)
{
    double t[4], b = e->phi[i], dbdg = 0.0, N = 1.0;
    if (e->n0 != NULL) { /* the 3-D contact: bound mu max(0, n0 + kn g), phi holding mu */
        N = e->n0[i] + e->kn[i] * gn;
        b = e->phi[i] * fmax(0.0, N);
        dbdg = e->phi[i] * e->kn[i];
    }
    if (N < 0.0)
        fr_slider_separated(2, q, &e->fs1[2 * i], &e->wt[2 * i], tan != NULL ? t : NULL, tagn);
    else
        fr_slider_return(e->k[i], b, dbdg, 2, q, &e->wc[2 * i], &e->fs1[2 * i], &e->wt[2 * i],
                         tan != NULL ? t : NULL, tagn);
    if (x != NULL) {
        x[0] = e->fs1[2 * i];
        x[1] = e->fs1[2 * i + 1];
    }
    if (tan != NULL) {
        tan[0] = t[0];
        tan[1] = t[3];
        tang[0] = t[1];
        tang[1] = t[2];
    }
}

/* The forces x[nc] at the coordinates y[nc] from the committed wc (the sliders' trial state as
 * element's): the elements', then the normal forces max(0, n0 + kn g). */
static void map(const struct fr_elements *e, const double y[], double x[])
{
    size_t me = e->me, nt = (size_t)e->dim * me;
    for (size_t i = 0; i < me && e->dim == 2; i++)
        element_2d(e, i, y + 2 * i, e->n0 != NULL ? y[nt + i] : 0.0, x + 2 * i, NULL, NULL, NULL);
    for (size_t i = 0; i < me && e->dim == 1; i++)
        x[i] = element(e, i, y[i], e->n0 != NULL ? y[me + i] : 0.0, NULL, NULL);
    for (size_t i = 0; i < e->nc - nt; i++)
        x[nt + i] = fmax(0.0, e->n0[i] + e->kn[i] * y[nt + i]);
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
                   i, what, sum, t, s->el.ns);
}

/* map, then FRICREG_ENONFINITE if an element's force x[i] overflowed. */
static int map_checked(fricreg_structure *s, const double y[], double x[], double t)
{
    const struct fr_elements *e = &s->el;
    map(e, y, x);
    for (size_t i = 0; i < e->nc; i++)
        if (!isfinite(x[i]))
            return overflowed(s, i < e->dim * e->me ? i / (size_t)e->dim : i - e->dim * e->me,
                              "force", x[i], t);
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
    size_t bytes = e->me * e->ns * (size_t)e->dim * sizeof(double); /* idempotent: sticks */
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

double fr_elements_residual(struct fr_elements *e, const double f[], double g[], double *rinf)
{
    size_t me = e->me, nc = e->nc, nt = (size_t)e->dim * me;
    struct fr_sumsq sum = {0.0, 0.0};
    double big = 0.0;
    for (size_t i = 0; i < me && e->dim == 2; i++) {
        double x[2], gn = e->n0 != NULL ? e->y[nt + i] : 0.0;
        element_2d(e, i, e->y + 2 * i, gn, x, &e->tan[2 * i], &e->tang[2 * i],
                   e->tagn != NULL ? &e->tagn[2 * i] : NULL);
        g[2 * i] = f[2 * i] - x[0];
        g[2 * i + 1] = f[2 * i + 1] - x[1];
    }
    e->overflow = 0;
    for (size_t i = 0; i < me && e->dim == 1; i++) {
        double gn = e->n0 != NULL ? e->y[me + i] : 0.0, tg = 0.0;
        double x = element(e, i, e->y[i], gn, &e->tan[i], &tg);
        if (e->n0 != NULL)
            e->tang[i] = tg;
        const char *what = !isfinite(x)           ? "force"
                           : !isfinite(e->tan[i]) ? "tangent"
                           : !isfinite(tg)        ? "df/dg"
                                                  : NULL;
        if (what != NULL && e->overflow == 0) {
            e->overflow = i + 1;
            e->overflow_what = what;
            e->overflow_sum = !isfinite(x) ? x : !isfinite(e->tan[i]) ? e->tan[i] : tg;
        }
        g[i] = f[i] - x;
    }
    for (size_t i = 0; i < (e->n0 != NULL ? me : 0); i++) {
        double N = e->n0[i] + e->kn[i] * e->y[nt + i];
        e->tan[nt + i] = N > 0.0 ? e->kn[i] : 0.0;
        g[nt + i] = f[nt + i] - fmax(0.0, N);
    }
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

/* df = -(I + c T E)^-1 g, T = diag(tan) plus tang's entries (row i, column
 * fr_elements_partner: dfe/dg with a normal law, a 2-D element's block), by GSL's QR with column pivoting (its LU allocates in GSL 2.7: a step must not);
 * 0 if the matrix is singular. */
static int direction(struct fr_elements *e, double c)
{
    size_t nc = e->nc;
    for (size_t i = 0; i < nc; i++) {
        size_t p = fr_elements_partner(e, i), pn = fr_elements_normal_column(e, i);
        for (size_t j = 0; j < nc; j++)
            e->A[i * nc + j] = c * e->tan[i] * e->E[i * nc + j];
        if (p < nc)
            for (size_t j = 0; j < nc; j++)
                e->A[i * nc + j] += c * e->tang[i] * e->E[p * nc + j];
        if (pn < nc)
            for (size_t j = 0; j < nc; j++)
                e->A[i * nc + j] += c * e->tagn[i] * e->E[pn * nc + j];
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
    size_t me = e->me, nt = (size_t)e->dim * me;
    for (size_t i = 0; i < me; i++) {
        double bound = 0.0;
        for (size_t j = i * e->ns; j < (i + 1) * e->ns; j++)
            bound += e->phi[j];
        if (e->n0 != NULL) { /* the normal law's range N >= 0, then the bound mu N */
            if (f[nt + i] < 0.0)
                f[nt + i] = 0.0;
            bound *= f[nt + i];
        }
        if (e->dim == 1 && fabs(f[i]) > bound)
            f[i] = copysign(bound, f[i]);
        double r = e->dim == 2 ? hypot(f[2 * i], f[2 * i + 1]) : 0.0;
        if (r > bound) { /* radially onto the disk, as the slider's return */
            f[2 * i] *= bound / r;
            f[2 * i + 1] *= bound / r;
        }
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

void fr_elements_commit(fricreg_structure *s)
{
    struct fr_elements *e = &s->el;
    if (e->me == 0)
        return; /* no arrays: memcpy may not take NULL */
    e->crossed = 0;
    for (size_t i = e->me * (size_t)e->dim; i < e->nc && e->n0 != NULL; i++)
        e->crossed |= (e->fe[i] > 0.0) != (e->fe1[i] > 0.0);
    memcpy(e->fe, e->fe1, e->nc * sizeof *e->fe);
    size_t slots = e->me * e->ns * (size_t)e->dim;
    memcpy(e->fs, e->fs1, slots * sizeof *e->fs);
    memcpy(e->wc, e->wt, slots * sizeof *e->wc);
}

void fr_elements_hold(fricreg_structure *s, int restore)
{
    struct fr_elements *e = &s->el;
    size_t bytes = e->nc * sizeof(double), sbytes = e->me * e->ns * (size_t)e->dim * sizeof(double);
    if (e->me == 0)
        return;
    memcpy(restore ? e->fe : e->fe_held, restore ? e->fe_held : e->fe, bytes);
    memcpy(restore ? e->fs : e->fs_held, restore ? e->fs_held : e->fs, sbytes);
    memcpy(restore ? e->wc : e->wc_held, restore ? e->wc_held : e->wc, sbytes);
}

void fr_elements_reset(fricreg_structure *s)
{
    struct fr_elements *e = &s->el;
    if (e->me == 0)
        return;
    memset(e->wc, 0, e->me * e->ns * (size_t)e->dim * sizeof *e->wc);
    memset(e->fs, 0, e->me * e->ns * (size_t)e->dim * sizeof *e->fs);
    memset(e->fe, 0, e->nc * sizeof *e->fe);
}

double fr_elements_strain(const fricreg_structure *s)
{
    const struct fr_elements *e = &s->el;
    double energy = 0.0;
    for (size_t j = 0; j < e->me * e->ns * (size_t)e->dim; j++) /* 2-D: |f|^2/(2 kt) */
        energy += 0.5 * e->fs[j] * (e->fs[j] / e->k[j / (size_t)e->dim]);
    size_t nt = e->me * (size_t)e->dim;
    for (size_t i = 0; i < (e->n0 != NULL ? e->me : 0); i++) /* the normal springs: N^2/(2 kn) */
        energy += 0.5 * e->fe[nt + i] * (e->fe[nt + i] / e->kn[i]);
    return energy;
}
