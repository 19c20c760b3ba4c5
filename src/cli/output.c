/* SPDX-License-Identifier: GPL-3.0-or-later */
/* output.c — runs one simulation and writes its JSON summary or its CSV trajectory. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli.h"

/* Whether a step refused with eps from the paper's rule is refused at every dt: the rule makes
 * dt * lambda independent of dt, and then only --eps helps. Probed with dt/1000 for one step
 * (the library checks the step before it takes any). */
static int refused_at_every_dt(const struct cli_run *run)
{
    if (run->eps > 0.0)
        return 0;
    struct cli_run probe = *run;
    probe.dt = run->dt * 1e-3;
    fricreg_sim *sim = cli_make_sim(&probe);
    int every = sim != NULL && fricreg_sim_run(sim, probe.dt) == FRICREG_ESTEP;
    fricreg_sim_free(sim);
    return every;
}

static int run_failed(fricreg_sim *sim, int status, const struct cli_run *run)
{
    /* A step that is too large is a bad --dt (or, under the paper's rule, a missing --eps), and
     * a run length the library refuses (EINVAL from the run: too many steps) a bad --t-end or
     * --cycles: usage errors like any other bad value. */
    const char *option = "";
    if (status == FRICREG_ESTEP)
        option = refused_at_every_dt(run) ? "--eps: " : "--dt: ";
    else if (status == FRICREG_EWORK) /* a run failure, named by the option that bounds it */
        option = "--max-steps: ";
    else if (status == FRICREG_EINVAL)
        option = run->t_end > 0.0 ? "--t-end: " : "--cycles: ";
    fprintf(stderr, "fricreg-sim: %s%s\n", option, fricreg_sim_errmsg(sim));
    fricreg_sim_free(sim);
    return status == FRICREG_ESTEP || status == FRICREG_EINVAL ? CLI_EXIT_USAGE : CLI_EXIT_RUN;
}

fricreg_sim *cli_make_sim(const struct cli_run *run)
{
    fricreg_sim *sim = NULL;
    if (fricreg_sim_create(run->system, &sim) != FRICREG_OK) {
        fprintf(stderr, "fricreg-sim: out of memory\n");
        return NULL;
    }
    int status = fricreg_sim_set_law(sim, run->law, run->eps);
    if (status == FRICREG_OK)
        status = fricreg_sim_set_integrator(sim, run->integrator, run->dt, run->rtol, run->atol);
    if (status == FRICREG_OK)
        status = fricreg_sim_set_partition(sim, run->partition);
    if (status == FRICREG_OK && run->max_steps >= 0)
        status = fricreg_sim_set_max_steps(sim, run->max_steps);
    if (status == FRICREG_OK)
        status = fricreg_sim_set_kink_location(sim, run->kink_location);
    if (status == FRICREG_OK)
        status = fricreg_sim_set_answer_rtol(sim, run->answer_rtol);
    for (int k = 0; status == FRICREG_OK && k < run->nparams; k++)
        status = fricreg_sim_set_param(sim, run->params[k].param, run->params[k].value);
    if (status != FRICREG_OK) {
        fprintf(stderr, "fricreg-sim: %s\n", fricreg_sim_errmsg(sim));
        fricreg_sim_free(sim);
        return NULL;
    }
    return sim;
}

static double value(const fricreg_sim *sim, int which)
{
    double v = 0.0;
    fricreg_sim_get_value(sim, which, &v);
    return v;
}

static int execute(fricreg_sim *sim, const struct cli_run *run)
{
    if (run->extrapolate) /* the leading order observed, else the declared (fricreg_sim.h) */
        return fricreg_sim_run_extrapolated_window(
            sim, run->t_end > 0.0 ? run->t_end : run->cycles * value(sim, FRICREG_VALUE_PERIOD),
            run->extrapolate, run->extrapolate_order, run->extrapolate_window);
    return run->t_end > 0.0 ? fricreg_sim_run(sim, run->t_end)
                            : fricreg_sim_run_cycles(sim, run->cycles);
}

