/* SPDX-License-Identifier: GPL-3.0-or-later */
/* jenkins.c — the per-kind element setters and getters of 1.x (fricreg_structure_set_jenkins,
 * _2d, _iwan, _normal, _2d_normal, their _csr twins, get_*_state): each checks its arrays as it
 * always has and installs elements of one type of fricreg_element.h (elements.c), in place of
 * those the structure held, so that their answers are the types' bit for bit.
 *
 * Element i sees q_i = (J_e u)_i and pushes back with fe_i = sum_s k_s (q_i - w_s),
 * |k_s (q_i - w_s)| <= phi_s: "jenkins" (one slider, k = kt, phi = mun) or "iwan" (ns). With a
 * normal law (set_jenkins_normal, set_iwan_normal: "jenkins_normal", "iwan_normal") element i
 * also has a row of J_n, g_i = (J_n u)_i, N_i = max(0, n0_i + kn_i g_i), each slider's bound
 * phi N (phi holding mu). 2-D elements (set_jenkins_2d: "jenkins_2d") have two rows of J_e each
 * and one slider returned radially onto its disk; 3-D contact elements (set_jenkins_2d_normal:
 * "contact_3d") are those with the normal law. The coordinates are J_e's rows, then J_n's. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/matrix_input.h"
#include "structure_internal.h"

#define MAX_ELEMENTS ((size_t)1 << 26)

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

/* The type of a setter's elements: dim tangential components, ns sliders, a normal law or
 * not. */
static const fricreg_element_type *setter_type(int dim, size_t ns, int normal)
{
    if (dim == 2)
        return fricreg_element_lookup(normal ? "contact_3d" : "jenkins_2d");
    if (ns == 1)
        return fricreg_element_lookup(normal ? "jenkins_normal" : "jenkins");
    return fricreg_element_sliders(fricreg_element_lookup(normal ? "iwan_normal" : "iwan"), ns);
}

/* The per-element parameters in the type's layout: k[ns], phi[ns], then kn, n0 and no gap. */
static void setter_params(size_t me, size_t ns, const double k[], const double phi[],
                          const double n0[], const double kn[], double params[])
{
    size_t np = 2 * ns + (n0 != NULL ? 3 : 0);
    for (size_t i = 0; i < me; i++) {
        double *p = params + i * np;
        memcpy(p, k + i * ns, ns * sizeof *p);
        memcpy(p + ns, phi + i * ns, ns * sizeof *p);
        if (n0 != NULL) {
            p[2 * ns] = kn[i];
            p[2 * ns + 1] = n0[i];
            p[2 * ns + 2] = 0.0;
        }
    }
}

/* Takes J (nc x n: J_e, then J_n with a normal law n0, kn (else NULL); J_e of 2 me rows for
 * dim 2; CHOLMOD's, freed here on every path) and installs the elements of ns sliders each. */
static int install(fricreg_structure *s, size_t me, size_t ns, int dim, cholmod_sparse *J,
                   const double k[], const double phi[], const double n0[], const double kn[],
                   const char *who)
{
    cholmod_sparse *Jt = cholmod_l_transpose(J, 1, &s->cc);
    cholmod_l_free_sparse(&J, &s->cc);
    if (Jt == NULL)
        return fr_fail(s, FRICREG_ENOMEM, "%s: no memory for %zu elements", who, me);
    int status = check_rows(s, Jt, me, dim, who);
    const fricreg_element_type *type = setter_type(dim, ns, n0 != NULL);
    size_t np = 2 * ns + (n0 != NULL ? 3 : 0);
    const fricreg_element_type **types = NULL;
    double *params = NULL;
    if (status == FRICREG_OK) {
        types = malloc(me * sizeof *types);
        params = malloc(me * np * sizeof *params);
        if (types == NULL || params == NULL)
            status = fr_fail(s, FRICREG_ENOMEM, "%s: no memory for %zu elements", who, me);
    }
    if (status != FRICREG_OK) {
        cholmod_l_free_sparse(&Jt, &s->cc);
    } else {
        for (size_t i = 0; i < me; i++)
            types[i] = type;
        setter_params(me, ns, k, phi, n0, kn, params);
        status = fr_elements_install(s, me, types, params, Jt, who);
    }
    free((void *)types);
    free(params);
    return status;
}

static int start_setter(fricreg_structure *s, size_t me, size_t ns, int dim, size_t ndof,
                        const char *who)
{
    if (s->running)
        return fr_structure_refuse(s, who);
    if (ndof != s->n)
        return fr_fail(s, FRICREG_ESIZE, "%s: ndof = %zu, the structure has %zu", who, ndof, s->n);
    if (ns == 0 && me > 0)
        return fr_fail(s, FRICREG_EINVAL, "%s: ns = 0: an Iwan element needs a slider", who);
    if (ns > FRICREG_ELEMENT_MAX_SLIDERS && me > 0)
        return fr_fail(s, FRICREG_EINVAL, "%s: ns = %zu sliders exceed the element types' %d", who,
                       ns, FRICREG_ELEMENT_MAX_SLIDERS);
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
    if (s->el.nnormal != me)
        return FRICREG_EINVAL; /* some element has no normal law */
    memcpy(N, s->el.fe + s->el.nt, me * sizeof *N);
    return FRICREG_OK;
}

int fricreg_structure_get_jenkins_state(const fricreg_structure *s, size_t me, double f[],
                                        double w[], double D[])
{
    if (s == NULL || (f == NULL && w == NULL && D == NULL))
        return FRICREG_ENULL;
    if (me != s->el.me || (w != NULL && me > 0 && s->el.ns != 1))
        return FRICREG_ESIZE;
    if (me > 0 && s->el.dim != 1 && (f != NULL || w != NULL))
        return FRICREG_EINVAL; /* f and w of 2 me: get_jenkins_2d_state; a mix: get_elements */
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
    if (s->el.dim != 2 || s->el.ns != 1)
        return FRICREG_EINVAL; /* 1-D elements: get_jenkins_state, get_iwan_state; a mix:
                                  get_elements */
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
    if (me > 0 && s->el.dim != 1)
        return FRICREG_EINVAL; /* 2-D Jenkins elements: get_jenkins_2d_state; a mix:
                                  get_elements */
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
