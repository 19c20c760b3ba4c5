/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_law_table.c — white box: each row of the law table (src/law/law_table.c) says of its law
 * what the law's kernel does, probed through the public fricreg_law_eval: its name, whether it
 * reads f_eq, whether its force jumps, its slope at rest (the paper's (1)-(4): (1) and (2) jump
 * by 2 mun at v = 0, (2) reads f_eq there; (3) has slope mun/eps, (4) 2 mun/eps (4a) and reads
 * f_eq in its zone; Karnopp reads f_eq in |v| < eps and jumps at its edge; tanh'(0) = 1). */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg.h"
#include "law/law.h"

static const double EPS = 1e-3, MUN = 2.0;

static double force(int law, double v, double f_eq)
{
    double f = NAN;
    ck_assert_int_eq(fricreg_law_eval(law, v, f_eq, MUN, EPS, &f), FRICREG_OK);
    return f;
}

START_TEST(a_row_per_law)
{
    ck_assert_int_eq(FR_LAW_COUNT, FRICREG_LAW_QUINN);
    ck_assert_ptr_null(fricreg_law_name(FR_LAW_COUNT + 1));
    ck_assert_ptr_null(fricreg_law_name(0));
    for (int law = FRICREG_LAW_COULOMB; law <= FR_LAW_COUNT; law++) {
        ck_assert_str_eq(fricreg_law_name(law), fr_law_table[law].name);
        ck_assert_int_eq(fricreg_law_from_name(fr_law_table[law].name), law);
    }
}
END_TEST

/* Reads f_eq: some velocity (rest, inside the band, at its edge, outside) where f_eq = +-mun/2
 * give different forces. */
START_TEST(reads_feq_as_the_kernel)
{
    const double v[] = {0.0, 0.25 * EPS, -0.25 * EPS, 0.9 * EPS, 2.0 * EPS};
    for (int law = FRICREG_LAW_COULOMB; law <= FR_LAW_COUNT; law++) {
        int reads = 0;
        for (size_t k = 0; k < sizeof v / sizeof v[0]; k++)
            reads |= force(law, v[k], 0.5 * MUN) != force(law, v[k], -0.5 * MUN);
        ck_assert_msg(reads == fr_law_table[law].reads_feq, "%s: reads f_eq %d, its row says %d",
                      fr_law_table[law].name, reads, fr_law_table[law].reads_feq);
    }
}
END_TEST

/* Jumps: across rest or the band's edges (f_eq = 0) the force changes by more than mun/2 over
 * 2e-9 eps; a continuous law of slope at most 2 mun/eps changes by 4e-9 mun there. */
START_TEST(jumps_as_the_kernel)
{
    const double at[] = {0.0, EPS, -EPS}, d = 1e-9 * EPS;
    for (int law = FRICREG_LAW_COULOMB; law <= FR_LAW_COUNT; law++) {
        int jumps = 0;
        for (size_t k = 0; k < sizeof at / sizeof at[0]; k++)
            jumps |= fabs(force(law, at[k] + d, 0.0) - force(law, at[k] - d, 0.0)) > 0.5 * MUN;
        ck_assert_msg(jumps == fr_law_table[law].jumps, "%s: jumps %d, its row says %d",
                      fr_law_table[law].name, jumps, fr_law_table[law].jumps);
    }
}
END_TEST

/* The slope at rest, -df/dv by a one-sided difference just above v = 0 (f_eq = 0), in units of
 * mun/eps: 2 for (4), 1 for (3) and tanh, 0 for the laws that hold their force there. */
START_TEST(slope_at_rest_as_the_kernel)
{
    const double d = 1e-6 * EPS;
    for (int law = FRICREG_LAW_COULOMB; law <= FR_LAW_COUNT; law++) {
        double slope = -(force(law, 2.0 * d, 0.0) - force(law, d, 0.0)) / d * EPS / MUN;
        ck_assert_msg(fabs(slope - fr_law_table[law].slope_at_rest) <= 1e-6,
                      "%s: slope at rest %.9g mun/eps, its row says %g", fr_law_table[law].name,
                      slope, fr_law_table[law].slope_at_rest);
    }
}
END_TEST

int main(void)
{
    Suite *suite = suite_create("law_table");
    TCase *tc = tcase_create("rows");
    tcase_add_test(tc, a_row_per_law);
    tcase_add_test(tc, reads_feq_as_the_kernel);
    tcase_add_test(tc, jumps_as_the_kernel);
    tcase_add_test(tc, slope_at_rest_as_the_kernel);
    suite_add_tcase(suite, tc);
    SRunner *runner = srunner_create(suite);
    srunner_run_all(runner, CK_NORMAL);
    int failed = srunner_ntests_failed(runner);
    srunner_free(runner);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
