/* SPDX-License-Identifier: GPL-3.0-or-later */
/* nma.c — `fricreg-sim nma`: the backbone of a nonlinear mode (its natural frequency and
 * damping ratio against its modal amplitude) of a linear structure with Jenkins, Iwan or
 * lift-off elements (or --elements sets of several kinds), by harmonic balance and the extended periodic motion concept
 * (fricreg_hb_nma), from the Matrix Market files of `hb` (hb_model.h); a JSON summary (with the
 * folds and the crossings k omega = omega_r) or a CSV row amplitude,omega,zeta,e_h1..e_hH (the
 * harmonics' kinetic energy shares) per point on stdout. Every bad option or file is one line
 * on stderr naming it, exit 2, nothing on stdout; a backbone that fails, exit 1. */
#include <stdlib.h>
#include <time.h>

#include "cli.h"
#include "cli_hb.h"
#include "fricreg_hb.h"
#include "hb_deadline.h"
#include "hb_model.h"

static const struct cli_word nma_outputs[] = {{"summary", NMA_SUMMARY},
                                              {"backbone", NMA_BACKBONE},
                                              {NULL, 0}};
enum { NMA_ARCLENGTH = 0, NMA_NATURAL = 1 };
static const struct cli_word nma_continuations[] = {{"arclength", NMA_ARCLENGTH},
                                                    {"natural", NMA_NATURAL},
                                                    {NULL, 0}};
static const struct cli_word nma_dampings[] = {{"matrix", FRICREG_HB_NMA_DAMPING_MATRIX},
                                               {"modal", FRICREG_HB_NMA_DAMPING_MODAL},
                                               {NULL, 0}};

static int check_options(const struct nma_options *o)
{
    int status = cli_hb_check_model(&o->model);
    if (status != 0)
        return status;
    if (!o->a0_given)
        return cli_usage_error("--amplitude-start", "missing");
    if (!o->a1_given)
        return cli_usage_error("--amplitude-end", "missing");
    if (!(o->a1 > o->a0))
        return cli_usage_error("--amplitude-end", "must be above --amplitude-start");
    return 0;
}

/* The rows over o, its defaults set: the parser's and the help's one table. */
static size_t nma_table(struct nma_options *o, struct cli_option table[])
{
    /* Newton's rule: the driver's defaults (fricreg_hb_set_newton) */
    *o = (struct nma_options){.harmonics = 7,
                              .mode = 1,
                              .points = 20,
                              .continuation = NMA_ARCLENGTH,
                              .linear_damping = FRICREG_HB_NMA_DAMPING_MATRIX,
                              .output = NMA_SUMMARY,
                              .newton_tol = 1e-10,
                              .newton_max = 50};
    cli_hb_model_defaults(&o->model);
    const struct cli_option opts[] = {
        CLI_HB_MODEL_OPTIONS(&o->model),
        {"--mode", CLI_WHOLE, .slot = &o->mode, .lo = 1, .hi = 1e8, .meta = "K",
         .help = "the mode, from 1 in ascending order of the structure's natural frequencies "
                 "with its elements stuck"},
        {"--harmonics", CLI_WHOLE, .slot = &o->harmonics, .lo = 1, .hi = FRICREG_HB_MAX_HARMONICS,
         .meta = "H", .help = "harmonics kept in the solution"},
        {"--amplitude-start", CLI_POSITIVE, .slot = &o->a0, .given = &o->a0_given, .meta = "A0",
         .help = "the smallest modal amplitude phi_k^T M x_1 (phi_k mass-normalized; for a unit "
                 "mass a displacement) (required)",
         .dflt = ""},
        {"--amplitude-end", CLI_POSITIVE, .slot = &o->a1, .given = &o->a1_given, .meta = "A1",
         .help = "the largest, above A0 (required)", .dflt = ""},
        {"--points", CLI_WHOLE, .slot = &o->points, .lo = 2, .hi = 2000, .meta = "N",
         .help = "points of the backbone written: at equal arclength along the branch from A0 to "
                 "A1 (arclength; each a solution, not an interpolation), or log-spaced in the "
                 "amplitude (natural)"},
        {"--continuation", CLI_CHOICE, .slot = &o->continuation, .words = nma_continuations,
         .help = "the backbone by pseudo-arclength continuation, passing its folds in the "
                 "amplitude (internal resonances), or by the natural-parameter march in log a "
                 "of 1.7, which stops at a fold"},
        {"--linear-damping", CLI_CHOICE, .slot = &o->linear_damping, .words = nma_dampings,
         .help = "the linear damping in the mode: the matrix as given, or the linear mode's "
                 "modal damping (C replaced by 2 zeta_k omega_k M)"},
        {"--newton-tol", CLI_POSITIVE, .slot = &o->newton_tol, .meta = "TOL",
         .help = "Newton's tolerance at each point"},
        {"--newton-max", CLI_WHOLE, .slot = &o->newton_max, .lo = 1, .hi = 1000, .meta = "N",
         .help = "Newton's iterations at most per point, 1 to 1000"},
        CLI_DEADLINE_OPTION(&o->deadline),
        {"--output", CLI_CHOICE, .slot = &o->output, .words = nma_outputs,
         .help = "a JSON summary (the backbone's ends, its largest damping ratio, its folds "
                 "and its crossings: where a harmonic k omega crosses another linear mode's "
                 "frequency, that mode counted from 1 as --mode), or the backbone: a CSV row "
                 "amplitude,omega,zeta,e_h1,...,e_hH per point, in the branch's order, e_hk the "
                 "share of harmonic k in the mode's kinetic energy (they add up to 1)"}};
    return cli_copy_rows(table, opts, sizeof opts / sizeof opts[0]);
}

