/* SPDX-License-Identifier: GPL-3.0-or-later */
/* problems.c — `fricreg-sim hold|belt|disk`: the reference problems beyond the paper
 * (src/problems/, the same code the benchmarks run; docs/laws2d.md), each with a JSON summary
 * of what it measures against its reference and its error estimate against eps -> 0
 * (problem_estimate.h), or a CSV row per GSL step (2 dt). Every bad
 * option is one line on stderr naming it, exit 2, nothing on stdout; a run that fails (or does
 * not reach what it measures) exits 1. */
#include <errno.h>
#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include "cli_problems.h"
#include "fricreg_disk.h"
#include "base/companion_estimate.h" /* fr_estimate_kind_name */
#include "problem_estimate.h"

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)
#define RK4_STABLE 2.78 /* RK4's real-axis stability bound, dt * lambda (src/ode/integrator.c) */
#define DISK_MAX 1e250  /* the 2-D laws' largest number (fricreg_disk.h) */

static const struct cli_name_table disk_law_names = {"2-D law", fricreg_disk_law_from_name,
                                                     fricreg_disk_law_name};

/* The stick zone's rate times dt must be inside RK4's stability interval (the library's own
 * step guard, src/ode/step_guard.c, for the 1-D law): 2 bound/(mass eps) dt <= 2.78. */
static int stable_step(double bound_per_mass, double dt, double eps)
{
    double rate = 2.0 * bound_per_mass / eps * dt;
    if (rate <= RK4_STABLE)
        return 0;
    char what[200];
    snprintf(what, sizeof what,
             "dt * 2 mun/(m eps) = %g exceeds RK4's %g: the stick zone is unstable; reduce dt "
             "to %g or raise eps to %g",
             rate, RK4_STABLE, dt * RK4_STABLE / rate, eps * rate / RK4_STABLE);
    return cli_usage_error("--dt", what);
}

/* eps as the laws take it (fricreg_disk.h, fricreg_stribeck.h): at least DBL_MIN, at most
 * `upper` (1e250 for the 2-D laws), named as the option it came from (--dt when eps is derived
 * from dt) rather than refused by the run (exit 1, no option named: fuzz finding). */
static int law_eps(const char *option, double eps, double upper)
{
    if (eps >= DBL_MIN && eps <= upper)
        return 0;
    char what[160];
    snprintf(what, sizeof what, "eps = %g is outside [%g, %g], the law's range", eps, DBL_MIN,
             upper);
    return cli_usage_error(option, what);
}

/* --error-estimate, as fricreg-sim's other commands (the summary's only). */
#define ESTIMATE_ROW(slot_)                                                                  \
    {                                                                                        \
        "--error-estimate", CLI_CHOICE,                                                      \
            .slot = (slot_), .words = cli_estimator_words,                                   \
            .help = "reruns at eps/2, dt/2 and eps/4, dt/4 add each headline number's "      \
                    "*_error_estimate to the summary, about 7x the run; one: eps/2 only, 3x" \
    }

/* --answer-rtol, as fricreg-sim's other commands. */
#define ANSWER_RTOL_ROW(slot_)                                                            \
    {                                                                                     \
        "--answer-rtol", CLI_POSITIVE,                                                    \
            .slot = (slot_), .meta = "X",                                                 \
            .help = "warn (error_estimate) where a headline number's estimate exceeds X " \
                    "times the number, whatever its kind"                                 \
    }

/* A failed run: exit 1 with the reason. */
static int run_failed(const char *command, const char *what, int status)
{
    fprintf(stderr, "fricreg-sim: %s: %s: %s\n", command, what, fricreg_strerror(status));
    return CLI_EXIT_RUN;
}

/* ---- Trajectories: rows to a temporary file, copied to out only when the run succeeded -- */

struct csv {
    FILE *f;
};

static int csv_row(void *user, double t, const double row[], size_t n)
{
    struct csv *c = user;
    fprintf(c->f, "%.17g", t);
    for (size_t i = 0; i < n; i++)
        isnan(row[i]) ? fputc(',', c->f) : fprintf(c->f, ",%.17g", row[i]);
    fputc('\n', c->f);
    return ferror(c->f) != 0;
}

static int csv_open(struct csv *c, const char *header)
{
    c->f = tmpfile();
    if (c->f == NULL) {
        fprintf(stderr, "fricreg-sim: cannot create a temporary file\n");
        return CLI_EXIT_RUN;
    }
    fprintf(c->f, "%s\n", header);
    return 0;
}

