/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb_rod.h — a test and benchmark model for the harmonic-balance driver (fricreg_hb.h): a
 * fixed-free rod of unit length, stiffness and mass per length, in n linear elements
 * (consistent mass, a tip mass 0.2 at the free end), so that its low frequencies do not depend
 * on n (the first near 1.3 rad/s); damping a0 M + a1 K plus a dashpot between the two ends
 * (an entry outside the band: D_h's pattern is the union of C's with M's and K's); three
 * Jenkins elements (the free end to ground, the middle to ground, and between the dofs at a
 * quarter and three quarters); the free end excited. Built as compressed columns, whole;
 * hb_rod_csc gives them in each of the setters' forms, hb_rod_dense densifies (small n). */
#ifndef FRICREG_HB_ROD_H
#define FRICREG_HB_ROD_H

#include <stddef.h>
#include <stdint.h>

#include "fricreg_hb.h"

#define HB_ROD_M 3 /* elements */

enum hb_rod_form { HB_ROD_FULL, HB_ROD_UPPER, HB_ROD_LOWER };

struct hb_rod {
    size_t n, m;
    int64_t *p[3], *i[3]; /* M, C, K whole, zero-based, rows sorted */
    double *x[3];
    double *J, kt[HB_ROD_M], mun[HB_ROD_M], *pc, *ps;
};

/* The rod of n >= 8 dofs; 0, or -1 if out of memory (then nothing to free). */
int hb_rod_build(struct hb_rod *r, size_t n);
void hb_rod_free(struct hb_rod *r);

/* Matrix which (0 M, 1 C, 2 K) in a setter's form, into p[n + 1], i[], x[] (room for its
 * whole entries plus one: the whole form gives the first diagonal entry in two halves, a
 * duplicate); one_based adds 1 to p and i. */
void hb_rod_csc(const struct hb_rod *r, int which, enum hb_rod_form form, int one_based, int64_t *p,
                int64_t *i, double *x);

/* Matrix which, dense row-major, into A[n n]. */
void hb_rod_dense(const struct hb_rod *r, int which, double *A);

/* Sets M, C, K by the _csc setters in form (or, dense, by the dense setters), the elements and
 * the excitation; FRICREG_OK or the first failure's status. */
int hb_rod_set(fricreg_hb *hb, const struct hb_rod *r, int dense, enum hb_rod_form form,
               int one_based);

#endif
