/* SPDX-License-Identifier: GPL-3.0-or-later */
/* matrix_market.c — a Matrix Market file into compressed sparse columns (matrix_market.h):
 * one pass over its lines, each entry kept with its line number, then a counting sort by
 * column, each column ordered by row, and duplicates found side by side.
 *
 * Written here because neither library reader keeps the checks: GSL's gsl_spmatrix_fscanf
 * builds a tree of every entry and stops at a comment or blank line after the size line, and
 * CHOLMOD's cholmod_l_read_sparse (CHOLMOD 3.0.14, Check/cholmod_read.c) names no line (its
 * error handler gets "indices out of range" or "premature EOF"), sums duplicates, takes an
 * entry above the diagonal of symmetric storage, NaN, infinities, a fractional index (1.5 as
 * 1), indices from 0, text after the value, and lines beyond the size line's count, which it
 * allocates before reading one entry.
 *
 * The first bad line is named, as a line-by-line check names it: a line's own fault stops the
 * pass, and a duplicate, found after the sort among the entries before it, wins if its line
 * comes first. Memory: 32 bytes an entry while reading, 56 while sorting, 16 in the result,
 * and 8 a column. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "input_line.h"
#include "matrix_market.h"

/* An entry as read: 0-based row and column, its value and its line. */
struct entry {
    int64_t row, col;
    double value;
    long line;
};

/* An entry sorted into its column. */
struct column_entry {
    int64_t row;
    double value;
    long line;
};

struct reading {
    const char *option, *path;
    size_t want_rows, want_cols;     /* 0: any */
    const struct cli_mtx_size *from; /* where they came from; NULL: the caller */
    int symmetric;
    long rows, cols, declared; /* the size line; rows = 0 before it */
    long size_line;
    struct entry *entries;
    size_t n, cap;
    long bad_line;  /* the first line at fault (0: none), stopping the pass */
    char what[256]; /* and what is wrong with it */
};

/* A line at fault: the pass stops here; reported unless a duplicate comes first. */
static void line_fault(struct reading *r, long line, const char *what)
{
    r->bad_line = line;
    snprintf(r->what, sizeof r->what, "%s", what);
}

/* The banner "%%MatrixMarket matrix coordinate real|integer general|symmetric"; its words are
 * case-insensitive. */
static int read_banner(struct reading *r, const char *banner)
{
    char words[4][32] = {"", "", "", ""};
    if (strncmp(banner, "%%MatrixMarket", 14) != 0)
        return cli_file_error(r->option, r->path, 1,
                              "not a Matrix Market file (no %%%%MatrixMarket banner)");
    sscanf(banner + 14, "%31s %31s %31s %31s", words[0], words[1], words[2], words[3]);
    for (int w = 0; w < 4; w++)
        for (char *c = words[w]; *c; c++)
            *c = (char)(*c | 0x20);
    if (strcmp(words[0], "matrix") != 0 || strcmp(words[1], "coordinate") != 0)
        return cli_file_error(r->option, r->path, 1, "'%s %s': only 'matrix coordinate' is read",
                              words[0], words[1]);
    if (strcmp(words[2], "real") != 0 && strcmp(words[2], "integer") != 0)
        return cli_file_error(r->option, r->path, 1, "field '%s': only real or integer is read",
                              words[2]);
    if (strcmp(words[3], "general") != 0 && strcmp(words[3], "symmetric") != 0)
        return cli_file_error(r->option, r->path, 1,
                              "symmetry '%s': only general or symmetric is read", words[3]);
    r->symmetric = strcmp(words[3], "symmetric") == 0;
    return 0;
}

/* 1 + the largest row or column of a nonzero entry of A, 0 if it has none. */
static size_t extent(const struct cli_sparse *A)
{
    size_t u = 0;
    for (size_t j = 0; j < A->cols; j++)
        for (int64_t p = A->colptr[j]; p < A->colptr[j + 1]; p++) {
            size_t i = (size_t)A->rowind[p];
            u = i + 1 > u ? i + 1 : u;
            u = j + 1 > u ? j + 1 : u;
        }
    return u;
}

