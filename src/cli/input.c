/* SPDX-License-Identifier: GPL-3.0-or-later */
/* input.c — the input files of `fricreg-sim structure`: Matrix Market matrices (checked here
 * line by line so that a bad file is named with its line, then read by GSL), and plain-text
 * columns of numbers. Every error is one line on stderr naming the option, the file and the line or entry;
 * the readers return CLI_EXIT_USAGE then, and their outputs are left unset. */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include <gsl/gsl_errno.h>
#include <gsl/gsl_matrix.h>
#include <gsl/gsl_spmatrix.h>

#include "cli_input.h"

/* The library's size limit (fricreg_structure_create): it also bounds the dense copies. */
#define MAX_DIM 32768

static int file_error(const char *option, const char *path, long line, const char *fmt, ...)
{
    char what[256];
    va_list args;
    va_start(args, fmt);
    vsnprintf(what, sizeof what, fmt, args);
    va_end(args);
    if (line > 0)
        fprintf(stderr, "fricreg-sim: %s %s: line %ld: %s\n", option, path, line, what);
    else
        fprintf(stderr, "fricreg-sim: %s %s: %s\n", option, path, what);
    return CLI_EXIT_USAGE;
}

/* Reads one line into buf; 0 at the end of the file or on a line too long (*too_long set). */
static int next_line(FILE *f, char *buf, size_t len, long *line, int *too_long)
{
    if (fgets(buf, (int)len, f) == NULL)
        return 0;
    (*line)++;
    size_t n = strlen(buf);
    *too_long = n == len - 1 && buf[n - 1] != '\n' && !feof(f);
    return !*too_long;
}

static int blank(const char *s)
{
    return s[strspn(s, " \t\r\n")] == '\0';
}

/* A finite double as the whole token starting at text; *end after it. strtod sets ERANGE on
 * underflow too (a subnormal time or entry, 1e-310), returning the number meant: kept, as the
 * options' parser keeps it (cli_parse_number); only an overflow (+-HUGE_VAL) is refused. */
static int read_number(const char *text, char **end, double *value)
{
    errno = 0;
    *value = strtod(text, end);
    return *end != text && !(errno == ERANGE && fabs(*value) == HUGE_VAL) && isfinite(*value) &&
           (**end == '\0' || strchr(" \t\r\n,", **end) != NULL);
}

/* A whole number from 1 to max as the token at text. */
static int read_index(const char *text, char **end, long max, long *value)
{
    errno = 0;
    *value = strtol(text, end, 10);
    return *end != text && errno == 0 && *value >= 1 && *value <= max &&
           (**end == '\0' || strchr(" \t\r\n", **end) != NULL);
}

/* The banner "%%MatrixMarket matrix coordinate real|integer general|symmetric". */
static int read_banner(const char *option, const char *path, const char *banner, int *symmetric)
{
    char object[32] = "", format[32] = "", field[32] = "", symmetry[32] = "";
    if (strncmp(banner, "%%MatrixMarket", 14) != 0)
        return file_error(option, path, 1,
                          "not a Matrix Market file (no %%%%MatrixMarket "
                          "banner)");
    sscanf(banner + 14, "%31s %31s %31s %31s", object, format, field, symmetry);
    for (char *c = object; *c; c++) /* the banner's words are case-insensitive */
        *c = (char)(*c | 0x20);
    for (char *c = format; *c; c++)
        *c = (char)(*c | 0x20);
    for (char *c = field; *c; c++)
        *c = (char)(*c | 0x20);
    for (char *c = symmetry; *c; c++)
        *c = (char)(*c | 0x20);
    if (strcmp(object, "matrix") != 0 || strcmp(format, "coordinate") != 0)
        return file_error(option, path, 1, "'%s %s': only 'matrix coordinate' is read", object,
                          format);
    if (strcmp(field, "real") != 0 && strcmp(field, "integer") != 0)
        return file_error(option, path, 1, "field '%s': only real or integer is read", field);
    if (strcmp(symmetry, "general") != 0 && strcmp(symmetry, "symmetric") != 0)
        return file_error(option, path, 1, "symmetry '%s': only general or symmetric is read",
                          symmetry);
    *symmetric = strcmp(symmetry, "symmetric") == 0;
    return 0;
}

