/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fit_hb.c — `fricreg-sim fit --model hb` (fit_hb.h): the HB model's options, read into a
 * harmonic-balance driver as `nma` reads them (hb_model.h), and made the fit's model. The
 * command line counts from 1; its checks here name the option and the --param in those
 * numbers, so that the library's messages (which count from 0) are left for what only it
 * can judge. */
#include <ctype.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fit_hb.h"

const struct cli_word cli_fit_dampings[] = {{"matrix", FRICREG_HB_NMA_DAMPING_MATRIX},
                                            {"modal", FRICREG_HB_NMA_DAMPING_MODAL},
                                            {NULL, 0}};
const struct cli_word cli_fit_backbones[] = {{"epmc", 0}, {"qsma", 1}, {NULL, 0}};

void cli_fit_hb_defaults(struct cli_fit_hb_options *o)
{
    /* Newton's tolerance tighter than the driver's 1e-10: the fit's Jacobian is the points'
     * exact sensitivities, and a loose point leaves its noise in them (docs/identification.md,
     * "Limits"). */
    *o = (struct cli_fit_hb_options){.harmonics = 7,
                                     .mode = 1,
                                     .linear_damping = FRICREG_HB_NMA_DAMPING_MATRIX,
                                     .dof = 1,
                                     .newton_tol = 1e-12,
                                     .newton_max = 50};
    cli_hb_model_defaults(&o->model);
}

/* A whole number from 1 at *p, digits only, below 1e9; *p moved past it. 1 if read, else 0. */
static int read_whole(const char **p, size_t *value)
{
    if (!isdigit((unsigned char)**p))
        return 0;
    char *end = NULL;
    errno = 0;
    unsigned long long v = strtoull(*p, &end, 10);
    *p = end;
    *value = (size_t)v;
    return errno == 0 && v >= 1 && v < 1000000000ULL;
}

/* "FIRST:COUNT:INDEX" at text into the three numbers: 1 if read whole, else 0. */
static int read_range(const char *text, size_t v[3])
{
    const char *p = text;
    for (int k = 0; k < 3; k++) {
        if (!read_whole(&p, &v[k]))
            return 0;
        if (*p != (k < 2 ? ':' : '\0'))
            return 0;
        p += k < 2;
    }
    return 1;
}

/* 1 if parameters a and b of o move one value (element ranges overlapping at one index, or
 * one Rayleigh coefficient), as the library refuses them. */
static int same_value(const struct cli_fit_hb_options *o, size_t a, size_t b)
{
    if (o->kind[a] != o->kind[b] || o->index[a] != o->index[b])
        return 0;
    if (o->kind[a] == FRICREG_HB_NMA_PARAM_DAMPING)
        return 1;
    return o->first[a] < o->first[b] + o->count[b] && o->first[b] < o->first[a] + o->count[a];
}

int cli_fit_parse_param(const struct cli_option *row, const char *text)
{
    struct cli_fit_hb_options *o = row->slot;
    char what[CLI_FIT_NAME + 160];
    if (o->np == CLI_FIT_MAX_PARAMS) {
        snprintf(what, sizeof what, "at most %d parameters", CLI_FIT_MAX_PARAMS);
        return cli_usage_error(row->name, what);
    }
    size_t j = o->np, v[3];
    if (strcmp(text, "damping:1") == 0 || strcmp(text, "damping:2") == 0) {
        o->kind[j] = FRICREG_HB_NMA_PARAM_DAMPING;
        o->first[j] = o->count[j] = 0; /* the library ignores them for damping */
        o->index[j] = (size_t)(text[8] - '0');
    } else if (strncmp(text, "element:", 8) == 0 && read_range(text + 8, v)) {
        o->kind[j] = FRICREG_HB_NMA_PARAM_ELEMENT;
        o->first[j] = v[0] - 1;
        o->count[j] = v[1];
        o->index[j] = v[2] - 1;
    } else {
        return cli_usage_error(row->name, "expected element:FIRST:COUNT:INDEX (whole numbers "
                                          "from 1) or damping:1 (Rayleigh's a0) or damping:2 "
                                          "(a1)");
    }
    if (o->kind[j] == FRICREG_HB_NMA_PARAM_DAMPING)
        snprintf(o->name[j], CLI_FIT_NAME, "%s", text);
    else
        snprintf(o->name[j], CLI_FIT_NAME, "element:%zu:%zu:%zu", v[0], v[1], v[2]);
    for (size_t b = 0; b < j; b++)
        if (same_value(o, b, j)) {
            snprintf(what, sizeof what,
                     "%s moves the value of parameter %zu (%s) again: give each value once",
                     o->name[j], b + 1, o->name[b]);
            return cli_usage_error(row->name, what);
        }
    o->np++;
    return 0;
}

/* The HB model's options, each with whether it was given, for the modal Iwan model's refusal. */
static const char *given_option(const struct cli_fit_hb_options *o)
{
    const struct cli_hb_model_options *m = &o->model;
    const struct cli_element_files *e = &m->elements;
    const struct {
        int given;
        const char *name;
    } rows[] = {{m->mass != NULL, "--mass"},
                {m->stiffness != NULL, "--stiffness"},
                {m->damping != NULL, "--damping"},
                {m->rayleigh_given, "--rayleigh"},
                {m->element_sets.n > 0, "--elements"},
                {e->rows != NULL, "--jenkins"},
                {e->rows_2d != NULL, "--jenkins-2d"},
                {e->jenkins != NULL, "--jenkins-params"},
                {e->iwan != NULL, "--iwan-params"},
                {e->segalman != NULL, "--iwan-segalman"},
                {e->sliders_given, "--iwan-sliders"},
                {e->resolution_given, "--iwan-resolution"},
                {e->normal != NULL, "--normal"},
                {e->normal_params != NULL, "--normal-params"},
                {e->iwan_normal != NULL, "--iwan-normal-params"},
                {o->np > 0, "--param"},
                {o->mode_given, "--mode"},
                {o->harmonics_given, "--harmonics"},
                {o->damping_given, "--linear-damping"},
                {o->dof_given, "--dof"},
                {o->tol_given, "--newton-tol"},
                {o->max_given, "--newton-max"},
                {o->backbone_given, "--backbone"}};
    for (size_t k = 0; k < sizeof rows / sizeof rows[0]; k++)
        if (rows[k].given)
            return rows[k].name;
    return NULL;
}

