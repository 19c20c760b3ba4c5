/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element_columns.c — the trajectory's element columns (element_columns.h). Each element's
 * sizes come from its type (fricreg_element_dim, fricreg_element_nstate): the old options'
 * one set (element_table.h) or the --elements sets, in the order the model adds them. */
#include <stdlib.h>
#include <string.h>

#include "element_columns.h"
#include "element_table.h"

/* Elements first .. first + me - 1 of one type into cols's sizes. */
static void set_sizes(struct cli_element_columns *cols, size_t first, size_t me,
                      const fricreg_element_type *type)
{
    for (size_t i = first; i < first + me; i++) {
        cols->dim[i] = (size_t)fricreg_element_dim(type);
        cols->nstate[i] = fricreg_element_nstate(type);
    }
}

int cli_element_columns_make(const char *list, const struct structure_input *in,
                             struct cli_element_columns *cols)
{
    if (list == NULL || strcmp(list, "none") == 0)
        return 0;
    size_t me = in->el.m + in->sets.me;
    int status = cli_expand_dof_list("--output-elements", &cli_element_list, list, me,
                                     &cols->nshown, &cols->shown);
    if (status != 0)
        return status;
    cols->me = me;
    cols->dim = malloc(4 * me * sizeof *cols->dim);
    if (cols->dim == NULL)
        return cli_usage_error("--output-elements", "out of memory");
    cols->nstate = cols->dim + me;
    cols->f_at = cols->nstate + me;
    cols->s_at = cols->f_at + me;
    if (in->el.m > 0)
        set_sizes(cols, 0, in->el.m, cli_elements_type(&in->el));
    for (size_t k = 0, first = in->el.m; k < in->sets.n; first += in->sets.set[k].me, k++)
        set_sizes(cols, first, in->sets.set[k].me, in->sets.set[k].type);
    size_t nf = 0, ns = 0;
    for (size_t i = 0; i < me; i++) {
        cols->f_at[i] = nf;
        cols->s_at[i] = ns;
        nf += cols->dim[i];
        ns += cols->nstate[i];
    }
    cols->f = malloc((nf + ns + 1) * sizeof *cols->f);
    if (cols->f == NULL)
        return cli_usage_error("--output-elements", "out of memory");
    cols->state = cols->f + nf;
    return 0;
}

void cli_element_columns_free(struct cli_element_columns *cols)
{
    free(cols->shown);
    free(cols->dim);
    free(cols->f);
}

void cli_element_columns_header(const struct cli_element_columns *cols, FILE *out)
{
    for (size_t k = 0; k < cols->nshown; k++) {
        size_t i = cols->shown[k];
        for (size_t c = 0; c < cols->dim[i]; c++)
            fprintf(out, ",e%zu_f%zu", i + 1, c + 1);
        for (size_t c = 0; c < cols->nstate[i]; c++)
            fprintf(out, ",e%zu_s%zu", i + 1, c + 1);
    }
}

void cli_element_columns_row(struct cli_element_columns *cols, const fricreg_structure *s,
                             FILE *out)
{
    if (cols->nshown == 0)
        return;
    fricreg_structure_get_elements(s, cols->me, cols->f, cols->state, NULL);
    for (size_t k = 0; k < cols->nshown; k++) {
        size_t i = cols->shown[k];
        for (size_t c = 0; c < cols->dim[i]; c++)
            fprintf(out, ",%.17g", cols->f[cols->f_at[i] + c]);
        for (size_t c = 0; c < cols->nstate[i]; c++)
            fprintf(out, ",%.17g", cols->state[cols->s_at[i] + c]);
    }
}