/* Checks the whole file, naming the first bad line: the banner, the size line "rows cols
 * entries", then exactly that many entries "i j value" with 1-based indices in range, each at
 * most once, finite, and on or below the diagonal in symmetric storage. Comment and blank lines
 * are skipped anywhere; the lines checked are copied to clean, which GSL reads (GSL 2.7 stops
 * at a comment or blank line after the size line, even a trailing one). */
static int check_mtx(const char *option, const char *path, FILE *f, FILE *clean, size_t *rows,
                     size_t *cols, int *symmetric)
{
    char buf[512];
    long line = 0, nrows = 0, ncols = 0, nentries = 0, seen_entries = 0;
    int too_long = 0, status = 0;
    if (!next_line(f, buf, sizeof buf, &line, &too_long))
        return file_error(option, path, 0, too_long ? "line 1 is too long" : "empty file");
    if ((status = read_banner(option, path, buf, symmetric)) != 0)
        return status;
    unsigned char *seen = NULL;
    while (next_line(f, buf, sizeof buf, &line, &too_long)) {
        if (buf[0] == '%' || blank(buf))
            continue;
        char *p = buf, *end;
        if (seen == NULL) { /* the size line */
            if (!read_index(p, &end, MAX_DIM, &nrows) || !read_index(end, &end, MAX_DIM, &ncols) ||
                (nentries = strtol(end, &end, 10)) < 0 || !blank(end))
                return file_error(option, path, line,
                                  "expected the size line 'rows columns "
                                  "entries' (1 to %d rows and columns)",
                                  MAX_DIM);
            if (*symmetric && nrows != ncols)
                return file_error(option, path, line, "symmetric storage of a %ld x %ld matrix",
                                  nrows, ncols);
            seen = calloc((size_t)nrows * (size_t)ncols, 1);
            if (seen == NULL)
                return file_error(option, path, line, "out of memory");
            fprintf(clean, "%%%%MatrixMarket matrix coordinate real general\n%ld %ld %ld\n", nrows,
                    ncols, nentries);
            continue;
        }
        long i = 0, j = 0; /* set by the reads below; initialized for -Wmaybe-uninitialized */
        double value = 0.0;
        if (!read_index(p, &end, nrows, &i) || !read_index(end, &end, ncols, &j) ||
            !read_number(end + strspn(end, " \t"), &end, &value) || !blank(end))
            status = file_error(option, path, line,
                                "expected 'row column value' with a row "
                                "from 1 to %ld, a column from 1 to %ld and a finite value",
                                nrows, ncols);
        else if (seen_entries == nentries)
            status = file_error(option, path, line,
                                "more entries than the %ld of the size "
                                "line",
                                nentries);
        else if (*symmetric && j > i)
            status = file_error(option, path, line,
                                "entry (%ld, %ld) above the diagonal in "
                                "symmetric storage (give the lower triangle)",
                                i, j);
        else if (seen[(i - 1) * ncols + (j - 1)]++)
            status = file_error(option, path, line, "entry (%ld, %ld) given twice", i, j);
        if (status != 0)
            break;
        fprintf(clean, "%ld %ld %.17g\n", i, j, value);
        seen_entries++;
    }
    free(seen);
    if (status != 0)
        return status;
    if (too_long)
        return file_error(option, path, line, "line too long");
    if (nrows == 0)
        return file_error(option, path, 0, "no size line");
    if (seen_entries < nentries)
        return file_error(option, path, 0, "%ld entries, the size line says %ld", seen_entries,
                          nentries);
    *rows = (size_t)nrows;
    *cols = (size_t)ncols;
    return 0;
}

