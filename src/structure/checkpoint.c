/* SPDX-License-Identifier: GPL-3.0-or-later */
/* checkpoint.c — fricreg_structure_save and fricreg_structure_restore: everything a structure
 * carries from one step to the next, as bytes, so that a run restored into a structure set up
 * the same way continues bit for bit as the saved one would have.
 *
 * The blob, in the machine's own byte order and type sizes (for the same build on the same
 * machine: the header refuses another byte order, type size or library version):
 *   header   magic "FRCKPT1\0", uint32 format, uint32 byte-order mark, uint32 library version
 *            (FRICREG_VERSION_NUMBER), uint32 the sizes of double and size_t, uint64 the
 *            payload's length, uint64 its FNV-1a hash (a corrupted or truncated blob is refused);
 *   payload  the model's fingerprint (sizes, kinds and parameters one by one, the matrices and
 *            the excitation by FNV-1a hashes), compared with the structure's before anything
 *            is read; then the state: t, u, v, a, p~, f, the flags of the equation at t, the
 *            dt K_eff was factored for, the run's grid, the energy balance, the counters, the
 *            peaks, the warnings' trackers and list, the elements' sliders and forces, what the
 *            context carries (ctx_carried.c), the near-stick block's held factor
 *            (blocks_carried.c) and the error estimate with its companion's blob (nested, the
 *            same format) and, with FRICREG_COMPANIONS_AUTO before the finer pair confirmed, the
 *            parked finer pair's blob and the calls it has still to take.
 * One function (state_fields) lists the state for the three passes: save, check (the blob read
 * and checked, nothing written) and load (after the check and after the fallible steps:
 * prepare, K_eff's factor, the context's part, the companion, the near-stick block's factor),
 * so that a failed restore leaves the structure as it was and a load cannot fail. */
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "blocks_carried.h"
#include "checkpoint_fingerprint.h"
#include "ctx/ctx_driver.h"
#include "structure_internal.h"

#define MAGIC "FRCKPT1" /* 8 bytes with its NUL */
#define FORMAT 4u /* 2 since 1.8: the block's factor; 3 since 1.9: auto companions; 4: its spare */
#define BYTE_ORDER_MARK 0x01020304u
#define TYPE_SIZES ((uint32_t)(sizeof(double) | sizeof(size_t) << 8))
#define HEADER_BYTES (8 + 4 * 4 + 2 * 8)

/* ---- Bytes in and out ---------------------------------------------------------------------- */

enum { IO_SAVE, IO_CHECK, IO_LOAD };

/* One pass over a blob: save writes buf[cap] (buf NULL: counts), check and load read buf[len];
 * pos counts the bytes passed; a read past the end sets bad. */
struct io {
    int mode;
    unsigned char *out;
    const unsigned char *in;
    size_t cap, pos;
    int bad;
};

/* bytes[len] of the structure: written (save), read into it (load) or passed over (check). */
static void field(struct io *io, void *bytes, size_t len)
{
    if (io->mode == IO_SAVE) {
        if (io->out != NULL && io->pos + len <= io->cap)
            memcpy(io->out + io->pos, bytes, len);
    } else if (io->cap - io->pos < len) {
        io->bad = 1;
        return;
    } else if (io->mode == IO_LOAD) {
        memcpy(bytes, io->in + io->pos, len);
    }
    io->pos += len;
}

/* A value read into *x (check and load: a local, assigned by the caller on load) or written
 * from it (save). */
static void value(struct io *io, void *x, size_t len)
{
    if (io->mode == IO_SAVE) {
        field(io, x, len);
    } else if (io->cap - io->pos < len) {
        io->bad = 1;
        memset(x, 0, len);
    } else {
        memcpy(x, io->in + io->pos, len);
        io->pos += len;
    }
}

/* ---- The state ----------------------------------------------------------------------------- */

/* Where check found the nested parts (load reads them before its own pass). */
struct nested {
    size_t ctx_at, ctx_len;       /* what the context carries (0: nothing) */
    size_t blocks_at, blocks_len; /* the near-stick block's held factor (blocks_carried.h) */
    size_t companion_at, companion_len;
    size_t confirm_at, confirm_len; /* FRICREG_COMPANIONS_AUTO's parked finer pair */
    int32_t estimate_state, companion_level;
    uint8_t prepared, ready, fresh;
    double step_dt;
};

static void vector(struct io *io, gsl_vector *x)
{
    field(io, x->data, x->size * sizeof(double));
}

