/* SPDX-License-Identifier: GPL-3.0-or-later */
/* reproduce_beyond.c — the part of `fricreg-sim reproduce` beyond the paper: the reference
 * problems (src/problems/, docs/laws2d.md) and a frequency response by harmonic balance
 * (docs/harmonic_balance.md), one CSV each beside the paper's figures, and their rows in the table.
 * Small runs: a few seconds in all. */
#include <math.h>
#include <stdlib.h>

#include "out_file.h"

#include "cli.h"
#include "fricreg_element.h"
#include "fricreg_hb.h"
#include "problems.h"

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)
/* D per forcing cycle of the 2-D oscillator, law quinn at eps = 2e-5, dt = 1e-5
 * (fricreg-bench-disk; docs/laws2d.md). */
#define DISK_D_REFERENCE 10.016060881132

/* Rows of a curve number and up to 5 columns, every `every`-th observation kept. */
struct rows {
    size_t n, cap, seen, every;
    int curve; /* column 0 of each row */
    double (*data)[6];
};

static int keep(struct rows *r, const double v[5])
{
    if (r->seen++ % r->every != 0)
        return 0;
    if (r->n == r->cap) {
        size_t cap = r->cap ? 2 * r->cap : 1024;
        double(*data)[6] = realloc(r->data, cap * sizeof *data);
        if (data == NULL)
            return 1;
        r->data = data, r->cap = cap;
    }
    r->data[r->n][0] = r->curve;
    for (int k = 0; k < 5; k++)
        r->data[r->n][k + 1] = v[k];
    r->n++;
    return 0;
}

/* hold: t, the tilt in degrees and the speed |v|. */
static int hold_row(void *user, double t, const double row[], size_t n)
{
    (void)n;
    const double v[5] = {t, row[0] / DEG, hypot(row[3], row[4]), 0.0, 0.0};
    return keep(user, v);
}

/* belt: t, x, x'. */
static int belt_row(void *user, double t, const double row[], size_t n)
{
    (void)n;
    const double v[5] = {t, row[0], row[1], 0.0, 0.0};
    return keep(user, v);
}

/* disk: t, x1, x2, f1, f2. */
static int disk_row(void *user, double t, const double row[], size_t n)
{
    (void)n;
    const double v[5] = {t, row[0], row[1], row[4], row[5]};
    return keep(user, v);
}

/* Writes rows (columns first..last of each) under header into dir/name. Returns 0 or 1. */
static int write_rows(const char *dir, const char *name, const char *header,
                      const struct rows *const sets[], int nsets, int first, int last)
{
    struct cli_out o;
    if (cli_out_open(&o, dir, name) != 0)
        return 1;
    fprintf(o.f, "%s\n", header);
    for (int s = 0; s < nsets; s++)
        for (size_t i = 0; i < sets[s]->n; i++) {
            for (int k = first; k <= last; k++)
                fprintf(o.f, k == first ? "%.10g" : ",%.10g", sets[s]->data[i][k]);
            fputc('\n', o.f);
        }
    return cli_out_commit(&o);
}

static int failed(const char *what, int status)
{
    fprintf(stderr, "fricreg-sim: reproduce: %s: %s\n", what, fricreg_strerror(status));
    return 1;
}

/* The block on the incline (tests/law/test_hold.c's): creep from rest inside the disk, then the
 * incline tilted at 0.02 rad/s from 0.9 atan(mu) through the break-away. */
