/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fit.c — `fricreg-sim fit`: a joint's parameters from a test's measured levels (the modal
 * Iwan model, or with --model hb a harmonic-balance model's nonlinear mode, fit_hb.c;
 * fricreg_fit.h; docs/identification.md): a JSON summary on stdout (each parameter
 * with its 95 % interval, the identifiability, the residuals), the fitted backbone with its
 * band as a CSV (--curve) and a PNG of measured against fitted (--plot, through gnuplot).
 * Every bad option or file is one line on stderr naming it, exit 2, nothing on stdout; a fit
 * that fails, exit 1 with the library's reason. */
#define _POSIX_C_SOURCE 200809L /* popen for gnuplot */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>

#include "cli.h"
#include "fit_hb.h"
#include "fit_levels.h"
#include "fricreg_fit.h"
#include "out_file.h"

#define NP FRICREG_FIT_NPARAMS
#define MAXP CLI_FIT_MAX_PARAMS
#define CURVE_POINTS 100

static const char *const param_names[NP] = {"fs", "kt", "chi", "beta", "zeta0", "k0"};

enum { MODEL_MODAL_IWAN = 0, MODEL_HB = 1 };
static const struct cli_word models[] = {{"modal-iwan", MODEL_MODAL_IWAN},
                                         {"hb", MODEL_HB},
                                         {NULL, 0}};

/* --fix and --start by index: the modal Iwan model's by name, an HB model's by position (from
 * 1 on the command line); by_name and by_position say which the user wrote (an option's name,
 * or NULL), checked against --model once every option is read. */
struct fit_options {
    const char *levels, *curve, *plot;
    int kind, starts, starts_given, sensor_given, model;
    double sensor;
    double fixed[MAXP], start[MAXP];
    int is_fixed[MAXP], has_start[MAXP];
    const char *by_name, *by_position;
    struct cli_fit_hb_options hb;
};

static const struct cli_word kinds[] = {{"acceleration", FRICREG_FIT_ACCELERATION},
                                        {"velocity", FRICREG_FIT_VELOCITY},
                                        {"displacement", FRICREG_FIT_DISPLACEMENT},
                                        {NULL, 0}};

/* NAME=VALUE, NAME one of param_names, or POSITION=VALUE, POSITION from 1 to MAXP (an HB
 * model's parameter by its --param's place): the index from 0, whether by name, and the value;
 * or CLI_EXIT_USAGE. */
static int name_value(const char *option, const char *text, int *which, int *named, double *value)
{
    const char *eq = strchr(text, '=');
    for (int j = 0; eq != NULL && j < NP; j++)
        if ((size_t)(eq - text) == strlen(param_names[j]) &&
            strncmp(text, param_names[j], strlen(param_names[j])) == 0) {
            *which = j;
            *named = 1;
            return cli_parse_number(option, eq + 1, value);
        }
    char *end = NULL;
    long pos = eq != NULL && eq > text && strspn(text, "0123456789") == (size_t)(eq - text)
                   ? strtol(text, &end, 10)
                   : 0;
    if (pos >= 1 && pos <= MAXP) {
        *which = (int)pos - 1;
        *named = 0;
        return cli_parse_number(option, eq + 1, value);
    }
    return cli_usage_error(option, "expected NAME=VALUE, NAME one of fs, kt, chi, beta, zeta0, "
                                   "k0, or with --model hb POSITION=VALUE, POSITION a --param's "
                                   "place from 1");
}

/* --fix NAME=VALUE and --start NAME=VALUE (row->arg 1 and 0), repeatable. */
static int parse_param(const struct cli_option *row, const char *text)
{
    struct fit_options *o = row->slot;
    int j = 0, named = 0;
    double v;
    int status = name_value(row->name, text, &j, &named, &v);
    if (status != 0)
        return status;
    if (named)
        o->by_name = row->name;
    else
        o->by_position = row->name;
    if (row->arg) {
        o->fixed[j] = v;
        o->is_fixed[j] = 1;
    } else {
        o->start[j] = v;
        o->has_start[j] = 1;
    }
    return 0;
}

