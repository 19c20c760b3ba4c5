/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fit_levels.c — the measured levels of `fricreg-sim fit` (fit_levels.h), read with the
 * structure's input lines (input_line.h). */
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "fit_levels.h"
#include "input_line.h"

#define MAX_COLS 5

/* A header: the line's first token is not a number. */
static int is_header(char *buf)
{
    char *p = buf + strspn(buf, " \t,"), *end;
    double x;
    return !cli_read_number(p, &end, &x);
}

/* Appends a row of cols numbers to *values (room *cap rows); 0 or CLI_EXIT_USAGE. */
static int append(const char *option, const char *path, long line, const double row[], size_t cols,
                  size_t *n, size_t *cap, double **values)
{
    if (*n == *cap) {
        size_t grown_cap = *cap ? 2 * *cap : 16;
        double *grown = realloc(*values, grown_cap * cols * sizeof **values);
        if (grown == NULL)
            return cli_file_error(option, path, line, "out of memory");
        *values = grown;
        *cap = grown_cap;
    }
    memcpy(*values + *n * cols, row, cols * sizeof *row);
    (*n)++;
    return 0;
}

int cli_read_levels(const char *option, const char *path, size_t *n, size_t *cols, double **values)
{
    FILE *f = fopen(path, "r");
    if (f == NULL)
        return cli_file_error(option, path, 0, "cannot open: %s", strerror(errno));
    char buf[CLI_LINE_MAX];
    long line = 0;
    int too_long = 0, status = 0, first = 1;
    size_t rows = 0, cap = 0, width = 0;
    double *v = NULL, row[MAX_COLS];
    while (status == 0 && cli_next_line(f, buf, sizeof buf, &line, &too_long)) {
        if (buf[0] == '#' || buf[0] == '%' || cli_blank(buf))
            continue;
        if (first && is_header(buf)) {
            first = 0;
            continue;
        }
        first = 0;
        size_t count;
        status = cli_line_numbers(option, path, line, buf, row, MAX_COLS, &count);
        if (status == 0 && count != 3 && count != 5)
            status = cli_file_error(option, path, line,
                                    "%zu numbers: expected 3 (amplitude, "
                                    "freq_hz, zeta) or 5 (and sd_freq_hz, sd_zeta)",
                                    count);
        else if (status == 0 && width != 0 && count != width)
            status = cli_file_error(option, path, line,
                                    "%zu numbers, but the lines before "
                                    "have %zu",
                                    count, width);
        if (status == 0) {
            width = count;
            status = append(option, path, line, row, width, &rows, &cap, &v);
        }
    }
    fclose(f);
    if (status == 0 && too_long)
        status = cli_file_error(option, path, line, "line too long");
    if (status == 0 && rows == 0)
        status = cli_file_error(option, path, 0, "no levels");
    if (status != 0) {
        free(v);
        return status;
    }
    *n = rows;
    *cols = width;
    *values = v;
    return 0;
}
