/* SPDX-License-Identifier: GPL-3.0-or-later */
/* checkpoint_fingerprint.c — what a checkpoint's structure and the one restored into must share
 * (checkpoint.c): sizes and kinds, the scheme and the law with their parameters one by one (a
 * mismatch is named), the matrices and the excitation hashed by FNV-1a. */
#include <string.h>

#include "checkpoint_fingerprint.h"
#include "ctx/ctx_driver.h"
#include "joint/element_kind.h"

uint64_t fr_fnv1a(uint64_t h, const void *bytes, size_t len)
{
    const unsigned char *b = bytes;
    for (size_t k = 0; k < len; k++)
        h = (h ^ b[k]) * 0x100000001b3ull;
    return h;
}

static uint64_t hash_sparse(uint64_t h, const cholmod_sparse *A)
{
    if (A == NULL)
        return fr_fnv1a(h, "-", 1);
    const SuiteSparse_long *Ap = A->p;
    size_t nnz = (size_t)Ap[A->ncol];
    h = fr_fnv1a(h, &A->nrow, sizeof A->nrow);
    h = fr_fnv1a(h, &A->ncol, sizeof A->ncol);
    h = fr_fnv1a(h, A->p, (A->ncol + 1) * sizeof(SuiteSparse_long));
    h = fr_fnv1a(h, A->i, nnz * sizeof(SuiteSparse_long));
    return fr_fnv1a(h, A->x, nnz * sizeof(double));
}

static uint64_t hash_record(uint64_t h, const struct fr_record *rec)
{
    h = fr_fnv1a(h, &rec->n, sizeof rec->n);
    h = fr_fnv1a(h, &rec->t0, sizeof rec->t0);
    h = fr_fnv1a(h, &rec->dt, sizeof rec->dt);
    return rec->n > 0 ? fr_fnv1a(h, rec->x, rec->n * sizeof *rec->x) : h;
}

/* The names of the entries: */
static const char *const count_names[] = {"ndof",
                                          "contacts",
                                          "elements",
                                          "sliders per element",
                                          "element coordinates",
                                          "element dimension",
                                          "elements with a normal law"};
static const char *const flag_names[] = {
    "J set",           "Rayleigh damping",  "scheme",
    "friction law",    "Newton's max_iter", "error estimate (on + 4 x companions)",
    "unguarded steps", "contact solver"};
static const char *const param_names[] = {"alpha",       "beta",           "gamma",
                                          "eps",         "Newton's tol",   "Rayleigh a0",
                                          "Rayleigh a1", "tolerance scale"};
/* The tables and the struct agree (a negative size where they do not). */
typedef char counts_agree[sizeof count_names / sizeof *count_names == NCOUNTS ? 1 : -1];
typedef char flags_agree[sizeof flag_names / sizeof *flag_names == NFLAGS ? 1 : -1];
typedef char params_agree[sizeof param_names / sizeof *param_names == NPARAMS ? 1 : -1];

/* The elements' types (name and sliders, in order) and parameters (a checkpoint is for the
 * same library version: nothing older to match). */
static uint64_t hash_elements(uint64_t h, const struct fr_elements *e)
{
    for (size_t i = 0; i < e->me; i++) {
        const char *name = fricreg_element_name(e->type[i]);
        uint64_t ns = e->type[i]->ns;
        h = fr_fnv1a(fr_fnv1a(h, name, strlen(name)), &ns, sizeof ns);
    }
    return fr_fnv1a(h, e->params, e->par[e->me] * sizeof *e->params);
}

void fr_fingerprint_of(const fricreg_structure *s, struct fingerprint *fp)
{
    const struct fr_elements *e = &s->el;
    memset(fp, 0, sizeof *fp);
    uint64_t counts[NCOUNTS] = {s->n, s->m, e->me, e->ns, e->nc, (uint64_t)e->dim, e->nnormal > 0};
    int32_t flags[NFLAGS] = {s->contacts_set, s->rayleigh,
                             s->scheme,       fr_ctx_law(s->ctx),
                             s->newton_max,   s->estimate_on | s->companions << 2,
                             s->unguarded,    s->contact_solver}; /* on: 0 .. 2, companions above */
    double params[NPARAMS] = {s->alpha,      s->beta, s->gamma, fr_ctx_eps(s->ctx),
                              s->newton_tol, s->a0,   s->a1,    s->tol_scale};
    memcpy(fp->count, counts, sizeof counts);
    memcpy(fp->flag, flags, sizeof flags);
    memcpy(fp->param, params, sizeof params);
    uint64_t h = FNV_START;
    h = hash_sparse(h, s->M);
    h = hash_sparse(h, s->K);
    h = hash_sparse(h, s->C);
    h = hash_sparse(h, s->Jt);
    h = fr_fnv1a(h, s->r->data, s->n * sizeof(double));
    h = fr_fnv1a(h, s->p->data, s->n * sizeof(double));
    if (e->me > 0)
        h = hash_elements(hash_sparse(h, e->Jt), e);
    fp->model = h;
    h = hash_record(FNV_START, &s->ground);
    h = hash_record(h, &s->load);
    h = fr_fnv1a(h, s->mun, s->m * sizeof *s->mun);
    size_t ode_n = s->ode_atol != NULL ? 2 * s->n + 2 + s->m : 0;
    h = fr_fnv1a(h, &ode_n, sizeof ode_n);
    fp->excitation = ode_n > 0 ? fr_fnv1a(h, s->ode_atol, ode_n * sizeof *s->ode_atol) : h;
}

/* FRICREG_OK, or FRICREG_EINVAL naming the first difference (recorded). */
int fr_fingerprint_compare(fricreg_structure *s, const struct fingerprint *blob)
{
    struct fingerprint own;
    fr_fingerprint_of(s, &own);
    for (size_t k = 0; k < NCOUNTS; k++)
        if (blob->count[k] != own.count[k])
            return fr_fail(s, FRICREG_EINVAL,
                           "restore: the checkpoint's structure has %s = %llu, this one %llu",
                           count_names[k], (unsigned long long)blob->count[k],
                           (unsigned long long)own.count[k]);
    for (size_t k = 0; k < NFLAGS; k++)
        if (blob->flag[k] != own.flag[k])
            return fr_fail(s, FRICREG_EINVAL,
                           "restore: the checkpoint's %s is %d, this structure's %d", flag_names[k],
                           (int)blob->flag[k], (int)own.flag[k]);
    for (size_t k = 0; k < NPARAMS; k++)
        if (memcmp(&blob->param[k], &own.param[k], sizeof(double)) != 0)
            return fr_fail(s, FRICREG_EINVAL,
                           "restore: the checkpoint's %s = %.17g, this structure's %.17g",
                           param_names[k], blob->param[k], own.param[k]);
    if (blob->model != own.model)
        return fr_fail(s, FRICREG_EINVAL,
                       "restore: the model (M, K, C, J, r, the load pattern or the elements' "
                       "matrices and parameters) is not the checkpoint's");
    if (blob->excitation != own.excitation)
        return fr_fail(s, FRICREG_EINVAL,
                       "restore: the ground or load record, the bounds mun or the run_ode "
                       "tolerances set are not the checkpoint's");
    return FRICREG_OK;
}
