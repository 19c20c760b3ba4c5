/* SPDX-License-Identifier: GPL-3.0-or-later */
/* out_file.c — output files written without losing the user's (out_file.h): reproduce's, and
 * one file replaced whole (the structure's checkpoint). */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "out_file.h"

static int io_error(const char *what, const char *path)
{
    fprintf(stderr, "fricreg-sim: reproduce: %s %s: %s\n", what, path, strerror(errno));
    return 1;
}

/* Whether the manifest of dir, a regular file, has the line `name`. */
static int listed(const char *dir, const char *name)
{
    char path[CLI_OUT_PATH], line[256];
    struct stat st;
    snprintf(path, sizeof path, "%s/%s", dir, CLI_OUT_MANIFEST);
    if (lstat(path, &st) != 0 || !S_ISREG(st.st_mode))
        return 0;
    FILE *f = fopen(path, "r");
    int found = 0;
    while (f != NULL && !found && fgets(line, sizeof line, f) != NULL) {
        line[strcspn(line, "\n")] = '\0';
        found = strcmp(line, name) == 0;
    }
    if (f != NULL)
        fclose(f);
    return found;
}

int cli_out_may_replace(const char *dir, const char *name)
{
    char path[CLI_OUT_PATH];
    struct stat st;
    snprintf(path, sizeof path, "%s/%s", dir, name);
    if (lstat(path, &st) != 0)
        return errno == ENOENT ? 1 : !io_error("cannot inspect", path);
    if (S_ISREG(st.st_mode) && (strcmp(name, CLI_OUT_MANIFEST) == 0 || listed(dir, name)))
        return 1;
    fprintf(stderr,
            "fricreg-sim: --out: %s exists and fricreg-sim did not write it (%s): not "
            "overwritten; move it away or choose another directory\n",
            path, S_ISREG(st.st_mode) ? "not listed in " CLI_OUT_MANIFEST : "not a regular file");
    return 0;
}

/* A temporary file beside path, its name in tmp (of CLI_OUT_PATH bytes), open for writing with
 * the mode fopen would give; NULL with errno set. */
static FILE *open_beside(const char *path, char *tmp)
{
    const char *slash = strrchr(path, '/');
    int n = slash != NULL ? snprintf(tmp, CLI_OUT_PATH, "%.*s/.%s.XXXXXX", (int)(slash - path),
                                     path, slash + 1)
                          : snprintf(tmp, CLI_OUT_PATH, ".%s.XXXXXX", path);
    if (n < 0 || n >= CLI_OUT_PATH) {
        errno = ENAMETOOLONG;
        return NULL;
    }
    int fd = mkstemp(tmp);
    if (fd < 0)
        return NULL;
    mode_t mask = umask(0); /* mkstemp makes 0600: give the file the mode fopen would */
    umask(mask);
    fchmod(fd, 0666 & ~mask);
    FILE *f = fdopen(fd, "wb");
    if (f == NULL) {
        int saved = errno;
        close(fd);
        unlink(tmp);
        errno = saved;
    }
    return f;
}

int cli_out_open(struct cli_out *o, const char *dir, const char *name)
{
    *o = (struct cli_out){.dir = dir, .name = name};
    snprintf(o->path, sizeof o->path, "%s/%s", dir, name);
    o->f = open_beside(o->path, o->tmp);
    return o->f == NULL ? io_error("cannot create a temporary file for", o->path) : 0;
}

void cli_out_discard(struct cli_out *o)
{
    if (o->f != NULL) {
        fclose(o->f);
        unlink(o->tmp);
        o->f = NULL;
    }
}

int cli_out_install(const char *from, const char *dir, const char *name)
{
    char path[CLI_OUT_PATH];
    snprintf(path, sizeof path, "%s/%s", dir, name);
    if (!cli_out_may_replace(dir, name)) {
        unlink(from);
        return 1;
    }
    if (rename(from, path) != 0) {
        int status = io_error("cannot rename a temporary file to", path);
        unlink(from);
        return status;
    }
    return 0;
}

int cli_out_commit(struct cli_out *o)
{
    FILE *f = o->f;
    o->f = NULL;
    errno = 0;
    int failed = ferror(f) || fflush(f) != 0 || fsync(fileno(f)) != 0;
    int saved = errno;
    failed |= fclose(f) != 0;
    if (failed) {
        errno = saved ? saved : errno ? errno : EIO; /* ferror alone leaves errno unset */
        io_error("cannot write", o->path);
        unlink(o->tmp);
        return 1;
    }
    return cli_out_install(o->tmp, o->dir, o->name);
}

int cli_out_write_manifest(const char *dir, const char *const names[], size_t n)
{
    struct cli_out o;
    if (cli_out_open(&o, dir, CLI_OUT_MANIFEST) != 0)
        return 1;
    for (size_t k = 0; k < n; k++)
        fprintf(o.f, "%s\n", names[k]);
    return cli_out_commit(&o);
}

int cli_replace_file(const char *path, const void *data, size_t len)
{
    struct stat st;
    if (lstat(path, &st) == 0 && !S_ISREG(st.st_mode))
        return -1;
    char tmp[CLI_OUT_PATH];
    FILE *f = open_beside(path, tmp);
    if (f == NULL)
        return errno;
    errno = 0;
    int failed = fwrite(data, 1, len, f) != len || fflush(f) != 0 || fsync(fileno(f)) != 0;
    int saved = errno; /* before fclose, which may set it again */
    failed |= fclose(f) != 0;
    if (!failed && rename(tmp, path) == 0)
        return 0;
    saved = saved ? saved : errno ? errno : EIO;
    unlink(tmp);
    return saved;
}
