/* SPDX-License-Identifier: GPL-3.0-or-later */
/* membrane.h — bench/membrane_contacts.c's friction interface on a continuum, in small, for
 * the tests: a side x side grid of 1 kg nodes, one degree of freedom each, springs of
 * spring_k N/m between neighbours and 10^3 N/m to the ground, Rayleigh C = 0.002 s K, shaken
 * by a_g(t) = 0.35 g sin(2 pi 4 t) sampled every 5 ms for 400 samples; contacts on the first
 * rows of the grid: the edge's against the ground (mu N = 20 N), each further row's against
 * the row before (4 N), rows x side in all; Quinn's law, eps = 10^-3 m/s, the near-stick
 * block's solver given (enum fricreg_contact_solver). No library is linked: each test brings
 * its own fricreg. */
#ifndef FRICREG_TEST_MEMBRANE_H
#define FRICREG_TEST_MEMBRANE_H

#include <stddef.h>

#include "fricreg_structure.h"

#define TEST_MEMBRANE_DT 0.005

/* The structure, or NULL if a setter failed (side >= 2, 1 <= rows <= side, side^2 <= 16384). */
fricreg_structure *test_membrane(size_t side, size_t rows, double spring_k, int solver);

#endif
