/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element_sets.c — the --elements sets of `fricreg-sim structure`, `hb` and `nma`
 * (element_sets.h): parsed, read with the CLI's readers (matrix_market.c through cli_read_dense,
 * input_line.c), each element's parameters judged by its kernel so that a bad one is named by
 * its line, added to the model in order and listed in the summary. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "element_sets.h"
#include "input_line.h"
#include "jenkins_input.h"

/* The kernel's type names, ", "-separated, into buf[len]. */
static const char *type_names(char *buf, size_t len)
{
    size_t used = 0;
    buf[0] = '\0';
    for (size_t k = 0; k < fricreg_element_count() && used < len; k++)
        used += (size_t)snprintf(buf + used, len - used, "%s%s", k > 0 ? ", " : "",
                                 fricreg_element_name(fricreg_element_at(k)));
    return buf;
}

const char *cli_element_set_help(void)
{
    static char help[1024];
    if (help[0] == '\0') {
        char names[256];
        snprintf(help, sizeof help,
                 "an element set of any type, repeatable (each set added in the order given): "
                 "TYPE one of %s (fricreg_element.h); J.mtx Matrix Market (me dim) x n, element "
                 "i's dim rows consecutive (tangential components, then the normal); P.txt a "
                 "line per element in the kernel's layout: kt mun; kt mu kn n0 gap "
                 "(jenkins_normal, contact_3d); k_1 .. k_ns phi_1 .. phi_ns (Iwan; ns from the "
                 "line's length); k_1 .. k_ns mu_1 .. mu_ns kn n0 gap (iwan_normal). Not with "
                 "the element options above",
                 type_names(names, sizeof names));
    }
    return help;
}

int cli_parse_element_set(const struct cli_option *row, const char *text)
{
    struct cli_element_set_options *o = row->slot;
    const char *first = strchr(text, ':'), *last = strrchr(text, ':');
    if (first == NULL || last == first || first == text || last == first + 1 || last[1] == '\0')
        return cli_usage_error(row->name, "expected TYPE:J.mtx:P.txt");
    if (o->n == CLI_MAX_ELEMENT_SETS) {
        char what[64];
        snprintf(what, sizeof what, "at most %d sets", CLI_MAX_ELEMENT_SETS);
        return cli_usage_error(row->name, what);
    }
    char name[32] = "", names[256], what[400]; /* a longer TYPE is no type's name */
    size_t len = (size_t)(first - text);
    if (len < sizeof name) {
        memcpy(name, text, len);
        name[len] = '\0';
    }
    const fricreg_element_type *type = fricreg_element_lookup(name);
    if (type == NULL) {
        snprintf(what, sizeof what, "unknown element type '%.*s' (%s)", (int)len, text,
                 type_names(names, sizeof names));
        return cli_usage_error(row->name, what);
    }
    o->set[o->n++] = (struct cli_element_set_option){type, text, len + 1,
                                                     (size_t)(last - first) - 1,
                                                     (size_t)(last - text) + 1};
    return 0;
}

void cli_free_element_sets(struct cli_element_sets *sets)
{
    for (size_t k = 0; k < sets->n; k++) {
        struct cli_element_set *e = &sets->set[k];
        free(e->J);
        free(e->params);
        free(e->line);
        free(e->rows_path);
    }
    memset(sets, 0, sizeof *sets);
}

/* The type of type's family whose parameters number count: the type itself if count is its
 * nparams, or an Iwan type's with ns sliders, count = 2 ns + its fixed tail (3 with a normal
 * law). NULL if none; *why then says what a line takes. */
static const fricreg_element_type *type_for_count(const fricreg_element_type *type, size_t count,
                                                  char *why, size_t len)
{
    size_t tail = fricreg_element_nparams(type) - 2; /* beyond ns = 1's pair */
    const char *name = fricreg_element_name(type);
    if (fricreg_element_sliders(type, 2) == NULL) { /* one slider: a fixed count */
        if (count == fricreg_element_nparams(type))
            return type;
        snprintf(why, len, "%zu numbers: %s takes %zu parameters", count, name,
                 fricreg_element_nparams(type));
        return NULL;
    }
    if (count > tail && (count - tail) % 2 == 0) {
        const fricreg_element_type *t = fricreg_element_sliders(type, (count - tail) / 2);
        if (t != NULL)
            return t;
        snprintf(why, len, "%zu sliders: at most %d", (count - tail) / 2,
                 FRICREG_ELEMENT_MAX_SLIDERS);
        return NULL;
    }
    snprintf(why, len, "%zu numbers: %s takes 2 ns%s parameters (ns sliders)", count, name,
             tail > 0 ? " + 3" : "");
    return NULL;
}

/* A line of count numbers v, element rows's (from 0): the first sets the set's type (an Iwan
 * type's ns) and count, the others must match it. */
static int take_line(struct cli_element_set *e, const fricreg_element_type *family, size_t rows,
                     long line, const double v[], size_t count)
{
    const char *path = e->params_path;
    if (rows == e->me)
        return cli_file_error("--elements", path, line,
                              "more lines than the %zu elements of %s (%zu rows of %zu)", e->me,
                              e->rows_path, e->me * e->dim, e->dim);
    if (rows > 0 && count != e->np)
        return cli_file_error("--elements", path, line,
                              "%zu numbers, line %ld has %zu: every element of a set takes the "
                              "same parameters",
                              count, e->line[0], e->np);
    if (rows == 0) {
        char why[160];
        if ((e->type = type_for_count(family, count, why, sizeof why)) == NULL)
            return cli_file_error("--elements", path, line, "%s", why);
        e->np = count;
        e->params = malloc(e->me * e->np * sizeof *e->params);
        e->line = malloc(e->me * sizeof *e->line);
        if (e->params == NULL || e->line == NULL)
            return cli_file_error("--elements", path, line, "out of memory");
    }
    memcpy(e->params + rows * e->np, v, count * sizeof *v);
    e->line[rows] = line;
    return 0;
}

