/* SPDX-License-Identifier: GPL-3.0-or-later */
/* hb_internal.h — the harmonic-balance driver's layout (fricreg_hb.h) and its inline
 * accessors. The kernels its files share have headers of their own beside it: dynamic.h
 * factors the dynamic stiffnesses and condenses them on the elements (G_h = J D_h^-1 J^T),
 * residual.h evaluates (R), its Jacobian and its Ω derivative, newton.h solves at one Ω,
 * recover.h gives the displacements. Complex numbers are stored as (re, im) pairs of doubles.
 * Included inside src/hb/ and by the modules built on the driver: floquet/ (stability), nma/
 * (nonlinear modes) and forced/ (the forced response), which each hang their own state on it
 * (its release table) and name no other's, and qsma/ (quasi-static modes), which reads its
 * model. */
#ifndef FRICREG_HB_INTERNAL_H
#define FRICREG_HB_INTERNAL_H

#include <stddef.h>
#include <stdint.h>

#include <cholmod.h>
#include <klu.h>

#include "base/error.h"
#include "fricreg_aft.h"
#include "fricreg_hb.h"

/* The halvings of one Newton direction in every HB Newton (base/line_search.h), alpha down to
 * 1/1024, where the structure's steps take 30: each trial costs every element's AFT, and a
 * direction cut below 1/1024 of its length has stopped helping (a point solve reports the
 * stall, FRICREG_EWORK; the continuation's corrector goes on from the shortest trial, its
 * iteration bound ending it). */
#define FR_HB_HALVINGS 10

struct fr_hb_lu;        /* sparse.c: one harmonic's LU factor */
struct fr_hb_stability; /* floquet/floquet_internal.h: the stability's state */
struct fr_aft_march;    /* joint/aft_march.h: the march's workspace */
struct fr_hb_forced;    /* forced/forced_internal.h: the forced response's branch */

/* The parts of the driver that modules above it own (its release table). */
enum fr_hb_part { FR_HB_PART_STABILITY, FR_HB_PART_NMA, FR_HB_PART_FORCED, FR_HB_PARTS };

/* Vectors of nq + 1 in the room the driver keeps for the forced response's continuation
 * (cont): sized here with J's rows, since only the element setters know when those change,
 * so that a solve allocates nothing; laid out by forced/ (forced_internal.h). */
#define FR_HB_CONT_VECTORS 7

/* The kinds of element the driver holds, each its number of rows of J and its AFT
 * (residual.c). */
enum fr_hb_kind {
    FR_HB_SLIDERS = 1,    /* Jenkins or Iwan: one row, fricreg_aft_iwan_exact */
    FR_HB_LIFTOFF = 2,    /* Jenkins or Iwan with lift-off: tangential row, then normal row */
    FR_HB_CONTACT_3D = 3, /* x, y, normal: the sampled AFT with Richardson's extrapolation */
    FR_HB_MARCH = 4       /* any other type of fricreg_element.h: its dim rows, the march of its
                             eval (joint/aft_march.h), with Richardson's for a law with state */
};

struct fricreg_hb {
    size_t n, m;    /* dofs, rows of J (the condensation's coordinates) */
    size_t me, rpe; /* elements (fricreg_hb_create's m), their kind when all are of one
                        (enum fr_hb_kind: 1 and 2 are also the rows per element), 0 for a mix */
    size_t count;   /* elements held (element_store.c): the model is whole at count = me */
    int *kind;      /* [me] each element's enum fr_hb_kind */
    size_t *erow;   /* [me + 1] element e's first row of J (erow[count] = m) */
    size_t *ejq;    /* [me + 1] its Jacobian block's offset in jq, in units of nc² */
    size_t *eso;    /* [me + 1] its first slider (eso[count] = nsl) */
    size_t *epo;    /* [me + 1] a marched element's parameters at ep + epo[e] (others: none) */
    const fricreg_element_type **etype; /* [me] a marched element's type, NULL for the others */
    double *ep;                         /* [epo[count]] the marched elements' parameters */
    struct fr_aft_march *march;         /* their AFT's workspace (N of fr_hb_contact_samples),
                                           NULL: none held yet */
    size_t march_nstate;                /* the most states it has room for */
    size_t rows_cap;   /* rows the buffers below hold (grown by elements of more rows, kept) */
    size_t sq_cap;     /* units of nc² the Jacobian blocks jq hold */
    int H;             /* harmonics */
    size_t nc, nq;     /* 2H + 1 coefficients, m nc unknowns */
    double *M, *C, *K; /* [n n] each, row-major, symmetric (dense models; NULL above 4096) */
    int rayleigh;      /* C = a0 M + a1 K instead of the matrix C */
    int c_zero;        /* the matrix C is zero (as created) */
    double a0, a1;
    double *J;  /* [m n] (room for rows_cap rows) */
    size_t ns;  /* sliders per element when alike (1: Jenkins), 0 when they differ */
    size_t nsl; /* sliders held */
    double *sk; /* the sliders' [nsl] stiffnesses then [nsl] slip forces (with lift-off:
                   friction coefficients), element e's from eso[e]; then, with an Iwan element
                   with lift-off (scratch), room for one slider's AFT */
    int scratch;
    double *nl; /* [4 me]: kt, mu, n0, kn of each element with a normal law (an Iwan element's
                   kt and mu summed over its sliders) */
    int have_elements;
    double *pc, *ps; /* [n] excitation of the fundamental */
    /* the excitation's factor in force, λ: 1 but along a continuation in the level
     * (fricreg_hb_continue_level, and fricreg_hb_solve's start), where (R)'s load J D_h^-1 P_h,
     * its Ω derivative and the displacements' load term are multiplied by it (fr_hb_load) */
    double level;

