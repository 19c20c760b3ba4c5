/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element_table.h — the elements of the old options (jenkins_input.h: --jenkins, --jenkins-2d
 * with their parameter files) added to a model the one way elements are added, by the element
 * table (fricreg_element.h) through the model's add_elements, as one set of element_sets.h
 * (element_table.c). */
#ifndef FRICREG_CLI_ELEMENT_TABLE_H
#define FRICREG_CLI_ELEMENT_TABLE_H

#include <stddef.h>

#include "element_sets.h"
#include "jenkins_input.h"

/* The type el's elements are added as (below); NULL beyond the kernel's most sliders. */
const fricreg_element_type *cli_elements_type(const struct cli_elements *el);

/* Adds el's m elements (none: nothing) for n dofs to model by add (the model's
 * cli_element_set_adder) as one set of the type the per-kind setters of 1.x installed: the
 * Jenkins types for one slider (an Iwan element of one slider too), the Iwan family of el->ns
 * sliders, jenkins_2d, or with a normal law jenkins_normal, iwan_normal or contact_3d (gap 0);
 * each element's rows tangential first, then its normal row of Jn, so that the model answers as
 * through those setters bit for bit. 0, or CLI_EXIT_USAGE after one line on stderr naming
 * el->option, el->path and the library's reason. */
int cli_add_elements(void *model, cli_element_set_adder *add, size_t n,
                     const struct cli_elements *el);

#endif
