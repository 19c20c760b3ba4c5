/* SPDX-License-Identifier: GPL-3.0-or-later */
/* switches.c — the schedule of the exact monodromy (switches.h): for each element of a periodic
 * HB solution, its sliders' switches as the exact AFT's march finds them (joint/aft_slips.h: a
 * Jenkins slider's slip intervals, or with lift-off every stick, slip and opening with its
 * offset's reset) and its contact's closings and openings, on one time axis θ = Ω t in
 * [0, 2π), sorted; and the state each is in at θ = 0, the one its last switch leaves. */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "base/fr_math.h"
#include "joint/aft_slips.h"
#include "switches.h"
#include "base/free_all.h"

/* Switches a slider with lift-off may make in one period (aft_slips.h). */
static size_t liftoff_cap(int H)
{
    return 8 * (size_t)H + 4;
}

void fr_hb_schedule_free(struct fr_hb_schedule *sc)
{
    FR_FREE_ALL(sc->sw, sc->element, sc->k, sc->mode, sc->lo);
    memset(sc, 0, sizeof *sc);
}

int fr_hb_schedule_alloc(const fricreg_hb *hb, struct fr_hb_schedule *sc)
{
    size_t me = hb->me, S = hb->nsl, H2 = 2 * (size_t)hb->H, cap = liftoff_cap(hb->H);
    memset(sc, 0, sizeof *sc);
    sc->sw = malloc((S * cap + H2 * me + 1) * sizeof *sc->sw);
    sc->element = malloc((2 * S + 1) * sizeof *sc->element);
    sc->k = malloc((3 * S + me + 4 * hb->nc + 1) * sizeof *sc->k);
    sc->mode = malloc((2 * S + me + H2 + 1) * sizeof *sc->mode);
    sc->lo = malloc(cap * sizeof *sc->lo);
    if (!sc->sw || !sc->element || !sc->k || !sc->mode || !sc->lo) {
        fr_hb_schedule_free(sc);
        return FRICREG_ENOMEM;
    }
    sc->stuck_element = sc->element + S;
    sc->c = sc->k + S;
    sc->stuck_k = sc->c + S;
    sc->kn = sc->stuck_k + S;
    sc->scratch = sc->kn + me; /* [4 nc]: the on/off angles [2H] each, or the AFT's f, nf */
    sc->dir = sc->mode + S;
    sc->closed = sc->dir + S;
    sc->lo_dir = sc->closed + me;
    return FRICREG_OK;
}

static double angle(double theta)
{
    double t = fmod(theta, FR_TWO_PI);
    return t < 0.0 ? t + FR_TWO_PI : t >= FR_TWO_PI ? 0.0 : t;
}

static void add(struct fr_hb_schedule *sc, struct fr_hb_switch s)
{
    s.theta = angle(s.theta);
    s.seq = sc->count;
    sc->sw[sc->count++] = s;
}

/* A slider that switches joins the state: its place. */
static size_t join(struct fr_hb_schedule *sc, size_t e, double k, double c)
{
    size_t j = sc->S++;
    sc->element[j] = e;
    sc->k[j] = k;
    sc->c[j] = c;
    sc->mode[j] = FR_AFT_STICK;
    sc->dir[j] = 0;
    return j;
}

static void stuck(struct fr_hb_schedule *sc, size_t e, double k)
{
    sc->stuck_element[sc->nstuck] = e;
    sc->stuck_k[sc->nstuck++] = k;
}

/* Element e without a normal law: each slider's slip intervals (onset, then the stop). */
static int jenkins(fricreg_hb *hb, const char *fn, struct fr_hb_schedule *sc, size_t e)
{
    const double *k, *phi;
    size_t ns = fr_hb_sliders(hb, e, &k, &phi), H2 = 2 * (size_t)hb->H;
    sc->closed[e] = 1;
    sc->kn[e] = 0.0;
    for (size_t s = 0; s < ns; s++) {
        struct fr_aft_slips sl = {.on = sc->scratch, .off = sc->scratch + H2};
        int status = fr_aft_exact_slips(hb->aft, fn, k[s], phi[s], hb->qjac + hb->erow[e] * hb->nc,
                                        &sl);
        if (status != FRICREG_OK)
            return status;
        if (sl.kind == FR_AFT_STUCK)
            stuck(sc, e, k[s]);
        if (sl.kind != FR_AFT_SLIPS)
            continue;
        size_t j = join(sc, e, k[s], 0.0);
        for (int i = 0; i < sl.count; i++) {
            add(sc, (struct fr_hb_switch){sl.on[i], 0.0, j, 0, 0, FR_AFT_SLIP, 0, FR_AFT_ONSET});
            add(sc, (struct fr_hb_switch){sl.off[i], 0.0, j, 0, 0, FR_AFT_STICK, 0, FR_AFT_KEEP});
        }
    }
    return FRICREG_OK;
}

/* Two switches closer than this in θ are one instant: the march's roots are not resolved
 * finer. */
#define FR_GRAZE_THETA 1e-8

/* A slider's switches that its perturbations see, in place (lo->nsw and lo->sw): the march
 * reports a switch into the state the slider is in (its start's, a stop while it sticks, a
 * second onset while it slides) and, where the force grazes the bound, a slip of no duration, an
 * onset and its stop at one instant. Neither changes the orbit, and a graze's onset would reset
 * the offset that the perturbed orbits, which do not slip, keep. Returns the state the slider
 * is in throughout where none is left. */