/* Copies the rows to out and closes the temporary file; discards them if status != 0. */
static int csv_close(struct csv *c, int status, FILE *out)
{
    int failed = status != 0 || fflush(c->f) != 0 || ferror(c->f);
    rewind(c->f);
    char chunk[1 << 16];
    size_t got;
    while (status == 0 && !failed && (got = fread(chunk, 1, sizeof chunk, c->f)) > 0)
        failed = fwrite(chunk, 1, got, out) != got;
    failed |= ferror(c->f);
    fclose(c->f);
    if (failed && status == 0) {
        fprintf(stderr, "fricreg-sim: writing the trajectory: %s\n", strerror(errno));
        return CLI_EXIT_RUN;
    }
    return status;
}

static double cpu_since(clock_t start)
{
    return (double)(clock() - start) / CLOCKS_PER_SEC;
}

/* ---- hold ------------------------------------------------------------------------------- */

enum { H_MU, H_MASS, H_G, H_THETA, H_PHI, H_RATE, H_STEPS, H_DT, H_EPS, H_N };
/* tests/test_hold.c's block; theta and eps 0: derived (cli_parse_hold) */
static const double hold_defaults[H_N] = {0.5385, 2.385, 9.81, 0.0, 35.4, 0.0, 1e7, 1e-4, 0.0};
#define DISK_REF_EPS 2e-4

/* hold's options as parsed: the values by H_*, and which were given. */
struct hold_options {
    double v[H_N];
    int theta_given, steps_given, eps_given, output;
    struct cli_estimate_options estimate;
};

/* The rows over o, its defaults set: the parser's and the help's one table. */
static size_t hold_table(struct hold_options *o, struct cli_option table[])
{
    *o = (struct hold_options){.output = CLI_SUMMARY,
                               .estimate = {FRICREG_ESTIMATE_TWO_COMPANIONS, CLI_ANSWER_RTOL}};
    memcpy(o->v, hold_defaults, sizeof o->v);
    double *v = o->v;
    const struct cli_option rows[] = {
        {"--mu", CLI_POSITIVE, .slot = &v[H_MU], .meta = "MU", .help = "friction coefficient"},
        {"--mass", CLI_POSITIVE, .slot = &v[H_MASS], .meta = "KG", .help = "the block's mass, kg"},
        {"--g", CLI_POSITIVE, .slot = &v[H_G], .meta = "G", .help = "gravity, m/s^2"},
        {"--theta-deg", CLI_NONNEGATIVE, .slot = &v[H_THETA], .given = &o->theta_given,
         .meta = "DEG", .help = "the incline's tilt at t = 0, degrees, below 90",
         .dflt = "atan(0.8 mu); with --tilt-rate 0.9 atan(mu)"},
        {"--phi-deg", CLI_NUMBER, .slot = &v[H_PHI], .meta = "DEG",
         .help = "the load's direction in the incline's plane, degrees"},
        {"--tilt-rate", CLI_NONNEGATIVE, .slot = &v[H_RATE], .meta = "DEG_PER_S",
         .help = "tilt rate, deg/s: 0 holds the tilt and measures the creep (m/s); above 0 "
                 "tilts until the block breaks away"},
        {"--steps", CLI_POSITIVE, .slot = &v[H_STEPS], .given = &o->steps_given, .meta = "N",
         .help = "classical RK4 steps at most, even, 2 to 10^9",
         .dflt = "1e7; with --tilt-rate to 90 deg and a second more"},
        {"--dt", CLI_POSITIVE, .slot = &v[H_DT], .meta = "S", .help = "RK4 step, s"},
        {"--eps", CLI_POSITIVE, .slot = &v[H_EPS], .given = &o->eps_given, .meta = "EPS",
         .help = "the 2-D law's regularization, m/s", .dflt = "20 dt"},
        ESTIMATE_ROW(&o->estimate.estimator),
        ANSWER_RTOL_ROW(&o->estimate.answer_rtol),
        {"--output", CLI_CHOICE, .slot = &o->output, .words = cli_output_words,
         .help = "a JSON summary, or a CSV row per GSL step (2 dt)"}};
    return cli_copy_rows(table, rows, sizeof rows / sizeof rows[0]);
}

