/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element_store.c — the driver's elements of any kinds together (element_store.h): each
 * element's kind and its offsets among J's rows, the Jacobian blocks and the sliders, the
 * sliders' k then phi in sk, the normal laws' kt, mu, n0, kn in nl. A model of one kind is
 * laid out as the per-kind setters always laid it out (row e of Jenkins, rows 2e, 2e + 1 with
 * lift-off, ...), so its answers are theirs bit for bit. */
#include <stdlib.h>
#include <string.h>

#include "element_store.h"
#include "joint/aft_march.h"
#include "rows.h"

#define CONTACT_SAMPLES 64

size_t fr_hb_contact_samples(int harmonics)
{
    size_t want = CONTACT_SAMPLES * (2 * (size_t)harmonics + 1), N = 1;
    while (N < want)
        N *= 2;
    return N;
}

int fr_hb_sampled_aft(fricreg_hb *hb)
{
    size_t N = fr_hb_contact_samples(hb->H), nc = hb->nc;
    if (fricreg_aft_samples(hb->aft) == N && hb->aft_half != NULL)
        return FRICREG_OK;
    fricreg_aft *aft = NULL, *half = NULL;
    double *results = malloc((3 * nc + 9 * nc * nc) * sizeof *results);
    if (results == NULL || fricreg_aft_create(hb->H, N, &aft) != FRICREG_OK ||
        fricreg_aft_create(hb->H, N / 2, &half) != FRICREG_OK) {
        free(results);
        fricreg_aft_free(aft);
        return FRICREG_ENOMEM;
    }
    fricreg_aft_free(hb->aft);
    fricreg_aft_free(hb->aft_half);
    free(hb->half);
    hb->aft = aft;
    hb->aft_half = half;
    hb->half = results;
    return FRICREG_OK;
}

/* The march's workspace with room for nstate states, and the sampled AFTs it runs on, unless
 * they are there. FRICREG_OK, or FRICREG_ENOMEM with the workspace unchanged. */
static int march_room(fricreg_hb *hb, size_t nstate)
{
    if (fr_hb_sampled_aft(hb) != FRICREG_OK)
        return FRICREG_ENOMEM;
    if (hb->march != NULL && hb->march_nstate >= nstate)
        return FRICREG_OK;
    struct fr_aft_march *w;
    if (fr_aft_march_create(fr_hb_contact_samples(hb->H), hb->nc, nstate, &w) != FRICREG_OK)
        return FRICREG_ENOMEM;
    fr_aft_march_free(hb->march);
    hb->march = w;
    hb->march_nstate = nstate;
    return FRICREG_OK;
}

/* An element's rows of J: its kind's, or a marched type's dim. */
static size_t block_rows(const struct fr_hb_block *blk)
{
    return blk->kind == FR_HB_MARCH ? blk->ra : (size_t)blk->kind;
}

/* The parameters a marched element keeps (the others keep theirs in sk and nl). */
static size_t block_params(const struct fr_hb_block *blk)
{
    return blk->kind == FR_HB_MARCH ? blk->pstride : 0;
}

/* The doubles of sk: the sliders' k and phi, and with an Iwan element with lift-off room for
 * one slider's forces and Jacobian (residual.c), 2 nc + (2 nc)². */
static size_t slider_doubles(size_t nsl, int scratch, size_t nc)
{
    return 2 * nsl + (scratch ? 2 * nc + 4 * nc * nc : 0);
}

/* rpe and ns of the elements held when they are all alike, else 0 (a mix); the scratch. */
static void summarize(fricreg_hb *hb)
{
    size_t count = hb->count;
    hb->rpe = count ? (size_t)hb->kind[0] : 1;
    hb->ns = count ? hb->eso[1] : 1;
    hb->scratch = 0;
    for (size_t e = 0; e < count; e++) {
        size_t ns = hb->eso[e + 1] - hb->eso[e];
        if ((size_t)hb->kind[e] != hb->rpe)
            hb->rpe = 0;
        if (ns != hb->ns)
            hb->ns = 0;
        if (hb->kind[e] == FR_HB_LIFTOFF && ns > 1)
            hb->scratch = 1;
    }
}

