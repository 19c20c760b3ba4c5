/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fuzz_argv.h — the CLI fuzz targets' argv: the input bytes from `from` on, one argument per
 * line (a NUL byte becomes a blank; the last line may be open), as fuzz_cli_options.c reads
 * them. At most FUZZ_MAX_ARGS arguments of FUZZ_MAX_ARG_LEN bytes (longer ones are cut). */
#ifndef FRICREG_FUZZ_ARGV_H
#define FRICREG_FUZZ_ARGV_H

#include <stddef.h>
#include <stdint.h>

enum { FUZZ_MAX_ARGS = 24, FUZZ_MAX_ARG_LEN = 64 };

struct fuzz_argv {
    char text[FUZZ_MAX_ARGS][FUZZ_MAX_ARG_LEN + 1];
    char *argv[FUZZ_MAX_ARGS + 1];
    int argc;
};

static inline void fuzz_argv_split(const uint8_t *data, size_t size, size_t from,
                                   struct fuzz_argv *a)
{
    size_t len = 0;
    a->argc = 0;
    for (size_t k = from; k <= size && a->argc < FUZZ_MAX_ARGS; k++) {
        if (k == size || data[k] == '\n') {
            if (k < size || len > 0) {
                a->text[a->argc][len] = '\0';
                a->argv[a->argc] = a->text[a->argc];
                a->argc++;
            }
            len = 0;
        } else if (len < FUZZ_MAX_ARG_LEN) {
            a->text[a->argc][len++] = data[k] ? (char)data[k] : ' ';
        }
    }
    a->argv[a->argc] = NULL;
}

#endif
