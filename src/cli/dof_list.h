/* SPDX-License-Identifier: GPL-3.0-or-later */
/* dof_list.h — `fricreg-sim structure --output-dofs LIST` (dof_list.c): degrees of freedom
 * numbered from 1 as the Matrix Market files number them, comma-separated, each a number or a
 * range A-B (A <= B), e.g. "1-10,57". */
#ifndef FRICREG_CLI_DOF_LIST_H
#define FRICREG_CLI_DOF_LIST_H

#include <stddef.h>

/* Checks LIST's syntax (no model needed: the parser's check). 0, or CLI_EXIT_USAGE after one
 * line on stderr naming option and what is wrong. */
int cli_check_dof_list(const char *option, const char *text);

/* The dofs of LIST against a model of n dofs, 0-based, in the order given, into a new
 * dofs[*count] (the caller frees it). 0, or CLI_EXIT_USAGE after one line on stderr: a dof
 * beyond n, or one named twice (a column twice is a mistake), or out of memory. */
int cli_expand_dof_list(const char *option, const char *text, size_t n, size_t *count,
                        size_t **dofs);

#endif