static size_t fit_table(struct fit_options *o, struct cli_option table[])
{
    *o = (struct fit_options){.kind = FRICREG_FIT_ACCELERATION, .starts = 32, .sensor = 1.0};
    cli_fit_hb_defaults(&o->hb);
    const struct cli_option opts[] = {
        {"--model", CLI_CHOICE, .slot = &o->model, .words = models,
         .help = "the model fitted: the modal Iwan model's closed forms, or a nonlinear mode of a "
                 "harmonic-balance model (EPMC) of the files and options of fricreg-sim nma, "
                 "its parameters by --param"},
        {"--levels", CLI_FILE, .slot = &o->levels, .meta = "LEVELS.csv",
         .help = "the measured levels, a line each: amplitude, freq_hz, zeta, and optionally "
                 "sd_freq_hz, sd_zeta (standard deviations: without them the residuals are "
                 "relative and the covariance scaled by their variance), separated by commas "
                 "or blanks; a first line of names is a header (required)",
         .dflt = ""},
        {"--kind", CLI_CHOICE, .slot = &o->kind, .words = kinds,
         .help = "what the amplitudes are, at the sensor"},
        {"--sensor", CLI_NUMBER, .slot = &o->sensor, .given = &o->sensor_given, .meta = "S",
         .help = "the mass-normalized mode shape's value at the sensor (1: modal amplitudes)"},
        {"--fix", CLI_CUSTOM, .slot = o, .parse = parse_param, .arg = 1, .repeatable = 1,
         .meta = "NAME=VALUE",
         .help = "a parameter fixed: fs, kt, chi, beta, zeta0 or k0 (beta=0: no delta); with "
                 "--model hb POSITION=VALUE, the --param at that place from 1 (2=0.01)",
         .dflt = "all free"},
        {"--start", CLI_CUSTOM, .slot = o, .parse = parse_param, .arg = 0, .repeatable = 1,
         .meta = "NAME=VALUE",
         .help = "a free parameter's first start (--model hb: POSITION=VALUE as --fix)",
         .dflt = "from the levels; --model hb: the model's values, Rayleigh's from the levels"},
        {"--starts", CLI_WHOLE, .slot = &o->starts, .given = &o->starts_given, .lo = 1, .hi = 1000,
         .meta = "N",
         .help = "starts of the least squares, 1 to 1000 (--model hb: each a backbone march or "
                 "more an iteration)",
         .dflt = "32; 1 with --model hb"},
        {"--curve", CLI_FILE, .slot = &o->curve, .meta = "CURVE.csv",
         .help = "write the fitted backbone at 100 amplitudes from half the smallest level to "
                 "twice the largest: amplitude,freq_hz,zeta and their 95 % bands",
         .dflt = "none"},
        {"--plot", CLI_FILE, .slot = &o->plot, .meta = "PLOT.png",
         .help = "draw measured against fitted frequency and damping with the 95 % band "
                 "(needs gnuplot)",
         .dflt = "none"},
        CLI_FIT_HB_OPTIONS(&o->hb)};
    return cli_copy_rows(table, opts, sizeof opts / sizeof opts[0]);
}

static size_t fit_help_table(struct cli_option table[])
{
    static struct fit_options o;
    return fit_table(&o, table);
}

const struct cli_command cli_fit_command = {
    "fit",
    "--levels LEVELS.csv [OPTION]... | --model hb --levels LEVELS.csv --mass M.mtx --stiffness "
    "K.mtx {--jenkins J.mtx ELEMENTS | --elements TYPE:J.mtx:P.txt...} --param PARAM... "
    "[OPTION]...",
    "a joint's parameters from measured levels (modal Iwan, HB model)",
    "The parameters of the modal Iwan model (Segalman's four-parameter joint F_S, K_T, chi, "
    "beta beside a linear modal stiffness K0 and damping ratio zeta0; fricreg_fit.h, "
    "docs/identification.md) that make its backbone match a mode's measured natural "
    "frequency and damping ratio at several response levels, by GSL's trust-region least "
    "squares with the exact Jacobian from --starts starts. The summary gives each parameter "
    "with its 95 % interval, the singular values of the Jacobian in the log-scaled parameters "
    "(small ones: combinations the levels hardly determine), the levels' residuals and the "
    "cost.\n\n"
    "--model hb fits a nonlinear mode's backbone instead (fricreg_fit_set_model_hb: EPMC, "
    "its exact sensitivities): the structure and its elements as fricreg-sim nma reads them, "
    "the mode --mode at --harmonics, and the parameters --param names, each a value shared by "
    "a range of elements (element:FIRST:COUNT:INDEX) or Rayleigh's a0 or a1 (damping:1, "
    "damping:2), every one free on (0, inf) from the model's value; --fix and --start take "
    "them by their place among the --param, from 1 (--fix 2=0.01). The levels' amplitudes are "
    "modal (times --sensor) or the first harmonic's at dof --dof. The summary keys the "
    "parameters by their --param.\n\n"
    "A fit that cannot be made (a parameter at its bound, levels that do not determine the "
    "parameters, no start converged, a level beyond the backbone's reach) exits 1 with the "
    "library's reason: fix a parameter (--fix beta=0) or add levels.",
    fit_help_table};

