/* SPDX-License-Identifier: GPL-3.0-or-later */
/* structure.c — the options of `fricreg-sim structure` (cli_structure.h): the one table the
 * parser and the help read, the integrators by name, and the checks of options that need or
 * exclude others; every bad option one line on stderr naming it, exit 2. The run that reads
 * them is structure_run.c's. */
#include <stdio.h>
#include <string.h>

#include "cli_structure.h"
#include "dof_list.h"
#include "fricreg_structure.h"

/* --rayleigh A0,A1: two numbers >= 0 (cli_parse_rayleigh). */
static int parse_rayleigh(const struct cli_option *row, const char *text)
{
    struct structure_options *o = row->slot;
    return cli_parse_rayleigh(row->name, text, &o->a0, &o->a1);
}

/* The structure's own schemes; "central" is its central differences, not fricreg_sim's. */
static const struct cli_word schemes[] = {{"newmark", SCHEME_NEWMARK},
                                          {"hht", SCHEME_HHT},
                                          {"central", SCHEME_CENTRAL},
                                          {NULL, 0}};

/* The library's integrators that --integrator runs through fricreg_structure_run_ode, each
 * after ", ", into buf[len]: all but fricreg_sim's "central" and "central-imex" (the word
 * "central" names the structure's own scheme here, listed once with the others). */
static const char *gsl_stepper_names(char *buf, size_t len)
{
    size_t used = 0;
    buf[0] = '\0';
    for (int k = 1; fricreg_integrator_name(k) != NULL && used < len; k++)
        if (strncmp(fricreg_integrator_name(k), "central", strlen("central")) != 0)
            used += (size_t)snprintf(buf + used, len - used, ", %s", fricreg_integrator_name(k));
    return buf;
}

/* --integrator: one of the schemes, or a GSL stepper by the library's name. */
static int parse_integrator(const struct cli_option *row, const char *text)
{
    struct structure_options *o = row->slot;
    const struct cli_word *scheme = cli_find_word(schemes, text);
    if (scheme != NULL)
        o->scheme = scheme->value;
    else if ((o->integrator = fricreg_integrator_from_name(text)) != 0)
        o->scheme = SCHEME_GSL;
    else {
        char words[64], names[256], what[340];
        snprintf(what, sizeof what, "unknown integrator (%s%s)",
                 cli_join_words(words, sizeof words, schemes, ", "),
                 gsl_stepper_names(names, sizeof names));
        return cli_usage_error(row->name, what);
    }
    return 0;
}

/* --output-dofs LIST: its syntax now, its range once the model is read (dof_list.h). */
static int parse_output_dofs(const struct cli_option *row, const char *text)
{
    struct structure_options *o = row->slot;
    o->output_dofs = text;
    return cli_check_dof_list(row->name, &cli_dof_list, text);
}

/* --output-contacts LIST or none: its syntax now, its range once J is read. */
static int parse_output_contacts(const struct cli_option *row, const char *text)
{
    struct structure_options *o = row->slot;
    o->output_contacts = text;
    return strcmp(text, "none") == 0 ? 0 : cli_check_dof_list(row->name, &cli_contact_list, text);
}

/* --output-elements LIST or none: its syntax now, its range once the elements are read. */
static int parse_output_elements(const struct cli_option *row, const char *text)
{
    struct structure_options *o = row->slot;
    o->output_elements = text;
    return strcmp(text, "none") == 0 ? 0 : cli_check_dof_list(row->name, &cli_element_list, text);
}