/* "extrapolation": {…}; an observed order that could not be measured (NaN) is null. */
static void write_extrapolation(FILE *out, const struct cli_extrapolation *x, size_t cycles)
{
    fprintf(out,
            ", \"extrapolation\": {\"levels\": %d, \"order\": %d, \"observed_order\": ", x->levels,
            x->order);
    isfinite(x->observed_order) ? fprintf(out, "%.17g", x->observed_order) : fprintf(out, "null");
    fprintf(out, ", \"flagged_cycles\": %.0f, \"eps_finest\": %.17g, \"rhs_evals\": %.0f",
            x->flagged_cycles, x->eps_finest, x->rhs_evals);
    fprintf(out, ", \"dissipation\": %.17g, \"dissipation_error\": ", x->dissipation);
    cli_json_number(out, x->dissipation_error);
    cli_json_array(out, "dissipation_per_cycle", cycles, x->D);
    cli_json_array(out, "error_per_cycle", cycles, x->err);
    fprintf(out, "}");
}

/* The simulation's warnings on its settings and run (fricreg_sim_warning_count). */
static void sim_warnings(fricreg_sim *sim, struct cli_warnings *w)
{
    size_t count = fricreg_sim_warning_count(sim);
    w->n = 0;
    for (size_t k = 0; k < count && w->n < 16; k++, w->n++)
        fricreg_sim_get_warning(sim, k, &w->code[w->n], w->message[w->n], sizeof w->message[0]);
}

void cli_write_summary(FILE *out, const struct cli_summary *s)
{
    fprintf(out, "{\"system\": \"%s\", \"law\": \"%s\", \"integrator\": \"%s\", ", s->system,
            s->law, s->integrator);
    fprintf(out, "\"adaptive\": %s, \"dt\": %.17g, \"rtol\": %.17g, \"atol\": ",
            s->adaptive ? "true" : "false", s->dt, s->rtol);
    if (s->atol == FRICREG_ATOL_FROM_EPS)
        fprintf(out, "\"eps\", ");
    else
        fprintf(out, "%.17g, ", s->atol);
    fprintf(out, "\"eps\": %.17g, \"steps\": %.0f, \"rhs_evals\": %.0f, \"t\": %.17g, ", s->eps,
            s->steps, s->rhs_evals, s->t);
    fprintf(out, "\"period\": %.17g", s->period);
    if (s->adaptive)
        fprintf(out, ", \"kinks\": %.0f", s->kinks);
    if (s->adaptive && s->atol_used != NULL) /* per component of y = (x, v, D) */
        cli_json_array(out, "atol_used", 2 * s->ndof + 1, s->atol_used);
    cli_json_array(out, "x", s->ndof, s->x);
    cli_json_array(out, "v", s->ndof, s->v);
    cli_json_array(out, "dissipation_per_cycle", s->cycles, s->D);
    struct cli_kind_counts kinds = {{0}};
    if (s->D_err != NULL) { /* an estimate that could not be formed is null */
        cli_json_array(out, "dissipation_error_estimate", s->cycles, s->D_err);
        cli_json_kinds(out, "dissipation_error_kind", s->cycles, s->D_kind);
        cli_count_kinds(&kinds, s->cycles, s->D_kind);
    }
    cli_json_array(out, "stick_fraction", s->ncontacts, s->stick);
    if (s->extrap != NULL)
        write_extrapolation(out, s->extrap, s->cycles);
    if (s->D_err != NULL)
        cli_json_kind_counts(out, &kinds);
    fprintf(out, ", \"cpu_seconds\": %.6f", s->cpu_seconds);
    cli_json_warnings(out, s->warnings);
    fputs("}\n", out);
}

static double extrap_value(const fricreg_sim *sim, int which)
{
    double v = NAN;
    fricreg_sim_get_extrapolation(sim, which, &v);
    return v;
}

