/* SPDX-License-Identifier: GPL-3.0-or-later */
/* structure_steps.c — the steps of `fricreg-sim structure`'s run to --t-end (structure_steps.h):
 * the structure's own schemes in one call, its observer writing a CSV row per step (every
 * K-th), or GSL's steppers from sample to sample within --max-steps over the whole run. */
#include <math.h>

#include "structure_steps.h"

size_t cli_structure_shown(const struct structure_run *run, size_t k)
{
    return run->dof != NULL ? run->dof[k] : k;
}

/* The k-th contact shown in the trajectory: the selection's, or k itself. */
static size_t contact_shown(const struct structure_run *run, size_t k)
{
    return run->contact != NULL ? run->contact[k] : k;
}

void cli_structure_csv_header(const struct structure_run *run)
{
    FILE *out = run->rows;
    fputs("t", out);
    for (size_t k = 0; k < run->ndof; k++)
        fprintf(out, ",u%zu", cli_structure_shown(run, k) + 1);
    for (size_t k = 0; k < run->ndof; k++)
        fprintf(out, ",v%zu", cli_structure_shown(run, k) + 1);
    for (size_t k = 0; k < run->ncontact; k++)
        fprintf(out, ",f%zu", contact_shown(run, k) + 1);
    cli_element_columns_header(&run->elements, out);
    fputc('\n', out);
}

/* Whether the state at t gets a row: the first, the last, and every K-th step time k dt
 * (k = t / dt rounded: a run's steps end on k dt, the last one on t_end; GSL's samples too). */
static int row_due(const struct structure_run *run, double t)
{
    if (run->every <= 1 || run->rows_written == 0 || !(t < run->t_end))
        return 1;
    return (int64_t)floor(t / run->dt + 0.5) % run->every == 0;
}

/* A CSV row of the state (t, u and v at the dofs shown, f[m], the elements' columns). */
static void csv_row(struct structure_run *run, double t, const double u[], const double v[],
                    const double f[])
{
    FILE *out = run->rows;
    fprintf(out, "%.17g", t);
    for (size_t k = 0; k < run->ndof; k++)
        fprintf(out, ",%.17g", u[cli_structure_shown(run, k)]);
    for (size_t k = 0; k < run->ndof; k++)
        fprintf(out, ",%.17g", v[cli_structure_shown(run, k)]);
    for (size_t k = 0; k < run->ncontact; k++)
        fprintf(out, ",%.17g", f[contact_shown(run, k)]);
    cli_element_columns_row(&run->elements, run->s, out);
    fputc('\n', out);
    run->rows_written++;
}

/* A row of the current state, after a call of GSL's steppers (and at the start). */
static void observe(const fricreg_structure *s, const struct structure_input *in,
                    struct structure_run *run)
{
    if (run->rows == NULL)
        return; /* the peaks are the library's (fricreg_structure_get_peak_displacement) */
    double t = 0.0;
    fricreg_structure_get_value(s, FRICREG_SVALUE_TIME, &t);
    if (!row_due(run, t))
        return;
    fricreg_structure_get_state(s, in->n, run->u, run->v, NULL);
    fricreg_structure_get_forces(s, in->mlib, run->f);
    csv_row(run, t, run->u, run->v, run->f);
}

/* The observer of fricreg_structure_run: a row per step (every K-th). */
static int observe_step(void *user, double t, size_t n, const double u[], const double v[],
                        size_t m, const double f[])
{
    (void)n;
    (void)m;
    struct structure_run *run = user;
    if (row_due(run, t))
        csv_row(run, t, u, v, f);
    return 0;
}

double cli_structure_value(const fricreg_structure *s, int which)
{
    double v = 0.0;
    fricreg_structure_get_value(s, which, &v);
    return v;
}

/* Bounds the next run_ode call at what is left of --max-steps for the whole run (at least one
 * step, so that a spent budget ends in the library's FRICREG_EWORK and its message): the
 * library's bound is per call, and the run makes one call per sample. */
static void spend_steps(fricreg_structure *s, const struct structure_options *o, int64_t start)
{
    if (o->scheme != SCHEME_GSL || !(o->rtol > 0.0 || o->atol != 0.0) || o->max_steps <= 0)
        return; /* fixed steps; the library's own bound per call (-1); no bound (0) */
    int64_t taken = 0;
    fricreg_structure_get_stat(s, FRICREG_SSTAT_STEPS, &taken);
    int64_t left = (int64_t)o->max_steps - (taken - start);
    fricreg_structure_set_max_steps(s, left > 1 ? left : 1);
}

int cli_structure_advance(fricreg_structure *s, const struct structure_options *o,
                          const struct structure_input *in, struct structure_run *run)
{
    observe(s, in, run);
    if (o->scheme != SCHEME_GSL) {
        if (run->rows != NULL)
            fricreg_structure_set_observer(s, observe_step, run);
        return fricreg_structure_run(s, o->dt, o->t_end);
    }
    double steps = ceil(o->t_end / o->dt * (1.0 - 1e-12)); /* <= 2^31: check_options */
    /* --max-steps counts from t = 0: a run restored from --checkpoint-in counts the steps
     * before its checkpoint too, as the uninterrupted run does. */
    int64_t nsteps = steps < 1.0 ? 1 : (int64_t)steps, start = 0;
    /* The structure's time, kept here: each call ends on its t1 exactly, and asking the
     * library (fricreg_structure_get_value) costs its energies, O(nnz), every step. */
    double t = cli_structure_value(s, FRICREG_SVALUE_TIME);
    /* the samples k dt after a checkpoint's time, as the uninterrupted run's */
    int64_t first = t > o->dt ? (int64_t)(t / o->dt) : 1;
    while (first > 1 && (double)(first - 1) * o->dt > t)
        first--;
    while (first < nsteps && !((double)first * o->dt > t))
        first++;
    for (int64_t k = first; k <= nsteps; k++) {
        spend_steps(s, o, start);
        double t1 = k == nsteps ? o->t_end : (double)k * o->dt;
        /* One step of exactly t1 - t: k dt - (k - 1) dt may exceed dt by a rounding, which
         * would make run() split it. */
        double h = t1 - t;
        int status = fricreg_structure_run_ode(s, o->integrator, h, o->rtol, o->atol, t1);
        if (status != FRICREG_OK)
            return status;
        t = t1;
        observe(s, in, run);
    }
    return FRICREG_OK;
}