/* P.txt: a line per element (# and % comments and blank lines skipped). */
static int read_params(struct cli_element_set *e, const fricreg_element_type *family)
{
    const char *path = e->params_path;
    FILE *f = fopen(path, "r");
    if (f == NULL)
        return cli_file_error("--elements", path, 0, "cannot open: %s", strerror(errno));
    const size_t cap = CLI_SLIDER_LINE_MAX / 2;
    char *buf = malloc(CLI_SLIDER_LINE_MAX);
    double *v = malloc(cap * sizeof *v);
    long line = 0;
    int too_long = 0, status = buf == NULL || v == NULL
                                   ? cli_file_error("--elements", path, 0, "out of memory")
                                   : 0;
    size_t rows = 0, count = 0;
    while (status == 0 && cli_next_line(f, buf, CLI_SLIDER_LINE_MAX, &line, &too_long)) {
        if (buf[0] == '#' || buf[0] == '%' || cli_blank(buf))
            continue;
        status = cli_line_numbers("--elements", path, line, buf, v, cap, &count);
        if (status == 0)
            status = take_line(e, family, rows++, line, v, count);
    }
    fclose(f);
    free(buf);
    free(v);
    if (status == 0 && too_long)
        status = cli_file_error("--elements", path, line, "line too long (%d characters at most)",
                                CLI_SLIDER_LINE_MAX - 2);
    if (status == 0 && rows != e->me)
        status = cli_file_error("--elements", path, 0,
                                "%zu lines, %s has %zu elements (%zu rows "
                                "of %zu)",
                                rows, e->rows_path, e->me, e->me * e->dim, e->dim);
    return status;
}

/* Each element's parameters by its kernel, the message naming its line. */
static int check_params(const struct cli_element_set *e)
{
    for (size_t i = 0; i < e->me; i++) {
        char why[200];
        if (fricreg_element_explain(e->type, e->params + i * e->np, NULL, NULL, why, sizeof why) !=
            FRICREG_OK)
            return cli_file_error("--elements", e->params_path, e->line[i], "%s", why);
    }
    return 0;
}

/* One set: J (rows a multiple of the type's dim), then P. */
static int read_set(const struct cli_element_set_option *o, size_t n, struct cli_element_set *e)
{
    e->dim = (size_t)fricreg_element_dim(o->type);
    e->params_path = o->text + o->params;
    e->rows_path = malloc(o->rows_len + 1);
    if (e->rows_path == NULL)
        return cli_usage_error("--elements", "out of memory");
    memcpy(e->rows_path, o->text + o->rows, o->rows_len);
    e->rows_path[o->rows_len] = '\0';
    size_t rows = 0, cols = 0;
    int status = cli_read_dense("--elements", e->rows_path, 0, n, &rows, &cols, &e->J);
    if (status != 0)
        return status;
    if (rows % e->dim != 0)
        return cli_file_error("--elements", e->rows_path, 0,
                              "%zu rows: %s takes %zu per element (its components), a "
                              "multiple of %zu",
                              rows, fricreg_element_name(o->type), e->dim, e->dim);
    e->me = rows / e->dim;
    status = read_params(e, o->type);
    return status != 0 ? status : check_params(e);
}

int cli_read_element_sets(const struct cli_element_set_options *o, size_t n,
                          struct cli_element_sets *sets)
{
    int status = 0;
    for (size_t k = 0; k < o->n && status == 0; k++) {
        struct cli_element_set *e = &sets->set[sets->n++];
        status = read_set(&o->set[k], n, e);
        sets->me += e->me;
        sets->nforces += e->me * e->dim;
    }
    return status;
}

int cli_check_element_sets_alone(const struct cli_element_set_options *o,
                                 const struct cli_element_files *e)
{
    const char *files[] = {e->rows,     e->rows_2d, e->jenkins,       e->iwan,
                           e->segalman, e->normal,  e->normal_params, e->iwan_normal};
    int given = e->sliders_given || e->resolution_given;
    for (size_t k = 0; k < sizeof files / sizeof files[0]; k++)
        given |= files[k] != NULL;
    if (o->n > 0 && given)
        return cli_usage_error("--elements", "give --elements or the element options (--jenkins, "
                                             "--jenkins-2d and their parameter files), not both");
    return 0;
}

int cli_add_element_sets(void *model, cli_element_set_adder *add, size_t n,
                         const struct cli_element_sets *sets)
{
    for (size_t k = 0; k < sets->n; k++) {
        const char *why = add(model, &sets->set[k], n);
        if (why != NULL)
            return cli_file_error("--elements", sets->set[k].rows_path, 0, "%s", why);
    }
    return 0;
}

const char *cli_element_sets_kind(const struct cli_element_sets *sets)
{
    const char *name = fricreg_element_name(sets->set[0].type);
    for (size_t k = 1; k < sets->n; k++)
        if (strcmp(fricreg_element_name(sets->set[k].type), name) != 0)
            return "mixed";
    return name;
}

void cli_json_element_sets(FILE *out, const struct cli_element_sets *sets)
{
    fprintf(out, ", \"element_kind\": \"%s\", \"element_sets\": [", cli_element_sets_kind(sets));
    for (size_t k = 0; k < sets->n; k++)
        fprintf(out, "%s{\"type\": \"%s\", \"nelements\": %zu, \"sliders_per_element\": %zu}",
                k > 0 ? ", " : "", fricreg_element_name(sets->set[k].type), sets->set[k].me,
                fricreg_element_nsliders(sets->set[k].type));
    fputs("]", out);
}
