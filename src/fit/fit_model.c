/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fit_model.c — which model a fit fits (fricreg_fit.h): the modal Iwan's closed forms, or a
 * harmonic-balance driver's nonlinear mode (or its quasi-static modal analysis) with the
 * caller's parameters (the driver's element
 * values and Rayleigh's coefficients), and where its levels' amplitudes are measured. Each
 * setter checks every input before it changes anything. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "hb_model.h"
#include "params.h"

#define DEFAULT_STARTS 32
#define HB_STARTS 1 /* each start of an HB model costs a backbone march per iteration */

void fr_fit_hb_free(struct fr_fit_hb *m)
{
    free(m);
}

void fr_fit_use_modal_iwan(fricreg_fit *fit)
{
    fr_fit_hb_free(fit->hb);
    fit->hb = NULL;
    fit->model = &fr_fit_modal_iwan_model;
    fit->np = FR_FIT_NP;
    fit->nstarts = DEFAULT_STARTS;
    for (int j = 0; j < FR_FIT_NP; j++)
        fit->par[j] = (struct fr_fit_param){1, NAN, fr_fit_param_floor(j), INFINITY};
    fit->have_fit = 0;
}

int fricreg_fit_set_model_modal_iwan(fricreg_fit *fit)
{
    if (fit == NULL)
        return FRICREG_ENULL;
    fr_fit_use_modal_iwan(fit);
    return FRICREG_OK;
}

/* Element parameter j's range: within the elements, index in each one's layout, one value that
 * all of them share (its value into *value), else the status (recorded). */
static int check_element(fricreg_fit *fit, const char *fn, fricreg_hb *hb, size_t j, size_t first,
                         size_t count, size_t index, double *value)
{
    size_t held = fricreg_hb_element_count(hb);
    if (count == 0 || first >= held || count > held - first)
        return fr_fail(fit, FRICREG_EINVAL,
                       "%s: parameter %zu's elements %zu..%zu+%zu-1 are not within the "
                       "driver's %zu",
                       fn, j, first, first, count, held);
    for (size_t e = first; e < first + count; e++) {
        double v;
        if (fricreg_hb_get_element_param(hb, e, index, &v) != FRICREG_OK)
            return fr_fail(fit, FRICREG_EINVAL, "%s: parameter %zu: %s", fn, j,
                           fricreg_hb_errmsg(hb));
        if (e > first && v != *value)
            return fr_fail(fit, FRICREG_EINVAL,
                           "%s: parameter %zu: element %zu's value %g differs from "
                           "element %zu's %g: a shared parameter needs one value "
                           "(fricreg_hb_set_element_param)",
                           fn, j, e, v, first, *value);
        *value = v;
    }
    return FRICREG_OK;
}

/* 1 if parameters a and b move the same value (one element range overlapping the other's with
 * the same index, or the same damping coefficient). */
static int same_value(const int kind[], const size_t first[], const size_t count[],
                      const size_t index[], size_t a, size_t b)
{
    if (kind[a] != kind[b] || index[a] != index[b])
        return 0;
    if (kind[a] == FRICREG_HB_NMA_PARAM_DAMPING)
        return 1;
    return first[a] < first[b] + count[b] && first[b] < first[a] + count[a];
}

/* Parameter j's description checked (its value, an element's, into *value; NaN for damping),
 * else the status (recorded). */
static int check_param(fricreg_fit *fit, const char *fn, fricreg_hb *hb, size_t j, const int kind[],
                       const size_t first[], const size_t count[], const size_t index[],
                       double *value)
{
    *value = NAN;
    for (size_t b = 0; b < j; b++)
        if (same_value(kind, first, count, index, b, j))
            return fr_fail(fit, FRICREG_EINVAL, "%s: parameters %zu and %zu move the same value",
                           fn, b, j);
    if (kind[j] == FRICREG_HB_NMA_PARAM_ELEMENT)
        return check_element(fit, fn, hb, j, first[j], count[j], index[j], value);
    if (kind[j] != FRICREG_HB_NMA_PARAM_DAMPING)
        return fr_fail(fit, FRICREG_EINVAL, "%s: parameter %zu's kind %d is not ELEMENT or DAMPING",
                       fn, j, kind[j]);
    if (index[j] == 0)
        return fr_fail(fit, FRICREG_EINVAL,
                       "%s: parameter %zu: the modal damping ratio zeta_k has no "
                       "setter on the driver; fit Rayleigh's a0 (DAMPING index 1) with "
                       "FRICREG_HB_NMA_DAMPING_MODAL and a1 = 0 instead (xi_k = a0)",
                       fn, j);
    if (index[j] > 2)
        return fr_fail(fit, FRICREG_EINVAL,
                       "%s: parameter %zu: DAMPING index %zu is not 1 (a0) or 2 (a1)", fn, j,
                       index[j]);
    return FRICREG_OK;
}