int cli_parse_nma(int argc, char **argv, struct nma_options *o)
{
    struct cli_option table[CLI_MAX_ROWS];
    size_t n = nma_table(o, table);
    int status = cli_parse_options(argc, argv, table, n, "nma");
    return status != 0 ? status : check_options(o);
}

/* The backbone's points: per point a, omega, zeta and the shares e_h1..e_hH of the harmonics
 * in its kinetic energy (fricreg_hb_nma_harmonic_energy; e_h0 is 0 by definition), stride
 * 3 + H, then its folds' a, omega, zeta (the special points of type FRICREG_HB_NMA_FOLD),
 * stride 3, into one array the caller frees. */
static int collect(fricreg_hb *hb, int H, size_t *npoints, size_t *nfolds, double **pts)
{
    size_t K = fricreg_hb_nma_points(hb), S = fricreg_hb_nma_special_points(hb), F = 0;
    size_t w = 3 + (size_t)H;
    *pts = malloc((K * w + 3 * S + (size_t)H + 2) * sizeof **pts);
    if (*pts == NULL)
        return cli_usage_error("nma", "out of memory");
    double *e = *pts + K * w + 3 * S; /* H + 1 shares */
    for (size_t k = 0; k < K + S; k++) {
        double *p = k < K ? *pts + w * k : *pts + K * w + 3 * F;
        int type = FRICREG_HB_NMA_FOLD, harmonic;
        size_t mode;
        int status = k < K ? fricreg_hb_nma_point(hb, k, &p[0], &p[1], &p[2], 0, 0, NULL)
                           : fricreg_hb_nma_special_point(hb, k - K, &type, &p[0], &p[1], &p[2],
                                                          &harmonic, &mode);
        if (status == FRICREG_OK && k < K &&
            (status = fricreg_hb_nma_harmonic_energy(hb, k, (size_t)H + 1, e)) == FRICREG_OK)
            for (int h = 1; h <= H; h++)
                p[2 + h] = e[h];
        if (status != FRICREG_OK)
            return cli_usage_error("nma", fricreg_hb_errmsg(hb));
        F += k >= K && type == FRICREG_HB_NMA_FOLD;
    }
    *npoints = K;
    *nfolds = F;
    return 0;
}

static void write_backbone(FILE *out, int H, size_t K, const double pts[])
{
    size_t w = 3 + (size_t)H;
    fprintf(out, "amplitude,omega,zeta");
    for (int h = 1; h <= H; h++)
        fprintf(out, ",e_h%d", h);
    fputc('\n', out);
    for (size_t k = 0; k < K; k++)
        for (size_t j = 0; j < w; j++)
            fprintf(out, "%.17g%c", pts[w * k + j], j + 1 < w ? ',' : '\n');
}

