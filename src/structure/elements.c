/* SPDX-License-Identifier: GPL-3.0-or-later */
/* elements.c — a structure's friction elements, of any types of fricreg_element.h together:
 * their storage, fricreg_structure_add_elements, _clear_elements, _get_elements, and what a
 * step does to their state around its Newton (element_step.c): commit, hold, reset, the
 * strain energy.
 *
 * Element i of type T sees the dim components u_i = J_i u (its rows of J) and pushes back with
 * the kernel's force f_i(u_i; state) (fricreg_element_eval), so the structure gets -J^T fe. The
 * coordinates are laid out tangential first, normal after (structure_internal.h), which is
 * 1.x's layout for a set of one type: its answers are those of the per-kind setters (jenkins.c)
 * bit for bit. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/matrix_input.h"
#include "joint/element_kind.h"
#include "structure_internal.h"

#define MAX_ELEMENTS ((size_t)1 << 26)

static int has_normal(const fricreg_element_type *type)
{
    return type->kind->normal;
}

static int tangential(const fricreg_element_type *type)
{
    return type->kind->dim - type->kind->normal;
}

void fr_elements_gather(const struct fr_elements *e, size_t i, const double x[], double out[])
{
    int td = tangential(e->type[i]);
    for (int a = 0; a < td; a++)
        out[a] = x[e->at[i] + (size_t)a];
    if (e->normal[i] < e->nc)
        out[td] = x[e->normal[i]];
}

void fr_elements_scatter(const struct fr_elements *e, size_t i, const double in[], double x[])
{
    int td = tangential(e->type[i]);
    for (int a = 0; a < td; a++)
        x[e->at[i] + (size_t)a] = in[a];
    if (e->normal[i] < e->nc)
        x[e->normal[i]] = in[td];
}

void fr_elements_free(fricreg_structure *s)
{
    struct fr_elements *e = &s->el;
    double *arrays[] = {e->params, e->kstick, e->wc,      e->wt,      e->fs,      e->fs1,
                        e->fe,     e->fe1,    e->wc_held, e->fs_held, e->fe_held, e->dissipation,
                        e->q0,     e->y,      e->fy,      e->g,       e->df,      e->ft,
                        e->gt,     e->tb,     e->E,       e->A,       e->tau,     e->norm};
    for (size_t k = 0; k < sizeof arrays / sizeof *arrays; k++)
        free(arrays[k]);
    size_t *indices[] = {e->at, e->normal, e->par, e->slot, e->blk, e->owner, e->perm};
    for (size_t k = 0; k < sizeof indices / sizeof *indices; k++)
        free(indices[k]);
    free((void *)e->type);
    fr_joint_free(&e->joint);
    cholmod_l_free_sparse(&e->Jt, &s->cc);
    *e = (struct fr_elements){0};
}

/* The layout of the elements of types[me] into e (e->me set, the index arrays allocated):
 * their coordinates, offsets and the summary fields. */
static void lay_out(struct fr_elements *e, const fricreg_element_type *const types[])
{
    size_t me = e->me, nt = 0, nnormal = 0;
    e->par[0] = e->slot[0] = e->blk[0] = 0;
    e->ns = types[0]->ns;
    e->dim = tangential(types[0]);
    for (size_t i = 0; i < me; i++) {
        const fricreg_element_type *T = types[i];
        size_t td = (size_t)tangential(T), dim = (size_t)T->kind->dim;
        e->type[i] = T;
        e->at[i] = nt;
        nt += td;
        nnormal += (size_t)has_normal(T);
        e->par[i + 1] = e->par[i] + T->kind->nparams(T->ns);
        e->slot[i + 1] = e->slot[i] + T->kind->nstate(T->ns);
        e->blk[i + 1] = e->blk[i] + dim * dim;
        if (T->ns != e->ns)
            e->ns = 0;
        if ((int)td != e->dim)
            e->dim = 0;
    }
    e->nt = nt;
    e->nnormal = nnormal;
    e->nc = nt + nnormal;
    e->nslots = e->slot[me];
    for (size_t i = 0, next = nt; i < me; i++) {
        for (size_t a = 0; a < (size_t)tangential(types[i]); a++)
            e->owner[e->at[i] + a] = i;
        e->normal[i] = has_normal(types[i]) ? next++ : e->nc;
        if (e->normal[i] < e->nc)
            e->owner[e->normal[i]] = i;
    }
}

