#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The modules of src/ are layered as src/README.md's table says: a file may include, and an
# object file may call, only its own module and the modules on lower floors. So no arrow runs
# back up and every circle stays inside one folder. Also: every folder of src/ is in the table,
# and ctx_internal.h is included only inside src/ctx/.
# Includes are read from the sources; calls from the object files of a built tree (nm), when
# BUILD_DIR is given. Usage: module_layers.sh SRC_DIR [BUILD_DIR]
src=$1 build=${2:-}
[ -z "$build" ] || build=$(cd "$build" && pwd) || exit 1
cd "$src" || exit 1
work=$(mktemp -d "${TMPDIR:-/tmp}/fricreg-layers.XXXXXX")
trap 'rm -rf "$work"' EXIT

# "module floor" per table row: | 2 | `ctx/` | ...
awk -F'|' '/^\| *[0-9]+ *\| *`[a-z_]+\/` *\|/ {
    floor = $2; gsub(/ /, "", floor); module = $3; gsub(/[ `\/]/, "", module); print module, floor }' \
    README.md >"$work/floors"
[ -s "$work/floors" ] || { echo "FAIL: src/README.md has no module table"; exit 1; }
fails=0 checked=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }
floor_of() { awk -v m="$1" '$1 == m { print $2 }' "$work/floors"; }

for dir in */; do
    dir=${dir%/}
    [ -n "$(floor_of "$dir")" ] || fail "src/$dir/ is not in src/README.md's module table"
done

# Each header's module, for bare includes reached through an include path (cli -> problems.h).
find . -name '*.h' | sed 's|^\./||' | awk -F/ '{ print $NF, $1 }' >"$work/headers"

# "file module included-module" for every include of an internal header.
for file in $(find . -name '*.c' -o -name '*.h' | sed 's|^\./||' | sort); do
    module=${file%%/*}
    grep -o '^#include "[^"]*"' "$file" | sed 's/^#include "//; s/"$//' | while read -r inc; do
        case $inc in
        */*) echo "$file $module ${inc%%/*} $inc" ;;
        *)
            if [ -f "$(dirname "$file")/$inc" ]; then
                echo "$file $module $module $inc"
            else
                owner=$(awk -v h="$inc" '$1 == h { print $2; exit }' "$work/headers")
                [ -n "$owner" ] && echo "$file $module $owner $inc"
            fi
            ;;
        esac
    done
done >"$work/includes"

while read -r file module used inc; do
    checked=$((checked + 1))
    [ "$used" = "$module" ] && continue
    mf=$(floor_of "$module") uf=$(floor_of "$used")
    if [ -z "$uf" ] || [ "$uf" -ge "$mf" ]; then
        fail "src/$file (floor $mf) includes $inc of $used/ (floor ${uf:-?})"
    fi
    case $inc in
    *ctx_internal.h) fail "src/$file includes $inc outside src/ctx/" ;;
    esac
done <"$work/includes"

# Calls: each object's undefined symbols, resolved to the module that defines them.
if [ -n "$build" ]; then
    # the objects of the library, the problems and fricreg-sim whose source still exists (a
    # tree built before a move keeps the old objects)
    objects=$(find "$build/CMakeFiles" -path '*.dir/src/*.c.o' 2>/dev/null |
        grep -E '/(fricreg_objects|fricreg_problems|fricreg-sim)\.dir/' |
        while read -r o; do
            rel=${o#*.dir/src/}
            [ -f "${rel%.o}" ] && echo "$o"
        done)
    [ -n "$objects" ] || fail "no object files of the library under $build/CMakeFiles"
    for o in $objects; do
        module=${o#*.dir/src/}
        module=${module%%/*}
        nm --defined-only -g "$o" | awk -v m="$module" 'NF == 3 { print $3, m }'
    done | sort -u >"$work/defined"
    for o in $objects; do
        rel=${o#*.dir/src/}
        module=${rel%%/*}
        nm -u "$o" | awk '{ print $2 }' | while read -r sym; do
            owner=$(awk -v s="$sym" '$1 == s { print $2; exit }' "$work/defined")
            [ -n "$owner" ] && [ "$owner" != "$module" ] && echo "${rel%.o} $module $owner $sym"
        done
    done | sort -u >"$work/calls"
    while read -r file module used sym; do
        checked=$((checked + 1))
        mf=$(floor_of "$module") uf=$(floor_of "$used")
        [ "$uf" -lt "$mf" ] || fail "src/$file (floor $mf) calls $sym of $used/ (floor $uf)"
    done <"$work/calls"
fi
echo "$((checked - fails)) passed, $fails failed"
[ $fails -eq 0 ]
