#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Whether a C test program's valgrind run guards a change since REF (tests/changed_files.sh:
# "landed", "release" or a commit): the release tier's changed scope runs only those
# (FRICREG_RELEASE_SCOPE=changed, a stop; tests/valgrind.sh --changed-since). It does when
#  - the changes cannot be known (no git, a shallow clone): every program runs;
#  - the compiler flags (cmake/c_flags_init.cmake) or the harness changed
#    (valgrind.sh, its suppressions, this file, changed_files.sh). The other CMake files are
#    not read: a new source file is a change of its module, a new test a new source; a link
#    or flag change that breaks memory is ASan's and UBSan's to see at the same stop;
#  - the program's source changed, or a file of the tree it includes (its test headers, an
#    example's model) or the .c beside such a header, followed through their own includes;
#  - a module it exercises changed (a file of src/M/, or include/'s header of M). A program
#    exercises the modules whose headers it includes (a public header names its module in
#    the table below; "M/x.h" and a bare "x.h" found in src/M/ name M) and every module on a
#    lower floor of src/README.md's table, which those may call (tests/module_layers.sh).
#    fricreg_hb.h's functions live in hb/ and in the three modules over it that build on hb/
#    alone (floquet/, nma/, forced/): a change there counts too, but not as a higher floor.
#    A module missing from the table runs everything.
# So a stop's change is checked under valgrind by every program that can reach it, at the stop
# that brings it; ASan and UBSan (tests/sanitize.sh) still run every program at every stop.
#
# Usage: valgrind_scope.sh ROOT REF SOURCE (SOURCE: the program's source, from ROOT)
# Prints why it runs and exits 0, or why not and exits 1.
here=$(cd "$(dirname "$0")" && pwd)
root=$1 ref=$2 source=$3
changes=$(sh "$here/changed_files.sh" "$root" "$ref" 2>/dev/null) || {
    echo "the changes since $ref cannot be known"
    exit 0
}
changed() { printf '%s\n' "$changes" | grep -qxF "$1"; }

harness=$(printf '%s\n' "$changes" | grep -E '^cmake/c_flags_init\.cmake$|^tests/(valgrind\.sh|valgrind\.supp|valgrind_scope\.sh|changed_files\.sh)$' | head -n 1)
[ -n "$harness" ] && { echo "the flags or the harness changed ($harness)"; exit 0; }

# The tree's files the program includes, itself first, by a worklist; and the modules named.
files=$source modules="" above="" todo=$source
while [ -n "$todo" ]; do
    set -- $todo
    file=$1
    shift
    todo=$*
    for name in $(sed -n 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*"\([^"]*\)".*/\1/p' "$root/$file"); do
        found=""
        case $name in
        fricreg.h | fricreg_version.h) modules="$modules ctx base" ;;
        fricreg_types.h) modules="$modules sim structure" ;;
        fricreg_aft.h | fricreg_iwan.h | fricreg_jenkins.h | fricreg_element.h) modules="$modules joint" ;;
        fricreg_disk.h | fricreg_stribeck.h) modules="$modules law" ;;
        fricreg_disk_ctx.h) modules="$modules disk_ctx" ;;
        fricreg_exact.h) modules="$modules exact" ;;
        fricreg_hb.h | fricreg_hb_forced.h | fricreg_hb_stability.h | fricreg_hb_nma.h)
            modules="$modules hb" above="floquet nma forced" ;;
        fricreg_hb_qsma.h) modules="$modules qsma" ;;
        fricreg_sim.h) modules="$modules sim" ;;
        fricreg_structure*.h | fricreg_ctx_step.h) modules="$modules structure" ;;
        fricreg_petsc.h) modules="$modules petsc" ;;
        fricreg*.h) modules="$modules unknown" ;;
        esac
        for dir in "$(dirname "$file")" tests tests/support src; do
            if [ -z "$found" ] && [ -f "$root/$dir/$name" ]; then
                found=$(cd "$root" && realpath --relative-to=. "$dir/$name")
            fi
        done
        if [ -z "$found" ] && [ "${name#*/}" = "$name" ] && [ "${name#fricreg}" = "$name" ]; then
            found=$(cd "$root" && ls -d -- src/*/"$name" 2>/dev/null | head -n 1)
        fi
        case $found in
        src/*/*) # a module's header: the module
            m=${found#src/}
            modules="$modules ${m%%/*}"
            ;;
        ?*) # a test header or an example's model, and its .c beside it: followed
            for f in "$found" "${found%.h}.c"; do
                if [ -f "$root/$f" ] && ! printf '%s\n' $files | grep -qxF "$f"; then
                    files="$files $f"
                    todo="$todo $f"
                fi
            done
            ;;
        esac
    done
done
for file in $files; do
    changed "$file" && { echo "its source or an included file changed ($file)"; exit 0; }
done

# Modules: the changed ones, and the floors of src/README.md's table.
floors=$(awk -F'|' '/^\| *[0-9]+ *\| *`[a-z_]+\/` *\|/ {
    floor = $2; gsub(/ /, "", floor); m = $3; gsub(/[ `\/]/, "", m); print m, floor }' \
    "$root/src/README.md")
floor() { printf '%s\n' "$floors" | awk -v m="$1" '$1 == m {print $2; f = 1} END {if (!f) print -1}'; }
top=-1
for m in $modules; do
    f=$(floor "$m")
    [ "$f" -lt 0 ] && { echo "it includes a module outside src/README.md's table ($m)"; exit 0; }
    [ "$f" -gt "$top" ] && top=$f
done
for file in $(printf '%s\n' "$changes" | grep -E '^(src/[a-z_]+/|include/fricreg)'); do
    case $file in
    src/*) m=${file#src/} m=${m%%/*} ;;
    include/fricreg_aft.h | include/fricreg_iwan.h | include/fricreg_jenkins.h | include/fricreg_element.h) m=joint ;;
    include/fricreg_disk.h | include/fricreg_stribeck.h) m=law ;;
    include/fricreg_disk_ctx.h) m=disk_ctx ;;
    include/fricreg_exact.h) m=exact ;;
    include/fricreg_hb.h | include/fricreg_hb_*.h) m=hb ;;
    include/fricreg_sim.h) m=sim ;;
    include/fricreg_structure*.h | include/fricreg_ctx_step.h) m=structure ;;
    include/fricreg_petsc.h) m=petsc ;;
    *) m=base ;; # fricreg.h, fricreg_types.h, the version: every program's
    esac
    f=$(floor "$m")
    [ "$f" -lt 0 ] && { echo "a module outside src/README.md's table changed ($file)"; exit 0; }
    if [ "$f" -lt "$top" ] || printf '%s\n' $modules $above | grep -qxF "$m"; then
        echo "a module it exercises changed ($file)"
        exit 0
    fi
done
echo "it guards no change since $ref"
exit 1
