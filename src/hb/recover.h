/* SPDX-License-Identifier: GPL-3.0-or-later */
/* recover.h — internal: the displacements' coefficients and their RMS from the element forces (recover.c). */
#ifndef FRICREG_HB_RECOVER_H
#define FRICREG_HB_RECOVER_H

#include "hb_internal.h"

/* The displacements' coefficients x[n nc] from the forces fq at the factored Ω. */
void fr_hb_recover(const fricreg_hb *hb, double *x);

/* Each dof's RMS over a period from the forces fq at the factored Ω, into rms[n]. */
void fr_hb_rms(const fricreg_hb *hb, double *rms);

/* As fr_hb_rms over the harmonics 0..harmonics (<= H) only, and each dof's amplitude of the
 * fundamental |X_1| into amplitude[n] (NULL: not wanted). */
void fr_hb_rms_upto(const fricreg_hb *hb, int harmonics, double *rms, double *amplitude);

/* Dof k's RMS over a period from the forces fq at the factored Ω. */
double fr_hb_rms_dof(const fricreg_hb *hb, size_t k);

#endif