/* The extrapolation of a run; its per-cycle arrays in buf[2 cycles]. */
static void read_extrapolation(const fricreg_sim *sim, size_t cycles, double buf[],
                               struct cli_extrapolation *x)
{
    fricreg_sim_get_extrapolated_dissipation(sim, cycles, buf, buf + cycles);
    *x = (struct cli_extrapolation){
        .levels = (int)extrap_value(sim, FRICREG_EXTRAP_LEVELS),
        .order = (int)extrap_value(sim, FRICREG_EXTRAP_ORDER),
        .observed_order = extrap_value(sim, FRICREG_EXTRAP_OBSERVED_ORDER),
        .flagged_cycles = extrap_value(sim, FRICREG_EXTRAP_FLAGGED_CYCLES),
        .eps_finest = extrap_value(sim, FRICREG_EXTRAP_EPS_FINEST),
        .rhs_evals = extrap_value(sim, FRICREG_EXTRAP_RHS_EVALS),
        .dissipation = extrap_value(sim, FRICREG_EXTRAP_DISSIPATION),
        .dissipation_error = extrap_value(sim, FRICREG_EXTRAP_DISSIPATION_ERR),
        .D = buf,
        .err = buf + cycles};
}

static double kink_count(const fricreg_sim *sim)
{
    int64_t n = 0;
    fricreg_sim_get_stat(sim, FRICREG_SIM_STAT_KINKS, &n);
    return (double)n;
}

static void write_summary(FILE *out, const struct cli_run *run, const fricreg_sim *sim,
                          double cpu_seconds, const struct cli_warnings *warnings)
{
    size_t n = fricreg_sim_ndof(sim), m = fricreg_sim_ncontacts(sim);
    size_t cycles = (size_t)value(sim, FRICREG_VALUE_CYCLES);
    double *buf = malloc((4 * n + m + 4 * cycles + 2) * sizeof *buf);
    if (buf == NULL) {
        fprintf(stderr, "fricreg-sim: out of memory\n");
        return;
    }
    double *x = buf, *v = x + n, *stick = v + n, *atol = stick + m, *D = atol + 2 * n + 1;
    fricreg_sim_get_abs_tolerances(sim, 2 * n + 1, atol);
    fricreg_sim_get_state(sim, n, x, v);
    fricreg_sim_get_stick_fraction(sim, m, stick);
    fricreg_sim_get_dissipation(sim, cycles, D);
    struct cli_extrapolation extrap;
    if (run->extrapolate)
        read_extrapolation(sim, cycles, D + cycles, &extrap);
    double *D_err = D + 3 * cycles;
    int *D_kind = malloc((cycles + 1) * sizeof *D_kind);
    int estimated = D_kind != NULL &&
                    fricreg_sim_get_dissipation_error(sim, cycles, D_err) == FRICREG_OK &&
                    fricreg_sim_get_dissipation_error_kind(sim, cycles, D_kind) == FRICREG_OK;
    struct cli_summary s = {.system = cli_system_name(run->system),
                            .law = fricreg_law_name(run->law),
                            .integrator = fricreg_integrator_name(run->integrator),
                            .adaptive = run->rtol > 0.0 || run->atol != 0.0,
                            .dt = run->dt,
                            .rtol = run->rtol,
                            .atol = run->atol,
                            .atol_used = atol,
                            .eps = value(sim, FRICREG_VALUE_EPS),
                            .steps = value(sim, FRICREG_VALUE_STEPS),
                            .rhs_evals = value(sim, FRICREG_VALUE_RHS_EVALS),
                            .kinks = kink_count(sim),
                            .t = value(sim, FRICREG_VALUE_TIME),
                            .period = value(sim, FRICREG_VALUE_PERIOD),
                            .cpu_seconds = cpu_seconds,
                            .ndof = n,
                            .ncontacts = m,
                            .cycles = cycles,
                            .x = x,
                            .v = v,
                            .D = D,
                            .D_err = estimated ? D_err : NULL,
                            .D_kind = D_kind,
                            .stick = stick,
                            .extrap = run->extrapolate ? &extrap : NULL,
                            .warnings = warnings};
    cli_write_summary(out, &s);
    free(D_kind);
    free(buf);
}

