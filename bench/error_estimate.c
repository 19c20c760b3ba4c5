/* SPDX-License-Identifier: GPL-3.0-or-later */
/* error_estimate.c — fricreg-bench-error-estimate: the calibration sweep of
 * fricreg_sim_set_error_estimate with one companion (FRICREG_ESTIMATE_ONE_COMPANION: 3 |d1|,
 * 1.6's estimator; the two-companion one shares fricreg_structure's). Over every reference system (the chain at n = 32 and
 * n = 1000 included), every integrator family (fixed rk4 and rk8pd, adaptive rkf45, rk8pd,
 * msadams and msbdf with tolerances 1e-3 … 1e-9 and atol from eps, central-imex), eps from
 * the paper's rule to 1e-8, it compares the estimate of the measured cycle's D with its true
 * error against the Coulomb problem: the exact solver for the oscillators, an RK4 ladder
 * extrapolated in eps for the chain and the two blocks (bench/reference.c; computed once per
 * problem). It prints one CSV line per run and the fractions: bounded (estimate + the
 * reference's uncertainty >= error) and within 10x (estimate <= 10 max(error, uncertainty)).
 * A second part sweeps the caller's atol (1e-2 … 1e-10) and counts runs that neither meet
 * their estimate nor warn. Usage: fricreg-bench-error-estimate [--quick | --atol-only]
 * [--two-companions]: about 15 minutes (the chain of 1000's adaptive runs most of them);
 * --atol-only the second part; --two-companions runs the default estimator of 1.7
 * (FRICREG_ESTIMATE_TWO_COMPANIONS, about twice the time) instead of 1.6's. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "bench.h"
#include "reference.h"

enum { NPROB = 5 };

/* The estimator calibrated: 1.6's one companion, or with --two-companions 1.7's default. */
static int estimator = FRICREG_ESTIMATE_ONE_COMPANION;

static const struct bench_problem problems[NPROB] = {
    {"osc_stick", "oscillator a = 2, omega = 0.5", FRICREG_SYSTEM_OSCILLATOR, 2.0, 0.5, 0, 4, 1e-4,
     1},
    {"osc_slip", "oscillator a = 3, omega = 1.5", FRICREG_SYSTEM_OSCILLATOR, 3.0, 1.5, 0, 4, 1e-4,
     1},
    {"twoblock", "two blocks on a belt", FRICREG_SYSTEM_TWOBLOCK, 0.0, 0.0, 0, 4, 1e-4, 0},
    {"chain32", "chain n = 32", FRICREG_SYSTEM_CHAIN, 0.25, 0.5, 32, 4, 1e-4, 1},
    {"chain1000", "chain n = 1000", FRICREG_SYSTEM_CHAIN, 0.25, 0.5, 1000, 1, 1e-4, 0},
};

/* The system's highest natural frequency (fricreg_sim_run's guard): the fixed steps used. */
static double omega_max(const struct bench_problem *p)
{
    return p->system == FRICREG_SYSTEM_CHAIN      ? 2.0 * (double)p->n
           : p->system == FRICREG_SYSTEM_TWOBLOCK ? sqrt(2.0)
                                                  : 1.0;
}

struct config {
    int integrator;
    double dt, rtol, atol, eps; /* rtol = 0: fixed step; eps = 0: the rule */
};

/* The runs' answer tolerance, the library's default (fricreg_sim_set_answer_rtol): a warning
 * is right where the last cycle's D is off by more than it times |D|, beyond the reference's
 * uncertainty, and a run more than 3 times off must warn (the warnings' precision and recall;
 * a run warns for any cycle or the total, the count judges the last cycle). */
#define ANSWER_RTOL 1e-2

struct tally {
    int runs, failed, bounded, within10, warned, unbounded_unwarned, infinite;
    int answer_warned;   /* warned that the error may exceed the answer tolerance */
    int warned_right;    /* of those, truly off by more than it */
    int far, far_warned; /* truly off by more than 3 times it, and of those the warned */
};

/* The tallies by family: [0] fixed steps, central-imex and one-step adaptive; [1] GSL's
 * multistep msadams and msbdf (their estimate warns). */
static struct tally family[2];

static void add(struct tally *to, const struct tally *t)
{
    to->runs += t->runs;
    to->failed += t->failed;
    to->bounded += t->bounded;
    to->within10 += t->within10;
    to->warned += t->warned;
    to->unbounded_unwarned += t->unbounded_unwarned;
    to->answer_warned += t->answer_warned;
    to->warned_right += t->warned_right;
    to->far += t->far;
    to->far_warned += t->far_warned;
    to->infinite += t->infinite;
}