/* One size wanted against the size declared, the size wanted being n (the from file's) or not:
 * 1 if they agree or the declared is the extent u < n of from's entries (from's size line at
 * fault), 0 if it is not, -1 if the size wanted was not n. */
static int from_extent(size_t want, long declared, size_t n, size_t u)
{
    if (want == 0 || (size_t)declared == want)
        return 1; /* not differing: no verdict */
    if (want != n)
        return -1;
    return (size_t)declared == u ? 1 : 0;
}

/* The size line's sizes differ from those wanted: whose fault it is, reported. */
static int size_differs(const struct reading *r)
{
    if (r->from != NULL && r->from->A->rows == r->from->A->cols) {
        size_t n = r->from->A->rows, u = extent(r->from->A);
        if (u > 0 && u < n && from_extent(r->want_rows, r->rows, n, u) == 1 &&
            from_extent(r->want_cols, r->cols, n, u) == 1)
            return cli_file_error(r->from->option, r->from->path, r->from->A->size_line,
                                  "the size line says %zu x %zu, but no entry is beyond row and "
                                  "column %zu, and %s %s is %ld x %ld",
                                  n, n, u, r->option, r->path, r->rows, r->cols);
    }
    return cli_file_error(r->option, r->path, 0, "the matrix is %ld x %ld, expected %zu x %zu",
                          r->rows, r->cols, r->want_rows ? r->want_rows : (size_t)r->rows,
                          r->want_cols ? r->want_cols : (size_t)r->cols);
}

/* The size line "rows columns entries", checked against the size wanted. */
static int read_size(struct reading *r, char *text, long line)
{
    r->size_line = line;
    char *end;
    if (!cli_read_index(text, &end, CLI_MTX_MAX_DIM, &r->rows) ||
        !cli_read_index(end, &end, CLI_MTX_MAX_DIM, &r->cols) ||
        (r->declared = strtol(end, &end, 10)) < 0 || !cli_blank(end))
        return cli_file_error(r->option, r->path, line,
                              "expected the size line 'rows columns entries' (1 to %ld rows "
                              "and columns)",
                              CLI_MTX_MAX_DIM);
    if (r->symmetric && r->rows != r->cols)
        return cli_file_error(r->option, r->path, line, "symmetric storage of a %ld x %ld matrix",
                              r->rows, r->cols);
    if ((r->want_rows && (size_t)r->rows != r->want_rows) ||
        (r->want_cols && (size_t)r->cols != r->want_cols))
        return size_differs(r);
    return 0;
}

/* Room for one more entry, doubling. */
static int make_room(struct reading *r)
{
    if (r->n < r->cap)
        return 1;
    size_t cap = r->cap ? 2 * r->cap : 1024;
    struct entry *grown = cap <= SIZE_MAX / sizeof *grown ? realloc(r->entries, cap * sizeof *grown)
                                                          : NULL;
    if (grown == NULL)
        return 0;
    r->entries = grown;
    r->cap = cap;
    return 1;
}

/* One entry line "row column value"; a fault is recorded (line_fault) and stops the pass. */
static int read_entry(struct reading *r, char *text, long line)
{
    char *end, what[256];
    long i = 0, j = 0; /* set by the reads below; initialized for -Wmaybe-uninitialized */
    double value = 0.0;
    if (!cli_read_index(text, &end, r->rows, &i) || !cli_read_index(end, &end, r->cols, &j) ||
        !cli_read_number(end + strspn(end, " \t"), &end, &value) || !cli_blank(end))
        snprintf(what, sizeof what,
                 "expected 'row column value' with a row from 1 to %ld, a column from 1 to %ld "
                 "and a finite value",
                 r->rows, r->cols);
    else if ((long)r->n == r->declared)
        snprintf(what, sizeof what, "more entries than the %ld of the size line", r->declared);
    else if (r->symmetric && j > i)
        snprintf(what, sizeof what,
                 "entry (%ld, %ld) above the diagonal in symmetric storage (give the lower "
                 "triangle)",
                 i, j);
    else if (!make_room(r))
        return cli_file_error(r->option, r->path, line, "out of memory");
    else {
        r->entries[r->n++] = (struct entry){i - 1, j - 1, value, line};
        return 0;
    }
    line_fault(r, line, what);
    return 0;
}