/* The model's parameter count: six, or the --param given. */
static size_t param_count(const struct fit_options *o)
{
    return o->model == MODEL_HB ? o->hb.np : NP;
}

static int check_options(const struct fit_options *o)
{
    if (o->levels == NULL)
        return cli_usage_error("--levels", "missing");
    if (o->sensor == 0.0)
        return cli_usage_error("--sensor", "must not be 0");
    int status = cli_fit_hb_check(&o->hb, o->model == MODEL_HB);
    if (status != 0)
        return status;
    if (o->model == MODEL_HB && o->by_name != NULL)
        return cli_usage_error(o->by_name, "--model hb takes its parameters by position "
                                           "(POSITION=VALUE, the --param's place from 1)");
    if (o->model != MODEL_HB && o->by_position != NULL)
        return cli_usage_error(o->by_position, "POSITION=VALUE only with --model hb (the modal "
                                               "Iwan model's parameters by name)");
    if (o->hb.dof_given && o->sensor_given)
        return cli_usage_error("--dof", "give --sensor (modal amplitudes) or --dof, not both");
    for (size_t j = param_count(o); j < MAXP; j++)
        if (o->is_fixed[j] || o->has_start[j]) {
            char what[96];
            snprintf(what, sizeof what, "position %zu beyond the %zu --param given", j + 1,
                     o->hb.np);
            return cli_usage_error(o->is_fixed[j] ? "--fix" : "--start", what);
        }
    for (int j = 0; j < MAXP; j++)
        if (o->is_fixed[j] && o->has_start[j])
            return cli_usage_error("--start", "a parameter also fixed with --fix");
    if (o->plot != NULL && (strchr(o->plot, '\'') != NULL || strchr(o->plot, '"') != NULL))
        return cli_usage_error("--plot", "a file name without quotes is required");
    return 0;
}

/* The library's message for a setter's failure, naming the option. */
static int refused(fricreg_fit *fit, const char *option)
{
    return cli_usage_error(option, fricreg_fit_errmsg(fit));
}

/* The fit set up from o and the levels (rows of cols), an HB model's driver into h. 0 or
 * CLI_EXIT_USAGE. */
static int set_up(fricreg_fit *fit, const struct fit_options *o, size_t n, size_t cols,
                  const double rows[], struct cli_fit_hb *h)
{
    /* the sensor before --dof, which it would undo */
    int status = fricreg_fit_set_sensor(fit, o->sensor) == FRICREG_OK ? 0
                                                                      : refused(fit, "--sensor");
    if (status == 0 && o->model == MODEL_HB)
        status = cli_fit_hb_set_up(fit, &o->hb, h);
    if (status != 0)
        return status;
    double *col = malloc(5 * n * sizeof *col);
    if (col == NULL)
        return cli_usage_error("--levels", "out of memory");
    for (size_t i = 0; i < n; i++)
        for (size_t c = 0; c < cols; c++)
            col[c * n + i] = rows[i * cols + c];
    if (fricreg_fit_set_levels(fit, n, o->kind, col, col + n, col + 2 * n) != FRICREG_OK ||
        (cols == 5 && fricreg_fit_set_deviations(fit, n, col + 3 * n, col + 4 * n)))
        status = refused(fit, "--levels");
    free(col);
    /* chi's own bound is -1; every other parameter's (an HB model's all) 0 */
    for (int j = 0; status == 0 && j < (int)param_count(o); j++) {
        double lower = o->model != MODEL_HB && j == FRICREG_FIT_CHI ? -1.0 : 0.0;
        int st = o->is_fixed[j] ? fricreg_fit_set_fixed(fit, j, o->fixed[j])
                                : fricreg_fit_set_free(fit, j, o->has_start[j] ? o->start[j] : NAN,
                                                       lower, INFINITY);
        if (st != FRICREG_OK)
            status = refused(fit, o->is_fixed[j] ? "--fix" : "--start");
    }
    /* an HB model keeps the library's one start unless told: each start costs marches */
    if (status == 0 && (o->model != MODEL_HB || o->starts_given) &&
        fricreg_fit_set_starts(fit, (size_t)o->starts) != FRICREG_OK)
        status = refused(fit, "--starts");
    return status;
}

