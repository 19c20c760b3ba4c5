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
    int output;             /* enum cli_output, as an int: the option table writes ints */
    int partition;          /* enum fricreg_partition; only twoblock's differs from the default */
    int extrapolate;        /* --extrapolate LEVELS (fricreg_sim_run_extrapolated); 0: off */
    int extrapolate_order;  /* --extrapolate-order P: the declared leading order (0: 1) */
    int extrapolate_window; /* --extrapolate-window W (fricreg_sim_run_extrapolated_window) */
    int max_steps;          /* --max-steps N (fricreg_sim_set_max_steps); -1: the default */
    int kink_location;      /* --kink-location on|off (fricreg_sim_set_kink_location) */
    int error_estimate;     /* --error-estimate on|off|one (fricreg_sim_set_error_estimate) */
    double answer_rtol;     /* --answer-rtol X (fricreg_sim_set_answer_rtol) */
    struct {
        int param;
        double value;
    } params[16];
    int nparams;
};

/* ---- option_table.c: every subcommand's options, as a table of rows ---------------------- */

/* What an option's value is: how it is parsed and what its row's slot points to. */
enum cli_option_kind {
    CLI_NUMBER,      /* double: a finite number */
    CLI_POSITIVE,    /* double: a finite number > 0 */
    CLI_NONNEGATIVE, /* double: a finite number >= 0 */
    CLI_WHOLE,       /* int: a whole number from lo to hi */
    CLI_NAME,        /* int: a name in one of the library's tables (names) */
    CLI_CHOICE,      /* int: the value of one of a few fixed words (words) */
    CLI_FILE,        /* const char *: a path, pointing into argv; read later */
    CLI_CUSTOM       /* anything: parse(row, text) */
};

/* A library name table: the noun its messages use, and its two look-ups (0 and NULL: none). */
struct cli_name_table {
    const char *what;
    int (*from_name)(const char *name);
    const char *(*name_of)(int id);
};
extern const struct cli_name_table cli_law_names, cli_integrator_names;

/* A fixed word and what it stands for; lists of them end with a NULL word. */
struct cli_word {
    const char *word;
    int value;
};
extern const struct cli_word cli_output_words[]; /* summary, trajectory */
/* --error-estimate on|off|one: enum fricreg_error_estimate's values (two companions, none, one) */
extern const struct cli_word cli_estimator_words[];
/* --error-companions auto|finer|coarser: enum fricreg_estimate_companions (structure only) */
extern const struct cli_word cli_companions_words[];
/* --answer-rtol's default: the library's (fricreg_sim_set_answer_rtol) */
#define CLI_ANSWER_RTOL 1e-2

/* --error-estimate and --answer-rtol of hold, belt and disk. */
struct cli_estimate_options {
    int estimator;      /* enum fricreg_error_estimate */
    double answer_rtol; /* an estimate above answer_rtol |q| warns */
};

/* One option: its name and kind first, the rest by field name, e.g.
 * {"--cycles", CLI_WHOLE, .slot = &run->cycles, .lo = 1, .hi = 1e7, .given = &cycles_given,
 *  .meta = "N", .help = "run length in forcing cycles"}.
 * The same rows give the parser, `fricreg-sim COMMAND --help` and the man page (help.c), so
 * that the text cannot drift from what is accepted. */
struct cli_option {
    const char *name; /* "--dt" */
    enum cli_option_kind kind;
    void *slot;                         /* where the value goes, as the kind says */
    int *given;                         /* set to 1 once the option is parsed; NULL: not needed */
    double lo, hi;                      /* CLI_WHOLE's range */
    const struct cli_name_table *names; /* CLI_NAME */
    const struct cli_word *words;       /* CLI_CHOICE */
    /* CLI_CUSTOM: parses text into row->slot (with row->arg); 0 or CLI_EXIT_USAGE (printed) */
    int (*parse)(const struct cli_option *row, const char *text);
    int arg;
    /* The help: the value's placeholder ("STEP", "M.mtx"; NULL for CLI_NAME and CLI_CHOICE,
     * whose names the help lists from the parser's own tables), what the option means with
     * its units, and the default where the slot's value before parsing does not show it
     * (derived, or a value meaning "not given"; "" shows none). */
    const char *meta, *help, *dflt;
    int hidden;     /* known by name only to be refused with a reason: not in the help */
    int repeatable; /* may be given more than once, each value parsed in turn (a list's
                     * CLI_CUSTOM parse appends it) */
};

/* The most rows a table has (with room for a subcommand's further options). */
#define CLI_MAX_ROWS 48

/* Copies a subcommand's rows[n] into table[CLI_MAX_ROWS]; returns n (aborts if n is above
 * CLI_MAX_ROWS: a table that outgrew the bound is a programming error). */
size_t cli_copy_rows(struct cli_option table[], const struct cli_option rows[], size_t n);

