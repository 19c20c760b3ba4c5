/* SPDX-License-Identifier: GPL-3.0-or-later */
/* probe_unknown_type.h — a prototype with a C type gen_interfaces.cmake has no Fortran
 * spelling for (float): the generator must stop, naming the function and the parameter. */
FRICREG_API int fricreg_probe_scale(double x, float factor, double *y);
