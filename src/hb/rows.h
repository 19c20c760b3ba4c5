/* SPDX-License-Identifier: GPL-3.0-or-later */
/* rows.h — the driver's buffers sized by the rows of J (rows.c): allocated at create, grown
 * once by the element setters of two or three rows an element, and the views into them set
 * for the rows per element in force. */
#ifndef FRICREG_HB_ROWS_H
#define FRICREG_HB_ROWS_H

#include <stddef.h>

#include "hb_internal.h"

/* The buffers sized by the rows of J, for cap rows of me elements (at most cap/me rows each):
 * J's block (J [cap n], kt, mun [me], pc, ps [n]), Y, Z (with colw), G (with ql, dG, dql),
 * fq's block (fq, jq, A, R, rw, dy, qw, qt, tan, yp (two), yo, tn, dir, yl, qsol) and piv2,
 * Newton's LU pivots. All or none. */
struct fr_hb_rows {
    double *J, *Y, *Z, *G, *fq;
    int *piv2;
};

/* b allocated for cap rows of hb's elements: FRICREG_OK, or FRICREG_ENOMEM with b empty. */
int fr_hb_rows_alloc(const fricreg_hb *hb, size_t cap, struct fr_hb_rows *b);

/* Frees b and empties it (a second call does nothing). */
void fr_hb_rows_free(struct fr_hb_rows *b);

/* Installs b (room for cap rows) in place of hb's buffers, the excitation and the Jenkins
 * parameters carried over from them, if any. */
void fr_hb_rows_install(fricreg_hb *hb, size_t cap, struct fr_hb_rows *b);

/* The views into the buffers for rpe rows per element (m = rpe me rows, nq = m nc). */
void fr_hb_rows_set(fricreg_hb *hb, size_t rpe);

#endif
