#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The ABI check must reject a broken library: runs tests/abi_check.sh on a probe library and
# passes only if the check fails and names the symbol that was broken.
# Usage: abi_bites.sh ABI_CHECK BASELINE PROBE_LIBRARY SYMBOL HEADER_DIR...
check=$1 baseline=$2 probe=$3 symbol=$4
shift 4
report=$(sh "$check" "$baseline" "$probe" "$@" 2>&1)
status=$?
if [ $status -eq 1 ] && echo "$report" | grep -q "$symbol"; then
    echo "abi_bites: the check rejects $probe, naming $symbol"
    echo "1 passed, 0 failed"
    exit 0
fi
echo "$report"
echo "abi_bites: the check did not reject $probe for $symbol (status $status)"
echo "0 passed, 1 failed"
exit 1
