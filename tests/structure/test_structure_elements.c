/* SPDX-License-Identifier: GPL-3.0-or-later */
/* test_structure_elements.c — Check suite for a structure holding elements of several types
 * (fricreg_structure_add_elements, _clear_elements, _element_count, _get_elements).
 *
 * Where the numbers come from:
 *   - a structure of three decoupled blocks (block-diagonal M, C, K), one of Jenkins elements
 *     beside a friction contact, one of a 3-D contact element, one of Iwan elements, holds all
 *     three kinds at once; each block is also run alone, with 1.x's per-kind setter: the
 *     motions, forces, slider states and dissipations agree to 1e-13 of their scales, for
 *     Newmark, HHT-alpha and the central difference (the blocks' equations are the same; only
 *     the Newton's shared stopping rule may differ, and a piecewise-linear Newton ends exact);
 *   - a set of one type added by add_elements, in one call or two, steps bit for bit as the
 *     per-kind setter's (the same type's kernel, the same coordinates' order);
 *   - types no per-kind setter has: "iwan_2d" of one slider is "jenkins_2d" (the same return
 *     to rounding); a "contact_3d" with a gap g0 is the one with the preload n0 = -kn g0 (to
 *     rounding); "jenkins_3d"'s energy balance closes (average-acceleration Newmark books the
 *     sliders' dissipation exactly, as fricreg_structure_set_jenkins's); "spring" is a
 *     Jenkins element that never slips (f = kt u from w = 0), to 1e-14, its balance closed;
 *     "dahl" (state not built from sliders) dissipates, its balance closed;
 *   - bad input: the statuses fricreg_structure.h promises, the element count and the run
 *     unchanged after each failure. */
#include <check.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fricreg_element.h"
#include "fricreg_structure.h"

#define NB 7 /* the blocks' dofs: A 0-1, B 2-4, C 5-6 */

/* Block A: two masses, a Jenkins element to ground on each, a contact on mass 1. Block B:
 * one mass in 3-D (x, y, n) on a 3-D contact element with a preload. Block C: two masses, an
 * Iwan element of four sliders between them, one to ground. */
static const size_t first[3] = {0, 2, 5}, size[3] = {2, 3, 2};

static void block_matrices(int b, double M[], double K[], double C[], double p[])
{
    size_t n = size[b];
    memset(M, 0, n * n * sizeof *M);
    memset(K, 0, n * n * sizeof *K);
    static const double mass[NB] = {1.1, 0.9, 1.3, 1.3, 1.3, 0.8, 1.2};
    static const double ks[NB] = {3.2, 2.1, 2.5, 1.9, 4.0, 1.6, 2.7};
    static const double load[NB] = {0.8, 0.0, 0.6, 0.4, -0.3, 0.5, 0.2};
    for (size_t i = 0; i < n; i++) {
        M[i * n + i] = mass[first[b] + i];
        K[i * n + i] = ks[first[b] + i];
        p[i] = load[first[b] + i];
    }
    if (b != 1) { /* a chain: a spring between the two masses */
        K[0] += 1.4, K[3] += 1.4, K[1] = K[2] = -1.4;
    }
    for (size_t i = 0; i < n * n; i++)
        C[i] = 0.04 * M[i] + 0.01 * K[i];
}

/* The elements' rows (row-major over the block's dofs) and parameters. */
static const double JA[2 * 2] = {1.0, 0.0, 0.0, 1.0}, PA[2 * 2] = {1.0, 0.05, 0.7, 0.08};
static const double JB[3 * 3] = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
static const double PB[5] = {1.5, 0.3, 2.0, 0.4, 0.0}; /* kt, mu, kn, n0, gap */
static const double JC[2 * 2] = {-1.0, 1.0, 0.0, 1.0};
static const double PC[2 * 8] = {1.0, 0.9, 0.6, 0.5, 0.05, 0.12, 0.13, 0.02,
                                 0.5, 0.4, 0.4, 0.3, 0.02, 0.05, 0.05, 0.04};
