#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The CalculiX tier's set-up (fixture calculix): Debian's source of ccx 2.20, built twice in
# WORK_DIR, privately (ccx is GPL-2.0-only: never installed, never shipped; README.md here):
#   WORK_DIR/stock/ccx     debian/rules build, unchanged (the reference)
#   WORK_DIR/patched/ccx   the same objects with ccx-fricreg.patch applied (its four friction
#                          blocks call fricreg's FRELEV), relinked with libfricreg_fortran and
#                          libfricreg; run-path to FRICREG_LIB_DIR
#   WORK_DIR/patched-iwan/ccx  the same with ccx-iwan.patch on top (the four blocks call
#                          fricreg's Iwan hook FRCCXI, frccxi.f here, compiled and linked in;
#                          *CONTACT PRINT with 17 digits): test calculix_iwan's ccx
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

# The Iwan build: the stock tree with both patches, FRCCXI compiled with fricreg.fi (and
# without a warning) and linked in through LDFLAGS (an object is linked wherever it stands).
iwan_patch=$(dirname "$patch")/ccx-iwan.patch
hook=$(dirname "$patch")/frccxi.f
say "patching with ccx-iwan.patch and relinking into patched-iwan/ccx"
rm -rf patched-iwan-tree patched-iwan && cp -a stock-tree patched-iwan-tree &&
    rm -f patched-iwan-tree/debian/debhelper-build-stamp patched-iwan-tree/ccx_$version/src/ccx_$version &&
    patch -d patched-iwan-tree -p1 <"$patch" >>"$log" 2>&1 &&
    patch -d patched-iwan-tree -p1 <"$iwan_patch" >>"$log" 2>&1 || fail "ccx-iwan.patch does not apply"
mkdir -p patched-iwan &&
    gfortran -Wall -Werror -O2 -I"$fi_dir" -c "$hook" -o patched-iwan/frccxi.o >>"$log" 2>&1 ||
    fail "frccxi.f does not compile without warnings"
(cd patched-iwan-tree &&
    DEB_BUILD_OPTIONS=parallel=2 DEB_FFLAGS_APPEND="-I$fi_dir" \
    DEB_LDFLAGS_APPEND="$work/patched-iwan/frccxi.o -L$flib -L$lib -Wl,-rpath,$lib -lfricreg_fortran -lfricreg" \
    debian/rules build) >>"$log" 2>&1 || fail "the patched-iwan build"
cp patched-iwan-tree/ccx_$version/src/ccx_$version patched-iwan/ccx || fail "no patched-iwan binary"
nm patched-iwan/ccx | grep -q ' T frccxi_' || fail "the patched-iwan ccx has no FRCCXI"
nm -u patched-iwan/ccx | grep -q fricreg_element_eval || fail "the patched-iwan ccx does not call fricreg"
say "stock, patched and patched-iwan ccx in $work"
echo "1 passed, 0 failed"