static const char *kind_word(int kind)
{
    for (size_t k = 0; kinds[k].word != NULL; k++)
        if (kinds[k].value == kind)
            return kinds[k].word;
    return "?";
}

/* An HB model's fields: its size, mode, harmonics, damping, backbone and sensor dof (from 1). */
static void write_hb_model(FILE *out, const struct fit_options *o, const struct cli_fit_hb *h)
{
    fprintf(out, ", \"ndof\": %zu, \"elements\": %zu", h->md.n, h->md.m);
    cli_hb_json_elements(out, &h->md);
    fprintf(out, ", \"mode\": %d, \"harmonics\": %d, \"linear_damping\": \"%s\"", o->hb.mode,
            o->hb.harmonics,
            o->hb.backbone == 1                                    ? "qsma"
            : o->hb.linear_damping == FRICREG_HB_NMA_DAMPING_MODAL ? "modal"
                                                                   : "matrix");
    fprintf(out, ", \"backbone\": \"%s\"", o->hb.backbone == 1 ? "qsma" : "epmc");
    if (o->hb.dof_given)
        fprintf(out, ", \"dof\": %d", o->hb.dof);
}

static void write_summary(FILE *out, fricreg_fit *fit, const struct fit_options *o,
                          const struct cli_fit_hb *h, size_t n, double cpu)
{
    size_t np = param_count(o);
    double p[MAXP], lo[MAXP], hi[MAXP], sv[MAXP], v;
    double *r = malloc(2 * n * sizeof *r);
    fricreg_fit_get_params(fit, np, p);
    fricreg_fit_get_covariance(fit, np, NULL, lo, hi);
    fricreg_fit_get_identifiability(fit, np, sv, NULL);
    int hb = o->model == MODEL_HB;
    fprintf(out, "{\"command\": \"fit\", \"model\": \"%s\"", hb ? "hb" : "modal_iwan");
    if (hb)
        write_hb_model(out, o, h);
    fprintf(out, ", \"levels\": %zu, \"kind\": ", n);
    cli_json_string(out, kind_word(o->kind));
    fputs(", \"parameters\": {", out);
    for (size_t j = 0; j < np; j++) { /* by name, or by the --param as written */
        fprintf(out, "%s\"%s\": {\"value\": ", j ? ", " : "", hb ? o->hb.name[j] : param_names[j]);
        cli_json_number(out, p[j]);
        fputs(", \"lower\": ", out);
        cli_json_number(out, lo[j]);
        fputs(", \"upper\": ", out);
        cli_json_number(out, hi[j]);
        fprintf(out, ", \"free\": %s}", o->is_fixed[j] ? "false" : "true");
    }
    fputs("}", out);
    fricreg_fit_get_value(fit, FRICREG_FIT_NFREE, &v);
    cli_json_array(out, "singular_values", (size_t)v, sv);
    const char *names[] = {"cost", "residual_variance", "quantile", "condition"};
    const int which[] = {FRICREG_FIT_COST, FRICREG_FIT_RESIDUAL_VARIANCE, -1,
                         FRICREG_FIT_CONDITION};
    for (int k = 0; k < 4; k++) {
        if (which[k] < 0)
            fricreg_fit_get_quantile(fit, &v);
        else
            fricreg_fit_get_value(fit, which[k], &v);
        fprintf(out, ", \"%s\": ", names[k]);
        cli_json_number(out, v);
    }
    const char *counts[] = {"nfev", "njev", "starts_converged", "nmodel", "nmarch"};
    const int cwhich[] = {FRICREG_FIT_NFEV, FRICREG_FIT_NJEV, FRICREG_FIT_STARTS_CONVERGED,
                          FRICREG_FIT_NMODEL, FRICREG_FIT_NMARCH};
    for (int k = 0; k < (hb ? 5 : 3); k++) {
        fricreg_fit_get_value(fit, cwhich[k], &v);
        fprintf(out, ", \"%s\": %.0f", counts[k], v);
    }
    if (r != NULL && fricreg_fit_get_residuals(fit, n, r, r + n) == FRICREG_OK) {
        cli_json_array(out, "residuals_freq", n, r);
        cli_json_array(out, "residuals_zeta", n, r + n);
    }
    free(r);
    fprintf(out, ", \"cpu_seconds\": %.6f}\n", cpu);
}