static int hold(const char *dir)
{
    struct prob_hold p = {.mass = 2.385,
                          .g = 9.81,
                          .mu = 0.5385,
                          .phi = 0.6180339887,
                          .dt = 1e-4,
                          .eps = 2e-3,
                          .steps = 100000};
    struct prob_hold_result r;
    p.theta0 = atan(0.8 * p.mu);
    int status = prob_hold_run(&p, NULL, NULL, &r);
    if (status != FRICREG_OK)
        return failed("hold", status);
    double creep = r.creep;
    p.theta0 = 0.9 * atan(p.mu), p.kappa = 0.02, p.steps = 1e6;
    struct rows rows = {.every = 5, .curve = -1};
    status = prob_hold_run(&p, hold_row, &rows, &r);
    const struct rows *sets[1] = {&rows};
    int bad = status != FRICREG_OK
                  ? failed("hold", status)
                  : write_rows(dir, "hold_breakaway.csv", "t,theta_deg,speed", sets, 1, 1, 3);
    free(rows.data);
    if (bad)
        return 1;
    double angle = 0.5 * (r.theta_rest + r.theta_moving) / DEG, exact = atan(p.mu) / DEG;
    char paper[32], d[48];
    snprintf(paper, sizeof paper, "%.6f atan mu", exact);
    snprintf(d, sizeof d, "%+.1e (<= kappa dt %.1e)", angle - exact, p.kappa * p.dt / DEG);
    cli_table_row("hold", "creep (m/s), tan(theta) = 0.8 mu, 1e5 steps", "0 (exact stick)", creep,
                  "");
    cli_table_row("hold", "break-away tilt (deg), 0.02 rad/s", paper, angle, d);
    return 0;
}

/* The belt-driven Stribeck oscillator at dt 0.0025, eps 0.005: its 12th cycle in the phase
 * plane beside the event-driven reference's. */
static int belt(const char *dir)
{
    struct prob_belt p = prob_belt_defaults();
    struct prob_belt_cycle ref, c;
    struct rows reg = {.every = 1, .curve = 0}, exact = {.every = 50, .curve = 1};
    p.dt = 0.0025, p.eps = 0.005;
    int status = prob_belt_reference(&p, belt_row, &exact, &ref);
    if (status == FRICREG_OK)
        status = prob_belt_regularized(&p, 0.5 * (ref.x_min + ref.x_max), belt_row, &reg, &c);
    const struct rows *sets[2] = {&exact, &reg};
    int bad = status != FRICREG_OK
                  ? failed("belt", status)
                  : write_rows(dir, "belt_limit_cycle.csv", "curve,t,x,v", sets, 2, 0, 3);
    free(reg.data);
    free(exact.data);
    if (bad)
        return 1;
    char p_ref[32], a_ref[32], dp[32], da[32];
    snprintf(p_ref, sizeof p_ref, "%.6f (ref.)", ref.period);
    snprintf(a_ref, sizeof a_ref, "%.6f (ref.)", ref.amplitude);
    snprintf(dp, sizeof dp, "%+.1e rel.", c.period / ref.period - 1.0);
    snprintf(da, sizeof da, "%+.1e rel.", c.amplitude / ref.amplitude - 1.0);
    cli_table_row("belt", "Stribeck limit cycle: period, dt 0.0025", p_ref, c.period, dp);
    cli_table_row("belt", "Stribeck limit cycle: amplitude, dt 0.0025", a_ref, c.amplitude, da);
    return 0;
}

/* The 2-D oscillator with rotating forcing, law quinn at dt 0.01: its path and its friction
 * force in the plane over the measured turn. */
static int disk(const char *dir)
{
    struct prob_disk p = prob_disk_defaults();
    struct prob_disk_result r;
    struct rows rows = {.every = 2, .curve = -1};
    int status = prob_disk_run(&p, disk_row, &rows, &r);
    const struct rows *sets[1] = {&rows};
    int bad = status != FRICREG_OK
                  ? failed("disk", status)
                  : write_rows(dir, "disk_oscillator.csv", "t,x1,x2,f1,f2", sets, 1, 1, 5);
    free(rows.data);
    if (bad)
        return 1;
    char ref[32], d[32];
    snprintf(ref, sizeof ref, "%.6f (ref.)", DISK_D_REFERENCE);
    snprintf(d, sizeof d, "%+.1e rel.", r.dissipation / DISK_D_REFERENCE - 1.0);
    cli_table_row("2-D", "D/cycle, rotating forcing, quinn, dt 0.01", ref, r.dissipation, d);
    return 0;
}

/* The chain of tests/hb/test_hb.c: three masses on springs, Rayleigh damping 0.03 M + 0.01 K,
 * a Jenkins element from mass 3 to the ground and one between masses 1 and 2, mass 1 excited
 * at 0.8 cos + 0.25 sin; harmonic balance at H = 7 over its first resonance with slip forces
 * scaled by `scale` (0: the elements slip freely; 1e6: stuck), into rows of curve `curve`:
 * Omega and the RMS of the three masses. The peak of mass 1 into *peak, *w_peak. */
