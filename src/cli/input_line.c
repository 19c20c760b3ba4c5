/* SPDX-License-Identifier: GPL-3.0-or-later */
/* input_line.c — reading the input files of `fricreg-sim structure` line by line, and naming
 * the line of a bad one (input_line.h). */
#include <errno.h>
#include <math.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "input_line.h"

int cli_file_error(const char *option, const char *path, long line, const char *fmt, ...)
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

int cli_next_line(FILE *f, char *buf, size_t len, long *line, int *too_long)
{
    if (fgets(buf, (int)len, f) == NULL)
        return 0;
    (*line)++;
    size_t n = strlen(buf);
    *too_long = n == len - 1 && buf[n - 1] != '\n' && !feof(f);
    return !*too_long;
}

int cli_blank(const char *s)
{
    return s[strspn(s, " \t\r\n")] == '\0';
}

/* strtod sets ERANGE on underflow too, returning the number meant: only +-HUGE_VAL is an
 * overflow. */
int cli_read_number(const char *text, char **end, double *value)
{
    errno = 0;
    *value = strtod(text, end);
    return *end != text && !(errno == ERANGE && fabs(*value) == HUGE_VAL) && isfinite(*value) &&
           (**end == '\0' || strchr(" \t\r\n,", **end) != NULL);
}

int cli_read_index(const char *text, char **end, long max, long *value)
{
    errno = 0;
    *value = strtol(text, end, 10);
    return *end != text && errno == 0 && *value >= 1 && *value <= max &&
           (**end == '\0' || strchr(" \t\r\n", **end) != NULL);
}

int cli_line_numbers(const char *option, const char *path, long line, char *p, double *v,
                     size_t cap, size_t *count)
{
    char *end;
    *count = 0;
    for (p += strspn(p, " \t,"); !cli_blank(p); p = end + strspn(end, " \t,")) {
        if (*count == cap)
            return cli_file_error(option, path, line, "more than %zu numbers", cap);
        if (!cli_read_number(p, &end, &v[(*count)++]))
            return cli_file_error(option, path, line, "number %zu is not a finite number", *count);
    }
    return 0;
}
