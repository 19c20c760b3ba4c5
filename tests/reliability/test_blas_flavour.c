/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_blas_flavour.c — the BLAS that fricreg loads can be called from several threads at once,
 * which fricreg's objects-per-thread promise needs (docs/install.md, "BLAS and LAPACK"). The
 * reference BLAS can; OpenBLAS built without threads and without USE_LOCKING cannot: Debian's
 * libopenblas0-serial gave 11 and 4 wrong results of 320 in 2 of 9 runs of 8 threads each
 * computing a 300 x 300 dgemm and dpotrf, where libopenblas0-pthread gave none. So an OpenBLAS
 * that reports no threading (openblas_get_parallel() == 0) fails here, naming the package to
 * install. A serial OpenBLAS built with USE_LOCKING=1 is safe too, and this test cannot tell
 * it from Debian's: it fails there as well, and says so. */
#include <dlfcn.h>
#include <stdio.h>

#include "fricreg.h"

int main(void)
{
    printf("fricreg %s\n", fricreg_version()); /* the library and its LAPACK are loaded */
    void *loaded = dlopen(NULL, RTLD_LAZY);
    if (!loaded) {
        printf("FAIL: dlopen(NULL) failed: %s\n", dlerror());
        return 1;
    }
    int (*parallel)(void) = NULL;
    *(void **)&parallel = dlsym(loaded, "openblas_get_parallel");
    char *(*config)(void) = NULL;
    *(void **)&config = dlsym(loaded, "openblas_get_config");
    int status = 0;
    if (!parallel) {
        printf("the BLAS is not OpenBLAS (no openblas_get_parallel): safe from threads\n");
    } else if (parallel() == 0) {
        printf("FAIL: OpenBLAS without threads (%s) is not safe to call from two threads at "
               "once unless built with USE_LOCKING=1, and Debian's libopenblas0-serial is not: "
               "install libopenblas0-pthread (docs/install.md)\n",
               config ? config() : "no config");
        status = 1;
    } else {
        printf("OpenBLAS with threads (%s, openblas_get_parallel() = %d): safe from threads\n",
               config ? config() : "no config", parallel());
    }
    dlclose(loaded);
    return status;
}
