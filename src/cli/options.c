/* SPDX-License-Identifier: GPL-3.0-or-later */
/* options.c — the options of the reference systems (oscillator, chain, twoblock) and of
 * exact: their table (option_table.c reads it) and the checks between options. */
#include <math.h>

#include "cli.h"

const char *cli_system_name(int system)
{
    switch (system) {
    case FRICREG_SYSTEM_OSCILLATOR: return "oscillator";
    case FRICREG_SYSTEM_CHAIN: return "chain";
    default: return "twoblock";
    }
}

/* A system parameter option: its name, its enum, and the system that has it. */
struct param_option {
    const char *name;
    int param;
    int system;
};

static const struct param_option param_options[] = {
    {"--a", FRICREG_PARAM_A, FRICREG_SYSTEM_OSCILLATOR},
    {"--omega", FRICREG_PARAM_OMEGA, FRICREG_SYSTEM_OSCILLATOR},
    {"--mun", FRICREG_PARAM_MUN, FRICREG_SYSTEM_OSCILLATOR},
    {"--x0", FRICREG_PARAM_X0, FRICREG_SYSTEM_OSCILLATOR},
    {"--v0", FRICREG_PARAM_V0, FRICREG_SYSTEM_OSCILLATOR},
    {"--n", FRICREG_PARAM_N, FRICREG_SYSTEM_CHAIN},
    {"--a", FRICREG_PARAM_A, FRICREG_SYSTEM_CHAIN},
    {"--omega", FRICREG_PARAM_OMEGA, FRICREG_SYSTEM_CHAIN},
    {"--k", FRICREG_PARAM_K, FRICREG_SYSTEM_TWOBLOCK},
    {"--mu1", FRICREG_PARAM_MU1, FRICREG_SYSTEM_TWOBLOCK},
    {"--mu2", FRICREG_PARAM_MU2, FRICREG_SYSTEM_TWOBLOCK},
    {"--belt-amp", FRICREG_PARAM_BELT_AMP, FRICREG_SYSTEM_TWOBLOCK},
    {"--belt-omega", FRICREG_PARAM_BELT_OMEGA, FRICREG_SYSTEM_TWOBLOCK},
};

void cli_print_param_defaults(FILE *out)
{
    int system = 0;
    fricreg_sim *sim = NULL;
    for (size_t k = 0; k < sizeof param_options / sizeof param_options[0]; k++) {
        const struct param_option *p = &param_options[k];
        if (p->system != system) { /* the table lists each system's options together */
            fricreg_sim_free(sim);
            sim = NULL;
            fricreg_sim_create(p->system, &sim);
            char label[16];
            snprintf(label, sizeof label, "%s:", cli_system_name(p->system));
            fprintf(out, "%s%-11s", system ? "\n" : "", label);
            system = p->system;
        }
        double value = NAN;
        fricreg_sim_get_param(sim, p->param, &value);
        fprintf(out, " %s [%g]", p->name, value);
    }
    fputs("\n", out);
    fricreg_sim_free(sim);
}

/* A system parameter: the library checks its value on a fresh simulation, and its message
 * gives the range (e.g. omega > 0, n integer >= 2). The row's slot is the run, arg the param. */
static int parse_param(const struct cli_option *row, const char *text)
{
    struct cli_run *run = row->slot;
    double value;
    int status = cli_parse_number(row->name, text, &value);
    if (status != 0)
        return status;
    fricreg_sim *probe = NULL;
    if (fricreg_sim_create(run->system, &probe) != FRICREG_OK)
        return cli_usage_error(row->name, "out of memory");
    if (fricreg_sim_set_param(probe, row->arg, value) != FRICREG_OK)
        status = cli_usage_error(row->name, fricreg_sim_errmsg(probe));
    fricreg_sim_free(probe);
    if (status != 0)
        return status;
    if (run->nparams == (int)(sizeof run->params / sizeof run->params[0]))
        return cli_usage_error(row->name, "too many parameters");
    run->params[run->nparams].param = row->arg;
    run->params[run->nparams++].value = value;
    return 0;
}

/* --partition paper|consistent (the two blocks only: the other systems have no coupled
 * contacts, so the choice would change nothing there). */
static int parse_partition(const struct cli_option *row, const char *text)
{
    static const struct cli_word partitions[] = {{"paper", FRICREG_PARTITION_PAPER},
                                                 {"consistent", FRICREG_PARTITION_CONSISTENT},
                                                 {NULL, 0}};
    struct cli_run *run = row->slot;
    if (run->system != FRICREG_SYSTEM_TWOBLOCK)
        return cli_usage_error(row->name, "only twoblock has coupled contacts");
    const struct cli_option choice = {row->name, CLI_CHOICE, .slot = &run->partition,
                                      .words = partitions};
    return cli_parse_value(&choice, text);
}

static const struct cli_word on_off[] = {{"on", 1}, {"off", 0}, {NULL, 0}};

/* `exact` solves in closed form: the integration options have no meaning for it. */
static int refused_by_exact(const struct cli_option *row, const char *text)
{
    (void)text;
    return cli_usage_error(row->name, "not an option of exact (closed-form solution)");
}

enum { MAX_ROWS = 32 };

/* The rows every system has (exact refuses the integration ones), then the system's
 * parameters; returns their number. */
