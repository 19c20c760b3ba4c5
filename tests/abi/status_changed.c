/* SPDX-License-Identifier: GPL-3.0-or-later */
/* status_changed.c — a deliberately incompatible src/base/status.c for the ABI check's own test:
 * fricreg_version_number returns a long instead of an int. (A function no other file calls,
 * so this definition is the only debug information that describes it.) Linked with the other
 * objects into a probe library that tests/abi_bites.sh expects tests/abi_check.sh to reject.
 * Not part of fricreg. */
#define PROBE_API __attribute__((visibility("default")))

PROBE_API const char *fricreg_strerror(int status);
PROBE_API long fricreg_version_number(void);
PROBE_API const char *fricreg_version(void);

const char *fricreg_strerror(int status)
{
    return status == 0 ? "success" : "error";
}

long fricreg_version_number(void)
{
    return 10000L;
}

const char *fricreg_version(void)
{
    return "1.0.0";
}
