/* SPDX-License-Identifier: GPL-3.0-or-later */
/* structure_model.h — the model of `fricreg-sim structure` from its files into the structure
 * (structure_model.c): matrices kept sparse from the file to the library. */
#ifndef FRICREG_CLI_STRUCTURE_MODEL_H
#define FRICREG_CLI_STRUCTURE_MODEL_H

#include "cli_structure.h"
#include "fricreg_structure.h"
#include "matrix_market.h"

/* The model as read: M, K, C (no columns: Rayleigh or none) n x n and J m x n in compressed
 * sparse columns (m = 0 without --contacts); the joint elements (jenkins_input.h, their rows
 * dense as for fricreg-sim hb; el.m = 0: none) or the element sets of --elements; the influence r[n] (NULL: not given), the
 * bounds mun[m] and the ground record ag[nrec] (NULL: none) from t0 every dt_rec; the load
 * pattern p[n] (NULL: none) and its time function g[nload] from load_t0 every load_dt
 * (NULL: g = 1). The library's structure has mlib = m contacts, or without any one of bound
 * 0 on dof 1, whose force is exactly 0 (fricreg_structure_create needs m >= 1): the output
 * shows the m of the files. */
struct structure_input {
    size_t n, m, mlib, nrec, nload;
    struct cli_elements el;
    struct cli_element_sets sets; /* --elements (element_sets.h); sets.n = 0: none */
    struct cli_sparse M, K, C, J;
    double *mun, *r, *ag, *p, *g;
    double t0, dt_rec, load_t0, load_dt;
};

/* Reads the files the options name into in, which must be zeroed. 0, or CLI_EXIT_USAGE after
 * one line on stderr naming the option, the file and the line or entry; either way in is the
 * caller's to free with cli_free_model. */
int cli_read_model(const struct structure_options *o, struct structure_input *in);

/* Sets M, K, C or Rayleigh damping, J and the bounds (or the one contact of bound 0), the
 * influence, the ground record and the load into s (created for in->n and in->mlib). 0, or CLI_EXIT_USAGE after one line on stderr naming the
 * option and the file the library refused, and why. */
int cli_set_model(const struct structure_options *o, const struct structure_input *in,
                  fricreg_structure *s);

/* Frees M, K, C and J once set (the structure holds its own copies), or with the rest. */
void cli_free_matrices(struct structure_input *in);
void cli_free_model(struct structure_input *in);

#endif
