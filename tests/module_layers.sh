#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The modules of src/ are layered as src/README.md's table says: a file may include, and an
# object file may call, only its own module and the modules on lower floors. So no arrow runs
# back up and every circle stays inside one folder; and inside a folder, no circle of calls
# and includes between its files either (a file uses only files that do not use it back,
# directly or round about; its module's *_internal.h, the layout, aside); and a folder that lists its files by floor (src/README.md's second table) lists
# every .c of it, and its files include the headers of, and call, only its files on lower
# floors. Also: every folder of src/ is in the table, a module's *_internal.h (its object's
# layout) is included only inside its folder (hb/hb_internal.h, the driver's, aside: the
# modules built on the driver include it), what a module hangs on the driver (a pointer of
# hb/hb_internal.h to a struct that the module's *_internal.h lays out, e.g. forced/'s
# hb->forced) is named only inside that module's folder, and no file of src/ is over 600
# lines.
# Includes are read from the sources; calls from the object files of a built tree (nm), when
# BUILD_DIR is given. A fixed handful of processes (find, two nm, a few awk) however many
# files, includes and symbols: an awk per lookup took a minute.
# Usage: module_layers.sh SRC_DIR [BUILD_DIR]
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
# "module/file floor" per row of the files' table: | `hb/` | 3 | `newton` `corrector` |
awk -F'|' '/^\| *`[a-z_]+\/` *\| *[0-9]+ *\|/ {
    module = $2; gsub(/[ `]/, "", module); floor = $3; gsub(/ /, "", floor)
    n = split($4, names, /[ `]+/)
    for (i = 1; i <= n; i++) if (names[i] != "") print module names[i], floor }' \
    README.md >"$work/inner"

# The folders, every file (an include next to its file must exist; a bare one is owned by the
# module of the header of that name, the first found), and the sources, sorted.
for dir in */; do [ -d "$dir" ] && echo "${dir%/}"; done >"$work/dirs"
find . ! -type d | sed 's|^\./||' >"$work/files"
grep -E '\.[ch]$' "$work/files" | sort >"$work/sources"