int cli_fit_hb_check(const struct cli_fit_hb_options *o, int hb)
{
    if (!hb) {
        const char *name = given_option(o);
        return name == NULL ? 0 : cli_usage_error(name, "only with --model hb");
    }
    int status = cli_hb_check_model(&o->model);
    if (status != 0)
        return status;
    if (o->np == 0)
        return cli_usage_error("--param", "missing (--model hb fits the parameters it names)");
    if (o->backbone == 1 && (o->dof_given || o->damping_given))
        return cli_usage_error(o->dof_given ? "--dof" : "--linear-damping",
                               "not with --backbone qsma (its levels are modal, its damping the "
                               "linear mode's)");
    return 0;
}

/* The model's sizes against the options: the mode, the dof and each --param's elements within
 * the model's. 0, or CLI_EXIT_USAGE (printed). */
static int check_sizes(const struct cli_fit_hb_options *o, const struct cli_hb_model *md)
{
    char what[CLI_FIT_NAME + 160];
    if ((size_t)o->mode > md->n)
        return cli_usage_error("--mode", "beyond the structure's modes (one per dof)");
    if (o->dof_given && (size_t)o->dof > md->n) {
        snprintf(what, sizeof what, "dof %d beyond the structure's %zu", o->dof, md->n);
        return cli_usage_error("--dof", what);
    }
    for (size_t j = 0; j < o->np; j++)
        if (o->kind[j] == FRICREG_HB_NMA_PARAM_ELEMENT &&
            (o->first[j] >= md->m || o->count[j] > md->m - o->first[j])) {
            snprintf(what, sizeof what, "%s: elements %zu to %zu, but the model has %zu",
                     o->name[j], o->first[j] + 1, o->first[j] + o->count[j], md->m);
            return cli_usage_error("--param", what);
        }
    return 0;
}

/* Each element --param's place within its elements' layouts, and one value over its range (the
 * library's refusals, said here from 1). 0, or CLI_EXIT_USAGE (printed). */
static int check_values(const struct cli_fit_hb_options *o, fricreg_hb *hb)
{
    char what[CLI_FIT_NAME + 200];
    for (size_t j = 0; j < o->np; j++) {
        size_t first = o->first[j];
        double v0 = 0.0, v = 0.0;
        for (size_t e = first;
             o->kind[j] == FRICREG_HB_NMA_PARAM_ELEMENT && e < first + o->count[j]; e++) {
            if (fricreg_hb_get_element_param(hb, e, o->index[j], &v) != FRICREG_OK) {
                snprintf(what, sizeof what, "%s: element %zu has no parameter %zu", o->name[j],
                         e + 1, o->index[j] + 1);
                return cli_usage_error("--param", what);
            }
            if (e > first && v != v0) {
                snprintf(what, sizeof what,
                         "%s: element %zu's value %g differs from element %zu's %g (a "
                         "parameter is one value over its elements)",
                         o->name[j], e + 1, v, first + 1, v0);
                return cli_usage_error("--param", what);
            }
            v0 = v;
        }
    }
    return 0;
}

/* The driver as the fit's model, by its backbone's route. */
static int set_model(fricreg_fit *fit, const struct cli_fit_hb_options *o, fricreg_hb *hb)
{
    size_t mode = (size_t)o->mode - 1;
    if (o->backbone == 1)
        return fricreg_fit_set_model_qsma(fit, hb, mode, o->np, o->kind, o->first, o->count,
                                          o->index);
    return fricreg_fit_set_model_hb(fit, hb, mode, o->linear_damping, o->np, o->kind, o->first,
                                    o->count, o->index);
}

int cli_fit_hb_set_up(fricreg_fit *fit, const struct cli_fit_hb_options *o, struct cli_fit_hb *h)
{
    int status = cli_hb_read_model(&o->model, &h->md);
    if (status == 0)
        status = check_sizes(o, &h->md);
    if (status == 0)
        status = cli_hb_create("fit", &h->md, o->harmonics, &h->hb);
    if (status == 0)
        status = cli_hb_set_model(&o->model, &h->md, h->hb);
    if (status == 0 && fricreg_hb_set_newton(h->hb, o->newton_tol, o->newton_max) != FRICREG_OK)
        status = cli_usage_error("--newton-tol", fricreg_hb_errmsg(h->hb));
    if (status == 0)
        status = check_values(o, h->hb);
    if (status == 0 && set_model(fit, o, h->hb) != FRICREG_OK)
        status = cli_usage_error("--param", fricreg_fit_errmsg(fit));
    if (status == 0 && o->dof_given &&
        fricreg_fit_set_sensor_dof(fit, h->md.n, o->harmonics, (size_t)o->dof - 1) != FRICREG_OK)
        status = cli_usage_error("--dof", fricreg_fit_errmsg(fit));
    return status;
}

void cli_fit_hb_free(struct cli_fit_hb *h)
{
    fricreg_hb_free(h->hb);
    cli_hb_free_model(&h->md);
    h->hb = NULL;
}