/* The fitted backbone on CURVE_POINTS amplitudes from half the smallest level to twice the
 * largest: a[], f[], z[] and the bands' halves df[], dz[] (the quantile times the sd). */
struct curve {
    double a[CURVE_POINTS], f[CURVE_POINTS], z[CURVE_POINTS], df[CURVE_POINTS], dz[CURVE_POINTS];
};

static int make_curve(fricreg_fit *fit, size_t n, size_t cols, const double rows[], struct curve *c)
{
    double lo = rows[0], hi = rows[0], q;
    for (size_t i = 1; i < n; i++) {
        lo = fmin(lo, rows[i * cols]);
        hi = fmax(hi, rows[i * cols]);
    }
    for (int k = 0; k < CURVE_POINTS; k++)
        c->a[k] = 0.5 * lo * pow(4.0 * hi / lo, k / (CURVE_POINTS - 1.0));
    if (fricreg_fit_curve(fit, CURVE_POINTS, c->a, c->f, c->z, c->df, c->dz) != FRICREG_OK ||
        fricreg_fit_get_quantile(fit, &q) != FRICREG_OK) {
        fprintf(stderr, "fricreg-sim: fit: the fitted backbone: %s\n", fricreg_fit_errmsg(fit));
        return CLI_EXIT_RUN;
    }
    for (int k = 0; k < CURVE_POINTS; k++) {
        c->df[k] *= q;
        c->dz[k] *= q;
    }
    return 0;
}

static int write_curve(const char *path, const struct curve *c)
{
    size_t len = 128 + CURVE_POINTS * 7 * 26, used;
    char *buf = malloc(len);
    if (buf == NULL)
        return cli_usage_error("--curve", "out of memory");
    used = (size_t)snprintf(buf, len, "amplitude,freq_hz,zeta,freq_lo,freq_hi,zeta_lo,zeta_hi\n");
    for (int k = 0; k < CURVE_POINTS && used < len; k++)
        used += (size_t)snprintf(buf + used, len - used, "%.9g,%.9g,%.9g,%.9g,%.9g,%.9g,%.9g\n",
                                 c->a[k], c->f[k], c->z[k], c->f[k] - c->df[k], c->f[k] + c->df[k],
                                 c->z[k] - c->dz[k], c->z[k] + c->dz[k]);
    int err = cli_replace_file(path, buf, used);
    free(buf);
    if (err != 0) {
        fprintf(stderr, "fricreg-sim: --curve %s: %s\n", path,
                err < 0 ? "exists and is not a regular file" : strerror(err));
        return CLI_EXIT_RUN;
    }
    return 0;
}

/* gnuplot's script: two panels against the amplitude (log), measured points, the fitted line
 * and its band, from inline data blocks. */
