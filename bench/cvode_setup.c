/* SPDX-License-Identifier: GPL-3.0-or-later */
/* cvode_setup.c — CVODE set-up and tear-down for the references of the belt and the 2-D
 * oscillator (cvode_setup.h), the same choices as event_driven.c: Adams with fixed-point
 * iteration (no Jacobian), or BDF with a dense difference-quotient Newton solver; abstol =
 * reltol; CVODE's messages kept off stderr. */
#include <string.h>

#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>
#include <sunnonlinsol/sunnonlinsol_fixedpoint.h>

#include "cvode_setup.h"
#include "event_driven.h"

#if SUNDIALS_VERSION_MAJOR >= 7
#define CV_COMM_NULL SUN_COMM_NULL
#else
#define CV_COMM_NULL NULL
static void quiet(int code, const char *module, const char *function, char *msg, void *user)
{
    (void)code, (void)module, (void)function, (void)msg, (void)user;
}
#endif

int cv_open(struct cv_handle *h, int method, size_t dim, CVRhsFn rhs, int n_roots, CVRootFn roots,
            void *user, double rtol)
{
    memset(h, 0, sizeof *h);
    if (SUNContext_Create(CV_COMM_NULL, &h->ctx) != 0)
        return -1;
    h->y = N_VNew_Serial((sunindextype)dim, h->ctx);
    h->mem = CVodeCreate(method == ED_BDF ? CV_BDF : CV_ADAMS, h->ctx);
    if (!h->y || !h->mem) {
        cv_close(h);
        return -1;
    }
    N_VConst(0.0, h->y);
    int flag = CVodeInit(h->mem, rhs, 0.0, h->y);
#if SUNDIALS_VERSION_MAJOR < 7
    flag |= CVodeSetErrHandlerFn(h->mem, quiet, NULL);
#endif
    flag |= CVodeSetUserData(h->mem, user);
    flag |= CVodeSStolerances(h->mem, rtol, rtol);
    flag |= CVodeSetMaxNumSteps(h->mem, 100000000L);
    flag |= CVodeRootInit(h->mem, n_roots, roots);
    if (method == ED_BDF) {
        h->A = SUNDenseMatrix((sunindextype)dim, (sunindextype)dim, h->ctx);
        h->LS = h->A ? SUNLinSol_Dense(h->y, h->A, h->ctx) : NULL;
        flag |= h->LS ? CVodeSetLinearSolver(h->mem, h->LS, h->A) : -1;
    } else {
        h->NLS = SUNNonlinSol_FixedPoint(h->y, 0, h->ctx);
        flag |= h->NLS ? CVodeSetNonlinearSolver(h->mem, h->NLS) : -1;
    }
    if (flag != 0) {
        cv_close(h);
        return -1;
    }
    return 0;
}

void cv_close(struct cv_handle *h)
{
    if (h->mem)
        CVodeFree(&h->mem);
    SUNNonlinSolFree(h->NLS);
    SUNLinSolFree(h->LS);
    SUNMatDestroy(h->A);
    if (h->y)
        N_VDestroy(h->y);
    if (h->ctx)
        SUNContext_Free(&h->ctx);
    memset(h, 0, sizeof *h);
}

double cv_steps(void *mem)
{
    long n = 0;
    CVodeGetNumSteps(mem, &n);
    return (double)n;
}
