/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb_model.c — the structure and its elements for `fricreg-sim hb` and `nma` (hb_model.h). */
#include <stdio.h>
#include <string.h>

#include "cli_input.h"
#include "element_table.h"
#include "input_line.h"
#include "hb_model.h"

int cli_hb_parse_rayleigh(const struct cli_option *row, const char *text)
{
    struct cli_hb_model_options *o = row->slot;
    return cli_parse_rayleigh(row->name, text, &o->a0, &o->a1);
}

void cli_hb_model_defaults(struct cli_hb_model_options *o)
{
    *o = (struct cli_hb_model_options){0};
    cli_element_defaults(&o->elements);
}

int cli_hb_check_model(const struct cli_hb_model_options *o)
{
    if (o->mass == NULL)
        return cli_usage_error("--mass", "missing (a file is required)");
    if (o->stiffness == NULL)
        return cli_usage_error("--stiffness", "missing (a file is required)");
    if (cli_check_element_sets_alone(&o->element_sets, &o->elements) != 0)
        return CLI_EXIT_USAGE;
    if (o->elements.rows_2d != NULL && o->elements.normal == NULL) /* 2-D: the 3-D contact only */
        return cli_usage_error("--jenkins-2d",
                               "harmonic balance has 2-D elements with a normal law "
                               "only (--normal with --normal-params: the 3-D "
                               "contact); fricreg-sim structure takes the others");
    int status = cli_check_elements(&o->elements, o->element_sets.n == 0);
    if (status != 0)
        return status;
    if (o->damping != NULL && o->rayleigh_given)
        return cli_usage_error("--rayleigh", "give --damping or --rayleigh, not both");
    return 0;
}

void cli_hb_free_model(struct cli_hb_model *md)
{
    cli_free_elements(&md->el);
    cli_free_element_sets(&md->sets);
    cli_sparse_free(&md->M);
    cli_sparse_free(&md->K);
    cli_sparse_free(&md->C);
    memset(md, 0, sizeof *md);
}

int cli_hb_read_model(const struct cli_hb_model_options *o, struct cli_hb_model *md)
{
    int status = cli_read_mtx("--mass", o->mass, 0, 0, &md->M);
    size_t n = md->M.rows;
    if (status == 0 && n != md->M.cols)
        status = cli_file_error("--mass", o->mass, 0, "%zu x %zu: not square", n, md->M.cols);
    const struct cli_mtx_size mass = {"--mass", o->mass, &md->M}; /* n's file */
    if (status == 0)
        status = cli_read_mtx_sized("--stiffness", o->stiffness, n, n, &mass, &md->K);
    if (status == 0 && o->damping != NULL)
        status = cli_read_mtx_sized("--damping", o->damping, n, n, &mass, &md->C);
    if (status == 0)
        status = cli_read_elements(&o->elements, n, &md->el);
    if (status == 0)
        status = cli_read_element_sets(&o->element_sets, n, &md->sets);
    md->n = n;
    md->m = md->el.m + md->sets.me; /* one of them 0 */
    return status;
}

/* One refused setter: its option and file, and the library's reason. */
static int refused(const fricreg_hb *hb, const char *option, const char *path)
{
    return cli_file_error(option, path, 0, "%s", fricreg_hb_errmsg(hb));
}

/* A matrix file's flags for the _csc setters: zero-based, whole or its lower triangle. */
/* M, K or C (which) by its columns, the lower triangle of symmetric storage as such: a status. */
static int set_square(fricreg_hb *hb, int which, size_t n, const struct cli_sparse *A)
{
    int format = FRICREG_MATRIX_CSC | (A->lower ? FRICREG_SPARSE_LOWER : 0);
    return fricreg_hb_set_matrix(hb, which, n, n, format, A->colptr, A->rowind, A->values);
}

/* One element set into the driver (cli_element_set_adder): NULL, or the library's reason,
 * which decides the types harmonic balance takes. */
static const char *add_set(void *model, const struct cli_element_set *e, size_t n)
{
    fricreg_hb *hb = model;
    return fricreg_hb_add_elements(hb, e->type, e->me, n, e->J, e->params) == FRICREG_OK
               ? NULL
               : fricreg_hb_errmsg(hb);
}

int cli_hb_create(const char *cmd, const struct cli_hb_model *md, int harmonics, fricreg_hb **hb)
{
    int status = fricreg_hb_create(md->n, md->m, harmonics, hb);
    if (status == FRICREG_OK)
        return 0;
    char what[200];
    if (status == FRICREG_EINVAL)
        snprintf(what, sizeof what,
                 "%zu elements in all, %zu dofs, H = %d: harmonic balance takes at least one "
                 "element, up to 2^24 dofs (fricreg_hb_create)",
                 md->m, md->n, harmonics);
    else
        snprintf(what, sizeof what, "cannot create the harmonic-balance driver (%s)",
                 fricreg_strerror(status));
    return cli_usage_error(cmd, what);
}

int cli_hb_set_model(const struct cli_hb_model_options *o, const struct cli_hb_model *md,
                     fricreg_hb *hb)
{
    size_t n = md->n;
    const struct cli_sparse *M = &md->M, *K = &md->K, *C = &md->C;
    if (set_square(hb, FRICREG_MASS, n, M) != FRICREG_OK)
        return refused(hb, "--mass", o->mass);
    if (set_square(hb, FRICREG_STIFFNESS, n, K) != FRICREG_OK)
        return refused(hb, "--stiffness", o->stiffness);
    if (C->colptr != NULL && set_square(hb, FRICREG_DAMPING, n, C) != FRICREG_OK)
        return refused(hb, "--damping", o->damping);
    if (o->rayleigh_given && fricreg_hb_set_rayleigh(hb, o->a0, o->a1) != FRICREG_OK)
        return cli_usage_error("--rayleigh", fricreg_hb_errmsg(hb));
    if (md->sets.n > 0)
        return cli_add_element_sets(hb, add_set, n, &md->sets);
    return cli_add_elements(hb, add_set, n, &md->el);
}

size_t cli_hb_rows(const struct cli_hb_model *md)
{
    if (md->sets.n > 0)
        return md->sets.nforces;
    if (md->el.kind == CLI_ELEMENTS_CONTACT_3D)
        return 3 * md->m;
    int normal = md->el.kind == CLI_ELEMENTS_NORMAL || md->el.kind == CLI_ELEMENTS_IWAN_NORMAL;
    return normal ? 2 * md->m : md->m;
}

void cli_hb_json_elements(FILE *out, const struct cli_hb_model *md)
{
    if (md->sets.n > 0) {
        cli_json_element_sets(out, &md->sets);
        return;
    }
    fprintf(out, ", \"element_kind\": \"%s\"", cli_element_kind_name(&md->el));
    if (md->el.kind == CLI_ELEMENTS_IWAN || md->el.kind == CLI_ELEMENTS_IWAN_NORMAL)
        fprintf(out, ", \"sliders_per_element\": %zu", md->el.ns);
}
