/* SPDX-License-Identifier: GPL-3.0-or-later */
/* jenkins_input.c — the joint elements' files that `fricreg-sim hb` and `fricreg-sim
 * structure` share (jenkins_input.h): Jenkins, Iwan (the caller's sliders or Segalman's
 * model), lift-off and (structure only) 2-D Jenkins elements. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "cli_input.h"
#include "fricreg_iwan.h"
#include "input_line.h"
#include "jenkins_input.h"
#include "matrix_market.h"

void cli_element_defaults(struct cli_element_files *e)
{
    *e = (struct cli_element_files){.sliders = 50, .resolution = 1e-6};
}

int cli_check_elements(const struct cli_element_files *e, int required)
{
    const char *params[] = {e->jenkins, e->iwan, e->segalman, e->normal_params, e->iwan_normal};
    static const char *const names[] = {"--jenkins-params", "--iwan-params", "--iwan-segalman",
                                        "--normal-params", "--iwan-normal-params"};
    size_t given = 0, last = 0;
    for (size_t k = 0; k < 5; k++)
        if (params[k] != NULL) {
            given++;
            last = k;
        }
    if (given > 1)
        return cli_usage_error(names[last], "give only one of --jenkins-params, --iwan-params, "
                                            "--iwan-segalman, --normal-params or "
                                            "--iwan-normal-params");
    if ((e->sliders_given || e->resolution_given) && e->segalman == NULL)
        return cli_usage_error(e->sliders_given ? "--iwan-sliders" : "--iwan-resolution",
                               "only with --iwan-segalman");
    if (!(e->resolution < 1.0))
        return cli_usage_error("--iwan-resolution", "must be < 1 (a fraction of phi_max)");
    if (e->rows_2d != NULL && e->rows != NULL)
        return cli_usage_error("--jenkins-2d", "give --jenkins or --jenkins-2d, not both");
    if (e->rows_2d != NULL && (e->iwan != NULL || e->segalman != NULL || e->iwan_normal != NULL))
        return cli_usage_error("--jenkins-2d", "2-D elements take --jenkins-params or --normal "
                                               "with --normal-params (no Iwan 2-D elements)");
    if (e->rows_2d != NULL && e->jenkins == NULL && e->normal == NULL && e->normal_params == NULL)
        return cli_usage_error("--jenkins-params", "missing (--jenkins-2d goes with "
                                                   "--jenkins-params, or --normal with "
                                                   "--normal-params)");
    if (e->rows_2d != NULL && e->jenkins == NULL &&
        (e->normal == NULL) != (e->normal_params == NULL))
        return cli_usage_error(e->normal == NULL ? "--normal" : "--normal-params",
                               "missing (--normal and --normal-params go together)");
    if (e->rows_2d != NULL)
        return 0;
    if (e->rows == NULL && (required || given > 0 || e->normal != NULL))
        return cli_usage_error("--jenkins", given > 0 || e->normal != NULL
                                                ? "missing (the elements' rows go with their "
                                                  "parameters)"
                                                : "missing (a file is required)");
    if (e->rows != NULL && given == 0 && e->normal == NULL)
        return cli_usage_error("--jenkins-params",
                               "missing (--jenkins goes with --jenkins-params, --iwan-params, "
                               "--iwan-segalman or --normal with --normal-params or "
                               "--iwan-normal-params)");
    const char *normal_params = e->normal_params != NULL ? e->normal_params : e->iwan_normal;
    if ((e->normal == NULL) != (normal_params == NULL))
        return cli_usage_error(e->normal == NULL ? "--normal" : "--normal-params",
                               "missing (--normal goes with --normal-params or "
                               "--iwan-normal-params)");
    return 0;
}

const char *cli_element_kind_name(const struct cli_elements *el)
{
    static const char *const names[] = {"jenkins",    "iwan",       "lift-off",
                                        "jenkins-2d", "contact-3d", "iwan-lift-off"};
    return names[el->kind];
}

void cli_free_elements(struct cli_elements *el)
{
    void *blocks[] = {el->J, el->Jn, el->k, el->phi, el->mu, el->n0, el->kn};
    for (size_t k = 0; k < sizeof blocks / sizeof *blocks; k++)
        free(blocks[k]);
    memset(el, 0, sizeof *el);
}

int cli_read_dense(const char *option, const char *path, size_t rows, size_t cols, size_t *nrows,
                   size_t *ncols, double **out)
{
    struct cli_sparse A = {0};
    int status = cli_read_mtx(option, path, rows, cols, &A);
    if (status != 0)
        return status;
    double *D = calloc(A.rows * A.cols, sizeof *D);
    if (D == NULL) {
        cli_sparse_free(&A);
        return cli_file_error(option, path, 0, "out of memory");
    }
    for (size_t j = 0; j < A.cols; j++)
        for (int64_t p = A.colptr[j]; p < A.colptr[j + 1]; p++) {
            size_t i = (size_t)A.rowind[p];
            D[i * A.cols + j] = A.values[p];
            if (A.lower)
                D[j * A.cols + i] = A.values[p];
        }
    *nrows = A.rows;
    *ncols = A.cols;
    *out = D;
    cli_sparse_free(&A);
    return 0;
}

/* Columns per row, one row per entity (dof or element): into v[rows * ncols]. */
static int read_rows(const char *option, const char *path, size_t rows, size_t ncols,
                     const char *what, double **v)
{
    size_t got = 0;
    int status = cli_read_columns(option, path, ncols, &got, v);
    if (status == 0 && got != rows) {
        free(*v);
        *v = NULL;
        status = cli_file_error(option, path, 0, "%zu lines, the model has %zu %s", got, rows,
                                what);
    }
    return status;
}