static void flag(struct io *io, int *x, uint8_t *seen)
{
    uint8_t b = (uint8_t)(*x != 0);
    value(io, &b, 1);
    if (b > 1)
        io->bad = 1;
    if (io->mode == IO_LOAD)
        *x = b;
    *seen = b;
}

static void elements(struct io *io, struct fr_elements *e)
{
    if (e->me == 0)
        return;
    size_t slots = e->nslots * sizeof(double), nc = e->nc * sizeof(double);
    double *slot_arrays[] = {e->wc, e->wt, e->fs, e->fs1};
    for (size_t k = 0; k < 4; k++)
        field(io, slot_arrays[k], slots);
    field(io, e->fe, nc);
    field(io, e->fe1, nc);
    field(io, e->dissipation, e->me * sizeof(double));
    field(io, &e->crossed, sizeof e->crossed);
}

static void warnings(struct io *io, struct fr_warnings *w)
{
    uint64_t n = w->n;
    value(io, &n, sizeof n);
    if (n > FR_WARN_MAX) {
        io->bad = 1;
        return;
    }
    for (size_t k = 0; k < n; k++) {
        int32_t code = w->w[k].code;
        value(io, &code, sizeof code);
        char msg[sizeof w->w[k].msg];
        memcpy(msg, w->w[k].msg, sizeof msg);
        value(io, msg, sizeof msg);
        if (io->mode == IO_LOAD) {
            w->w[k].code = code;
            memcpy(w->w[k].msg, msg, sizeof msg);
            w->w[k].msg[sizeof msg - 1] = '\0';
        }
    }
    if (io->mode == IO_LOAD)
        w->n = (size_t)n;
    field(io, &w->delivered, sizeof w->delivered);
}

/* A nested part: its length, then its bytes (saved by put, found by check, passed by load). */
static void part(struct io *io, size_t len, void (*put)(const fricreg_structure *, void *, size_t),
                 const fricreg_structure *s, size_t *at, size_t *found)
{
    uint64_t n = len;
    value(io, &n, sizeof n);
    if (io->mode != IO_SAVE && n > io->cap - io->pos) {
        io->bad = 1;
        return;
    }
    if (io->mode == IO_SAVE && io->out != NULL && io->pos + n <= io->cap)
        put(s, io->out + io->pos, (size_t)n);
    *at = io->pos;
    *found = (size_t)n;
    io->pos += (size_t)n;
}

static void put_ctx(const fricreg_structure *s, void *out, size_t len)
{
    (void)len;
    fr_ctx_carried_save(s->ctx, s->prepared, out);
}

static void put_blocks(const fricreg_structure *s, void *out, size_t len)
{
    (void)len;
    fr_blocks_carried_save(s, out);
}

static void put_companion(const fricreg_structure *s, void *out, size_t len)
{
    fricreg_structure_save(s->companion, out, &len);
}

static void put_confirm(const fricreg_structure *s, void *out, size_t len)
{
    fricreg_structure_save(s->confirm, out, &len);
}

/* The bytes of a companion c of s's active estimate (a stale one is not the run's). */
static size_t companion_bytes(const fricreg_structure *s, fricreg_structure *c)
{
    size_t len = 0;
    if (s->estimate_state == FR_ESTIMATE_ACTIVE && c != NULL)
        fricreg_structure_save(c, NULL, &len);
    return len;
}

/* What FRICREG_COMPANIONS_AUTO keeps beside the companions: their levels, the kind of call the
 * parked pair has still to take and what the screen said. */
static void screen_fields(struct io *io, fricreg_structure *s, struct nested *found)
{
    int32_t level = s->companion_level, integrator = s->parked.integrator;
    value(io, &level, sizeof level);
    value(io, &integrator, sizeof integrator);
    found->companion_level = level;
    if (level != FRICREG_COMPANIONS_FINER && level != FRICREG_COMPANIONS_COARSER)
        io->bad = 1;
    if (io->mode == IO_LOAD) {
        s->companion_level = level;
        s->parked.integrator = integrator;
    }
    double *values[] = {&s->parked.dt, &s->parked.rtol, &s->parked.atol, &s->screen_peak_err,
                        &s->screen_dissipation_err};
    for (size_t k = 0; k < sizeof values / sizeof *values; k++)
        field(io, values[k], sizeof *values[k]);
}

