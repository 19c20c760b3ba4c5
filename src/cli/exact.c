/* SPDX-License-Identifier: GPL-3.0-or-later */
/* exact.c — `fricreg-sim exact`: the closed-form oscillator, with the summary fields of a
 * simulated run (integrator "exact"; steps counts the switches). The period, the run length
 * in cycles, the law names and every message come from the library. */
#include <stdlib.h>
#include <time.h>

#include "cli.h"
#include "fricreg_exact.h"

/* The oscillator's parameters a, omega, mun, x0, v0 as the options set them over the
 * library's defaults: a simulation of the oscillator holds both (fricreg_sim_get_param). */
static int oscillator_params(const struct cli_run *run, double p[5])
{
    static const int which[5] = {FRICREG_PARAM_A, FRICREG_PARAM_OMEGA, FRICREG_PARAM_MUN,
                                 FRICREG_PARAM_X0, FRICREG_PARAM_V0};
    fricreg_sim *sim = cli_make_sim(run);
    if (sim == NULL)
        return CLI_EXIT_USAGE;
    for (int k = 0; k < 5; k++)
        fricreg_sim_get_param(sim, which[k], &p[k]);
    fricreg_sim_free(sim);
    return 0;
}

/* A run length the solver refuses is a bad --t-end or --cycles: a usage error naming it. */
static int run_failed(fricreg_exact *ex, int status, const struct cli_run *run)
{
    int usage = status == FRICREG_EINVAL;
    const char *what = usage ? (run->t_end > 0.0 ? "--t-end" : "--cycles") : "exact";
    fprintf(stderr, "fricreg-sim: %s: %s\n", what, fricreg_exact_errmsg(ex));
    fricreg_exact_free(ex);
    return usage ? CLI_EXIT_USAGE : CLI_EXIT_RUN;
}

static double value(const fricreg_exact *ex, int which)
{
    double v = 0.0;
    fricreg_exact_get_value(ex, which, &v);
    return v;
}

int cli_exact_summary(const struct cli_run *run, FILE *out)
{
    double p[5], x, v;
    int status = oscillator_params(run, p);
    if (status != 0)
        return status;
    fricreg_exact *ex = NULL;
    status = fricreg_exact_create(p[0], p[1], p[2], p[3], p[4], &ex);
    if (status != FRICREG_OK) { /* the values passed fricreg_sim_set_param already */
        fprintf(stderr, "fricreg-sim: exact: %s\n", fricreg_strerror(status));
        return CLI_EXIT_RUN;
    }
    clock_t start = clock();
    status = run->t_end > 0.0 ? fricreg_exact_run(ex, run->t_end)
                              : fricreg_exact_run_cycles(ex, run->cycles);
    double cpu_seconds = (double)(clock() - start) / CLOCKS_PER_SEC;
    if (status != FRICREG_OK)
        return run_failed(ex, status, run);
    size_t cycles = fricreg_exact_ncycles(ex);
    double t_end = value(ex, FRICREG_EXACT_VALUE_TIME);
    double period = value(ex, FRICREG_EXACT_VALUE_PERIOD);
    double *D = malloc((cycles + 1) * sizeof *D), stick = 0.0;
    if (D == NULL) {
        fricreg_exact_free(ex);
        fprintf(stderr, "fricreg-sim: out of memory\n");
        return CLI_EXIT_RUN;
    }
    fricreg_exact_dissipation(ex, cycles, D);
    fricreg_exact_state(ex, t_end, &x, &v);
    /* The stick fraction of the last whole cycle, as a simulation reports it. */
    double from = cycles > 0 ? (double)(cycles - 1) * period : 0.0;
    fricreg_exact_stick_fraction(ex, from, cycles > 0 ? (double)cycles * period : t_end, &stick);
    char law[64];
    snprintf(law, sizeof law, "%s+%s", fricreg_law_name(FRICREG_LAW_COULOMB),
             fricreg_law_name(FRICREG_LAW_FORCE_BALANCE));
    struct cli_summary s = {.system = "oscillator",
                            .law = law,
                            .integrator = "exact",
                            .steps = (double)fricreg_exact_nswitches(ex),
                            .t = t_end,
                            .period = period,
                            .cpu_seconds = cpu_seconds,
                            .ndof = 1,
                            .ncontacts = 1,
                            .cycles = cycles,
                            .x = &x,
                            .v = &v,
                            .D = D,
                            .stick = &stick};
    cli_write_summary(out, &s);
    free(D);
    fricreg_exact_free(ex);
    return 0;
}
