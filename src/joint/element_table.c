/* SPDX-License-Identifier: GPL-3.0-or-later */
/* element_table.c — the element table: every law's kind, in the order of their Fortran 77
 * codes (fricreg_element_at; new laws are appended, none is moved), and the types made of
 * them. A fixed kind is one type; a family is FRICREG_ELEMENT_MAX_SLIDERS types, one per
 * number of sliders, each knowing its family's first. */
#include <string.h>

#include "element_kind.h"

/* The table, one line per law: FIXED(name) or FAMILY(name), the kind fr_element_<name>
 * defined in the law's file. */
#define FR_ELEMENT_TABLE(FIXED, FAMILY) \
    FIXED(jenkins)                      \
    FIXED(jenkins_2d)                   \
    FIXED(contact_3d)                   \
    FAMILY(iwan)                        \
    FAMILY(iwan_normal)                 \
    FIXED(jenkins_3d)                   \
    FIXED(jenkins_normal)               \
    FAMILY(iwan_2d)                     \
    FAMILY(iwan_3d)                     \
    FIXED(spring)                       \
    FIXED(dahl)

#define FR_DECLARE(name) extern const struct fr_element_kind fr_element_##name;
FR_ELEMENT_TABLE(FR_DECLARE, FR_DECLARE)

/* A fixed kind's type. */
#define FR_FIXED_TYPE(name) \
    static const fricreg_element_type name##_types[1] = {{&fr_element_##name, 1, NULL}};

/* A family's types, member ns - 1 of ns sliders. */
#define FR_MEMBER(name, i)                        \
    {                                             \
        &fr_element_##name, (i) + 1, name##_types \
    }
#define FR_MEMBERS4(name, i) \
    FR_MEMBER(name, i), FR_MEMBER(name, (i) + 1), FR_MEMBER(name, (i) + 2), FR_MEMBER(name, (i) + 3)
#define FR_MEMBERS16(name, i)                                                     \
    FR_MEMBERS4(name, i), FR_MEMBERS4(name, (i) + 4), FR_MEMBERS4(name, (i) + 8), \
        FR_MEMBERS4(name, (i) + 12)
#define FR_MEMBERS64(name, i)                                                          \
    FR_MEMBERS16(name, i), FR_MEMBERS16(name, (i) + 16), FR_MEMBERS16(name, (i) + 32), \
        FR_MEMBERS16(name, (i) + 48)
#define FR_MEMBERS256(name, i)                                                          \
    FR_MEMBERS64(name, i), FR_MEMBERS64(name, (i) + 64), FR_MEMBERS64(name, (i) + 128), \
        FR_MEMBERS64(name, (i) + 192)
#define FR_FAMILY_TYPES(name)                                                       \
    static const fricreg_element_type name##_types[FRICREG_ELEMENT_MAX_SLIDERS] = { \
        FR_MEMBERS256(name, 0), FR_MEMBERS256(name, 256), FR_MEMBERS256(name, 512), \
        FR_MEMBERS256(name, 768)};
#if FRICREG_ELEMENT_MAX_SLIDERS != 1024
#error "FR_FAMILY_TYPES lists 1024 members"
#endif

FR_ELEMENT_TABLE(FR_FIXED_TYPE, FR_FAMILY_TYPES)

#define FR_FIRST(name) name##_types,
static const fricreg_element_type *const table[] = {FR_ELEMENT_TABLE(FR_FIRST, FR_FIRST)};
#define FR_TABLE_SIZE (sizeof table / sizeof table[0])

size_t fricreg_element_count(void)
{
    return FR_TABLE_SIZE;
}

const fricreg_element_type *fricreg_element_at(size_t index)
{
    return index < FR_TABLE_SIZE ? table[index] : NULL;
}

const fricreg_element_type *fricreg_element_lookup(const char *name)
{
    if (name == NULL)
        return NULL;
    for (size_t i = 0; i < FR_TABLE_SIZE; i++)
        if (strcmp(name, table[i]->kind->name) == 0)
            return table[i];
    return NULL;
}

const fricreg_element_type *fricreg_element_sliders(const fricreg_element_type *type, size_t ns)
{
    if (type == NULL || ns == 0)
        return NULL;
    if (type->family == NULL)
        return ns == 1 ? type : NULL;
    return ns <= FRICREG_ELEMENT_MAX_SLIDERS ? &type->family[ns - 1] : NULL;
}
