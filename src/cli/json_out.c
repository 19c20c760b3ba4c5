/* SPDX-License-Identifier: GPL-3.0-or-later */
/* json_out.c — the numbers and strings of fricreg-sim's JSON summaries (cli.h). */
#include <math.h>
#include <stdio.h>

#include "base/companion_estimate.h" /* fr_estimate_kind_name */
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

void cli_json_kinds(FILE *out, const char *name, size_t n, const int kind[])
{
    fprintf(out, ", \"%s\": [", name);
    for (size_t i = 0; i < n; i++)
        fprintf(out, "%s\"%s\"", i ? ", " : "", fr_estimate_kind_name(kind[i]));
    fprintf(out, "]");
}

void cli_count_kinds(struct cli_kind_counts *c, size_t n, const int kind[])
{
    for (size_t i = 0; i < n; i++)
        if (kind[i] >= FRICREG_EST_KIND_ASYMPTOTIC && kind[i] <= FRICREG_EST_KIND_ASSUMED)
            c->n[kind[i]]++;
}

void cli_json_kind_counts(FILE *out, const struct cli_kind_counts *c)
{
    fprintf(out,
            ", \"error_estimate_kinds\": {\"asymptotic\": %zu, \"bound\": %zu, "
            "\"assumed\": %zu}",
            c->n[FRICREG_EST_KIND_ASYMPTOTIC], c->n[FRICREG_EST_KIND_BOUND],
            c->n[FRICREG_EST_KIND_ASSUMED]);
}
