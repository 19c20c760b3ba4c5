/* SPDX-License-Identifier: GPL-3.0-or-later */
/* model.h — what the fit asks of a model (fricreg_fit.h): its parameters' names and ranges, a
 * first start, and the backbone at measured levels with the total derivatives in its np
 * parameters. Three models: the modal Iwan's closed forms (modal_iwan_model.c), a
 * harmonic-balance driver's nonlinear mode (hb_model.c, hb_levels.c) and its quasi-static modal
 * analysis (hb_model.c, qsma_levels.c). */
#ifndef FRICREG_FIT_MODEL_H
#define FRICREG_FIT_MODEL_H

#include <stddef.h>

#include "fit_internal.h"

/* The model at n levels: row i of dfreq, dzeta (n x np, row major) is level i's. */
struct fr_fit_levels {
    double *freq_hz, *zeta, *modal, *dfreq, *dzeta;
};

#define FR_FIT_REACHED ((size_t)-1) /* no level out of reach */

struct fr_fit_model {
    /* Parameter j's name as messages write it. */
    const char *(*name)(const fricreg_fit *fit, int j);
    /* Parameter j's own lower limit. */
    double (*floor)(int j);
    /* 1 if v is a value parameter j takes, else 0. */
    int (*in_range)(int j, double v);
    /* The first start of every parameter p[np] where the caller gave none. */
    void (*start)(const fricreg_fit *fit, double p[]);
    /* The model at the amplitudes amp[n] of kind at p[np] into out. guess[n]: in, each
     * level's modal amplitude to start from or NaN; out, the ones found. Returns FRICREG_OK;
     * else a status, why in fit->reason, and *bad the level beyond the backbone's reach, or
     * FR_FIT_REACHED where the model cannot be evaluated for another reason (a value the
     * driver refuses, a call from its monitor, no memory). Counts its backbone marches in
     * fit->marches. */
    int (*eval)(fricreg_fit *fit, const double p[], int kind, size_t n, const double amp[],
                double guess[], const struct fr_fit_levels *out, size_t *bad);
};

extern const struct fr_fit_model fr_fit_modal_iwan_model;
extern const struct fr_fit_model fr_fit_hb_model;
extern const struct fr_fit_model fr_fit_qsma_model; /* the driver's QSMA (qsma_levels.c) */

/* out's arrays for n levels and *guess[n] (NaN each), n (4 + 2 np) doubles in one block, the
 * block returned for free (NULL out of memory: nothing set). */
double *fr_fit_levels_alloc(size_t n, size_t np, struct fr_fit_levels *out, double **guess);

#endif
