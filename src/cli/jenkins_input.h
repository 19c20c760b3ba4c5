/* SPDX-License-Identifier: GPL-3.0-or-later */
/* jenkins_input.h — the joint elements of `fricreg-sim hb` (hb.c) and `fricreg-sim structure`
 * (structure_model.c), from their files: --jenkins J.mtx (Matrix Market, m x n: element i's
 * q_i = (J x)_i), or for the structure --jenkins-2d J.mtx (2m x n: 2-D element i on rows 2i,
 * 2i + 1, with --jenkins-params, or with --normal and --normal-params: the 3-D contact
 * element, tangential x, y and normal n), and one parameter file, a line per element:
 *   --jenkins-params P.txt   kt mun                       (Jenkins elements)
 *   --iwan-params P.txt      k_1 phi_1 ... k_ns phi_ns    (Iwan elements, ns sliders each)
 *   --iwan-segalman S.txt    F_S K_T chi beta             (Iwan elements, Segalman's model
 *                            discretized into --iwan-sliders NS at --iwan-resolution R)
 *   --normal-params Q.txt    kt mu n0 kn                  (lift-off, with --normal Jn.mtx:
 *                            element i's normal g_i = (Jn x)_i)
 *   --iwan-normal-params Q.txt  n0 kn k_1 mu_1 ... k_ns mu_ns  (Iwan elements with lift-off,
 *                            with --normal Jn.mtx: slider s bounded by mu_s N) */
#ifndef FRICREG_CLI_JENKINS_INPUT_H
#define FRICREG_CLI_JENKINS_INPUT_H

#include <stddef.h>

/* The element options as parsed (file options point into argv). */
struct cli_element_files {
    const char *rows;                      /* --jenkins */
    const char *rows_2d;                   /* --jenkins-2d (instead of --jenkins) */
    const char *jenkins, *iwan, *segalman; /* the parameter files: one of these ... */
    const char *normal, *normal_params;    /* ... or --normal with --normal-params, */
    const char *iwan_normal;               /* ... or with --iwan-normal-params */
    int sliders, sliders_given;            /* --iwan-sliders (Segalman's discretization) */
    double resolution;                     /* --iwan-resolution */
    int resolution_given;
};

/* The element options' rows of a subcommand's option table (cli.h's struct cli_option), e
 * a struct cli_element_files *. */
/* (kept as written: clang-format would take the rows for one braced list) */
/* clang-format off */
#define CLI_ELEMENT_OPTIONS(e)                                                                \
    {"--jenkins", CLI_FILE, .slot = &(e)->rows, .meta = "J.mtx",                              \
     .help = "joint elements' rows, Matrix Market m x n: element i's q_i = (J x)_i, with one " \
             "parameter file below"},                                                         \
    {"--jenkins-2d", CLI_FILE, .slot = &(e)->rows_2d, .meta = "J2.mtx",                       \
     .help = "2-D Jenkins elements instead: element i on rows 2i-1 (x) and 2i (y), with "     \
             "--jenkins-params (isotropic), or --normal (3-D contact)"},                     \
    {"--jenkins-params", CLI_FILE, .slot = &(e)->jenkins, .meta = "P.txt",                    \
     .help = "Jenkins elements: a line kt mun per element (stiffness, slip force)"},          \
    {"--iwan-params", CLI_FILE, .slot = &(e)->iwan, .meta = "P.txt",                          \
     .help = "Iwan elements: a line k_1 phi_1 ... k_ns phi_ns per element, the same ns on "   \
             "every line"},                                                                   \
    {"--iwan-segalman", CLI_FILE, .slot = &(e)->segalman, .meta = "S.txt",                    \
     .help = "Iwan elements from Segalman's model: a line F_S K_T chi beta per element"},    \
    {"--iwan-sliders", CLI_WHOLE, .slot = &(e)->sliders, .lo = 1, .hi = 1024,                \
     .given = &(e)->sliders_given, .meta = "NS",                                              \
     .help = "sliders per element of Segalman's model, 1 to 1024"},                           \
    {"--iwan-resolution", CLI_POSITIVE, .slot = &(e)->resolution,                            \
     .given = &(e)->resolution_given, .meta = "R",                                            \
     .help = "Segalman's model discretized down to R phi_max"},                               \
    {"--normal", CLI_FILE, .slot = &(e)->normal, .meta = "Jn.mtx",                            \
     .help = "lift-off elements: the normal rows, element i's gap g_i = (Jn x)_i, with "      \
             "--normal-params"},                                                              \
    {"--normal-params", CLI_FILE, .slot = &(e)->normal_params, .meta = "Q.txt",               \
     .help = "lift-off elements: a line kt mu n0 kn per element; N = max(0, n0 + kn g)"},     \
    {"--iwan-normal-params", CLI_FILE, .slot = &(e)->iwan_normal, .meta = "Q.txt",            \
     .help = "Iwan elements with lift-off, with --normal: a line n0 kn k_1 mu_1 ... k_ns "     \
             "mu_ns per element, slider s bounded by mu_s N"}