/* Reads every line after the banner; 0, or CLI_EXIT_USAGE (printed) for a fault that no
 * earlier duplicate can precede (the size line, memory). Line faults are recorded. */
static int read_lines(struct reading *r, FILE *f, char *buf, size_t len, long *line)
{
    int too_long = 0, status = 0;
    while (status == 0 && r->bad_line == 0 && cli_next_line(f, buf, len, line, &too_long)) {
        if (buf[0] == '%' || cli_blank(buf))
            continue;
        status = r->rows == 0 ? read_size(r, buf, *line) : read_entry(r, buf, *line);
    }
    if (status == 0 && too_long)
        line_fault(r, *line, "line too long");
    return status;
}

/* Orders one column's entries by row (and line, which no two share). */
static int by_row(const void *a, const void *b)
{
    const struct column_entry *x = a, *y = b;
    if (x->row != y->row)
        return x->row < y->row ? -1 : 1;
    return (x->line > y->line) - (x->line < y->line);
}

/* The entries by column into sorted[n] and colptr[cols + 1] (counting sort: stable, so each
 * column is in the file's order), then each column by row where the file had it otherwise. */
static int sort_by_column(const struct reading *r, int64_t **colptr, struct column_entry **sorted)
{
    size_t cols = (size_t)r->cols;
    int64_t *ptr = calloc(cols + 1, sizeof *ptr);
    struct column_entry *s = malloc((r->n > 0 ? r->n : 1) * sizeof *s);
    if (ptr == NULL || s == NULL) {
        free(ptr);
        free(s);
        return 0;
    }
    for (size_t k = 0; k < r->n; k++)
        ptr[r->entries[k].col + 1]++;
    for (size_t j = 0; j < cols; j++)
        ptr[j + 1] += ptr[j];
    for (size_t k = 0; k < r->n; k++) { /* ptr[j] runs to column j's end... */
        const struct entry *e = &r->entries[k];
        s[ptr[e->col]++] = (struct column_entry){e->row, e->value, e->line};
    }
    memmove(ptr + 1, ptr, cols * sizeof *ptr); /* ...which is column j + 1's start */
    ptr[0] = 0;
    for (size_t j = 0; j < cols; j++)
        for (int64_t p = ptr[j] + 1; p < ptr[j + 1]; p++)
            if (s[p].row < s[p - 1].row) {
                qsort(s + ptr[j], (size_t)(ptr[j + 1] - ptr[j]), sizeof *s, by_row);
                break;
            }
    *colptr = ptr;
    *sorted = s;
    return 1;
}

/* The earliest line that repeats an entry of a line before it, 0 if none; (*row, *col) its
 * entry, 1-based. In a column ordered by row and line, a repeat follows its first. */
static long first_duplicate(const int64_t colptr[], const struct column_entry s[], size_t cols,
                            long *row, long *col)
{
    long first = 0;
    for (size_t j = 0; j < cols; j++)
        for (int64_t p = colptr[j] + 1; p < colptr[j + 1]; p++)
            if (s[p].row == s[p - 1].row && (first == 0 || s[p].line < first)) {
                first = s[p].line;
                *row = (long)s[p].row + 1;
                *col = (long)j + 1;
            }
    return first;
}

