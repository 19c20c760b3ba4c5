/* SPDX-License-Identifier: GPL-3.0-or-later */
/* aft_normal_exact.c — the exact AFT of a 1-D Jenkins element under normal load with lift-off
 * (fricreg_aft_jenkins_normal_exact): the pieces of the periodic response located as roots of
 * trigonometric polynomials and integrated in closed form (aft_roots.c's root isolation, Brent
 * and Gram matrices), the counterpart of aft_normal.c's sampled march.
 *
 * With the gap P(θ) = N0 + kn g(θ), the bound is mu max(0, P). Three kinds of piece:
 *   open   (P < 0): f = 0, N = 0; at the touchdown (P rising through 0) the slider takes w = u,
 *          the spring unstressed;
 *   stick  f = kt (u − w), w constant, until the margin c_s = s kt (u − w) − mu P reaches 0
 *          rising, s = ±1 (then slip s), or P falls through 0 (then open);
 *   slip s f = s mu P, w = u − s mu P/kt, until the slider's velocity
 *          v_s = u' − s mu kn g'/kt changes sign against s (then stick), or P falls through 0.
 * Since c_s' = s kt v_s, c_s is monotone between consecutive sign changes of v_s: each onset is
 * bracketed in one such arc (the arc where c_s rises and ends positive) and found by GSL's
 * Brent, as the constant-bound path does between the reversals of u. The sign changes of v+,
 * v− and P are found once per call (fr_aft_sign_changes).
 *
 * The periodic state. With an opening the march starts at a touchdown (memory reset) and one
 * period is periodic. Without, it starts at the maximum of u with the slider at the positive
 * bound (w = u − mu P/kt, the constant-bound path's wiping-out state) and periods are marched
 * until the state at the start repeats to the bit (at most MAX_PERIODS): a period that slips
 * both ways ends on a slip whose end is a fixed root, so the state repeats from the second
 * period. A period with no slip, or slips one way only (which at the periodic state have no
 * length: the slider touches the bound), takes the centred slider w = (max u + min u)/2 where
 * it holds (the margins c_s <= 0 at their maxima, the sign changes of v_s), else the stuck
 * slider nearest it: the stuck sliders are [lo, hi], lo = max (u − mu P/kt), hi =
 * min (u + mu P/kt), the march's state is lo, and a centre above hi takes hi (anchored where
 * c_- is largest, as after a negative slip), so that the state is continuous where the centre
 * leaves [lo, hi]; as the sampled path does; with kn = 0 this is fricreg_aft_jenkins_exact at
 * mun = mu N0 (the centre is in [lo, hi] whenever that is not empty).
 *
 * The Jacobian. f and N are continuous at every switch point, so the switch points' motion adds
 * nothing: the Jacobian is the integral of the pointwise derivatives. Slip s: ∂f/∂g_j =
 * s mu kn φ_j. Stick after a slip s ended at θw (v_s(θw) = 0): ∂f/∂u_j = kt (φ_j − φ_j(θw)),
 * ∂f/∂g_j = s mu kn φ_j(θw). Stick after a touchdown at θt (w = u(θt), θt moving with g by
 * ∂θt/∂g_j = −φ_j(θt)/g'(θt)): ∂f/∂u_j = kt (φ_j − φ_j(θt)), ∂f/∂g_j = kt u'(θt) φ_j(θt)/g'(θt).
 * N = P on the closed arcs: ∂N/∂g_j = kn φ_j there. */
#include <float.h>
#include <math.h>
#include <string.h>

#include "aft_internal.h"
#include "aft_slips.h"
#include "base/fr_math.h"

#define MAX_PERIODS 16 /* periods marched in search of the periodic state without opening */

enum mode { OPEN, STICK, SLIP };

/* The march's state: the mode, the slip direction or the anchor's, the slider as the force
 * kw = kt w (w = u − mu P/kt overflows for a subnormal kt, kt u − mu P does not), and where
 * it was anchored (a slip's end, or a touchdown when touch is set). */
struct state {
    enum mode mode;
    int dir, touch;
    double kw, th;
};

/* A set of sign changes: angles in [0, 2pi), the sign after each, and the sign throughout when
 * there are none. */
struct changes {
    const double *r;
    const int *d;
    int m, sign;
};

