/* SPDX-License-Identifier: GPL-3.0-or-later */
/* dof_list.h — the lists of `fricreg-sim structure --output-dofs LIST`, `--output-contacts
 * LIST` and `--output-elements LIST`: dofs or contacts numbered from 1 as the Matrix Market
 * files number them (a contact is a row of J), elements from 1 in the order the run adds them,
 * comma-separated, each a number or a range A-B (A <= B), e.g. "1-10,57". */
#ifndef FRICREG_CLI_DOF_LIST_H
#define FRICREG_CLI_DOF_LIST_H

#include <stddef.h>

/* What a list names, for its messages: "dof" beyond "the model's" n ("--mass is n x n"),
 * "contact" beyond n ("--contacts has n rows"), or "element" ("the run adds n elements"). */
struct cli_list_kind {
    const char *noun;      /* "dof", "contact" */
    const char *size_says; /* a printf format of n (%zu twice) naming where n comes from */
};
extern const struct cli_list_kind cli_dof_list, cli_contact_list, cli_element_list;

/* Checks LIST's syntax (no model needed: the parser's check). 0, or CLI_EXIT_USAGE after one
 * line on stderr naming option and what is wrong. */
int cli_check_dof_list(const char *option, const struct cli_list_kind *kind, const char *text);

/* The items of LIST against n of them, 0-based, in the order given, into a new
 * items[*count] (the caller frees it). 0, or CLI_EXIT_USAGE after one line on stderr: an item
 * beyond n, or one named twice (a column twice is a mistake), or out of memory. */
int cli_expand_dof_list(const char *option, const struct cli_list_kind *kind, const char *text,
                        size_t n, size_t *count, size_t **items);

#endif