/* The checked description into a new model (NULL out of memory). */
static struct fr_fit_hb *describe(fricreg_hb *hb, size_t mode, int damping, size_t np,
                                  const int kind[], const size_t first[], const size_t count[],
                                  const size_t index[], const double value[])
{
    struct fr_fit_hb *m = calloc(1, sizeof *m);
    if (m == NULL)
        return NULL;
    *m = (struct fr_fit_hb){.hb = hb, .mode = mode, .damping = damping};
    for (size_t j = 0; j < np; j++) {
        m->kind[j] = kind[j];
        m->first[j] = first[j];
        m->count[j] = count[j];
        m->index[j] = index[j];
        m->value0[j] = value[j];
        if (kind[j] == FRICREG_HB_NMA_PARAM_DAMPING)
            snprintf(m->names[j], FR_FIT_NAME, "Rayleigh %s", index[j] == 1 ? "a0" : "a1");
        else
            snprintf(m->names[j], FR_FIT_NAME, "p%zu (elements %zu..%zu, index %zu)", j, first[j],
                     first[j] + count[j] - 1, index[j]);
    }
    m->kind[np] = FRICREG_HB_NMA_PARAM_AMPLITUDE;
    return m;
}

/* An HB driver's model, EPMC's or QSMA's, with its parameters checked first. */
static int set_model(fricreg_fit *fit, const char *fn, const struct fr_fit_model *model,
                     fricreg_hb *hb, size_t mode, int damping, size_t np, const int kind[],
                     const size_t first[], const size_t count[], const size_t index[])
{
    if (kind == NULL || first == NULL || count == NULL || index == NULL)
        return fr_fail(fit, FRICREG_ENULL, "%s: kind, first, count or index is NULL", fn);
    if (np == 0 || np > FR_FIT_MAXP)
        return fr_fail(fit, FRICREG_EINVAL, "%s: np = %zu parameters, not 1..%d", fn, np,
                       FR_FIT_MAXP);
    if (damping != FRICREG_HB_NMA_DAMPING_MATRIX && damping != FRICREG_HB_NMA_DAMPING_MODAL)
        return fr_fail(fit, FRICREG_EINVAL, "%s: unknown damping %d", fn, damping);
    double value[FR_FIT_MAXP];
    for (size_t j = 0; j < np; j++) {
        int st = check_param(fit, fn, hb, j, kind, first, count, index, &value[j]);
        if (st != FRICREG_OK)
            return st;
    }
    struct fr_fit_hb *m = describe(hb, mode, damping, np, kind, first, count, index, value);
    if (m == NULL)
        return fr_fail(fit, FRICREG_ENOMEM, "%s: out of memory", fn);
    fr_fit_hb_free(fit->hb);
    fit->hb = m;
    fit->model = model;
    fit->np = np;
    fit->nstarts = HB_STARTS;
    for (size_t j = 0; j < np; j++)
        fit->par[j] = (struct fr_fit_param){1, NAN, 0.0, INFINITY};
    fit->have_fit = 0;
    return FRICREG_OK;
}

int fricreg_fit_set_model_hb(fricreg_fit *fit, fricreg_hb *hb, size_t mode, int damping, size_t np,
                             const int kind[], const size_t first[], const size_t count[],
                             const size_t index[])
{
    if (fit == NULL)
        return FRICREG_ENULL;
    if (hb == NULL)
        return fricreg_fit_set_model_modal_iwan(fit);
    return set_model(fit, "set_model_hb", &fr_fit_hb_model, hb, mode, damping, np, kind, first,
                     count, index);
}

int fricreg_fit_set_model_qsma(fricreg_fit *fit, fricreg_hb *hb, size_t mode, size_t np,
                               const int kind[], const size_t first[], const size_t count[],
                               const size_t index[])
{
    if (fit == NULL)
        return FRICREG_ENULL;
    if (hb == NULL)
        return fricreg_fit_set_model_modal_iwan(fit);
    return set_model(fit, "set_model_qsma", &fr_fit_qsma_model, hb, mode,
                     FRICREG_HB_NMA_DAMPING_MODAL, np, kind, first, count, index);
}

int fricreg_fit_set_sensor_dof(fricreg_fit *fit, size_t ndof, int harmonics, size_t dof)
{
    if (fit == NULL)
        return FRICREG_ENULL;
    if (fit->hb == NULL)
        return fr_fail(fit, FRICREG_EINVAL,
                       "set_sensor_dof: the modal Iwan model has no dofs (fricreg_fit_set_sensor "
                       "sets its mode shape's value)");
    if (fit->model == &fr_fit_qsma_model)
        return fr_fail(fit, FRICREG_EINVAL,
                       "set_sensor_dof: the QSMA model's levels are modal (fricreg_fit_set_sensor "
                       "sets the mode shape's value at the sensor)");
    if (harmonics < 1)
        return fr_fail(fit, FRICREG_EINVAL, "set_sensor_dof: harmonics = %d, not >= 1", harmonics);
    if (dof >= ndof)
        return fr_fail(fit, FRICREG_EINVAL, "set_sensor_dof: dof %zu is not below ndof = %zu", dof,
                       ndof);
    fit->hb->has_dof = 1;
    fit->hb->dof = dof;
    fit->hb->ndof = ndof;
    fit->hb->nc = 2 * (size_t)harmonics + 1;
    fit->have_fit = 0;
    return FRICREG_OK;
}
