#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The API reference builds with no warning, and is organized by object: Doxygen runs on the
# configured Doxyfile (docs/Doxyfile.in, as `cmake --build build --target docs` does) into a
# temporary folder, and fails on any warning (a broken link or \ref, an unknown command, an
# undocumented declaration: WARN_AS_ERROR, and here any line on its error output); then every
# public function, type, enum and macro of HEADER (a header, or a folder of them) must be a
# member of exactly one group (\defgroup, the Modules page). Exits 77, which ctest reports as
# skipped, when Doxygen is absent. Usage: doxygen_check.sh DOXYGEN|- DOXYFILE HEADER...
doxygen=$1 doxyfile=$2
shift 2
if [ "$doxygen" = "-" ] || ! command -v "$doxygen" >/dev/null 2>&1; then
    echo "Doxygen not found: the API reference check is skipped"
    exit 77
fi
[ -f "$doxyfile" ] || { echo "FAIL: no Doxyfile $doxyfile"; exit 1; }
work=$(mktemp -d "${TMPDIR:-/tmp}/fricreg-doxygen.XXXXXX")
trap 'rm -rf "$work"' EXIT
fails=0 checked=0
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

# The reference as the docs target renders it, plus XML for the group check below.
checked=$((checked + 1))
{ cat "$doxyfile"; printf 'OUTPUT_DIRECTORY = %s\nGENERATE_XML = YES\nXML_PROGRAMLISTING = NO\n' "$work"; } |
    "$doxygen" - >"$work/out" 2>"$work/warnings"
status=$?
if [ $status -ne 0 ] || [ -s "$work/warnings" ]; then
    fail "doxygen exited with $status and $(grep -c . "$work/warnings") lines of warnings:"
    cat "$work/warnings"
fi
checked=$((checked + 1)) # Doxygen 1.9 names the page of groups Modules, 1.10 and later Topics
[ -f "$work/html/modules.html" ] || [ -f "$work/html/topics.html" ] ||
    fail "no Modules (Topics) page: the reference has no groups"

# Each group's members, "group name" per line, from the XML (a memberdef's first <name>).
for xml in "$work"/xml/group__*.xml; do
    [ -f "$xml" ] || break
    awk '/<compoundname>/ { g = $0; sub(/.*<compoundname>/, "", g); sub(/<.*/, "", g) }
         /<memberdef / { m = 1; next }
         m && /<name>/ { n = $0; sub(/.*<name>/, "", n); sub(/<.*/, "", n); print g, n; m = 0 }' "$xml"
done >"$work/members"
# The public declarations: FRICREG_API functions, typedefs (callbacks too), enums, and the
# macros but the include guards.
declarations() {
    grep -ho 'FRICREG_API [^(]*(' "$1" | sed 's/($//' | awk '{print $NF}' | tr -d '*'
    sed -n -e 's/^typedef .*(\*\(fricreg_[a-z0-9_]*\)).*/\1/p' \
        -e 's/^typedef [^(]* \(fricreg_[a-z0-9_]*\);.*/\1/p' \
        -e 's/^enum \(fricreg_[a-z0-9_]*\) {.*/\1/p' \
        -e 's/^#define \(FRICREG_[A-Z0-9_]*\).*/\1/p' "$1" | grep -v '_H$'
}
for header in "$@"; do
    if [ -d "$header" ]; then
        for h in "$header"/*.h; do declarations "$h"; done
    else
        declarations "$header"
    fi
done | sort -u >"$work/declared"
[ -s "$work/declared" ] || fail "no declarations found in $*"
# Each declaration's groups, in one awk (an awk per declaration took seconds a run).
awk 'FILENAME == ARGV[1] { groups[$2] = groups[$2] $1 " "; next }
     !($0 in groups) { print "FAIL: " $0 " is in no group (add it to its object'"'"'s \\{ ... \\} block)" }
     split(groups[$0], g, " ") > 1 { print "FAIL: " $0 " is in more than one group: " groups[$0] }' \
    "$work/members" "$work/declared" >"$work/groups"
cat "$work/groups"
checked=$((checked + $(grep -c . "$work/declared")))
fails=$((fails + $(grep -c '^FAIL' "$work/groups")))
echo "$((checked - fails)) passed, $fails failed ($(wc -l <"$work/declared") declarations in \
$(ls "$work"/xml/group__*.xml 2>/dev/null | wc -l) groups)"
[ $fails -eq 0 ]
