/* SPDX-License-Identifier: GPL-3.0-or-later */
/* main.c — fricreg-sim: runs the paper's reference systems from the command line. */
#include <errno.h>
#include <signal.h>
#include <string.h>

#include <gsl/gsl_errno.h>

#include "cli.h"

static int system_of(const char *name)
{
    if (strcmp(name, "oscillator") == 0)
        return FRICREG_SYSTEM_OSCILLATOR;
    if (strcmp(name, "chain") == 0)
        return FRICREG_SYSTEM_CHAIN;
    if (strcmp(name, "twoblock") == 0)
        return FRICREG_SYSTEM_TWOBLOCK;
    return 0;
}

static int dispatch(int argc, char **argv);

/* --help or -h anywhere after a subcommand asks for that subcommand's help (no number, name
 * or sensible file name is spelled so; before, it was a "missing value"). */
static int wants_help(int argc, char **argv)
{
    for (int k = 2; k < argc; k++)
        if (strcmp(argv[k], "--help") == 0 || strcmp(argv[k], "-h") == 0)
            return 1;
    return 0;
}

/* Every byte written reaches its file, or the exit status says it did not: stdout's last
 * buffer is flushed and closed here, and a file-size limit fails a write (EFBIG) instead of
 * killing the program with SIGXFSZ. */
int main(int argc, char **argv)
{
    signal(SIGXFSZ, SIG_IGN);
    int status = dispatch(argc, argv);
    if (fflush(stdout) != 0 || ferror(stdout)) {
        fprintf(stderr, "fricreg-sim: writing standard output: %s\n", strerror(errno));
        fclose(stdout);
        return status ? status : CLI_EXIT_RUN;
    }
    if (fclose(stdout) != 0) {
        fprintf(stderr, "fricreg-sim: closing standard output: %s\n", strerror(errno));
        return status ? status : CLI_EXIT_RUN;
    }
    return status;
}

static int dispatch(int argc, char **argv)
{
    /* The program's own choice (docs/reliability.md): GSL reports by status, never aborts —
     * memory running out inside a GSL stepper. */
    gsl_set_error_handler_off();
    if (argc < 2) {
        cli_print_overview(stderr);
        return CLI_EXIT_USAGE;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        cli_print_overview(stdout);
        return 0;
    }
    if (strcmp(argv[1], "--man") == 0) { /* not in the help: the build writes fricreg-sim.1 */
        cli_print_man(stdout);
        return 0;
    }
    const struct cli_command *command = cli_find_command(argv[1]);
    if (command == NULL && strcmp(argv[1], "--version") != 0) {
        fprintf(stderr, "fricreg-sim: %s: unknown command (see fricreg-sim --help)\n", argv[1]);
        return CLI_EXIT_USAGE;
    }
    if (command != NULL && wants_help(argc, argv)) {
        cli_print_command_help(stdout, command);
        return 0;
    }
    if (strcmp(argv[1], "--version") == 0) {
        printf("fricreg-sim %s\n", fricreg_version());
        return 0;
    }
    if (strcmp(argv[1], "reproduce") == 0)
        return cli_reproduce(argc - 2, argv + 2);
    if (strcmp(argv[1], "structure") == 0)
        return cli_structure(argc - 2, argv + 2, stdout);
    if (strcmp(argv[1], "hb") == 0)
        return cli_hb(argc - 2, argv + 2, stdout);
    if (strcmp(argv[1], "nma") == 0)
        return cli_nma(argc - 2, argv + 2, stdout);
    if (strcmp(argv[1], "fit") == 0)
        return cli_fit(argc - 2, argv + 2, stdout);
    int problem = cli_problem(argv[1], argc - 2, argv + 2, stdout);
    if (problem >= 0)
        return problem;
    struct cli_run run;
    if (strcmp(argv[1], "exact") == 0) {
        int status = cli_parse_exact(argc - 2, argv + 2, &run);
        return status ? status : cli_exact_summary(&run, stdout);
    }
    int system = system_of(argv[1]);
    int status = cli_parse_run(system, argc - 2, argv + 2, &run);
    if (status != 0)
        return status;
    return run.output == CLI_SUMMARY ? cli_run_summary(&run, stdout)
                                     : cli_run_trajectory(&run, stdout);
}
