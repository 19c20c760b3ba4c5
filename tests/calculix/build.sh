#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The CalculiX tier's set-up (fixture calculix): Debian's source of ccx 2.20, built twice in
# WORK_DIR, privately (ccx is GPL-2.0-only: never installed, never shipped; README.md here):
#   WORK_DIR/stock/ccx     debian/rules build, unchanged (the reference)
#   WORK_DIR/patched/ccx   the same objects with ccx-fricreg.patch applied (each surface
#                          interaction's law from the job's laws file, JOB.fricreg, through
#                          fricreg's hook frccx.c here, compiled and linked in), relinked with
#                          libfricreg; run-path to FRICREG_LIB_DIR
# The stock build (about 8 minutes on two busy cores, 80 s on an idle fast machine) is kept
# between runs; the patched copy is made again from it every run (seconds), so it always holds
# the patch and the library of this tree. Needs the build dependencies and a deb-src entry (the
# README's command).
# Usage: build.sh WORK_DIR PATCH HOOK FRICREG_INCLUDE_DIR FRICREG_GENERATED_INCLUDE_DIR
#                 FRICREG_LIB_DIR
work=$1 patch=$2 hook=$3 inc=$4 geninc=$5 lib=$6
version=2.20
src=calculix-ccx-$version
mkdir -p "$work" || exit 1
cd "$work" || exit 1
log=$work/build.log
: >"$log"
say() { echo "$*"; echo "$*" >>"$log"; }
fail() { echo "FAIL: $*"; tail -n 30 "$log"; echo "0 passed, 1 failed"; exit 1; }

for tool in apt-get dpkg-source gfortran gcc patch make; do
    command -v $tool >/dev/null || fail "no $tool: install the build dependencies (README.md)"
done
if [ ! -d source/$src ]; then
    say "fetching Debian's source of calculix-ccx $version"
    rm -rf source && mkdir source &&
        (cd source && apt-get source -qq calculix-ccx=$version-1) >>"$log" 2>&1 ||
        fail "apt-get source calculix-ccx: is there a deb-src entry? (README.md)"
fi

if [ ! -x stock/ccx ]; then
    say "building stock ccx $version (debian/rules build, about 8 minutes on two cores)"
    start=$(date +%s)
    rm -rf stock-tree && cp -a source/$src stock-tree &&
        (cd stock-tree && DEB_BUILD_OPTIONS=parallel=2 debian/rules build) >>"$log" 2>&1 ||
        fail "the stock build"
    mkdir -p stock && cp stock-tree/ccx_$version/src/ccx_$version stock/ccx || fail "no stock binary"
    say "stock ccx built in $(($(date +%s) - start)) s"
fi

# The patched copy: the stock tree's objects, the patched files newer than theirs, so
# debian/rules build (its stamp removed) recompiles those and relinks. The hook's object and the
# library come through LDFLAGS (dpkg-buildflags' _APPEND variable, read by debian/rules); ccx's
# link line puts LDFLAGS after its own objects and libraries.
say "patching and relinking ccx against $lib/libfricreg"
rm -rf patched-tree patched && cp -a stock-tree patched-tree &&
    rm -f patched-tree/debian/debhelper-build-stamp patched-tree/ccx_$version/src/ccx_$version &&
    patch -d patched-tree -p1 <"$patch" >>"$log" 2>&1 || fail "the patch does not apply"
mkdir -p patched &&
    gcc -std=c99 -O2 -Wall -Wextra -Wpedantic -Werror -I"$inc" -I"$geninc" -c "$hook" \
        -o patched/frccx.o >>"$log" 2>&1 || fail "frccx.c does not compile without warnings"
(cd patched-tree &&
    DEB_BUILD_OPTIONS=parallel=2 \
    DEB_LDFLAGS_APPEND="$work/patched/frccx.o -L$lib -Wl,-rpath,$lib -lfricreg" \
    debian/rules build) >>"$log" 2>&1 || fail "the patched build"
cp patched-tree/ccx_$version/src/ccx_$version patched/ccx || fail "no patched binary"
# The patched binary calls fricreg through the hook, and the stock one does not.
nm patched/ccx | grep -q ' T frccxl_' || fail "the patched ccx has no frccxl"
nm -u patched/ccx | grep -q fricreg_element_eval || fail "the patched ccx does not call fricreg"
nm stock/ccx 2>/dev/null | grep -q fricreg && fail "the stock ccx calls fricreg"
say "stock and patched ccx in $work"
echo "1 passed, 0 failed"
