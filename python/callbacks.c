/* SPDX-License-Identifier: GPL-3.0-or-later */
/* callbacks.c — the binding's callbacks that run in C between calls into Python, compiled
 * into the extension module (build_ffi.py appends it to the module's source; cdef/callbacks.h
 * declares it to Python). A call into Python takes the GIL back and costs microseconds, as
 * much as a small model's step: the structure's rows are copied here, and Python is asked
 * about Ctrl-C at most once per interval of wall time. */
#include <math.h>
#include <string.h>
#include <time.h>

/* A driver's watch: Python's monitor runs once per interval (s) of wall time, next the time
 * of its next turn. */
struct fricreg_py_watch {
    double interval, next;
};

/* The rows of a structure's run (structure_result.Recorder): step times[capacity], u and
 * v[capacity nout] at the output dofs (dofs[nout]; NULL: all, nout = ndof), the forces
 * f[capacity m]; count rows recorded. Python owns the arrays, grows them and checks for
 * Ctrl-C through handle. */
struct fricreg_py_rows {
    double dt, t_end, interval, next;
    int64_t every;
    size_t count, capacity, nout, m;
    const int64_t *dofs;
    double *times, *u, *v, *f;
    void *handle;
};

/* cffi's extern "Python" functions (the cdef files), defined further down the module. */
static int fricreg_py_hb_monitor(void *user, int64_t iterations, double parameter, double residual);
static int fricreg_py_rows_grow(void *handle);
static int fricreg_py_rows_check(void *handle);

static double wall_seconds(void)
{
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)now.tv_sec + 1e-9 * (double)now.tv_nsec;
}

/* Whether Python's turn has come (interval 0: at every call). */
static int check_due(double interval, double *next)
{
    if (interval <= 0.0)
        return 1;
    double now = wall_seconds();
    if (now < *next)
        return 0;
    *next = now + interval;
    return 1;
}

/* fricreg_hb's monitor: Python's (Ctrl-C) once per interval. */
static int fricreg_py_hb_watch(void *user, int64_t iterations, double parameter, double residual)
{
    struct fricreg_py_watch *w = user;
    if (!check_due(w->interval, &w->next))
        return 0;
    return fricreg_py_hb_monitor(NULL, iterations, parameter, residual);
}

/* The row of step time t is due: the first, the last and every every-th k dt (the CLI's
 * row_due). */
static int fricreg_py_rows_due(const struct fricreg_py_rows *r, double t)
{
    if (r->every <= 1 || r->count == 0 || !(t < r->t_end))
        return 1;
    return (int64_t)floor(t / r->dt + 0.5) % r->every == 0;
}

/* The row of step time t appended, the arrays grown by Python when full; nonzero if that
 * failed (its exception kept by Python). */
static int fricreg_py_rows_append(struct fricreg_py_rows *r, double t, const double u[],
                                  const double v[], const double f[])
{
    if (r->count == r->capacity && fricreg_py_rows_grow(r->handle) != 0)
        return 1;
    size_t k = r->count, n = r->nout;
    r->times[k] = t;
    if (r->dofs == NULL && n > 0) {
        memcpy(r->u + k * n, u, n * sizeof(double));
        memcpy(r->v + k * n, v, n * sizeof(double));
    } else {
        for (size_t j = 0; j < n; j++) {
            r->u[k * n + j] = u[r->dofs[j]];
            r->v[k * n + j] = v[r->dofs[j]];
        }
    }
    if (r->m > 0) /* none: f's array may have no storage */
        memcpy(r->f + k * r->m, f, r->m * sizeof(double));
    r->count = k + 1;
    return 0;
}

/* fricreg_structure_run's observer: the row where due, then Python's check once per interval;
 * nonzero stops the run. ndof and m are the structure's, which the rows were made for. */
static int fricreg_py_rows_observer(void *user, double t, size_t ndof, const double u[],
                                    const double v[], size_t m, const double f[])
{
    struct fricreg_py_rows *r = user;
    (void)ndof, (void)m;
    if (fricreg_py_rows_due(r, t) && fricreg_py_rows_append(r, t, u, v, f) != 0)
        return 1;
    return check_due(r->interval, &r->next) ? fricreg_py_rows_check(r->handle) : 0;
}