/* The crossings of a harmonic k omega with another linear mode's frequency, the mode from 1 as
 * --mode (the special points of type FRICREG_HB_NMA_CROSSING, fricreg_hb_nma_special_point). */
static void write_crossings(FILE *out, fricreg_hb *hb)
{
    const char *sep = "";
    fputs(", \"crossings\": [", out);
    for (size_t i = 0; i < fricreg_hb_nma_special_points(hb); i++) {
        int type, k;
        size_t r;
        double a, w, z;
        if (fricreg_hb_nma_special_point(hb, i, &type, &a, &w, &z, &k, &r) == FRICREG_OK &&
            type == FRICREG_HB_NMA_CROSSING) {
            fprintf(out,
                    "%s{\"harmonic\": %d, \"mode\": %zu, \"amplitude\": %.17g, \"omega\": %.17g}",
                    sep, k, r + 1, a, w);
            sep = ", ";
        }
    }
    fputs("]", out);
}

/* The summary; error is NULL for a complete backbone, else the failure's message (the points
 * are those reached); the folds (a, omega, zeta each) found, in the branch's order. */
static void write_summary(FILE *out, fricreg_hb *hb, const struct nma_options *o,
                          const struct cli_hb_model *md, size_t K, const double pts[],
                          size_t nfolds, const double folds[], double cpu, const char *error)
{
    size_t top = 0, w = 3 + (size_t)o->harmonics;
    for (size_t k = 1; k < K; k++)
        if (pts[w * k + 2] > pts[w * top + 2])
            top = k;
    fprintf(out, "{\"command\": \"nma\", \"ndof\": %zu, \"elements\": %zu", md->n, md->m);
    cli_hb_json_elements(out, md);
    fprintf(out, ", \"harmonics\": %d, \"mode\": %d, \"linear_damping\": \"%s\", \"points\": %zu",
            o->harmonics, o->mode,
            o->linear_damping == FRICREG_HB_NMA_DAMPING_MODAL ? "modal" : "matrix", K);
    const char *names[3] = {"first", "last", "zeta_max"};
    size_t at[3] = {0, K - 1, top};
    for (int j = 0; j < 3 && K > 0; j++)
        fprintf(out, ", \"%s\": {\"amplitude\": %.17g, \"omega\": %.17g, \"zeta\": %.17g}",
                names[j], pts[w * at[j]], pts[w * at[j] + 1], pts[w * at[j] + 2]);
    fputs(", \"folds\": [", out);
    for (size_t i = 0; i < nfolds; i++)
        fprintf(out, "%s{\"amplitude\": %.17g, \"omega\": %.17g, \"zeta\": %.17g}", i ? ", " : "",
                folds[3 * i], folds[3 * i + 1], folds[3 * i + 2]);
    fputs("]", out);
    write_crossings(out, hb);
    fprintf(out, ", \"complete\": %s", error == NULL ? "true" : "false");
    if (error != NULL) {
        fputs(", \"error\": ", out);
        cli_json_string(out, error);
    }
    fprintf(out, ", \"cpu_seconds\": %.6f}\n", cpu);
}

/* The backbone, written whole or, when the march fails, up to the failure (the points the
 * library kept), the failure then said on stderr and in the summary. */