static int hb_chain(double scale, int curve, struct rows *rows, double *peak, double *w_peak)
{
    const double M[9] = {1.1, 0, 0, 0, 0.9, 0, 0, 0, 1.25};
    const double K[9] = {5.3, -2.1, 0, -2.1, 3.7, -1.6, 0, -1.6, 1.6};
    const double J[6] = {0, 0, 1, -1, 1, 0}, pc[3] = {0.8, 0, 0}, ps[3] = {0.25, 0, 0};
    const double params[4] = {2.5, 0.3 * scale, 1.4, 0.12 * scale}; /* kt mun per element */
    fricreg_hb *hb = NULL;
    int status = fricreg_hb_create(3, 2, 7, &hb);
    if (status == FRICREG_OK && (status = fricreg_hb_set_mass(hb, 3, M)) == FRICREG_OK &&
        (status = fricreg_hb_set_stiffness(hb, 3, K)) == FRICREG_OK &&
        (status = fricreg_hb_set_rayleigh(hb, 0.03, 0.01)) == FRICREG_OK &&
        (status = fricreg_hb_add_elements(hb, fricreg_element_lookup("jenkins"), 2, 3, J,
                                          params)) == FRICREG_OK &&
        (status = fricreg_hb_set_excitation(hb, 3, pc, ps)) == FRICREG_OK &&
        (status = fricreg_hb_set_continuation(hb, 0.01, 1e-6, 0.02, 2000)) == FRICREG_OK)
        status = fricreg_hb_continue(hb, 0.5, 1.38, 2 * 15, NULL);
    *peak = 0.0;
    rows->curve = curve;
    for (size_t k = 0; status == FRICREG_OK && k < fricreg_hb_points(hb); k++) {
        double w, rms[3];
        if ((status = fricreg_hb_point(hb, k, &w, 3, rms)) != FRICREG_OK)
            break;
        const double v[5] = {w, rms[0], rms[1], rms[2], 0.0};
        if (keep(rows, v) != 0)
            status = FRICREG_ENOMEM;
        if (rms[0] > *peak)
            *peak = rms[0], *w_peak = w;
    }
    fricreg_hb_free(hb);
    return status;
}

/* The chain's frequency response: slipping freely, with its Jenkins elements, and stuck. The
 * elements' resonance lies between the two linear ones. */
static int hb(const char *dir)
{
    struct rows rows = {.every = 1};
    double peak[3], w[3];
    const double scale[3] = {0.0, 1.0, 1e6};
    int status = FRICREG_OK;
    for (int c = 0; c < 3 && status == FRICREG_OK; c++)
        status = hb_chain(scale[c], c, &rows, &peak[c], &w[c]);
    const struct rows *sets[1] = {&rows};
    int bad = status != FRICREG_OK
                  ? failed("hb", status)
                  : write_rows(dir, "hb_frf.csv", "curve,omega,rms1,rms2,rms3", sets, 1, 0, 4);
    free(rows.data);
    if (bad)
        return 1;
    char bounds[48];
    snprintf(bounds, sizeof bounds, "in (%.4f, %.4f)", w[0], w[2]);
    cli_table_row("HB", "3-dof chain, 2 Jenkins: peak Omega, H = 7", bounds, w[1],
                  w[1] > w[0] && w[1] < w[2] ? "between the linear peaks" : "OUTSIDE");
    return 0;
}

/* The gap pair of tests/floquet/test_hb_stability.c: two masses, K = [140 -20; -20 180], C = 0.002 K,
 * a unilateral spring (kn = 500) behind a gap of 0.02 on dof 1 (normal gap -x_1, N0 = -10)
 * with a weak friction (mu = 0.01) along dof 2, dof 1 excited at 2 cos, dof 2 at 1 cos. It
 * hardens once the gap closes, so its branch from 11 to 17 rad/s overhangs between two
 * turning points (at 16.0666439 rad/s: tests/floquet/test_hb_stability.c's fine continuation). */