/* The state, in one order for the three passes; *found what check and save saw. */
static void state_fields(struct io *io, fricreg_structure *s, struct nested *found)
{
    field(io, &s->t, sizeof s->t);
    gsl_vector *vectors[] = {s->u, s->v, s->a, s->ptil};
    for (size_t k = 0; k < 4; k++)
        vector(io, vectors[k]);
    vector(io, s->f);
    flag(io, &s->ready, &found->ready);
    flag(io, &s->fresh, &found->fresh);
    int prepared = s->prepared; /* load: prepare made it so */
    flag(io, &prepared, &found->prepared);
    double step_dt = s->scheme == FR_SCHEME_NEWMARK && s->prepared ? s->step_dt : 0.0;
    value(io, &step_dt, sizeof step_dt);
    found->step_dt = step_dt;
    if (!(step_dt >= 0.0 && step_dt <= 1e300))
        io->bad = 1;
    field(io, &s->clock_t0, sizeof s->clock_t0);
    field(io, &s->clock_dt, sizeof s->clock_dt);
    field(io, &s->clock_k, sizeof s->clock_k);

    struct fr_energy *en = &s->energy;
    double *energies[] = {&en->initial, &en->input, &en->viscous, &en->friction, &en->jenkins};
    for (size_t k = 0; k < 5; k++)
        field(io, energies[k], sizeof *energies[k]);
    field(io, en->per_contact, s->m * sizeof(double));
    field(io, s->stats, sizeof s->stats);
    field(io, s->peak, s->n * sizeof(double));

    double *trackers[] = {&s->peak_speed,   &s->peak_dof_speed, &s->max_dt,   &s->ode_tol_level,
                          &s->ode_rtol_max, &s->ode_rtol,       &s->ode_atol1};
    for (size_t k = 0; k < sizeof trackers / sizeof *trackers; k++)
        field(io, trackers[k], sizeof *trackers[k]);
    field(io, &s->inexact_steps, sizeof s->inexact_steps);
    warnings(io, &s->warnings);
    elements(io, &s->el);

    size_t ctx_len = io->mode == IO_SAVE ? fr_ctx_carried_size(s->ctx, s->prepared) : 0;
    part(io, ctx_len, put_ctx, s, &found->ctx_at, &found->ctx_len);
    part(io, io->mode == IO_SAVE ? fr_blocks_carried_size(s) : 0, put_blocks, s, &found->blocks_at,
         &found->blocks_len);
    int32_t state = s->estimate_state;
    value(io, &state, sizeof state);
    found->estimate_state = state;
    if (state < FR_ESTIMATE_NONE || state > FR_ESTIMATE_FAILED ||
        (state != FR_ESTIMATE_NONE && !s->estimate_on))
        io->bad = 1; /* an estimate (and its companion: two levels at most) only where it is on */
    char msg[sizeof s->estimate_msg];
    memcpy(msg, s->estimate_msg, sizeof msg);
    value(io, msg, sizeof msg);
    if (io->mode == IO_LOAD) {
        s->estimate_state = state;
        memcpy(s->estimate_msg, msg, sizeof msg);
        s->estimate_msg[sizeof msg - 1] = '\0';
    }
    screen_fields(io, s, found);
    part(io, io->mode == IO_SAVE ? companion_bytes(s, s->companion) : 0, put_companion, s,
         &found->companion_at, &found->companion_len);
    part(io, io->mode == IO_SAVE ? companion_bytes(s, s->confirm) : 0, put_confirm, s,
         &found->confirm_at, &found->confirm_len);
    int parked = state == FR_ESTIMATE_ACTIVE && s->companions == FRICREG_COMPANIONS_AUTO &&
                 found->companion_level == FRICREG_COMPANIONS_COARSER;
    if (io->mode != IO_SAVE && ((found->companion_len > 0) != (state == FR_ESTIMATE_ACTIVE) ||
                                (found->confirm_len > 0) != parked))
        io->bad = 1; /* a companion exactly while the estimate is active, a parked pair while
                      * auto's screen is */
    if (io->mode != IO_SAVE &&
        (found->ready > found->prepared || (found->step_dt != 0.0 && !found->prepared)))
        io->bad = 1; /* the equation at t needs the set-up, so does K_eff */
}

/* ---- Header -------------------------------------------------------------------------------- */

static void header(struct io *io, uint32_t *fields, uint64_t *payload, uint64_t *hash,
                   char magic[8])
{
    value(io, magic, 8);
    for (size_t k = 0; k < 4; k++)
        value(io, &fields[k], sizeof fields[k]);
    value(io, payload, sizeof *payload);
    value(io, hash, sizeof *hash);
}

