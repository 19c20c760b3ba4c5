/* SPDX-License-Identifier: GPL-3.0-or-later */
/* structure_model.c — the model of `fricreg-sim structure`: its Matrix Market files read as
 * compressed sparse columns (matrix_market.c) and handed to the library's _csc setters, so that
 * nothing of n x n is ever dense; the bounds, the influence vector and the ground record as
 * plain arrays. A file the library refuses is named with what is wrong in it, entries and rows
 * numbered from 1 as the file numbers them. */
#include <math.h>
#include <stdlib.h>

#include "cli_input.h"
#include "element_table.h"
#include "input_line.h"
#include "jenkins_input.h"
#include "structure_model.h"

/* ---- Reading ------------------------------------------------------------------------------ */

void cli_free_matrices(struct structure_input *in)
{
    cli_sparse_free(&in->M);
    cli_sparse_free(&in->K);
    cli_sparse_free(&in->C);
    cli_sparse_free(&in->J);
}

void cli_free_model(struct structure_input *in)
{
    cli_free_matrices(in);
    free(in->mun);
    free(in->r);
    free(in->ag);
    free(in->p);
    free(in->g);
    cli_free_elements(&in->el);
    cli_free_element_sets(&in->sets);
}

/* --influence or --load: an n x 1 file as the vector r[n], n from the mass matrix's file. */
static int read_vector(const char *option, const char *path, const struct cli_mtx_size *mass,
                       size_t n, double **r)
{
    struct cli_sparse R = {0};
    int status = cli_read_mtx_sized(option, path, n, 1, mass, &R);
    if (status != 0)
        return status;
    *r = calloc(n, sizeof **r);
    if (*r == NULL)
        status = cli_usage_error(option, "out of memory");
    for (int64_t p = 0; status == 0 && p < R.colptr[1]; p++)
        (*r)[R.rowind[p]] = R.values[p];
    cli_sparse_free(&R);
    return status;
}

static int read_bounds(const char *path, const char *contacts, size_t m, double **mun)
{
    size_t rows = 0;
    int status = cli_read_columns("--mun", path, 1, &rows, mun);
    if (status == 0 && rows != m) {
        fprintf(stderr, "fricreg-sim: --mun %s: %zu bounds, %s has %zu contacts (rows)\n", path,
                rows, contacts, m);
        status = CLI_EXIT_USAGE;
    }
    return status;
}

int cli_read_model(const struct structure_options *o, struct structure_input *in)
{
    int status = cli_read_mtx("--mass", o->mass, 0, 0, &in->M);
    if (status == 0 && in->M.cols != in->M.rows) {
        fprintf(stderr, "fricreg-sim: --mass %s: the matrix is %zu x %zu, not square\n", o->mass,
                in->M.rows, in->M.cols);
        status = CLI_EXIT_USAGE;
    }
    in->n = in->M.rows;
    const struct cli_mtx_size mass = {"--mass", o->mass, &in->M}; /* n's file */
    if (status == 0)
        status = cli_read_mtx_sized("--stiffness", o->stiffness, in->n, in->n, &mass, &in->K);
    if (status == 0 && o->damping != NULL)
        status = cli_read_mtx_sized("--damping", o->damping, in->n, in->n, &mass, &in->C);
    if (status == 0 && o->contacts != NULL)
        status = cli_read_mtx_sized("--contacts", o->contacts, 0, in->n, &mass, &in->J);
    in->m = in->J.rows;
    in->mlib = in->m > 0 ? in->m : 1;
    if (status == 0 && o->influence != NULL)
        status = read_vector("--influence", o->influence, &mass, in->n, &in->r);
    if (status == 0 && o->contacts != NULL)
        status = read_bounds(o->mun, o->contacts, in->m, &in->mun);
    if (status == 0 && o->ground != NULL)
        status = cli_read_record("--ground-accel", o->ground, &in->t0, &in->dt_rec, &in->nrec,
                                 &in->ag);
    if (status == 0 && o->load != NULL)
        status = read_vector("--load", o->load, &mass, in->n, &in->p);
    if (status == 0 && o->load_history != NULL)
        status = cli_read_record("--load-history", o->load_history, &in->load_t0, &in->load_dt,
                                 &in->nload, &in->g);
    if (status == 0)
        status = cli_read_elements(&o->elements, in->n, &in->el);
    if (status == 0)
        status = cli_read_element_sets(&o->element_sets, in->n, &in->sets);
    return status;
}

/* ---- What the library refuses, named ------------------------------------------------------- */

