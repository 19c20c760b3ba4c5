/* SPDX-License-Identifier: GPL-3.0-or-later */
/* options.c — parsing and validation of fricreg-sim's options. Every error is one line on
 * stderr that names the option, and exit status 2; nothing is run or written. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"

const char *cli_names(char *buf, size_t len, const char *(*name_of)(int), const char *sep)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int k = 1; name_of(k) != NULL && used < len; k++)
        used += (size_t)snprintf(buf + used, len - used, "%s%s", k > 1 ? sep : "", name_of(k));
    return buf;
}

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

int cli_usage_error(const char *option, const char *what)
{
    fprintf(stderr, "fricreg-sim: %s: %s\n", option, what);
    return CLI_EXIT_USAGE;
}

int cli_next_option(int argc, char **argv, int *k, char **option, char **value)
{
    *option = argv[*k];
    if (strncmp(*option, "--", 2) != 0)
        return cli_usage_error(*option, "unexpected argument");
    char *eq = strchr(*option, '=');
    if (eq != NULL) { /* --name=value */
        *eq = '\0';
        *value = eq + 1;
    } else if (*k + 1 < argc) {
        *value = argv[++*k];
    } else {
        return cli_usage_error(*option, "missing value");
    }
    return 0;
}

/* A finite double, the whole of text. strtod sets ERANGE on underflow too (1e-310, 1e-400),
 * returning the subnormal or zero nearest the text: that is the number meant, so it is kept;
 * only an overflow (±HUGE_VAL) is refused. */
static int parse_double(const char *option, const char *text, double *value)
{
    char *end = NULL;
    errno = 0;
    *value = strtod(text, &end);
    if (end == text || *end != '\0')
        return cli_usage_error(option, "not a number");
    if (errno == ERANGE && fabs(*value) == HUGE_VAL)
        return cli_usage_error(option, "out of the range of a double");
    if (!isfinite(*value))
        return cli_usage_error(option, "not a finite number");
    return 0;
}

static int parse_positive(const char *option, const char *text, double *value)
{
    int status = parse_double(option, text, value);
    if (status == 0 && !(*value > 0.0))
        return cli_usage_error(option, "must be > 0");
    return status;
}

static int parse_nonnegative(const char *option, const char *text, double *value)
{
    int status = parse_double(option, text, value);
    if (status == 0 && !(*value >= 0.0))
        return cli_usage_error(option, "must be >= 0");
    return status;
}

static int parse_law(const char *text, int *law)
{
    *law = fricreg_law_from_name(text);
    if (*law != 0)
        return 0;
    char names[256], what[300];
    snprintf(what, sizeof what, "unknown law (%s)",
             cli_names(names, sizeof names, fricreg_law_name, ", "));
    return cli_usage_error("--law", what);
}

static int parse_param(int system, const char *option, const char *text, struct cli_run *run)
{
    for (size_t k = 0; k < sizeof param_options / sizeof param_options[0]; k++) {
        const struct param_option *p = &param_options[k];
        if (p->system != system || strcmp(p->name, option) != 0)
            continue;
        double value;
        int status = parse_double(option, text, &value);
        if (status != 0)
            return status;
        /* The library's own check gives the range (e.g. omega > 0, n integer >= 2). */
        fricreg_sim *probe = NULL;
        if (fricreg_sim_create(system, &probe) != FRICREG_OK)
            return cli_usage_error(option, "out of memory");
        status = fricreg_sim_set_param(probe, p->param, value);
        if (status != FRICREG_OK) {
            status = cli_usage_error(option, fricreg_sim_errmsg(probe));
            fricreg_sim_free(probe);
            return status;
        }
        fricreg_sim_free(probe);
        if (run->nparams == (int)(sizeof run->params / sizeof run->params[0]))
            return cli_usage_error(option, "too many parameters");
        run->params[run->nparams].param = p->param;
        run->params[run->nparams++].value = value;
        return 0;
    }
    return cli_usage_error(option, "unknown option for this system (see fricreg-sim --help)");
}

/* --partition paper|consistent (the two blocks only: the other systems have no coupled
 * contacts, so the choice would change nothing there). */
static int parse_partition(int system, const char *text, struct cli_run *run)
{
    if (system != FRICREG_SYSTEM_TWOBLOCK)
        return cli_usage_error("--partition", "only twoblock has coupled contacts");
    if (strcmp(text, "consistent") == 0)
        run->partition = FRICREG_PARTITION_CONSISTENT;
    else if (strcmp(text, "paper") == 0)
        run->partition = FRICREG_PARTITION_PAPER;
    else
        return cli_usage_error("--partition", "expected paper or consistent");
    return 0;
}