struct march {
    fricreg_aft *a;
    double kt, mu, n0, kn;
    const double *u, *g, *gap;  /* coefficients (copies), and of P = N0 + kn g */
    double *cs;                 /* coefficients of a margin c_s */
    struct changes v[2], p;     /* v[0]: v+, v[1]: v-; p: the gap */
    double *jac;                /* 2nc x 2nc or NULL */
    int moved;                  /* the period's slips: 1 positive, 2 negative, 3 both */
    int unresolved;             /* sticks below the rounding of u: they take no time */
    struct fr_aft_liftoff *rec; /* the period's switches recorded (NULL: not) */
};

/* The switch into st at th recorded (when recording), with its reset. */
static void record(struct march *s, const struct state *st, double th, int reset)
{
    struct fr_aft_liftoff *lo = s->rec;
    if (lo == NULL)
        return;
    if (lo->nsw >= lo->cap) {
        lo->nsw = lo->cap + 1; /* overflowed: the caller fails */
        return;
    }
    double ratio = 0.0;
    if (reset == FR_AFT_TOUCHDOWN) {
        double du, dg;
        fr_aft_trig_eval(s->a->H, s->u, th, &du);
        fr_aft_trig_eval(s->a->H, s->g, th, &dg);
        ratio = dg != 0.0 ? du / dg : 0.0; /* a grazing touchdown: 0, as the AFT's Jacobian */
        if (!(fabs(ratio) <= 1e150))
            ratio = 0.0;
    }
    int mode = st->mode == OPEN ? FR_AFT_OPEN : st->mode == STICK ? FR_AFT_STICK : FR_AFT_SLIP;
    lo->sw[lo->nsw++] = (struct fr_aft_switch){th, ratio, mode, st->dir, reset};
}

/* The first sign change of c after th (strictly), with the sign want after it (0: any), as an
 * absolute angle; its index into *k. INFINITY if none. */
static double next_change(const struct changes *c, int want, double th, int *k)
{
    double base = floor(th / FR_TWO_PI) * FR_TWO_PI, best = INFINITY;
    for (int i = 0; i < c->m; i++) {
        if (want != 0 && c->d[i] != want)
            continue;
        double t = base + c->r[i];
        if (!(t > th))
            t += FR_TWO_PI;
        if (t < best) {
            best = t;
            *k = i;
        }
    }
    return best;
}

static double eval(const struct march *s, const double *co, double th)
{
    double d;
    return fr_aft_trig_eval(s->a->H, co, th, &d);
}

/* The margin c_dir = dir (kt u − kw) − mu P as coefficients into s->cs. */
static void margin(struct march *s, int dir, double kw)
{
    for (size_t j = 0; j < s->a->nc; j++)
        s->cs[j] = dir * s->kt * s->u[j] - s->mu * s->gap[j];
    s->cs[0] -= dir * kw;
}

/* The first stick→slip onset in direction dir after th and before lim (INFINITY if none): in
 * the arcs of v_dir where c_dir rises, the first whose end has c_dir > 0. */
static double onset(struct march *s, int dir, double kw, double th, double lim)
{
    const struct changes *v = &s->v[dir > 0 ? 0 : 1];
    margin(s, dir, kw);
    for (double pos = th; pos < lim;) {
        int k = 0;
        double t = next_change(v, 0, pos, &k), end = fmin(t, lim);
        int sg = v->m > 0 ? -v->d[k] : v->sign; /* sign of v on (pos, t) */
        if (dir * sg > 0 && eval(s, s->cs, end) > 0.0)
            return eval(s, s->cs, pos) >= 0.0 ? pos : fr_aft_root_in(s->a, s->cs, pos, end);
        pos = end;
    }
    return INFINITY;
}

/* The slip that starts at th where sticks take no time: the direction d whose slider velocity
 * v_d has the sign d on the arc after th (0 if neither: the onsets then decide). */
static int slip_at_once(const struct march *s, double th)
{
    for (int d = 1; d >= -1; d -= 2) {
        const struct changes *v = &s->v[d > 0 ? 0 : 1];
        int k = 0;
        next_change(v, 0, th, &k);
        if (d * (v->m > 0 ? -v->d[k] : v->sign) > 0)
            return d;
    }
    return 0;
}