/* clang-format on */

/* The defaults: 50 sliders at resolution 1e-6 (docs/joints.md's rule for Segalman's model). */
void cli_element_defaults(struct cli_element_files *e);

/* Options that need or exclude others: --jenkins (or --jenkins-2d, not both) with exactly one
 * parameter file (required: both must be given), --jenkins-2d with --jenkins-params or with
 * --normal and --normal-params,
 * --normal with --normal-params or --iwan-normal-params (--jenkins only), --iwan-sliders and
 * --iwan-resolution with --iwan-segalman only. 0, or CLI_EXIT_USAGE after one line naming the option. */
int cli_check_elements(const struct cli_element_files *e, int required);

enum cli_element_kind {
    CLI_ELEMENTS_JENKINS,
    CLI_ELEMENTS_IWAN,
    CLI_ELEMENTS_NORMAL,
    CLI_ELEMENTS_JENKINS_2D,
    CLI_ELEMENTS_CONTACT_3D, /* --jenkins-2d with --normal: 2-D elements with lift-off */
    CLI_ELEMENTS_IWAN_NORMAL /* --iwan-normal-params: Iwan elements with lift-off */
};

/* The elements as read: m elements on the rows of J (m x n, dense row-major; 2-D elements: 2m
 * rows, element i's x on row 2i, y on 2i + 1); ns sliders each
 * (1 but for Iwan elements) of stiffness k[m ns] and slip force phi[m ns] (row-major, element
 * i's slider s at [i ns + s]; Jenkins elements: kt, mun); lift-off: kt in k, mu[m], n0[m],
 * kn[m] and the normal rows Jn (m x n); Iwan elements with lift-off: k[m ns], mu[m ns], n0[m],
 * kn[m], Jn. option and path name the parameter file. */
struct cli_elements {
    enum cli_element_kind kind;
    size_t m, ns;
    double *J, *Jn, *k, *phi, *mu, *n0, *kn;
    const char *option, *path;
};

/* Reads the files e names for n degrees of freedom into el, which must be zeroed (nothing read
 * without --jenkins: m = 0). 0, or CLI_EXIT_USAGE after one line on stderr naming the option,
 * the file and the line; either way el is the caller's to free with cli_free_elements. */
int cli_read_elements(const struct cli_element_files *e, size_t n, struct cli_elements *el);
void cli_free_elements(struct cli_elements *el);

/* "jenkins", "iwan", "lift-off", "jenkins-2d", "contact-3d" or "iwan-lift-off", the
 * summaries' element_kind. */
const char *cli_element_kind_name(const struct cli_elements *el);

/* The matrix of option's Matrix Market file path (rows x cols; 0: any), dense row-major into
 * *out[*nrows * *ncols] (a symmetric file's lower triangle mirrored), the caller's to free.
 * 0, or CLI_EXIT_USAGE after one line on stderr naming the option, the file and the line. */
int cli_read_dense(const char *option, const char *path, size_t rows, size_t cols, size_t *nrows,
                   size_t *ncols, double **out);

/* Two columns per row, one row per entity (rows of them: dofs or elements, named by what in
 * the message): into a[rows], b[rows], the caller's to free. 0, or CLI_EXIT_USAGE after one
 * line on stderr naming the option, the file and the line. */
int cli_read_pairs(const char *option, const char *path, size_t rows, const char *what, double **a,
                   double **b);

#endif