int cli_read_mtx(const char *option, const char *path, size_t *rows, size_t *cols, double **A)
{
    FILE *f = fopen(path, "r");
    if (f == NULL)
        return file_error(option, path, 0, "cannot open: %s", strerror(errno));
    FILE *clean = tmpfile();
    if (clean == NULL) {
        fclose(f);
        return file_error(option, path, 0, "cannot create a temporary file");
    }
    int symmetric = 0;
    int status = check_mtx(option, path, f, clean, rows, cols, &symmetric);
    fclose(f);
    if (status != 0) {
        fclose(clean);
        return status;
    }
    rewind(clean);
    gsl_spmatrix *S = gsl_spmatrix_fscanf(clean);
    fclose(clean);
    double *dense = malloc(*rows * *cols * sizeof *dense);
    int gsl_status = S == NULL || dense == NULL ? GSL_ENOMEM : GSL_SUCCESS;
    if (gsl_status == GSL_SUCCESS) {
        gsl_matrix_view view = gsl_matrix_view_array(dense, *rows, *cols);
        gsl_status = gsl_spmatrix_sp2d(&view.matrix, S);
        /* Symmetric storage holds the lower triangle only: mirror it. */
        for (size_t i = 0; symmetric && i < *rows; i++)
            for (size_t j = i + 1; j < *cols; j++)
                dense[i * *cols + j] = dense[j * *cols + i];
    }
    gsl_spmatrix_free(S);
    if (gsl_status != GSL_SUCCESS) {
        free(dense);
        return file_error(option, path, 0, "GSL could not read it: %s", gsl_strerror(gsl_status));
    }
    *A = dense;
    return 0;
}

int cli_read_columns(const char *option, const char *path, size_t ncols, size_t *nrows,
                     double **values)
{
    FILE *f = fopen(path, "r");
    if (f == NULL)
        return file_error(option, path, 0, "cannot open: %s", strerror(errno));
    char buf[512];
    long line = 0;
    int too_long = 0, status = 0;
    size_t n = 0, cap = 0;
    double *v = NULL;
    while (status == 0 && next_line(f, buf, sizeof buf, &line, &too_long)) {
        if (buf[0] == '#' || buf[0] == '%' || blank(buf))
            continue;
        if (n == cap) {
            cap = cap ? 2 * cap : 64;
            double *grown = realloc(v, cap * ncols * sizeof *v);
            if (grown == NULL) {
                status = file_error(option, path, line, "out of memory");
                break;
            }
            v = grown;
        }
        char *p = buf, *end;
        for (size_t c = 0; c < ncols && status == 0; c++, p = end) {
            p += strspn(p, " \t,");
            if (!read_number(p, &end, &v[n * ncols + c]))
                status = file_error(option, path, line, "expected %zu finite number%s per line",
                                    ncols, ncols > 1 ? "s" : "");
        }
        if (status == 0 && !blank(p + strspn(p, " \t,")))
            status = file_error(option, path, line, "expected %zu number%s per line", ncols,
                                ncols > 1 ? "s" : "");
        n++;
    }
    fclose(f);
    if (status == 0 && too_long)
        status = file_error(option, path, line, "line too long");
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
        return file_error(option, path, 0, "%zu samples: a record needs at least 2", rows);
    }
    double start = tv[0], step = (tv[2 * (rows - 1)] - start) / (double)(rows - 1);
    if (!(step > 0.0)) {
        free(tv);
        return file_error(option, path, 0, "the times must increase");
    }
    /* A uniform grid: every time within 1e-6 steps of t0 + k dt (written to 7 digits). */
    for (size_t k = 0; k < rows; k++) {
        double expected = start + (double)k * step;
        if (fabs(tv[2 * k] - expected) > 1e-6 * step) {
            status = file_error(option, path, 0,
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
