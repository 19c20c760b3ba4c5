/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fuzz_cli_structure.c — fuzz target: what `fricreg-sim structure` parses (src/cli/
 * structure.c, cli_structure.h; input.c, cli_input.h), without the run. The input's first byte
 * picks the parser: the options (the rest is argv, one argument per line), or one of the file
 * readers on the rest written to a file: a Matrix Market matrix (cli_read_mtx, matrix_market.h),
 * columns of 1 to 3 numbers (cli_read_columns), a ground-motion record (cli_read_record).
 * Contract: the status is 0 or CLI_EXIT_USAGE (2), never a crash, undefined behaviour (UBSan)
 * or leak (ASan); on success the options are complete and consistent (the four required files,
 * a known scheme, law and stepper, dt and t_end > 0 and finite with at most 2^31 steps,
 * --damping or --rayleigh (two numbers >= 0), --alpha only with hht, tolerances >= 0 and only
 * with a GSL stepper); a matrix has 1 to CLI_MTX_MAX_DIM rows and columns and well-formed
 * compressed columns (pointers from 0, non-decreasing; rows in range, strictly ascending in
 * each column, on or below the diagonal in symmetric storage; values finite and nonzero);
 * columns are finite; a record has n >= 2 samples, finite a_g and a finite step dt > 0. */
#define _POSIX_C_SOURCE 200809L
#include <unistd.h>

#include "fuzz_argv.h"
#include "fuzz_input.h"

#include "cli_input.h"
#include "cli_structure.h"
#include "matrix_market.h"

static void check_options(const struct structure_options *o)
{
    FUZZ_REQUIRE(o->mass && o->stiffness && o->contacts && o->mun, "a required file missing");
    FUZZ_REQUIRE(o->scheme >= SCHEME_NEWMARK && o->scheme <= SCHEME_GSL, "scheme %d",
                 (int)o->scheme);
    FUZZ_REQUIRE(o->scheme != SCHEME_GSL || fricreg_integrator_name(o->integrator) != NULL,
                 "integrator %d", o->integrator);
    FUZZ_REQUIRE(fricreg_law_name(o->law) != NULL, "law %d", o->law);
    FUZZ_REQUIRE(isfinite(o->dt) && o->dt > 0.0 && isfinite(o->t_end) && o->t_end > 0.0 &&
                     o->t_end / o->dt <= 2147483647.0,
                 "dt %g t_end %g", o->dt, o->t_end);
    FUZZ_REQUIRE(isfinite(o->eps) && o->eps >= 0.0, "eps %g", o->eps);
    FUZZ_REQUIRE(!(o->damping && o->rayleigh_given), "--damping and --rayleigh");
    FUZZ_REQUIRE(!o->rayleigh_given ||
                     (isfinite(o->a0) && isfinite(o->a1) && o->a0 >= 0.0 && o->a1 >= 0.0),
                 "rayleigh %g %g", o->a0, o->a1);
    FUZZ_REQUIRE(isfinite(o->alpha) && (!o->alpha_given || o->scheme == SCHEME_HHT), "alpha %g",
                 o->alpha);
    FUZZ_REQUIRE(isfinite(o->rtol) && isfinite(o->atol) && o->rtol >= 0.0 && o->atol >= 0.0 &&
                     (o->scheme == SCHEME_GSL || (o->rtol == 0.0 && o->atol == 0.0)),
                 "rtol %g atol %g", o->rtol, o->atol);
    FUZZ_REQUIRE(o->output == CLI_SUMMARY || o->output == CLI_TRAJECTORY, "output %d",
                 (int)o->output);
}

/* The file the readers read: one per process, rewritten for each input, removed at exit. */
static char input_path[64];

static void remove_input(void)
{
    unlink(input_path);
}

static const char *input_file(const uint8_t *data, size_t size)
{
    char *path = input_path;
    if (path[0] == '\0') {
        snprintf(path, sizeof input_path, "/tmp/fuzz_cli_structure.XXXXXX");
        int fd = mkstemp(path);
        FUZZ_REQUIRE(fd >= 0, "harness: mkstemp");
        close(fd);
        atexit(remove_input);
    }
    FILE *f = fopen(path, "wb");
    FUZZ_REQUIRE(f != NULL && fwrite(data, 1, size, f) == size && fclose(f) == 0,
                 "harness: writing %s", path);
    return path;
}