int cli_run_summary(const struct cli_run *run, FILE *out)
{
    fricreg_sim *sim = cli_make_sim(run);
    if (sim == NULL)
        return CLI_EXIT_USAGE;
    /* the summary's headline D with its error bar; an extrapolation carries its own */
    fricreg_sim_set_error_estimate(sim,
                                   run->extrapolate ? FRICREG_ESTIMATE_OFF : run->error_estimate);
    clock_t start = clock();
    int status = execute(sim, run);
    double cpu_seconds = (double)(clock() - start) / CLOCKS_PER_SEC;
    if (status != FRICREG_OK)
        return run_failed(sim, status, run);
    struct cli_warnings warnings;
    sim_warnings(sim, &warnings);
    cli_print_warnings(&warnings);
    write_summary(out, run, sim, cpu_seconds, &warnings);
    fricreg_sim_free(sim);
    return 0;
}

/* CSV row per step; f_eq is an empty field where it was not computed (slipping contact). */
static int csv_row(void *user, double t, size_t ndof, const double x[], const double v[], size_t m,
                   const double f[], const double f_eq[])
{
    FILE *out = user;
    fprintf(out, "%.17g", t);
    for (size_t i = 0; i < ndof; i++)
        fprintf(out, ",%.17g", x[i]);
    for (size_t i = 0; i < ndof; i++)
        fprintf(out, ",%.17g", v[i]);
    for (size_t i = 0; i < m; i++)
        fprintf(out, ",%.17g", f[i]);
    for (size_t i = 0; i < m; i++)
        isnan(f_eq[i]) ? fputc(',', out) : fprintf(out, ",%.17g", f_eq[i]);
    fputc('\n', out);
    return 0;
}

static void csv_header(FILE *out, size_t ndof, size_t m)
{
    const char *names[4] = {"x", "v", "f", "f_eq"};
    fprintf(out, "t");
    for (int k = 0; k < 4; k++) {
        size_t count = k < 2 ? ndof : m;
        for (size_t i = 0; i < count; i++)
            count == 1 ? fprintf(out, ",%s", names[k]) : fprintf(out, ",%s%zu", names[k], i + 1);
    }
    fputc('\n', out);
}

/* Rows go to a temporary file first, so that a failed run writes nothing to out. */
int cli_run_trajectory(const struct cli_run *run, FILE *out)
{
    fricreg_sim *sim = cli_make_sim(run);
    if (sim == NULL)
        return CLI_EXIT_USAGE;
    FILE *tmp = tmpfile();
    if (tmp == NULL) {
        fprintf(stderr, "fricreg-sim: cannot create a temporary file\n");
        fricreg_sim_free(sim);
        return CLI_EXIT_RUN;
    }
    csv_header(tmp, fricreg_sim_ndof(sim), fricreg_sim_ncontacts(sim));
    fricreg_sim_set_observer(sim, csv_row, tmp);
    int status = execute(sim, run);
    if (status != FRICREG_OK) {
        fclose(tmp);
        return run_failed(sim, status, run);
    }
    fricreg_sim_free(sim);
    int failed = fflush(tmp) != 0 || ferror(tmp);
    rewind(tmp);
    char chunk[1 << 16];
    size_t got;
    while (!failed && (got = fread(chunk, 1, sizeof chunk, tmp)) > 0)
        failed = fwrite(chunk, 1, got, out) != got;
    failed |= ferror(tmp);
    fclose(tmp);
    if (failed) {
        fprintf(stderr, "fricreg-sim: writing the trajectory: %s\n", strerror(errno));
        return CLI_EXIT_RUN;
    }
    return 0;
}