/* A stick piece [al, be] of the slider st. */
static void add_stick(struct march *s, const struct state *st, double al, double be)
{
    fricreg_aft *a = s->a;
    size_t nc = a->nc;
    fr_aft_add_stick(a, s->kt, s->u, st->kw, st->th, al, be, s->jac != NULL);
    if (s->jac == NULL)
        return;
    double c;
    fr_aft_basis(a->H, st->th, a->phw);
    if (st->touch) {
        double du, dg;
        fr_aft_trig_eval(a->H, s->u, st->th, &du);
        fr_aft_trig_eval(a->H, s->g, st->th, &dg);
        /* a touchdown that grazes, g' = 0 or kt u'/g' beyond DBL_MAX / (8 nc) (whose
         * contributions, summed over the pieces, overflowed), moves with g without bound: 0,
         * as the sampled path's touchdown on a sample */
        c = dg != 0.0 ? s->kt * du / dg : 0.0;
        if (!(fabs(c) <= DBL_MAX / (8.0 * (double)nc)))
            c = 0.0;
    } else {
        c = st->dir * s->mu * s->kn;
    }
    for (size_t i = 0; i < nc; i++)
        for (size_t j = 0; j < nc; j++)
            s->jac[2 * nc * i + nc + j] += fr_aft_weight(i) * c * a->phw[j] * a->gram[nc * i];
}

/* A slip piece [al, be] in direction dir: f = dir mu P. */
static void add_slip(struct march *s, int dir, double al, double be)
{
    fricreg_aft *a = s->a;
    size_t nc = a->nc;
    fr_aft_gram(a, al, be);
    const double *G = a->gram;
    for (size_t i = 0; i < nc; i++) {
        double v = 0.0; /* mu P's integral: mu first, which a subnormal N0 (5e-324) needs */
        for (size_t j = 0; j < nc; j++)
            v += G[nc * i + j] * (s->mu * s->gap[j]);
        a->fout[i] += fr_aft_weight(i) * dir * v;
        if (s->jac != NULL)
            for (size_t j = 0; j < nc; j++)
                s->jac[2 * nc * i + nc + j] += fr_aft_weight(i) * dir * s->mu * s->kn *
                                               G[nc * i + j];
    }
    s->moved |= dir > 0 ? 1 : 2;
}

/* March one period [th0, th0 + 2pi) from *st, accumulating f into fout, jout and jac's
 * df/dg block (zeroed here); *st becomes the state at the end. */
static void period(struct march *s, struct state *st, double th0)
{
    fricreg_aft *a = s->a;
    size_t nc = a->nc;
    memset(a->fout, 0, nc * sizeof *a->fout);
    memset(a->jout, 0, nc * nc * sizeof *a->jout);
    if (s->jac != NULL)
        for (size_t i = 0; i < nc; i++)
            memset(&s->jac[2 * nc * i + nc], 0, nc * sizeof *s->jac);
    s->moved = 0;
    double th = th0, the = th0 + FR_TWO_PI;
    int k = 0;
    if (s->rec != NULL)
        s->rec->nsw = 0;
    record(s, st, th0, st->mode == STICK && st->touch && st->th == th0 ? FR_AFT_TOUCHDOWN : 0);
    while (th < the) {
        if (st->mode == OPEN) {
            double t = next_change(&s->p, 1, th, &k);
            if (t >= the)
                return;
            *st = (struct state){STICK, 0, 1, s->kt * eval(s, s->u, t), t};
            th = t;
            record(s, st, t, FR_AFT_TOUCHDOWN);
        } else if (st->mode == STICK && s->unresolved && slip_at_once(s, th) != 0) {
            st->dir = slip_at_once(s, th);
            st->mode = SLIP;
            record(s, st, th, FR_AFT_ONSET);
        } else if (st->mode == STICK) {
            double t_open = fmin(next_change(&s->p, -1, th, &k), the);
            double tp = onset(s, 1, st->kw, th, t_open), tm = onset(s, -1, st->kw, th, t_open);
            double t_slip = fmin(tp, tm), t = fmin(t_open, t_slip);
            if (t > th)
                add_stick(s, st, th, t);
            if (t_open <= t_slip) { /* an opening first (or the period's end) */
                if (t < the) {
                    st->mode = OPEN;
                    record(s, st, t, FR_AFT_KEEP);
                }
            } else {
                st->mode = SLIP;
                st->dir = tp <= tm ? 1 : -1;
                record(s, st, t, FR_AFT_ONSET);
            }
            th = t;
        } else {
            const struct changes *v = &s->v[st->dir > 0 ? 0 : 1];
            /* the slip stops at the next sign change of v against dir, or at once where the
             * arc it starts on already has v against dir (a start on a sign change, which
             * rounding may put on either side of it) */
            next_change(v, 0, th, &k);
            int arc = v->m > 0 ? -v->d[k] : v->sign;
            double t_open = next_change(&s->p, -1, th, &k);
            double t_stop = st->dir * arc < 0 ? th : next_change(v, -st->dir, th, &k);
            double t = fmin(fmin(t_open, t_stop), the);
            if (t > th)
                add_slip(s, st->dir, th, t);
            if (t < the && t_open <= t_stop) {
                st->mode = OPEN;
                record(s, st, t, FR_AFT_KEEP);
            } else if (t < the || t_stop == the) {
                double kw = s->kt * eval(s, s->u, t) - st->dir * s->mu * eval(s, s->gap, t);
                *st = (struct state){STICK, st->dir, 0, kw, t};
                if (t < the)
                    record(s, st, t, FR_AFT_KEEP);
            }
            th = t;
        }
    }
}