static int warned(fricreg_sim *sim)
{
    return fricreg_sim_warning_count(sim) > 0;
}

/* Whether sim warns that D's error may exceed the answer tolerance (not that a companion
 * failed, nor that a multistep run's estimate exceeds its tolerances, nor tol_loose). */
static int answer_warned(fricreg_sim *sim)
{
    for (size_t k = 0; k < fricreg_sim_warning_count(sim); k++) {
        int code = 0;
        fricreg_sim_get_warning(sim, k, &code, NULL, 0);
        if (code == FRICREG_WARN_ERROR_ESTIMATE &&
            strstr(fricreg_sim_warning_message(sim, k), "answer tolerance") != NULL)
            return 1;
    }
    return 0;
}

/* One run: 0 and a line, or the run's failure (counted, not in the statistics). */
static void run_one(const struct bench_problem *p, const struct bench_reference *ref,
                    const struct config *c, const char *part, struct tally *t)
{
    fricreg_sim *sim = NULL;
    int status = fricreg_sim_create(p->system, &sim);
    if (p->system != FRICREG_SYSTEM_TWOBLOCK && status == FRICREG_OK) {
        status = fricreg_sim_set_param(sim, FRICREG_PARAM_A, p->a);
        if (status == FRICREG_OK)
            status = fricreg_sim_set_param(sim, FRICREG_PARAM_OMEGA, p->omega);
    }
    if (p->system == FRICREG_SYSTEM_OSCILLATOR && status == FRICREG_OK) /* from rest, as the */
        status = fricreg_sim_set_param(sim, FRICREG_PARAM_X0, 0.0);     /* reference's */
    if (p->n > 0 && status == FRICREG_OK)
        status = fricreg_sim_set_param(sim, FRICREG_PARAM_N, (double)p->n);
    if (status == FRICREG_OK)
        status = fricreg_sim_set_law(sim, FRICREG_LAW_QUINN, c->eps);
    if (status == FRICREG_OK)
        status = fricreg_sim_set_integrator(sim, c->integrator, c->dt, c->rtol, c->atol);
    if (status == FRICREG_OK)
        status = fricreg_sim_set_error_estimate(sim, estimator);
    double t0 = bench_cpu_seconds();
    if (status == FRICREG_OK)
        status = fricreg_sim_run_cycles(sim, p->cycle);
    double cpu = bench_cpu_seconds() - t0;
    double eps = 0.0;
    fricreg_sim_get_value(sim, FRICREG_VALUE_EPS, &eps);
    int multistep = c->rtol > 0 &&
                    (c->integrator == FRICREG_INT_MSADAMS || c->integrator == FRICREG_INT_MSBDF);
    struct tally one = {0};
    if (status != FRICREG_OK) {
        t->failed++;
        if (strcmp(part, "main") == 0)
            family[multistep].failed++;
        printf("%s,%s,%s,%g,%g,%g,%g,failed,,,,,%.3f,\"%s\"\n", part, p->key,
               fricreg_integrator_name(c->integrator), c->dt, c->rtol, c->atol, eps, cpu,
               fricreg_sim_errmsg(sim));
        fricreg_sim_free(sim);
        return;
    }
    double D[64], err[64];
    size_t n = (size_t)p->cycle;
    fricreg_sim_get_dissipation(sim, n, D);
    fricreg_sim_get_dissipation_error(sim, n, err);
    double truth = fabs(D[n - 1] - ref->D), est = err[n - 1];
    int bounded = est + ref->uncertainty >= truth;
    int within = bounded && est <= 10.0 * fmax(truth, ref->uncertainty);
    int w = warned(sim);
    one.runs = 1;
    one.bounded = bounded;
    one.within10 = within;
    one.warned = w;
    one.unbounded_unwarned = !bounded && !w;
    double off = truth - ref->uncertainty; /* surely off by this much */
    one.answer_warned = answer_warned(sim);
    one.warned_right = one.answer_warned && off > ANSWER_RTOL * fabs(ref->D);
    one.far = off > 3.0 * ANSWER_RTOL * fabs(ref->D);
    one.far_warned = one.far && w;
    one.infinite = isinf(est);
    add(t, &one);
    if (strcmp(part, "main") == 0)
        add(&family[multistep], &one);
    printf("%s,%s,%s,%g,%g,%g,%g,ok,%.15g,%.3g,%.3g,%.3g,%.3f,%s%s%s\n", part, p->key,
           fricreg_integrator_name(c->integrator), c->dt, c->rtol, c->atol, eps, D[n - 1], truth,
           est, truth > 0 ? est / truth : INFINITY, cpu, bounded ? "bounded" : "UNBOUNDED",
           within ? " within10" : "", w ? " warned" : "");
    fflush(stdout);
    fricreg_sim_free(sim);
}

