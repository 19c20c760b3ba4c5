/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb_chain.c — NLvib's chain (hb_chain.h). */
#include "hb_chain.h"

#include "fricreg_element.h"

fricreg_hb *hb_chain(int marched, int stability)
{
    size_t n = marched ? 5 : 3, dim = marched ? 2 : 1;
    double M[25] = {0}, K[25] = {0}, C[25], pc[5] = {0, 1, 0, 0, 0}, ps[5] = {0};
    double J[20] = {0}, p[4] = {20, 1, 20, 1};
    for (size_t i = 0; i < n; i++) {
        M[i * n + i] = 1.0;
        K[i * n + i] = i < 3 ? 2.0 : 1.0;
        if (i > 0 && i < 3)
            K[i * n + i - 1] = K[(i - 1) * n + i] = -1.0;
    }
    for (size_t i = 0; i < n * n; i++)
        C[i] = 0.02 * K[i];
    J[0] = 1.0; /* element 0 on dof 1, element 1 on dof 2 - dof 1: rows 0 and dim */
    J[dim * n] = -1.0;
    J[dim * n + 1] = 1.0;
    if (marched) { /* their second components on dofs 4 and 5 */
        J[n + 3] = 1.0;
        J[3 * n + 4] = 1.0;
    }
    fricreg_hb *hb = NULL;
    if (fricreg_hb_create(n, 2, HB_CHAIN_H, &hb) != FRICREG_OK)
        return NULL;
    if (fricreg_hb_set_mass(hb, n, M) != FRICREG_OK ||
        fricreg_hb_set_stiffness(hb, n, K) != FRICREG_OK ||
        fricreg_hb_set_damping(hb, n, C) != FRICREG_OK ||
        fricreg_hb_set_excitation(hb, n, pc, ps) != FRICREG_OK ||
        fricreg_hb_set_stability(hb, stability) != FRICREG_OK ||
        fricreg_hb_add_elements(hb, fricreg_element_lookup(marched ? "jenkins_2d" : "jenkins"), 2,
                                n, J, p) != FRICREG_OK) {
        fricreg_hb_free(hb);
        return NULL;
    }
    return hb;
}

size_t hb_chain_nq(int marched)
{
    return (size_t)(marched ? 4 : 2) * (2 * HB_CHAIN_H + 1);
}
