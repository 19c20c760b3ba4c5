/* SPDX-License-Identifier: GPL-3.0-or-later */
/* fuzz_structure_restore.c — fuzz target: fricreg_structure_restore of any bytes into a set-up
 * structure (3 degrees of freedom, 2 contacts, a Jenkins element, Newmark, the error estimate
 * with two companions; the first input byte's bit 1 gives it a consistent mass, whose W couples
 * the contacts), against its contract in include/fricreg_structure.h: the status is
 * FRICREG_OK, FRICREG_EINVAL or FRICREG_ENOMEM, a failure is recorded and leaves everything a
 * getter shows unchanged bit for bit, and a restored structure steps (any documented status, no
 * crash) and saves again to a blob that restores into a new structure of the same set-up.
 * With the first byte's bit 0 the harness writes the header's fields after the magic as this
 * build's own checkpoint has them (format, byte order, library version, type sizes) and the
 * length and hash of the bytes given, so that mutated payloads reach the parser behind the
 * hash (a corrupted blob without it is refused at the hash), and the corpus still does after
 * a change of version or format. The rest of the input is the blob. */
#include "fuzz_input.h"

#include "fricreg.h"
#include "fricreg_structure.h"

#define N 3
#define MC 2
#define HEADER 40 /* checkpoint.c's: magic 8, four uint32, the payload's length and hash */
#define FIELDS 8  /* where the four uint32 start */

static fricreg_structure *scene(int coupled)
{
    double M[N * N] = {1.0, 0.0, 0.0, 0.0, 0.8, 0.0, 0.0, 0.0, 1.3};
    if (coupled) {
        M[1] = M[3] = 0.1;
        M[5] = M[7] = 0.07;
    }
    static const double K[N * N] = {40.0, -15.0, 0.0, -15.0, 35.0, -20.0, 0.0, -20.0, 30.0};
    static const double J[MC * N] = {1.0, 0.0, 0.0, 0.0, 1.0, -0.5}, mun[MC] = {0.35, 0.5};
    static const double p[N] = {1.1, -0.4, 0.7}, g[3] = {0.0, 1.0, -0.5};
    static const double Je[N] = {0.0, 0.0, 1.0}, kt = 25.0, slip = 0.3;
    fricreg_structure *s = NULL;
    if (fricreg_structure_create(N, MC, &s) != FRICREG_OK)
        return NULL;
    int ok = fricreg_structure_set_mass(s, N, M) == FRICREG_OK &&
             fricreg_structure_set_stiffness(s, N, K) == FRICREG_OK &&
             fricreg_structure_set_rayleigh(s, 0.05, 0.002) == FRICREG_OK &&
             fricreg_structure_set_contacts(s, MC, N, J) == FRICREG_OK &&
             fricreg_structure_set_bounds(s, MC, mun) == FRICREG_OK &&
             fricreg_structure_set_law(s, FRICREG_LAW_QUINN, 2e-3) == FRICREG_OK &&
             fricreg_structure_set_load(s, N, p, 0.0, 0.5, 3, g) == FRICREG_OK &&
             fricreg_structure_set_jenkins(s, 1, N, Je, &kt, &slip) == FRICREG_OK &&
             fricreg_structure_set_error_estimate(s, FRICREG_ESTIMATE_TWO_COMPANIONS) == FRICREG_OK;
    if (!ok) {
        fricreg_structure_free(s);
        return NULL;
    }
    return s;
}

/* Everything the contract keeps on failure. */
struct shown {
    double u[N], v[N], a[N], f[MC], D[MC], values[10], peak[N];
    int64_t stats[5];
};

static void show(const fricreg_structure *s, struct shown *x)
{
    memset(x, 0, sizeof *x);
    fricreg_structure_get_state(s, N, x->u, x->v, x->a);
    fricreg_structure_get_forces(s, MC, x->f);
    fricreg_structure_get_dissipation(s, MC, x->D);
    for (int k = 0; k < 10; k++)
        fricreg_structure_get_value(s, k, &x->values[k]);
    fricreg_structure_get_peak_displacement(s, N, x->peak);
    for (int k = 0; k < 5; k++)
        fricreg_structure_get_stat(s, k, &x->stats[k]);
}

static uint64_t fnv1a(const uint8_t *b, size_t len)
{
    uint64_t h = 0xcbf29ce484222325ull;
    for (size_t k = 0; k < len; k++)
        h = (h ^ b[k]) * 0x100000001b3ull;
    return h;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    if (size < 1)
        return 0;
    int mode = data[0];
    size_t len = size - 1;
    uint8_t *blob = malloc(len > 0 ? len : 1);
    if (blob == NULL)
        return 0;
    memcpy(blob, data + 1, len);
    fricreg_structure *s = scene(mode & 2);
    if (s == NULL) {
        free(blob);
        return 0;
    }
    if ((mode & 1) && len >= HEADER) {
        uint8_t own[HEADER + 4096];
        size_t own_len = sizeof own;
        if (fricreg_structure_save(s, own, &own_len) == FRICREG_OK)
            memcpy(blob + FIELDS, own + FIELDS, 4 * sizeof(uint32_t));
        uint64_t payload = len - HEADER, hash = fnv1a(blob + HEADER, len - HEADER);
        memcpy(blob + 24, &payload, sizeof payload);
        memcpy(blob + 32, &hash, sizeof hash);
    }
    fricreg_structure_run(s, 0.01, 0.03); /* a state of its own to keep */
    struct shown before, after;
    show(s, &before);
    int status = fricreg_structure_restore(s, blob, len);
    FUZZ_REQUIRE(status == FRICREG_OK || status == FRICREG_EINVAL || status == FRICREG_ENOMEM,
                 "restore returned %d", status);
    if (status != FRICREG_OK) {
        FUZZ_REQUIRE(fricreg_structure_errcode(s) == status, "errcode %d, returned %d",
                     fricreg_structure_errcode(s), status);
        show(s, &after);
        FUZZ_REQUIRE(memcmp(&before, &after, sizeof before) == 0,
                     "a failed restore (%d: %s) "
                     "changed the state",
                     status, fricreg_structure_errmsg(s));
    } else {
        size_t again = 0;
        FUZZ_REQUIRE(fricreg_structure_save(s, NULL, &again) == FRICREG_OK, "save: %s",
                     fricreg_structure_errmsg(s));
        uint8_t *copy = malloc(again);
        fricreg_structure *r = scene(mode & 2);
        if (copy != NULL && r != NULL) {
            FUZZ_REQUIRE(fricreg_structure_save(s, copy, &again) == FRICREG_OK, "save: %s",
                         fricreg_structure_errmsg(s));
            int back = fricreg_structure_restore(r, copy, again);
            FUZZ_REQUIRE(back == FRICREG_OK || back == FRICREG_ENOMEM,
                         "a restored structure's own checkpoint was refused: %s",
                         fricreg_structure_errmsg(r));
        }
        free(copy);
        fricreg_structure_free(r);
        double t = 0.0;
        fricreg_structure_get_value(s, FRICREG_SVALUE_TIME, &t);
        if (isfinite(t) && fabs(t) < 1e6)
            fricreg_structure_run(s, 0.01, t + 0.05); /* any status: a hostile state may fail */
    }
    fricreg_structure_free(s);
    free(blob);
    return 0;
}