/* A's transpose, in the same form (A's rows ascending in each of its columns). */
static int transpose(const struct cli_sparse *A, struct cli_sparse *T)
{
    size_t nnz = (size_t)A->colptr[A->cols], room = nnz > 0 ? nnz : 1;
    *T = (struct cli_sparse){.rows = A->cols, .cols = A->rows};
    T->colptr = calloc(A->rows + 1, sizeof *T->colptr);
    T->rowind = malloc(room * sizeof *T->rowind);
    T->values = malloc(room * sizeof *T->values);
    if (T->colptr == NULL || T->rowind == NULL || T->values == NULL) {
        cli_sparse_free(T);
        return 0;
    }
    for (size_t p = 0; p < nnz; p++)
        T->colptr[A->rowind[p] + 1]++;
    for (size_t i = 0; i < A->rows; i++)
        T->colptr[i + 1] += T->colptr[i];
    for (size_t j = 0; j < A->cols; j++) /* T->colptr[i] runs to row i's end... */
        for (int64_t p = A->colptr[j]; p < A->colptr[j + 1]; p++) {
            int64_t q = T->colptr[A->rowind[p]]++;
            T->rowind[q] = (int64_t)j;
            T->values[q] = A->values[p];
        }
    for (size_t i = A->rows; i > 0; i--) /* ...which is row i + 1's start */
        T->colptr[i] = T->colptr[i - 1];
    T->colptr[0] = 0;
    return 1;
}

/* A pair (i, j), i > j, and its two entries A_ij and A_ji. */
struct asymmetry {
    size_t i, j;
    double aij, aji;
};

/* Keeps in *worst the pair below the diagonal of column j with |A_ij - A_ji| largest, the
 * first in row-major order on a tie (as a dense scan finds it): column j of A and of A^T
 * merged by row. */
static void merge_column(const struct cli_sparse *A, const struct cli_sparse *T, size_t j,
                         struct asymmetry *worst)
{
    int64_t p = A->colptr[j], q = T->colptr[j];
    while (p < A->colptr[j + 1] || q < T->colptr[j + 1]) {
        int64_t ip = p < A->colptr[j + 1] ? A->rowind[p] : INT64_MAX;
        int64_t iq = q < T->colptr[j + 1] ? T->rowind[q] : INT64_MAX;
        int64_t i = ip < iq ? ip : iq;
        double aij = ip == i ? A->values[p++] : 0.0, aji = iq == i ? T->values[q++] : 0.0;
        double d = fabs(aij - aji), w = fabs(worst->aij - worst->aji);
        int first = (size_t)i < worst->i || ((size_t)i == worst->i && j <= worst->j);
        if ((size_t)i > j && (d > w || (d == w && first)))
            *worst = (struct asymmetry){(size_t)i, j, aij, aji};
    }
}

/* The library decides symmetry (its tolerance); the message names the most asymmetric entry
 * as the file numbers it, from 1. */
static void name_asymmetry(const char *option, const char *path, const struct cli_sparse *A)
{
    struct cli_sparse T;
    if (!transpose(A, &T)) {
        fprintf(stderr, "fricreg-sim: %s %s: not symmetric\n", option, path);
        return;
    }
    struct asymmetry worst = {1, 0, 0.0, 0.0};
    for (size_t j = 0; j < A->cols; j++)
        merge_column(A, &T, j, &worst);
    cli_sparse_free(&T);
    fprintf(stderr,
            "fricreg-sim: %s %s: not symmetric: entry (%zu, %zu) = %.17g but "
            "(%zu, %zu) = %.17g\n",
            option, path, worst.i + 1, worst.j + 1, worst.aij, worst.j + 1, worst.i + 1, worst.aji);
}

/* A refused model file: one line naming it, exit 2. */
static int model_error(fricreg_structure *s, int status, const char *option, const char *path,
                       const struct cli_sparse *A)
{
    if (status == FRICREG_ENOTSYM && A != NULL)
        name_asymmetry(option, path, A);
    else if (status == FRICREG_ENOTPSD)
        fprintf(stderr,
                "fricreg-sim: %s %s: the mass matrix is singular or not positive "
                "definite (its Cholesky factorization fails)\n",
                option, path);
    else
        fprintf(stderr, "fricreg-sim: %s %s: %s\n", option, path, fricreg_structure_errmsg(s));
    return CLI_EXIT_USAGE;
}

/* Rows of J without an entry (the reader leaves zeros out), named from 1: the library refuses
 * them too, numbered from 0. */
static int check_contacts(const char *path, const struct cli_sparse *J)
{
    unsigned char *moves = calloc(J->rows, 1);
    if (moves == NULL)
        return cli_usage_error("--contacts", "out of memory");
    for (int64_t p = 0; p < J->colptr[J->cols]; p++)
        moves[J->rowind[p]] = 1;
    size_t i = 0;
    while (i < J->rows && moves[i])
        i++;
    free(moves);
    if (i == J->rows)
        return 0;
    fprintf(stderr, "fricreg-sim: --contacts %s: row %zu is zero: contact %zu does not move\n",
            path, i + 1, i + 1);
    return CLI_EXIT_USAGE;
}

static int check_bounds(const char *path, size_t m, const double mun[])
{
    for (size_t i = 0; i < m; i++)
        if (mun[i] < 0.0) {
            fprintf(stderr, "fricreg-sim: --mun %s: bound %zu = %g must be >= 0\n", path, i + 1,
                    mun[i]);
            return CLI_EXIT_USAGE;
        }
    return 0;
}

/* ---- Setting ------------------------------------------------------------------------------ */

