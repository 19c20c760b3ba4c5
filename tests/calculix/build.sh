#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The CalculiX tier's set-up (fixture calculix): Debian's source of ccx 2.20, built twice in
# WORK_DIR, privately (ccx is GPL-2.0-only: never installed, never shipped; README.md here):
#   WORK_DIR/stock/ccx     debian/rules build, unchanged (the reference)
#   WORK_DIR/patched/ccx   the same objects with ccx-fricreg.patch applied (its four friction
#                          blocks call fricreg's FRELEV), relinked with libfricreg_fortran and
#                          libfricreg; run-path to FRICREG_LIB_DIR
# The stock build (about 8 minutes on two cores) is kept between runs; the patched copy is
# made again from it every run (seconds), so it always holds the patch and the library of
# this tree. Needs the build dependencies and a deb-src entry (the README's command).
# Usage: build.sh WORK_DIR PATCH FRICREG_FI_DIR FRICREG_LIB_DIR FRICREG_FORTRAN_LIB_DIR
work=$1 patch=$2 fi_dir=$3 lib=$4 flib=$5
version=2.20
src=calculix-ccx-$version
mkdir -p "$work" || exit 1
cd "$work" || exit 1
log=$work/build.log
: >"$log"
say() { echo "$*"; echo "$*" >>"$log"; }
fail() { echo "FAIL: $*"; tail -n 30 "$log"; echo "0 passed, 1 failed"; exit 1; }

for tool in apt-get dpkg-source gfortran patch make; do
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

# The patched copy: the stock tree's objects, the four patched files newer than theirs, so
# debian/rules build (its stamp removed) recompiles those four and relinks. fricreg.fi comes
# through FFLAGS, the libraries through LDFLAGS (dpkg-buildflags' _APPEND variables, read by
# debian/rules); ccx's link line puts LDFLAGS after its own libraries.
say "patching and relinking ccx against $lib/libfricreg"
rm -rf patched-tree patched && cp -a stock-tree patched-tree &&
    rm -f patched-tree/debian/debhelper-build-stamp patched-tree/ccx_$version/src/ccx_$version &&
    patch -d patched-tree -p1 <"$patch" >>"$log" 2>&1 || fail "the patch does not apply"
(cd patched-tree &&
    DEB_BUILD_OPTIONS=parallel=2 DEB_FFLAGS_APPEND="-I$fi_dir" \
    DEB_LDFLAGS_APPEND="-L$flib -L$lib -Wl,-rpath,$lib -lfricreg_fortran -lfricreg" \
    debian/rules build) >>"$log" 2>&1 || fail "the patched build"
mkdir -p patched && cp patched-tree/ccx_$version/src/ccx_$version patched/ccx || fail "no patched binary"
# The patched binary calls fricreg, and the stock one does not.
nm -u patched/ccx | grep -q fricreg_element_eval || fail "the patched ccx does not call fricreg"
nm stock/ccx 2>/dev/null | grep -q fricreg && fail "the stock ccx calls fricreg"
say "stock and patched ccx in $work"
echo "1 passed, 0 failed"