/* Options that need others, or exclude them. */
static int check_options(const struct structure_options *o)
{
    static const char *const required[] = {"--mass", "--stiffness"};
    const char *given[] = {o->mass, o->stiffness};
    for (size_t k = 0; k < 2; k++)
        if (given[k] == NULL)
            return cli_usage_error(required[k], "missing (a file is required)");
    if ((o->contacts == NULL) != (o->mun == NULL))
        return cli_usage_error(o->contacts == NULL ? "--contacts" : "--mun",
                               "missing: --contacts and --mun come together (neither: no "
                               "friction contacts)");
    if (o->contacts == NULL && (o->eps_given || o->law_given))
        return cli_usage_error(o->eps_given ? "--eps" : "--law",
                               "the friction law of the contacts: without --contacts there is "
                               "none");
    if (o->load_history != NULL && o->load == NULL)
        return cli_usage_error("--load-history", "the time function of --load P.mtx: give both");
    if (o->output_every_given && o->output != CLI_TRAJECTORY)
        return cli_usage_error("--output-every", "only --output trajectory writes rows");
    if (o->output_contacts != NULL && o->output != CLI_TRAJECTORY)
        return cli_usage_error("--output-contacts",
                               "only --output trajectory writes force columns");
    if (o->output_elements != NULL && o->output != CLI_TRAJECTORY)
        return cli_usage_error("--output-elements",
                               "only --output trajectory writes element columns");
    if (o->dt == 0.0)
        return cli_usage_error("--dt", "missing");
    if (o->t_end == 0.0)
        return cli_usage_error("--t-end", "missing");
    if (o->t_end / o->dt > 2147483647.0)
        return cli_usage_error("--dt", "more than 2^31 steps to --t-end");
    if (o->damping != NULL && o->rayleigh_given)
        return cli_usage_error("--rayleigh", "give --damping or --rayleigh, not both");
    if (o->alpha_given && o->scheme != SCHEME_HHT)
        return cli_usage_error("--alpha", "only --integrator hht has alpha");
    if (cli_check_element_sets_alone(&o->element_sets, &o->elements) != 0)
        return CLI_EXIT_USAGE;
    if (o->element_sets.n > 0 && o->scheme == SCHEME_GSL)
        return cli_usage_error("--elements", "elements are integrated by newmark, hht or central "
                                             "only");
    int status = cli_check_elements(&o->elements, 0);
    if (status != 0)
        return status;
    if ((o->elements.rows != NULL || o->elements.rows_2d != NULL) && o->scheme == SCHEME_GSL)
        return cli_usage_error(o->elements.rows != NULL ? "--jenkins" : "--jenkins-2d",
                               "Jenkins elements are integrated by newmark, hht or central only");
    if ((o->rtol > 0.0 || o->atol != 0.0) && o->scheme != SCHEME_GSL)
        return cli_usage_error(o->rtol > 0.0 ? "--rtol" : "--atol",
                               "only GSL's steppers are adaptive");
    if (o->error_companions == FRICREG_COMPANIONS_COARSER && o->error_estimate &&
        o->output == CLI_SUMMARY && o->scheme == SCHEME_GSL &&
        !(o->rtol > 0.0 || o->atol != 0.0)) /* a call per --dt: the companions' 4 dt never fits */
        return cli_usage_error("--error-companions",
                               "coarser companions need 4 steps per call; GSL's fixed steps are "
                               "called per --dt: use newmark, hht or central, or --rtol");
    return o->scheme == SCHEME_GSL ? cli_check_tolerances(o->integrator, o->rtol, o->atol) : 0;
}

/* --integrator's placeholder: the schemes and the GSL steppers, as the parser takes them. */
static const char *integrator_meta(void)
{
    static char meta[320];
    if (meta[0] == '\0') {
        char names[256];
        gsl_stepper_names(names, sizeof names);
        size_t used = 0;
        for (size_t k = 0; schemes[k].word != NULL; k++)
            used += (size_t)snprintf(meta + used, sizeof meta - used, "%s%s", k ? "|" : "",
                                     schemes[k].word);
        for (char *c = names; *c != '\0'; c++) /* ", rk2, rk4" -> "|rk2|rk4" */
            if (*c == ',')
                *c = '|';
        for (const char *c = names; *c != '\0' && used + 1 < sizeof meta; c++)
            if (*c != ' ')
                meta[used++] = *c;
        meta[used] = '\0';
    }
    return meta;
}