int cli_parse_hold(int argc, char **argv, struct prob_hold *p, enum cli_output *output,
                   struct cli_estimate_options *estimate)
{
    struct hold_options o;
    struct cli_option table[CLI_MAX_ROWS];
    size_t n = hold_table(&o, table);
    double *v = o.v;
    int status = cli_parse_options(argc, argv, table, n, "hold");
    if (status != 0)
        return status;
    *output = o.output;
    *estimate = o.estimate;
    if (!o.theta_given) /* inside the disk: tan(theta) = 0.8 mu, or 0.9 atan(mu) to tilt from */
        v[H_THETA] = (v[H_RATE] > 0.0 ? 0.9 * atan(v[H_MU]) : atan(0.8 * v[H_MU])) / DEG;
    if (v[H_THETA] >= 90.0)
        return cli_usage_error("--theta-deg", "must be below 90");
    if (!o.steps_given && v[H_RATE] > 0.0) { /* to 90 degrees and a second more */
        v[H_STEPS] = 2.0 * ceil(((90.0 - v[H_THETA]) / v[H_RATE] + 1.0) / (2.0 * v[H_DT]));
        if (v[H_STEPS] > 1e9)
            return cli_usage_error("--tilt-rate", "more than 10^9 steps to 90 deg: give --steps");
    }
    if ((status = cli_check_whole("--steps", v[H_STEPS], 2, 1e9)) != 0)
        return status;
    if (fmod(v[H_STEPS], 2.0) != 0.0)
        return cli_usage_error("--steps", "must be even (GSL's rk4 takes two classical steps)");
    if (!o.eps_given)
        v[H_EPS] = 20.0 * v[H_DT]; /* tests/test_hold.c: the stick zone's rate 0.49 / step */
    if ((status = law_eps(o.eps_given ? "--eps" : "--dt", v[H_EPS], DISK_MAX)) != 0)
        return status;
    *p = (struct prob_hold){.mass = v[H_MASS],
                            .g = v[H_G],
                            .mu = v[H_MU],
                            .theta0 = v[H_THETA] * DEG,
                            .phi = v[H_PHI] * DEG,
                            .kappa = v[H_RATE] * DEG,
                            .dt = v[H_DT],
                            .eps = v[H_EPS],
                            .steps = v[H_STEPS]};
    return stable_step(p->mu * p->g, p->dt, p->eps);
}

/* hold's headline numbers: at a fixed tilt the creep and the displacement (both 0 for
 * Coulomb), tilting the break-away angle. */
static size_t hold_numbers(const struct prob_hold *p, const struct prob_hold_result *r, double q[])
{
    if (p->kappa > 0.0) {
        q[0] = 0.5 * (r->theta_rest + r->theta_moving) / DEG;
        return 1;
    }
    q[0] = r->creep;
    q[1] = r->displacement;
    return 2;
}

static const char *const hold_names[2][2] = {{"creep", "displacement"}, {"breakaway_deg", ""}};

/* The hold run at eps / 2^k, dt / 2^k over the same time (problem_estimate.h). */
static int hold_level(const void *problem, int k, double q[])
{
    struct prob_hold p = *(const struct prob_hold *)problem;
    struct prob_hold_result r;
    double scale = ldexp(1.0, -k);
    p.dt *= scale, p.eps *= scale, p.steps /= scale;
    int status = prob_hold_run(&p, NULL, NULL, &r);
    if (status == FRICREG_OK)
        hold_numbers(&p, &r, q);
    return status;
}

/* The headline numbers' estimates and their kinds (cli_problem_estimate). */
struct problem_estimate {
    double err[CLI_ESTIMATE_MAX];
    int kind[CLI_ESTIMATE_MAX];
};

/* ", \"NAME_error_estimate\": err, \"NAME_error_kind\": KIND" for each of the n headline
 * numbers, then their kinds' counts; none when e is NULL. */
static void estimate_fields(FILE *out, size_t n, const char *const names[],
                            const struct problem_estimate *e)
{
    if (e == NULL)
        return;
    for (size_t i = 0; i < n; i++) {
        fprintf(out, ", \"%s_error_estimate\": ", names[i]);
        cli_json_number(out, e->err[i]);
        fprintf(out, ", \"%s_error_kind\": \"%s\"", names[i], fr_estimate_kind_name(e->kind[i]));
    }
    struct cli_kind_counts counts = {{0}};
    cli_count_kinds(&counts, n, e->kind);
    cli_json_kind_counts(out, &counts);
}