/* Column c of v[rows * ncols] into a new array *out. */
static int column(const double *v, size_t rows, size_t ncols, size_t c, double **out)
{
    *out = malloc((rows > 0 ? rows : 1) * sizeof **out);
    if (*out == NULL)
        return 0;
    for (size_t i = 0; i < rows; i++)
        (*out)[i] = v[i * ncols + c];
    return 1;
}

int cli_read_pairs(const char *option, const char *path, size_t rows, const char *what, double **a,
                   double **b)
{
    double *values = NULL;
    int status = read_rows(option, path, rows, 2, what, &values);
    if (status == 0 && !(column(values, rows, 2, 0, a) && column(values, rows, 2, 1, b)))
        status = cli_file_error(option, path, 0, "out of memory");
    free(values);
    return status;
}

/* --iwan-params (lead 0: m lines of k_1 phi_1 ... k_ns phi_ns) or --iwan-normal-params (lead
 * 2: n0 kn, then k_1 mu_1 ... k_ns mu_ns), the same ns on each line: the pairs into k[m ns] and
 * phi[m ns], the lead numbers into head[m lead] (lead > 0). */
static int read_sliders(const char *option, const char *path, size_t m, size_t lead, size_t *ns,
                        double **k, double **phi, double **head)
{
    FILE *f = fopen(path, "r");
    if (f == NULL)
        return cli_file_error(option, path, 0, "cannot open: %s", strerror(errno));
    const size_t cap = CLI_SLIDER_LINE_MAX / 2;
    char *buf = malloc(CLI_SLIDER_LINE_MAX);
    double *v = malloc(cap * sizeof *v);
    long line = 0, first = 0;
    int too_long = 0, status = 0;
    size_t rows = 0, width = 0;
    if (buf == NULL || v == NULL ||
        (lead > 0 && (*head = malloc(m * lead * sizeof **head)) == NULL))
        status = cli_file_error(option, path, 0, "out of memory");
    while (status == 0 && cli_next_line(f, buf, CLI_SLIDER_LINE_MAX, &line, &too_long)) {
        if (buf[0] == '#' || buf[0] == '%' || cli_blank(buf))
            continue;
        size_t count = 0;
        if ((status = cli_line_numbers(option, path, line, buf, v, cap, &count)) != 0)
            break;
        if (count < lead + 2 || (count - lead) % 2 != 0)
            status = cli_file_error(option, path, line,
                                    "%zu numbers: give %spairs k_s %s, one per slider", count,
                                    lead > 0 ? "n0 kn, then " : "", lead > 0 ? "mu_s" : "phi_s");
        else if (rows == m)
            status = cli_file_error(option, path, line,
                                    "more lines than the %zu elements (rows of --jenkins)", m);
        else if (rows > 0 && count - lead != 2 * width)
            status = cli_file_error(option, path, line,
                                    "%zu sliders, line %ld has %zu: every element needs the same "
                                    "number of sliders (give a slider %s = 0 to drop it)",
                                    (count - lead) / 2, first, width, lead > 0 ? "mu" : "phi");
        else {
            if (rows == 0) {
                width = (count - lead) / 2;
                first = line;
                *k = malloc(m * width * sizeof **k);
                *phi = malloc(m * width * sizeof **phi);
                if (*k == NULL || *phi == NULL)
                    status = cli_file_error(option, path, line, "out of memory");
            }
            for (size_t c = 0; status == 0 && c < lead; c++)
                (*head)[rows * lead + c] = v[c];
            for (size_t sl = 0; status == 0 && sl < width; sl++) {
                (*k)[rows * width + sl] = v[lead + 2 * sl];
                (*phi)[rows * width + sl] = v[lead + 2 * sl + 1];
            }
            rows++;
        }
    }
    fclose(f);
    free(buf);
    free(v);
    if (status == 0 && too_long)
        status = cli_file_error(option, path, line, "line too long (%d characters at most)",
                                CLI_SLIDER_LINE_MAX - 2);
    if (status == 0 && rows != m)
        status = cli_file_error(option, path, 0,
                                "%zu lines, the model has %zu elements (rows of --jenkins)", rows,
                                m);
    *ns = width;
    return status;
}

