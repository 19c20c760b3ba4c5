/* SPDX-License-Identifier: GPL-3.0-or-later */
/* structure.c — `fricreg-sim structure`: a linear structure with friction contacts
 * (fricreg_structure.h) from Matrix Market files, run with Newmark, HHT-alpha, central
 * difference or one of GSL's steppers; a JSON summary or a CSV row per step on stdout.
 * Every bad option or file is one line on stderr naming it, exit 2, nothing on stdout. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "base/companion_estimate.h" /* fr_estimate_kind_name */
#include "cli_structure.h"
#include "dof_list.h"
#include "input_line.h"
#include "out_file.h"
#include "structure_model.h"

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
         .help = "where the estimate's companions sit: finer (eps/2 at dt/2, eps/4 at dt/4) or "
                 "coarser (2 eps at 2 dt, 4 eps at 4 dt: about 0.7x the run's cost instead of "
                 "6x, bounding the error less often; not with GSL's fixed steps)"},
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

/* ---- Setting up the structure ------------------------------------------------------------ */

/* The default eps, 1 % of the ground's peak velocity |integral of a_g| as the library computes
 * it for its warnings (a velocity scale known before the run; docs/structural.md, "Choosing
 * eps"), or the library's 1e-3 without motion. */
static double default_eps(const fricreg_structure *s)
{
    double peak = 0.0;
    fricreg_structure_get_value(s, FRICREG_SVALUE_GROUND_PGV, &peak);
    return peak > 0.0 ? 0.01 * peak : 1e-3;
}

static int set_scheme(fricreg_structure *s, const struct structure_options *o)
{
    int status = FRICREG_OK;
    if (o->scheme == SCHEME_HHT && (status = fricreg_structure_set_hht(s, o->alpha)) != 0)
        return cli_usage_error("--alpha", fricreg_structure_errmsg(s));
    if (o->scheme == SCHEME_CENTRAL)
        status = fricreg_structure_set_central_difference(s);
    return status == FRICREG_OK ? 0 : cli_usage_error("--integrator", fricreg_structure_errmsg(s));
}

static int setup(const struct structure_options *o, const struct structure_input *in,
                 fricreg_structure *s, double *eps)
{
    int status = cli_set_model(o, in, s);
    if (status != 0)
        return status;
    *eps = o->eps > 0.0 ? o->eps : default_eps(s);
    int law_status = fricreg_structure_set_law(s, o->law, *eps);
    if (law_status != FRICREG_OK && o->eps > 0.0)
        return cli_usage_error("--eps", fricreg_structure_errmsg(s));
    if (law_status != FRICREG_OK) { /* the default, from the record: name the record */
        char why[320];
        snprintf(why, sizeof why,
                 "the default eps, 1 %% of the record's peak ground velocity, is %g, which the "
                 "law refuses (%s): check the record's times, or give --eps",
                 *eps, fricreg_structure_errmsg(s));
        return cli_usage_error("--ground-accel", why);
    }
    /* The library's error estimate (companions at eps / 2 and eps / 4 along dt, or an adaptive
     * run's tolerances; one with --error-estimate one): the summary's only, a trajectory has
     * no place for it. */
    if (o->error_estimate && o->output == CLI_SUMMARY) {
        fricreg_structure_set_error_estimate(s, o->error_estimate);
        fricreg_structure_set_error_companions(s, o->error_companions); /* the parser's 0, 1 */
    }
    fricreg_structure_set_answer_rtol(s, o->answer_rtol);       /* > 0 and finite: the parser's */
    fricreg_structure_set_contact_solver(s, o->contact_solver); /* one of the words' */
    return set_scheme(s, o);
}

/* ---- Running ------------------------------------------------------------------------------ */

/* What a run collects beside the structure's own records. */
struct structure_run {
    double *u, *v, *f, *peak; /* [n], [n], [mlib], [n] */
    double *De; /* [2 me]: the elements' dissipation, the 2-D forces; --elements: [me + the
                 * sets' forces] (NULL without elements) */
    FILE *rows; /* CSV rows, or NULL */
    /* What the output shows: the dofs dof[ndof] (0-based; NULL: all n in order), and in the
     * trajectory the contacts contact[ncontact] (NULL: all m in order) of the m of the files
     * (0 without --contacts: not the one of bound 0 standing in). */
    const size_t *dof, *contact;
    size_t ndof, ncontact, m;
    /* --output-every K: a row at step times k dt with k a multiple of every, and at the run's
     * first (rows = 0) and last (t = t_end) */
    double dt, t_end;
    int64_t every, rows_written;
};

