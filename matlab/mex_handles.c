/* SPDX-License-Identifier: GPL-3.0-or-later */
/* mex_handles.c — the gateway's table of library objects (mex_handles.h). */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <time.h>

#include "mex_args.h"
#include "mex_handles.h"
#include "mex_hb.h"
#include "mex_structure.h"
#include "fricreg_fit.h"

typedef struct {
    double id; /* 0: a free slot */
    int kind;
    void *object;
    size_t aux;
} entry;

static entry *table = NULL;
static size_t capacity = 0, live = 0;
/* The next handle. Each load of the MEX file starts at 1 + 2^20 b, b in 0 .. 2^28 - 1 mixed
 * from the clock and the table's address (a reload's address moves with the loader's
 * randomization), so handles stay below 2^48, exact in a double, and a handle from an earlier
 * load names no object of this one but by a chance of about one in 2^28. */
static double next_id = 0.0;

static double first_id(void)
{
    unsigned long mix = (unsigned long)time(NULL) ^ ((unsigned long)clock() << 7) ^
                        (unsigned long)((uintptr_t)(void *)&table >> 4);
    mix ^= mix >> 17;
    mix *= 0x9e3779b1UL; /* Knuth's multiplicative hash: the bits spread */
    mix ^= mix >> 15;
    return 1.0 + 1048576.0 * (double)(mix & 0xfffffffUL);
}

static void free_object(int kind, void *object)
{
    switch (kind) {
    case MEXH_FIT: fricreg_fit_free(object); break;
    case MEXH_HB: mexhb_free(object); break;
    case MEXH_STRUCTURE: mexst_free(object); break;
    default: break;
    }
}

double mexh_add(int kind, void *object)
{
    size_t slot = capacity;
    if (next_id == 0.0)
        next_id = first_id();
    for (size_t i = 0; i < capacity; i++)
        if (table[i].id == 0.0) {
            slot = i;
            break;
        }
    if (slot == capacity) {
        size_t grown = capacity ? 2 * capacity : 16;
        entry *bigger = realloc(table, grown * sizeof *bigger);
        if (bigger == NULL) {
            free_object(kind, object);
            mexa_status(FRICREG_ENOMEM, "handle table", "out of memory for a new handle");
        }
        for (size_t i = capacity; i < grown; i++)
            bigger[i].id = 0.0;
        table = bigger;
        capacity = grown;
    }
    table[slot].id = next_id;
    table[slot].kind = kind;
    table[slot].object = object;
    table[slot].aux = 0;
    live++;
    next_id += 1.0;
    return table[slot].id;
}

/* The slot of the handle in a, or raises fricreg:handle. */
static size_t find(const mxArray *a, const char *cmd)
{
    double id;
    if (!mxIsDouble(a) || mxIsComplex(a) || mxIsSparse(a) || mxGetNumberOfElements(a) != 1)
        mexa_error("fricreg:handle", "%s: a handle is a real double scalar, not %s of %d elements",
                   cmd, mxGetClassName(a), (int)mxGetNumberOfElements(a));
    id = mxGetPr(a)[0];
    if (id > 0.0 && id == floor(id))
        for (size_t i = 0; i < capacity; i++)
            if (table[i].id == id)
                return i;
    mexa_error("fricreg:handle",
               "%s: %.17g is not a live handle (freed, never made, or made "
               "before the MEX file was cleared)",
               cmd, id);
    return capacity; /* not reached: mexErrMsgIdAndTxt does not return */
}

void *mexh_get(const mxArray *a, int kind, const char *cmd, size_t **aux)
{
    size_t i = find(a, cmd);
    if (table[i].kind != kind)
        mexa_error("fricreg:handle", "%s: handle %.17g is not of this command's kind", cmd,
                   table[i].id);
    if (aux != NULL)
        *aux = &table[i].aux;
    return table[i].object;
}

void mexh_free(const mxArray *a, const char *cmd)
{
    size_t i = find(a, cmd);
    free_object(table[i].kind, table[i].object);
    table[i].id = 0.0;
    table[i].object = NULL;
    live--;
}

void mexh_free_all(void)
{
    for (size_t i = 0; i < capacity; i++)
        if (table[i].id != 0.0)
            free_object(table[i].kind, table[i].object);
    free(table);
    table = NULL;
    capacity = 0;
    live = 0;
    /* next_id is kept: handles made before stay unknown if the table is used again */
}

size_t mexh_count(void)
{
    return live;
}
