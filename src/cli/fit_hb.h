/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fit_hb.h — `fricreg-sim fit --model hb` (fit_hb.c): the fit of a harmonic-balance model's
 * nonlinear mode (fricreg_fit_set_model_hb) from the model files of `nma` (hb_model.h), its
 * parameters by --param, the levels at a dof by --dof. Numbers on the command line count from
 * 1, as everywhere in fricreg-sim (--mode, --output-dofs, --output-elements): the elements of
 * --param, the parameter's place in an element's layout, the dof, and the positions --fix and
 * --start take; the library's count from 0. */
#ifndef FRICREG_CLI_FIT_HB_H
#define FRICREG_CLI_FIT_HB_H

#include <stddef.h>

#include "cli.h"
#include "fricreg_fit.h"
#include "fricreg_hb.h"
#include "hb_model.h"

/* The most parameters an HB model's fit takes (fricreg_fit_set_model_hb's np). */
#define CLI_FIT_MAX_PARAMS 16
/* Room for a parameter's name: its --param text, canonical ("element:1:10:2", "damping:1"). */
#define CLI_FIT_NAME 64

/* The HB model's options as parsed; kind, first, count, index as the library takes them (from
 * 0), name as the summary writes them (from 1). */
struct cli_fit_hb_options {
    struct cli_hb_model_options model;
    int harmonics, mode, linear_damping, dof, newton_max, backbone;
    int harmonics_given, mode_given, damping_given, dof_given, tol_given, max_given, backbone_given;
    double newton_tol;
    size_t np;
    int kind[CLI_FIT_MAX_PARAMS];
    size_t first[CLI_FIT_MAX_PARAMS], count[CLI_FIT_MAX_PARAMS], index[CLI_FIT_MAX_PARAMS];
    char name[CLI_FIT_MAX_PARAMS][CLI_FIT_NAME];
};

/* The model as read, and its driver (NULL until made). */
struct cli_fit_hb {
    struct cli_hb_model md;
    fricreg_hb *hb;
};

/* --param's parser (repeatable): row->slot is a struct cli_fit_hb_options. */
int cli_fit_parse_param(const struct cli_option *row, const char *text);
/* The --linear-damping words (matrix, modal); the --backbone words (epmc 0, qsma 1). */
extern const struct cli_word cli_fit_dampings[];
extern const struct cli_word cli_fit_backbones[];

/* The HB model's rows over o (a struct cli_fit_hb_options *): the model's (hb_model.h), then
 * --param, --mode, --harmonics, --linear-damping, --dof, --newton-tol, --newton-max,
 * --backbone. */
/* clang-format off */
#define CLI_FIT_HB_OPTIONS(o)                                                                   \
    CLI_HB_MODEL_OPTIONS(&(o)->model),                                                          \
    {"--param", CLI_CUSTOM, .slot = (o), .parse = cli_fit_parse_param, .repeatable = 1,        \
     .meta = "element:FIRST:COUNT:INDEX|damping:1|2",                                          \
     .help = "--model hb: a parameter to fit, repeatable (their order gives the positions of " \
             "--fix and --start, from 1): the value shared by elements FIRST .. FIRST+COUNT-1 " \
             "(numbered from 1 in the order the model adds them) at place INDEX of each one's " \
             "layout (from 1, the column of --elements' P.txt: jenkins 1 kt, 2 mun), or "      \
             "Rayleigh's damping a0 (damping:1) or a1 (damping:2); at least one",             \
     .dflt = "none"},                                                                           \
    {"--mode", CLI_WHOLE, .slot = &(o)->mode, .given = &(o)->mode_given, .lo = 1, .hi = 1e8,   \
     .meta = "K", .help = "--model hb: the mode, from 1 in ascending order of the structure's " \
                          "natural frequencies with its elements stuck"},                      \
    {"--harmonics", CLI_WHOLE, .slot = &(o)->harmonics, .given = &(o)->harmonics_given,        \
     .lo = 1, .hi = FRICREG_HB_MAX_HARMONICS, .meta = "H",                                      \
     .help = "--model hb: harmonics kept in the solution"},                                     \
    {"--linear-damping", CLI_CHOICE, .slot = &(o)->linear_damping, .words = cli_fit_dampings,  \
     .given = &(o)->damping_given,                                                              \
     .help = "--model hb: the linear damping in the mode: the matrix as given, or the linear " \
             "mode's modal damping (then damping:1 is its 2 zeta_k omega_k)"},                 \
    {"--dof", CLI_WHOLE, .slot = &(o)->dof, .given = &(o)->dof_given, .lo = 1, .hi = 1e9,      \
     .meta = "D", .help = "--model hb: the levels' amplitudes are the first harmonic's at dof " \
                          "D (from 1), not modal ones (not with --sensor)",                    \
     .dflt = "modal"},                                                                          \
    {"--newton-tol", CLI_POSITIVE, .slot = &(o)->newton_tol, .given = &(o)->tol_given,         \
     .meta = "TOL", .help = "--model hb: Newton's tolerance at each backbone point (tight: "    \
                            "the fit differentiates the points)"},                              \
    {"--newton-max", CLI_WHOLE, .slot = &(o)->newton_max, .given = &(o)->max_given,            \
     .lo = 1, .hi = 1000, .meta = "N",                                                         \
     .help = "--model hb: Newton's iterations at most per backbone point, 1 to 1000"},          \
    {"--backbone", CLI_CHOICE, .slot = &(o)->backbone, .words = cli_fit_backbones,             \
     .given = &(o)->backbone_given,                                                             \
     .help = "--model hb: the backbone fitted: the nonlinear mode (EPMC), or quasi-static "     \
             "modal analysis (qsma: the cheap route where it holds, its levels modal, its "    \
             "damping the linear mode's; not with --dof or --linear-damping)"}
/* clang-format on */

/* The defaults (H = 7, mode 1, the matrix's damping, Newton 1e-12 and 50). */
void cli_fit_hb_defaults(struct cli_fit_hb_options *o);

/* With --model hb (hb = 1): the model's options consistent and at least one --param; else none
 * of the HB model's options given. 0, or CLI_EXIT_USAGE after one line naming the option. */
int cli_fit_hb_check(const struct cli_fit_hb_options *o, int hb);

/* Reads the model, makes its driver and makes it the fit's model (fricreg_fit_set_model_hb;
 * fricreg_fit_set_sensor_dof with --dof). 0, or CLI_EXIT_USAGE after one line naming the
 * option; h is the caller's to free with cli_fit_hb_free either way. */
int cli_fit_hb_set_up(fricreg_fit *fit, const struct cli_fit_hb_options *o, struct cli_fit_hb *h);
void cli_fit_hb_free(struct cli_fit_hb *h);

#endif
