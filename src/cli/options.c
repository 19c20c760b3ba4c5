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

/* A system parameter option: its name, its enum, the system that has it, and its help. */
struct param_option {
    const char *name;
    int param;
    int system;
    const char *meta, *help;
};

static const struct param_option param_options[] = {
    {"--a", FRICREG_PARAM_A, FRICREG_SYSTEM_OSCILLATOR, "A", "forcing amplitude a"},
    {"--omega", FRICREG_PARAM_OMEGA, FRICREG_SYSTEM_OSCILLATOR, "W",
     "forcing frequency omega > 0 (sets the cycle, 2 pi/omega)"},
    {"--mun", FRICREG_PARAM_MUN, FRICREG_SYSTEM_OSCILLATOR, "MUN", "friction bound mu N >= 0"},
    {"--x0", FRICREG_PARAM_X0, FRICREG_SYSTEM_OSCILLATOR, "X0", "initial position"},
    {"--v0", FRICREG_PARAM_V0, FRICREG_SYSTEM_OSCILLATOR, "V0", "initial velocity"},
    {"--n", FRICREG_PARAM_N, FRICREG_SYSTEM_CHAIN, "N", "number of blocks, 2 to 10^7"},
    {"--a", FRICREG_PARAM_A, FRICREG_SYSTEM_CHAIN, "A", "amplitude of block 1's forcing"},
    {"--omega", FRICREG_PARAM_OMEGA, FRICREG_SYSTEM_CHAIN, "W", "forcing frequency omega > 0"},
    {"--k", FRICREG_PARAM_K, FRICREG_SYSTEM_TWOBLOCK, "K", "upper spring's stiffness k > 0"},
    {"--mu1", FRICREG_PARAM_MU1, FRICREG_SYSTEM_TWOBLOCK, "MU1",
     "friction bound of the lower interface (block 1 on the belt), >= 0"},
    {"--mu2", FRICREG_PARAM_MU2, FRICREG_SYSTEM_TWOBLOCK, "MU2",
     "friction bound of the upper interface (block 2 on block 1), >= 0"},
    {"--belt-amp", FRICREG_PARAM_BELT_AMP, FRICREG_SYSTEM_TWOBLOCK, "U",
     "belt displacement amplitude"},
    {"--belt-omega", FRICREG_PARAM_BELT_OMEGA, FRICREG_SYSTEM_TWOBLOCK, "W",
     "belt frequency > 0 (sets the cycle)"},
};
enum { N_PARAMS = sizeof param_options / sizeof param_options[0] };

/* The library's default of each parameter, as the help shows it (fricreg_sim_get_param on a
 * fresh simulation of its system). */
