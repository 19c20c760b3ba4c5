#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The shared library exports exactly the functions the public headers declare with
# FRICREG_API, each tagged with a FRICREG_<major>.<minor> version node, and its SONAME is
# libfricreg.so.<SOVERSION>. Usage: exports.sh LIBRARY SOVERSION HEADER...
library=$1 soversion=$2
shift 2
fails=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

soname=$(readelf -d "$library" | sed -n 's/.*Library soname: \[\(.*\)\]/\1/p')
[ "$soname" = "libfricreg.so.$soversion" ] || fail "SONAME is '$soname', expected libfricreg.so.$soversion"

declared=$(grep -ho 'FRICREG_API [^(]*(' "$@" | sed 's/($//' | awk '{print $NF}' | tr -d '*' | sort)
exported=$(nm -D --defined-only "$library" | awk '$2 != "A" {print $3}' | sort)
untagged=$(echo "$exported" | grep -v '@@FRICREG_[0-9]*\.[0-9]*$')
[ -z "$untagged" ] || fail "symbols without a version node: $untagged"
names=$(echo "$exported" | sed 's/@.*//' | sort)
only_exported=$(echo "$declared" | comm -13 - "$(echo "$names" > "${TMPDIR:-/tmp}/exported.$$" && echo "${TMPDIR:-/tmp}/exported.$$")")
only_declared=$(echo "$declared" | comm -23 - "${TMPDIR:-/tmp}/exported.$$")
rm -f "${TMPDIR:-/tmp}/exported.$$"
[ -z "$only_exported" ] || fail "exported but not declared (not API): $only_exported"
[ -z "$only_declared" ] || fail "declared but not exported (missing from src/fricreg.map?): $only_declared"
echo "$((4 - fails)) passed, $fails failed"
[ $fails -eq 0 ]
