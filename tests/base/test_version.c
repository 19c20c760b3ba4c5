/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_version.c — the version has one source, project(VERSION) in CMakeLists.txt: the
 * header's macros, the library's functions and CMake's numbers (passed in by the build) agree. */
#include <check.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg.h"

START_TEST(macros_match_cmake)
{
    ck_assert_int_eq(FRICREG_VERSION_MAJOR, FRICREG_EXPECTED_MAJOR);
    ck_assert_int_eq(FRICREG_VERSION_MINOR, FRICREG_EXPECTED_MINOR);
    ck_assert_int_eq(FRICREG_VERSION_PATCH, FRICREG_EXPECTED_PATCH);
    ck_assert_str_eq(FRICREG_VERSION_STRING, FRICREG_EXPECTED_VERSION);
    ck_assert_int_eq(FRICREG_VERSION_NUMBER, FRICREG_EXPECTED_MAJOR * 10000 +
                                                 FRICREG_EXPECTED_MINOR * 100 +
                                                 FRICREG_EXPECTED_PATCH);
}
END_TEST

START_TEST(library_matches_cmake)
{
    ck_assert_str_eq(fricreg_version(), FRICREG_EXPECTED_VERSION);
    ck_assert_int_eq(fricreg_version_number(), FRICREG_VERSION_NUMBER);
}
END_TEST

int main(void)
{
    Suite *suite = suite_create("version");
    TCase *tc = tcase_create("version");
    tcase_add_test(tc, macros_match_cmake);
    tcase_add_test(tc, library_matches_cmake);
    suite_add_tcase(suite, tc);
    SRunner *runner = srunner_create(suite);
    srunner_run_all(runner, CK_NORMAL);
    int failed = srunner_ntests_failed(runner);
    srunner_free(runner);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