static size_t run_table(struct cli_run *run, int exact, int *cycles_given,
                        struct cli_option table[MAX_ROWS])
{
    const struct cli_option integration[] = {
        {"--law", CLI_NAME, .slot = &run->law, .names = &cli_law_names},
        {"--integrator", CLI_NAME, .slot = &run->integrator, .names = &cli_integrator_names},
        {"--dt", CLI_POSITIVE, .slot = &run->dt},
        {"--rtol", CLI_NONNEGATIVE, .slot = &run->rtol},
        {"--atol", CLI_NONNEGATIVE, .slot = &run->atol},
        {"--eps", CLI_POSITIVE, .slot = &run->eps},
        {"--extrapolate", CLI_WHOLE, .slot = &run->extrapolate, .lo = 2, .hi = 8},
        {"--extrapolate-order", CLI_WHOLE, .slot = &run->extrapolate_order, .lo = 0, .hi = 4},
        {"--extrapolate-window", CLI_WHOLE, .slot = &run->extrapolate_window, .lo = 0, .hi = 1e7},
        {"--max-steps", CLI_WHOLE, .slot = &run->max_steps, .lo = 0, .hi = 1e9},
        {"--kink-location", CLI_CHOICE, .slot = &run->kink_location, .words = on_off},
        {"--error-estimate", CLI_CHOICE, .slot = &run->error_estimate, .words = on_off}};
    const struct cli_option run_length_and_output[] = {
        {"--t-end", CLI_POSITIVE, .slot = &run->t_end},
        {"--cycles", CLI_WHOLE, .slot = &run->cycles, .lo = 1, .hi = 1e7, .given = cycles_given},
        {"--output", CLI_CHOICE, .slot = &run->output, .words = cli_output_words},
        {"--partition", CLI_CUSTOM, .slot = run, .parse = parse_partition}};
    size_t n = 0;
    for (size_t k = 0; k < sizeof integration / sizeof integration[0]; k++) {
        table[n] = integration[k];
        if (exact) { /* the name is known, its value never read */
            table[n].kind = CLI_CUSTOM;
            table[n].parse = refused_by_exact;
        }
        n++;
    }
    for (size_t k = 0; k < sizeof run_length_and_output / sizeof run_length_and_output[0]; k++)
        table[n++] = run_length_and_output[k];
    for (size_t k = 0; k < sizeof param_options / sizeof param_options[0]; k++)
        if (param_options[k].system == run->system && n < MAX_ROWS)
            table[n++] = (struct cli_option){param_options[k].name, CLI_CUSTOM, .slot = run,
                                             .parse = parse_param, .arg = param_options[k].param};
    return n;
}

/* The checks between options, once all are read. */
static int check_run(const struct cli_run *run, int cycles_given)
{
    if (run->t_end > 0.0 && cycles_given)
        return cli_usage_error("--t-end", "give --t-end or --cycles, not both");
    if (!run->extrapolate && (run->extrapolate_order || run->extrapolate_window))
        return cli_usage_error(run->extrapolate_order ? "--extrapolate-order"
                                                      : "--extrapolate-window",
                               "needs --extrapolate LEVELS");
    if (run->extrapolate && run->output == CLI_TRAJECTORY)
        return cli_usage_error("--extrapolate",
                               "adds to the summary; not with --output trajectory");
    return cli_check_tolerances(run->integrator, run->rtol, run->atol);
}

/* --atol's value before parsing: no number the option accepts (CLI_NONNEGATIVE). */
#define ATOL_NOT_GIVEN (-2.0)

static int parse_run(int system, int exact, int argc, char **argv, struct cli_run *run)
{
    *run = (struct cli_run){.system = system,
                            .law = FRICREG_LAW_QUINN,
                            .integrator = FRICREG_INT_RK4,
                            .dt = 0.01,
                            .cycles = 4,
                            .output = CLI_SUMMARY,
                            .partition = FRICREG_PARTITION_CONSISTENT,
                            .max_steps = -1,
                            .kink_location = 1,
                            .error_estimate = 1,
                            .atol = ATOL_NOT_GIVEN};
    int cycles_given = 0;
    struct cli_option table[MAX_ROWS];
    size_t n = run_table(run, exact, &cycles_given, table);
    int status = cli_parse_options(argc, argv, table, n, exact ? "exact" : cli_system_name(system));
    if (run->atol == ATOL_NOT_GIVEN) /* adaptive: the rule from eps; else fixed steps */
        run->atol = run->rtol > 0.0 ? FRICREG_ATOL_FROM_EPS : 0.0;
    return status != 0 ? status : check_run(run, cycles_given);
}

int cli_parse_run(int system, int argc, char **argv, struct cli_run *run)
{
    return parse_run(system, 0, argc, argv, run);
}

/* GSL's implicit and multistep steppers end their Newton iterations when the correction is
 * below atol + rtol |y| per component, which is 0 where a component is 0 — every start from
 * rest at the origin — so with atol = 0 they fail at t = 0 ("GSL stepper failed"). Refused
 * here with the reason, rather than run with an atol the user did not choose. */
int cli_check_tolerances(int integrator, double rtol, double atol)
{
    static const int newton[] = {FRICREG_INT_RK1IMP, FRICREG_INT_RK2IMP, FRICREG_INT_RK4IMP,
                                 FRICREG_INT_MSADAMS, FRICREG_INT_MSBDF};
    if (!(rtol > 0.0 && atol == 0.0))
        return 0;
    for (size_t k = 0; k < sizeof newton / sizeof newton[0]; k++)
        if (integrator == newton[k])
            return cli_usage_error("--atol",
                                   "must be > 0 for an implicit GSL stepper: its Newton "
                                   "iteration converges to atol + rtol |y|, which is 0 where "
                                   "a state component is 0 (a start at rest)");
    return 0;
}

/* `exact` takes the oscillator's parameters and the run length. */
int cli_parse_exact(int argc, char **argv, struct cli_run *run)
{
    int status = parse_run(FRICREG_SYSTEM_OSCILLATOR, 1, argc, argv, run);
    if (status == 0 && run->output != CLI_SUMMARY)
        return cli_usage_error("--output", "exact writes a summary only");
    return status;
}
