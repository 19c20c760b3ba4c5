/* SPDX-License-Identifier: GPL-3.0-or-later */
/* warnings_out.c — the library's warnings as fricreg-sim reports them (cli.h, struct
 * cli_warnings): once each on stderr, and as the JSON summary's "warnings" list. */
#include <stdio.h>

#include "cli.h"

void cli_json_warnings(FILE *out, const struct cli_warnings *w)
{
    fputs(", \"warnings\": [", out);
    for (size_t k = 0; w != NULL && k < w->n; k++) {
        fprintf(out, "%s{\"code\": ", k ? ", " : "");
        cli_json_string(out, fricreg_warning_name(w->code[k]));
        fputs(", \"message\": ", out);
        cli_json_string(out, w->message[k]);
        fputc('}', out);
    }
    fputc(']', out);
}

void cli_print_warnings(const struct cli_warnings *w)
{
    for (size_t k = 0; k < w->n; k++)
        fprintf(stderr, "fricreg-sim: warning: %s\n", w->message[k]);
}