/* Options that every system has. Returns -1 if option is not one of them. */
/* A whole number from lo to hi (the extrapolation's order and window). */
static int parse_whole(const char *option, const char *text, double lo, double hi, int *out)
{
    char *end = NULL;
    double x = strtod(text, &end);
    if (end == text || *end != '\0' || !(x >= lo && x <= hi) || x != floor(x)) {
        char what[96];
        snprintf(what, sizeof what, "must be a whole number from %g to %g", lo, hi);
        return cli_usage_error(option, what);
    }
    *out = (int)x;
    return 0;
}

static int parse_common(const char *option, const char *text, struct cli_run *run)
{
    if (strcmp(option, "--law") == 0)
        return parse_law(text, &run->law);
    if (strcmp(option, "--integrator") == 0) {
        run->integrator = fricreg_integrator_from_name(text);
        if (run->integrator != 0)
            return 0;
        char names[256], what[300];
        snprintf(what, sizeof what, "unknown integrator (%s)",
                 cli_names(names, sizeof names, fricreg_integrator_name, ", "));
        return cli_usage_error(option, what);
    }
    if (strcmp(option, "--dt") == 0)
        return parse_positive(option, text, &run->dt);
    if (strcmp(option, "--eps") == 0)
        return parse_positive(option, text, &run->eps);
    if (strcmp(option, "--rtol") == 0)
        return parse_nonnegative(option, text, &run->rtol);
    if (strcmp(option, "--atol") == 0)
        return parse_nonnegative(option, text, &run->atol);
    if (strcmp(option, "--t-end") == 0)
        return parse_positive(option, text, &run->t_end);
    if (strcmp(option, "--cycles") == 0) {
        double cycles;
        int status = parse_positive(option, text, &cycles);
        if (status != 0)
            return status; /* NaN, Inf, <= 0: never converted to int */
        if (cycles != floor(cycles) || cycles > 1e7)
            return cli_usage_error(option, "must be a whole number from 1 to 10^7");
        run->cycles = (int)cycles;
        return 0;
    }
    if (strcmp(option, "--extrapolate") == 0) {
        double levels;
        int status = parse_positive(option, text, &levels);
        if (status != 0)
            return status; /* not a number: never converted to int */
        if (levels != floor(levels) || levels < 2 || levels > 8)
            return cli_usage_error(option, "must be a whole number of levels from 2 to 8");
        run->extrapolate = (int)levels;
        return 0;
    }
    if (strcmp(option, "--extrapolate-order") == 0)
        return parse_whole(option, text, 0, 4, &run->extrapolate_order);
    if (strcmp(option, "--extrapolate-window") == 0)
        return parse_whole(option, text, 0, 1e7, &run->extrapolate_window);
    if (strcmp(option, "--output") == 0) {
        if (strcmp(text, "summary") == 0)
            run->output = CLI_SUMMARY;
        else if (strcmp(text, "trajectory") == 0)
            run->output = CLI_TRAJECTORY;
        else
            return cli_usage_error(option, "expected summary or trajectory");
        return 0;
    }
    return -1;
}

int cli_parse_run(int system, int argc, char **argv, struct cli_run *run)
{
    *run = (struct cli_run){.system = system,
                            .law = FRICREG_LAW_QUINN,
                            .integrator = FRICREG_INT_RK4,
                            .dt = 0.01,
                            .cycles = 4,
                            .output = CLI_SUMMARY,
                            .partition = FRICREG_PARTITION_CONSISTENT};
    int cycles_given = 0;
    for (int k = 0; k < argc; k++) {
        char *option = NULL, *value = NULL;
        int split = cli_next_option(argc, argv, &k, &option, &value);
        if (split != 0)
            return split;
        cycles_given |= strcmp(option, "--cycles") == 0;
        int status = strcmp(option, "--partition") == 0 ? parse_partition(system, value, run)
                                                        : parse_common(option, value, run);
        if (status < 0)
            status = parse_param(system, option, value, run);
        if (status != 0)
            return status;
    }
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

/* `exact` takes the oscillator's parameters and the run length; the integration options have
 * no meaning for it and are refused by name. */
int cli_parse_exact(int argc, char **argv, struct cli_run *run)
{
    static const char *const refused[] = {"--law",
                                          "--integrator",
                                          "--dt",
                                          "--rtol",
                                          "--atol",
                                          "--eps",
                                          "--extrapolate",
                                          "--extrapolate-order",
                                          "--extrapolate-window"};
    for (int k = 0; k < argc; k++)
        for (size_t r = 0; r < sizeof refused / sizeof refused[0]; r++) {
            size_t len = strlen(refused[r]);
            if (strncmp(argv[k], refused[r], len) == 0 &&
                (argv[k][len] == '\0' || argv[k][len] == '='))
                return cli_usage_error(refused[r], "not an option of exact (closed-form solution)");
        }
    int status = cli_parse_run(FRICREG_SYSTEM_OSCILLATOR, argc, argv, run);
    if (status == 0 && run->output != CLI_SUMMARY)
        return cli_usage_error("--output", "exact writes a summary only");
    return status;
}
