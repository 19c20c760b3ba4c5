/* exact.c — `fricreg-sim exact`: the closed-form oscillator, with the summary fields of a
 * simulated run (integrator "exact"; steps counts the switches). */
#include <math.h>
#include <stdlib.h>
#include <time.h>

#include "cli.h"
#include "fricreg_exact.h"

#define TWO_PI 6.283185307179586

/* The oscillator's parameters as the options set them, over the paper's defaults. */
static void oscillator_params(const struct cli_run *run, double *a, double *omega, double *mun,
                              double *x0, double *v0)
{
    *a = 0.0, *omega = 1.0, *mun = 1.0, *x0 = 2.75, *v0 = 0.0;
    for (int k = 0; k < run->nparams; k++) {
        double value = run->params[k].value;
        switch (run->params[k].param) {
        case FRICREG_PARAM_A: *a = value; break;
        case FRICREG_PARAM_OMEGA: *omega = value; break;
        case FRICREG_PARAM_MUN: *mun = value; break;
        case FRICREG_PARAM_X0: *x0 = value; break;
        default: *v0 = value; break;
        }
    }
}

int cli_exact_summary(const struct cli_run *run, FILE *out)
{
    double a, omega, mun, x0, v0, x, v;
    oscillator_params(run, &a, &omega, &mun, &x0, &v0);
    double period = TWO_PI / omega;
    double t_end = run->t_end > 0.0 ? run->t_end : run->cycles * period;
    fricreg_exact *ex = NULL;
    clock_t start = clock();
    int status = fricreg_exact_solve(a, omega, mun, x0, v0, t_end, &ex);
    double cpu_seconds = (double)(clock() - start) / CLOCKS_PER_SEC;
    if (status != FRICREG_OK) {
        fprintf(stderr, "fricreg-sim: exact: %s\n", fricreg_strerror(status));
        return status == FRICREG_EINVAL ? CLI_EXIT_USAGE : CLI_EXIT_RUN;
    }
    size_t cycles = fricreg_exact_ncycles(ex);
    double *D = malloc((cycles + 1) * sizeof *D), stick = 0.0;
    if (D == NULL) {
        fricreg_exact_free(ex);
        fprintf(stderr, "fricreg-sim: out of memory\n");
        return CLI_EXIT_RUN;
    }
    fricreg_exact_dissipation(ex, cycles, D);
    fricreg_exact_state(ex, t_end, &x, &v);
    double from = cycles > 0 ? (double)(cycles - 1) * period : 0.0;
    fricreg_exact_stick_fraction(ex, from, cycles > 0 ? cycles * period : t_end, &stick);
    struct cli_summary s = {
        .system = "oscillator", .law = "coulomb+force-balance", .integrator = "exact",
        .steps = (double)fricreg_exact_nswitches(ex), .t = t_end, .period = period,
        .cpu_seconds = cpu_seconds, .ndof = 1, .ncontacts = 1, .cycles = cycles,
        .x = &x, .v = &v, .D = D, .stick = &stick};
    cli_write_summary(out, &s);
    free(D);
    fricreg_exact_free(ex);
    return 0;
}
