/* SPDX-License-Identifier: GPL-3.0-or-later */
/* structure_checkpoint.c — --checkpoint-in and --checkpoint-out of `fricreg-sim structure`
 * (structure_checkpoint.h): the blob read whole and restored, or saved and replacing the file
 * only once complete (out_file.h); a file that fails is named, exit 2. */
#include <errno.h>
#include <stdlib.h>
#include <string.h>

#include "input_line.h"
#include "out_file.h"
#include "structure_checkpoint.h"
#include "structure_steps.h"

int cli_checkpoint_in(fricreg_structure *s, const struct structure_options *o)
{
    const char *path = o->checkpoint_in;
    FILE *f = fopen(path, "rb");
    if (f == NULL)
        return cli_file_error("--checkpoint-in", path, 0, "cannot open: %s", strerror(errno));
    size_t len = 0, cap = 1 << 16;
    unsigned char *buf = malloc(cap);
    for (size_t got = 1; buf != NULL && got > 0;) {
        got = fread(buf + len, 1, cap - len, f);
        len += got;
        unsigned char *more = len == cap ? realloc(buf, cap *= 2) : buf;
        if (more == NULL)
            free(buf);
        buf = more;
    }
    int read_error = ferror(f);
    fclose(f);
    if (buf == NULL || read_error) {
        free(buf);
        return cli_file_error("--checkpoint-in", path, 0, "%s",
                              read_error ? "cannot read" : "out of memory");
    }
    int status = fricreg_structure_restore(s, buf, len);
    free(buf);
    if (status != FRICREG_OK)
        return cli_file_error("--checkpoint-in", path, 0, "%s", fricreg_structure_errmsg(s));
    double t = cli_structure_value(s, FRICREG_SVALUE_TIME);
    if (!(o->t_end > t)) {
        char what[96];
        snprintf(what, sizeof what, "must be after the checkpoint's time %.17g", t);
        return cli_usage_error("--t-end", what);
    }
    return 0;
}

int cli_checkpoint_out(fricreg_structure *s, const char *path)
{
    size_t len = 0;
    unsigned char *buf = NULL;
    int status = fricreg_structure_save(s, NULL, &len);
    if (status == FRICREG_OK && (buf = malloc(len)) == NULL)
        return cli_file_error("--checkpoint-out", path, 0, "out of memory");
    if (status == FRICREG_OK)
        status = fricreg_structure_save(s, buf, &len);
    if (status != FRICREG_OK) {
        free(buf);
        return cli_file_error("--checkpoint-out", path, 0, "%s", fricreg_structure_errmsg(s));
    }
    int err = cli_replace_file(path, buf, len);
    free(buf);
    if (err < 0)
        return cli_file_error("--checkpoint-out", path, 0, "not a regular file: not replaced");
    return err == 0
               ? 0
               : cli_file_error("--checkpoint-out", path, 0, "cannot write: %s", strerror(err));
}