/* The tables' entries of element e of the block's kind, rows, sliders and parameters. */
static void table_entry(fricreg_hb *hb, size_t e, const struct fr_hb_block *blk)
{
    size_t rows = block_rows(blk);
    hb->kind[e] = blk->kind;
    hb->etype[e] = blk->kind == FR_HB_MARCH ? blk->type : NULL;
    hb->erow[e + 1] = hb->erow[e] + rows;
    hb->ejq[e + 1] = hb->ejq[e] + rows * rows;
    hb->eso[e + 1] = hb->eso[e] + blk->ns;
    hb->epo[e + 1] = hb->epo[e] + block_params(blk);
}

/* Element e's normal law: kt and mu the sums of its sliders' (an Iwan element's stuck
 * stiffness), n0, kn; 0 without one. */
static void normal_entry(fricreg_hb *hb, size_t e, const struct fr_hb_block *blk, size_t i)
{
    size_t me = hb->me, ns = blk->ns;
    double ksum = 0.0, musum = 0.0;
    for (size_t s = 0; s < ns; s++) {
        ksum += blk->k[i * blk->pstride + s];
        musum += blk->phi[i * blk->pstride + s];
    }
    int normal = blk->kind == FR_HB_LIFTOFF || blk->kind == FR_HB_CONTACT_3D;
    hb->nl[e] = ksum;
    hb->nl[me + e] = musum;
    hb->nl[2 * me + e] = normal ? blk->n0[i * blk->nstride] : 0.0;
    hb->nl[3 * me + e] = normal ? blk->kn[i * blk->nstride] : 0.0;
}

/* The block's rows, sliders and laws written into hb after element c0 (sk: the new one, of
 * nsl sliders, and ep, the held ones copied from the old). */
static void write_block(fricreg_hb *hb, const struct fr_hb_block *blk, size_t c0, double *sk,
                        size_t nsl, double *ep)
{
    size_t n = hb->n, rows = block_rows(blk), S0 = hb->eso[c0], np = block_params(blk);
    if (S0 > 0) { /* the held elements' sliders */
        memcpy(sk, hb->sk, S0 * sizeof *sk);
        memcpy(sk + nsl, hb->sk + hb->nsl, S0 * sizeof *sk);
    }
    if (hb->epo[c0] > 0)
        memcpy(ep, hb->ep, hb->epo[c0] * sizeof *ep);
    for (size_t i = 0; i < blk->me; i++) {
        size_t e = c0 + i;
        table_entry(hb, e, blk);
        if (np > 0)
            memcpy(ep + hb->epo[e], blk->k + i * blk->pstride, np * sizeof *ep);
        for (size_t r = 0; r < rows; r++) {
            const double *src = r < blk->ra ? blk->Ja + (i * blk->ra + r) * n : blk->Jb + i * n;
            memcpy(hb->J + (hb->erow[e] + r) * n, src, n * sizeof *src);
        }
        for (size_t s = 0; s < blk->ns; s++) {
            sk[hb->eso[e] + s] = blk->k[i * blk->pstride + s];
            sk[nsl + hb->eso[e] + s] = blk->phi[i * blk->pstride + s];
        }
        normal_entry(hb, e, blk, i);
    }
}