/* M, K or C (which) by its columns: the lower triangle of symmetric storage as such. */
static int set_square(fricreg_structure *s, const struct cli_sparse *A, const char *option,
                      const char *path, int which)
{
    int flags = A->lower ? FRICREG_SPARSE_LOWER : FRICREG_SPARSE_ZERO_BASED;
    int status = fricreg_structure_set_matrix(s, which, A->cols, A->cols,
                                              FRICREG_MATRIX_CSC | flags, A->colptr, A->rowind,
                                              A->values);
    return status == FRICREG_OK ? 0 : model_error(s, status, option, path, A);
}

/* r from --influence; without it the library's default, every DOF moving with the ground. */
static int set_influence(fricreg_structure *s, const struct structure_options *o,
                         const struct structure_input *in)
{
    if (in->r == NULL)
        return 0;
    int status = fricreg_structure_set_influence(s, in->n, in->r);
    return status == FRICREG_OK ? 0 : model_error(s, status, "--influence", o->influence, NULL);
}

/* One element set into the structure (cli_element_set_adder): NULL, or its reason. */
static const char *add_set(void *model, const struct cli_element_set *e, size_t n)
{
    fricreg_structure *s = model;
    return fricreg_structure_add_elements(s, e->type, e->me, n, e->J, e->params) == FRICREG_OK
               ? NULL
               : fricreg_structure_errmsg(s);
}

/* The elements (beside the contacts, whatever their bounds: one step solves both) by the
 * element table; what the library refuses in them, named by their parameter file. A normal law
 * needs kn > 0 here, as the structure's per-kind setters did (the kernel takes kn = 0). */
static int set_elements(fricreg_structure *s, const struct structure_input *in)
{
    const struct cli_elements *el = &in->el;
    for (size_t i = 0; el->kn != NULL && i < el->m; i++)
        if (!(el->kn[i] > 0.0))
            return cli_file_error(el->option, el->path, 0, "element %zu needs kn > 0 (kn = %g)", i,
                                  el->kn[i]);
    return cli_add_elements(s, add_set, in->n, el);
}

/* Without --contacts: the library's structure has at least one contact (fricreg_structure.h:
 * "a structure without friction: one contact with mun = 0, whose force is exactly 0"), here
 * on dof 1, J = e_1^T by one compressed row. */
static int set_no_contacts(fricreg_structure *s, size_t n)
{
    const int64_t rowptr[] = {0, 1}, colind[] = {0};
    const double one[] = {1.0}, zero[] = {0.0};
    if (fricreg_structure_set_matrix(s, FRICREG_CONTACTS, 1, n, FRICREG_MATRIX_CSR, rowptr, colind,
                                     one) != FRICREG_OK ||
        fricreg_structure_set_bounds(s, 1, zero) != FRICREG_OK)
        return cli_usage_error("structure", fricreg_structure_errmsg(s));
    return 0;
}

int cli_set_model(const struct structure_options *o, const struct structure_input *in,
                  fricreg_structure *s)
{
    int status = set_square(s, &in->M, "--mass", o->mass, FRICREG_MASS);
    if (status == 0)
        status = set_square(s, &in->K, "--stiffness", o->stiffness, FRICREG_STIFFNESS);
    if (status == 0 && o->damping != NULL)
        status = set_square(s, &in->C, "--damping", o->damping, FRICREG_DAMPING);
    if (status == 0 && o->rayleigh_given && fricreg_structure_set_rayleigh(s, o->a0, o->a1) != 0)
        return cli_usage_error("--rayleigh", fricreg_structure_errmsg(s));
    if (status == 0 && in->m == 0)
        status = set_no_contacts(s, in->n);
    if (status == 0 && in->m > 0 && (status = check_contacts(o->contacts, &in->J)) == 0 &&
        (status = fricreg_structure_set_matrix(s, FRICREG_CONTACTS, in->m, in->n,
                                               FRICREG_MATRIX_CSC, in->J.colptr, in->J.rowind,
                                               in->J.values)) != FRICREG_OK)
        status = model_error(s, status, "--contacts", o->contacts, NULL);
    if (status == 0 && in->m > 0 && (status = check_bounds(o->mun, in->m, in->mun)) == 0 &&
        (status = fricreg_structure_set_bounds(s, in->m, in->mun)) != FRICREG_OK)
        status = model_error(s, status, "--mun", o->mun, NULL);
    if (status == 0)
        status = set_influence(s, o, in);
    if (status == 0 && in->ag != NULL &&
        fricreg_structure_set_ground_accel(s, in->t0, in->dt_rec, in->nrec, in->ag) != 0)
        status = model_error(s, FRICREG_EINVAL, "--ground-accel", o->ground, NULL);
    if (status == 0 && in->p != NULL &&
        (status = fricreg_structure_set_load(s, in->n, in->p, in->load_t0, in->load_dt, in->nload,
                                             in->g)) != FRICREG_OK)
        status = model_error(s, status, o->load_history != NULL ? "--load-history" : "--load",
                             o->load_history != NULL ? o->load_history : o->load, NULL);
    if (status == 0 && in->el.m > 0)
        status = set_elements(s, in);
    if (status == 0)
        status = cli_add_element_sets(s, add_set, in->n, &in->sets);
    return status;
}
