/* SPDX-License-Identifier: GPL-3.0-or-later */
/* cli_structure.h — the options of `fricreg-sim structure` (structure.c) and their parser,
 * apart from the run so that tests/fuzz/fuzz_cli_structure.c can drive it. */
#ifndef FRICREG_CLI_STRUCTURE_H
#define FRICREG_CLI_STRUCTURE_H

#include "cli.h"
#include "element_sets.h"
#include "jenkins_input.h"

enum scheme { SCHEME_NEWMARK, SCHEME_HHT, SCHEME_CENTRAL, SCHEME_GSL };

struct structure_options {
    const char *mass, *stiffness, *damping, *contacts, *mun, *influence, *ground;
    const char *load, *load_history; /* --load P.mtx and its time function g (NULL: g = 1) */
    const char *output_dofs;         /* --output-dofs LIST as given (dof_list.h), or NULL */
    const char *output_contacts;     /* --output-contacts LIST or "none" as given, or NULL */
    const char *output_elements;     /* --output-elements LIST or "none" as given, or NULL */
    const char *checkpoint_in, *checkpoint_out; /* fricreg_structure_save's blob, or NULL */
    struct cli_element_files elements; /* --jenkins with its parameters (jenkins_input.h) */
    struct cli_element_set_options element_sets; /* --elements, in order (element_sets.h) */
    int rayleigh_given, alpha_given, atol_given, law_given, eps_given, law, integrator;
    enum scheme scheme;
    double a0, a1, eps, alpha, dt, t_end, rtol;
    double atol;        /* without --atol and with --rtol > 0: FRICREG_ATOL_FROM_EPS */
    int max_steps;      /* --max-steps: GSL's adaptive steps over the whole run (0: no bound; -1:
                    * not given, the library's bound on each sample's call) */
    int output;         /* enum cli_output, as an int: the option table writes ints */
    int error_estimate; /* --error-estimate on|off|one: enum fricreg_error_estimate (summary only) */
    double answer_rtol;   /* --answer-rtol X (fricreg_structure_set_answer_rtol) */
    int error_companions; /* --error-companions: enum fricreg_estimate_companions */
    int contact_solver;   /* --contact-solver: enum fricreg_contact_solver */
    int output_every;     /* --output-every K: the trajectory's every K-th step (1: every step) */
    int output_every_given;
};

/* Parses argv (after the subcommand) into o, the file options as pointers into argv; checks
 * the options that need or exclude others. On error prints one line naming the option to
 * stderr and returns CLI_EXIT_USAGE, else 0. Reads no file. */
int cli_parse_structure(int argc, char **argv, struct structure_options *o);

#endif
