/* SPDX-License-Identifier: GPL-3.0-or-later */
/* structure_steps.h — a run of `fricreg-sim structure` from the structure's time to --t-end
 * (structure_steps.c): what it collects, its steps, the trajectory's CSV rows written at them.
 * Beneath the summary (structure_summary.h) and the command (structure_run.c), which share
 * the run's record. */
#ifndef FRICREG_CLI_STRUCTURE_STEPS_H
#define FRICREG_CLI_STRUCTURE_STEPS_H

#include <stdint.h>
#include <stdio.h>

#include "cli_structure.h"
#include "element_columns.h"
#include "fricreg_structure.h"
#include "structure_model.h"

/* What a run collects beside the structure's own records. */
struct structure_run {
    double *u, *v, *f, *peak; /* [n], [n], [mlib], [n] */
    double *De; /* [2 me]: the elements' dissipation, the 2-D forces; --elements: [me + the
                 * sets' forces] (NULL without elements) */
    FILE *rows; /* CSV rows, or NULL */
    /* What the output shows: the dofs dof[ndof] (0-based; NULL: all n in order), and in the
     * trajectory the contacts contact[ncontact] (NULL: all m in order) of the m of the files
     * (0 without --contacts: not the one of bound 0 standing in). */
    const size_t *dof, *contact;
    size_t ndof, ncontact, m;
    /* --output-elements: the elements' columns of the trajectory, read from s */
    struct cli_element_columns elements;
    const fricreg_structure *s;
    /* --output-every K: a row at step times k dt with k a multiple of every, and at the run's
     * first (rows = 0) and last (t = t_end) */
    double dt, t_end;
    int64_t every, rows_written;
};

/* The k-th dof shown: the selection's, or k itself. */
size_t cli_structure_shown(const struct structure_run *run, size_t k);

/* One of the structure's values (fricreg_structure_get_value's which; 0 if it has none). */
double cli_structure_value(const fricreg_structure *s, int which);

/* The trajectory's header into run->rows: t, u and v at the dofs shown, f at the contacts
 * shown, the elements' columns. */
void cli_structure_csv_header(const struct structure_run *run);

/* Steps of dt to t_end, the last one shortened, the state observed after each: the
 * structure's own schemes in one fricreg_structure_run (its observer writing the rows), GSL's
 * steppers from sample to sample (adaptive ones restart at each with dt as their first step,
 * within --max-steps over the whole run). A fricreg status. */
int cli_structure_advance(fricreg_structure *s, const struct structure_options *o,
                          const struct structure_input *in, struct structure_run *run);

#endif
