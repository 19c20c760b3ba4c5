/* SPDX-License-Identifier: GPL-3.0-or-later */
/* replay.c — runs a fuzz target on each file of its corpus, with any compiler (no libFuzzer):
 * `fuzz_replay_<target> DIR|FILE ...`. Each file is one call of LLVMFuzzerTestOneInput, whose
 * contract checks abort on a violation, failing the ctest entry. Exits 1 if a directory or file
 * cannot be read or no file was found, so an empty or missing corpus cannot pass. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static int replay_file(const char *path)
{
    FILE *in = fopen(path, "rb");
    if (in == NULL) {
        fprintf(stderr, "replay: cannot open %s\n", path);
        return 1;
    }
    size_t cap = 4096, size = 0, got;
    uint8_t *data = malloc(cap);
    while (data != NULL && (got = fread(data + size, 1, cap - size, in)) > 0) {
        size += got;
        if (size == cap) {
            uint8_t *more = realloc(data, cap *= 2);
            if (more == NULL)
                free(data);
            data = more;
        }
    }
    int failed = data == NULL || ferror(in);
    fclose(in);
    if (failed) {
        fprintf(stderr, "replay: cannot read %s\n", path);
        free(data);
        return 1;
    }
    LLVMFuzzerTestOneInput(data, size);
    free(data);
    return 0;
}

static int replay_dir(const char *dir, long *count)
{
    DIR *d = opendir(dir);
    if (d == NULL) {
        fprintf(stderr, "replay: cannot open directory %s\n", dir);
        return 1;
    }
    int failed = 0;
    struct dirent *e;
    char path[4096];
    while ((e = readdir(d)) != NULL && !failed) {
        if (e->d_name[0] == '.')
            continue;
        snprintf(path, sizeof path, "%s/%s", dir, e->d_name);
        failed = replay_file(path);
        ++*count;
    }
    closedir(d);
    return failed;
}

int main(int argc, char **argv)
{
    long count = 0;
    for (int k = 1; k < argc; k++) {
        struct stat st;
        int failed = stat(argv[k], &st) != 0
                         ? (fprintf(stderr, "replay: no such file %s\n", argv[k]), 1)
                     : S_ISDIR(st.st_mode) ? replay_dir(argv[k], &count)
                                           : (++count, replay_file(argv[k]));
        if (failed)
            return 1;
    }
    printf("replayed %ld inputs\n", count);
    return count > 0 ? 0 : 1;
}
