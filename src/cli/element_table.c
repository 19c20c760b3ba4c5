/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element_table.c — the old element options' elements as one element set (element_table.h):
 * the type, the rows and the parameters in the kernel's layout that the library's per-kind
 * setters built from the same arrays (src/structure/jenkins.c's setter_type and setter_params,
 * src/hb/elements.c's blocks), added by the model's add_elements. */
#include <stdlib.h>
#include <string.h>

#include "element_table.h"
#include "input_line.h"

/* A normal law (lift-off, the 3-D contact): a row of Jn and kt mu n0 kn per element. */
static int has_normal(const struct cli_elements *el)
{
    return el->kind == CLI_ELEMENTS_NORMAL || el->kind == CLI_ELEMENTS_CONTACT_3D ||
           el->kind == CLI_ELEMENTS_IWAN_NORMAL;
}

/* The type as the setters chose it: two tangential rows the 2-D types, one slider the Jenkins
 * types, else the Iwan family's of ns sliders (NULL beyond the kernel's most). */
const fricreg_element_type *cli_elements_type(const struct cli_elements *el)
{
    int normal = has_normal(el);
    if (el->kind == CLI_ELEMENTS_JENKINS_2D || el->kind == CLI_ELEMENTS_CONTACT_3D)
        return fricreg_element_lookup(normal ? "contact_3d" : "jenkins_2d");
    if (el->ns == 1)
        return fricreg_element_lookup(normal ? "jenkins_normal" : "jenkins");
    return fricreg_element_sliders(fricreg_element_lookup(normal ? "iwan_normal" : "iwan"), el->ns);
}

/* el as a set for n dofs: element i's rows J's tangential ones then row i of Jn, its parameters
 * k[ns], the bounds (phi, or mu with a normal law)[ns], then kn, n0 and gap 0. 0, or
 * CLI_EXIT_USAGE after one line naming el's option and file; set->params, and set->J with a
 * normal law, the caller's to free either way. */
static int elements_as_set(const struct cli_elements *el, size_t n, struct cli_element_set *set)
{
    int normal = has_normal(el);
    size_t m = el->m, ns = el->ns;
    *set = (struct cli_element_set){.type = cli_elements_type(el),
                                    .me = m,
                                    .params_path = el->path};
    if (set->type == NULL)
        return cli_file_error(el->option, el->path, 0, "%zu sliders an element: at most %d", ns,
                              FRICREG_ELEMENT_MAX_SLIDERS);
    set->dim = (size_t)fricreg_element_dim(set->type);
    set->np = fricreg_element_nparams(set->type);
    size_t dim = set->dim, np = set->np, td = dim - (size_t)normal;
    /* without a normal law the rows are el's own, in order: not copied (a big model's J) */
    set->J = normal ? malloc(m * dim * n * sizeof *set->J) : el->J;
    set->params = malloc(m * np * sizeof *set->params);
    if (set->J == NULL || set->params == NULL)
        return cli_file_error(el->option, el->path, 0, "out of memory");
    const double *bound = normal ? el->mu : el->phi;
    for (size_t i = 0; i < m; i++) {
        double *rows = set->J + i * dim * n, *p = set->params + i * np;
        memcpy(p, el->k + i * ns, ns * sizeof *p);
        memcpy(p + ns, bound + i * ns, ns * sizeof *p);
        if (normal) {
            memcpy(rows, el->J + i * td * n, td * n * sizeof *rows);
            memcpy(rows + td * n, el->Jn + i * n, n * sizeof *rows);
            p[2 * ns] = el->kn[i];
            p[2 * ns + 1] = el->n0[i];
            p[2 * ns + 2] = 0.0;
        }
    }
    return 0;
}

int cli_add_elements(void *model, cli_element_set_adder *add, size_t n,
                     const struct cli_elements *el)
{
    if (el->m == 0)
        return 0;
    struct cli_element_set set;
    int status = elements_as_set(el, n, &set);
    const char *why = status == 0 ? add(model, &set, n) : NULL;
    if (why != NULL)
        status = cli_file_error(el->option, el->path, 0, "%s", why);
    if (has_normal(el))
        free(set.J);
    free(set.params);
    return status;
}
