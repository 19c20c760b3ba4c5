/* SPDX-License-Identifier: GPL-3.0-or-later */
/* problems.c — the options of `fricreg-sim hold|belt|disk` (cli_problems.h): each problem's one
 * table that its parser and the help read, its defaults, and the checks of the values that the
 * laws or RK4 would refuse; every bad option one line on stderr naming it, exit 2. The runs
 * are problem_runs.c's. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "cli_problems.h"
#include "fricreg_disk.h"

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

/* ---- hold ------------------------------------------------------------------------------- */

enum { H_MU, H_MASS, H_G, H_THETA, H_PHI, H_RATE, H_STEPS, H_DT, H_EPS, H_N };
/* tests/law/test_hold.c's block; theta and eps 0: derived (cli_parse_hold) */
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
        v[H_EPS] = 20.0 * v[H_DT]; /* tests/law/test_hold.c: the stick zone's rate 0.49 / step */
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