static const double CONTACT_A[2] = {0.0, 1.0}, MUN_A = 0.06;

static const fricreg_element_type *block_type(int b)
{
    if (b == 0)
        return fricreg_element_lookup("jenkins");
    if (b == 1)
        return fricreg_element_lookup("contact_3d");
    return fricreg_element_sliders(fricreg_element_lookup("iwan"), 4);
}

static const double *block_rows(int b)
{
    return b == 0 ? JA : b == 1 ? JB : JC;
}

static const double *block_params(int b)
{
    return b == 0 ? PA : b == 1 ? PB : PC;
}

static size_t block_elements(int b)
{
    return b == 1 ? 1 : 2;
}

static void set_scheme(fricreg_structure *s, int scheme)
{
    if (scheme == 1)
        ck_assert_int_eq(fricreg_structure_set_hht(s, -0.1), FRICREG_OK);
    if (scheme == 2)
        ck_assert_int_eq(fricreg_structure_set_central_difference(s), FRICREG_OK);
}

static double step_of(int scheme)
{
    return scheme == 2 ? 0.004 : 0.02;
}

/* Block b alone, its elements by 1.x's per-kind setter. */
static fricreg_structure *block_alone(int b, int scheme)
{
    size_t n = size[b];
    double M[9], K[9], C[9], p[3], u0[3] = {0.3, -0.2, 0.1}, v0[3] = {0.0, 0.0, 0.0};
    fricreg_structure *s = NULL;
    ck_assert_int_eq(fricreg_structure_create(n, 1, &s), FRICREG_OK);
    block_matrices(b, M, K, C, p);
    ck_assert_int_eq(fricreg_structure_set_mass(s, n, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_stiffness(s, n, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_damping(s, n, C), FRICREG_OK);
    double Jc[3] = {0.0, 0.0, 0.0}, mun = 0.0; /* a contact without friction on the last dof */
    Jc[n - 1] = 1.0;
    if (b == 0)
        memcpy(Jc, CONTACT_A, 2 * sizeof *Jc), mun = MUN_A;
    ck_assert_int_eq(fricreg_structure_set_contacts(s, 1, n, Jc), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_bounds(s, 1, &mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_load(s, n, p, 0.0, 0.0, 0, NULL), FRICREG_OK);
    set_scheme(s, scheme);
    if (b == 0) {
        const double kt[2] = {PA[0], PA[2]}, mu[2] = {PA[1], PA[3]};
        ck_assert_int_eq(fricreg_structure_set_jenkins(s, 2, n, JA, kt, mu), FRICREG_OK);
    } else if (b == 1) {
        const double Je[6] = {1, 0, 0, 0, 1, 0}, Jn[3] = {0, 0, 1};
        ck_assert_int_eq(fricreg_structure_set_jenkins_2d_normal(s, 1, n, Je, Jn, &PB[0], &PB[1],
                                                                 &PB[3], &PB[2]),
                         FRICREG_OK);
    } else {
        double k[8], phi[8];
        for (int i = 0; i < 2; i++)
            for (int j = 0; j < 4; j++)
                k[4 * i + j] = PC[8 * i + j], phi[4 * i + j] = PC[8 * i + 4 + j];
        ck_assert_int_eq(fricreg_structure_set_iwan(s, 2, n, JC, 4, k, phi), FRICREG_OK);
    }
    ck_assert_int_eq(fricreg_structure_set_initial(s, n, u0, v0), FRICREG_OK);
    return s;
}

/* The three blocks in one structure, their elements added block by block. */
static fricreg_structure *blocks_together(int scheme)
{
    double M[NB * NB] = {0}, K[NB * NB] = {0}, C[NB * NB] = {0}, p[NB], u0[NB], v0[NB] = {0};
    double Jc[NB] = {0};
    fricreg_structure *s = NULL;
    ck_assert_int_eq(fricreg_structure_create(NB, 1, &s), FRICREG_OK);
    for (int b = 0; b < 3; b++) {
        double Mb[9], Kb[9], Cb[9], pb[3], ub[3] = {0.3, -0.2, 0.1};
        size_t n = size[b], o = first[b];
        block_matrices(b, Mb, Kb, Cb, pb);
        for (size_t i = 0; i < n; i++) {
            for (size_t j = 0; j < n; j++) {
                M[(o + i) * NB + o + j] = Mb[i * n + j];
                K[(o + i) * NB + o + j] = Kb[i * n + j];
                C[(o + i) * NB + o + j] = Cb[i * n + j];
            }
            p[o + i] = pb[i];
            u0[o + i] = ub[i];
        }
    }
    Jc[1] = 1.0;
    double mun = MUN_A;
    ck_assert_int_eq(fricreg_structure_set_mass(s, NB, M), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_stiffness(s, NB, K), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_damping(s, NB, C), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_contacts(s, 1, NB, Jc), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_bounds(s, 1, &mun), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_set_load(s, NB, p, 0.0, 0.0, 0, NULL), FRICREG_OK);
    set_scheme(s, scheme);
    for (int b = 0; b < 3; b++) {
        size_t me = block_elements(b), dim = (size_t)fricreg_element_dim(block_type(b));
        double J[3 * NB] = {0};
        for (size_t r = 0; r < me * dim; r++)
            for (size_t j = 0; j < size[b]; j++)
                J[r * NB + first[b] + j] = block_rows(b)[r * size[b] + j];
        ck_assert_int_eq(fricreg_structure_add_elements(s, block_type(b), me, NB, J,
                                                        block_params(b)),
                         FRICREG_OK);
    }
    ck_assert_uint_eq(fricreg_structure_element_count(s), 5);
    ck_assert_int_eq(fricreg_structure_set_initial(s, NB, u0, v0), FRICREG_OK);
    return s;
}

static double largest(const double x[], size_t n)
{
    double big = 0.0;
    for (size_t i = 0; i < n; i++)
        big = fmax(big, fabs(x[i]));
    return big;
}

/* The mix's dofs, forces, states and dissipations of block b against block b alone. */
static void compare_block(fricreg_structure *mix, fricreg_structure *alone, int b)
{
    double u[NB], v[NB], ub[3], vb[3];
    ck_assert_int_eq(fricreg_structure_get_state(mix, NB, u, v, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_state(alone, size[b], ub, vb, NULL), FRICREG_OK);
    double su = largest(ub, size[b]), sv = largest(vb, size[b]);
    for (size_t i = 0; i < size[b]; i++) {
        ck_assert_msg(fabs(u[first[b] + i] - ub[i]) <= 1e-13 * su, "block %d u[%zu]: %.17g, %.17g",
                      b, i, u[first[b] + i], ub[i]);
        ck_assert_msg(fabs(v[first[b] + i] - vb[i]) <= 1e-13 * sv, "block %d v[%zu]", b, i);
    }
    /* the elements, in the mix's order: A's 2 (dim 1, 1 slot), B's 1 (dim 3, 2 slots), C's 2
     * (dim 1, 4 slots) */
    double f[2 + 3 + 2], state[2 + 2 + 8], D[5];
    ck_assert_int_eq(fricreg_structure_get_elements(mix, 5, f, state, D), FRICREG_OK);
    static const size_t f_at[3] = {0, 2, 5}, s_at[3] = {0, 2, 4}, d_at[3] = {0, 2, 3};
    static const size_t nf[3] = {2, 3, 2}, nstate[3] = {2, 2, 8};
    double fb[3], wb[8], Db[2];
    size_t me = block_elements(b);
    ck_assert_int_eq(fricreg_structure_get_elements(alone, me, fb, wb, Db), FRICREG_OK);
    double sf = largest(fb, nf[b]), sw = largest(wb, nstate[b]), sd = largest(Db, me);
    ck_assert(sf > 0.0 && sd > 0.0); /* the elements carry load and slip */
    for (size_t i = 0; i < nf[b]; i++)
        ck_assert_msg(fabs(f[f_at[b] + i] - fb[i]) <= 1e-13 * sf, "block %d f[%zu]", b, i);
    for (size_t i = 0; i < nstate[b]; i++)
        ck_assert_msg(fabs(state[s_at[b] + i] - wb[i]) <= 1e-13 * sw, "block %d w[%zu]", b, i);
    for (size_t i = 0; i < me; i++)
        ck_assert_msg(fabs(D[d_at[b] + i] - Db[i]) <= 1e-13 * sd, "block %d D[%zu]", b, i);
}

START_TEST(mix_equals_blocks)
{
    int scheme = _i;
    fricreg_structure *mix = blocks_together(scheme);
    ck_assert_int_eq(fricreg_structure_run(mix, step_of(scheme), 12.0), FRICREG_OK);
    for (int b = 0; b < 3; b++) {
        fricreg_structure *alone = block_alone(b, scheme);
        ck_assert_int_eq(fricreg_structure_run(alone, step_of(scheme), 12.0), FRICREG_OK);
        compare_block(mix, alone, b);
        fricreg_structure_free(alone);
    }
    fricreg_structure_free(mix);
}
END_TEST

/* u, v and the elements' state of two structures of n dofs and me elements, bit for bit. */
static void assert_same(fricreg_structure *a, fricreg_structure *b, size_t n, size_t me,
                        size_t nstate)
{
    double ua[NB], va[NB], ub[NB], vb[NB], sa[16], sb[16];
    ck_assert_int_eq(fricreg_structure_get_state(a, n, ua, va, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_state(b, n, ub, vb, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_elements(a, me, NULL, sa, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_elements(b, me, NULL, sb, NULL), FRICREG_OK);
    ck_assert(memcmp(ua, ub, n * sizeof *ua) == 0 && memcmp(va, vb, n * sizeof *va) == 0);
    ck_assert(memcmp(sa, sb, nstate * sizeof *sa) == 0);
}

START_TEST(add_equals_setter)
{
    for (int scheme = 0; scheme < 3; scheme++) {
        fricreg_structure *setter = block_alone(2, scheme), *added = block_alone(2, scheme);
        ck_assert_int_eq(fricreg_structure_clear_elements(added), FRICREG_OK);
        ck_assert_uint_eq(fricreg_structure_element_count(added), 0);
        const fricreg_element_type *T = block_type(2); /* in two calls of one element */
        ck_assert_int_eq(fricreg_structure_add_elements(added, T, 1, 2, JC, PC), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_add_elements(added, T, 1, 2, JC + 2, PC + 8),
                         FRICREG_OK);
        double u0[2] = {0.3, -0.2}, v0[2] = {0.0, 0.0};
        ck_assert_int_eq(fricreg_structure_set_initial(added, 2, u0, v0), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_run(setter, step_of(scheme), 8.0), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_run(added, step_of(scheme), 8.0), FRICREG_OK);
        assert_same(setter, added, 2, 2, 8);
        fricreg_structure_free(setter);
        fricreg_structure_free(added);

        setter = block_alone(1, scheme); /* the 3-D contact: its rows x, y, n in one J */
        added = block_alone(1, scheme);
        ck_assert_int_eq(fricreg_structure_clear_elements(added), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_add_elements(added, block_type(1), 1, 3, JB, PB),
                         FRICREG_OK);
        double w0[3] = {0.3, -0.2, 0.1}, z0[3] = {0.0, 0.0, 0.0};
        ck_assert_int_eq(fricreg_structure_set_initial(added, 3, w0, z0), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_run(setter, step_of(scheme), 8.0), FRICREG_OK);
        ck_assert_int_eq(fricreg_structure_run(added, step_of(scheme), 8.0), FRICREG_OK);
        assert_same(setter, added, 3, 1, 2);
        fricreg_structure_free(setter);
        fricreg_structure_free(added);
    }
}
END_TEST

/* Block B with its element replaced by me elements of type T (rows J, params P), run to t. */
static fricreg_structure *block_b_with(const fricreg_element_type *T, const double J[],
                                       const double P[], double t)
{
    fricreg_structure *s = block_alone(1, 0);
    ck_assert_int_eq(fricreg_structure_clear_elements(s), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_add_elements(s, T, 1, 3, J, P), FRICREG_OK);
    double u0[3] = {0.3, -0.2, 0.1}, v0[3] = {0.0, 0.0, 0.0};
    ck_assert_int_eq(fricreg_structure_set_initial(s, 3, u0, v0), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run(s, 0.02, t), FRICREG_OK);
    return s;
}

static void assert_close(fricreg_structure *a, fricreg_structure *b, double rtol)
{
    double ua[3], ub[3];
    ck_assert_int_eq(fricreg_structure_get_state(a, 3, ua, NULL, NULL), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_state(b, 3, ub, NULL, NULL), FRICREG_OK);
    for (int i = 0; i < 3; i++)
        ck_assert_msg(fabs(ua[i] - ub[i]) <= rtol * largest(ub, 3), "u[%d]: %.17g, %.17g", i, ua[i],
                      ub[i]);
}

/* Average-acceleration Newmark's energy balance of s closes to 1e-12 of the input, with its
 * elements' dissipation above min_dissipation where that is > 0. */
static void assert_balance_closes(fricreg_structure *s, double min_dissipation)
{
    double input, residual, D;
    ck_assert_int_eq(fricreg_structure_get_value(s, FRICREG_SVALUE_INPUT, &input), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_value(s, FRICREG_SVALUE_RESIDUAL, &residual),
                     FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_value(s, FRICREG_SVALUE_JENKINS, &D), FRICREG_OK);
    ck_assert_msg(fabs(residual) <= 1e-12 * fabs(input), "residual %g input %g", residual, input);
    ck_assert_msg(min_dissipation == 0.0 || D > min_dissipation, "D %g", D);
}

START_TEST(types_beyond_setters)
{
    /* iwan_2d of one slider on block B's x, y is jenkins_2d; the normal dof free of it */
    const double J2[2 * 3] = {1, 0, 0, 0, 1, 0}, P2[2] = {1.5, 0.12};
    const fricreg_element_type *iwan_2d = fricreg_element_sliders(fricreg_element_lookup("iwan_2d"),
                                                                  1);
    fricreg_structure *a = block_b_with(iwan_2d, J2, P2, 10.0);
    fricreg_structure *b = block_b_with(fricreg_element_lookup("jenkins_2d"), J2, P2, 10.0);
    assert_close(a, b, 1e-14);
    fricreg_structure_free(a);
    fricreg_structure_free(b);

    /* a gap g0 with no preload is the preload -kn g0 */
    const double Pgap[5] = {1.5, 0.3, 2.0, 0.0, -0.2}, Ppre[5] = {1.5, 0.3, 2.0, 0.4, 0.0};
    a = block_b_with(block_type(1), JB, Pgap, 10.0);
    b = block_b_with(block_type(1), JB, Ppre, 10.0);
    assert_close(a, b, 1e-12);
    fricreg_structure_free(a);
    fricreg_structure_free(b);

    /* jenkins_3d on x, y, n: average-acceleration Newmark's balance closes with its
     * dissipation */
    const double P3[2] = {1.5, 0.1};
    a = block_b_with(fricreg_element_lookup("jenkins_3d"), JB, P3, 10.0);
    assert_balance_closes(a, 1e-3);
    fricreg_structure_free(a);

    /* spring (a law of one file and a table line) on x is a Jenkins element that never slips,
     * f = kt (u - 0); its stored energy closes the balance */
    const double Jx[3] = {1, 0, 0}, Pspring[1] = {0.8}, Pstuck[2] = {0.8, 1e6};
    a = block_b_with(fricreg_element_lookup("spring"), Jx, Pspring, 10.0);
    b = block_b_with(fricreg_element_lookup("jenkins"), Jx, Pstuck, 10.0);
    assert_close(a, b, 1e-14);
    assert_balance_closes(a, 0.0);
    fricreg_structure_free(a);
    fricreg_structure_free(b);

    /* dahl (state not built from sliders) on x: its bristles dissipate, and average-acceleration
     * Newmark's balance closes with that dissipation (its force is linear in the bristles'
     * deflection u - w, so the trapezoid's work splits exactly into F dw and the stored F^2 /
     * (2 sigma)) */
    const double Pdahl[2] = {0.8, 0.1};
    a = block_b_with(fricreg_element_lookup("dahl"), Jx, Pdahl, 10.0);
    assert_balance_closes(a, 1e-3);
    fricreg_structure_free(a);
}
END_TEST

/* The mix's state after a run of 2 s: bit for bit the same when a failed call came between. */
static void run_and_state(fricreg_structure *s, double u[NB])
{
    ck_assert_int_eq(fricreg_structure_run(s, 0.02, 2.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_get_state(s, NB, u, NULL, NULL), FRICREG_OK);
}

START_TEST(bad_input)
{
    double ref[NB], u[NB], f[7], w[12], D[5];
    fricreg_structure *s = blocks_together(0);
    run_and_state(s, ref);
    fricreg_structure_free(s);

    s = blocks_together(0);
    const fricreg_element_type *T = fricreg_element_lookup("jenkins");
    double J[NB] = {1.0}, P[2] = {1.0, 0.1};
    ck_assert_int_eq(fricreg_structure_add_elements(NULL, T, 1, NB, J, P), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_add_elements(s, NULL, 1, NB, J, P), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_add_elements(s, T, 1, NB, NULL, P), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_add_elements(s, T, 1, NB, J, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_add_elements(s, T, 1, NB - 1, J, P), FRICREG_ESIZE);
    double bad_kt[4] = {1.0, 0.1, 0.0, 0.1}, J2[2 * NB] = {1.0};
    J2[NB] = 1.0;
    ck_assert_int_eq(fricreg_structure_add_elements(s, T, 2, NB, J2, bad_kt), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(s), "element 1"));
    double nan_p[2] = {NAN, 0.1};
    ck_assert_int_eq(fricreg_structure_add_elements(s, T, 1, NB, J, nan_p), FRICREG_ENONFINITE);
    double zero[NB] = {0.0};
    ck_assert_int_eq(fricreg_structure_add_elements(s, T, 1, NB, zero, P), FRICREG_EINVAL);
    ck_assert_ptr_nonnull(strstr(fricreg_structure_errmsg(s), "zero"));
    double inf_row[NB] = {1.0, INFINITY};
    ck_assert_int_eq(fricreg_structure_add_elements(s, T, 1, NB, inf_row, P), FRICREG_ENONFINITE);
    const double both[5] = {1.5, 0.3, 2.0, 0.4, 0.1}; /* a preload and a gap */
    double J3[3 * NB] = {0};
    J3[2] = J3[NB + 3] = J3[2 * NB + 4] = 1.0;
    ck_assert_int_eq(fricreg_structure_add_elements(s, block_type(1), 1, NB, J3, both),
                     FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_add_elements(s, T, 0, NB, NULL, NULL), FRICREG_OK);
    ck_assert_uint_eq(fricreg_structure_element_count(s), 5);
    run_and_state(s, u);
    ck_assert(memcmp(u, ref, sizeof u) == 0);

    /* the getters */
    ck_assert_int_eq(fricreg_structure_get_elements(s, 4, f, w, D), FRICREG_ESIZE);
    ck_assert_int_eq(fricreg_structure_get_elements(s, 5, NULL, NULL, NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_get_elements(NULL, 5, f, w, D), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_get_jenkins_state(s, 5, f, NULL, NULL), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_get_jenkins_2d_state(s, 5, f, NULL, NULL), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_get_normal_forces(s, 5, f), FRICREG_EINVAL);
    ck_assert_int_eq(fricreg_structure_get_jenkins_state(s, 5, NULL, NULL, D), FRICREG_OK);
    ck_assert_uint_eq(fricreg_structure_element_count(NULL), 0);
    ck_assert_int_eq(fricreg_structure_clear_elements(NULL), FRICREG_ENULL);
    ck_assert_int_eq(fricreg_structure_clear_elements(s), FRICREG_OK);
    ck_assert_uint_eq(fricreg_structure_element_count(s), 0);
    ck_assert_int_eq(fricreg_structure_get_elements(s, 0, f, w, D), FRICREG_OK);
    fricreg_structure_free(s);
}
END_TEST

START_TEST(checkpoint_of_a_mix)
{
    fricreg_structure *a = blocks_together(0), *b = blocks_together(0);
    ck_assert_int_eq(fricreg_structure_run(a, 0.02, 1.0), FRICREG_OK);
    size_t bytes = 0;
    ck_assert_int_eq(fricreg_structure_save(a, NULL, &bytes), FRICREG_OK);
    void *buf = malloc(bytes);
    ck_assert_ptr_nonnull(buf);
    ck_assert_int_eq(fricreg_structure_save(a, buf, &bytes), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_restore(b, buf, bytes), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run(a, 0.02, 3.0), FRICREG_OK);
    ck_assert_int_eq(fricreg_structure_run(b, 0.02, 3.0), FRICREG_OK);
    assert_same(a, b, NB, 5, 12);
    /* the same sizes with the types swapped (block A's Jenkins as one-slider Iwans) refused */
    fricreg_structure *c = blocks_together(0);
    ck_assert_int_eq(fricreg_structure_clear_elements(c), FRICREG_OK);
    for (int blk = 0; blk < 3; blk++) {
        const fricreg_element_type *T =
            blk == 0 ? fricreg_element_sliders(fricreg_element_lookup("iwan"), 1) : block_type(blk);
        size_t me = block_elements(blk), dim = (size_t)fricreg_element_dim(T);
        double J[3 * NB] = {0};
        for (size_t r = 0; r < me * dim; r++)
            for (size_t j = 0; j < size[blk]; j++)
                J[r * NB + first[blk] + j] = block_rows(blk)[r * size[blk] + j];
        ck_assert_int_eq(fricreg_structure_add_elements(c, T, me, NB, J, block_params(blk)),
                         FRICREG_OK);
    }
    ck_assert_int_eq(fricreg_structure_restore(c, buf, bytes), FRICREG_EINVAL);
    free(buf);
    fricreg_structure_free(a);
    fricreg_structure_free(b);
    fricreg_structure_free(c);
}
END_TEST

static Suite *suite(void)
{
    Suite *s = suite_create("structure_elements");
    TCase *tc = tcase_create("core");
    tcase_set_timeout(tc, 60);
    tcase_add_loop_test(tc, mix_equals_blocks, 0, 3);
    tcase_add_test(tc, add_equals_setter);
    tcase_add_test(tc, types_beyond_setters);
    tcase_add_test(tc, bad_input);
    tcase_add_test(tc, checkpoint_of_a_mix);
    suite_add_tcase(s, tc);
    return s;
}

int main(void)
{
    SRunner *sr = srunner_create(suite());
    srunner_run_all(sr, CK_NORMAL);
    int failed = srunner_ntests_failed(sr);
    srunner_free(sr);
    return failed == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
