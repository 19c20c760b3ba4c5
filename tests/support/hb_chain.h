/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb_chain.h — NLvib's chain as a harmonic-balance model (fricreg_hb.h), for test_hb_march and
 * bench/hb_march.c: bench/nlvib/chain_jenkins.m's system (unit masses and springs
 * ground-1-2-3, C = 0.02 K, cos(Omega t) on dof 2, Jenkins elements kt = 20, mu N = 1 between
 * dof 1 and the ground and between dofs 1 and 2) at HB_CHAIN_H harmonics, with jenkins elements
 * (exact AFT) or with jenkins_2d elements whose second components sit on dofs 4 and 5 of their
 * own (unit mass and spring, unforced: at rest; the march of their eval). */
#ifndef FRICREG_HB_CHAIN_H
#define FRICREG_HB_CHAIN_H

#include "fricreg_hb.h"

#define HB_CHAIN_H 7

/* The chain, marched (jenkins_2d, 5 dofs) or not (jenkins, 3 dofs), stability on or off; NULL
 * if a call failed (out of memory). */
fricreg_hb *hb_chain(int marched, int stability);

/* Its unknowns: the elements' rows times 2H + 1. */
size_t hb_chain_nq(int marched);

#endif