static void hold_summary(FILE *out, const struct prob_hold *p, const struct prob_hold_result *r,
                         double cpu, const struct problem_estimate *err,
                         const struct cli_warnings *warnings)
{
    fprintf(out, "{\"system\": \"hold\", \"law\": \"%s\", \"integrator\": \"rk4\", ",
            fricreg_disk_law_name(FRICREG_DISK_QUINN));
    fprintf(out, "\"dt\": %.17g, \"eps\": %.17g, \"steps\": %.0f, \"t\": %.17g, ", p->dt, p->eps,
            r->steps, r->t);
    fprintf(out, "\"mu\": %.17g, \"mass\": %.17g, \"g\": %.17g, ", p->mu, p->mass, p->g);
    fprintf(out, "\"theta_deg\": %.17g, \"phi_deg\": %.17g, \"tilt_rate_deg\": %.17g, ",
            p->theta0 / DEG, p->phi / DEG, p->kappa / DEG);
    if (p->kappa == 0.0) /* tilting, the first speed above 0 is the break-away itself */
        fprintf(out, "\"creep\": %.17g, ", r->creep);
    fprintf(out, "\"displacement\": %.17g, \"slides\": %s", r->displacement,
            r->broke_away ? "true" : "false");
    if (p->kappa > 0.0) {
        double exact = atan(p->mu), mid = 0.5 * (r->theta_rest + r->theta_moving);
        fprintf(out, ", \"breakaway_deg\": %.17g, \"bracket_deg\": [%.17g, %.17g]", mid / DEG,
                r->theta_rest / DEG, r->theta_moving / DEG);
        fprintf(out, ", \"exact_deg\": %.17g, \"error_deg\": %.17g, \"bound_deg\": %.17g",
                exact / DEG, (mid - exact) / DEG, p->kappa * p->dt / DEG);
    }
    double q[2];
    estimate_fields(out, hold_numbers(p, r, q), hold_names[p->kappa > 0.0], err);
    fprintf(out, ", \"cpu_seconds\": %.6f", cpu);
    cli_json_warnings(out, warnings);
    fputs("}\n", out);
}

static int cli_hold(int argc, char **argv, FILE *out)
{
    struct prob_hold p;
    struct prob_hold_result r;
    enum cli_output output = CLI_SUMMARY;
    struct cli_estimate_options estimate;
    int status = cli_parse_hold(argc, argv, &p, &output, &estimate);
    if (status != 0)
        return status;
    struct csv c;
    if (output == CLI_TRAJECTORY && (status = csv_open(&c, "t,theta,x1,x2,v1,v2")) != 0)
        return status;
    clock_t start = clock();
    int run = prob_hold_run(&p, output == CLI_TRAJECTORY ? csv_row : NULL, &c, &r);
    if (run == FRICREG_EDIVERGED) {
        fprintf(stderr, "fricreg-sim: hold: no break-away within %.0f steps\n", p.steps);
        status = CLI_EXIT_RUN;
    } else if (run != FRICREG_OK) {
        status = run_failed("hold", "the run", run);
    }
    if (output == CLI_TRAJECTORY)
        return csv_close(&c, status, out);
    if (status != 0)
        return status;
    struct cli_warnings warnings = {0};
    double q[2];
    struct problem_estimate e;
    size_t n = hold_numbers(&p, &r, q);
    if (estimate.estimator != FRICREG_ESTIMATE_OFF)
        cli_problem_estimate(hold_level, &p, &estimate, n, hold_names[p.kappa > 0.0], q, e.err,
                             e.kind, &warnings);
    cli_print_warnings(&warnings);
    hold_summary(out, &p, &r, cpu_since(start), estimate.estimator ? &e : NULL, &warnings);
    return 0;
}

/* ---- belt ------------------------------------------------------------------------------- */

/* belt's options as parsed. */
struct belt_options {
    struct prob_belt b;
    int eps_given, output;
    struct cli_estimate_options estimate;
};

static size_t belt_table(struct belt_options *o, struct cli_option table[])
{
    *o = (struct belt_options){.b = prob_belt_defaults(),
                               .output = CLI_SUMMARY,
                               .estimate = {FRICREG_ESTIMATE_TWO_COMPANIONS, CLI_ANSWER_RTOL}};
    struct prob_belt *b = &o->b;
    const struct cli_option rows[] = {
        {"--fs", CLI_POSITIVE, .slot = &b->fs, .meta = "FS",
         .help = "static friction level, the curve at zero slip"},
        {"--fk", CLI_NONNEGATIVE, .slot = &b->fk, .meta = "FK",
         .help = "kinetic friction level at fast slip, <= --fs"},
        {"--vs", CLI_POSITIVE, .slot = &b->vs, .meta = "VS", .help = "Stribeck velocity"},
        {"--delta", CLI_POSITIVE, .slot = &b->delta, .meta = "DELTA",
         .help = "Stribeck exponent: k(s) = fk + (fs - fk) exp(-(s/vs)^delta)"},
        {"--v-belt", CLI_POSITIVE, .slot = &b->v_belt, .meta = "V", .help = "belt speed"},
        {"--dt", CLI_POSITIVE, .slot = &b->dt, .meta = "STEP",
         .help = "the regularized run's RK4 step"},
        {"--eps", CLI_POSITIVE, .slot = &b->eps, .given = &o->eps_given, .meta = "EPS",
         .help = "the regularization, a velocity", .dflt = "2 dt"},
        {"--cycles", CLI_WHOLE, .slot = &b->cycles, .lo = 2, .hi = 1000, .meta = "N",
         .help = "the limit cycle measured: the N-th, 2 to 1000"},
        {"--ref-dt", CLI_POSITIVE, .slot = &b->ref_dt, .meta = "STEP",
         .help = "the event-driven reference's RK4 step in its slip phases"},
        ESTIMATE_ROW(&o->estimate.estimator),
        ANSWER_RTOL_ROW(&o->estimate.answer_rtol),
        {"--output", CLI_CHOICE, .slot = &o->output, .words = cli_output_words,
         .help = "a JSON summary, or a CSV row per GSL step of the measured cycle"}};
    return cli_copy_rows(table, rows, sizeof rows / sizeof rows[0]);
}