static const char *param_default(size_t k)
{
    static char text[N_PARAMS][32];
    if (text[k][0] == '\0') {
        fricreg_sim *sim = NULL;
        double value = NAN;
        if (fricreg_sim_create(param_options[k].system, &sim) == FRICREG_OK)
            fricreg_sim_get_param(sim, param_options[k].param, &value);
        fricreg_sim_free(sim);
        snprintf(text[k], sizeof text[k], "%.6g", value);
    }
    return text[k];
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

/* The rows every system has (exact refuses the integration ones), then the system's
 * parameters, into table[CLI_MAX_ROWS]; returns their number. */
static size_t run_table(struct cli_run *run, int exact, int *cycles_given,
                        struct cli_option table[])
{
    const int chain = run->system == FRICREG_SYSTEM_CHAIN;
    const struct cli_option integration[] = {
        {"--law", CLI_NAME, .slot = &run->law, .names = &cli_law_names,
         .help = "the friction law (docs/usage.md, \"Laws\")"},
        {"--integrator", CLI_NAME, .slot = &run->integrator, .names = &cli_integrator_names,
         .help = "the stepper: fixed step, or adaptive with --rtol (docs/integrators.md)"},
        {"--dt", CLI_POSITIVE, .slot = &run->dt, .meta = "STEP",
         .help = "time step; with --rtol, the first step"},
        {"--rtol", CLI_NONNEGATIVE, .slot = &run->rtol, .meta = "R",
         .help = "relative tolerance of adaptive step control (0: fixed steps)"},
        {"--atol", CLI_NONNEGATIVE, .slot = &run->atol, .meta = "A",
         .help = "absolute tolerance; without it velocities get min(1e-3 eps, R), x and D get R",
         .dflt = "from eps"},
        {"--eps", CLI_POSITIVE, .slot = &run->eps, .meta = "EPS",
         .help = "the laws' regularization, a velocity", .dflt = chain ? "10 omega dt" : "2 dt"},
        {"--extrapolate", CLI_WHOLE, .slot = &run->extrapolate, .lo = 2, .hi = 8, .meta = "LEVELS",
         .help = "also run at eps/2 ... eps/2^(LEVELS-1) and add D extrapolated to eps -> 0, "
                 "with its error estimate, to the summary (2 to 8)",
         .dflt = "off"},
        {"--extrapolate-order", CLI_WHOLE, .slot = &run->extrapolate_order, .lo = 0, .hi = 4,
         .meta = "P",
         .help = "the leading order in eps where the levels show none (2 levels), 0 to 4 "
                 "(0: order 1)"},
        {"--extrapolate-window", CLI_WHOLE, .slot = &run->extrapolate_window, .lo = 0, .hi = 1e7,
         .meta = "W",
         .help = "the finer levels over the last W cycles only, from the state of the first "
                 "level there (0: the whole run)"},
        {"--max-steps", CLI_WHOLE, .slot = &run->max_steps, .lo = 0, .hi = 1e9, .meta = "N",
         .help = "adaptive steps a forcing cycle may take (0: no bound)",
         .dflt = "10^4 for coulomb, force-balance, karnopp; else 10^6"},
        {"--kink-location", CLI_CHOICE, .slot = &run->kink_location, .words = on_off,
         .help = "adaptive steps stop at the friction law's kinks and restart the stepper there"},
        {"--error-estimate", CLI_CHOICE, .slot = &run->error_estimate, .words = cli_estimator_words,
         .help = "companion runs at eps/2 and eps/4 (dt/2 and dt/4, or tolerances/16 and /256) "
                 "add dissipation_error_estimate per cycle to the summary, about 7x the cost; "
                 "one: 1.6's single companion at eps/2, 3x"},
        {"--answer-rtol", CLI_POSITIVE, .slot = &run->answer_rtol, .meta = "X",
         .help = "warn (error_estimate) where the last whole cycle's estimate exceeds X |D|, "
                 "whatever its kind"}};
    const struct cli_option run_length_and_output[] = {
        {"--t-end", CLI_POSITIVE, .slot = &run->t_end, .meta = "T",
         .help = "run length in time (instead of --cycles)", .dflt = ""},
        {"--cycles", CLI_WHOLE, .slot = &run->cycles, .lo = 1, .hi = 1e7, .given = cycles_given,
         .meta = "N", .help = "run length in forcing cycles, 1 to 10^7"},
        {"--output", CLI_CHOICE, .slot = &run->output, .words = cli_output_words,
         .help = exact ? "a JSON summary (the closed form writes no trajectory)"
                       : "a JSON summary, or a CSV row per step"},
        {"--partition", CLI_CUSTOM, .slot = run, .parse = parse_partition,
         .meta = "paper|consistent",
         .help = "the coupled contacts' near-stick law: the paper's joint solve, or the "
                 "consistent one, continuous at the band's edge (docs/coupled.md)",
         .dflt = "consistent", .hidden = run->system != FRICREG_SYSTEM_TWOBLOCK}};
    size_t n = 0;
    for (size_t k = 0; k < sizeof integration / sizeof integration[0]; k++) {
        table[n] = integration[k];
        if (exact) { /* the name is known, its value never read */
            table[n].kind = CLI_CUSTOM;
            table[n].parse = refused_by_exact;
            table[n].hidden = 1;
        }
        n++;
    }
    for (size_t k = 0; k < sizeof run_length_and_output / sizeof run_length_and_output[0]; k++)
        table[n++] = run_length_and_output[k];
    for (size_t k = 0; k < N_PARAMS; k++)
        if (param_options[k].system == run->system && n < CLI_MAX_ROWS)
            table[n++] = (struct cli_option){param_options[k].name,
                                             CLI_CUSTOM,
                                             .slot = run,
                                             .parse = parse_param,
                                             .arg = param_options[k].param,
                                             .meta = param_options[k].meta,
                                             .help = param_options[k].help,
                                             .dflt = param_default(k)};
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

/* The defaults, as the parser starts from them and the help shows them. */
static void run_defaults(int system, struct cli_run *run)
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
                            .answer_rtol = CLI_ANSWER_RTOL,
                            .atol = ATOL_NOT_GIVEN};
}

