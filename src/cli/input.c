/* SPDX-License-Identifier: GPL-3.0-or-later */
/* input.c — the plain-text input files of `fricreg-sim structure`: columns of numbers and the
 * ground-motion record (the matrices: matrix_market.c). Every error is one line on stderr
 * naming the option, the file and the line or sample; the readers return CLI_EXIT_USAGE then,
 * and their outputs are left unset. */
#include <errno.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "cli_input.h"
#include "input_line.h"

int cli_read_columns(const char *option, const char *path, size_t ncols, size_t *nrows,
                     double **values)
{
    FILE *f = fopen(path, "r");
    if (f == NULL)
        return cli_file_error(option, path, 0, "cannot open: %s", strerror(errno));
    char buf[CLI_LINE_MAX];
    long line = 0;
    int too_long = 0, status = 0;
    size_t n = 0, cap = 0;
    double *v = NULL;
    while (status == 0 && cli_next_line(f, buf, sizeof buf, &line, &too_long)) {
        if (buf[0] == '#' || buf[0] == '%' || cli_blank(buf))
            continue;
        if (n == cap) {
            cap = cap ? 2 * cap : 64;
            double *grown = realloc(v, cap * ncols * sizeof *v);
            if (grown == NULL) {
                status = cli_file_error(option, path, line, "out of memory");
                break;
            }
            v = grown;
        }
        char *p = buf, *end;
        for (size_t c = 0; c < ncols && status == 0; c++, p = end) {
            p += strspn(p, " \t,");
            if (!cli_read_number(p, &end, &v[n * ncols + c]))
                status = cli_file_error(option, path, line, "expected %zu finite number%s per line",
                                        ncols, ncols > 1 ? "s" : "");
        }
        if (status == 0 && !cli_blank(p + strspn(p, " \t,")))
            status = cli_file_error(option, path, line, "expected %zu number%s per line", ncols,
                                    ncols > 1 ? "s" : "");
        n++;
    }
    fclose(f);
    if (status == 0 && too_long)
        status = cli_file_error(option, path, line, "line too long");
    if (status != 0) {
        free(v);
        return status;
    }
    *nrows = n;
    *values = v;
    return 0;
}

int cli_read_record(const char *option, const char *path, double *t0, double *dt_rec, size_t *n,
                    double **ag)
{
    double *tv = NULL;
    size_t rows = 0;
    int status = cli_read_columns(option, path, 2, &rows, &tv);
    if (status != 0)
        return status;
    if (rows < 2) {
        free(tv);
        return cli_file_error(option, path, 0, "%zu samples: a record needs at least 2", rows);
    }
    double start = tv[0], step = (tv[2 * (rows - 1)] - start) / (double)(rows - 1);
    if (!(step > 0.0)) {
        free(tv);
        return cli_file_error(option, path, 0, "the times must increase");
    }
    /* A uniform grid: every time within 1e-6 steps of t0 + k dt (written to 7 digits). */
    for (size_t k = 0; k < rows; k++) {
        double expected = start + (double)k * step;
        if (fabs(tv[2 * k] - expected) > 1e-6 * step) {
            status = cli_file_error(option, path, 0,
                                    "sample %zu: t = %.17g, the uniform grid from "
                                    "the first and last times needs %.17g (step %.17g)",
                                    k + 1, tv[2 * k], expected, step);
            free(tv);
            return status;
        }
        tv[k] = tv[2 * k + 1]; /* compact a_g in place: k <= 2k + 1 */
    }
    *t0 = start;
    *dt_rec = step;
    *n = rows;
    *ag = tv;
    return 0;
}
