/* SPDX-License-Identifier: GPL-3.0-or-later */
/* callbacks.h — cffi declarations of the binding's own C callbacks (python/callbacks.c, which
 * says why they are C): a driver's watch on the HB monitor, the rows a structure's observer
 * records, and the calls into Python they make. */
struct fricreg_py_watch {
    double interval, next;
};
int fricreg_py_hb_watch(void *user, int64_t iterations, double parameter, double residual);

struct fricreg_py_rows {
    double dt, t_end, interval, next;
    int64_t every;
    size_t count, capacity, nout, m;
    const int64_t *dofs;
    double *times, *u, *v, *f;
    void *handle;
};
int fricreg_py_rows_due(const struct fricreg_py_rows *r, double t);
int fricreg_py_rows_append(struct fricreg_py_rows *r, double t, const double u[], const double v[],
                           const double f[]);
int fricreg_py_rows_observer(void *user, double t, size_t ndof, const double u[], const double v[],
                             size_t m, const double f[]);
extern "Python" int fricreg_py_rows_grow(void *handle);
extern "Python" int fricreg_py_rows_check(void *handle);