#define GAP_PAIR_FOLD 16.0666439

static int hb_gap_pair(fricreg_hb **out)
{
    const double M[4] = {1, 0, 0, 1}, K[4] = {140, -20, -20, 180};
    const double J[4] = {0, 1, -1, 0};                        /* the tangential row, the normal */
    const double params[5] = {40.0, 0.01, 500.0, -10.0, 0.0}; /* kt mu kn n0 gap */
    const double pc[2] = {2.0, 1.0}, ps[2] = {0.0, 0.0};
    double C[4];
    for (int i = 0; i < 4; i++)
        C[i] = 0.002 * K[i];
    int status = fricreg_hb_create(2, 1, 15, out);
    if (status == FRICREG_OK && (status = fricreg_hb_set_mass(*out, 2, M)) == FRICREG_OK &&
        (status = fricreg_hb_set_stiffness(*out, 2, K)) == FRICREG_OK &&
        (status = fricreg_hb_set_damping(*out, 2, C)) == FRICREG_OK &&
        (status = fricreg_hb_add_elements(*out, fricreg_element_lookup("jenkins_normal"), 1, 2, J,
                                          params)) == FRICREG_OK &&
        (status = fricreg_hb_set_excitation(*out, 2, pc, ps)) == FRICREG_OK &&
        (status = fricreg_hb_set_stability(*out, 1)) == FRICREG_OK)
        status = fricreg_hb_continue(*out, 11.0, 17.0, 2 * 31, NULL);
    return status;
}

/* The branch's rows (curve 0: omega, rms1, rms2, stable) and its bifurcations' (curve 1:
 * omega, rms1, rms2, 1, type). The largest turning point's Omega into *fold. */
static int overhang_rows(fricreg_hb *hb, struct rows *rows, double *fold)
{
    int status = FRICREG_OK;
    for (size_t k = 0; status == FRICREG_OK && k < fricreg_hb_points(hb); k++) {
        double w, rms[2], mu_max;
        int stable = 0;
        if ((status = fricreg_hb_point(hb, k, &w, 2, rms)) == FRICREG_OK &&
            (status = fricreg_hb_point_stability(hb, k, &stable, &mu_max)) == FRICREG_OK) {
            const double v[5] = {w, rms[0], rms[1], stable, 0.0};
            if (keep(rows, v) != 0)
                status = FRICREG_ENOMEM;
        }
    }
    *fold = 0.0;
    rows->curve = 1;
    for (size_t i = 0; status == FRICREG_OK && i < fricreg_hb_bifurcations(hb); i++) {
        int type;
        double w, rms[2];
        size_t k;
        if ((status = fricreg_hb_bifurcation(hb, i, &type, &w, &k, 2, rms)) != FRICREG_OK)
            break;
        const double v[5] = {w, rms[0], rms[1], 1.0, type};
        if (keep(rows, v) != 0)
            status = FRICREG_ENOMEM;
        if (type == FRICREG_HB_TP && w > *fold)
            *fold = w;
    }
    return status;
}

/* An overhanging frequency response with its stability (Hill's method) and bifurcations. */
static int hb_overhang(const char *dir)
{
    struct rows rows = {.every = 1};
    fricreg_hb *hb = NULL;
    double fold = 0.0;
    int status = hb_gap_pair(&hb);
    if (status == FRICREG_OK)
        status = overhang_rows(hb, &rows, &fold);
    fricreg_hb_free(hb);
    const struct rows *sets[1] = {&rows};
    int bad = status != FRICREG_OK ? failed("hb overhang", status)
                                   : write_rows(dir, "hb_overhang.csv",
                                                "curve,omega,rms1,rms2,stable,type", sets, 1, 0, 5);
    free(rows.data);
    if (bad)
        return 1;
    char diff[48];
    snprintf(diff, sizeof diff, "%.1e", fold - GAP_PAIR_FOLD);
    cli_table_row("HB", "gap pair, H = 15: upper turning point Omega", "16.0666439 (fine)", fold,
                  diff);
    return 0;
}

int cli_reproduce_beyond(const char *dir)
{
    return hold(dir) || belt(dir) || disk(dir) || hb(dir) || hb_overhang(dir);
}
