#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The README's "Layout" table is true: every path it lists exists, and every top-level entry
# of the repository (tracked files and folders) is listed; and the README names every public
# header of include/ (X.h.in by the X.h the build makes of it). Usage: readme_layout.sh ROOT
root=$1
cd "$root" || exit 1
listed=$(awk '/^## / {inside = ($0 == "## Layout"); next}
              inside && /^\| `[^`]+` \|/ {sub(/^\| `/, ""); sub(/`.*/, ""); print}' README.md)
[ -n "$listed" ] || { echo "FAIL: README.md has no Layout table"; exit 1; }
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    top=$(git ls-files | sed 's|/.*|/|' | sort -u)
else # an unpacked release
    top=$(ls -A | grep -v '^build' | while read -r e; do [ -d "$e" ] && echo "$e/" || echo "$e"; done)
fi
fails=0 checked=0
for path in $listed; do
    checked=$((checked + 1))
    [ -e "$path" ] || { echo "FAIL: the Layout lists $path, which does not exist"; fails=$((fails + 1)); }
done
nl='
'
for entry in $top; do
    checked=$((checked + 1))
    case "$nl$listed$nl" in # a whole line of the list (the shell's own match: no process per entry)
    *"$nl$entry$nl"*) ;;
    *) echo "FAIL: top-level $entry is not in the README's Layout"; fails=$((fails + 1)) ;;
    esac
done
for header in include/*.h include/*.h.in; do
    checked=$((checked + 1))
    name=$(basename "$header" .in)
    grep -q "\`$name\`" README.md ||
        { echo "FAIL: the README does not name the public header $name"; fails=$((fails + 1)); }
done
echo "$((checked - fails)) passed, $fails failed"
[ $fails -eq 0 ]
