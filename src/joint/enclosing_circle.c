/* SPDX-License-Identifier: GPL-3.0-or-later */
/* enclosing_circle.c — the smallest circle enclosing a sampled orbit (enclosing_circle.h). */
#include <math.h>

#include "enclosing_circle.h"

static double dist2(const double *x, const double *y, size_t n, const double c[2])
{
    double dx = x[n] - c[0], dy = y[n] - c[1];
    return dx * dx + dy * dy;
}

static struct fr_circle through2(const double *x, const double *y, size_t i, size_t j)
{
    struct fr_circle k = {.c = {0.5 * (x[i] + x[j]), 0.5 * (y[i] + y[j])},
                          .sup = {i, j},
                          .nsup = 2};
    k.r2 = fmax(dist2(x, y, i, k.c), dist2(x, y, j, k.c));
    return k;
}

/* The circle through three samples; nearly collinear, the widest pair's. */
static struct fr_circle through3(const double *x, const double *y, size_t i, size_t j, size_t k)
{
    double bx = x[j] - x[i], by = y[j] - y[i];
    double cx = x[k] - x[i], cy = y[k] - y[i];
    double det = 2.0 * (bx * cy - by * cx), b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    if (!(fabs(det) > 1e-12 * (b2 + c2))) {
        struct fr_circle p = through2(x, y, i, j), q = through2(x, y, i, k),
                         t = through2(x, y, j, k);
        return p.r2 >= q.r2 && p.r2 >= t.r2 ? p : q.r2 >= t.r2 ? q : t;
    }
    struct fr_circle out = {.c = {x[i] + (cy * b2 - by * c2) / det,
                                  y[i] + (bx * c2 - cx * b2) / det},
                            .sup = {i, j, k},
                            .nsup = 3};
    out.r2 = fmax(dist2(x, y, i, out.c), fmax(dist2(x, y, j, out.c), dist2(x, y, k, out.c)));
    return out;
}

static int outside(const double *x, const double *y, size_t n, const struct fr_circle *k)
{
    return dist2(x, y, n, k->c) > k->r2 * (1.0 + 1e-12);
}

struct fr_circle fr_enclosing_circle(const double *x, const double *y, size_t N)
{
#define ORDER(i) (((size_t)(i) * (size_t)2654435761u) & (N - 1))
    struct fr_circle k = {.c = {x[0], y[0]}, .r2 = 0.0, .sup = {0}, .nsup = 1};
    for (size_t i = 1; i < N; i++) {
        size_t pi = ORDER(i);
        if (!outside(x, y, pi, &k))
            continue;
        k = (struct fr_circle){.c = {x[pi], y[pi]}, .r2 = 0.0, .sup = {pi}, .nsup = 1};
        for (size_t j = 0; j < i; j++) {
            size_t pj = ORDER(j);
            if (!outside(x, y, pj, &k))
                continue;
            k = through2(x, y, pi, pj);
            for (size_t l = 0; l < j; l++)
                if (outside(x, y, ORDER(l), &k))
                    k = through3(x, y, pi, pj, ORDER(l));
        }
    }
#undef ORDER
    return k;
}

void fr_circle_centre_derivative(const struct fr_circle *k, const double *x, const double *y,
                                 const double dp[3][2], double dc[2])
{
    if (k->nsup == 1) {
        dc[0] = dp[0][0];
        dc[1] = dp[0][1];
        return;
    }
    if (k->nsup == 2) {
        dc[0] = 0.5 * (dp[0][0] + dp[1][0]);
        dc[1] = 0.5 * (dp[0][1] + dp[1][1]);
        return;
    }
    /* |c - p_i|^2 equal for the three: (p_b - p_a).dc = (c - p_a).dp_a - (c - p_b).dp_b */
    double A[4], rhs[2];
    for (int r = 0; r < 2; r++) {
        size_t pa = k->sup[0], pb = k->sup[r + 1];
        A[2 * r] = x[pb] - x[pa];
        A[2 * r + 1] = y[pb] - y[pa];
        rhs[r] = (k->c[0] - x[pa]) * dp[0][0] + (k->c[1] - y[pa]) * dp[0][1] -
                 (k->c[0] - x[pb]) * dp[r + 1][0] - (k->c[1] - y[pb]) * dp[r + 1][1];
    }
    double det = A[0] * A[3] - A[1] * A[2];
    dc[0] = (A[3] * rhs[0] - A[1] * rhs[1]) / det;
    dc[1] = (A[0] * rhs[1] - A[2] * rhs[0]) / det;
}
