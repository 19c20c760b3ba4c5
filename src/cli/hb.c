/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb.c — `fricreg-sim hb`: the frequency response of a linear structure with Jenkins, Iwan or
 * lift-off elements (jenkins_input.h; or --elements sets of several kinds, element_sets.h) by
 * harmonic balance (fricreg_hb.h) from Matrix Market
 * files, continued in the excitation frequency from --omega-start to --omega-end (or, with
 * --continue-in level, in the excitation level from --level-start to --level-end at --omega),
 * each point's
 * stability (fricreg_hb_set_stability: the exact monodromy or Hill's method, --stability); a JSON
 * summary (per dof
 * the peak RMS and its frequency, its truncation error estimate, the located bifurcations) or a CSV row per continuation point
 * (and per bifurcation) on stdout. Every bad option or file is one line on stderr naming it, exit 2, nothing on stdout;
 * a continuation that fails, exit 1. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli.h"
#include "cli_hb.h"
#include "fricreg_hb.h"
#include "hb_deadline.h"
#include "hb_model.h"
#include "input_line.h"
#include "jenkins_input.h"

/* Up to this many dofs the summary's peaks are located (fricreg_hb_peak: 10 to 20 corrector
 * solves each); beyond, the largest stored point's, so that a large model's summary costs no
 * more than its continuation. */
enum { HB_LOCATE_MAX = 256 };
static const struct cli_word hb_outputs[] = {{"summary", HB_SUMMARY}, {"frf", HB_FRF}, {NULL, 0}};
static const struct cli_word hb_parameters[] = {{"omega", HB_IN_OMEGA},
                                                {"level", HB_IN_LEVEL},
                                                {NULL, 0}};
static const struct cli_word hb_stabilities[] = {{"auto", FRICREG_HB_STABILITY_AUTO},
                                                 {"hill", FRICREG_HB_STABILITY_HILL},
                                                 {"monodromy", FRICREG_HB_STABILITY_MONODROMY},
                                                 {"condensed", FRICREG_HB_STABILITY_CONDENSED},
                                                 {"off", HB_STABILITY_OFF},
                                                 {NULL, 0}};

/* The model (hb_model.h: its matrices passed sparse to the driver, nothing densified) and the
 * excitation pc[n], ps[n]. */
struct hb_model {
    struct cli_hb_model s;
    size_t n, m;
    double *pc, *ps;
};

static void free_model(struct hb_model *md)
{
    cli_hb_free_model(&md->s);
    free(md->pc);
    free(md->ps);
    memset(md, 0, sizeof *md);
}

static int check_options(const struct hb_options *o)
{
    int status = cli_hb_check_model(&o->model);
    if (status != 0)
        return status;
    if (o->excitation == NULL)
        return cli_usage_error("--excitation", "missing (a file is required)");
    if (o->continue_in == HB_IN_LEVEL) {
        if (o->omega_start_given || o->omega_end_given)
            return cli_usage_error(o->omega_start_given ? "--omega-start" : "--omega-end",
                                   "applies to --continue-in omega (the level's branch is at "
                                   "--omega)");
        if (!o->omega_given)
            return cli_usage_error("--omega", "missing (--continue-in level)");
        if (!o->level_start_given || !o->level_end_given)
            return cli_usage_error(o->level_start_given ? "--level-end" : "--level-start",
                                   "missing (--continue-in level)");
        if (o->level_end == o->level_start)
            return cli_usage_error("--level-end", "equals --level-start: no branch to follow");
        return 0;
    }
    if (o->omega_given || o->level_start_given || o->level_end_given)
        return cli_usage_error(o->omega_given         ? "--omega"
                               : o->level_start_given ? "--level-start"
                                                      : "--level-end",
                               "applies to --continue-in level");
    if (!o->omega_start_given)
        return cli_usage_error("--omega-start", "missing");
    if (!o->omega_end_given)
        return cli_usage_error("--omega-end", "missing");
    if (o->omega_end == o->omega_start)
        return cli_usage_error("--omega-end", "equals --omega-start: no branch to follow");
    return 0;
}

/* The rows over o, its defaults set: the parser's and the help's one table. */
static size_t hb_table(struct hb_options *o, struct cli_option table[])
{
    /* Newton's rule and the step control: the driver's defaults (fricreg_hb_set_newton,
     * fricreg_hb_set_continuation) */
    *o = (struct hb_options){.harmonics = 7,
                             .output = HB_SUMMARY,
                             .newton_tol = 1e-10,
                             .newton_max = 50,
                             .ds = 0.02,
                             .ds_min = 1e-6,
                             .ds_max = 0.1,
                             .max_points = 2000,
                             .stability = FRICREG_HB_STABILITY_AUTO};
    cli_hb_model_defaults(&o->model);
    const struct cli_option opts[] = {
        CLI_HB_MODEL_OPTIONS(&o->model),
        {"--excitation", CLI_FILE, .slot = &o->excitation, .meta = "F.txt",
         .help = "the force's cosine and sine amplitudes, a line pc ps per dof (required)"},
        {"--harmonics", CLI_WHOLE, .slot = &o->harmonics, .lo = 1, .hi = FRICREG_HB_MAX_HARMONICS,
         .meta = "H", .help = "harmonics kept in the solution"},
        {"--omega-start", CLI_POSITIVE, .slot = &o->omega_start, .given = &o->omega_start_given,
         .meta = "W0",
         .help = "excitation frequency the continuation starts at, from q = 0 "
                 "(required)",
         .dflt = ""},
        {"--omega-end", CLI_POSITIVE, .slot = &o->omega_end, .given = &o->omega_end_given,
         .meta = "W1", .help = "excitation frequency it ends at (required)", .dflt = ""},
        {"--continue-in", CLI_CHOICE, .slot = &o->continue_in, .words = hb_parameters,
         .help = "the continued parameter: the excitation frequency, or the excitation level "
                 "(the excitation times a factor) at the fixed --omega"},
        {"--omega", CLI_POSITIVE, .slot = &o->omega, .given = &o->omega_given, .meta = "W",
         .help = "the excitation frequency of the level's branch (required with --continue-in "
                 "level)",
         .dflt = ""},
        {"--level-start", CLI_NONNEGATIVE, .slot = &o->level_start, .given = &o->level_start_given,
         .meta = "L0",
         .help = "excitation level the level's branch starts at (required with --continue-in "
                 "level)",
         .dflt = ""},
        {"--level-end", CLI_NONNEGATIVE, .slot = &o->level_end, .given = &o->level_end_given,
         .meta = "L1", .help = "excitation level it ends at (required with --continue-in level)",
         .dflt = ""},
        {"--newton-tol", CLI_POSITIVE, .slot = &o->newton_tol, .meta = "TOL",
         .help = "Newton's tolerance at each point"},
        {"--newton-max", CLI_WHOLE, .slot = &o->newton_max, .lo = 1, .hi = 1000, .meta = "N",
         .help = "Newton's iterations at most per point, 1 to 1000"},
        {"--ds", CLI_POSITIVE, .slot = &o->ds, .meta = "DS",
         .help = "the continuation's first step, in the arclength of the scaled unknowns"},
        {"--ds-min", CLI_POSITIVE, .slot = &o->ds_min, .meta = "DS",
         .help = "its smallest step: below it the continuation stops"},
        {"--ds-max", CLI_POSITIVE, .slot = &o->ds_max, .meta = "DS",
         .help = "its largest step, <= 1"},
        CLI_DEADLINE_OPTION(&o->deadline),
        {"--max-points", CLI_WHOLE, .slot = &o->max_points, .lo = 2, .hi = 1e8, .meta = "N",
         .help = "points stored at most: reaching it stops the continuation"},
        {"--stability", CLI_CHOICE, .slot = &o->stability, .words = hb_stabilities,
         .help = "each point's stability: by the exact monodromy of the orbit (1-D Jenkins and "
                 "Iwan elements, with or without lift-off, all of one kind: a mix of --elements "
                 "sets is refused), condensed (the same on the model condensed onto the dofs "
                 "the elements touch), by Hill's method (any element, ndof (2H + 1) <= 1024), "
                 "auto (the condensed monodromy where the elements touch at most a quarter of "
                 "32 to 1024 dofs, else the monodromy up to order 512, else the condensed one "
                 "up to 4096 dofs, else Hill's where the size allows it, else none), or off"},
        {"--output", CLI_CHOICE, .slot = &o->output, .words = hb_outputs,
         .help = "a JSON summary (each dof's peak RMS and its frequency, the estimate of its "
                 "error from truncating at H harmonics at the largest stored point, by a solve "
                 "at 2H + 1 harmonics: null where H > 19 or that solve failed, the "
                 "bifurcations, isola: true where the branch closed on itself before the end), "
                 "or the "
                 "frequency response: a CSV row omega,rms_1,...,rms_n,stable,bifurcation,mu_max "
                 "per point (stable 1/0 and mu_max the largest |Floquet multiplier| by "
                 "--stability's method, empty without), and a row at each located bifurcation "
                 "labelled TP, BP, PD or NS; with "
                 "--continue-in level the first column is the level and the summary's peaks "
                 "are the largest points' (peak_level)"}};
    return cli_copy_rows(table, opts, sizeof opts / sizeof opts[0]);
}

int cli_parse_hb(int argc, char **argv, struct hb_options *o)
{
    struct cli_option table[CLI_MAX_ROWS];
    size_t n = hb_table(o, table);
    int status = cli_parse_options(argc, argv, table, n, "hb");
    return status != 0 ? status : check_options(o);
}

static int read_model(const struct hb_options *o, struct hb_model *md)
{
    int status = cli_hb_read_model(&o->model, &md->s);
    md->n = md->s.n;
    md->m = md->s.m;
    if (status == 0)
        status = cli_read_pairs("--excitation", o->excitation, md->n, "degrees of freedom", &md->pc,
                                &md->ps);
    return status;
}

static int set_model(const struct hb_options *o, const struct hb_model *md, fricreg_hb *hb)
{
    size_t n = md->n;
    int status = cli_hb_set_model(&o->model, &md->s, hb);
    if (status != 0)
        return status;
    if (fricreg_hb_set_newton(hb, o->newton_tol, o->newton_max) != FRICREG_OK)
        return cli_usage_error("--newton-tol", fricreg_hb_errmsg(hb));
    /* the library names the order: 0 < ds_min <= ds <= ds_max <= 1 */
    if (fricreg_hb_set_continuation(hb, o->ds, o->ds_min, o->ds_max, (size_t)o->max_points) !=
        FRICREG_OK)
        return cli_usage_error(o->ds_max > 1.0     ? "--ds-max"
                               : o->ds_min > o->ds ? "--ds-min"
                                                   : "--ds",
                               fricreg_hb_errmsg(hb));
    if (fricreg_hb_set_excitation(hb, n, md->pc, md->ps) != FRICREG_OK)
        return cli_file_error("--excitation", o->excitation, 0, "%s", fricreg_hb_errmsg(hb));
    return 0;
}

/* The branch's points: their parameter omega[k] (Ω, or a level branch's λ) and rms[k n + i]
 * of dof i, into arrays the caller frees. */
static int collect(fricreg_hb *hb, int level, size_t n, size_t *npoints, double **omega,
                   double **rms)
{
    size_t K = fricreg_hb_points(hb);
    *omega = malloc((K > 0 ? K : 1) * sizeof **omega);
    *rms = malloc((K > 0 ? K * n : 1) * sizeof **rms);
    if (*omega == NULL || *rms == NULL)
        return cli_usage_error("hb", "out of memory");
    for (size_t k = 0; k < K; k++)
        if (fricreg_hb_point(hb, k, &(*omega)[k], n, &(*rms)[k * n]) != FRICREG_OK ||
            (level && fricreg_hb_point_level(hb, k, &(*omega)[k]) != FRICREG_OK))
            return cli_usage_error("hb", fricreg_hb_errmsg(hb));
    *npoints = K;
    return 0;
}

/* A bifurcation type's label (enum fricreg_hb_bifurcation_type). */
static const char *bifurcation_name(int type)
{
    static const char *const names[] = {"", "TP", "BP", "PD", "NS"};
    return type >= 1 && type <= 4 ? names[type] : "";
}

/* A row omega, rms_1 .. rms_n, stable (1/0; empty where unknown), bifurcation (a label or
 * empty). */
static void write_row(FILE *out, size_t n, double omega, const double rms[], int stable,
                      double mu_max, const char *label)
{
    fprintf(out, "%.17g", omega);
    for (size_t i = 0; i < n; i++)
        fprintf(out, ",%.17g", rms[i]);
    if (stable >= 0)
        fprintf(out, ",%d,%s,%.17g\n", stable, label, mu_max);
    else
        fprintf(out, ",,%s,\n", label);
}

/* The points, each with its stability (when the driver computed it), and after point k a row
 * inserted at each bifurcation located between points k and k + 1 (stable empty). */
static int write_frf(fricreg_hb *hb, FILE *out, int level, size_t n, size_t K, const double omega[],
                     const double rms[])
{
    double *brms = malloc((n ? n : 1) * sizeof *brms);
    if (brms == NULL)
        return cli_usage_error("hb", "out of memory");
    fprintf(out, level ? "level" : "omega");
    for (size_t i = 0; i < n; i++)
        fprintf(out, ",rms_%zu", i + 1);
    fprintf(out, ",stable,bifurcation,mu_max\n");
    size_t nb = fricreg_hb_bifurcations(hb), b = 0;
    for (size_t k = 0; k < K; k++) {
        int stable = -1;
        double mu = 0.0;
        if (fricreg_hb_point_stability(hb, k, &stable, &mu) != FRICREG_OK)
            stable = -1;
        write_row(out, n, omega[k], &rms[k * n], stable, mu, "");
        for (; b < nb; b++) {
            int type = 0;
            double bw = 0.0;
            size_t at = 0;
            if (fricreg_hb_bifurcation(hb, b, &type, &bw, &at, n, brms) != FRICREG_OK || at != k ||
                (level && fricreg_hb_bifurcation_level(hb, b, &bw) != FRICREG_OK))
                break;
            write_row(out, n, bw, brms, -1, 0.0, bifurcation_name(type));
        }
    }
    free(brms);
    return 0;
}

/* The located bifurcations as the summary's JSON array. */
static int write_bifurcations(fricreg_hb *hb, FILE *out, int level, size_t n)
{
    double *brms = malloc((n ? n : 1) * sizeof *brms);
    if (brms == NULL)
        return cli_usage_error("hb", "out of memory");
    fprintf(out, ", \"bifurcations\": [");
    for (size_t b = 0; b < fricreg_hb_bifurcations(hb); b++) {
        int type = 0;
        double bw = 0.0;
        double lv = 1.0;
        if (fricreg_hb_bifurcation(hb, b, &type, &bw, NULL, n, brms) != FRICREG_OK ||
            fricreg_hb_bifurcation_level(hb, b, &lv) != FRICREG_OK)
            continue;
        fprintf(out, "%s{\"omega\": %.17g, ", b ? ", " : "", bw);
        if (level)
            fprintf(out, "\"level\": %.17g, ", lv);
        fprintf(out, "\"type\": \"%s\", \"dof_rms\": [", bifurcation_name(type));
        for (size_t i = 0; i < n; i++)
            fprintf(out, "%s%.17g", i ? ", " : "", brms[i]);
        fprintf(out, "]}");
    }
    fprintf(out, "]");
    free(brms);
    return 0;
}

/* Each dof's peak into peak_omega[n], peak_rms[n]: located by fricreg_hb_peak up to
 * HB_LOCATE_MAX dofs, else the largest stored point's. 0, or CLI_EXIT_RUN after a line on
 * stderr (a corrector that failed in the location). */
static int peaks(fricreg_hb *hb, const struct cli_deadline *d, int locate, size_t n, size_t K,
                 const double omega[], const double rms[], double peak_omega[], double peak_rms[])
{
    for (size_t i = 0; i < n; i++) {
        if (locate && n <= HB_LOCATE_MAX) {
            if (fricreg_hb_peak(hb, i, &peak_omega[i], &peak_rms[i]) == FRICREG_OK)
                continue;
            if (!cli_deadline_report(d, "hb", "locating the peaks"))
                fprintf(stderr, "fricreg-sim: hb: the peak of dof %zu: %s\n", i + 1,
                        fricreg_hb_errmsg(hb));
            return CLI_EXIT_RUN;
        }
        size_t best = 0;
        for (size_t k = 1; k < K; k++)
            if (rms[k * n + i] > rms[best * n + i])
                best = k;
        peak_omega[i] = omega[best];
        peak_rms[i] = rms[best * n + i];
    }
    return 0;
}

/* Each dof's truncation error estimate (fricreg_hb_truncation_error: the solve at 2H + 1) at its
 * largest stored point into err[n], each distinct point solved once; +infinity (null in the
 * JSON) where it could not be formed: H > 19, or the solve at 2H + 1 failed. */
static int truncation_errors(fricreg_hb *hb, size_t n, size_t K, const double rms[], double err[])
{
    size_t *best = malloc(n * sizeof *best);
    double *e = malloc(n * sizeof *e);
    if (best == NULL || e == NULL) {
        free(best);
        free(e);
        return cli_usage_error("hb", "out of memory");
    }
    for (size_t i = 0; i < n; i++) {
        best[i] = 0;
        for (size_t k = 1; k < K; k++)
            if (rms[k * n + i] > rms[best[i] * n + i])
                best[i] = k;
        err[i] = NAN; /* not yet */
    }
    for (size_t i = 0; i < n; i++) {
        if (!isnan(err[i]))
            continue;
        int ok = K > 0 && fricreg_hb_truncation_error(hb, best[i], n, e, NULL) == FRICREG_OK;
        for (size_t j = i; j < n; j++)
            if (best[j] == best[i])
                err[j] = ok ? e[j] : INFINITY;
    }
    free(best);
    free(e);
    return 0;
}

/* Each point's stability by --stability's method; auto takes none where the automatic choice is
 * Hill's and its dense companion is too large. 0, or CLI_EXIT_USAGE after a line on stderr. */
static int set_stability(fricreg_hb *hb, const struct hb_options *o, size_t n)
{
    int method = FRICREG_HB_STABILITY_HILL;
    if (o->stability == HB_STABILITY_OFF)
        return 0;
    if (fricreg_hb_set_stability_method(hb, o->stability) != FRICREG_OK ||
        fricreg_hb_get_stability_method(hb, &method) != FRICREG_OK)
        return cli_usage_error("--stability", fricreg_hb_errmsg(hb));
    size_t coefficients = n * (2 * (size_t)o->harmonics + 1);
    if (o->stability == FRICREG_HB_STABILITY_AUTO && method == FRICREG_HB_STABILITY_HILL &&
        coefficients > FRICREG_HB_MAX_HILL)
        return 0;
    if (fricreg_hb_set_stability(hb, 1) != FRICREG_OK)
        return cli_usage_error("--stability", fricreg_hb_errmsg(hb));
    return 0;
}

/* The stability's method as the summary names it: "monodromy", "condensed", "hill" or "off". */
static const char *stability_name(fricreg_hb *hb)
{
    int stable = 0, method = 0;
    double mu = 0.0;
    if (fricreg_hb_point_stability(hb, FRICREG_HB_SOLUTION, &stable, &mu) != FRICREG_OK ||
        fricreg_hb_get_stability_method(hb, &method) != FRICREG_OK)
        return "off";
    if (method == FRICREG_HB_STABILITY_HILL)
        return "hill";
    return method == FRICREG_HB_STABILITY_MONODROMY ? "monodromy" : "condensed";
}

static void write_summary(fricreg_hb *hb, FILE *out, const struct hb_options *o,
                          const struct hb_model *md, size_t K, const double omega[],
                          const double peak_omega[], const double peak_rms[],
                          const double peak_err[], double cpu)
{
    size_t n = md->n;
    int level = o->continue_in == HB_IN_LEVEL;
    fprintf(out, "{\"command\": \"hb\", \"ndof\": %zu, \"elements\": %zu, \"harmonics\": %d, ", n,
            md->m, o->harmonics);
    if (level)
        fprintf(out,
                "\"continue_in\": \"level\", \"omega\": %.17g, \"level_start\": %.17g, "
                "\"level_end\": %.17g, \"points\": %zu",
                o->omega, o->level_start, o->level_end, K);
    else
        fprintf(out, "\"omega_start\": %.17g, \"omega_end\": %.17g, \"points\": %zu",
                o->omega_start, o->omega_end, K);
    cli_hb_json_elements(out, &md->s);
    fprintf(out, ", \"stability_method\": \"%s\"", stability_name(hb));
    fprintf(out, ", \"%s_reached\": %.17g, \"peaks\": \"%s\", \"dofs\": [",
            level ? "level" : "omega",
            K > 0 ? omega[K - 1] : (level ? o->level_start : o->omega_start),
            !level && n <= HB_LOCATE_MAX ? "located" : "sampled");
    for (size_t i = 0; i < n; i++)
        fprintf(out, "%s{\"dof\": %zu, \"peak_rms\": %.17g, \"peak_%s\": %.17g}", i ? ", " : "",
                i + 1, peak_rms[i], level ? "level" : "omega", peak_omega[i]);
    fprintf(out, "]");
    cli_json_array(out, "peak_rms_error_estimate", n, peak_err);
    write_bifurcations(hb, out, level, n);
    /* a continuation that succeeded short of its end came round to its start (fricreg_hb.h) */
    double end = level ? o->level_end : o->omega_end;
    fprintf(out, ", \"isola\": %s", K > 0 && omega[K - 1] != end ? "true" : "false");
    fprintf(out, ", \"cpu_seconds\": %.6f}\n", cpu);
}

/* The continuation from omega_start (its solution from q = 0) to omega_end, and the output. */
static int run_hb(fricreg_hb *hb, struct hb_options *o, const struct hb_model *md, FILE *out)
{
    clock_t start = clock();
    /* lift-off elements: tangential and normal coefficients, 2 m rows */
    size_t nq = cli_hb_rows(&md->s) * (2 * (size_t)o->harmonics + 1);
    int status = set_stability(hb, o, md->n);
    if (status != 0)
        return status;
    int level = o->continue_in == HB_IN_LEVEL;
    cli_deadline_start(&o->deadline, hb);
    status = level ? fricreg_hb_continue_level(hb, o->omega, o->level_start, o->level_end, nq, NULL)
                   : fricreg_hb_continue(hb, o->omega_start, o->omega_end, nq, NULL);
    double cpu = (double)(clock() - start) / CLOCKS_PER_SEC;
    /* the monodromy's refusal of the elements (a mix, the 3-D contact) comes with the first
     * point's stability: the library's reason, as a bad option */
    if (status == FRICREG_EINVAL && (o->stability == FRICREG_HB_STABILITY_MONODROMY ||
                                     o->stability == FRICREG_HB_STABILITY_CONDENSED))
        return cli_usage_error("--stability", fricreg_hb_errmsg(hb));
    if (status != FRICREG_OK) {
        char progress[128];
        snprintf(progress, sizeof progress, "the continuation from %s = %g had reached %zu points",
                 level ? "level" : "omega", level ? o->level_start : o->omega_start,
                 fricreg_hb_points(hb));
        if (!cli_deadline_report(&o->deadline, "hb", progress))
            fprintf(stderr, "fricreg-sim: hb: the continuation failed: %s\n",
                    fricreg_hb_errmsg(hb));
        return CLI_EXIT_RUN;
    }
    size_t K = 0, n = md->n;
    double *omega = NULL, *rms = NULL, *peak = NULL;
    status = collect(hb, level, n, &K, &omega, &rms);
    if (status == 0 && o->output == HB_FRF) {
        status = write_frf(hb, out, level, n, K, omega, rms);
    } else if (status == 0) {
        if ((peak = malloc(3 * n * sizeof *peak)) == NULL)
            status = cli_usage_error("hb", "out of memory");
        if (status == 0)
            status = peaks(hb, &o->deadline, !level, n, K, omega, rms, peak, peak + n);
        if (status == 0)
            status = truncation_errors(hb, n, K, rms, peak + 2 * n);
        /* the CPU time includes the peaks' location and their error estimates */
        cpu = (double)(clock() - start) / CLOCKS_PER_SEC;
        if (status == 0)
            write_summary(hb, out, o, md, K, omega, peak, peak + n, peak + 2 * n, cpu);
    }
    free(omega);
    free(rms);
    free(peak);
    return status;
}

int cli_hb(int argc, char **argv, FILE *out)
{
    struct hb_options o;
    int status = cli_parse_hb(argc, argv, &o);
    if (status != 0)
        return status;
    struct hb_model md = {0};
    if ((status = read_model(&o, &md)) != 0) {
        free_model(&md);
        return status;
    }
    fricreg_hb *hb = NULL;
    if ((status = cli_hb_create("hb", &md.s, o.harmonics, &hb)) != 0) {
        free_model(&md);
        return status;
    }
    status = set_model(&o, &md, hb);
    if (status == 0)
        status = run_hb(hb, &o, &md, out);
    fricreg_hb_free(hb);
    free_model(&md);
    return status;
}

/* ---- The help (help.c) -------------------------------------------------------------------- */

static size_t hb_help_table(struct cli_option table[])
{
    static struct hb_options o; /* the help's rows point here */
    return hb_table(&o, table);
}

const struct cli_command cli_hb_command = {
    "hb",
    "--mass M.mtx --stiffness K.mtx [--damping C.mtx | --rayleigh A0,A1] --excitation F.txt "
    "{--jenkins J.mtx ELEMENTS | --elements TYPE:J.mtx:P.txt...} {--omega-start W0 --omega-end "
    "W1 | --continue-in level --omega W "
    "--level-start L0 --level-end L1} [OPTION]...",
    "frequency response of a structure with joints (harmonic balance)",
    "The frequency response of a linear structure M x'' + C x' + K x + J^T f(q) = pc cos(omega t) "
    "+ ps sin(omega t) with Jenkins, Iwan, lift-off or 3-D contact elements on q = J x, by "
    "harmonic balance (fricreg_hb.h), continued in omega from --omega-start to --omega-end, or "
    "with --continue-in level in the excitation level (the excitation times a factor) from "
    "--level-start to --level-end at --omega (docs/harmonic_balance.md).\n\n"
    "ELEMENTS is one parameter file, a line per row of J.mtx: --jenkins-params, --iwan-params "
    "or --iwan-segalman, or --normal with --normal-params (lift-off); or --jenkins-2d J2.mtx "
    "instead of --jenkins with --normal and --normal-params (3-D contact: rows x, y of J2.mtx "
    "and n of the normal file per element, a line kt mu n0 kn). Or, instead, --elements "
    "TYPE:J.mtx:P.txt, repeatable: sets of any of the types harmonic balance takes, mixed in "
    "one model, each added in the order given, in the files fricreg-sim structure takes "
    "(docs/structural.md); the library decides the types (fricreg_hb_add_elements, "
    "fricreg_hb.h), a type it refuses a usage error with its reason, naming the set's file.",
    hb_help_table};