/* The rows over o, its defaults set: the parser's and the help's one table. */
static const struct cli_word contact_solver_words[] = {{"auto", FRICREG_CONTACT_SOLVER_AUTO},
                                                       {"dense", FRICREG_CONTACT_SOLVER_DENSE},
                                                       {"sparse", FRICREG_CONTACT_SOLVER_SPARSE},
                                                       {NULL, 0}};

static size_t structure_table(struct structure_options *o, struct cli_option table[])
{
    *o = (struct structure_options){.law = FRICREG_LAW_QUINN,
                                    .scheme = SCHEME_NEWMARK,
                                    .alpha = -0.05,
                                    .output = CLI_SUMMARY,
                                    .max_steps = -1,
                                    .error_estimate = 1,
                                    .error_companions = FRICREG_COMPANIONS_AUTO,
                                    .answer_rtol = CLI_ANSWER_RTOL,
                                    .output_every = 1};
    cli_element_defaults(&o->elements);
    const struct cli_option opts[] = {
        {"--mass", CLI_FILE, .slot = &o->mass, .meta = "M.mtx",
         .help = "mass matrix M, Matrix Market n x n, symmetric positive definite (required)"},
        {"--stiffness", CLI_FILE, .slot = &o->stiffness, .meta = "K.mtx",
         .help = "stiffness matrix K, n x n, symmetric (required)"},
        {"--damping", CLI_FILE, .slot = &o->damping, .meta = "C.mtx",
         .help = "damping matrix C, n x n, symmetric (or --rayleigh; none: undamped)"},
        {"--contacts", CLI_FILE, .slot = &o->contacts, .meta = "J.mtx",
         .help = "contact rows, m x n: contact i's velocity is (J u')_i (with --mun)",
         .dflt = "none: no friction contacts, plain linear dynamics (and the elements)"},
        {"--mun", CLI_FILE, .slot = &o->mun, .meta = "MUN.txt",
         .help = "the m contacts' friction bounds mu N_i >= 0, N (with --contacts)",
         .dflt = "none"},
        {"--influence", CLI_FILE, .slot = &o->influence, .meta = "R.mtx",
         .help = "the ground motion's influence vector r, n x 1",
         .dflt = "1: every dof moves with the ground"},
        {"--ground-accel", CLI_FILE, .slot = &o->ground, .meta = "FILE",
         .help = "ground acceleration record: lines t a_g (s, m/s^2) on a uniform grid, linear "
                 "between samples",
         .dflt = "none"},
        {"--load", CLI_FILE, .slot = &o->load, .meta = "P.mtx",
         .help = "external load p(t) = P g(t): its pattern P, Matrix Market n x 1, N",
         .dflt = "none"},
        {"--load-history", CLI_FILE, .slot = &o->load_history, .meta = "FILE",
         .help = "the load's time function g: lines t g (s, dimensionless) on a uniform grid, "
                 "linear between samples, 0 outside, as --ground-accel",
         .dflt = "g = 1 at all times: a constant load from t = 0"},
        CLI_ELEMENT_OPTIONS(&o->elements),
        {"--elements", CLI_CUSTOM, .slot = &o->element_sets, .parse = cli_parse_element_set,
         .repeatable = 1, .meta = CLI_ELEMENT_SET_META, .help = cli_element_set_help(),
         .dflt = "none"},
        {"--rayleigh", CLI_CUSTOM, .slot = o, .parse = parse_rayleigh, .given = &o->rayleigh_given,
         .meta = "A0,A1", .help = "Rayleigh damping C = A0 M + A1 K (A0 in 1/s, A1 in s, >= 0)"},
        {"--integrator", CLI_CUSTOM, .slot = o, .parse = parse_integrator,
         .meta = integrator_meta(),
         .help = "newmark (average acceleration), hht (HHT-alpha, --alpha), central (explicit "
                 "central difference), or a GSL stepper",
         .dflt = "newmark"},
        {"--law", CLI_NAME, .slot = &o->law, .names = &cli_law_names, .given = &o->law_given,
         .help = "the contacts' friction law"},
        {"--output", CLI_CHOICE, .slot = &o->output, .words = cli_output_words,
         .help = "a JSON summary, or a CSV row per step"},
        {"--output-dofs", CLI_CUSTOM, .slot = o, .parse = parse_output_dofs, .meta = "LIST",
         .help = "the dofs the trajectory's columns and the summary's per-dof arrays show, "
                 "numbered from 1, e.g. 1-10,57 (in the order given, each once)",
         .dflt = "all"},
        {"--output-contacts", CLI_CUSTOM, .slot = o, .parse = parse_output_contacts, .meta = "LIST",
         .help = "the contacts (rows of J) whose force columns the trajectory shows, numbered "
                 "from 1 as --output-dofs's dofs, or none",
         .dflt = "all"},
        {"--output-elements", CLI_CUSTOM, .slot = o, .parse = parse_output_elements, .meta = "LIST",
         .help = "the elements whose columns the trajectory shows, numbered from 1 in the order "
                 "added, as --output-dofs's dofs: each one's forces eI_f1.. (tangential, then "
                 "normal) and its sliders' slips eI_s1..",
         .dflt = "none"},
        {"--output-every", CLI_WHOLE, .slot = &o->output_every, .lo = 1, .hi = 1e9,
         .given = &o->output_every_given, .meta = "K",
         .help = "trajectory only: a row every K-th step (step times k dt, k a multiple of K), "
                 "and always the run's first and last"},
        {"--eps", CLI_POSITIVE, .slot = &o->eps, .given = &o->eps_given, .meta = "EPS",
         .help = "the law's regularization, m/s",
         .dflt = "1 % of the ground's peak velocity; 1e-3 without a record"},
        {"--dt", CLI_POSITIVE, .slot = &o->dt, .meta = "STEP",
         .help = "time step, s; with --rtol the output interval, the GSL stepper's first step "
                 "(its steps in between are adaptive) (required)",
         .dflt = ""},
        {"--t-end", CLI_POSITIVE, .slot = &o->t_end, .meta = "T",
         .help = "end time, s; the last step lands on it (required)", .dflt = ""},
        {"--rtol", CLI_NONNEGATIVE, .slot = &o->rtol, .meta = "R",
         .help = "GSL steppers only: relative tolerance of adaptive step control (0: fixed)"},
        {"--atol", CLI_NONNEGATIVE, .slot = &o->atol, .given = &o->atol_given, .meta = "A",
         .help = "GSL steppers only: absolute tolerance; with --rtol R and without it, each "
                 "velocity a contact reads gets min(1e-3 eps / max_i sum_k |J_ik|, R)",
         .dflt = "0, or from eps"},
        {"--alpha", CLI_NUMBER, .slot = &o->alpha, .given = &o->alpha_given, .meta = "A",
         .help = "hht's alpha, in [-1/3, 0]"},
        {"--max-steps", CLI_WHOLE, .slot = &o->max_steps, .lo = 0, .hi = 1e9, .meta = "N",
         .help = "GSL's adaptive steps over the whole run (0: no bound)",
         .dflt = "the library's bound on each sample's call"},
        {"--checkpoint-in", CLI_FILE, .slot = &o->checkpoint_in, .meta = "FILE",
         .help = "continue the run saved by --checkpoint-out, set up with the same options, "
                 "from its time to --t-end",
         .dflt = "none: from t = 0"},
        {"--checkpoint-out", CLI_FILE, .slot = &o->checkpoint_out, .meta = "FILE",
         .help = "save the run's state at --t-end into FILE (this build and machine only); an "
                 "existing FILE is replaced, once the new one is complete",
         .dflt = "none"},
        {"--error-estimate", CLI_CHOICE, .slot = &o->error_estimate, .words = cli_estimator_words,
         .help = "companion runs at eps/2 and eps/4 add an error estimate to the summary "
                 "(one: 1.6's single companion at eps/2)"},
        {"--error-companions", CLI_CHOICE, .slot = &o->error_companions,
         .words = cli_companions_words,
         .help = "where the estimate's companions sit: auto screens with the coarser and "
                 "confirms with the finer where the screen would warn or fails; finer (eps/2 at "
                 "dt/2, eps/4 at dt/4: about 6x the run's cost); coarser (2 eps at 2 dt, 4 eps "
                 "at 4 dt: about 0.7x, bounding the error less often and warning on many runs "
                 "within the tolerance; not with GSL's fixed steps)",
         .dflt = "auto"},
        {"--contact-solver", CLI_CHOICE, .slot = &o->contact_solver, .words = contact_solver_words,
         .help = "newmark and hht: the near-stick block's solver, dense (a factor of the block "
                 "of J K_eff^-1 J^T) or sparse (one of K_eff + J^T T J); auto takes the dense "
                 "path, the faster on every case measured but one (docs/benchmark.md)",
         .dflt = "auto"},
        {"--answer-rtol", CLI_POSITIVE, .slot = &o->answer_rtol, .meta = "X",
         .help = "warn (error_estimate) where the largest peak's estimate exceeds X times the "
                 "largest peak, or the dissipations' summed estimate X times their sum, "
                 "whatever the kinds"}};
    return cli_copy_rows(table, opts, sizeof opts / sizeof opts[0]);
}

