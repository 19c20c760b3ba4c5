/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element_energy.c — fricreg_element_energy: the energies of one increment of an element that
 * a host books (Abaqus FRIC's SFD and SED, ANSYS USERFRIC's frictional and elastic energy):
 * the sliders' dissipation and the springs' stored energy, from the kind's own eval, so the
 * numbers belong to the very return mapping fricreg_element_eval makes. */
#include <math.h>

#include "element_kind.h"

int fricreg_element_energy(const fricreg_element_type *type, const double params[],
                           const double state_in[], const double u[], double *dissipated,
                           double *stored)
{
    if (type == NULL || params == NULL || state_in == NULL || u == NULL || dissipated == NULL ||
        stored == NULL)
        return FRICREG_ENULL;
    const struct fr_element_kind *kind = type->kind;
    int status = kind->check(type, params, state_in, u, NULL, 0);
    if (status != FRICREG_OK)
        return status;
    /* the state is the sliders' positions, eval's slider forces laid out alike */
    double f[3], w[3 * FRICREG_ELEMENT_MAX_SLIDERS], fs[3 * FRICREG_ELEMENT_MAX_SLIDERS];
    kind->eval(type, params, state_in, u, f, NULL, NULL, w, fs);
    /* the return mapping slips at the force it ends on: f_s' . (w_s' - w_s) (Simo & Hughes
     * 1998, Ch. 1: the backward-Euler dissipation), >= 0 as f_s' is along w_s' - w_s */
    double d = 0.0;
    size_t nstate = kind->nstate(type->ns);
    for (size_t j = 0; j < nstate; j++)
        d += fs[j] * (w[j] - state_in[j]);
    double e = kind->stored(type, params, fs, f, 1, kind->stored(type, params, fs, f, 0, 0.0));
    if (!isfinite(d) || !isfinite(e)) /* a product of numbers near 1e308 */
        return FRICREG_ENONFINITE;
    *dissipated = d;
    *stored = e;
    return FRICREG_OK;
}