/* The sorted entries without their lines and zeros, as A's arrays (colptr rewritten). */
static int compress(const struct reading *r, int64_t colptr[], const struct column_entry s[],
                    struct cli_sparse *A)
{
    size_t cols = (size_t)r->cols, nnz = 0;
    for (size_t k = 0; k < r->n; k++)
        nnz += s[k].value != 0.0;
    int64_t *rowind = malloc((nnz > 0 ? nnz : 1) * sizeof *rowind);
    double *values = malloc((nnz > 0 ? nnz : 1) * sizeof *values);
    if (rowind == NULL || values == NULL) {
        free(rowind);
        free(values);
        return 0;
    }
    int64_t q = 0, start = 0;
    for (size_t j = 0; j < cols; j++) {
        for (int64_t p = start; p < colptr[j + 1]; p++)
            if (s[p].value != 0.0) {
                rowind[q] = s[p].row;
                values[q++] = s[p].value;
            }
        start = colptr[j + 1];
        colptr[j + 1] = q;
    }
    *A = (struct cli_sparse){(size_t)r->rows, cols,   r->symmetric, colptr,
                             rowind,          values, r->size_line};
    return 1;
}

/* After the pass: the first fault by line (a duplicate or the line that stopped the pass),
 * else the count against the size line, else the matrix into *A. */
static int finish(struct reading *r, struct cli_sparse *A)
{
    if (r->rows == 0)
        return r->bad_line > 0 ? cli_file_error(r->option, r->path, r->bad_line, "%s", r->what)
                               : cli_file_error(r->option, r->path, 0, "no size line");
    int64_t *colptr = NULL;
    struct column_entry *sorted = NULL;
    if (!sort_by_column(r, &colptr, &sorted))
        return cli_file_error(r->option, r->path, 0, "out of memory");
    free(r->entries);
    r->entries = NULL;
    long row = 0, col = 0, twice = first_duplicate(colptr, sorted, (size_t)r->cols, &row, &col);
    int status = 0;
    if (twice > 0 && (r->bad_line == 0 || twice < r->bad_line))
        status = cli_file_error(r->option, r->path, twice, "entry (%ld, %ld) given twice", row,
                                col);
    else if (r->bad_line > 0)
        status = cli_file_error(r->option, r->path, r->bad_line, "%s", r->what);
    else if ((long)r->n < r->declared)
        status = cli_file_error(r->option, r->path, 0, "%zu entries, the size line says %ld", r->n,
                                r->declared);
    else if (!compress(r, colptr, sorted, A))
        status = cli_file_error(r->option, r->path, 0, "out of memory");
    if (status != 0)
        free(colptr);
    free(sorted);
    return status;
}

int cli_read_mtx(const char *option, const char *path, size_t rows, size_t cols,
                 struct cli_sparse *A)
{
    return cli_read_mtx_sized(option, path, rows, cols, NULL, A);
}

int cli_read_mtx_sized(const char *option, const char *path, size_t rows, size_t cols,
                       const struct cli_mtx_size *from, struct cli_sparse *A)
{
    FILE *f = fopen(path, "r");
    if (f == NULL)
        return cli_file_error(option, path, 0, "cannot open: %s", strerror(errno));
    struct reading r = {
        .option = option, .path = path, .want_rows = rows, .want_cols = cols, .from = from};
    char buf[CLI_LINE_MAX];
    long line = 0;
    int too_long = 0, status;
    if (!cli_next_line(f, buf, sizeof buf, &line, &too_long))
        status = cli_file_error(option, path, 0, too_long ? "line 1 is too long" : "empty file");
    else if ((status = read_banner(&r, buf)) == 0 &&
             (status = read_lines(&r, f, buf, sizeof buf, &line)) == 0)
        status = finish(&r, A);
    fclose(f);
    free(r.entries);
    return status;
}

void cli_sparse_free(struct cli_sparse *A)
{
    free(A->colptr);
    free(A->rowind);
    free(A->values);
    *A = (struct cli_sparse){0};
}