/* A subcommand as its help and the man page describe it (help.c lists them all). */
struct cli_command {
    const char *name;
    const char *synopsis;    /* its arguments after "fricreg-sim NAME" */
    const char *summary;     /* one line, for `fricreg-sim --help` */
    const char *description; /* paragraphs, separated by blank lines ("\n\n") */
    /* Its option table, as its parser builds it, over options of the command's own storage
     * with their defaults set (so the help reads the defaults from the slots): fills
     * table[CLI_MAX_ROWS], returns the number of rows. */
    size_t (*table)(struct cli_option table[]);
};

/* Each subcommand's, next to its table (options.c: oscillator, chain, twoblock and exact;
 * reproduce.c, structure.c, hb.c, nma.c, fit.c, problems.c). */
extern const struct cli_command cli_oscillator_command, cli_chain_command, cli_twoblock_command,
    cli_exact_command, cli_reproduce_command, cli_structure_command, cli_hb_command,
    cli_nma_command, cli_fit_command, cli_hold_command, cli_belt_command, cli_disk_command;

/* help.c: the subcommands in the order the help lists them, ending with NULL. */
extern const struct cli_command *const cli_commands[];
/* The command named name, or NULL. */
const struct cli_command *cli_find_command(const char *name);
/* `fricreg-sim --help`: the subcommands, one line each. */
void cli_print_overview(FILE *out);
/* `fricreg-sim COMMAND --help`: synopsis, description, and every option not hidden with its
 * placeholder, meaning and default. */
void cli_print_command_help(FILE *out, const struct cli_command *command);
/* The man page fricreg-sim(1), in roff (man macros), from the same tables. */
void cli_print_man(FILE *out);

/* --rayleigh A0,A1 of `structure` and `hb`: two finite numbers >= 0, comma-separated (the
 * library names the range too; checked here first so that the message names the option).
 * 0, or CLI_EXIT_USAGE after one line on stderr. */
int cli_parse_rayleigh(const char *option, const char *text, double *a0, double *a1);

/* Parses argv (after the subcommand) against table[n] (n <= CLI_MAX_ROWS): each option's
 * value by its row, each option at most once (a repeatable row's as often as given). Returns 0, or CLI_EXIT_USAGE after one line on
 * stderr naming the option: "unknown option for COMMAND" (also as the last argument), "given
 * twice", "missing value", or its value's fault. */
int cli_parse_options(int argc, char **argv, const struct cli_option table[], size_t n,
                      const char *command);
/* One value by its row's kind, as cli_parse_options does (for a custom parse to build on). */
int cli_parse_value(const struct cli_option *row, const char *text);
/* A finite double, the whole of text (an underflow is kept as the subnormal or zero it gives). */
int cli_parse_number(const char *option, const char *text, double *value);
/* 0, or CLI_EXIT_USAGE (printed) unless value is a whole number from lo to hi. */
int cli_check_whole(const char *option, double value, double lo, double hi);
/* Prints "fricreg-sim: OPTION: WHAT" on stderr and returns CLI_EXIT_USAGE. */
int cli_usage_error(const char *option, const char *what);
/* The option at argv[*k] and its value ("--name=value", or the next argument, advancing *k;
 * NULL when none follows, for the caller to report once it knows the option). Returns 0, or
 * CLI_EXIT_USAGE (message printed) for a non-option. */
int cli_next_option(int argc, char **argv, int *k, char **option, char **value);
/* The library's names name_of(1), name_of(2), … up to the first NULL (fricreg_law_name,
 * fricreg_integrator_name), joined by sep into buf[len] (truncated to fit); returns buf. */
const char *cli_names(char *buf, size_t len, const char *(*name_of)(int), const char *sep);
/* The words joined by ", ", the last by last_sep (" or "), into buf[len]; returns buf. */
const char *cli_join_words(char *buf, size_t len, const struct cli_word words[],
                           const char *last_sep);
/* The entry of words whose word is text, or NULL. */
const struct cli_word *cli_find_word(const struct cli_word words[], const char *text);

/* ---- options.c: the reference systems oscillator|chain|twoblock, and exact ---------------- */

/* Parses argv (after the subcommand) into run; on error prints one line naming the option to
 * stderr and returns CLI_EXIT_USAGE. */
int cli_parse_run(int system, int argc, char **argv, struct cli_run *run);
/* 0, or CLI_EXIT_USAGE (message printed) for atol = 0 with rtol > 0 on a stepper whose Newton
 * iteration needs atol > 0 (rk1imp, rk2imp, rk4imp, msadams, msbdf). */
