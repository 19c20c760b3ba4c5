/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb_rod.c — the rod model of hb_rod.h. */
#include "hb_rod.h"

#include <stdlib.h>
#include <string.h>

/* Entry (row, col) of matrix which. */
static double value(size_t n, int which, size_t row, size_t col)
{
    double h = 1.0 / (double)n, mass = 0.0, stiff = 0.0, dash = 0.0;
    size_t lo = row < col ? row : col, hi = row < col ? col : row;
    if (lo == hi) {
        mass = (lo + 1 < n ? 4.0 : 2.0) * h / 6.0 + (lo + 1 == n ? 0.2 : 0.0);
        stiff = (lo + 1 < n ? 2.0 : 1.0) / h;
        dash = lo == 0 || lo + 1 == n ? 0.02 : 0.0;
    } else if (hi == lo + 1) {
        mass = h / 6.0;
        stiff = -1.0 / h;
    }
    if (lo == 0 && hi + 1 == n)
        dash = -0.02;
    if (which == 0)
        return mass;
    return which == 2 ? stiff : 0.05 * mass + 0.005 * stiff + dash;
}

/* The rows that may hold an entry in column col (n >= 8), sorted, into rows[3]; their count. */
static size_t candidates(size_t n, size_t col, size_t *rows)
{
    size_t c = 0;
    if (col + 1 == n)
        rows[c++] = 0; /* the dashpot's corner */
    if (col > 0)
        rows[c++] = col - 1;
    rows[c++] = col;
    if (col + 1 < n)
        rows[c++] = col + 1;
    if (col == 0)
        rows[c++] = n - 1;
    return c;
}

int hb_rod_build(struct hb_rod *r, size_t n)
{
    memset(r, 0, sizeof *r);
    r->n = n;
    r->m = HB_ROD_M;
    int ok = 1;
    for (int w = 0; w < 3; w++) {
        r->p[w] = malloc((n + 1) * sizeof(int64_t));
        r->i[w] = malloc(5 * n * sizeof(int64_t));
        r->x[w] = malloc(5 * n * sizeof(double));
        ok = ok && r->p[w] && r->i[w] && r->x[w];
    }
    r->J = calloc(HB_ROD_M * n, sizeof(double));
    r->pc = calloc(n, sizeof(double));
    r->ps = calloc(n, sizeof(double));
    if (!ok || !r->J || !r->pc || !r->ps) {
        hb_rod_free(r);
        return -1;
    }
    for (int w = 0; w < 3; w++) {
        size_t k = 0, rows[3];
        for (size_t col = 0; col < n; col++) {
            r->p[w][col] = (int64_t)k;
            size_t c = candidates(n, col, rows);
            for (size_t a = 0; a < c; a++) {
                double v = value(n, w, rows[a], col);
                if (v != 0.0) {
                    r->i[w][k] = (int64_t)rows[a];
                    r->x[w][k++] = v;
                }
            }
        }
        r->p[w][n] = (int64_t)k;
    }
    r->J[n - 1] = 1.0;             /* the free end to ground */
    r->J[n + n / 2] = 1.0;         /* the middle to ground */
    r->J[2 * n + 3 * n / 4] = 1.0; /* between a quarter and three quarters */
    r->J[2 * n + n / 4] = -1.0;
    const double kt[HB_ROD_M] = {1.0, 0.5, 0.8}, mun[HB_ROD_M] = {0.08, 0.05, 0.04};
    memcpy(r->kt, kt, sizeof kt);
    memcpy(r->mun, mun, sizeof mun);
    r->pc[n - 1] = 0.3;
    r->ps[n - 1] = 0.05;
    return 0;
}

void hb_rod_free(struct hb_rod *r)
{
    for (int w = 0; w < 3; w++) {
        free(r->p[w]);
        free(r->i[w]);
        free(r->x[w]);
    }
    free(r->J);
    free(r->pc);
    free(r->ps);
    memset(r, 0, sizeof *r);
}

void hb_rod_csc(const struct hb_rod *r, int which, enum hb_rod_form form, int one_based, int64_t *p,
                int64_t *i, double *x)
{
    size_t k = 0;
    int64_t b = one_based ? 1 : 0;
    for (size_t col = 0; col < r->n; col++) {
        p[col] = (int64_t)k + b;
        for (int64_t q = r->p[which][col]; q < r->p[which][col + 1]; q++) {
            size_t row = (size_t)r->i[which][q];
            if ((form == HB_ROD_UPPER && row > col) || (form == HB_ROD_LOWER && row < col))
                continue;
            double v = r->x[which][q];
            if (form == HB_ROD_FULL && col == 0 && row == 0) {
                i[k] = b, x[k++] = 0.5 * v; /* a duplicate: summed */
                v *= 0.5;
            }
            i[k] = (int64_t)row + b;
            x[k++] = v;
        }
    }
    p[r->n] = (int64_t)k + b;
}

void hb_rod_dense(const struct hb_rod *r, int which, double *A)
{
    size_t n = r->n;
    memset(A, 0, n * n * sizeof *A);
    for (size_t col = 0; col < n; col++)
        for (int64_t q = r->p[which][col]; q < r->p[which][col + 1]; q++)
            A[(size_t)r->i[which][q] * n + col] = r->x[which][q];
}

int hb_rod_set(fricreg_hb *hb, const struct hb_rod *r, int dense, enum hb_rod_form form,
               int one_based)
{
    size_t n = r->n;
    int status = FRICREG_OK;
    for (int w = 0; w < 3 && status == FRICREG_OK; w++) {
        if (dense) {
            double *A = malloc(n * n * sizeof *A);
            if (A == NULL)
                return FRICREG_ENOMEM;
            hb_rod_dense(r, w, A);
            status = w == 0   ? fricreg_hb_set_mass(hb, n, A)
                     : w == 1 ? fricreg_hb_set_damping(hb, n, A)
                              : fricreg_hb_set_stiffness(hb, n, A);
            free(A);
            continue;
        }
        size_t nnz = (size_t)r->p[w][n] + 1;
        int64_t *p = malloc((n + 1) * sizeof *p), *i = malloc(nnz * sizeof *i);
        double *x = malloc(nnz * sizeof *x);
        if (p && i && x) {
            hb_rod_csc(r, w, form, one_based, p, i, x);
            int f = (one_based ? FRICREG_SPARSE_ONE_BASED : 0) |
                    (form == HB_ROD_UPPER   ? FRICREG_SPARSE_UPPER
                     : form == HB_ROD_LOWER ? FRICREG_SPARSE_LOWER
                                            : 0);
            status = w == 0   ? fricreg_hb_set_mass_csc(hb, n, f, p, i, x)
                     : w == 1 ? fricreg_hb_set_damping_csc(hb, n, f, p, i, x)
                              : fricreg_hb_set_stiffness_csc(hb, n, f, p, i, x);
        } else {
            status = FRICREG_ENOMEM;
        }
        free(p);
        free(i);
        free(x);
    }
    if (status == FRICREG_OK)
        status = fricreg_hb_set_elements(hb, r->m, n, r->J, r->kt, r->mun);
    if (status == FRICREG_OK)
        status = fricreg_hb_set_excitation(hb, n, r->pc, r->ps);
    return status;
}
