/* SPDX-License-Identifier: GPL-3.0-or-later */
/* disk_kind.h — internal: what an evaluation decided for a contact of a 2-D context, kept for
 * the tangent and read by the reduced Hessian's frames (disk_factor.h). */
#ifndef FRICREG_DISK_KIND_H
#define FRICREG_DISK_KIND_H

enum fr_disk_kind {
    FR_DISK_FIXED = 0, /* sliding, mun = 0 or a radius 0: f_i does not depend on the others */
    FR_DISK_FREE = 1,  /* near stick, inside K_i */
    FR_DISK_CIRCLE = 2 /* near stick, on the circle of K_i */
};

#endif