int cli_parse_structure(int argc, char **argv, struct structure_options *o)
{
    struct cli_option table[CLI_MAX_ROWS];
    size_t n = structure_table(o, table);
    int status = cli_parse_options(argc, argv, table, n, "structure");
    /* adaptive: the rule from eps, as the sim's runs; with no contact reading a dof the rule
     * is atol = rtol (fricreg_structure_run_ode), which the one contact of bound 0 standing in
     * for none (structure_model.h) would change */
    if (!o->atol_given && o->rtol > 0.0)
        o->atol = o->contacts != NULL ? FRICREG_ATOL_FROM_EPS : o->rtol;
    return status != 0 ? status : check_options(o);
}

/* ---- The help (help.c) -------------------------------------------------------------------- */

static size_t structure_help_table(struct cli_option table[])
{
    static struct structure_options o; /* the help's rows point here */
    return structure_table(&o, table);
}

const struct cli_command cli_structure_command = {
    "structure",
    "--mass M.mtx --stiffness K.mtx [--damping C.mtx | --rayleigh A0,A1] [--contacts J.mtx "
    "--mun MUN.txt] [--ground-accel FILE] [--load P.mtx [--load-history FILE]] [ELEMENTS] "
    "--dt STEP --t-end T [--integrator I] [OPTION]...",
    "a structure from Matrix Market files: contacts, joint elements",
    "A linear structure M u'' + C u' + K u = P g(t) - M r a_g(t) + J^T f with friction contacts "
    "(fricreg_structure.h; none without --contacts: plain linear dynamics), an external load "
    "P g(t) and a ground motion a_g(t), and optionally Jenkins, Iwan or lift-off elements "
    "(ELEMENTS: "
    "--jenkins J.mtx with --jenkins-params, --iwan-params or --iwan-segalman, or --normal "
    "with --normal-params; --jenkins-2d J2.mtx with --jenkins-params, or with --normal and "
    "--normal-params for 3-D contact elements; or --elements TYPE:J.mtx:P.txt, repeatable, sets "
    "of the kernel's types mixed in one structure), run with Newmark (the default), HHT-alpha, "
    "central differences or a GSL stepper; "
    "a JSON summary with the energy balance, or a CSV row per step (--output-dofs, "
    "--output-contacts and --output-every select the columns and the rows; "
    "docs/structural.md).",
    structure_help_table};
