/* SPDX-License-Identifier: GPL-3.0-or-later */
/* monitor.h — internal: the monitor's hook at every Newton iterate, a solving call's start and end (monitor.c). */
#ifndef FRICREG_HB_MONITOR_H
#define FRICREG_HB_MONITOR_H

#include "hb_internal.h"

/* The monitor's hook (monitor.c), called at every Newton iterate of every solve: counts it,
 * enforces fricreg_hb_set_max_iterations's bound and calls the monitor with the continued
 * parameter's value and the iterate's residual relative to Newton's bound. FRICREG_OK, or
 * FRICREG_EWORK with hb->stopped set (message recorded, with fn): the call is over. */
int fr_hb_tick(fricreg_hb *hb, const char *fn, double parameter, double residual);

/* The monitor's parameter at the factored iterate of fr_hb_newton and the corrector: Ω or λ
 * (fr_hb_begin's report_omega). */
double fr_hb_parameter(const fricreg_hb *hb);

/* A solving call's start (busy, its count reset, the parameter the monitor sees) and end: the status it returns, FRICREG_EWORK
 * with the stop's message once stopped, whatever a fallback made of it. */
void fr_hb_begin(fricreg_hb *hb, int report_omega);
int fr_hb_end(fricreg_hb *hb, int status);

#endif
