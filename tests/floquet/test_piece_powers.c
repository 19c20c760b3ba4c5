/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_piece_powers.c — Check suite for the exact monodromy's kept piece matrices (white box:
 * src/floquet/piece_powers.c, and the half-wave test of src/floquet/switches.c, on the static
 * library).
 *
 * Where the numbers come from: the kept powers of a matrix are fr_hb_expm_powers' own (the same
 * calls on a copy, bit for bit); an entry is found by the matrix's content, so one changed bit
 * is another entry; the capacity is the byte budget's quotient; the least recently used entry
 * is the one replaced. The half-wave schedules are built by hand: a symmetric one, and the same
 * with one change each (an angle 1e-9 off, another slider, another mode, another reset, an odd
 * count, a slider with a normal law). */
#include <check.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_hb.h"
#include "floquet/expm.h"
#include "floquet/piece_powers.h"
#include "floquet/switches.h"
#include "joint/aft_slips.h"

enum { P = 3 };

/* A dense test matrix: a[i] = base + i / 7. */
static void matrix(double *a, double base)
{
    for (int i = 0; i < P * P; i++)
        a[i] = base + i / 7.0;
}

START_TEST(test_found_by_content)
{
    struct fr_hb_pieces c;
    double a[P * P], b[P * P], pow[5 * P * P];
    ck_assert_int_eq(fr_hb_pieces_init(&c, P), 0);
    ck_assert_uint_eq(c.cap, FR_HB_PIECES_MAX);
    matrix(a, 0.5);
    const struct fr_hb_piece *first = fr_hb_pieces_find(&c, a, P);
    ck_assert_ptr_nonnull(first);
    double nu = fr_hb_expm_powers(a, P, pow);
    ck_assert(first->nu == nu);
    ck_assert_int_eq(memcmp(first->pow, pow, sizeof pow), 0);
    ck_assert_ptr_eq(fr_hb_pieces_find(&c, a, P), first); /* found, not made again */
    ck_assert_uint_eq(c.count, 1);
    memcpy(b, a, sizeof a);
    b[4] = nextafter(b[4], 2.0); /* one bit: another matrix */
    const struct fr_hb_piece *second = fr_hb_pieces_find(&c, b, P);
    ck_assert_ptr_ne(second, first);
    ck_assert_uint_eq(c.count, 2);
    const struct fr_hb_piece *small = fr_hb_pieces_find(&c, a, 2); /* order 2: another entry */
    ck_assert_ptr_nonnull(small);
    ck_assert_ptr_ne(small, first);
    ck_assert_uint_eq(small->p, 2);
    ck_assert_uint_eq(c.count, 3);
    ck_assert_ptr_null(fr_hb_pieces_find(&c, a, P + 1)); /* beyond pmax: none kept */
    fr_hb_pieces_free(&c);
    fr_hb_pieces_free(&c); /* a second call does nothing */
}
END_TEST

/* Full: the least recently used entry gives way, the others stay. */
START_TEST(test_least_recently_used_replaced)
{
    struct fr_hb_pieces c;
    double a[FR_HB_PIECES_MAX + 1][P * P];
    ck_assert_int_eq(fr_hb_pieces_init(&c, P), 0);
    for (int k = 0; k <= FR_HB_PIECES_MAX; k++)
        matrix(a[k], k);
    const struct fr_hb_piece *zero = fr_hb_pieces_find(&c, a[0], P);
    for (int k = 1; k < FR_HB_PIECES_MAX; k++)
        (void)fr_hb_pieces_find(&c, a[k], P);
    ck_assert_ptr_eq(fr_hb_pieces_find(&c, a[0], P), zero); /* 0 used again: 1 is the oldest */
    const struct fr_hb_piece *last = fr_hb_pieces_find(&c, a[FR_HB_PIECES_MAX], P);
    ck_assert_uint_eq(c.count, FR_HB_PIECES_MAX);
    ck_assert_ptr_eq(fr_hb_pieces_find(&c, a[0], P), zero);
    ck_assert_ptr_eq(fr_hb_pieces_find(&c, a[FR_HB_PIECES_MAX], P), last);
    ck_assert(zero->A[0] == 0.0 && last->A[0] == FR_HB_PIECES_MAX);
    for (size_t k = 0; k < c.count; k++) /* 1 gave way, 2 .. 15 stay */
        ck_assert(c.piece[k].A[0] != 1.0);
    for (int k = 2; k < FR_HB_PIECES_MAX; k++) {
        const struct fr_hb_piece *e = fr_hb_pieces_find(&c, a[k], P);
        ck_assert(e->A[0] == k);
    }
    ck_assert_uint_eq(c.count, FR_HB_PIECES_MAX);
    fr_hb_pieces_free(&c);
}
END_TEST

/* The budget: a large order keeps fewer; one beyond it keeps none; a matrix whose powers
 * overflow is not kept. */