static void plot_script(FILE *gp, const char *tmp, const struct fit_options *o, size_t n,
                        size_t cols, const double rows[], const struct curve *c)
{
    fprintf(gp, "set terminal pngcairo noenhanced size 900,720\nset output '%s'\n", tmp);
    fputs("$levels << EOD\n", gp);
    for (size_t i = 0; i < n; i++)
        fprintf(gp, "%.9g %.9g %.9g\n", rows[i * cols], rows[i * cols + 1], rows[i * cols + 2]);
    fputs("EOD\n$curve << EOD\n", gp);
    for (int k = 0; k < CURVE_POINTS; k++)
        fprintf(gp, "%.9g %.9g %.9g %.9g %.9g %.9g %.9g\n", c->a[k], c->f[k], c->z[k],
                c->f[k] - c->df[k], c->f[k] + c->df[k], c->z[k] - c->dz[k], c->z[k] + c->dz[k]);
    fprintf(gp,
            "EOD\nset multiplot layout 2,1\nset logscale x\nset xlabel '%s amplitude'\n"
            "set ylabel 'natural frequency (Hz)'\n"
            "plot $curve using 1:4:5 with filledcurves fs transparent solid 0.3 "
            "title '95 %% band', $curve using 1:2 with lines lw 2 title 'fitted', "
            "$levels using 1:2 with points pt 7 title 'measured'\n"
            "set logscale y\nset ylabel 'damping ratio'\n"
            "plot $curve using 1:6:7 with filledcurves fs transparent solid 0.3 "
            "title '95 %% band', $curve using 1:3 with lines lw 2 title 'fitted', "
            "$levels using 1:3 with points pt 7 title 'measured'\nunset multiplot\n",
            kind_word(o->kind));
}

static int write_plot(const struct fit_options *o, size_t n, size_t cols, const double rows[],
                      const struct curve *c)
{
    if (system("command -v gnuplot >/dev/null 2>&1") != 0) {
        fprintf(stderr, "fricreg-sim: fit: gnuplot not found: no %s\n", o->plot);
        return 0;
    }
    char tmp[CLI_OUT_PATH];
    snprintf(tmp, sizeof tmp, "%s.part", o->plot);
    FILE *gp = popen("gnuplot", "w");
    if (gp == NULL)
        return cli_usage_error("--plot", "cannot start gnuplot");
    plot_script(gp, tmp, o, n, cols, rows, c);
    if (pclose(gp) != 0 || rename(tmp, o->plot) != 0) {
        unlink(tmp);
        fprintf(stderr, "fricreg-sim: --plot %s: gnuplot failed: no PNG\n", o->plot);
        return CLI_EXIT_RUN;
    }
    return 0;
}

/* The fit of the levels, its summary, curve and plot. */
static int run_fit(fricreg_fit *fit, const struct fit_options *o, size_t n, size_t cols,
                   const double rows[], struct cli_fit_hb *h, FILE *out)
{
    int status = set_up(fit, o, n, cols, rows, h);
    if (status != 0)
        return status;
    clock_t start = clock();
    if (fricreg_fit_run(fit) != FRICREG_OK) {
        fprintf(stderr, "fricreg-sim: fit: %s\n", fricreg_fit_errmsg(fit));
        return CLI_EXIT_RUN;
    }
    write_summary(out, fit, o, h, n, (double)(clock() - start) / CLOCKS_PER_SEC);
    struct curve c;
    if (o->curve == NULL && o->plot == NULL)
        return 0;
    status = make_curve(fit, n, cols, rows, &c);
    if (status == 0 && o->curve != NULL)
        status = write_curve(o->curve, &c);
    if (status == 0 && o->plot != NULL)
        status = write_plot(o, n, cols, rows, &c);
    return status;
}

int cli_fit(int argc, char **argv, FILE *out)
{
    struct fit_options o;
    struct cli_option table[CLI_MAX_ROWS];
    size_t nrows = fit_table(&o, table);
    int status = cli_parse_options(argc, argv, table, nrows, "fit");
    if (status == 0)
        status = check_options(&o);
    if (status != 0)
        return status;
    size_t n, cols;
    double *rows;
    status = cli_read_levels("--levels", o.levels, &n, &cols, &rows);
    if (status != 0)
        return status;
    fricreg_fit *fit = NULL;
    if (fricreg_fit_create(&fit) != FRICREG_OK) {
        free(rows);
        return cli_usage_error("fit", "out of memory");
    }
    struct cli_fit_hb h = {0}; /* an HB model's driver: borrowed by the fit, freed after it */
    status = run_fit(fit, &o, n, cols, rows, &h, out);
    fricreg_fit_free(fit);
    cli_fit_hb_free(&h);
    free(rows);
    return status;
}