/* The arrays of me elements of types[] into e (zeroed; e->me set); 0 when out of memory (e then
 * partly filled: the caller frees it). */
static int allocate(struct fr_elements *e, const fricreg_element_type *const types[])
{
    size_t me = e->me;
    e->type = calloc(me, sizeof *e->type);
    size_t **per_element[] = {&e->at, &e->normal}, **offsets[] = {&e->par, &e->slot, &e->blk};
    for (size_t k = 0; k < 2; k++)
        if ((*per_element[k] = calloc(me, sizeof(size_t))) == NULL)
            return 0;
    for (size_t k = 0; k < 3; k++)
        if ((*offsets[k] = calloc(me + 1, sizeof(size_t))) == NULL)
            return 0;
    size_t nc = 0;
    for (size_t i = 0; i < me; i++)
        nc += (size_t)types[i]->kind->dim;
    if (e->type == NULL || (e->owner = calloc(nc, sizeof *e->owner)) == NULL)
        return 0;
    lay_out(e, types);
    double **slots[] = {&e->wc, &e->wt, &e->fs, &e->fs1, &e->wc_held, &e->fs_held};
    double **coordinates[] = {&e->kstick, &e->fe, &e->fe1, &e->fe_held, &e->q0,  &e->y,   &e->fy,
                              &e->g,      &e->df, &e->ft,  &e->gt,      &e->tau, &e->norm};
    for (size_t k = 0; k < sizeof slots / sizeof *slots; k++) /* none for a law without state */
        if ((*slots[k] = calloc(e->nslots > 0 ? e->nslots : 1, sizeof(double))) == NULL)
            return 0;
    for (size_t k = 0; k < sizeof coordinates / sizeof *coordinates; k++)
        if ((*coordinates[k] = calloc(nc, sizeof(double))) == NULL)
            return 0;
    e->params = calloc(e->par[me], sizeof(double));
    e->tb = calloc(e->blk[me], sizeof(double));
    e->dissipation = calloc(me, sizeof(double));
    e->E = calloc(nc * nc, sizeof(double));
    e->A = calloc(nc * nc, sizeof(double));
    e->perm = calloc(nc, sizeof *e->perm);
    return e->params != NULL && e->tb != NULL && e->dissipation != NULL && e->E != NULL &&
           e->A != NULL && e->perm != NULL;
}

/* The stiffness of each coordinate with every element elastic (its type's). */
static void stick_stiffness(struct fr_elements *e)
{
    for (size_t i = 0; i < e->me; i++) {
        const fricreg_element_type *T = e->type[i];
        double k[3];
        T->kind->elastic(T, e->params + e->par[i], k);
        for (int a = 0; a < tangential(T); a++)
            e->kstick[e->at[i] + (size_t)a] = k[a];
        if (e->normal[i] < e->nc)
            e->kstick[e->normal[i]] = k[tangential(T)];
    }
}

int fr_elements_install(fricreg_structure *s, size_t me, const fricreg_element_type *const types[],
                        const double params[], cholmod_sparse *Jt, const char *who)
{
    struct fr_elements e = {0};
    e.me = me;
    e.Jt = Jt;
    if (!allocate(&e, types)) {
        struct fr_elements old = s->el;
        s->el = e;
        fr_elements_free(s); /* e's (Jt with it), then the structure's own back */
        s->el = old;
        return fr_fail(s, FRICREG_ENOMEM, "%s: no memory for %zu elements", who, me);
    }
    memcpy(e.params, params, e.par[me] * sizeof *params);
    stick_stiffness(&e);
    fr_elements_free(s);
    s->el = e;
    fr_structure_changed(s, FR_CHANGED_MODEL); /* E = J_e K_eff^-1 J_e^T and the equilibrium anew */
    fr_structure_rates_stale(s);               /* the rates see the sticking springs */
    return FRICREG_OK;
}