int cli_parse_belt(int argc, char **argv, struct prob_belt *p, enum cli_output *output,
                   struct cli_estimate_options *estimate)
{
    struct belt_options o;
    struct cli_option table[CLI_MAX_ROWS];
    size_t n = belt_table(&o, table);
    int status = cli_parse_options(argc, argv, table, n, "belt");
    if (status != 0)
        return status;
    *output = o.output;
    *estimate = o.estimate;
    struct prob_belt b = o.b;
    int eps_given = o.eps_given;
    if (b.fk > b.fs)
        return cli_usage_error("--fk", "kinetic above static: must be <= --fs");
    if (!eps_given)
        b.eps = 2.0 * b.dt; /* the paper's rule */
    *p = b;
    if ((status = law_eps(eps_given ? "--eps" : "--dt", p->eps, DBL_MAX)) != 0)
        return status;
    /* a cycle is at most a stick of 2 fs/V and about a natural period of slip: a run of more
     * than 1e9 steps is refused rather than left to run for hours */
    double length = (p->cycles + 1) * (2.0 * PI + 2.0 * p->fs / p->v_belt);
    if (length / p->dt > 1e9)
        return cli_usage_error("--dt", "more than 10^9 steps over the cycles");
    if (length / p->ref_dt > 1e9)
        return cli_usage_error("--ref-dt", "more than 10^9 steps over the cycles");
    return stable_step(p->fs, p->dt, p->eps);
}

static void cycle_fields(FILE *out, const struct prob_belt_cycle *c)
{
    fprintf(out, "\"period\": %.17g, \"amplitude\": %.17g, \"x_min\": %.17g, \"x_max\": %.17g",
            c->period, c->amplitude, c->x_min, c->x_max);
}

/* The belt's check of plausibility (docs/laws2d.md, "Warnings"). Inside the band the
 * regularized law runs straight from fs at v = 0 to k(eps), where the kinetic curve falls
 * from fs like (fs - fk)(s/vs)^delta: with delta < 1 its slope is unbounded at 0, and the
 * band's error relative to fs, of order (fs - fk)/fs (eps/vs)^delta, falls only by 2^delta
 * when eps halves. Measured with --fs 1 --fk 0.7 --vs 0.02 --delta 0.5 --v-belt 0.1: period
 * 1.3 % off at eps = 0.005 (this ratio 0.15), 0.53 % at 0.001 (0.067). With delta >= 1 the
 * error falls at least like eps: no warning. */
#define STRIBECK_BAND_ERROR 1e-2

static void belt_warnings(const struct prob_belt *p, struct cli_warnings *w)
{
    w->n = 0;
    if (!(p->delta < 1.0))
        return;
    double band = (p->fs - p->fk) / p->fs * pow(p->eps / p->vs, p->delta);
    if (band > STRIBECK_BAND_ERROR) {
        w->code[0] = FRICREG_WARN_STRIBECK_EPS;
        snprintf(w->message[0], sizeof w->message[0],
                 "Stribeck delta = %g < 1: the regularization's error near v = 0 is of order "
                 "(fs - fk)/fs (eps/vs)^delta = %.3g and halves only when eps falls %.3gx; "
                 "check the result's convergence in eps",
                 p->delta, band, pow(2.0, 1.0 / p->delta));
        w->n = 1;
    }
}

static const char *const belt_names[2] = {"period", "amplitude"};

/* The regularized belt at eps / 2^k, dt / 2^k, its period measured at the level the run's
 * was (problem_estimate.h). */
