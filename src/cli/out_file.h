/* SPDX-License-Identifier: GPL-3.0-or-later */
/* out_file.h — files that `fricreg-sim reproduce` writes into a directory the user names,
 * without ever losing the user's data there; and one file replaced whole
 * (cli_replace_file).
 *
 * Each file is written under a temporary name made with mkstemp (O_CREAT|O_EXCL: never an
 * existing file, never through a symlink), every write, flush and close is checked, and only
 * a complete file is renamed to its name. An existing file of that name is replaced only if it
 * is a regular file (not a symlink) that an earlier run wrote: DIR/.fricreg-reproduce lists
 * the names written. Anything else is refused, naming the file. */
#ifndef FRICREG_CLI_OUT_FILE_H
#define FRICREG_CLI_OUT_FILE_H

#include <stddef.h>
#include <stdio.h>

#define CLI_OUT_MANIFEST ".fricreg-reproduce"
#define CLI_OUT_PATH 4096

struct cli_out {
    FILE *f;                 /* write here */
    char tmp[CLI_OUT_PATH];  /* its temporary name */
    char path[CLI_OUT_PATH]; /* its final name, dir/name */
    const char *dir, *name;
};

/* 1 if dir/name may be (re)written: absent, or a regular file the manifest lists; else 0,
 * with a message naming the file on stderr. */
int cli_out_may_replace(const char *dir, const char *name);

/* Opens a temporary file for dir/name in o. Returns 0, or 1 with a message naming the path. */
int cli_out_open(struct cli_out *o, const char *dir, const char *name);

/* Checks every write, flushes, syncs and closes o, then renames it to its name if
 * cli_out_may_replace allows. Returns 0, or 1 with a message naming the path (the temporary
 * file removed). */
int cli_out_commit(struct cli_out *o);

/* Closes and removes o's temporary file (after a failure elsewhere). */
void cli_out_discard(struct cli_out *o);

/* Renames the complete file `from` to dir/name if cli_out_may_replace allows. Returns 0, or 1
 * with a message (from is removed). */
int cli_out_install(const char *from, const char *dir, const char *name);

/* Writes the manifest: the n names written. Returns 0 or 1 (message printed). */
int cli_out_write_manifest(const char *dir, const char *const names[], size_t n);

/* Writes data[len] to path through a temporary file beside it, renamed to path once complete:
 * a failed write (a full disk, a file-size limit) leaves an existing path as it was. Returns 0;
 * an errno value (the temporary file removed); or -1 if path exists and is not a regular file
 * (a device, a directory, a symbolic link: not replaced). */
int cli_replace_file(const char *path, const void *data, size_t len);

#endif