int fr_elements_clone(fricreg_structure *dst, const fricreg_structure *src)
{
    const struct fr_elements *e = &src->el;
    if (e->me == 0)
        return FRICREG_OK;
    cholmod_sparse *Jt = cholmod_l_copy_sparse(e->Jt, &dst->cc);
    if (Jt == NULL)
        return fr_fail(dst, FRICREG_ENOMEM, "companion: no memory for %zu elements", e->me);
    return fr_elements_install(dst, e->me, e->type, e->params, Jt, "companion");
}

/* ---- fricreg_structure_add_elements ----------------------------------------------------- */

/* Every parameter set valid for the type (fricreg_element_explain's message), every row of J
 * finite and nonzero (an element that does not move is a mistake). */
static int check_new(fricreg_structure *s, const fricreg_element_type *type, size_t me, size_t ndof,
                     const double J[], const double params[])
{
    static const char who[] = "add_elements";
    size_t dim = (size_t)type->kind->dim, np = type->kind->nparams(type->ns);
    for (size_t i = 0; i < me; i++) {
        char msg[200];
        int status = fricreg_element_explain(type, params + i * np, NULL, NULL, msg, sizeof msg);
        if (status != FRICREG_OK)
            return fr_fail(s, status, "%s: element %zu: %s", who, i, msg);
    }
    for (size_t r = 0; r < me * dim; r++) {
        int moves = 0;
        for (size_t c = 0; c < ndof; c++) {
            double x = J[r * ndof + c];
            if (!isfinite(x))
                return fr_fail(s, FRICREG_ENONFINITE, "%s: J(%zu, %zu) = %g is not finite", who, r,
                               c, x);
            moves |= x != 0.0;
        }
        if (!moves)
            return fr_fail(s, FRICREG_EINVAL,
                           "%s: row %zu of J is zero: element %zu does not move along its "
                           "component %zu",
                           who, r, r / dim, r % dim);
    }
    return FRICREG_OK;
}

/* Column j of the merged J^T: column src[j] of the held J^T (from_new[j] = 0) or of the new
 * ones' (1). */
struct column_map {
    const size_t *src;
    const unsigned char *from_new;
};

/* The columns of held (NULL: none) and added picked by map into a new n x nc matrix; NULL when
 * out of memory. */
static cholmod_sparse *pick_columns(const cholmod_sparse *held, const cholmod_sparse *added,
                                    size_t nc, struct column_map map, cholmod_common *cc)
{
    size_t nnz = (held != NULL ? cholmod_l_nnz((cholmod_sparse *)held, cc) : 0) +
                 cholmod_l_nnz((cholmod_sparse *)added, cc);
    cholmod_sparse *out = cholmod_l_allocate_sparse(added->nrow, nc, nnz, 1, 1, 0, CHOLMOD_REAL,
                                                    cc);
    if (out == NULL)
        return NULL;
    SuiteSparse_long *op = out->p, *oi = out->i, k = 0;
    double *ox = out->x;
    for (size_t j = 0; j < nc; j++) {
        const cholmod_sparse *A = map.from_new[j] ? added : held;
        const SuiteSparse_long *p = A->p, *ri = A->i;
        const double *x = A->x;
        op[j] = k;
        for (SuiteSparse_long q = p[map.src[j]]; q < p[map.src[j] + 1]; q++, k++) {
            oi[k] = ri[q];
            ox[k] = x[q];
        }
    }
    op[nc] = k;
    return out;
}