struct belt_level {
    struct prob_belt p;
    double level;
};

static int belt_level(const void *problem, int k, double q[])
{
    const struct belt_level *b = problem;
    struct prob_belt p = b->p;
    struct prob_belt_cycle c;
    double scale = ldexp(1.0, -k);
    p.dt *= scale, p.eps *= scale;
    int status = prob_belt_regularized(&p, b->level, NULL, NULL, &c);
    q[0] = c.period, q[1] = c.amplitude;
    return status;
}

static void belt_summary(FILE *out, const struct prob_belt *p, const struct prob_belt_cycle *c,
                         const struct prob_belt_cycle *ref, double cpu,
                         const struct problem_estimate *err, const struct cli_warnings *warnings)
{
    fprintf(out, "{\"system\": \"belt\", \"law\": \"stribeck\", \"integrator\": \"rk4\", ");
    fprintf(out, "\"dt\": %.17g, \"eps\": %.17g, \"steps\": %.0f, \"t\": %.17g, ", p->dt, p->eps,
            c->steps, c->t);
    fprintf(out, "\"fs\": %.17g, \"fk\": %.17g, \"vs\": %.17g, \"delta\": %.17g, ", p->fs, p->fk,
            p->vs, p->delta);
    fprintf(out, "\"v_belt\": %.17g, \"cycle\": %d, ", p->v_belt, p->cycles);
    cycle_fields(out, c);
    fprintf(out, ", \"reference\": {\"method\": \"event-driven\", \"dt\": %.17g, ", p->ref_dt);
    cycle_fields(out, ref);
    fprintf(out, "}, \"period_error\": %.17g, \"amplitude_error\": %.17g",
            fabs(c->period / ref->period - 1.0), fabs(c->amplitude / ref->amplitude - 1.0));
    estimate_fields(out, 2, belt_names, err);
    fprintf(out, ", \"cpu_seconds\": %.6f", cpu);
    cli_json_warnings(out, warnings);
    fputs("}\n", out);
}

static int cli_belt(int argc, char **argv, FILE *out)
{
    struct prob_belt p;
    struct prob_belt_cycle ref, c;
    enum cli_output output = CLI_SUMMARY;
    struct cli_estimate_options estimate;
    int status = cli_parse_belt(argc, argv, &p, &output, &estimate);
    if (status != 0)
        return status;
    clock_t start = clock();
    int run = prob_belt_reference(&p, NULL, NULL, &ref);
    if (run != FRICREG_OK)
        return run_failed("belt", "the event-driven reference found no stick-slip cycle", run);
    struct csv csv;
    if (output == CLI_TRAJECTORY && (status = csv_open(&csv, "t,x,v,f")) != 0)
        return status;
    struct belt_level level = {p, 0.5 * (ref.x_min + ref.x_max)};
    run = prob_belt_regularized(&p, level.level, output == CLI_TRAJECTORY ? csv_row : NULL, &csv,
                                &c);
    if (run != FRICREG_OK)
        status = run_failed("belt", "the regularized run found no limit cycle", run);
    if (output == CLI_TRAJECTORY)
        return csv_close(&csv, status, out);
    if (status != 0)
        return status;
    struct cli_warnings warnings;
    belt_warnings(&p, &warnings);
    double q[2] = {c.period, c.amplitude};
    struct problem_estimate e;
    if (estimate.estimator != FRICREG_ESTIMATE_OFF)
        cli_problem_estimate(belt_level, &level, &estimate, 2, belt_names, q, e.err, e.kind,
                             &warnings);
    cli_print_warnings(&warnings);
    belt_summary(out, &p, &c, &ref, cpu_since(start), estimate.estimator ? &e : NULL, &warnings);
    return 0;
}

/* ---- disk ------------------------------------------------------------------------------- */

/* disk's options as parsed. */
struct disk_options {
    struct prob_disk d;
    double reference;
    int eps_given, output;
    struct cli_estimate_options estimate;
};