START_TEST(test_budget_and_overflow)
{
    struct fr_hb_pieces c;
    size_t p = 500; /* 12 MB an entry: 2 in the 32 MiB */
    ck_assert_int_eq(fr_hb_pieces_init(&c, p), 0);
    ck_assert_uint_eq(c.cap, 2);
    fr_hb_pieces_free(&c);
    ck_assert_int_eq(fr_hb_pieces_init(&c, 2000), 0);
    ck_assert_uint_eq(c.cap, 0);
    double a[P * P];
    matrix(a, 1.0);
    ck_assert_ptr_null(fr_hb_pieces_find(&c, a, P));
    fr_hb_pieces_free(&c);
    ck_assert_int_eq(fr_hb_pieces_init(&c, P), 0);
    matrix(a, 1e308); /* ν overflows */
    ck_assert_ptr_null(fr_hb_pieces_find(&c, a, P));
    a[0] = NAN;
    ck_assert_ptr_null(fr_hb_pieces_find(&c, a, P));
    fr_hb_pieces_free(&c);
}
END_TEST

/* ---- The half-wave test of a schedule ----------------------------------------------------- */

/* A model of one Jenkins element (rpe 1) with its schedule's arrays. */
static fricreg_hb *jenkins_model(struct fr_hb_schedule *sc)
{
    const double M[4] = {1, 0, 0, 1}, K[4] = {2, -1, -1, 2}, J[4] = {1, 0, 0, 1},
                 kt[2] = {3.0, 3.0}, mun[2] = {0.4, 0.4};
    fricreg_hb *hb = NULL;
    ck_assert_int_eq(fricreg_hb_create(2, 2, 3, &hb), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_mass(hb, 2, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_stiffness(hb, 2, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_hb_set_elements(hb, 2, 2, J, kt, mun), FRICREG_OK);
    ck_assert_int_eq(fr_hb_schedule_alloc(hb, sc), FRICREG_OK);
    return hb;
}

/* Two sliders, each slipping from an onset to a stop in either half: switches at a, a + 0.4
 * (slider 0), b, b + 0.2 (slider 1), and the same half a period on, sorted. */
static void symmetric(struct fr_hb_schedule *sc)
{
    const double half = 0.5 * FR_TWO_PI, at[4] = {0.3, 0.5, 0.7, 0.9};
    const size_t who[4] = {0, 1, 0, 1};
    const int mode[4] = {FR_AFT_SLIP, FR_AFT_SLIP, FR_AFT_STICK, FR_AFT_STICK},
              reset[4] = {FR_AFT_ONSET, FR_AFT_ONSET, FR_AFT_KEEP, FR_AFT_KEEP};
    sc->S = 2;
    sc->count = 8;
    sc->c[0] = sc->c[1] = 0.0;
    for (size_t i = 0; i < 8; i++) {
        size_t k = i % 4;
        sc->sw[i] = (struct fr_hb_switch){.theta = at[k] + (i < 4 ? 0.0 : half),
                                          .index = who[k],
                                          .seq = i,
                                          .mode = mode[k],
                                          .dir = i < 4 ? 1 : -1,
                                          .reset = reset[k]};
    }
}

START_TEST(test_half_wave_schedules)
{
    struct fr_hb_schedule sc;
    fricreg_hb *hb = jenkins_model(&sc);
    symmetric(&sc);
    ck_assert_int_eq(fr_hb_schedule_half_wave(hb, &sc), 1);
    sc.sw[6].theta += 0.5 * FR_HB_HALF_WAVE_TOL; /* within the tolerance */
    ck_assert_int_eq(fr_hb_schedule_half_wave(hb, &sc), 1);
    sc.sw[6].theta += 1e-9; /* an asymmetric orbit's */
    ck_assert_int_eq(fr_hb_schedule_half_wave(hb, &sc), 0);
    symmetric(&sc);
    sc.sw[5].index = 0; /* another slider */
    ck_assert_int_eq(fr_hb_schedule_half_wave(hb, &sc), 0);
    symmetric(&sc);
    sc.sw[7].mode = FR_AFT_SLIP; /* another mode */
    ck_assert_int_eq(fr_hb_schedule_half_wave(hb, &sc), 0);
    symmetric(&sc);
    sc.sw[4].reset = FR_AFT_KEEP; /* another reset */
    ck_assert_int_eq(fr_hb_schedule_half_wave(hb, &sc), 0);
    symmetric(&sc);
    sc.count = 7; /* an odd count */
    ck_assert_int_eq(fr_hb_schedule_half_wave(hb, &sc), 0);
    symmetric(&sc);
    sc.c[1] = 0.5; /* a normal law's slip depends on its direction */
    ck_assert_int_eq(fr_hb_schedule_half_wave(hb, &sc), 0);
    symmetric(&sc);
    sc.count = 0; /* nothing switches */
    ck_assert_int_eq(fr_hb_schedule_half_wave(hb, &sc), 0);
    fr_hb_schedule_free(&sc);
    fricreg_hb_free(hb);
}
END_TEST

int main(void)
{
    Suite *s = suite_create("piece_powers");
    TCase *tc = tcase_create("core");
    tcase_add_test(tc, test_found_by_content);
    tcase_add_test(tc, test_least_recently_used_replaced);
    tcase_add_test(tc, test_budget_and_overflow);
    tcase_add_test(tc, test_half_wave_schedules);
    suite_add_tcase(s, tc);
    SRunner *sr = srunner_create(s);
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? 0 : 1;
}