/* The merged J^T (n x nc) of the held elements and me new ones of type on the rows J: the held
 * tangential columns, the new tangential rows, the held normal columns, the new normal rows.
 * FRICREG_OK, or the conversion's status (recorded). */
static int merged_columns(fricreg_structure *s, const fricreg_element_type *type, size_t me,
                          const double J[], cholmod_sparse **out)
{
    const struct fr_elements *e = &s->el;
    size_t dim = (size_t)type->kind->dim, td = (size_t)tangential(type);
    size_t nc = e->nc + me * dim;
    cholmod_sparse *rows = NULL, *added = NULL;
    int status = fr_dense_to_cholmod(me * dim, s->n, J, 0, &s->cc, &rows, &s->err, "add_elements");
    if (status != FRICREG_OK)
        return status;
    added = cholmod_l_transpose(rows, 1, &s->cc);
    cholmod_l_free_sparse(&rows, &s->cc);
    size_t *src = malloc(nc * sizeof *src);
    unsigned char *from_new = malloc(nc);
    *out = NULL;
    if (added != NULL && src != NULL && from_new != NULL) {
        size_t j = 0;
        for (size_t c = 0; c < e->nt; c++, j++)
            src[j] = c, from_new[j] = 0;
        for (size_t i = 0; i < me; i++)
            for (size_t a = 0; a < td; a++, j++)
                src[j] = i * dim + a, from_new[j] = 1;
        for (size_t c = e->nt; c < e->nc; c++, j++)
            src[j] = c, from_new[j] = 0;
        for (size_t i = 0; i < me && td < dim; i++, j++)
            src[j] = i * dim + td, from_new[j] = 1;
        *out = pick_columns(e->me > 0 ? e->Jt : NULL, added, nc, (struct column_map){src, from_new},
                            &s->cc);
    }
    free(src);
    free(from_new);
    cholmod_l_free_sparse(&added, &s->cc);
    return *out != NULL
               ? FRICREG_OK
               : fr_fail(s, FRICREG_ENOMEM, "add_elements: no memory for %zu elements", e->me + me);
}

/* The held elements' types and parameters followed by me of type with params, into types[]
 * and all[] (allocated; NULL both when out of memory). */
static void merged_params(const struct fr_elements *e, const fricreg_element_type *type, size_t me,
                          const double params[], const fricreg_element_type ***types, double **all)
{
    size_t np = type->kind->nparams(type->ns), held = e->me > 0 ? e->par[e->me] : 0;
    *types = malloc((e->me + me) * sizeof **types);
    *all = malloc((held + me * np) * sizeof **all);
    if (*types == NULL || *all == NULL) {
        free((void *)*types);
        free(*all);
        *types = NULL;
        *all = NULL;
        return;
    }
    for (size_t i = 0; i < e->me; i++)
        (*types)[i] = e->type[i];
    for (size_t i = 0; i < me; i++)
        (*types)[e->me + i] = type;
    if (held > 0)
        memcpy(*all, e->params, held * sizeof **all);
    memcpy(*all + held, params, me * np * sizeof **all);
}

