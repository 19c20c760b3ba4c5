/* SPDX-License-Identifier: GPL-3.0-or-later */
/* laws.h — fricreg.h's friction laws (fricreg_law_eval for the tests, which compare the
 * batch with it), in the syntax of cffi's cdef (no macros, no includes;
 * python/build_ffi.py). */
const char *fricreg_law_name(int law);
int fricreg_law_from_name(const char *name);
int fricreg_law_eval(int law, double v, double f_eq, double mun, double eps, double *f);
int fricreg_law_eval_batch(int law, double eps, size_t m, const double v[], const double f_eq[],
                           const double mun[], double f[]);