static int run_nma(fricreg_hb *hb, struct nma_options *o, const struct cli_hb_model *md, FILE *out)
{
    if ((size_t)o->mode > md->n)
        return cli_usage_error("--mode", "beyond the structure's modes (one per dof)");
    clock_t start = clock();
    cli_deadline_start(&o->deadline, hb);
    int run = (o->continuation == NMA_NATURAL ? fricreg_hb_nma
                                              : fricreg_hb_nma_continue)(hb, (size_t)o->mode - 1,
                                                                         o->linear_damping, o->a0,
                                                                         o->a1, (size_t)o->points);
    double cpu = (double)(clock() - start) / CLOCKS_PER_SEC;
    size_t K = 0, F = 0;
    double *pts = NULL;
    int status = collect(hb, o->harmonics, &K, &F, &pts);
    if (status == 0 && o->output == NMA_BACKBONE)
        write_backbone(out, o->harmonics, K, pts);
    else if (status == 0)
        write_summary(out, hb, o, md, K, pts, F, pts + (3 + (size_t)o->harmonics) * K, cpu,
                      run == FRICREG_OK ? NULL : fricreg_hb_errmsg(hb));
    free(pts);
    if (status == 0 && run != FRICREG_OK) {
        char progress[96];
        snprintf(progress, sizeof progress, "the backbone had reached %zu of its %d points", K,
                 o->points);
        if (!cli_deadline_report(&o->deadline, "nma", progress))
            fprintf(stderr,
                    "fricreg-sim: nma: the backbone failed after %zu of its %d points: %s\n", K,
                    o->points, fricreg_hb_errmsg(hb));
        status = CLI_EXIT_RUN;
    }
    return status;
}

int cli_nma(int argc, char **argv, FILE *out)
{
    struct nma_options o;
    int status = cli_parse_nma(argc, argv, &o);
    if (status != 0)
        return status;
    struct cli_hb_model md = {0};
    if ((status = cli_hb_read_model(&o.model, &md)) != 0) {
        cli_hb_free_model(&md);
        return status;
    }
    fricreg_hb *hb = NULL;
    if ((status = cli_hb_create("nma", &md, o.harmonics, &hb)) != 0) {
        cli_hb_free_model(&md);
        return status;
    }
    status = cli_hb_set_model(&o.model, &md, hb);
    if (status == 0 && fricreg_hb_set_newton(hb, o.newton_tol, o.newton_max) != FRICREG_OK)
        status = cli_usage_error("--newton-tol", fricreg_hb_errmsg(hb));
    if (status == 0)
        status = run_nma(hb, &o, &md, out);
    fricreg_hb_free(hb);
    cli_hb_free_model(&md);
    return status;
}

/* ---- The help (help.c) -------------------------------------------------------------------- */

static size_t nma_help_table(struct cli_option table[])
{
    static struct nma_options o; /* the help's rows point here */
    return nma_table(&o, table);
}

const struct cli_command cli_nma_command = {
    "nma",
    "--mass M.mtx --stiffness K.mtx [--damping C.mtx | --rayleigh A0,A1] {--jenkins J.mtx "
    "ELEMENTS | --elements TYPE:J.mtx:P.txt...} --amplitude-start A0 --amplitude-end A1 "
    "[OPTION]...",
    "backbone of a nonlinear mode of a structure with joints (EPMC)",
    "The backbone of mode K of a linear structure M x'' + C x' + K x + J^T f(q) = 0 with "
    "Jenkins, Iwan or lift-off elements on q = J x: its natural frequency omega and damping "
    "ratio zeta against its modal amplitude, by harmonic balance and the extended periodic "
    "motion concept (fricreg_hb_nma_continue, fricreg_hb.h; docs/nonlinear_modes.md), "
    "from the linear mode with the elements stuck, followed from --amplitude-start to "
    "--amplitude-end by pseudo-arclength continuation: it passes the folds of the backbone in "
    "the amplitude (internal resonances), which the summary lists (\"folds\"), and writes "
    "--points points at equal arclength along the branch, in its order (--continuation natural: "
    "1.7's march, at --points amplitudes log-spaced, stopping at a fold). Each point says what "
    "it is made of: the share of each harmonic in its kinetic energy (e_h1..e_hH: a higher "
    "harmonic's share rising is energy flowing into it, fricreg_hb_nma_harmonic_energy); the "
    "summary lists where a harmonic k omega (k >= 2) crosses the frequency of another mode of "
    "the structure with its elements stuck (\"crossings\", sparse models up to 256 dofs: "
    "fricreg_hb_nma_special_points).\n\n"
    "ELEMENTS is one parameter file, a line per row of J.mtx: --jenkins-params, --iwan-params "
    "or --iwan-segalman, or --normal with --normal-params (lift-off). Or, instead, --elements "
    "TYPE:J.mtx:P.txt, repeatable: sets of any types harmonic balance takes, mixed in one "
    "model, as for fricreg-sim hb.",
    nma_help_table};