int fricreg_structure_save(fricreg_structure *s, void *buf, size_t *size)
{
    if (s == NULL)
        return FRICREG_ENULL;
    if (size == NULL)
        return fr_fail(s, FRICREG_ENULL, "save: size is NULL");
    if (s->running)
        return fr_structure_refuse(s, "save");
    if (fr_ctx_carried_size(s->ctx, s->prepared) == 0)
        return fr_fail(s, FRICREG_EINVAL,
                       "save: not supported for a structure whose %zu contacts couple through a "
                       "sparse W (more than 64 coupled contacts): the context's factor, updated "
                       "row by row, is not carried",
                       s->m);
    fr_estimate_sync(s); /* the companion takes the setters' changes it has not had */
    if (s->estimate_state == FR_ESTIMATE_ACTIVE &&
        (fr_ctx_carried_size(s->companion->ctx, s->companion->prepared) == 0 ||
         (s->confirm != NULL && fr_ctx_carried_size(s->confirm->ctx, s->confirm->prepared) == 0)))
        return fr_fail(s, FRICREG_EINVAL, "save: not supported for this structure's companion");
    struct nested found;
    struct fingerprint fp;
    fr_fingerprint_of(s, &fp);
    struct io count = {.mode = IO_SAVE};
    value(&count, &fp, sizeof fp);
    state_fields(&count, s, &found);
    size_t need = HEADER_BYTES + count.pos;
    if (buf == NULL) {
        *size = need;
        return FRICREG_OK;
    }
    if (*size < need) {
        size_t given = *size;
        *size = need;
        return fr_fail(s, FRICREG_ESIZE, "save: the buffer has %zu bytes, the checkpoint %zu",
                       given, need);
    }
    unsigned char *out = buf;
    struct io io = {.mode = IO_SAVE, .out = out + HEADER_BYTES, .cap = need - HEADER_BYTES};
    value(&io, &fp, sizeof fp);
    state_fields(&io, s, &found);
    uint32_t fields[4] = {FORMAT, BYTE_ORDER_MARK, (uint32_t)FRICREG_VERSION_NUMBER, TYPE_SIZES};
    uint64_t payload = io.pos, hash = fr_fnv1a(FNV_START, io.out, io.pos);
    char magic[8] = MAGIC;
    struct io head = {.mode = IO_SAVE, .out = out, .cap = HEADER_BYTES};
    header(&head, fields, &payload, &hash, magic);
    *size = need;
    return FRICREG_OK;
}

/* ---- Restore ------------------------------------------------------------------------------- */

static int refuse(fricreg_structure *s, const char *why)
{
    return fr_fail(s, FRICREG_EINVAL, "restore: %s", why);
}

/* The header of buf[size]: its payload's place on success. */
static int read_header(fricreg_structure *s, const unsigned char *buf, size_t size,
                       struct io *payload)
{
    if (size < HEADER_BYTES)
        return refuse(s, "the blob is shorter than a checkpoint's header");
    uint32_t fields[4];
    uint64_t len, hash;
    char magic[8];
    struct io head = {.mode = IO_CHECK, .in = buf, .cap = HEADER_BYTES};
    header(&head, fields, &len, &hash, magic);
    if (memcmp(magic, MAGIC, sizeof magic) != 0)
        return refuse(s, "not a structure's checkpoint (fricreg_structure_save)");
    if (fields[1] != BYTE_ORDER_MARK || fields[3] != TYPE_SIZES)
        return refuse(s, "the checkpoint was written on a machine of another byte order or type "
                         "sizes");
    if (fields[0] != FORMAT)
        return fr_fail(s, FRICREG_EINVAL, "restore: checkpoint format %u, this library reads %u",
                       (unsigned)fields[0], FORMAT);
    if (fields[2] != (uint32_t)FRICREG_VERSION_NUMBER)
        return fr_fail(s, FRICREG_EINVAL,
                       "restore: the checkpoint was written by fricreg %u.%u.%u, this is %s: "
                       "its numbers would not continue bit for bit",
                       (unsigned)fields[2] / 10000, (unsigned)fields[2] / 100 % 100,
                       (unsigned)fields[2] % 100, FRICREG_VERSION_STRING);
    if (len != size - HEADER_BYTES)
        return fr_fail(s, FRICREG_EINVAL,
                       "restore: the blob has %zu bytes, its header says %llu (truncated?)", size,
                       (unsigned long long)(len + HEADER_BYTES));
    if (fr_fnv1a(FNV_START, buf + HEADER_BYTES, (size_t)len) != hash)
        return refuse(s, "the checkpoint is corrupted (its hash does not match)");
    *payload = (struct io){.mode = IO_CHECK, .in = buf + HEADER_BYTES, .cap = (size_t)len};
    return FRICREG_OK;
}

