/* SPDX-License-Identifier: GPL-3.0-or-later */
/* mex_element.h — element types by name for the gateway's commands (element_eval in
 * fricreg_mex.c, hb_add_elements in mex_hb.c): one lookup, one message listing the types. */
#ifndef FRICREG_MEX_ELEMENT_H
#define FRICREG_MEX_ELEMENT_H

#include <stddef.h>

#include "mex.h"
#include "fricreg_element.h"

/** The type named by the string a (its family's first member: one slider for an Iwan type);
 *  raises fricreg:type if a is not a string, fricreg:EINVAL naming the types if none has the
 *  name. */
const fricreg_element_type *mexe_first(const mxArray *a, const char *cmd);

/** The member of first's family with nparams parameters (an Iwan type's slider count follows
 *  from it), or NULL where none has that many. */
const fricreg_element_type *mexe_member(const fricreg_element_type *first, size_t nparams);

/** Raise fricreg:size: params of rows x cols is not a count of parameters first's family takes
 *  (the message says which counts it does). */
void mexe_bad_params(const fricreg_element_type *first, const char *cmd, const char *what,
                     size_t rows, size_t cols);

#endif
