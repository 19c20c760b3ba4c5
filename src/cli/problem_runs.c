/* SPDX-License-Identifier: GPL-3.0-or-later */
/* problem_runs.c — `fricreg-sim hold|belt|disk`: the reference problems beyond the paper
 * (src/problems/, the same code the benchmarks run; docs/laws2d.md), each with a JSON summary
 * of what it measures against its reference and its error estimate against eps -> 0
 * (problem_estimate.h), or a CSV row per GSL step (2 dt); a run that fails (or does not reach
 * what it measures) exits 1. The options are problems.c's. */
#include <errno.h>
#include <math.h>
#include <string.h>
#include <time.h>

#include "base/companion_estimate.h" /* fr_estimate_kind_name */
#include "cli_problems.h"
#include "fricreg_disk.h"
#include "problem_estimate.h"

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)

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