int fricreg_structure_add_elements(fricreg_structure *s, const fricreg_element_type *type,
                                   size_t me, size_t ndof, const double J[], const double params[])
{
    static const char who[] = "add_elements";
    if (s == NULL || s->running)
        return fr_structure_refuse(s, who);
    if (type == NULL || (me > 0 && (J == NULL || params == NULL)))
        return fr_fail(s, FRICREG_ENULL, "%s: %s is NULL", who,
                       type == NULL ? "type"
                       : J == NULL  ? "J"
                                    : "params");
    if (ndof != s->n)
        return fr_fail(s, FRICREG_ESIZE, "%s: ndof = %zu, the structure has %zu", who, ndof, s->n);
    if (me == 0)
        return FRICREG_OK;
    if (me > MAX_ELEMENTS / 4 || s->el.me > MAX_ELEMENTS / 4 - me)
        return fr_fail(s, FRICREG_EINVAL, "%s: %zu elements and the %zu held exceed 2^24", who, me,
                       s->el.me);
    int status = check_new(s, type, me, ndof, J, params);
    cholmod_sparse *Jt = NULL;
    if (status != FRICREG_OK || (status = merged_columns(s, type, me, J, &Jt)) != FRICREG_OK)
        return status;
    const fricreg_element_type **types;
    double *all;
    merged_params(&s->el, type, me, params, &types, &all);
    if (types == NULL) {
        cholmod_l_free_sparse(&Jt, &s->cc);
        return fr_fail(s, FRICREG_ENOMEM, "%s: no memory for %zu elements", who, s->el.me + me);
    }
    status = fr_elements_install(s, s->el.me + me, types, all, Jt, who);
    free((void *)types);
    free(all);
    return status;
}

int fricreg_structure_clear_elements(fricreg_structure *s)
{
    if (s == NULL || s->running)
        return fr_structure_refuse(s, "clear_elements");
    fr_elements_free(s);
    fr_structure_changed(s, FR_CHANGED_MODEL);
    fr_structure_rates_stale(s);
    return FRICREG_OK;
}

size_t fricreg_structure_element_count(const fricreg_structure *s)
{
    return s != NULL ? s->el.me : 0;
}

int fricreg_structure_get_elements(const fricreg_structure *s, size_t me, double f[],
                                   double state[], double D[])
{
    if (s == NULL || (f == NULL && state == NULL && D == NULL))
        return FRICREG_ENULL;
    const struct fr_elements *e = &s->el;
    if (me != e->me)
        return FRICREG_ESIZE;
    for (size_t i = 0, k = 0; i < me && f != NULL; k += (size_t)e->type[i]->kind->dim, i++)
        fr_elements_gather(e, i, e->fe, f + k);
    if (state != NULL && me > 0)
        memcpy(state, e->wc, e->nslots * sizeof *state);
    if (D != NULL && me > 0)
        memcpy(D, e->dissipation, me * sizeof *D);
    return FRICREG_OK;
}

/* ---- Around a step ------------------------------------------------------------------------ */

void fr_elements_commit(fricreg_structure *s)
{
    struct fr_elements *e = &s->el;
    if (e->me == 0)
        return; /* no arrays: memcpy may not take NULL */
    e->crossed = 0;
    for (size_t i = e->nt; i < e->nc; i++)
        e->crossed |= (e->fe[i] > 0.0) != (e->fe1[i] > 0.0);
    memcpy(e->fe, e->fe1, e->nc * sizeof *e->fe);
    memcpy(e->fs, e->fs1, e->nslots * sizeof *e->fs);
    memcpy(e->wc, e->wt, e->nslots * sizeof *e->wc);
}

void fr_elements_hold(fricreg_structure *s, int restore)
{
    struct fr_elements *e = &s->el;
    size_t bytes = e->nc * sizeof(double), sbytes = e->nslots * sizeof(double);
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
    memset(e->wc, 0, e->nslots * sizeof *e->wc);
    memset(e->fs, 0, e->nslots * sizeof *e->fs);
    memset(e->fe, 0, e->nc * sizeof *e->fe);
}

/* The springs' energy, by the types: every element's tangential springs, then every normal
 * spring (1.x's order). */
double fr_elements_strain(const fricreg_structure *s)
{
    const struct fr_elements *e = &s->el;
    double energy = 0.0, f[3];
    for (int normal = 0; normal < 2; normal++)
        for (size_t i = 0; i < e->me; i++) {
            const fricreg_element_type *T = e->type[i];
            fr_elements_gather(e, i, e->fe, f);
            energy = T->kind->stored(T, e->params + e->par[i], e->fs + e->slot[i], f, normal,
                                     energy);
        }
    return energy;
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