static int effective_switches(struct fr_aft_liftoff *lo)
{
    int throughout = lo->nsw > 0 ? lo->sw[lo->nsw - 1].mode : FR_AFT_STICK;
    for (int changed = 1; changed && lo->nsw > 0;) {
        changed = 0;
        int now = lo->sw[lo->nsw - 1].mode, kept = 0; /* periodic: the state before the first */
        for (int i = 0; i < lo->nsw; i++) {
            if (lo->sw[i].mode == now && lo->sw[i].reset != FR_AFT_TOUCHDOWN) {
                changed = 1;
                continue;
            }
            now = lo->sw[i].mode;
            lo->sw[kept++] = lo->sw[i];
        }
        lo->nsw = kept;
        for (int i = 0; i + 1 < lo->nsw && !changed; i++) { /* a slip back where it came from */
            int before = lo->sw[i > 0 ? i - 1 : lo->nsw - 1].mode;
            if (lo->sw[i].mode == FR_AFT_SLIP && lo->sw[i + 1].mode == before &&
                fabs(lo->sw[i + 1].theta - lo->sw[i].theta) <= FR_GRAZE_THETA) {
                memmove(&lo->sw[i], &lo->sw[i + 2], (size_t)(lo->nsw - i - 2) * sizeof *lo->sw);
                lo->nsw -= 2;
                changed = 1;
            }
        }
    }
    return throughout;
}

/* Element e with lift-off: its contact's switches (from the first slider's march), and each
 * slider's. */
static int liftoff(fricreg_hb *hb, const char *fn, struct fr_hb_schedule *sc, size_t e)
{
    size_t me = hb->me, nc = hb->nc;
    const double *k, *mu, *nl = hb->nl, *u = hb->qjac + hb->erow[e] * nc;
    size_t ns = fr_hb_sliders(hb, e, &k, &mu);
    if (ns == 1) /* a Jenkins element: the normal law's kt, mu */
        k = &nl[e], mu = &nl[me + e];
    double n0 = nl[2 * me + e], kn = nl[3 * me + e];
    sc->kn[e] = kn;
    for (size_t s = 0; s < ns; s++) {
        struct fr_aft_liftoff lo = {.cap = (int)liftoff_cap(hb->H),
                                    .at = sc->scratch + 2 * nc,
                                    .dir = sc->lo_dir,
                                    .sw = sc->lo};
        int status = fr_aft_exact_normal_switches(hb->aft, fn, k[s], mu[s], n0, kn, u, u + nc,
                                                  sc->scratch, &lo);
        if (status != FRICREG_OK)
            return status;
        if (s == 0) {
            sc->closed[e] = lo.count > 0 ? lo.dir[lo.count - 1] > 0 : lo.sign > 0;
            for (int i = 0; i < lo.count; i++)
                add(sc, (struct fr_hb_switch){lo.at[i], 0.0, e, 0, 1, lo.dir[i] > 0, 0, 0});
        }
        /* a slider whose switches all vanish sticks throughout where the contact never opens */
        int throughout = lo.kind == FR_AFT_SLIPS ? effective_switches(&lo) : FR_AFT_OPEN;
        int closed_throughout = lo.count == 0 && lo.sign > 0;
        if (lo.kind == FR_AFT_STUCK || (lo.kind == FR_AFT_SLIPS && lo.nsw == 0 &&
                                        throughout == FR_AFT_STICK && closed_throughout))
            stuck(sc, e, k[s]);
        if (lo.kind != FR_AFT_SLIPS || lo.nsw == 0)
            continue;
        size_t j = join(sc, e, k[s], mu[s] * kn);
        for (int i = 0; i < lo.nsw; i++) {
            const struct fr_aft_switch *w = &lo.sw[i];
            add(sc, (struct fr_hb_switch){w->theta, w->ratio, j, 0, 0, w->mode, w->dir, w->reset});
        }
    }
    return FRICREG_OK;
}

static int by_angle(const void *x, const void *y)
{
    const struct fr_hb_switch *a = x, *b = y;
    if (a->theta != b->theta)
        return (a->theta > b->theta) - (a->theta < b->theta);
    return (a->seq > b->seq) - (a->seq < b->seq);
}

int fr_hb_schedule(fricreg_hb *hb, const char *fn, struct fr_hb_schedule *sc)
{
    sc->S = sc->nstuck = sc->count = 0;
    for (size_t e = 0; e < hb->me; e++) {
        int status = hb->kind[e] == FR_HB_SLIDERS ? jenkins(hb, fn, sc, e) : liftoff(hb, fn, sc, e);
        if (status != FRICREG_OK)
            return fr_fail(hb, status, "%s: stability: the AFT of element %zu failed: %s", fn, e,
                           fricreg_aft_errmsg(hb->aft));
    }
    qsort(sc->sw, sc->count, sizeof *sc->sw, by_angle);
    for (size_t i = 0; i < sc->count; i++) { /* the state at θ = 0: the last switch's */
        const struct fr_hb_switch *s = &sc->sw[i];
        if (s->contact)
            sc->closed[s->index] = s->mode;
        else
            sc->mode[s->index] = s->mode, sc->dir[s->index] = s->dir;
    }
    return FRICREG_OK;
}

int fr_hb_schedule_half_wave(const fricreg_hb *hb, const struct fr_hb_schedule *sc)
{
    size_t h = sc->count / 2;
    if (hb->rpe != 1 || sc->count == 0 || sc->count % 2 != 0)
        return 0;
    for (size_t j = 0; j < sc->S; j++)
        if (sc->c[j] != 0.0)
            return 0;
    for (size_t i = 0; i < h; i++) {
        const struct fr_hb_switch *a = &sc->sw[i], *b = &sc->sw[i + h];
        double shift = b->theta - a->theta - 0.5 * FR_TWO_PI;
        if (a->contact || b->contact || a->index != b->index || a->mode != b->mode ||
            a->reset != b->reset || !(fabs(shift) <= FR_HB_HALF_WAVE_TOL))
            return 0;
    }
    return 1;
}
