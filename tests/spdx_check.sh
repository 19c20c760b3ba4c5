#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Every tracked source file names its licence in an SPDX line: C (.c, .h), Fortran (.f90, .F90,
# .f, .F), CMake (CMakeLists.txt, .cmake), shell scripts (.sh or a #! first line) and .in
# templates, within their first 3 lines; a script on the line right after its shebang.
# Markdown, LICENSE, the ABI baseline and data files are not checked.
# Usage: spdx_check.sh ROOT. Lists every file that lacks the line, and fails if there is one.
root=$1
tag='SPDX-License-Identifier: GPL-3.0-or-later'
cd "$root" || exit 1
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    files=$(git ls-files)
else # an unpacked release: every file but the build trees
    files=$(find . -path ./.git -prune -o -path './build*' -prune -o -type f -print | sed 's|^\./||')
fi

checked=0 fails=0
for file in $files; do
    [ -f "$file" ] || continue
    case $file in
        *.c | *.h | *.f90 | *.F90 | *.f | *.F | CMakeLists.txt | */CMakeLists.txt | *.cmake | \
            *.in | *.sh) ;;
        *) head -c 2 "$file" | grep -q '^#!' || continue ;;
    esac
    checked=$((checked + 1))
    if head -c 2 "$file" | grep -q '^#!'; then
        sed -n 2p "$file" | grep -qF "$tag" && continue
    else
        head -n 3 "$file" | grep -qF "$tag" && continue
    fi
    echo "FAIL: no '$tag' line: $file"
    fails=$((fails + 1))
done
[ $checked -gt 0 ] || { echo "FAIL: no source files found under $root"; exit 1; }
echo "$((checked - fails)) passed, $fails failed"
[ $fails -eq 0 ]