/* The sign changes of co (nc coefficients, scaled here into co) into set i of the workspace. */
static int changes_of(fricreg_aft *a, const char *fn, double *co, int i, struct changes *c)
{
    double big = 0.0, top = fabs(co[0]);
    for (size_t j = 1; j < a->nc; j++)
        big = fmax(big, fabs(co[j]));
    top = fmax(top, big);
    *c = (struct changes){a->nroot + 2 * a->H * i, a->ndir + 2 * a->H * i, 0, 0};
    if (big <= 1e-15 * top || top == 0.0) { /* constant (to rounding): its sign */
        c->sign = (co[0] > 0.0) - (co[0] < 0.0);
        return FRICREG_OK;
    }
    for (size_t j = 0; j < a->nc; j++)
        co[j] /= top;
    int status = fr_aft_sign_changes(a, fn, co, a->nroot + 2 * a->H * i, a->ndir + 2 * a->H * i,
                                     &c->m);
    if (status == FRICREG_OK && c->m == 0) { /* one sign: the largest of a few probes */
        double best = 0.0, d;
        for (int q = 0; q < 8 * a->H; q++) {
            double v = fr_aft_trig_eval(a->H, co, FR_TWO_PI * q / (8 * a->H), &d);
            if (fabs(v) > fabs(best))
                best = v;
        }
        c->sign = (best > 0.0) - (best < 0.0);
    }
    return status;
}

/* Which margin the centred slider wc breaks, checked at the maxima of c_s (the sign changes of
 * v_s, or anywhere when v_s keeps one sign): 0 neither; 1 c_+ (wc below the least stuck
 * slider: the march's own periodic state, from the positive bound, is then that least one);
 * -1 c_- alone (wc above the greatest stuck slider), with *th where c_- is largest, the greatest
 * slider's anchor. */
static int centred_breaks(struct march *s, double wc, double *th)
{
    int breaks = 0;
    for (int i = 0; i < 2 && breaks == 0; i++) {
        int dir = i == 0 ? 1 : -1;
        double top = 0.0;
        margin(s, dir, s->kt * wc);
        if (s->v[i].m == 0 && eval(s, s->cs, 0.0) > 0.0) {
            *th = 0.0;
            breaks = dir;
        }
        for (int k = 0; k < s->v[i].m; k++) {
            double c = eval(s, s->cs, s->v[i].r[k]);
            if (c > top) {
                top = c;
                *th = s->v[i].r[k];
                breaks = dir;
            }
        }
    }
    return breaks;
}

/* The normal force's coefficients and Jacobian block over the closed arcs. */
static void normal_force(struct march *s, double *nf)
{
    fricreg_aft *a = s->a;
    size_t nc = a->nc;
    memset(nf, 0, nc * sizeof *nf);
    int k = 0;
    for (int i = 0; i < (s->p.m > 0 ? s->p.m : 1); i++) {
        double al = 0.0, be = FR_TWO_PI;
        if (s->p.m > 0) {
            if (s->p.d[i] < 0)
                continue;
            al = s->p.r[i];
            be = next_change(&s->p, -1, al, &k);
        }
        fr_aft_gram(a, al, be);
        const double *G = a->gram;
        for (size_t r = 0; r < nc; r++) {
            double v = 0.0;
            for (size_t j = 0; j < nc; j++)
                v += G[nc * r + j] * s->gap[j];
            nf[r] += fr_aft_weight(r) * v;
            if (s->jac != NULL)
                for (size_t j = 0; j < nc; j++)
                    s->jac[2 * nc * (nc + r) + nc + j] += fr_aft_weight(r) * s->kn * G[nc * r + j];
        }
    }
}

