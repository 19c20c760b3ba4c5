/* SPDX-License-Identifier: GPL-3.0-or-later */
/* json_out.c — the numbers and strings of fricreg-sim's JSON summaries (cli.h). */
#include <math.h>
#include <stdio.h>

#include "cli.h"

/* JSON has no infinity and no NaN: an estimate that could not be formed (+infinity in the
 * library) or a cycle an extrapolation over a window did not extrapolate is written null. */
void cli_json_number(FILE *out, double x)
{
    isfinite(x) ? fprintf(out, "%.17g", x) : fprintf(out, "null");
}

void cli_json_array(FILE *out, const char *name, size_t n, const double a[])
{
    fprintf(out, ", \"%s\": [", name);
    for (size_t i = 0; i < n; i++) {
        fprintf(out, "%s", i ? ", " : "");
        cli_json_number(out, a[i]);
    }
    fprintf(out, "]");
}

/* The library's messages are plain text, but quotes, backslashes and control characters are
 * escaped all the same. */
void cli_json_string(FILE *out, const char *text)
{
    fputc('"', out);
    for (const unsigned char *c = (const unsigned char *)text; *c; c++) {
        if (*c == '"' || *c == '\\')
            fprintf(out, "\\%c", *c);
        else if (*c < 0x20)
            fprintf(out, "\\u%04x", *c);
        else
            fputc(*c, out);
    }
    fputc('"', out);
}
