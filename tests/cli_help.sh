#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# fricreg-sim's help against its parsers, from outside: every option COMMAND --help lists is
# one COMMAND's parser knows, and every option name in src/cli that a parser knows is in that
# command's help, but for the few it knows only to refuse with a reason (below). The man page
# the build wrote is the program's own, and groff and man render it without a warning.
# Each option name against each command (some 800 calls of the 1000, most of its time) with
# FRICREG_CLI_LONG=1 only (the release tier's cli_help_options_release); the quick tier tries
# the listed options, and test_cli_help.c checks from the option tables that every row is listed.
# Usage: cli_help.sh PATH/TO/fricreg-sim SOURCE_DIR PATH/TO/fricreg-sim.1
sim=$1 src=$2 page=$3
fails=0 total=0
tmp=$(mktemp -d "${TMPDIR:-/tmp}/fricreg-cli-help.XXXXXX")
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*"; fails=$((fails + 1)); }

# Known to the parser only to be refused with a reason (the rows marked hidden): twoblock's
# --partition elsewhere, the integration options of the closed-form exact, hb's and nma's
# --jenkins-2d and --elements (structure's element sets).
refused_only() { # COMMAND OPTION
    case "$1 $2" in
    "oscillator --partition" | "chain --partition" | "exact --partition") return 0 ;;
    "exact --law" | "exact --integrator" | "exact --dt" | "exact --rtol" | "exact --atol") return 0 ;;
    "exact --eps" | "exact --extrapolate" | "exact --extrapolate-order") return 0 ;;
    "exact --extrapolate-window" | "exact --max-steps" | "exact --kink-location") return 0 ;;
    "exact --error-estimate" | "exact --answer-rtol") return 0 ;;
    "hb --jenkins-2d" | "nma --jenkins-2d" | "hb --elements" | "nma --elements") return 0 ;;
    esac
    return 1
}

# Whether COMMAND's parser knows OPTION: with an empty value every option is refused (exit 2,
# nothing run), by name as unknown or for its value.
# One process per call (the shell's builtins read its message): some 2000 calls.
known() { # COMMAND OPTION
    "$sim" "$1" "$2=" >"$tmp/out" 2>"$tmp/err"
    rc=$?
    if [ $rc -ne 2 ] || [ -s "$tmp/out" ]; then
        fail "fricreg-sim $1 $2= -> exit $rc, $(wc -c <"$tmp/out") bytes on stdout"
    fi
    message=
    read -r message <"$tmp/err"
    case $message in *"unknown option"*) return 1 ;; esac
    return 0
}

grep -ho '"--[a-z0-9][a-z0-9-]*"' "$src"/src/cli/*.c "$src"/src/cli/*.h | tr -d '"' |
    sort -u >"$tmp/names"
commands=$("$sim" --help | sed -n 's/^  \([a-z][a-z0-9]*\)  .*/\1/p')
[ -n "$commands" ] || fail "fricreg-sim --help lists no command"
for command in $commands; do
    "$sim" "$command" --help >"$tmp/help" || fail "fricreg-sim $command --help: exit $?"
    sed -n 's/^  \(--[a-z0-9-]*\) .*/\1/p' "$tmp/help" | grep -v '^--help$' | sort -u >"$tmp/listed"
    [ -s "$tmp/listed" ] || fail "fricreg-sim $command --help lists no option"
    while read -r option; do
        total=$((total + 1))
        known "$command" "$option" || fail "$command --help lists $option, the parser refuses it as unknown"
    done <"$tmp/listed"
    [ "${FRICREG_CLI_LONG:-0}" = 1 ] || continue
    while read -r option; do
        grep -qx -- "$option" "$tmp/listed" && continue
        total=$((total + 1))
        if known "$command" "$option" && ! refused_only "$command" "$option"; then
            fail "the $command parser takes $option, its help does not list it"
        elif refused_only "$command" "$option" && ! known "$command" "$option"; then
            fail "$command: $option is listed here as refused with a reason, the parser does not know it"
        fi
    done <"$tmp/names"
done

# The man page: the program's own, and clean.
total=$((total + 1))
"$sim" --man >"$tmp/page" && cmp -s "$tmp/page" "$page" || fail "$page is not fricreg-sim --man's"
if command -v groff >/dev/null 2>&1; then
    total=$((total + 1))
    groff -man -Tutf8 -ww -z "$page" 2>"$tmp/warnings"
    [ -s "$tmp/warnings" ] && fail "groff warns on $page: $(head -n 5 "$tmp/warnings")"
fi
if command -v man >/dev/null 2>&1; then
    total=$((total + 1))
    MANWIDTH=80 man -l "$page" >"$tmp/rendered" 2>"$tmp/err" &&
        grep -q '^FRICREG-SIM(1)' "$tmp/rendered" && grep -q '^ *fricreg-sim - ' "$tmp/rendered" &&
        [ ! -s "$tmp/err" ] || fail "man -l $page: $(head -n 3 "$tmp/err")"
    total=$((total + 1))
    awk 'length > 80' "$tmp/rendered" | grep -q . && fail "man -l $page: lines over 80 columns"
fi
echo "$((total - fails)) passed, $fails failed"
[ $fails -eq 0 ]
