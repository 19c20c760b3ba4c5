/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fuzz_cli_options.c — fuzz target: fricreg-sim's option parsing (src/cli/options.c), the
 * seam that turns argv into a run without running anything: cli_parse_run for each system,
 * cli_parse_exact for `exact`, and the splitter cli_next_option under both. The input's first
 * byte picks the subcommand; the rest is argv, one argument per line. Contract (src/cli/cli.h
 * and the usage text): the status is 0 or CLI_EXIT_USAGE (2), never a crash or undefined
 * behaviour (run under UBSan: e.g. a float-to-int overflow of --cycles); on success every
 * field is one the library takes: a known law, integrator and partition, dt > 0, eps, rtol,
 * atol and t_end >= 0 and finite, 1 <= cycles <= 10^7, not both --t-end and --cycles, and
 * each system parameter accepted by fricreg_sim_set_param on a fresh simulation. */
#include "fuzz_input.h"

#include "cli.h"

enum { MAX_ARGS = 24, MAX_ARG_LEN = 64 };

static void check_run(int system, const struct cli_run *run, int exact)
{
    FUZZ_REQUIRE(run->system == system, "system %d", run->system);
    FUZZ_REQUIRE(fricreg_law_name(run->law) != NULL, "law %d", run->law);
    FUZZ_REQUIRE(fricreg_integrator_name(run->integrator) != NULL, "integrator %d",
                 run->integrator);
    FUZZ_REQUIRE(isfinite(run->dt) && run->dt > 0.0, "dt %g", run->dt);
    FUZZ_REQUIRE(isfinite(run->eps) && run->eps >= 0.0, "eps %g", run->eps);
    FUZZ_REQUIRE(isfinite(run->rtol) && run->rtol >= 0.0, "rtol %g", run->rtol);
    FUZZ_REQUIRE(isfinite(run->atol) && run->atol >= 0.0, "atol %g", run->atol);
    FUZZ_REQUIRE(isfinite(run->t_end) && run->t_end >= 0.0, "t_end %g", run->t_end);
    FUZZ_REQUIRE(run->cycles >= 1 && run->cycles <= 10000000, "cycles %d", run->cycles);
    FUZZ_REQUIRE(run->output == CLI_SUMMARY || (!exact && run->output == CLI_TRAJECTORY),
                 "output %d", (int)run->output);
    FUZZ_REQUIRE(run->partition == FRICREG_PARTITION_CONSISTENT ||
                     (system == FRICREG_SYSTEM_TWOBLOCK &&
                      run->partition == FRICREG_PARTITION_PAPER),
                 "partition %d", run->partition);
    FUZZ_REQUIRE(run->nparams >= 0 && run->nparams <= 16, "nparams %d", run->nparams);
    fricreg_sim *sim = NULL;
    if (fricreg_sim_create(system, &sim) != FRICREG_OK)
        return;
    for (int k = 0; k < run->nparams; k++) {
        int status = fricreg_sim_set_param(sim, run->params[k].param, run->params[k].value);
        FUZZ_REQUIRE(status == FRICREG_OK, "param %d = %g refused: %s", run->params[k].param,
                     run->params[k].value, fricreg_sim_errmsg(sim));
    }
    fricreg_sim_free(sim);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    static const int systems[4] = {FRICREG_SYSTEM_OSCILLATOR, FRICREG_SYSTEM_CHAIN,
                                   FRICREG_SYSTEM_TWOBLOCK, FRICREG_SYSTEM_OSCILLATOR};
    if (size == 0)
        return 0;
    int sub = data[0] % 4, exact = sub == 3;
    char text[MAX_ARGS][MAX_ARG_LEN + 1];
    char *argv[MAX_ARGS + 1];
    int argc = 0;
    size_t len = 0;
    for (size_t k = 1; k <= size && argc < MAX_ARGS; k++) {
        if (k == size || data[k] == '\n') { /* one argument per line; the last may be open */
            if (k < size || len > 0) {
                text[argc][len] = '\0';
                argv[argc] = text[argc];
                argc++;
            }
            len = 0;
        } else if (len < MAX_ARG_LEN) {
            text[argc][len++] = data[k] ? (char)data[k] : ' ';
        }
    }
    argv[argc] = NULL;
    struct cli_run run;
    int status = exact ? cli_parse_exact(argc, argv, &run)
                       : cli_parse_run(systems[sub], argc, argv, &run);
    FUZZ_REQUIRE(status == 0 || status == CLI_EXIT_USAGE, "parse: status %d", status);
    if (status == 0)
        check_run(systems[sub], &run, exact);
    return 0;
}
