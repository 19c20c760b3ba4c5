/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb_model.h — what `fricreg-sim hb` and `fricreg-sim nma` share: the structure's matrices
 * (Matrix Market files, passed sparse to fricreg_hb's _csc setters) and its joint elements (one
 * kind by the options of jenkins_input.h, or --elements sets of any kinds, element_sets.h),
 * their option rows, their checks, their reading, the driver's setters and the summaries'
 * element fields. */
#ifndef FRICREG_CLI_HB_MODEL_H
#define FRICREG_CLI_HB_MODEL_H

#include <stddef.h>

#include "cli.h"
#include "element_sets.h"
#include "fricreg_hb.h"
#include "jenkins_input.h"
#include "matrix_market.h"

struct cli_hb_model_options {
    const char *mass, *stiffness, *damping;
    struct cli_element_files elements; /* --jenkins with its parameters (jenkins_input.h) */
    struct cli_element_set_options element_sets; /* --elements, in order (element_sets.h) */
    int rayleigh_given;
    double a0, a1;
};

/* The model: M, K, C (C.colptr NULL: Rayleigh or none) n x n as the files' compressed columns;
 * the elements of one kind (el) or the --elements sets (sets.n > 0), their rows dense; m
 * elements in all (cli_hb_create refuses more than harmonic balance's 256). */
struct cli_hb_model {
    size_t n, m;
    struct cli_sparse M, K, C;
    struct cli_elements el;
    struct cli_element_sets sets;
};

/* --rayleigh's parser: the row's slot is the struct cli_hb_model_options. */
int cli_hb_parse_rayleigh(const struct cli_option *row, const char *text);

/* The model's option rows over o (a struct cli_hb_model_options *). */
/* clang-format off */
#define CLI_HB_MODEL_OPTIONS(o)                                                                 \
    {"--mass", CLI_FILE, .slot = &(o)->mass, .meta = "M.mtx",                                  \
     .help = "mass matrix M, Matrix Market n x n, symmetric positive definite (required)"},    \
    {"--stiffness", CLI_FILE, .slot = &(o)->stiffness, .meta = "K.mtx",                        \
     .help = "stiffness matrix K, n x n, symmetric (required)"},                               \
    {"--damping", CLI_FILE, .slot = &(o)->damping, .meta = "C.mtx",                            \
     .help = "damping matrix C, n x n, symmetric (or --rayleigh; none: undamped)"},            \
    CLI_ELEMENT_OPTIONS(&(o)->elements),                                                        \
    {"--rayleigh", CLI_CUSTOM, .slot = (o), .parse = cli_hb_parse_rayleigh,                    \
     .given = &(o)->rayleigh_given, .meta = "A0,A1",                                            \
     .help = "Rayleigh damping C = A0 M + A1 K (both >= 0)"},                                 \
    {"--elements", CLI_CUSTOM, .slot = &(o)->element_sets, .parse = cli_parse_element_set,     \
     .repeatable = 1, .meta = CLI_ELEMENT_SET_META, .help = cli_element_set_help(),             \
     .dflt = "none"}
/* clang-format on */

/* The defaults (the elements'). */
void cli_hb_model_defaults(struct cli_hb_model_options *o);

/* --mass and --stiffness given, --elements or the elements' options (consistent, 1-D or the 3-D
 * contact), not both --damping and --rayleigh. 0, or CLI_EXIT_USAGE after one line on
 * stderr. */
int cli_hb_check_model(const struct cli_hb_model_options *o);

/* Reads the files into md (freed by cli_hb_free_model, also on failure). 0, or CLI_EXIT_USAGE
 * after one line on stderr naming the option and the file. */
int cli_hb_read_model(const struct cli_hb_model_options *o, struct cli_hb_model *md);
void cli_hb_free_model(struct cli_hb_model *md);

/* fricreg_hb_create for the model at H harmonics into *hb: 0, or CLI_EXIT_USAGE after one line
 * on stderr for cmd, naming the limits where the model is beyond them (no element, more than
 * 2^24 dofs) or the status (FRICREG_ENOMEM where the elements' memory is short). */
int cli_hb_create(const char *cmd, const struct cli_hb_model *md, int harmonics, fricreg_hb **hb);

/* The matrices, Rayleigh's damping and the elements into hb; 0, or CLI_EXIT_USAGE after one line
 * on stderr with the library's reason. */
int cli_hb_set_model(const struct cli_hb_model_options *o, const struct cli_hb_model *md,
                     fricreg_hb *hb);

/* Rows of J of the model's elements: m, 2 m with lift-off (tangential and normal), 3 m for the
 * 3-D contact; the sets' rows in all. */
size_t cli_hb_rows(const struct cli_hb_model *md);

/* The summaries' element fields after "elements": , "element_kind" (the old options' kind
 * name, or the sets' type or "mixed"), and "sliders_per_element" (Iwan elements of the old
 * options) or "element_sets" (element_sets.h). */
void cli_hb_json_elements(FILE *out, const struct cli_hb_model *md);

#endif