static size_t disk_table(struct disk_options *o, struct cli_option table[])
{
    *o = (struct disk_options){.d = prob_disk_defaults(),
                               .reference = DISK_REF_EPS,
                               .output = CLI_SUMMARY,
                               .estimate = {FRICREG_ESTIMATE_TWO_COMPANIONS, CLI_ANSWER_RTOL}};
    struct prob_disk *d = &o->d;
    const struct cli_option rows[] = {
        {"--a", CLI_POSITIVE, .slot = &d->a, .meta = "A", .help = "forcing amplitude"},
        {"--omega", CLI_POSITIVE, .slot = &d->omega, .meta = "W", .help = "forcing frequency"},
        {"--dt", CLI_POSITIVE, .slot = &d->dt, .meta = "STEP", .help = "RK4 step"},
        {"--eps", CLI_POSITIVE, .slot = &d->eps, .given = &o->eps_given, .meta = "EPS",
         .help = "the 2-D law's regularization, a speed", .dflt = "2 dt"},
        {"--ref-eps", CLI_NONNEGATIVE, .slot = &o->reference, .meta = "EPS",
         .help = "the reference run's eps, at dt = eps/2 (0: no reference run)"},
        {"--law", CLI_NAME, .slot = &d->law, .names = &disk_law_names,
         .help = "the 2-D friction law (docs/laws2d.md)"},
        ESTIMATE_ROW(&o->estimate.estimator),
        ANSWER_RTOL_ROW(&o->estimate.answer_rtol),
        {"--output", CLI_CHOICE, .slot = &o->output, .words = cli_output_words,
         .help = "a JSON summary, or a CSV row per GSL step of the measured turn"}};
    return cli_copy_rows(table, rows, sizeof rows / sizeof rows[0]);
}

int cli_parse_disk(int argc, char **argv, struct prob_disk *p, double *ref_eps,
                   enum cli_output *output, struct cli_estimate_options *estimate)
{
    struct disk_options o;
    struct cli_option table[CLI_MAX_ROWS];
    size_t n = disk_table(&o, table);
    int status = cli_parse_options(argc, argv, table, n, "disk");
    if (status != 0)
        return status;
    *output = o.output;
    *estimate = o.estimate;
    struct prob_disk d = o.d;
    double reference = o.reference;
    int eps_given = o.eps_given;
    if (!eps_given)
        d.eps = 2.0 * d.dt; /* the paper's rule */
    *p = d;
    *ref_eps = reference;
    if ((status = law_eps(eps_given ? "--eps" : "--dt", p->eps, DISK_MAX)) != 0 ||
        (*ref_eps > 0.0 && (status = law_eps("--ref-eps", *ref_eps, DISK_MAX)) != 0))
        return status;
    double turns = (p->turns_transient + 1) * 2.0 * PI * p->cycles_per_turn / p->omega;
    if (turns / p->dt > 1e9)
        return cli_usage_error("--dt", "more than 10^9 steps over the four turns");
    if (*ref_eps > 0.0 && turns / (0.5 * *ref_eps) > 1e9)
        return cli_usage_error("--ref-eps", "more than 10^9 steps over the four turns");
    return stable_step(1.0, p->dt, p->eps);
}

static const char *const disk_names[1] = {"dissipation_per_cycle"};

/* The disk at eps / 2^k, dt / 2^k (problem_estimate.h). */
static int disk_level(const void *problem, int k, double q[])
{
    struct prob_disk p = *(const struct prob_disk *)problem;
    struct prob_disk_result r;
    double scale = ldexp(1.0, -k);
    p.dt *= scale, p.eps *= scale;
    int status = prob_disk_run(&p, NULL, NULL, &r);
    q[0] = r.dissipation;
    return status;
}

static void disk_summary(FILE *out, const struct prob_disk *p, const struct prob_disk_result *r,
                         double ref_eps, const struct prob_disk_result *ref, double cpu,
                         const struct problem_estimate *err, const struct cli_warnings *warnings)
{
    fprintf(out, "{\"system\": \"disk\", \"law\": \"%s\", \"integrator\": \"rk4\", ",
            fricreg_disk_law_name(p->law));
    fprintf(out, "\"dt\": %.17g, \"eps\": %.17g, \"steps\": %.0f, \"t\": %.17g, ", p->dt, p->eps,
            r->steps, r->t);
    fprintf(out, "\"a\": %.17g, \"omega\": %.17g, \"mun\": 1, \"period\": %.17g, ", p->a, p->omega,
            2.0 * PI / p->omega);
    fprintf(out, "\"cycles_per_turn\": %d, \"turns_transient\": %d, ", p->cycles_per_turn,
            p->turns_transient);
    fprintf(out, "\"dissipation_per_cycle\": %.17g, \"band_fraction\": %.17g, \"reference\": ",
            r->dissipation, r->band);
    if (ref_eps > 0.0) {
        fprintf(out, "{\"eps\": %.17g, \"dt\": %.17g, \"dissipation_per_cycle\": %.17g", ref_eps,
                0.5 * ref_eps, ref->dissipation);
        fprintf(out, ", \"band_fraction\": %.17g}, \"relative_error\": %.17g", ref->band,
                fabs(r->dissipation / ref->dissipation - 1.0));
    } else {
        fprintf(out, "null, \"relative_error\": null");
    }
    estimate_fields(out, 1, disk_names, err);
    fprintf(out, ", \"cpu_seconds\": %.6f", cpu);
    cli_json_warnings(out, warnings);
    fputs("}\n", out);
}

