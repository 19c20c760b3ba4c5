/* SPDX-License-Identifier: GPL-3.0-or-later */
/* probe_case.h — two parameters whose names differ only in case, one dummy to Fortran: the
 * generator must stop, naming them. */
FRICREG_API int fricreg_probe_scale(double W, double w);
