/* SPDX-License-Identifier: GPL-3.0-or-later */
/* consumer.c — a user's program built against an installed fricreg only (tests/install.sh).
 * Exits 0 if the installed headers and library agree and give law (4)'s force balance. */
#include <stdio.h>

#include <fricreg.h>

int main(void)
{
    double f = 0.0;
    /* (4) at rest equals (2): f = mun sat(f_eq/mun) = 0.2385 exactly representable input */
    int status = fricreg_law_eval(FRICREG_LAW_QUINN, 0.0, 0.2385, 0.731, 0.02, &f);
    if (status != FRICREG_OK || f != 0.2385) {
        fprintf(stderr, "consumer: law (4) gave %.17g (%s)\n", f, fricreg_strerror(status));
        return 1;
    }
    if (fricreg_version_number() != FRICREG_VERSION_NUMBER) {
        fprintf(stderr, "consumer: header %s, library %s\n", FRICREG_VERSION_STRING,
                fricreg_version());
        return 1;
    }
    printf("consumer: fricreg %s OK\n", fricreg_version());
    return 0;
}