# Calls: each object's undefined symbols, resolved to the module that defines them, as
# "file module owner symbol".
: >"$work/calls"
: >"$work/edges"
nobjects=-
if [ -n "$build" ]; then
    # the objects of the library, the problems and fricreg-sim whose source still exists (a
    # tree built before a move keeps the old objects)
    objects=$(find "$build/CMakeFiles" -path '*.dir/src/*.c.o' 2>/dev/null |
        grep -E '/(fricreg_objects|fricreg_problems|fricreg_cli|fricreg-sim)\.dir/' |
        while read -r o; do
            rel=${o#*.dir/src/}
            [ -f "${rel%.o}" ] && echo "$o"
        done)
    nobjects=$(echo "$objects" | grep -c .)
    if [ "$nobjects" -gt 0 ]; then
        # nm -A prefixes each line with "OBJECT:"; a symbol defined in two modules belongs to
        # the first of them in sorted order
        # shellcheck disable=SC2086 # the objects are words
        { nm --defined-only -g -A $objects | sed 's/^/D /'; nm -u -A $objects | sed 's/^/U /'; } |
            awk -v edges="$work/edges" '
                 function rel(path,    p) { sub(/:[^:]*$/, "", path); p = index(path, ".dir/src/")
                                             return substr(path, p + 9) }
                 function module(r) { sub(/\/.*/, "", r); return r }
                 $1 == "D" && NF == 4 { r = rel($2); m = module(r)
                                         if (!($4 in owner) || m < owner[$4]) { owner[$4] = m; file[$4] = r }
                                         next }
                 $1 == "U" { r = rel($2); m = module(r); s = $NF
                             if ((s in owner) && owner[s] != m) print substr(r, 1, length(r) - 2), m, owner[s], s
                             else if ((s in owner) && file[s] != r)
                                 print substr(r, 1, length(r) - 2), substr(file[s], 1, length(file[s]) - 2) > edges }' |
            sort -u >"$work/calls"
    fi
fi

awk -v nobjects="$nobjects" -v build="$build" -v inner="$work/inner" '
function fail(what) { print "FAIL: " what; fails++ }
function floor_of(m) { return (m in floor) ? floor[m] : "" }
function stem(path) { sub(/\.[ch]$/, "", path); return path }
BEGIN { # the files by floor inside a module: "hb/newton" -> 3; listed[module] once it lists any
    while ((getline line < inner) > 0) {
        split(line, w, " "); infloor[w[1]] = w[2]; m = w[1]; sub(/\/.*/, "", m); listed[m] = 1 }
    close(inner)
}
FILENAME == ARGV[1] { if (!($1 in floor)) floor[$1] = $2; next }
FILENAME == ARGV[2] { if (floor_of($0) == "") fail("src/" $0 "/ is not in src/README.md'\''s module table"); next }
FILENAME == ARGV[3] {
    exists[$0] = 1
    if ($0 ~ /\.h$/) { base = $0; sub(/.*\//, "", base); m = $0; sub(/\/.*/, "", m)
                       if (!(base in owner)) owner[base] = m }
    m = $0; sub(/\/.*/, "", m)
    if ($0 ~ /\.c$/ && (m in listed) && !(stem($0) in infloor))
        fail("src/" $0 " is not in src/README.md" "\047" "s table of " m "/" "\047" "s files")
    next
}
FILENAME == ARGV[4] { # includes of internal headers
    file = $0; module = file; sub(/\/.*/, "", module)
    dir = file; if (!sub(/\/[^\/]*$/, "", dir)) dir = ""
    while ((getline line < file) > 0) {
        if (!match(line, /^#include "[^"]*"/)) continue
        inc = substr(line, 11, RLENGTH - 11)
        if (inc ~ /\//) { used = inc; sub(/\/.*/, "", used) }
        else if (((dir == "" ? "" : dir "/") inc) in exists) used = module
        else if (inc in owner) used = owner[inc]
        else continue
        checked++
        if (used == module) {
            own = stem(file); hdr = (dir == "" ? "" : dir "/") stem(inc)
            if ((own in infloor) && (hdr in infloor) && hdr != own && infloor[hdr] + 0 >= infloor[own] + 0)
                fail("src/" file " (" module "/ floor " infloor[own] ") includes " inc " of " hdr " (floor " infloor[hdr] ")")
            continue
        }
        mf = floor_of(module); uf = floor_of(used)
        if (uf == "" || (mf != "" && uf + 0 >= mf + 0))
            fail("src/" file " (floor " mf ") includes " inc " of " used "/ (floor " (uf == "" ? "?" : uf) ")")
        if (inc ~ /_internal\.h$/ && inc != "hb/hb_internal.h")
            fail("src/" file " includes " inc " outside src/" used "/")
    }
    close(file)
    next
}
FILENAME == ARGV[6] { # calls between the files of one folder: "file.c file.c"
    caller = stem($1); callee = stem($2); m = caller; sub(/\/.*/, "", m)
    if ((caller in infloor) && (callee in infloor) && !(($1 " " $2) in seen)) {
        seen[$1 " " $2] = 1
        checked++
        if (infloor[callee] + 0 >= infloor[caller] + 0)
            fail("src/" $1 " (" m "/ floor " infloor[caller] ") calls src/" $2 " (floor " infloor[callee] ")")
    }
    next
}
{ # calls: "file module owner symbol"
    checked++
    mf = floor_of($2); uf = floor_of($3)
    if (!(uf != "" && mf != "" && uf + 0 < mf + 0))
        fail("src/" $1 " (floor " mf ") calls " $4 " of " $3 "/ (floor " uf ")")
}
END {
    if (nobjects == 0) fail("no object files of the library under " build "/CMakeFiles")
    printf "%d passed, %d failed\n", checked - fails, fails
    exit fails > 0
}' "$work/floors" "$work/dirs" "$work/files" "$work/sources" "$work/calls" "$work/edges" || status=1

# What a module hangs on the driver is its own: each pointer "struct fr_hb_X *field;" of
# hb/hb_internal.h whose struct a module's *_internal.h lays out ("struct fr_hb_X {") is named
# ("->field") in no file outside that module's folder that sees the driver's layout (includes
# hb/hb_internal.h, directly or through headers of src/). Others reach it through its
# functions.
# shellcheck disable=SC2046 # the sources are words
awk '
FNR == 1 { file = FILENAME; dir = file; sub(/\/[^\/]*$/, "", dir); top = file; sub(/\/.*/, "", top) }
match($0, /^#include "[^"]*"/) {
    inc = substr($0, 11, RLENGTH - 11)
    incs[file] = incs[file] " " (inc ~ /\// ? inc : dir "/" inc) }
file ~ /_internal\.h$/ && match($0, /^struct fr_hb_[a-z_0-9]+ \{/) {
    name = substr($0, 8, RLENGTH - 9); lays[name] = top }
file == "hb/hb_internal.h" && match($0, /^ *struct fr_hb_[a-z_0-9]+ \*[a-z_0-9]+;/) {
    split(substr($0, RSTART, RLENGTH), w, /[ *;]+/); i = (w[1] == "" ? 2 : 1)
    hung[w[i + 2]] = w[i + 1] }
{ text[file] = text[file] "\n" $0 }
END {
    sees["hb/hb_internal.h"] = 1
    do { # the files that include one that sees it, round after round
        added = 0
        for (f in text)
            if (!(f in sees)) {
                k = split(incs[f], list, " ")
                for (i = 1; i <= k; i++)
                    if (list[i] in sees) { sees[f] = 1; added++; break }
            }
    } while (added > 0)
    for (field in hung) {
        owner = lays[hung[field]]
        if (owner == "" || owner == "hb") continue
        for (f in sees) {
            d = f; sub(/\/.*/, "", d)
            if (d != owner && text[f] ~ ("->" field "([^a-z_0-9]|$)")) {
                print "FAIL: src/" f " names ->" field ", the state " owner "/ hangs on the driver, outside src/" owner "/"
                fails++
            }
        }
    }
    exit fails > 0
}' $(cat "$work/sources") || status=1

# Includes between the files of one folder, as edges like the calls' ("dir/x.c dir/y.c", a
# header standing for the .c beside it): a file that includes the header of a file that calls
# it is on a circle too. A module's *_internal.h, its object's layout, is below its files and
# left out.
awk -v files="$work/files" '
BEGIN { while ((getline f < files) > 0) exists[f] = 1 }
function node(path,    c) { c = path; sub(/\.h$/, ".c", c); return (c in exists) ? c : path }
{
    file = $0; dir = file; if (!sub(/\/[^\/]*$/, "", dir)) next
    if (file ~ /_internal\.h$/) next
    while ((getline line < file) > 0) {
        if (!match(line, /^#include "[a-z_0-9]+\.h"/)) continue
        inc = dir "/" substr(line, 11, RLENGTH - 11)
        if (!(inc in exists) || inc ~ /_internal\.h$/) continue
        if (node(inc) != node(file)) print node(file), node(inc)
    }
    close(file)
}' "$work/sources" >>"$work/edges"

# Circles of calls and includes between the files of one folder: the files left once every
# file that uses no file still left, or that no file still left uses, is taken away, round
# after round, are those on a circle; each is named with the files it uses among them.
sort -u "$work/edges" | awk '
{ out[$1] = out[$1] " " $2; node[$1] = 1; node[$2] = 1; from[NR] = $1; to_[NR] = $2 }
END {
    do {
        removed = 0
        for (f in node) { calls[f] = 0; called[f] = 0 }
        for (e = 1; e <= NR; e++)
            if ((from[e] in node) && (to_[e] in node)) { calls[from[e]]++; called[to_[e]]++ }
        for (f in node)
            if (calls[f] == 0 || called[f] == 0) { delete node[f]; removed++ }
    } while (removed > 0)
    for (f in node) {
        list = ""; k = split(out[f], to, " ")
        for (i = 1; i <= k; i++) if (to[i] in node) list = list " " to[i]
        print "FAIL: src/" f " is on a circle of calls and includes (it uses" list ")"
        fails++
    }
    exit fails > 0
}' || status=1
# One concept per file: no source of src/ over 600 lines (the house rule, docs/contributing.md).
# shellcheck disable=SC2046 # the sources are words
wc -l $(cat "$work/sources") | awk '$2 != "total" && $1 > 600 {
    print "FAIL: src/" $2 " has " $1 " lines, over 600: split it by concept"; fails++ }
    END { exit fails > 0 }' || status=1

exit "${status:-0}"
