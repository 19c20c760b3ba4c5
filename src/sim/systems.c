/* SPDX-License-Identifier: GPL-3.0-or-later */
/* systems.c — enum fricreg_system mapped onto the reference systems' types (src/sim/systems/),
 * and their parameter tables read by parameter id. */
#include <stddef.h>

#include "system.h"

static const struct fr_system_type *const types[] = {
    &fr_oscillator_type,
    &fr_chain_type,
    &fr_twoblock_type,
};

#define NTYPES (sizeof types / sizeof types[0])

const struct fr_system_type *fr_system_type_find(int id)
{
    for (size_t k = 0; k < NTYPES; k++)
        if (types[k]->id == id)
            return types[k];
    return NULL;
}

void fr_system_init(struct fr_system *sys, const struct fr_system_type *type)
{
    sys->type = type;
    sys->memo_arg = NAN; /* no sine memorized: NaN equals no argument */
    sys->memo_sin = 0.0;
    for (size_t k = 0; k < type->nparams; k++)
        sys->p[k] = type->params[k].paper_value;
}

const struct fr_param_spec *fr_system_param(const struct fr_system_type *type, int param,
                                            size_t *slot)
{
    for (size_t k = 0; k < type->nparams; k++) {
        if (type->params[k].param == param) {
            *slot = k;
            return &type->params[k];
        }
    }
    return NULL;
}

const char *fr_param_name(int param)
{
    size_t slot;
    for (size_t k = 0; k < NTYPES; k++) {
        const struct fr_param_spec *spec = fr_system_param(types[k], param, &slot);
        if (spec != NULL)
            return spec->name;
    }
    return NULL;
}
