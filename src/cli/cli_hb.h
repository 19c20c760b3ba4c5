/* SPDX-License-Identifier: GPL-3.0-or-later */
/* cli_hb.h — the options of `fricreg-sim hb` (hb.c) and `fricreg-sim nma` (nma.c) and their
 * parsers, apart from the runs so that tests/fuzz/fuzz_cli_hb.c can drive them. */
#ifndef FRICREG_CLI_HB_H
#define FRICREG_CLI_HB_H

#include "cli.h"
#include "hb_deadline.h"
#include "hb_model.h"

enum { HB_SUMMARY, HB_FRF };
enum { HB_IN_OMEGA, HB_IN_LEVEL };
/* --stability: off, or a method (enum fricreg_hb_stability_method) */
enum { HB_STABILITY_OFF = -1 };

struct hb_options {
    struct cli_hb_model_options model; /* the matrices and elements (hb_model.h) */
    const char *excitation;
    int harmonics, output, omega_start_given, omega_end_given, newton_max;
    int max_points, continue_in, omega_given, level_start_given, level_end_given;
    int stability; /* HB_STABILITY_OFF or enum fricreg_hb_stability_method */
    double omega_start, omega_end, newton_tol, ds, ds_min, ds_max;
    double omega, level_start, level_end; /* --continue-in level */
    struct cli_deadline deadline;         /* --max-seconds */
};

enum { NMA_SUMMARY, NMA_BACKBONE };

struct nma_options {
    struct cli_hb_model_options model; /* the matrices and elements (hb_model.h) */
    int harmonics, mode, points, linear_damping, output, newton_max;
    int continuation; /* NMA_ARCLENGTH (fricreg_hb_nma_continue) or NMA_NATURAL (fricreg_hb_nma) */
    int a0_given, a1_given;
    double a0, a1, newton_tol;
    struct cli_deadline deadline; /* --max-seconds */
};

/* Parse argv (after the subcommand) into o, the file options as pointers into argv, and check
 * the options that need or exclude others (hb: the continued parameter's; nma: the amplitude
 * range). On error print one line naming the option to stderr and return CLI_EXIT_USAGE, else
 * 0. Read no file; the step sizes' order (0 < ds_min <= ds <= ds_max <= 1) is the library's
 * check (fricreg_hb_set_continuation), made once the model is read. */
int cli_parse_hb(int argc, char **argv, struct hb_options *o);
int cli_parse_nma(int argc, char **argv, struct nma_options *o);

#endif