static void report(const char *what, const struct tally *t)
{
    printf("# %s: %d runs (+%d failed): bounded %d (%.1f%%), within 10x %d (%.1f%%), warned %d, "
           "unbounded without a warning %d, no estimate (companion failed) %d; answer-tolerance "
           "warnings right (the true error above the tolerance %g) %d of %d, runs more than 3x "
           "it off warned %d of %d\n",
           what, t->runs, t->failed, t->bounded, 100.0 * t->bounded / (t->runs ? t->runs : 1),
           t->within10, 100.0 * t->within10 / (t->runs ? t->runs : 1), t->warned,
           t->unbounded_unwarned, t->infinite, ANSWER_RTOL, t->warned_right, t->answer_warned,
           t->far_warned, t->far);
}

/* The configurations of problem p: fixed steps under the rule and at set eps, adaptive
 * steppers over tolerances and eps, central-imex where it applies. */
static void sweep(const struct bench_problem *p, const struct bench_reference *ref, int quick,
                  struct tally *t)
{
    double w = omega_max(p);
    double base = fmin(0.02, 0.5 / w); /* dt omega_max <= 1/2: inside every guard */
    int is_chain1000 = p->n >= 1000;
    /* fixed rk4 under the paper's rule, three steps */
    for (int k = 0; k < 3; k++)
        run_one(p, ref, &(struct config){FRICREG_INT_RK4, ldexp(base, -k), 0, 0, 0}, "main", t);
    /* fixed rk4 and rk8pd at set eps, dt within the stick zone (dt lambda <= 1) */
    const double fixed_eps[] = {1e-2, 3e-3, 1e-3};
    for (int e = 0; e < 3; e++)
        for (int s = 0; s < 2; s++) {
            if (is_chain1000 && s == 1)
                continue;
            double lambda = 2.0 * (p->system == FRICREG_SYSTEM_TWOBLOCK ? 2.0 : 1.0) / fixed_eps[e];
            double dt = fmin(base, 1.0 / lambda);
            run_one(p, ref,
                    &(struct config){s ? FRICREG_INT_RK8PD : FRICREG_INT_RK4, dt, 0, 0,
                                     fixed_eps[e]},
                    "main", t);
        }
    /* central-imex: eps free of dt (oscillator, chain) */
    if (p->system != FRICREG_SYSTEM_TWOBLOCK) {
        const double eps[] = {1e-2, 1e-4, 1e-6, 1e-8};
        for (int e = 0; e < 4; e++)
            for (int k = 0; k < (is_chain1000 ? 1 : 2); k++)
                run_one(p, ref,
                        &(struct config){FRICREG_INT_CENTRAL_IMEX, ldexp(base, -k), 0, 0, eps[e]},
                        "main", t);
    }
    /* adaptive: tolerances 1e-3 … 1e-9, atol from eps */
    const int steppers[] = {FRICREG_INT_RKF45, FRICREG_INT_RK8PD, FRICREG_INT_MSADAMS,
                            FRICREG_INT_MSBDF};
    const double rtols[] = {1e-3, 1e-5, 1e-7, 1e-9};
    const double eps[] = {1e-2, 1e-4, 1e-6, 1e-8};
    for (int s = 0; s < 4; s++)
        for (int r = 0; r < 4; r++)
            for (int e = 0; e < 4; e++) {
                int implicit = steppers[s] == FRICREG_INT_MSBDF;
                /* explicit steppers cross a stick in steps of eps: too slow below 1e-4 */
                if (!implicit && eps[e] < 1e-4)
                    continue;
                /* the chain of 1000: GSL's multistep steppers' dense Jacobian is out of reach */
                if (is_chain1000 &&
                    (r < 1 || r > 2 || e > 1 || steppers[s] == FRICREG_INT_MSADAMS ||
                     steppers[s] == FRICREG_INT_MSBDF))
                    continue;
                if (quick && (r % 2 || e % 2))
                    continue;
                run_one(p, ref,
                        &(struct config){steppers[s], base, rtols[r], FRICREG_ATOL_FROM_EPS,
                                         eps[e]},
                        "main", t);
            }
}

/* The caller's atol: each run either bounds its error or warns. msbdf (its estimate always
 * warns) and rk8pd (explicit: eps >= 1e-4). */
