/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element_sets.h — `fricreg-sim structure`, `hb` and `nma --elements TYPE:J.mtx:P.txt`,
 * repeatable: element sets of any of the kernel's types (fricreg_element.h) in one model, each
 * added by the model's add_elements (fricreg_structure_add_elements, fricreg_hb_add_elements) in
 * the order given (element_sets.c). TYPE is a name of
 * fricreg_element_lookup; J.mtx a Matrix Market (me dim) x n matrix, element i's dim rows
 * consecutive in the type's order; P.txt a line per element of the type's parameters in the
 * kernel's layout, every line the same count (an Iwan type's ns from it). */
#ifndef FRICREG_CLI_ELEMENT_SETS_H
#define FRICREG_CLI_ELEMENT_SETS_H

#include <stddef.h>
#include <stdio.h>

#include "cli.h"
#include "fricreg_element.h"
#include "jenkins_input.h"

/* The most --elements one run takes. */
#define CLI_MAX_ELEMENT_SETS 32

/* One --elements as parsed: its type, and its value's text (pointing into argv) with the
 * two paths' places in it: J.mtx from rows to the last ':', P.txt from params on. */
struct cli_element_set_option {
    const fricreg_element_type *type; /* ns = 1: the family, its ns read with P.txt */
    const char *text;
    size_t rows, rows_len, params;
};

/* The --elements given, in order. */
struct cli_element_set_options {
    size_t n;
    struct cli_element_set_option set[CLI_MAX_ELEMENT_SETS];
};

/* The --elements row's parse (CLI_CUSTOM, repeatable): row->slot is a struct
 * cli_element_set_options, the value TYPE:J.mtx:P.txt appended after TYPE is looked up. */
int cli_parse_element_set(const struct cli_option *row, const char *text);

/* The --elements row's placeholder, and its help with the kernel's type names as the library
 * lists them (fricreg_element_at), so that a new type is in the help once it is in the library. */
#define CLI_ELEMENT_SET_META "TYPE:J.mtx:P.txt"
const char *cli_element_set_help(void);

/* One set as read: me elements of type (its ns set) of dim components and np parameters, J
 * dense row-major [me dim * n], params[me np], line[me] each element's line in P.txt; the
 * paths for messages (rows_path the caller's copy). */
struct cli_element_set {
    const fricreg_element_type *type;
    size_t me, dim, np;
    double *J, *params;
    long *line;
    char *rows_path;
    const char *params_path;
};

/* The sets read, and their totals: me elements, nforces = sum of their dims. */
struct cli_element_sets {
    size_t n, me, nforces;
    struct cli_element_set set[CLI_MAX_ELEMENT_SETS];
};

/* Reads every set's files for n degrees of freedom into sets, which must be zeroed, and checks
 * each element's parameters by its kernel (fricreg_element_explain). 0, or CLI_EXIT_USAGE after
 * one line on stderr naming --elements, the file and the line; either way sets is the caller's
 * to free with cli_free_element_sets. */
int cli_read_element_sets(const struct cli_element_set_options *o, size_t n,
                          struct cli_element_sets *sets);
void cli_free_element_sets(struct cli_element_sets *sets);

/* --elements given beside the element options of one kind per run (the two ways do not mix):
 * CLI_EXIT_USAGE after one line on stderr, else 0. */
int cli_check_element_sets_alone(const struct cli_element_set_options *o,
                                 const struct cli_element_files *e);

/* Adds set e to model for n dofs by the model's add_elements: NULL, or the library's reason
 * (the structure's or the HB driver's errmsg), so that one loop serves either model. */
typedef const char *cli_element_set_adder(void *model, const struct cli_element_set *e, size_t n);

/* Adds the sets to model in order by add. 0, or CLI_EXIT_USAGE after one line naming the set's
 * file and the library's reason. */
int cli_add_element_sets(void *model, cli_element_set_adder *add, size_t n,
                         const struct cli_element_sets *sets);

/* The summary's element_kind: the type's name for one set's type, else "mixed". */
const char *cli_element_sets_kind(const struct cli_element_sets *sets);

/* The summaries' fields of the sets: , "element_kind": the kind, "element_sets": per set its
 * type, nelements and sliders_per_element, in the order given. */
void cli_json_element_sets(FILE *out, const struct cli_element_sets *sets);

#endif
