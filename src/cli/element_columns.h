/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element_columns.h — the trajectory's element columns of `fricreg-sim structure
 * --output-elements LIST` (element_columns.c): for each element listed, its force components
 * and its state (the sliders' slips) at every row, read by fricreg_structure_get_elements. */
#ifndef FRICREG_CLI_ELEMENT_COLUMNS_H
#define FRICREG_CLI_ELEMENT_COLUMNS_H

#include <stddef.h>
#include <stdio.h>

#include "dof_list.h"
#include "fricreg_structure.h"
#include "structure_model.h"

/* The elements shown and where each one's numbers sit in fricreg_structure_get_elements's
 * arrays: element i's dim[i] forces from f + f_at[i], its nstate[i] states from
 * state + s_at[i]. */
struct cli_element_columns {
    size_t me, nshown;
    size_t *shown;                      /* [nshown] 0-based, in the order listed */
    size_t *dim, *nstate, *f_at, *s_at; /* [me] */
    double *f, *state;                  /* [sum dim], [sum nstate]: one row's */
};

/* The columns of LIST (dof_list.h's syntax; NULL: none) against in's elements into cols,
 * which must be zeroed. 0, or CLI_EXIT_USAGE after one line on stderr (an element beyond the
 * run's, one named twice, out of memory); either way cols is the caller's to free. */
int cli_element_columns_make(const char *list, const struct structure_input *in,
                             struct cli_element_columns *cols);
void cli_element_columns_free(struct cli_element_columns *cols);

/* The header's columns: ",eI_fC" for C = 1..dim, then ",eI_sK" for K = 1..nstate, I the
 * element's number from 1. */
void cli_element_columns_header(const struct cli_element_columns *cols, FILE *out);

/* The same columns of s's current step (its elements' committed forces and states). */
void cli_element_columns_row(struct cli_element_columns *cols, const fricreg_structure *s,
                             FILE *out);

#endif
