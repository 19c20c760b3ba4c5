/* SPDX-License-Identifier: GPL-3.0-or-later */
/* dof_list.c — the lists of --output-dofs, --output-contacts and --output-elements (dof_list.h): "A" or "A-B"
 * items between commas,
 * whole numbers from 1 written in decimal digits only (no sign, no blank), read by strtoull.
 * Checked twice: its syntax when the options are parsed, its range against the model once
 * the mass matrix has said how many dofs there are. */
#include <ctype.h>
#include <errno.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "dof_list.h"

const struct cli_list_kind cli_dof_list = {"dof", "(--mass is %zu x %zu)"},
                           cli_contact_list = {"contact", "(--contacts has %zu rows)"},
                           cli_element_list = {"element", "(the run adds %zu elements)"};

/* One number at *text, digits only, >= 1; *text moved past it. 1 if read, else 0. */
static int read_dof(const char **text, unsigned long long *value)
{
    if (!isdigit((unsigned char)**text))
        return 0;
    char *end = NULL;
    errno = 0;
    *value = strtoull(*text, &end, 10);
    int ok = errno == 0 && *value >= 1;
    *text = end;
    return ok;
}

/* The next item "A" or "A-B" at *text into [*lo, *hi]; *text moved to the comma after it or
 * the end. 0, or CLI_EXIT_USAGE with a message naming the item. */
static int read_item(const char *option, const struct cli_list_kind *kind, const char **text,
                     unsigned long long *lo, unsigned long long *hi)
{
    const char *start = *text;
    int ok = read_dof(text, lo);
    *hi = *lo;
    if (ok && **text == '-') {
        ++*text;
        ok = read_dof(text, hi);
    }
    if (ok && **text != ',' && **text != '\0')
        ok = 0;
    int len = 0;
    while (start[len] != ',' && start[len] != '\0' && len < 40)
        len++;
    char what[128];
    if (!ok) {
        snprintf(what, sizeof what,
                 "'%.*s' is not %s %s from 1 or a range A-B of them (LIST: e.g. 1-10,57)", len,
                 start, strchr("aeiou", kind->noun[0]) ? "an" : "a", kind->noun);
        return cli_usage_error(option, what);
    }
    if (*lo > *hi) {
        snprintf(what, sizeof what, "range '%.*s' runs backwards (A-B needs A <= B)", len, start);
        return cli_usage_error(option, what);
    }
    return 0;
}

int cli_check_dof_list(const char *option, const struct cli_list_kind *kind, const char *text)
{
    unsigned long long lo, hi;
    for (const char *c = text;; c++) {
        int status = read_item(option, kind, &c, &lo, &hi);
        if (status != 0)
            return status;
        if (*c == '\0')
            return 0;
    }
}

int cli_expand_dof_list(const char *option, const struct cli_list_kind *kind, const char *text,
                        size_t n, size_t *count, size_t **items)
{
    unsigned char *named = calloc(n, 1);
    size_t used = 0, cap = 16;
    size_t *list = malloc(cap * sizeof *list);
    int status = named == NULL || list == NULL ? cli_usage_error(option, "out of memory") : 0;
    char what[160];
    unsigned long long lo = 0, hi = 0;
    for (const char *c = text; status == 0; c++) {
        if ((status = read_item(option, kind, &c, &lo, &hi)) != 0)
            break;
        if (hi > n) {
            char size[64];
            snprintf(size, sizeof size, kind->size_says, n, n);
            snprintf(what, sizeof what, "%s %llu is beyond the model's %zu %s", kind->noun, hi, n,
                     size);
            status = cli_usage_error(option, what);
            break;
        }
        for (size_t k = (size_t)lo - 1; status == 0 && k < (size_t)hi; k++) {
            if (named[k]) {
                snprintf(what, sizeof what, "%s %zu is named twice", kind->noun, k + 1);
                status = cli_usage_error(option, what);
            } else if (used == cap) { /* at most n entries: each dof once */
                size_t *more = realloc(list, 2 * cap * sizeof *list);
                if (more == NULL)
                    status = cli_usage_error(option, "out of memory");
                else {
                    list = more;
                    cap *= 2;
                }
            }
            if (status == 0) {
                named[k] = 1;
                list[used++] = k;
            }
        }
        if (*c == '\0')
            break;
    }
    free(named);
    if (status != 0) {
        free(list);
        return status;
    }
    *count = used;
    *items = list;
    return 0;
}
