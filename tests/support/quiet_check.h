/* SPDX-License-Identifier: GPL-3.0-or-later */
/* Assertions for loops that run 10^4 times or more.
 *
 * Check records the place of every assertion that passes (_mark_point: a message to the runner
 * through a temporary file), some microseconds each, most of it in the kernel. The quick tier's
 * C tests made 28 million such records, nearly all of them in loops over time steps and sample
 * points, and they took more CPU time than the tests' own work (test_hb: 9.7 s with them, 2.0 s
 * without). These assert only when the condition fails, with Check's own message then, so a
 * passing loop costs a comparison. Outside hot loops, use Check's assertions as usual. */
#ifndef FRICREG_TESTS_QUIET_CHECK_H
#define FRICREG_TESTS_QUIET_CHECK_H

#include <check.h>

#include "fricreg.h"

/* ck_assert_msg(expr, ...), recorded only on failure (expr is evaluated again then). */
#define QUIET_ASSERT(expr, ...)               \
    do {                                      \
        if (!(expr))                          \
            ck_assert_msg(expr, __VA_ARGS__); \
    } while (0)

/* ck_assert(expr), recorded only on failure. */
#define QUIET_CHECK(expr)    \
    do {                     \
        if (!(expr))         \
            ck_assert(expr); \
    } while (0)

/* ck_assert_int_eq(call, FRICREG_OK) with the call and its status named, recorded only on
 * failure. */
#define QUIET_OK(call)                                                \
    do {                                                              \
        int quiet_status_ = (call);                                   \
        if (quiet_status_ != FRICREG_OK)                              \
            ck_abort_msg("%s returned %d (%s)", #call, quiet_status_, \
                         fricreg_strerror(quiet_status_));            \
    } while (0)

#endif