/* --iwan-segalman: m lines F_S K_T chi beta, discretized into e->sliders sliders each by
 * fricreg_iwan_set_segalman. */
static int read_segalman(const struct cli_element_files *e, struct cli_elements *el)
{
    const char *option = "--iwan-segalman";
    size_t m = el->m, ns = (size_t)e->sliders;
    double *v = NULL, *fs = NULL, *kt = NULL, *chi = NULL, *beta = NULL;
    int status = read_rows(option, e->segalman, m, 4, "elements (rows of --jenkins)", &v);
    if (status != 0)
        return status;
    fricreg_iwan *iw = NULL;
    el->k = malloc(m * ns * sizeof *el->k);
    el->phi = malloc(m * ns * sizeof *el->phi);
    if (el->k == NULL || el->phi == NULL || !column(v, m, 4, 0, &fs) || !column(v, m, 4, 1, &kt) ||
        !column(v, m, 4, 2, &chi) || !column(v, m, 4, 3, &beta) ||
        fricreg_iwan_create(1, m, ns, &iw) != FRICREG_OK)
        status = cli_file_error(option, e->segalman, 0, "out of memory");
    else if (fricreg_iwan_set_segalman(iw, m, fs, kt, chi, beta, e->resolution) != FRICREG_OK)
        status = cli_file_error(option, e->segalman, 0, "%s", fricreg_iwan_errmsg(iw));
    else
        fricreg_iwan_get_params(iw, m, ns, el->k, el->phi);
    el->ns = ns;
    fricreg_iwan_free(iw);
    free(v);
    free(fs);
    free(kt);
    free(chi);
    free(beta);
    return status;
}

/* --normal and --normal-params: the normal rows and m lines kt mu n0 kn. */
static int read_normal(const struct cli_element_files *e, size_t n, struct cli_elements *el)
{
    size_t m = el->m, rows = 0, cols = 0;
    double *v = NULL;
    int status = cli_read_dense("--normal", e->normal, m, n, &rows, &cols, &el->Jn);
    if (status == 0)
        status = read_rows("--normal-params", e->normal_params, m, 4,
                           "elements (rows of --jenkins)", &v);
    if (status == 0 && !(column(v, m, 4, 0, &el->k) && column(v, m, 4, 1, &el->mu) &&
                         column(v, m, 4, 2, &el->n0) && column(v, m, 4, 3, &el->kn)))
        status = cli_file_error("--normal-params", e->normal_params, 0, "out of memory");
    el->ns = 1;
    free(v);
    return status;
}