/* The size line's columns as the reader would take them, roughly: a matrix declared with more
 * than 10^6 columns is not read (its column pointers would be up to 0.8 GB, legitimately). */
static int declared_large(const uint8_t *data, size_t size)
{
    char text[4096];
    size_t n = size < sizeof text - 1 ? size : sizeof text - 1;
    memcpy(text, data, n);
    text[n] = '\0';
    for (char *line = text; line != NULL && *line != '\0';) {
        char *next = strchr(line, '\n');
        long rows = 0, cols = 0;
        if (line[0] != '%' && sscanf(line, "%ld %ld", &rows, &cols) == 2)
            return cols > 1000000;
        line = next ? next + 1 : NULL;
    }
    return 0;
}

/* The reader's compressed columns are what the library's _csc setters take. */
static void check_columns(const struct cli_sparse *A)
{
    FUZZ_REQUIRE(A->rows >= 1 && A->rows <= (size_t)CLI_MTX_MAX_DIM && A->cols >= 1 &&
                     A->cols <= (size_t)CLI_MTX_MAX_DIM && (!A->lower || A->rows == A->cols),
                 "read_mtx: %zu x %zu, lower %d", A->rows, A->cols, A->lower);
    FUZZ_REQUIRE(A->colptr[0] == 0, "read_mtx: colptr[0] = %lld", (long long)A->colptr[0]);
    for (size_t j = 0; j < A->cols; j++) {
        FUZZ_REQUIRE(A->colptr[j + 1] >= A->colptr[j], "read_mtx: colptr decreases at %zu", j);
        for (int64_t p = A->colptr[j]; p < A->colptr[j + 1]; p++) {
            int64_t i = A->rowind[p];
            FUZZ_REQUIRE(i >= 0 && (size_t)i < A->rows && (!A->lower || (size_t)i >= j) &&
                             (p == A->colptr[j] || i > A->rowind[p - 1]),
                         "read_mtx: row %lld in column %zu", (long long)i, j);
            FUZZ_REQUIRE(isfinite(A->values[p]) && A->values[p] != 0.0,
                         "read_mtx: entry (%lld, %zu) = %g", (long long)i, j, A->values[p]);
        }
    }
}

static void read_matrix(const char *path)
{
    struct cli_sparse A = {0};
    int status = cli_read_mtx("--mass", path, 0, 0, &A);
    FUZZ_REQUIRE(status == 0 || status == CLI_EXIT_USAGE, "read_mtx: status %d", status);
    if (status == 0)
        check_columns(&A);
    cli_sparse_free(&A);
}

static void read_file(uint8_t which, const uint8_t *data, size_t size)
{
    const char *path = input_file(data, size);
    double *A = NULL;
    size_t rows = 0, cols = 0;
    int status;
    if (which == 1) {
        if (!declared_large(data, size))
            read_matrix(path);
        return;
    }
    if (which == 2) {
        size_t ncols = 1 + size % 3;
        status = cli_read_columns("--mun", path, ncols, &rows, &A);
        FUZZ_REQUIRE(status == 0 || status == CLI_EXIT_USAGE, "read_columns: status %d", status);
        if (status == 0)
            FUZZ_REQUIRE(fuzz_all_finite(A, rows * ncols), "read_columns: a value not finite");
    } else {
        double t0 = NAN, dt = NAN;
        status = cli_read_record("--ground-accel", path, &t0, &dt, &rows, &A);
        FUZZ_REQUIRE(status == 0 || status == CLI_EXIT_USAGE, "read_record: status %d", status);
        if (status == 0)
            FUZZ_REQUIRE(rows >= 2 && isfinite(t0) && isfinite(dt) && dt > 0.0 &&
                             fuzz_all_finite(A, rows),
                         "read_record: n %zu t0 %g dt %g", rows, t0, dt);
    }
    free(A);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size == 0)
        return 0;
    uint8_t which = data[0] % 4;
    if (which != 0) {
        read_file(which, data + 1, size - 1);
        return 0;
    }
    static struct fuzz_argv a;
    fuzz_argv_split(data, size, 1, &a);
    struct structure_options o;
    int status = cli_parse_structure(a.argc, a.argv, &o);
    FUZZ_REQUIRE(status == 0 || status == CLI_EXIT_USAGE, "parse: status %d", status);
    if (status == 0)
        check_options(&o);
    return 0;
}