    /* The nonlinear modes (nma/nma.c, fricreg_hb_nma): while one is solved, D_h's damping is
     * C − xi M (C left out when no_c: the modal-damping option), and free_vibration says that
     * the load column of Y_1 holds the normalization's M φ rather than a load: (R), its Ω
     * derivative and the displacements leave it out. 0 otherwise. */
    double xi;
    int no_c, free_vibration;
    struct fr_hb_nma *nma; /* the backbone's points and workspace, NULL: none yet */

    double tol;
    int max_iter;
    double ds0, ds_min, ds_max;
    size_t max_points;
    const double *nma_targets; /* during fricreg_hb_nma_at: its amplitudes (nma/nma.c) */

    fricreg_aft *aft; /* exact paths; with fr_hb_contact_samples' N once 3-D elements were set */
    /* the 3-D contact element's AFT at N/2 samples and its results, [3 nc + 9 nc²]: the
     * residual extrapolates 2 F(N) − F(N/2) (residual.c); NULL: no 3-D elements yet */
    fricreg_aft *aft_half;
    double *half;

    /* The factors of one frequency (dynamic.c), valid while factored_omega is that Ω. */
    double factored_omega;       /* NaN: none */
    int factored_deriv;          /* the Ω derivative dql is there too */
    unsigned long factor_serial; /* counts the factorizations: G_h's identity */
    unsigned long k_kept;        /* model_serial + 1 while Y_0, G_0 hold K's solves (D_0 = K
                                    at every Ω; dense models), 0: not */
    double *D;                   /* [n n] complex: one D_h at a time, LU-factored in place */
    int *piv;                    /* [n] its row interchanges (lu.c: LAPACK's) */
    double *Y;    /* [(H+1) n (m+1)] complex: D_h^-1 [J^T | P_h], row k of harmonic h at
                     Y[(h n + k)(m+1)], column m the load (0 but for h = 1) */
    double *Z;    /* [n (m+2)] complex scratch: y and D_h' y (dynamic.c), or (sparse.c) the
                     right-hand sides of Y_h, solved in place */
    double *G;    /* [(H+1) m m] complex: G_h = J D_h^-1 J^T */
    double *ql;   /* [(H+1) m] complex: J D_h^-1 P_h */
    double *dql;  /* [(H+1) m] complex: dql_h/dΩ */
    double *colw; /* [n] complex scratch: one column */
    /* The modes of (K, M) (modal.c), for a dense model with proportional damping: modes
     * [n n] column-major, Φ^T M Φ = I, then lambda [n] (K Φ = M Φ Λ); jmodes [m n] J Φ
     * column-major, then xmodal [2 n (m + 1)] scratch; NULL: none yet. modes_serial is
     * mk_serial + 1 while the modes hold (mk_serial counts M's and K's changes), modes_failed
     * the same where they cannot serve, jmodes_serial model_serial + 1 while J Φ holds; the
     * least n solved through them (SIZE_MAX: never; fricreg_hb_set_receptance). */
    double *modes, *lambda, *jmodes, *xmodal;
    size_t jmodes_rows, modal_min;
    unsigned long mk_serial, modes_serial, modes_failed, jmodes_serial;

    /* The sparse model (sparse.c): M, C, K as the upper triangles of their symmetric parts,
     * and D_h's pattern, the union of theirs with both triangles (compressed columns, rows
     * sorted), with each matrix's values on it; KLU's analysis of that pattern (once per
     * pattern) and each harmonic's LU factor, refactored at the next frequency of a call. */
    int sparse;                   /* the model is sparse: dense setters convert to it */
    cholmod_common cc;            /* fr_cholmod_start's: the setters' conversions */
    cholmod_sparse *Ms, *Cs, *Ks; /* upper triangles (stype 1) */
    int64_t *Dp, *Di;             /* [n + 1], [dnz]: the pattern of D_h */
    size_t dnz;
    double *vM, *vC, *vK;     /* [dnz] each: M, C, K on that pattern */
    double *Dv;               /* [2 dnz]: D_h, complex interleaved (KLU's layout) */
    klu_l_common klu;         /* KLU's settings and last status */
    klu_l_symbolic *symbolic; /* klu_l_analyze's, NULL: none yet */
    struct fr_hb_lu *lu;      /* [H + 1]: each harmonic's factor (sparse.c) */

