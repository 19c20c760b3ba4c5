/* SPDX-License-Identifier: GPL-3.0-or-later */
/* structure_model.h — the model of `fricreg-sim structure` from its files into the structure
 * (structure_model.c): matrices kept sparse from the file to the library. */
#ifndef FRICREG_CLI_STRUCTURE_MODEL_H
#define FRICREG_CLI_STRUCTURE_MODEL_H

#include "cli_structure.h"
#include "fricreg_structure.h"
#include "matrix_market.h"

/* The model as read: M, K, C (no columns: Rayleigh or none) n x n and J m x n in compressed
 * sparse columns; the joint elements (jenkins_input.h, their rows dense as for fricreg-sim
 * hb; el.m = 0: none); the influence r[n] (NULL: not given), the bounds mun[m] and the ground
 * record ag[nrec] (NULL: none) from t0 every dt_rec. */
struct structure_input {
    size_t n, m, nrec;
    struct cli_elements el;
    struct cli_sparse M, K, C, J;
    double *mun, *r, *ag;
    double t0, dt_rec;
};

/* Reads the files the options name into in, which must be zeroed. 0, or CLI_EXIT_USAGE after
 * one line on stderr naming the option, the file and the line or entry; either way in is the
 * caller's to free with cli_free_model. */
int cli_read_model(const struct structure_options *o, struct structure_input *in);

/* Sets M, K, C or Rayleigh damping, J, the bounds, the influence and the ground record into s
 * (created for in->n and in->m). 0, or CLI_EXIT_USAGE after one line on stderr naming the
 * option and the file the library refused, and why. */
int cli_set_model(const struct structure_options *o, const struct structure_input *in,
                  fricreg_structure *s);

/* Frees M, K, C and J once set (the structure holds its own copies), or with the rest. */
void cli_free_matrices(struct structure_input *in);
void cli_free_model(struct structure_input *in);

#endif