/* --normal and --iwan-normal-params: the normal rows and m lines n0 kn k_1 mu_1 ... */
static int read_iwan_normal(const struct cli_element_files *e, size_t n, struct cli_elements *el)
{
    size_t m = el->m, rows = 0, cols = 0;
    double *head = NULL;
    int status = cli_read_dense("--normal", e->normal, m, n, &rows, &cols, &el->Jn);
    if (status == 0)
        status = read_sliders("--iwan-normal-params", e->iwan_normal, m, 2, &el->ns, &el->k,
                              &el->mu, &head);
    if (status == 0 && !(column(head, m, 2, 0, &el->n0) && column(head, m, 2, 1, &el->kn)))
        status = cli_file_error("--iwan-normal-params", e->iwan_normal, 0, "out of memory");
    free(head);
    return status;
}

/* --jenkins-2d and --jenkins-params: 2m rows (two per element) and m lines kt mun; or, with
 * --normal and --normal-params, the 3-D contact elements: m normal rows, m lines kt mu n0 kn. */
static int read_planar(const struct cli_element_files *e, size_t n, struct cli_elements *el)
{
    size_t rows = 0, cols = 0;
    int status = cli_read_dense("--jenkins-2d", e->rows_2d, 0, n, &rows, &cols, &el->J);
    if (status != 0)
        return status;
    if (rows % 2 != 0)
        return cli_file_error("--jenkins-2d", e->rows_2d, 0,
                              "%zu rows: a 2-D element takes two (x, y), an even count", rows);
    el->m = rows / 2;
    el->ns = 1;
    if (e->normal != NULL) {
        el->kind = CLI_ELEMENTS_CONTACT_3D;
        el->option = "--normal-params";
        el->path = e->normal_params;
        return read_normal(e, n, el);
    }
    el->kind = CLI_ELEMENTS_JENKINS_2D;
    el->option = "--jenkins-params";
    el->path = e->jenkins;
    return cli_read_pairs("--jenkins-params", e->jenkins, el->m,
                          "elements (row pairs of --jenkins-2d)", &el->k, &el->phi);
}

int cli_read_elements(const struct cli_element_files *e, size_t n, struct cli_elements *el)
{
    if (e->rows_2d != NULL)
        return read_planar(e, n, el);
    if (e->rows == NULL)
        return 0;
    size_t cols = 0;
    int status = cli_read_dense("--jenkins", e->rows, 0, n, &el->m, &cols, &el->J);
    if (status != 0)
        return status;
    el->ns = 1;
    if (e->iwan_normal != NULL) {
        el->kind = CLI_ELEMENTS_IWAN_NORMAL;
        el->option = "--iwan-normal-params";
        el->path = e->iwan_normal;
        return read_iwan_normal(e, n, el);
    }
    if (e->normal != NULL) {
        el->kind = CLI_ELEMENTS_NORMAL;
        el->option = "--normal-params";
        el->path = e->normal_params;
        return read_normal(e, n, el);
    }
    if (e->iwan != NULL) {
        el->kind = CLI_ELEMENTS_IWAN;
        el->option = "--iwan-params";
        el->path = e->iwan;
        return read_sliders("--iwan-params", e->iwan, el->m, 0, &el->ns, &el->k, &el->phi, NULL);
    }
    if (e->segalman != NULL) {
        el->kind = CLI_ELEMENTS_IWAN;
        el->option = "--iwan-segalman";
        el->path = e->segalman;
        return read_segalman(e, el);
    }
    el->kind = CLI_ELEMENTS_JENKINS;
    el->option = "--jenkins-params";
    el->path = e->jenkins;
    return cli_read_pairs("--jenkins-params", e->jenkins, el->m, "elements (rows of --jenkins)",
                          &el->k, &el->phi);
}