/* A new companion of s at `level` into *c, restored from blob[len]. */
static int companion_from(fricreg_structure *s, int level, const unsigned char *blob, size_t len,
                          fricreg_structure **c)
{
    char msg[256];
    int status = fr_estimate_companion(s, level, c, msg);
    if (status != FRICREG_OK)
        return fr_fail(s, status, "restore: %s", msg);
    status = fricreg_structure_restore(*c, blob, len);
    if (status != FRICREG_OK)
        fr_fail(s, status, "restore: the error estimate's companion: %s",
                fricreg_structure_errmsg(*c));
    return status;
}

/* The fallible steps before the load: the set-up, K_eff's factor, the context's part, the new
 * companions (into companion[2]: the estimate's, auto's parked finer pair) from their blobs,
 * and last the near-stick block's factor (on its failure the companions are freed). */
static int rebuild(fricreg_structure *s, const unsigned char *payload, const struct nested *found,
                   fricreg_structure *companion[2])
{
    int status = FRICREG_OK;
    if (found->prepared && (status = fr_structure_prepare(s)) != FRICREG_OK)
        return status;
    if (found->step_dt > 0.0) {
        if (s->scheme != FR_SCHEME_NEWMARK || !(found->step_dt <= 1e300))
            return refuse(s, "the checkpoint's K_eff is not its scheme's");
        if ((status = fr_newmark_factor(s, found->step_dt)) != FRICREG_OK)
            return status;
    }
    if (fr_ctx_carried_restore(s->ctx, payload + found->ctx_at, found->ctx_len, found->prepared) !=
        FRICREG_OK)
        return refuse(s, "the context's part of the checkpoint does not fit the contacts");
    if (found->companion_len > 0)
        status = companion_from(s, found->companion_level, payload + found->companion_at,
                                found->companion_len, &companion[0]);
    if (status == FRICREG_OK && found->confirm_len > 0)
        status = companion_from(s, FRICREG_COMPANIONS_FINER, payload + found->confirm_at,
                                found->confirm_len, &companion[1]);
    if (status == FRICREG_OK) {
        status = fr_blocks_carried_restore(s, payload + found->blocks_at, found->blocks_len,
                                           found->step_dt > 0.0);
        if (status == FRICREG_EINVAL)
            refuse(s, "the near-stick block's part of the checkpoint does not fit this structure");
        else if (status != FRICREG_OK)
            fr_fail(s, status, "restore: the near-stick block's factor: %s",
                    fricreg_strerror(status));
    }
    if (status != FRICREG_OK) {
        fricreg_structure_free(companion[0]);
        fricreg_structure_free(companion[1]);
        companion[0] = companion[1] = NULL;
    }
    return status;
}

int fricreg_structure_restore(fricreg_structure *s, const void *buf, size_t size)
{
    if (s == NULL)
        return FRICREG_ENULL;
    if (buf == NULL)
        return fr_fail(s, FRICREG_ENULL, "restore: buf is NULL");
    if (s->running)
        return fr_structure_refuse(s, "restore");
    struct io io;
    int status = read_header(s, buf, size, &io);
    if (status != FRICREG_OK)
        return status;
    struct fingerprint fp;
    value(&io, &fp, sizeof fp);
    if (io.bad)
        return refuse(s, "the checkpoint is truncated");
    if ((status = fr_fingerprint_compare(s, &fp)) != FRICREG_OK)
        return status;
    size_t state_at = io.pos;
    struct nested found;
    state_fields(&io, s, &found);
    if (io.bad || io.pos != io.cap)
        return refuse(s, "the checkpoint's state does not fit this structure (corrupted?)");
    fricreg_structure *companion[2] = {NULL, NULL};
    if ((status = rebuild(s, io.in, &found, companion)) != FRICREG_OK)
        return status;
    /* From here nothing fails. */
    io.mode = IO_LOAD;
    io.pos = state_at;
    state_fields(&io, s, &found);
    s->step_dt = found.step_dt; /* 0: K_eff factored at the next step, as the saved one's */
    if (!found.prepared)
        s->prepared = 0; /* the saved one sets its model up at its next step: so does this */
    s->stick_valid = 0;
    fricreg_structure_free(s->companion);
    fricreg_structure_free(s->confirm);
    s->companion = companion[0];
    s->confirm = companion[1];
    s->companion_pending = 0; /* the saved companion had every change (save passed them on) */
    return FRICREG_OK;
}
