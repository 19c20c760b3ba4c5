#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# The files changed since a reference commit, one per line (paths from the top of the tree):
# the commits since, and what the work tree adds (changed, staged or untracked files); a file
# only moved, or a C file whose comments alone changed, is left out. The
# release tier's changed scope (FRICREG_RELEASE_SCOPE=changed) runs its slow parts only where
# they guard these files (tests/mutation/run.sh --changed-since).
#
# REF "landed" is the last stop that landed, named in .ci/landed (a commit on the way to
# HEAD; a stale one only widens the list); when it names none, REF is "release".
# REF "release" is the last release, found without tags (a CI clone may have none): the newest
# commit that set CMakeLists.txt's project VERSION to a release number (a patch below 90; the
# development versions are X.Y.90 and up, docs/contributing.md). A release commits its VERSION
# before or with its tag, so this commit is the tag's or older: the list is the tag's or longer.
#
# Usage: changed_files.sh ROOT REF
# Prints "since COMMIT (WHY)" (the full hash) on stderr and the files on stdout; exits 0. Exits 1, with the
# reason on stderr and nothing on stdout, when there is no git, the clone is shallow, or REF
# cannot be found: the caller then runs in full.
root=$1 ref=$2
git -C "$root" rev-parse --is-inside-work-tree >/dev/null 2>&1 || {
    echo "no git repository at $root" >&2
    exit 1
}
if [ "$(git -C "$root" rev-parse --is-shallow-repository 2>/dev/null)" != false ]; then
    echo "a shallow clone: its history may not reach the release" >&2
    exit 1
fi
why=$ref
if [ "$ref" = landed ]; then
    landed=$(grep -E -o -m 1 '^[0-9a-f]{7,40}' "$root/.ci/landed" 2>/dev/null)
    commit=$(git -C "$root" rev-parse -q --verify "${landed:-none}^{commit}" 2>/dev/null) &&
        git -C "$root" merge-base --is-ancestor "$commit" HEAD 2>/dev/null && why="the stop that landed"
    if [ "$why" = landed ]; then
        echo "note: .ci/landed names no commit on the way to HEAD: since the last release" >&2
        ref=release
    fi
fi
if [ "$ref" = release ]; then
    commit=""
    for c in $(git -C "$root" log --format=%H -G'^project\(fricreg VERSION' -- CMakeLists.txt); do
        version=$(git -C "$root" show "$c:CMakeLists.txt" |
            sed -n 's/^project(fricreg VERSION \([0-9]*\.[0-9]*\.[0-9]*\).*/\1/p')
        case $version in
        *.*.[0-9] | *.*.[0-8][0-9])
            commit=$c why="release $version"
            break
            ;;
        esac
    done
    [ -n "$commit" ] || {
        echo "no commit sets a release VERSION in CMakeLists.txt" >&2
        exit 1
    }
elif [ "$ref" != landed ]; then
    commit=$(git -C "$root" rev-parse -q --verify "$ref^{commit}") || {
        echo "no commit $ref" >&2
        exit 1
    }
fi
# A file moved without a change (git's rename at 100 % similarity), or a C file whose code is
# the same once its comments are gone (the compiler's preprocessor strips them; runs of white
# space count as one), is not a change: what it guards, or what guards it, is what it was at
# REF (a regrouping of tests/ moves files and rewrites the paths their comments name).
work=$(mktemp -d "${TMPDIR:-/tmp}/fricreg-changed.XXXXXX") || exit 1
trap 'rm -rf "$work"' EXIT
code() { # FILE: its C code without comments, or nothing when the compiler cannot read it
    "${CC:-cc}" -fpreprocessed -dD -E -P -x c "$1" 2>/dev/null | tr -s ' \t\n' '  '
}
same_code() { # OLD NEW: whether OLD at the commit and NEW in the work tree hold the same C code
    case $2 in *.c | *.h) ;; *) return 1 ;; esac
    [ -f "$root/$2" ] && git -C "$root" show "$commit:$1" >"$work/old" 2>/dev/null || return 1
    code "$work/old" >"$work/old.code" && code "$root/$2" >"$work/new.code" &&
        [ -s "$work/old.code" ] && cmp -s "$work/old.code" "$work/new.code"
}
tab=$(printf '\t')
status=$(git -C "$root" diff --name-status -M "$commit" --) &&
    files=$(printf '%s\n' "$status" | while IFS=$tab read -r st a b; do
        case $st in
        R100) continue ;;
        R* | C*) old=$a new=$b ;;
        *) old=$a new=$a ;;
        esac
        same_code "$old" "$new" || printf '%s\n' "$new"
    done) &&
    untracked=$(git -C "$root" ls-files --others --exclude-standard) || {
    echo "git diff against $commit failed" >&2
    exit 1
}
echo "since $commit ($why)" >&2
printf '%s\n%s\n' "$files" "$untracked" | grep . | sort -u
exit 0
