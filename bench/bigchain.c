/* SPDX-License-Identifier: GPL-3.0-or-later */
/* bigchain.c — fricreg-bench-bigchain OUTDIR [N …]: the chain of Sec. 3.2 with n = 1000 (or
 * the N given) blocks against event-driven CVODE Adams, D on the first forcing cycle.
 *
 * No independent reference exists at this size: it is law (4) + RK4 extrapolated in eps over
 * three levels (fricreg_sim_run_extrapolated, dt halving with eps under the paper's rule,
 * from the largest step the guard accepts, dt = 0.35/n), with its own error estimate. Then
 * each method's error and CPU seconds (one run each: these take seconds to minutes): fricreg
 * RK4 at dt = 0.35/n and 0.175/n; the implicit prototype of chain_implicit.c (Newmark, Newton
 * on a tridiagonal matrix, law (4) at eps = 1e-4) at dt = 1e-3 and 2.5e-4; the explicit
 * central differences of chain_explicit.c at dt = 0.35/n and 0.9/n; the library's
 * (FRICREG_INT_CENTRAL) at 0.5/n … 0.8/n on its guard's bound, and with law (4) implicit
 * (FRICREG_INT_CENTRAL_IMEX) at 0.5/n … 0.94/n, eps = 2.5 dt; and CVODE Adams at
 * rtol 1e-4, 1e-6, 1e-8, each stopped at a CPU cap of CVODE_CAP seconds (the message says how
 * far it got). Above n = 2000 (10^4) only what fits in minutes: the reference is RK4 at
 * 0.35/n itself, the implicit prototype runs at 1e-3 only, CVODE at 1e-6 only, capped at
 * CVODE_CAP_BIG seconds (FRICREG_BENCH_CVODE_CAP=S sets another). BDF's dense Newton on
 * 2n + 1 unknowns is left out: O(n^3) per Jacobian. Writes bigchain.csv. Not in bench/run.sh
 * by default (FRICREG_BENCH_BIG=1 runs it): n = 1000 takes about a minute of CPU, n = 10^4
 * three. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "bench.h"
#include "chain_explicit.h"
#include "chain_implicit.h"
#ifdef FRICREG_BENCH_CVODE
#include "event_driven.h"
#endif

#define CVODE_CAP 600.0    /* CPU seconds per CVODE run */
#define CVODE_CAP_BIG 60.0 /* the same above n = 2000; FRICREG_BENCH_CVODE_CAP overrides it */

/* The CPU cap of a CVODE run above n = 2000: CVODE_CAP_BIG, or the environment's
 * FRICREG_BENCH_CVODE_CAP seconds (> 0), to let a run finish the cycle. */
static double big_cap(void)
{
    const char *env = getenv("FRICREG_BENCH_CVODE_CAP");
    double cap = env ? strtod(env, NULL) : 0.0;
    return cap > 0.0 ? cap : CVODE_CAP_BIG;
}

struct row {
    const char *method;
    double param, cpu, D, err;
    int status;
    char msg[256];
};

static void record(struct row *r, const char *method, double param, double t0,
                   const struct bench_run *run, double ref)
{
    r->method = method;
    r->param = param;
    r->cpu = bench_cpu_seconds() - t0;
    r->status = run->status;
    r->D = run->D;
    r->err = run->status == FRICREG_OK ? bench_rel_error(run->D, ref) : NAN;
    snprintf(r->msg, sizeof r->msg, "%s", run->status == FRICREG_OK ? "" : run->msg);
}