/* The k-th dof shown: the selection's, or k itself. */
static size_t shown(const struct structure_run *run, size_t k)
{
    return run->dof != NULL ? run->dof[k] : k;
}

/* The k-th contact shown in the trajectory: the selection's, or k itself. */
static size_t contact_shown(const struct structure_run *run, size_t k)
{
    return run->contact != NULL ? run->contact[k] : k;
}

static void csv_header(const struct structure_run *run)
{
    FILE *out = run->rows;
    fputs("t", out);
    for (size_t k = 0; k < run->ndof; k++)
        fprintf(out, ",u%zu", shown(run, k) + 1);
    for (size_t k = 0; k < run->ndof; k++)
        fprintf(out, ",v%zu", shown(run, k) + 1);
    for (size_t k = 0; k < run->ncontact; k++)
        fprintf(out, ",f%zu", contact_shown(run, k) + 1);
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

/* A CSV row of the state (t, u and v at the dofs shown, f[m]). */
static void csv_row(struct structure_run *run, double t, const double u[], const double v[],
                    const double f[])
{
    FILE *out = run->rows;
    fprintf(out, "%.17g", t);
    for (size_t k = 0; k < run->ndof; k++)
        fprintf(out, ",%.17g", u[shown(run, k)]);
    for (size_t k = 0; k < run->ndof; k++)
        fprintf(out, ",%.17g", v[shown(run, k)]);
    for (size_t k = 0; k < run->ncontact; k++)
        fprintf(out, ",%.17g", f[contact_shown(run, k)]);
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

static double svalue(const fricreg_structure *s, int which)
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

/* Steps of dt to t_end, the last one shortened, the state observed after each: the
 * structure's own schemes in one fricreg_structure_run (its observer writing the rows), GSL's
 * steppers from sample to sample (adaptive ones restart at each with dt as their first step,
 * within --max-steps over the whole run). */
static int advance(fricreg_structure *s, const struct structure_options *o,
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
    double t = svalue(s, FRICREG_SVALUE_TIME);
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

static int64_t sstat(const fricreg_structure *s, int which)
{
    int64_t v = 0;
    fricreg_structure_get_stat(s, which, &v);
    return v;
}

/* The library's warnings on the structure and its run (fricreg_structure_warning_count, judged
 * by the caller after the run), each printed once on stderr. */
static void structure_warnings(fricreg_structure *s, struct cli_warnings *w)
{
    size_t count = fricreg_structure_warning_count(s);
    w->n = 0;
    for (size_t k = 0; k < count && w->n < 16; k++, w->n++)
        fricreg_structure_get_warning(s, k, &w->code[w->n], w->message[w->n], sizeof w->message[0]);
    cli_print_warnings(w);
}

static const char *scheme_name(const struct structure_options *o)
{
    static const char *const names[] = {"newmark", "hht", "central"};
    return o->scheme == SCHEME_GSL ? fricreg_integrator_name(o->integrator) : names[o->scheme];
}

/* The error estimates of the headline quantities against eps -> 0, the library's
 * (fricreg_structure_set_error_estimate: a companion at eps / 2 and dt / 2, or tolerances / 16,
 * err = 3 |q - q_companion|; docs/structural.md, "Error estimate"). NULL arrays: none made. */
struct structure_estimate {
    double *peak_err, *D_err, *De_err; /* [n], [m], [me]; +infinity where a companion failed */
    int *peak_kind, *D_kind, *De_kind; /* their kinds (enum fricreg_estimate_kind) */
};

/* "name": [a at the dofs shown], as cli_json_array. */
static void json_shown(FILE *out, const char *name, const struct structure_run *run,
                       const double a[])
{
    if (run->dof == NULL) {
        cli_json_array(out, name, run->ndof, a);
        return;
    }
    fprintf(out, ", \"%s\": [", name);
    for (size_t k = 0; k < run->ndof; k++) {
        fputs(k > 0 ? ", " : "", out);
        cli_json_number(out, a[run->dof[k]]);
    }
    fputs("]", out);
}

/* ", \"NAME\": [the kinds at the dofs shown]", as json_shown; counted into *c. */
static void kinds_shown(FILE *out, const char *name, const struct structure_run *run,
                        const int kind[], struct cli_kind_counts *c)
{
    if (run->dof == NULL) {
        cli_json_kinds(out, name, run->ndof, kind);
        cli_count_kinds(c, run->ndof, kind);
        return;
    }
    fprintf(out, ", \"%s\": [", name);
    for (size_t k = 0; k < run->ndof; k++) {
        const int *shown = &kind[run->dof[k]];
        cli_count_kinds(c, 1, shown);
        fprintf(out, "%s\"%s\"", k > 0 ? ", " : "", fr_estimate_kind_name(*shown));
    }
    fputs("]", out);
}

/* run_ode's tolerances per component (u, v, W_in, E_visc, D_1 .. D_m), the dofs' entries
 * those shown, the contacts' the files' (none of the one standing in for none). */
static void json_atol(FILE *out, const struct structure_input *in, const fricreg_structure *s,
                      const struct structure_run *run)
{
    size_t dim = 2 * in->n + 2 + in->mlib;
    double *atol = malloc(dim * sizeof *atol);
    if (atol == NULL || fricreg_structure_get_ode_abs_tolerances(s, dim, atol) != FRICREG_OK) {
        free(atol);
        return;
    }
    fputs(", \"atol_used\": [", out);
    for (size_t k = 0; k < 2 * run->ndof; k++) {
        fputs(k > 0 ? ", " : "", out);
        cli_json_number(out, atol[shown(run, k % run->ndof) + (k < run->ndof ? 0 : in->n)]);
    }
    for (size_t k = 2 * in->n; k < 2 * in->n + 2 + in->m; k++) {
        fputs(", ", out);
        cli_json_number(out, atol[k]);
    }
    fputs("]", out);
    free(atol);
}

/* The --elements sets' fields, in the order of the old options' (njenkins ...
 * jenkins_dissipation, element_kind): their count, each element's dissipation (and its error
 * estimate), the sum, the kind, each set's type and sliders, and each element's force, its
 * dim components. De[me + nforces] is room for the dissipations and forces. */
static void write_element_sets(FILE *out, const fricreg_structure *s,
                               const struct cli_element_sets *sets, double *De,
                               const struct structure_estimate *est, struct cli_kind_counts *kinds)
{
    double *f = De + sets->me;
    fricreg_structure_get_elements(s, sets->me, f, NULL, De);
    fprintf(out, ", \"nelements\": %zu", sets->me);
    cli_json_array(out, "dissipation_per_element", sets->me, De);
    if (est->De_err != NULL) {
        cli_json_array(out, "dissipation_per_element_error_estimate", sets->me, est->De_err);
        cli_json_kinds(out, "dissipation_per_element_error_kind", sets->me, est->De_kind);
        cli_count_kinds(kinds, sets->me, est->De_kind);
    }
    fprintf(out, ", \"element_dissipation\": %.17g", svalue(s, FRICREG_SVALUE_JENKINS));
    cli_json_element_sets(out, sets);
    fputs(", \"element_forces\": [", out);
    for (size_t k = 0, i = 0; k < sets->n; k++)
        for (size_t e = 0; e < sets->set[k].me; e++, i++) { /* element i's dim components */
            fputs(i > 0 ? ", [" : "[", out);
            for (size_t c = 0; c < sets->set[k].dim; c++, f++) {
                fputs(c > 0 ? ", " : "", out);
                cli_json_number(out, *f);
            }
            fputs("]", out);
        }
    fputs("]", out);
}

static void write_summary(FILE *out, const struct structure_options *o,
                          const struct structure_input *in, const fricreg_structure *s,
                          const struct structure_run *run, double eps, double cpu_seconds,
                          const struct cli_warnings *warnings, const struct structure_estimate *est)
{
    int64_t steps = sstat(s, FRICREG_SSTAT_STEPS);
    double *D = run->f; /* the forces are not needed any more */
    fricreg_structure_get_dissipation(s, in->mlib, D);
    fricreg_structure_get_state(s, in->n, run->u, run->v, NULL);
    fprintf(out, "{\"system\": \"structure\", \"law\": \"%s\", \"integrator\": \"%s\", ",
            fricreg_law_name(o->law), scheme_name(o));
    if (o->scheme == SCHEME_HHT)
        fprintf(out, "\"alpha\": %.17g, ", o->alpha);
    if (o->scheme == SCHEME_NEWMARK || o->scheme == SCHEME_HHT) { /* the path in force */
        int solver = FRICREG_CONTACT_SOLVER_DENSE;
        fricreg_structure_get_contact_solver(s, &solver);
        fprintf(out, "\"contact_solver\": \"%s\", ",
                solver == FRICREG_CONTACT_SOLVER_SPARSE ? "sparse" : "dense");
    }
    int adaptive = o->rtol > 0.0 || o->atol != 0.0;
    fprintf(out, "\"adaptive\": %s, \"dt\": %.17g, \"rtol\": %.17g, \"atol\": ",
            adaptive ? "true" : "false", o->dt, o->rtol);
    if (o->atol == FRICREG_ATOL_FROM_EPS) /* as the sim's summaries (output.c) */
        fprintf(out, "\"eps\", ");
    else
        fprintf(out, "%.17g, ", o->atol);
    fprintf(out,
            "\"eps\": %.17g, \"steps\": %lld, \"t\": %.17g, \"ndof\": %zu, "
            "\"ncontacts\": %zu",
            eps, (long long)steps, svalue(s, FRICREG_SVALUE_TIME), in->n, in->m);
    if (run->dof != NULL) { /* --output-dofs: the dofs the per-dof arrays show, from 1 */
        fputs(", \"output_dofs\": [", out);
        for (size_t k = 0; k < run->ndof; k++)
            fprintf(out, "%s%zu", k > 0 ? ", " : "", run->dof[k] + 1);
        fputs("]", out);
    }
    json_shown(out, "x", run, run->u);
    json_shown(out, "v", run, run->v);
    if (adaptive)
        json_atol(out, in, s, run);
    json_shown(out, "peak_displacement", run, run->peak);
    struct cli_kind_counts kinds = {{0}};
    if (est->peak_err != NULL) {
        json_shown(out, "peak_displacement_error_estimate", run, est->peak_err);
        kinds_shown(out, "peak_displacement_error_kind", run, est->peak_kind, &kinds);
    }
    cli_json_array(out, "dissipation_per_contact", in->m, D);
    if (est->D_err != NULL) {
        cli_json_array(out, "dissipation_per_contact_error_estimate", in->m, est->D_err);
        cli_json_kinds(out, "dissipation_per_contact_error_kind", in->m, est->D_kind);
        cli_count_kinds(&kinds, in->m, est->D_kind);
    }
    const struct cli_elements *el = &in->el;
    if (el->m > 0) {
        fprintf(out, ", \"njenkins\": %zu", el->m);
        fricreg_structure_get_jenkins_state(s, el->m, NULL, NULL, run->De);
        cli_json_array(out, "dissipation_per_jenkins", el->m, run->De);
        if (est->De_err != NULL) {
            cli_json_array(out, "dissipation_per_jenkins_error_estimate", el->m, est->De_err);
            cli_json_kinds(out, "dissipation_per_jenkins_error_kind", el->m, est->De_kind);
            cli_count_kinds(&kinds, el->m, est->De_kind);
        }
        fprintf(out, ", \"jenkins_dissipation\": %.17g, \"element_kind\": \"%s\"",
                svalue(s, FRICREG_SVALUE_JENKINS), cli_element_kind_name(el));
        if (el->kind == CLI_ELEMENTS_IWAN || el->kind == CLI_ELEMENTS_IWAN_NORMAL)
            fprintf(out, ", \"sliders_per_element\": %zu", el->ns);
        int planar = el->kind == CLI_ELEMENTS_JENKINS_2D || el->kind == CLI_ELEMENTS_CONTACT_3D;
        if (planar) { /* element i's [f_x, f_y], as J_e's rows */
            fricreg_structure_get_jenkins_2d_state(s, el->m, run->De, NULL, NULL);
            fputs(", \"jenkins_forces\": [", out);
            for (size_t i = 0; i < el->m; i++) {
                fputs(i > 0 ? ", [" : "[", out);
                cli_json_number(out, run->De[2 * i]);
                fputs(", ", out);
                cli_json_number(out, run->De[2 * i + 1]);
                fputs("]", out);
            }
            fputs("]", out);
        }
        if (el->kind == CLI_ELEMENTS_NORMAL || el->kind == CLI_ELEMENTS_CONTACT_3D ||
            el->kind == CLI_ELEMENTS_IWAN_NORMAL) {
            fricreg_structure_get_normal_forces(s, el->m, run->De);
            cli_json_array(out, "normal_forces", el->m, run->De);
        }
    }
    if (in->sets.me > 0)
        write_element_sets(out, s, &in->sets, run->De, est, &kinds);
    if (est->peak_err != NULL)
        cli_json_kind_counts(out, &kinds);
    fprintf(out,
            ", \"energy_balance\": {\"initial\": %.17g, \"input\": %.17g, "
            "\"kinetic\": %.17g, \"strain\": %.17g, \"viscous\": %.17g, \"friction\": %.17g, ",
            svalue(s, FRICREG_SVALUE_INITIAL), svalue(s, FRICREG_SVALUE_INPUT),
            svalue(s, FRICREG_SVALUE_KINETIC), svalue(s, FRICREG_SVALUE_STRAIN),
            svalue(s, FRICREG_SVALUE_VISCOUS), svalue(s, FRICREG_SVALUE_FRICTION));
    if (el->m > 0 || in->sets.me > 0) /* every element's, whatever its type */
        fprintf(out, "\"jenkins\": %.17g, ", svalue(s, FRICREG_SVALUE_JENKINS));
    fprintf(out, "\"residual\": %.17g}", svalue(s, FRICREG_SVALUE_RESIDUAL));
    int64_t iterations = sstat(s, FRICREG_SSTAT_NEWTON_ITERATIONS);
    fprintf(out,
            ", \"newton_iterations\": {\"mean\": %.17g, \"max\": %lld}, "
            "\"newton_failures\": %lld, \"cpu_seconds\": %.6f",
            steps > 0 ? (double)iterations / (double)steps : 0.0,
            (long long)sstat(s, FRICREG_SSTAT_NEWTON_MAX),
            (long long)sstat(s, FRICREG_SSTAT_NEWTON_FAILURES), cpu_seconds);
    if (est->peak_err != NULL) /* the estimate's share of cpu_seconds */
        fprintf(out, ", \"error_companions\": \"%s\", \"companion_cpu_seconds\": %.6f",
                o->error_companions == FRICREG_COMPANIONS_COARSER ? "coarser" : "finer",
                svalue(s, FRICREG_SVALUE_COMPANION_CPU));
    cli_json_warnings(out, warnings);
    fputs("}\n", out);
}

/* The library's estimates into est (one allocation, at est->peak_err, and one of their kinds,
 * at est->peak_kind), if it made them. */
static void read_estimate(const fricreg_structure *s, const struct structure_input *in,
                          struct structure_estimate *est)
{
    size_t n = in->n, m = in->mlib, me = in->el.m + in->sets.me; /* one of them 0 */
    double *buf = malloc((n + m + me + 1) * sizeof *buf);
    int *kind = malloc((n + m + me + 1) * sizeof *kind);
    if (buf != NULL && kind != NULL &&
        fricreg_structure_get_peak_displacement_error(s, n, buf) == FRICREG_OK &&
        fricreg_structure_get_dissipation_error(s, m, buf + n) == FRICREG_OK &&
        fricreg_structure_get_jenkins_dissipation_error(s, me, buf + n + m) == FRICREG_OK &&
        fricreg_structure_get_error_kind(s, FRICREG_EST_PEAK_DISPLACEMENT, n, kind) == FRICREG_OK &&
        fricreg_structure_get_error_kind(s, FRICREG_EST_DISSIPATION, m, kind + n) == FRICREG_OK &&
        fricreg_structure_get_error_kind(s, FRICREG_EST_ELEMENT_DISSIPATION, me, kind + n + m) ==
            FRICREG_OK) {
        *est = (struct structure_estimate){buf, buf + n, buf + n + m, kind, kind + n, kind + n + m};
    } else {
        free(buf);
        free(kind);
    }
}

/* A refused step size is a bad --dt (exit 2); any other failure of the run exits 1. */
static int run_failed(const fricreg_structure *s, int status)
{
    double t = svalue(s, FRICREG_SVALUE_TIME);
    if (status == FRICREG_ESTEP) {
        fprintf(stderr, "fricreg-sim: --dt: %s\n", fricreg_structure_errmsg(s));
        return CLI_EXIT_USAGE;
    }
    if (status == FRICREG_EWORK) { /* --max-steps bounds the whole run, not one call */
        fprintf(stderr, "fricreg-sim: --max-steps: the run's adaptive steps passed the bound: %s\n",
                fricreg_structure_errmsg(s));
        return CLI_EXIT_RUN;
    }
    fprintf(stderr, "fricreg-sim: structure: the run failed after t = %g: %s\n", t,
            fricreg_structure_errmsg(s));
    return CLI_EXIT_RUN;
}

static void copy_stream(FILE *from, FILE *to)
{
    char chunk[1 << 16];
    size_t got;
    rewind(from);
    while ((got = fread(chunk, 1, sizeof chunk, from)) > 0)
        fwrite(chunk, 1, got, to);
}

/* ---- Checkpoints (fricreg_structure_save / _restore) ---------------------------------------- */

/* --checkpoint-in: the blob read whole and restored into the set-up structure, whose time must
 * then be before --t-end. 0, or a message naming the file and exit 2. */
static int checkpoint_in(fricreg_structure *s, const struct structure_options *o)
{
    const char *path = o->checkpoint_in;
    FILE *f = fopen(path, "rb");
    if (f == NULL)
        return cli_file_error("--checkpoint-in", path, 0, "cannot open: %s", strerror(errno));
    size_t len = 0, cap = 1 << 16;
    unsigned char *buf = malloc(cap);
    for (size_t got = 1; buf != NULL && got > 0;) {
        got = fread(buf + len, 1, cap - len, f);
        len += got;
        unsigned char *more = len == cap ? realloc(buf, cap *= 2) : buf;
        if (more == NULL)
            free(buf);
        buf = more;
    }
    int read_error = ferror(f);
    fclose(f);
    if (buf == NULL || read_error) {
        free(buf);
        return cli_file_error("--checkpoint-in", path, 0, "%s",
                              read_error ? "cannot read" : "out of memory");
    }
    int status = fricreg_structure_restore(s, buf, len);
    free(buf);
    if (status != FRICREG_OK)
        return cli_file_error("--checkpoint-in", path, 0, "%s", fricreg_structure_errmsg(s));
    double t = svalue(s, FRICREG_SVALUE_TIME);
    if (!(o->t_end > t)) {
        char what[96];
        snprintf(what, sizeof what, "must be after the checkpoint's time %.17g", t);
        return cli_usage_error("--t-end", what);
    }
    return 0;
}

/* --checkpoint-out: the state at the run's end into the file, replaced only once the new one
 * is complete (cli_replace_file). 0, or a message naming it and exit 2. */
static int checkpoint_out(fricreg_structure *s, const char *path)
{
    size_t len = 0;
    unsigned char *buf = NULL;
    int status = fricreg_structure_save(s, NULL, &len);
    if (status == FRICREG_OK && (buf = malloc(len)) == NULL)
        return cli_file_error("--checkpoint-out", path, 0, "out of memory");
    if (status == FRICREG_OK)
        status = fricreg_structure_save(s, buf, &len);
    if (status != FRICREG_OK) {
        free(buf);
        return cli_file_error("--checkpoint-out", path, 0, "%s", fricreg_structure_errmsg(s));
    }
    int err = cli_replace_file(path, buf, len);
    free(buf);
    if (err < 0)
        return cli_file_error("--checkpoint-out", path, 0, "not a regular file: not replaced");
    return err == 0
               ? 0
               : cli_file_error("--checkpoint-out", path, 0, "cannot write: %s", strerror(err));
}

/* The dofs and contacts the output shows (--output-dofs, --output-contacts) into run, their
 * lists into *dof and *contact (the caller frees them; NULL: all). 0 or a usage error. */
static int select_output(const struct structure_options *o, const struct structure_input *in,
                         struct structure_run *run, size_t **dof, size_t **contact)
{
    int status = 0;
    if (o->output_dofs != NULL)
        status = cli_expand_dof_list("--output-dofs", &cli_dof_list, o->output_dofs, in->n,
                                     &run->ndof, dof);
    if (status == 0 && o->output_contacts != NULL && strcmp(o->output_contacts, "none") == 0)
        run->ncontact = 0;
    else if (status == 0 && o->output_contacts != NULL)
        status = cli_expand_dof_list("--output-contacts", &cli_contact_list, o->output_contacts,
                                     in->m, &run->ncontact, contact);
    if (status != 0) {
        free(*dof);
        *dof = NULL;
        return status;
    }
    run->dof = *dof;
    run->contact = *contact;
    return 0;
}

/* Runs the set-up structure; the trajectory goes to a temporary file first, so that a failed
 * run writes nothing to out. */
static int run_structure(fricreg_structure *s, const struct structure_options *o,
                         const struct structure_input *in, double eps, FILE *out)
{
    struct structure_run run = {.ndof = in->n,
                                .ncontact = in->m,
                                .m = in->m,
                                .dt = o->dt,
                                .t_end = o->t_end,
                                .every = o->output_every};
    size_t *dof = NULL, *contact = NULL;
    int listed = select_output(o, in, &run, &dof, &contact);
    if (listed != 0)
        return listed;
    /* De: the old options' 2 me, or the sets' D[me] and forces[nforces] */
    double *buf = calloc(3 * in->n + in->mlib + 2 * in->el.m + in->sets.me + in->sets.nforces,
                         sizeof *buf);
    if (buf == NULL) {
        free(dof);
        free(contact);
        return cli_usage_error("structure", "out of memory");
    }
    run.u = buf;
    run.v = buf + in->n;
    run.peak = buf + 2 * in->n;
    run.f = buf + 3 * in->n;
    run.De = in->el.m > 0 || in->sets.me > 0 ? buf + 3 * in->n + in->mlib : NULL;
    if (o->output == CLI_TRAJECTORY) {
        if ((run.rows = tmpfile()) == NULL) {
            free(buf);
            free(dof);
            free(contact);
            fprintf(stderr, "fricreg-sim: cannot create a temporary file\n");
            return CLI_EXIT_RUN;
        }
        csv_header(&run);
    }
    clock_t start = clock();
    int status = advance(s, o, in, &run);
    double cpu_seconds = (double)(clock() - start) / CLOCKS_PER_SEC;
    struct cli_warnings warnings;
    structure_warnings(s, &warnings);
    struct structure_estimate est = {0};
    fricreg_structure_get_peak_displacement(s, in->n, run.peak);
    if (status == FRICREG_OK)
        read_estimate(s, in, &est);
    if (status != FRICREG_OK)
        status = run_failed(s, status);
    else if (o->checkpoint_out != NULL) /* the run's output only with its checkpoint */
        status = checkpoint_out(s, o->checkpoint_out);
    if (status == 0 && run.rows != NULL)
        copy_stream(run.rows, out);
    else if (status == 0)
        write_summary(out, o, in, s, &run, eps, cpu_seconds, &warnings, &est);
    free(est.peak_err);
    free(est.peak_kind);
    if (run.rows != NULL)
        fclose(run.rows);
    free(buf);
    free(dof);
    free(contact);
    return status;
}

int cli_structure(int argc, char **argv, FILE *out)
{
    struct structure_options o;
    int status = cli_parse_structure(argc, argv, &o);
    if (status != 0)
        return status;
    struct structure_input in = {0};
    if ((status = cli_read_model(&o, &in)) != 0) {
        cli_free_model(&in);
        return status;
    }
    fricreg_structure *s = NULL;
    if (fricreg_structure_create(in.n, in.mlib, &s) != FRICREG_OK) {
        cli_free_model(&in);
        return cli_usage_error("structure", "cannot create the structure (out of memory)");
    }
    double eps = 0.0;
    status = setup(&o, &in, s, &eps);
    cli_free_matrices(&in);
    if (status == 0 && o.checkpoint_in != NULL)
        status = checkpoint_in(s, &o);
    if (status == 0)
        status = run_structure(s, &o, &in, eps, out);
    fricreg_structure_free(s);
    cli_free_model(&in);
    return status;
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