static int parse_run(int system, int exact, int argc, char **argv, struct cli_run *run)
{
    run_defaults(system, run);
    int cycles_given = 0;
    struct cli_option table[CLI_MAX_ROWS];
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

/* ---- The help (help.c): the tables over runs with the defaults set ------------------------ */

static struct cli_run help_run; /* the help's rows point here */
static int help_cycles_given;

static size_t help_table(int system, int exact, struct cli_option table[])
{
    run_defaults(system, &help_run);
    return run_table(&help_run, exact, &help_cycles_given, table);
}

static size_t oscillator_table(struct cli_option table[])
{
    return help_table(FRICREG_SYSTEM_OSCILLATOR, 0, table);
}

static size_t chain_table(struct cli_option table[])
{
    return help_table(FRICREG_SYSTEM_CHAIN, 0, table);
}

static size_t twoblock_table(struct cli_option table[])
{
    return help_table(FRICREG_SYSTEM_TWOBLOCK, 0, table);
}

static size_t exact_table(struct cli_option table[])
{
    return help_table(FRICREG_SYSTEM_OSCILLATOR, 1, table);
}

#define RUN_SYNOPSIS "[--law L] [--integrator I] [--dt STEP] [--t-end T | --cycles N] [OPTION]..."
#define RUN_OUTPUT                                                                                 \
    "\n\nThe summary (one JSON object) gives the state at the end, the dissipation D per forcing " \
    "cycle with its error estimate, and each contact's stick fraction; --output trajectory "       \
    "writes a CSV row per step instead. Time, lengths and forces are nondimensional, as in "       \
    "the paper."

const struct cli_command cli_oscillator_command = {
    "oscillator", RUN_SYNOPSIS, "the forced oscillator with one friction contact (Eq. 5)",
    "The forced oscillator of Quinn (2004), Eq. (5): x'' + x = f + a sin(omega t), one contact "
    "with bound mu N, from x0, v0." RUN_OUTPUT,
    oscillator_table};

const struct cli_command cli_chain_command = {
    "chain", RUN_SYNOPSIS, "a chain of n blocks, each with friction (Sec. 3.2)",
    "The chain of Quinn (2004), Sec. 3.2: n blocks of mass 1/n joined by springs of stiffness "
    "n, the last tied to a wall, the first driven by a sin(omega t), every block on a contact "
    "with mu N = 1, from rest." RUN_OUTPUT,
    chain_table};

const struct cli_command cli_twoblock_command = {
    "twoblock", RUN_SYNOPSIS, "two stacked blocks on a moving belt, coupled contacts (Eqs. 7)",
    "The two blocks of Quinn (2004), Eqs. (7): the lower block on a belt moving as belt_amp "
    "sin(belt_omega t), the upper block on it, springs 1 and k to the ground; two coupled "
    "contacts with bounds mu1 and mu2, from rest." RUN_OUTPUT,
    twoblock_table};

const struct cli_command cli_exact_command = {
    "exact", "[--a A] [--omega W] [--mun MUN] [--x0 X0] [--v0 V0] [--t-end T | --cycles N]",
    "the oscillator's exact (closed-form) solution, as a summary",
    "The oscillator of Eq. (5) solved in closed form, stick and slip phases joined exactly: "
    "the summary fields of a simulated run, with integrator \"exact\" and steps counting the "
    "switches. The integration options (--law, --dt, --rtol, ...) are refused.",
    exact_table};
