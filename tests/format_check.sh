#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The tracked C sources and headers are formatted as .clang-format says (clang-format
# --dry-run -Werror). Exits 77, which ctest reports as skipped, when clang-format is absent.
# To apply: git ls-files '*.c' '*.h' | xargs clang-format -i
# Usage: format_check.sh ROOT CLANG_FORMAT|-
root=$1 clang_format=$2
if [ "$clang_format" = "-" ] || ! command -v "$clang_format" >/dev/null 2>&1; then
    echo "clang-format not found: the format check is skipped"
    exit 77
fi
cd "$root" || exit 1
if git rev-parse --is-inside-work-tree >/dev/null 2>&1; then
    files=$(git ls-files '*.c' '*.h')
else # an unpacked release
    files=$(find . -path './build*' -prune -o -type f \( -name '*.c' -o -name '*.h' \) -print)
fi
"$clang_format" --version
fails=0 checked=0
for file in $files; do
    checked=$((checked + 1))
    "$clang_format" --style=file --dry-run -Werror "$file" 2>"${TMPDIR:-/tmp}/format.$$" && continue
    echo "FAIL: $file: $(grep -c 'error:' "${TMPDIR:-/tmp}/format.$$") places not formatted"
    fails=$((fails + 1))
done
rm -f "${TMPDIR:-/tmp}/format.$$"
echo "$((checked - fails)) passed, $fails failed"
[ $fails -eq 0 ]