static int cli_disk(int argc, char **argv, FILE *out)
{
    struct prob_disk p;
    struct prob_disk_result r, ref = {0};
    double ref_eps;
    enum cli_output output = CLI_SUMMARY;
    struct cli_estimate_options estimate;
    int status = cli_parse_disk(argc, argv, &p, &ref_eps, &output, &estimate);
    if (status != 0)
        return status;
    struct csv c;
    if (output == CLI_TRAJECTORY && (status = csv_open(&c, "t,x1,x2,v1,v2,f1,f2")) != 0)
        return status;
    clock_t start = clock();
    int run = prob_disk_run(&p, output == CLI_TRAJECTORY ? csv_row : NULL, &c, &r);
    if (run != FRICREG_OK)
        status = run_failed("disk", "the run", run);
    if (output == CLI_TRAJECTORY)
        return csv_close(&c, status, out);
    if (status == 0 && ref_eps > 0.0) { /* the same problem at a tiny eps, dt = eps/2 */
        struct prob_disk q = p;
        q.eps = ref_eps, q.dt = 0.5 * ref_eps;
        run = prob_disk_run(&q, NULL, NULL, &ref);
        if (run != FRICREG_OK)
            status = run_failed("disk", "the reference run", run);
    }
    if (status != 0)
        return status;
    struct cli_warnings warnings = {0};
    struct problem_estimate e;
    if (estimate.estimator != FRICREG_ESTIMATE_OFF)
        cli_problem_estimate(disk_level, &p, &estimate, 1, disk_names, &r.dissipation, e.err,
                             e.kind, &warnings);
    cli_print_warnings(&warnings);
    disk_summary(out, &p, &r, ref_eps, &ref, cpu_since(start), estimate.estimator ? &e : NULL,
                 &warnings);
    return 0;
}

/* ---- The help (help.c): the tables over options with the defaults set ------------------ */

static size_t hold_help_table(struct cli_option table[])
{
    static struct hold_options o; /* the help's rows point here */
    return hold_table(&o, table);
}

static size_t belt_help_table(struct cli_option table[])
{
    static struct belt_options o;
    return belt_table(&o, table);
}

static size_t disk_help_table(struct cli_option table[])
{
    static struct disk_options o;
    return disk_table(&o, table);
}

const struct cli_command cli_hold_command = {
    "hold", "[--tilt-rate DEG_PER_S] [OPTION]...",
    "a block on an incline: creep at a fixed tilt, or break-away",
    "A block on an incline under gravity along a direction of the incline's plane, with the 2-D "
    "law quinn (docs/laws2d.md, \"The hold test\"): at a fixed tilt inside the friction cone "
    "the summary gives the creep speed (m/s) and displacement; with --tilt-rate the tilt grows "
    "until the block slides, and the summary gives the break-away angle against the exact "
    "atan(mu).",
    hold_help_table};

const struct cli_command cli_belt_command = {
    "belt", "[--fs FS --fk FK --vs VS --delta DELTA --v-belt V] [OPTION]...",
    "a belt-driven oscillator with Stribeck friction: its limit cycle",
    "The oscillator x'' + x = f on a belt moving at V, with Stribeck friction (fricreg_stribeck.h):"
    " the stick-slip limit cycle's period and amplitude by the regularized law, against an "
    "event-driven reference whose stick phases are exact (docs/laws2d.md).",
    belt_help_table};

const struct cli_command cli_disk_command = {
    "disk", "[--law L] [--a A] [--omega W] [--dt STEP] [OPTION]...",
    "the 2-D oscillator under rotating forcing: dissipation per cycle",
    "The 2-D oscillator x'' + x = f + a sin(omega t) (cos Omega t, sin Omega t), mu N = 1, with "
    "a 2-D friction law (docs/laws2d.md, \"Comparison\"): the dissipation D per forcing cycle "
    "over one turn of the forcing direction after three turns of transient, against a reference "
    "run at --ref-eps.",
    disk_help_table};

int cli_problem(const char *command, int argc, char **argv, FILE *out)
{
    if (strcmp(command, "hold") == 0)
        return cli_hold(argc, argv, out);
    if (strcmp(command, "belt") == 0)
        return cli_belt(argc, argv, out);
    if (strcmp(command, "disk") == 0)
        return cli_disk(argc, argv, out);
    return -1;
}
