/* SPDX-License-Identifier: GPL-3.0-or-later */
/* probe_variadic.h — a variadic prototype, which Fortran cannot call: the generator must stop. */
FRICREG_API int fricreg_probe_printf(const char *format, ...);
