/* SPDX-License-Identifier: GPL-3.0-or-later */
/* rows.h — the driver's buffers sized by the rows of J (rows.c): allocated at create, grown
 * by the elements of more rows (element_store.c), and the views into them set
 * for the rows per element in force. */
#ifndef FRICREG_HB_ROWS_H
#define FRICREG_HB_ROWS_H

#include <stddef.h>

#include "hb_internal.h"

/* The buffers sized by the rows of J, for cap rows and sq units of nc² of the elements'
 * Jacobian blocks (sum of their rows²): J's block (J [cap n], pc, ps [n]), Y, Z (with colw), G (with ql, dG, dql),
 * fq's block (fq, jq, A, R, rw, dy, qw, qt, tan, yp (two), yo, tn, dir, yl, qsol) and piv2,
 * Newton's LU pivots. All or none. */
struct fr_hb_rows {
    double *J, *Y, *Z, *G, *fq;
    int *piv2;
};

/* b allocated for cap rows and sq units of Jacobian blocks: FRICREG_OK, or FRICREG_ENOMEM with
 * b empty. */
int fr_hb_rows_alloc(const fricreg_hb *hb, size_t cap, size_t sq, struct fr_hb_rows *b);

/* Frees b and empties it (a second call does nothing). */
void fr_hb_rows_free(struct fr_hb_rows *b);

/* Installs b (room for cap rows, sq units of Jacobian blocks) in place of hb's buffers, J's
 * rows held and the excitation carried over from them, if any. */
void fr_hb_rows_install(fricreg_hb *hb, size_t cap, size_t sq, struct fr_hb_rows *b);

/* The views into the buffers for the rows of the elements held (m = erow[count] rows, nq =
 * m nc). */
void fr_hb_rows_set(fricreg_hb *hb);

#endif