/* fr_aft_exact_normal, its march's switches recorded into rec when not NULL (its kind and the
 * contact's schedule set by the caller from the march). */
static int exact_normal(fricreg_aft *a, const char *fn, double kt, double mu, double n0, double kn,
                        const double *u, const double *g, double *f, double *nf, double *jac,
                        struct fr_aft_liftoff *rec)
{
    int H = a->H;
    size_t nc = a->nc;
    double *vp = a->ncoef, *vm = vp + nc, *gap = vm + nc, *cs = gap + nc, *uc = cs + nc,
           *gc = uc + nc;
    memcpy(uc, u, nc * sizeof *uc);
    memcpy(gc, g, nc * sizeof *gc);
    struct march s = {a, kt, mu, n0, kn, uc, gc, gap, cs, {{0}}, {0}, NULL, 0, 0, rec};
    for (size_t j = 0; j < nc; j++)
        cs[j] = kn * gc[j];
    cs[0] += n0;
    int status = changes_of(a, fn, cs, 2, &s.p); /* scales cs: gap keeps P itself */
    for (size_t j = 0; j < nc; j++)
        gap[j] = kn * gc[j];
    gap[0] += n0;
    double psum = 0.0, usum = 0.0;
    for (size_t j = 0; j < nc; j++) {
        psum += fabs(gap[j]);
        usum += fabs(uc[j]);
    }
    /* a bound mu max P that underflows to 0 (mu 1e-270 against P of 1e-323) is 0: f = 0, as
     * for mu = 0 (the stick and slip decisions on numbers below the subnormals' spacing gave
     * forces of kt u's order against a bound of 0) */
    double thmax = 0.0, thmin = 0.0;
    int open_throughout = s.p.m == 0 && s.p.sign <= 0;
    int slides = mu * psum > 0.0 && !open_throughout;
    if (status == FRICREG_OK && slides) {
        /* kt v_± / 64 = (kt u' ∓ mu kn g') / 64, whose sign changes are v_±'s: every product
         * stays finite under the input checks (8 max(1, kt) sum |u_j| and
         * 8 (1 + mu)(|n0| + kn (1 + sum |g_j|)) finite; h <= 40), where h g_h mu kn / kt
         * overflowed for g_h near DBL_MAX with a subnormal kn, and the slider's velocity came
         * out infinite */
        for (int h = 1; h <= H; h++) {
            double dub = h * (kt * (uc[2 * h] / 64.0)), dua = -h * (kt * (uc[2 * h - 1] / 64.0));
            double dgb = h * (kn * gc[2 * h] * mu / 64.0),
                   dga = -h * (kn * gc[2 * h - 1] * mu / 64.0);
            vp[2 * h - 1] = dub - dgb;
            vp[2 * h] = dua - dga;
            vm[2 * h - 1] = dub + dgb;
            vm[2 * h] = dua + dga;
        }
        vp[0] = vm[0] = 0.0;
        status = changes_of(a, fn, vp, 0, &s.v[0]);
        if (status == FRICREG_OK)
            status = changes_of(a, fn, vm, 1, &s.v[1]);
        if (status == FRICREG_OK)
            status = fr_aft_extremes(a, fn, uc, &thmax, &thmin);
    }
    if (status != FRICREG_OK)
        return status;
    /* kt sum |u_j| first: 1e-12 kt underflowed for a subnormal kt */
    s.unresolved = mu * psum <= UNRESOLVED_STICK * (kt * usum);
    /* nothing fails from here on: the outputs are written directly (u, g were copied) */
    s.jac = jac;
    if (jac != NULL)
        memset(jac, 0, 4 * nc * nc * sizeof *jac);
    memset(a->fout, 0, nc * sizeof *a->fout);
    memset(a->jout, 0, nc * nc * sizeof *a->jout);
    if (rec != NULL) { /* the contact's schedule, and no tangential force unless it slides */
        rec->count = s.p.m;
        rec->sign = s.p.sign;
        memcpy(rec->at, s.p.r, (size_t)s.p.m * sizeof *rec->at);
        memcpy(rec->dir, s.p.d, (size_t)s.p.m * sizeof *rec->dir);
        rec->kind = slides ? FR_AFT_SLIPS : FR_AFT_SLIDES;
        rec->nsw = 0;
    }
    if (open_throughout) {
        memset(f, 0, nc * sizeof *f);
        memset(nf, 0, nc * sizeof *nf);
        return FRICREG_OK;
    }
    normal_force(&s, a->dcoef);
    if (slides && s.p.m > 0) { /* one period from a touchdown */
        double t0 = 0.0;
        for (int k = s.p.m - 1; k >= 0; k--)
            if (s.p.d[k] > 0)
                t0 = s.p.r[k];
        struct state st = {STICK, 0, 1, kt * eval(&s, uc, t0), t0};
        period(&s, &st, t0);
    } else if (slides) {
        struct state st = {STICK, 1, 0, kt * eval(&s, uc, thmax) - mu * eval(&s, gap, thmax),
                           thmax};
        for (int p = 0; p < MAX_PERIODS; p++) {
            struct state st0 = st;
            period(&s, &st, thmax);
            if (st.mode == st0.mode && st.dir == st0.dir && st.kw == st0.kw)
                break;
        }
        int constant_u = 1;
        for (size_t j = 1; j < nc; j++)
            constant_u &= uc[j] == 0.0;
        double wc = constant_u ? uc[0] : 0.5 * (eval(&s, uc, thmax) + eval(&s, uc, thmin));
        /* stuck, or slipping one way only (at the periodic state such a slip has no length:
         * the slider touches the bound, its place a leftover of the start): the centred
         * slider where it holds, else the stuck slider nearest it, so that the state moves
         * continuously as the stuck sliders [lo, hi] shrink past it (the march gives lo) */
        double thhi = 0.0;
        int breaks = s.moved != 3 ? centred_breaks(&s, wc, &thhi) : 1;
        if (breaks == -1) { /* wc above hi: the slider at hi, anchored as a negative slip's end */
            struct state hi = {STICK, -1, 0, kt * eval(&s, uc, thhi) + mu * eval(&s, gap, thhi),
                               thhi};
            period(&s, &hi, thmax);
        }
        if (breaks == 0) {
            if (rec != NULL)
                rec->kind = FR_AFT_STUCK;
            a->fout[0] = kt * (uc[0] - wc);
            for (size_t j = 1; j < nc; j++)
                a->fout[j] = kt * uc[j];
            memset(a->jout, 0, nc * nc * sizeof *a->jout);
            if (jac != NULL)
                for (size_t i = 0; i < nc; i++)
                    memset(&jac[2 * nc * i + nc], 0, nc * sizeof *jac);
            double *pmax = a->phw, *pmin = a->cm; /* cm is free scratch after the march */
            fr_aft_basis(H, thmax, pmax);
            fr_aft_basis(H, thmin, pmin);
            for (size_t j = 1; j < nc; j++) {
                if (!constant_u)
                    a->jout[j] = -0.5 * kt * (pmax[j] + pmin[j]);
                a->jout[nc * j + j] = kt;
            }
        }
    }
    memcpy(f, a->fout, nc * sizeof *f);
    memcpy(nf, a->dcoef, nc * sizeof *nf);
    if (jac != NULL)
        for (size_t i = 0; i < nc; i++)
            memcpy(&jac[2 * nc * i], &a->jout[nc * i], nc * sizeof *jac);
    return FRICREG_OK;
}

int fr_aft_exact_normal(fricreg_aft *a, const char *fn, double kt, double mu, double n0, double kn,
                        const double *u, const double *g, double *f, double *nf, double *jac)
{
    return exact_normal(a, fn, kt, mu, n0, kn, u, g, f, nf, jac, NULL);
}

int fr_aft_exact_normal_switches(fricreg_aft *a, const char *fn, double kt, double mu, double n0,
                                 double kn, const double *u, const double *g, double *scratch,
                                 struct fr_aft_liftoff *lo)
{
    size_t nc = a->nc;
    int status = exact_normal(a, fn, kt, mu, n0, kn, u, g, scratch, scratch + nc, NULL, lo);
    if (status == FRICREG_OK && lo->nsw > lo->cap)
        return fr_fail(a, FRICREG_EINTEGRATOR,
                       "%s: the slider switches more than %d times in a period", fn, lo->cap);
    return status;
}