    /* Newton (residual.c, newton.c; forced/corrector.c, forced/arclength.c) */
    double *fq;     /* [nq] element force coefficients at the last evaluation */
    double *jq;     /* [ejq[count] nc²] their Jacobians, element e's block [(rows nc)²] at
                       fr_hb_block_of */
    double *R;      /* [nq + 1] residual (continuation: the arclength equation last) */
    double *A;      /* [(nq + 1)^2] Newton's matrix, LU-factored in place */
    double *rw;     /* [nq + 1] dR/dΩ, then scratch */
    double *dy;     /* [nq + 1] Newton's step */
    double *qw;     /* [nq + 1] iterate (continuation: Ω last) */
    double *qt;     /* [nq + 1] line search trial */
    double *bcol;   /* [nq + 1] the bordered matrix's column, recorded until it is formed */
    double *brow;   /* [nq + 1] its row */
    double *refine; /* [4 (nq + 1)] the refinement's b, x, Ĵ x and r (newton_matrix.c) */
    double *cont;   /* [FR_HB_CONT_VECTORS (nq + 1)] the forced response's continuation's room */
    double *qjac;   /* [nq] the q of the last residual with Jacobians (the monodromy's orbit) */
    int *piv2;      /* [nq + 1] A's row interchanges (lu.c: LAPACK's) */
    /* Newton's matrix recorded (newton_matrix.c): its order, whether by the capacitance
     * (capacitance.c's room, NULL: none yet) and whether factored; the order of the dense LU
     * factor A holds (0: none), and the least order at which a later matrix is solved by
     * refinement on it (FR_HB_REFINE_MIN); the least nq and the share of non-diagonal rows
     * for the capacitance (FR_HB_CAPACITANCE_MIN, _SHARE) */
    size_t newton_nd, held_nd, held_min;
    int by_capacitance, newton_factored;
    struct fr_hb_capacitance *capacitance;
    size_t capacitance_min;
    double capacitance_share;
    int iterations; /* of the last Newton solve */

    /* the last solution (its stability, when on, is floquet/'s) */
    int have_solution;
    double omega_sol, level_sol; /* its Ω and excitation level λ */
    double *qsol;                /* [nq] */

    /* Stability (floquet/floquet_internal.h): its state while on (fricreg_hb_set_stability),
     * NULL: off; and the method chosen (enum fricreg_hb_stability_method,
     * fricreg_hb_set_stability_method), a setting kept while stability is off */
    struct fr_hb_stability *stability;
    int stability_method;
    unsigned long model_serial; /* counts the model's changes (fr_hb_invalidate) */

    /* the forced response's branch, its points and bifurcations (forced/forced_internal.h),
     * NULL: none stored yet */
    struct fr_hb_forced *forced;
    /* counts the changes of what a solution keeps beside its unknowns (stability turned on or
     * off, floquet/stability_method.c): points stored before one are dropped (forced/) */
    unsigned long extras_serial;

    /* The monitor (monitor.c, fricreg_hb_set_monitor) and the bound on one call's Newton
     * iterations (0: none); while a solving call runs, busy (only the getters are allowed: the
     * monitor's calls), its iterations so far, and stopped once the monitor or the bound ended
     * it (its error record kept in stop_err: every retry and fallback then gives up). */
    fricreg_hb_monitor monitor;
    void *monitor_user;
    int64_t max_iterations, call_iterations;
    int busy, stopped;
    int report_omega; /* the monitor's parameter is the factored Ω, else the level λ */
    struct fr_error stop_err;

    /* What the modules above the driver hang on it (floquet/'s stability, nma/'s backbone,
     * forced/'s branch), each with the function that frees it, set by the module that made
     * it: the driver's free calls them, so no module frees the objects of another. NULL:
     * nothing hung. */
    void (*release[FR_HB_PARTS])(fricreg_hb *hb);

    struct fr_error err;
};

/* Element e's sliders: their count, stiffnesses and slip forces (friction coefficients with
 * lift-off). */
static inline size_t fr_hb_sliders(const fricreg_hb *hb, size_t e, const double **k,
                                   const double **phi)
{
    *k = hb->sk + hb->eso[e];
    *phi = hb->sk + hb->nsl + hb->eso[e];
    return hb->eso[e + 1] - hb->eso[e];
}

/* Element e's rows of J and its Jacobian block in jq, [(rows nc)²]. */
static inline size_t fr_hb_rows_of(const fricreg_hb *hb, size_t e)
{
    return hb->erow[e + 1] - hb->erow[e];
}

static inline double *fr_hb_block_of(const fricreg_hb *hb, size_t e)
{
    return hb->jq + hb->ejq[e] * hb->nc * hb->nc;
}

/* The load's factor in (R) and the displacements: λ, 0 in a nonlinear mode (no load). */
static inline double fr_hb_load(const fricreg_hb *hb)
{
    return hb->free_vibration ? 0.0 : hb->level;
}

#endif