int fr_hb_store_add(fricreg_hb *hb, const struct fr_hb_block *blk, int replace)
{
    size_t c0 = replace ? 0 : hb->count, rows = block_rows(blk), me = blk->me;
    size_t m = hb->erow[c0] + me * rows, sq = hb->ejq[c0] + me * rows * rows;
    size_t nsl = hb->eso[c0] + me * blk->ns, nep = hb->epo[c0] + me * block_params(blk);
    int scratch = blk->kind == FR_HB_LIFTOFF && blk->ns > 1;
    for (size_t e = 0; e < c0; e++)
        scratch |= hb->kind[e] == FR_HB_LIFTOFF && hb->eso[e + 1] - hb->eso[e] > 1;
    /* the buffers sized by the rows grow (and stay), the sliders' array is the model's */
    double *sk = malloc((slider_doubles(nsl, scratch, hb->nc) + 1) * sizeof *sk);
    double *ep = malloc((nep + 1) * sizeof *ep);
    struct fr_hb_rows b = {0};
    size_t cap = m > hb->rows_cap ? m : hb->rows_cap, sq_cap = sq > hb->sq_cap ? sq : hb->sq_cap;
    int grow = cap > hb->rows_cap || sq_cap > hb->sq_cap;
    if (sk == NULL || ep == NULL || (grow && fr_hb_rows_alloc(hb, cap, sq_cap, &b) != FRICREG_OK) ||
        (blk->kind == FR_HB_CONTACT_3D && fr_hb_sampled_aft(hb) != FRICREG_OK) ||
        (blk->kind == FR_HB_MARCH &&
         march_room(hb, fricreg_element_nstate(blk->type)) != FRICREG_OK)) {
        free(sk);
        free(ep);
        fr_hb_rows_free(&b);
        return FRICREG_ENOMEM;
    }
    if (grow)
        fr_hb_rows_install(hb, cap, sq_cap, &b);
    write_block(hb, blk, c0, sk, nsl, ep);
    free(hb->sk);
    hb->sk = sk;
    free(hb->ep);
    hb->ep = ep;
    hb->nsl = nsl;
    hb->count = c0 + me;
    summarize(hb);
    fr_hb_rows_set(hb);
    hb->have_elements = hb->count == hb->me;
    return FRICREG_OK;
}

void fr_hb_store_clear(fricreg_hb *hb)
{
    hb->count = 0;
    hb->nsl = 0;
    summarize(hb);
    fr_hb_rows_set(hb);
    hb->have_elements = 0;
}

int fr_hb_store_copy(fricreg_hb *dst, const fricreg_hb *src)
{
    size_t count = src->count, me = src->me, n = src->n;
    double *sk = malloc((slider_doubles(src->nsl, src->scratch, dst->nc) + 1) * sizeof *sk);
    size_t nep = src->epo[count];
    double *ep = malloc((nep + 1) * sizeof *ep);
    struct fr_hb_rows b = {0};
    size_t m = src->erow[count], sq = src->ejq[count];
    int grow = m > dst->rows_cap || sq > dst->sq_cap;
    int contact = 0;
    for (size_t e = 0; e < count; e++)
        contact |= src->kind[e] == FR_HB_CONTACT_3D;
    if (sk == NULL || ep == NULL || (grow && fr_hb_rows_alloc(dst, m, sq, &b) != FRICREG_OK) ||
        (contact && fr_hb_sampled_aft(dst) != FRICREG_OK) ||
        (src->march != NULL && march_room(dst, src->march_nstate) != FRICREG_OK)) {
        free(sk);
        free(ep);
        fr_hb_rows_free(&b);
        return FRICREG_ENOMEM;
    }
    if (grow)
        fr_hb_rows_install(dst, m, sq, &b);
    if (src->nsl > 0)
        memcpy(sk, src->sk, 2 * src->nsl * sizeof *sk);
    free(dst->sk);
    dst->sk = sk;
    if (nep > 0)
        memcpy(ep, src->ep, nep * sizeof *ep);
    free(dst->ep);
    dst->ep = ep;
    memcpy(dst->J, src->J, m * n * sizeof *src->J);
    memcpy(dst->nl, src->nl, 4 * me * sizeof *src->nl);
    memcpy(dst->erow, src->erow, 4 * (me + 1) * sizeof *src->erow);
    memcpy(dst->kind, src->kind, me * sizeof *src->kind);
    memcpy(dst->etype, src->etype, me * sizeof *src->etype);
    dst->nsl = src->nsl;
    dst->count = count;
    summarize(dst);
    fr_hb_rows_set(dst);
    dst->have_elements = src->have_elements;
    return FRICREG_OK;
}