int cli_check_tolerances(int integrator, double rtol, double atol);
const char *cli_system_name(int system);

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
    const double *atol_used; /* [2 ndof + 1] absolute tolerances of y = (x, v, D), or NULL */
    double kinks;            /* adaptive steps cut at a kink (written for adaptive runs only) */
    size_t ndof, ncontacts, cycles;
    const double *x, *v; /* [ndof] */
    const double *D;     /* [cycles] dissipation per cycle */
    const double *D_err; /* [cycles] its error estimate (fricreg_sim_get_dissipation_error), or
                          * NULL: none made */
    const int *D_kind;   /* [cycles] the estimates' kinds, with D_err */
    const double *stick; /* [ncontacts] stick fraction of the last whole cycle */
    const struct cli_extrapolation *extrap; /* NULL: not extrapolated */
    const struct cli_warnings *warnings;    /* NULL: none judged (an empty list) */
};

/* An object's warnings as fricreg-sim reports them (fricreg_structure_warning_count,
 * fricreg_sim_warning_count): each once on stderr, and as the summary's "warnings" list. */
struct cli_warnings {
    size_t n;
    int code[16];
    char message[16][256];
};

/* Each of w's warnings on stderr, "fricreg-sim: warning: MESSAGE"; the exit status stays the
 * run's. */
void cli_print_warnings(const struct cli_warnings *w);
/* ", \"warnings\": [{\"code\": NAME, \"message\": TEXT}, ...]" (JSON strings escaped). */
void cli_json_warnings(FILE *out, const struct cli_warnings *w);

/* json_out.c: a number as JSON, %.17g or null where it is not finite; ", \"NAME\": [a_0, ...]". */
void cli_json_number(FILE *out, double x);
void cli_json_array(FILE *out, const char *name, size_t n, const double a[]);
/* TEXT as a JSON string, quoted, its quotes, backslashes and control characters escaped. */
void cli_json_string(FILE *out, const char *text);
/* ", \"NAME\": [\"asymptotic\", ...]": each kind (enum fricreg_estimate_kind) by name. */
void cli_json_kinds(FILE *out, const char *name, size_t n, const int kind[]);
/* A summary's count of its estimates by kind: n[kind] for the kinds 1 .. 3. */
struct cli_kind_counts {
    size_t n[4];
};
void cli_count_kinds(struct cli_kind_counts *c, size_t n, const int kind[]);
/* ", \"error_estimate_kinds\": {\"asymptotic\": A, \"bound\": B, \"assumed\": C}" */
void cli_json_kind_counts(FILE *out, const struct cli_kind_counts *c);

/* output.c */
void cli_write_summary(FILE *out, const struct cli_summary *s);
int cli_run_summary(const struct cli_run *run, FILE *out);
int cli_run_trajectory(const struct cli_run *run, FILE *out);
/* Applies the run's settings to a new simulation; on failure prints why and returns NULL. */
fricreg_sim *cli_make_sim(const struct cli_run *run);

/* exact.c: `fricreg-sim exact`, the closed-form oscillator (fricreg_exact.h). */
int cli_parse_exact(int argc, char **argv, struct cli_run *run);
int cli_exact_summary(const struct cli_run *run, FILE *out);

/* structure_run.c: `fricreg-sim structure`, a linear structure from Matrix Market files
 * (fricreg_structure.h); argv after the subcommand. Returns the exit status. */
int cli_structure(int argc, char **argv, FILE *out);

/* problem_runs.c: `fricreg-sim hold|belt|disk`, the reference problems beyond the paper
 * (src/problems/); argv after the subcommand. Returns the exit status, or -1 if command is
 * none of them. */
int cli_problem(const char *command, int argc, char **argv, FILE *out);

/* reproduce.c: the paper's experiments into dir, and the comparison table on stdout. */
int cli_reproduce(int argc, char **argv);
/* One row of that table: figure, quantity, the paper's (or reference) value as text, ours,
 * and the difference as text. */
void cli_table_row(const char *figure, const char *quantity, const char *paper, double ours,
                   const char *difference);
/* reproduce_beyond.c: the problems beyond the paper (hold, belt, 2-D oscillator), a CSV each in
 * dir and their table rows. Returns 0, or 1 (message printed). */
int cli_reproduce_beyond(const char *dir);

/* `fricreg-sim hb` (hb.c): the frequency response of a structure with Jenkins elements by
 * harmonic balance. Returns the exit status. */
int cli_hb(int argc, char **argv, FILE *out);

/* `fricreg-sim fit` (fit.c): a joint's parameters from a test's measured levels (fricreg_fit.h);
 * the JSON summary on out. 0, CLI_EXIT_USAGE or CLI_EXIT_RUN (message printed). */
int cli_fit(int argc, char **argv, FILE *out);

/* `fricreg-sim nma` (nma.c): the backbone of a nonlinear mode of a structure with joint elements
 * by harmonic balance. Returns the exit status. */
int cli_nma(int argc, char **argv, FILE *out);

#endif