static void atol_sweep(const struct bench_problem *p, const struct bench_reference *ref,
                       struct tally *t)
{
    const double atols[] = {1e-2, 1e-4, 1e-6, 1e-8, 1e-10};
    const double eps[2][2] = {{1e-3, 1e-6}, {1e-3, 1e-4}};
    const int steppers[] = {FRICREG_INT_MSBDF, FRICREG_INT_RK8PD};
    for (int s = 0; s < 2; s++)
        for (int a = 0; a < 5; a++)
            for (int e = 0; e < 2; e++)
                run_one(p, ref, &(struct config){steppers[s], 0.01, 1e-6, atols[a], eps[s][e]},
                        "atol", t);
}

/* The chain of 1000 blocks, beyond bench_reference's ladder (its first step exceeds the
 * guard): law (4) + RK4 under the paper's rule, dt = 2.5e-4 … 1.6e-5 (5 levels), D
 * Richardson-extrapolated in eps (fricreg_sim_run_extrapolated), its estimate the
 * uncertainty. */
static int extrapolated_reference(const struct bench_problem *p, struct bench_reference *ref)
{
    fricreg_sim *sim = NULL;
    int status = fricreg_sim_create(p->system, &sim);
    if (status == FRICREG_OK)
        status = fricreg_sim_set_param(sim, FRICREG_PARAM_N, (double)p->n);
    if (status == FRICREG_OK)
        status = fricreg_sim_set_integrator(sim, FRICREG_INT_RK4, 2.5e-4, 0.0, 0.0);
    double period = bench_period(p);
    if (status == FRICREG_OK)
        status = fricreg_sim_run_extrapolated(sim, p->cycle * period, 5, 2);
    double D[64], err[64];
    if (status == FRICREG_OK)
        status = fricreg_sim_get_extrapolated_dissipation(sim, (size_t)p->cycle, D, err);
    if (status == FRICREG_OK) {
        ref->D = D[p->cycle - 1];
        ref->uncertainty = err[p->cycle - 1];
        snprintf(ref->how, sizeof ref->how,
                 "law (4) + RK4, dt = 2.5e-4 … 1.6e-5 under the paper's rule, "
                 "Richardson-extrapolated in eps over 5 levels");
    }
    fricreg_sim_free(sim);
    return status;
}

int main(int argc, char **argv)
{
    int quick = 0, atol_only = 0; /* atol_only: the second part */
    for (int i = 1; i < argc; i++) {
        if (strcmp(argv[i], "--quick") == 0)
            quick = 1;
        else if (strcmp(argv[i], "--atol-only") == 0)
            atol_only = 1;
        else if (strcmp(argv[i], "--two-companions") == 0)
            estimator = FRICREG_ESTIMATE_TWO_COMPANIONS;
        else {
            fprintf(stderr, "usage: fricreg-bench-error-estimate [--quick | --atol-only] "
                            "[--two-companions]\n");
            return 2;
        }
    }
    printf("# estimator: %s\n", estimator == FRICREG_ESTIMATE_TWO_COMPANIONS
                                    ? "two companions (1.7's default)"
                                    : "one companion (1.6's)");
    struct bench_reference refs[NPROB];
    for (int k = 0; k < NPROB; k++) {
        if (atol_only && k != 0 && k != 2)
            continue;
        double t0 = bench_cpu_seconds();
        int status = problems[k].n >= 1000 ? extrapolated_reference(&problems[k], &refs[k])
                                           : bench_reference(&problems[k], &refs[k], stderr);
        if (status != FRICREG_OK) {
            fprintf(stderr, "fricreg-bench-error-estimate: reference of %s failed (%d)\n",
                    problems[k].key, status);
            return 1;
        }
        printf("# reference %s cycle %d: D = %.15g +- %.2g (%s; %.1f s)\n", problems[k].key,
               problems[k].cycle, refs[k].D, refs[k].uncertainty, refs[k].how,
               bench_cpu_seconds() - t0);
        fflush(stdout);
    }
    printf("part,problem,integrator,dt,rtol,atol,eps,status,D,error,estimate,ratio,cpu_s,"
           "verdict\n");
    struct tally all = {0}, per[NPROB] = {{0}};
    for (int k = 0; k < NPROB && !atol_only; k++) {
        sweep(&problems[k], &refs[k], quick, &per[k]);
        add(&all, &per[k]);
    }
    struct tally atol = {0};
    atol_sweep(&problems[0], &refs[0], &atol);
    atol_sweep(&problems[2], &refs[2], &atol);
    for (int k = 0; k < NPROB; k++)
        report(problems[k].key, &per[k]);
    report("all", &all);
    report("fixed steps, central-imex, one-step adaptive", &family[0]);
    report("multistep adaptive (msadams, msbdf)", &family[1]);
    report("caller atol 1e-2 … 1e-10 (msbdf, rk8pd; rtol 1e-6)", &atol);
    return 0;
}