static int one_n(size_t n, FILE *csv)
{
    struct bench_problem p = {"chain_big", "chain", FRICREG_SYSTEM_CHAIN, 0.25, 0.5, n, 1, 1e-3, 1};
    double dt = 0.35 / (double)n; /* dt * 2n = 0.7 <= 1/sqrt(2): the guard's bound */
    struct bench_run run;
    struct row rows[20];
    int nr = 0;

    /* Above n = 2000 (10^4: RK4 alone takes about 100x the n = 1000 work) the reference is
     * RK4 at the guard's step, not extrapolated, and CVODE gets a shorter cap. */
    int big = n > 2000;
    struct bench_sim_point ref_pt = {
        &p, FRICREG_LAW_QUINN, FRICREG_INT_RK4, dt, 0.0, 0.0, 0, big ? 0 : 3, 0, 0, 0};
    double t0 = bench_cpu_seconds();
    if (bench_sim_run(&ref_pt, &run) != FRICREG_OK) {
        fprintf(stderr, "fricreg-bench-bigchain: n = %zu: the reference failed: %s\n", n, run.msg);
        return 1;
    }
    double ref = run.D;
    printf("\nchain n = %zu, a = 0.25, omega = 0.5, D on cycle 1\n", n);
    if (big) {
        printf("reference: law (4) + RK4, dt = %g (eps = 10 omega dt), not extrapolated: "
               "D = %.15g (%.1f CPU s)\n",
               dt, ref, bench_cpu_seconds() - t0);
        record(&rows[nr++], "rk4/quinn(4)", dt, t0, &run, ref);
        rows[0].err = NAN;
        snprintf(rows[0].msg, sizeof rows[0].msg,
                 "the reference (not extrapolated; at n = 1000 this step's error is 4e-6)");
    } else {
        printf("reference: law (4) + RK4, dt = %g, %g, %g (eps = 10 omega dt), extrapolated: "
               "D = %.15g, estimate %.1e relative%s (%.1f CPU s)\n",
               dt, dt / 2, dt / 4, ref, run.D_error / fabs(ref),
               run.flagged ? ", flagged: no clean order" : "", bench_cpu_seconds() - t0);
        record(&rows[nr++], "rk4/quinn(4)/extrap3", dt, t0, &run, ref);
        rows[0].err = run.D_error / fabs(ref); /* the reference's row: its own estimate */
        snprintf(rows[0].msg, sizeof rows[0].msg, "the reference; error: its estimate%s",
                 run.flagged ? " (flagged: no clean order)" : "");
    }
    for (int k = 0; !big && k < 2; k++) {
        struct bench_sim_point pt = {
            &p, FRICREG_LAW_QUINN, FRICREG_INT_RK4, dt / (1 << k), 0.0, 0.0, 0, 0, 0, 0, 0};
        t0 = bench_cpu_seconds();
        bench_sim_run(&pt, &run);
        record(&rows[nr++], "rk4/quinn(4)", dt / (1 << k), t0, &run, ref);
    }
    static const double implicit_dts[2] = {1e-3, 2.5e-4};
    for (int k = 0; k < (big ? 1 : 2); k++) {
        struct chain_implicit_opts o = {n, p.a, p.omega, 1e-4, implicit_dts[k], 0.0, 1e-12};
        t0 = bench_cpu_seconds();
        chain_implicit_run(&o, &run);
        record(&rows[nr++], "newmark-tridiag/quinn(4)", implicit_dts[k], t0, &run, ref);
        snprintf(
            rows[nr - 1].msg, sizeof rows[nr - 1].msg,
            "prototype (bench/chain_implicit.c); eps = 1e-4; %.2f Newton iterations a step%s%.100s",
            run.rhs_evals / run.steps, run.status == FRICREG_OK ? "" : ": ", run.msg);
    }
    /* Central differences at the guard's step (dt * 2n = 0.7) and beyond it, within their
     * own stability (dt * 2n < 2), eps = 2.5 dt (stick zone: dt * 2/eps = 0.8 < 1). */
    static const double cd_dts[2] = {0.35, 0.9};
    for (int k = 0; k < 2; k++) {
        double h = cd_dts[k] / (double)n;
        struct chain_explicit_opts o = {n, p.a, p.omega, bench_period(&p), 2.5 * h, h};
        t0 = bench_cpu_seconds();
        chain_explicit_run(&o, &run);
        record(&rows[nr++], "central-diff/quinn(4)", h, t0, &run, ref);
        snprintf(rows[nr - 1].msg, sizeof rows[nr - 1].msg,
                 "prototype (bench/chain_explicit.c); eps = 2.5 dt%s",
                 k == 0 ? "" : "; beyond the step guard's dt*2n <= 1/sqrt 2");
    }
    /* The library's central differences (FRICREG_INT_CENTRAL) along its guard's bound
     * (dt*2n/2)^2 + dt*lambda < 0.9, lambda = 2/eps: at dt*n = x, the smallest eps it
     * accepts, with a margin, eps = 2 dt/(0.88 - x^2). The error is mostly law (4)'s, O(eps),
     * so a larger step costs accuracy through the larger eps it needs. */
    static const double cd_lib[4] = {0.5, 0.6, 0.7, 0.8};
    for (int k = 0; k < 4; k++) {
        double h = cd_lib[k] / (double)n, eps_dt = 2.0 / (0.88 - cd_lib[k] * cd_lib[k]);
        struct bench_sim_point pt = {
            &p, FRICREG_LAW_QUINN, FRICREG_INT_CENTRAL, h, 0.0, eps_dt * h, 0, 0, 0, 0, 0};
        t0 = bench_cpu_seconds();
        bench_sim_run(&pt, &run);
        record(&rows[nr++], "central/quinn(4)", h, t0, &run, ref);
        snprintf(rows[nr - 1].msg, sizeof rows[nr - 1].msg, "fricreg_sim; eps = %.3g dt%s%.100s",
                 eps_dt, run.status == FRICREG_OK ? "" : ": ", run.msg);
    }
    /* Central differences with law (4) implicit (FRICREG_INT_CENTRAL_IMEX): the stick zone no
     * longer bounds the step, only the springs, (dt*2n/2)^2 < 0.9, dt*n < 0.949; eps = 2.5 dt
     * keeps law (4)'s band resolved (dt*lambda = 0.8 < 0.9), where the guard needs no
     * friction-reversal bound. */
    static const double imex_dts[4] = {0.5, 0.7, 0.9, 0.94};
    for (int k = 0; k < 4; k++) {
        double h = imex_dts[k] / (double)n;
        struct bench_sim_point pt = {
            &p, FRICREG_LAW_QUINN, FRICREG_INT_CENTRAL_IMEX, h, 0.0, 2.5 * h, 0, 0, 0, 0, 0};
        t0 = bench_cpu_seconds();
        bench_sim_run(&pt, &run);
        record(&rows[nr++], "central-imex/quinn(4)", h, t0, &run, ref);
        snprintf(rows[nr - 1].msg, sizeof rows[nr - 1].msg, "fricreg_sim; eps = 2.5 dt%s%.100s",
                 run.status == FRICREG_OK ? "" : ": ", run.msg);
    }
#ifdef FRICREG_BENCH_CVODE
    static const double rtols[3] = {1e-4, 1e-6, 1e-8};
    for (int k = 0; k < 3; k++) {
        if (big && rtols[k] != 1e-6)
            continue;
        struct ed_point ep = {&p, ED_ADAMS, rtols[k], big ? big_cap() : CVODE_CAP, 0.0};
        t0 = bench_cpu_seconds();
        ed_run(&ep, &run);
        record(&rows[nr++], "cvode-adams/event-driven", rtols[k], t0, &run, ref);
    }
#endif
    printf("%-26s %10s %10s %12s %s\n", "method", "dt|rtol", "cpu s", "rel error", "");
    for (int k = 0; k < nr; k++) {
        const struct row *r = &rows[k];
        printf("%-26s %10.3g %10.3g %12.3e %s\n", r->method, r->param, r->cpu, r->err, r->msg);
        fprintf(csv, "%zu,%s,%g,%.6e,%.15g,%.6e,%d,\"%s\"\n", n, r->method, r->param, r->cpu, r->D,
                r->err, r->status, r->msg);
    }
    return 0;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        fprintf(stderr, "usage: fricreg-bench-bigchain OUTDIR [N …]\n");
        return 2;
    }
    FILE *csv = bench_open_out("fricreg-bench-bigchain", argv[1], "bigchain.csv");
    if (csv == NULL)
        return 1;
    fprintf(csv, "n,method,param,cpu_s,D,rel_error,status,message\n");
    int status = 0;
    if (argc == 2)
        status = one_n(1000, csv);
    for (int k = 2; k < argc; k++)
        status |= one_n((size_t)strtoul(argv[k], NULL, 10), csv);
    fclose(csv);
    return status;
}
