/* SPDX-License-Identifier: GPL-3.0-or-later */
/* cli.h — fricreg-sim, the command-line tool: shared declarations of its parts. */
#ifndef FRICREG_CLI_H
#define FRICREG_CLI_H

#include <stdio.h>

#include "fricreg_sim.h"

#define CLI_EXIT_USAGE 2 /* bad option or value: nothing written */
#define CLI_EXIT_RUN 1   /* the simulation failed */

enum cli_output { CLI_SUMMARY, CLI_TRAJECTORY };

/* One run of a reference system, as the options describe it. */
struct cli_run {
    int system;
    int law;
    int integrator;
    double dt, rtol, atol, eps; /* eps = 0: the paper's rule */
    double t_end;               /* 0: use cycles */
    int cycles;
    enum cli_output output;
    int partition;          /* enum fricreg_partition; only twoblock's differs from the default */
    int extrapolate;        /* --extrapolate LEVELS (fricreg_sim_run_extrapolated); 0: off */
    int extrapolate_order;  /* --extrapolate-order P: the declared leading order (0: 1) */
    int extrapolate_window; /* --extrapolate-window W (fricreg_sim_run_extrapolated_window) */
    struct {
        int param;
        double value;
    } params[16];
    int nparams;
};

/* options.c: parses argv (after the subcommand) into run; on error prints one line naming the
 * option to stderr and returns CLI_EXIT_USAGE. */
int cli_parse_run(int system, int argc, char **argv, struct cli_run *run);
/* 0, or CLI_EXIT_USAGE (message printed) for atol = 0 with rtol > 0 on a stepper whose Newton
 * iteration needs atol > 0 (rk1imp, rk2imp, rk4imp, msadams, msbdf). */
int cli_check_tolerances(int integrator, double rtol, double atol);
/* Prints "fricreg-sim: OPTION: WHAT" on stderr and returns CLI_EXIT_USAGE. */
int cli_usage_error(const char *option, const char *what);
/* The option at argv[*k] and its value ("--name=value", or the next argument, advancing *k).
 * Returns 0, or CLI_EXIT_USAGE (message printed) for a non-option or a missing value. */
int cli_next_option(int argc, char **argv, int *k, char **option, char **value);
const char *cli_system_name(int system);
/* Each system's parameter options with the library's defaults, one line per system. */
void cli_print_param_defaults(FILE *out);
/* The library's names name_of(1), name_of(2), … up to the first NULL (fricreg_law_name,
 * fricreg_integrator_name), joined by sep into buf[len] (truncated to fit); returns buf. */
const char *cli_names(char *buf, size_t len, const char *(*name_of)(int), const char *sep);

/* The extrapolation in eps of a run (fricreg_sim_run_extrapolated), for its summary. */
struct cli_extrapolation {
    int levels, order;
    double observed_order, flagged_cycles, eps_finest, rhs_evals, dissipation, dissipation_error;
    const double *D, *err; /* [cycles] per cycle: extrapolated D and its error estimate */
};

/* One run's summary, as `--output summary` prints it (one JSON object). */
struct cli_summary {
    const char *system, *law, *integrator;
    int adaptive;
    double dt, rtol, atol, eps, steps, rhs_evals, t, period, cpu_seconds;
    size_t ndof, ncontacts, cycles;
    const double *x, *v;                    /* [ndof] */
    const double *D;                        /* [cycles] dissipation per cycle */
    const double *stick;                    /* [ncontacts] stick fraction of the last whole cycle */
    const struct cli_extrapolation *extrap; /* NULL: not extrapolated */
};

/* output.c */
void cli_write_summary(FILE *out, const struct cli_summary *s);
int cli_run_summary(const struct cli_run *run, FILE *out);
int cli_run_trajectory(const struct cli_run *run, FILE *out);
/* Applies the run's settings to a new simulation; on failure prints why and returns NULL. */
fricreg_sim *cli_make_sim(const struct cli_run *run);

/* exact.c: `fricreg-sim exact`, the closed-form oscillator (fricreg_exact.h). */
int cli_parse_exact(int argc, char **argv, struct cli_run *run);
int cli_exact_summary(const struct cli_run *run, FILE *out);

/* structure.c: `fricreg-sim structure`, a linear structure from Matrix Market files
 * (fricreg_structure.h); argv after the subcommand. Returns the exit status. */
int cli_structure(int argc, char **argv, FILE *out);

/* problems.c: `fricreg-sim hold|belt|disk`, the reference problems beyond the paper
 * (src/problems/); argv after the subcommand. Returns the exit status, or -1 if command is
 * none of them. */
int cli_problem(const char *command, int argc, char **argv, FILE *out);
/* Their options' defaults, for the usage text. */
void cli_print_problem_defaults(FILE *out);

/* reproduce.c: the paper's experiments into dir, and the comparison table on stdout. */
int cli_reproduce(int argc, char **argv);
/* One row of that table: figure, quantity, the paper's (or reference) value as text, ours,
 * and the difference as text. */
void cli_table_row(const char *figure, const char *quantity, const char *paper, double ours,
                   const char *difference);
/* reproduce_beyond.c: the problems beyond the paper (hold, belt, 2-D oscillator), a CSV each in
 * dir and their table rows. Returns 0, or 1 (message printed). */
int cli_reproduce_beyond(const char *dir);

#endif
