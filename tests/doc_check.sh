#!/bin/sh
# SPDX-License-Identifier: GPL-3.0-or-later
# Every public declaration in DIR/*.h has a doc comment: each FRICREG_API function, enum,
# enumerator and typedef is preceded by a /** ... */ comment (blank lines and plain /* */
# comments may not stand between them) or, for an enumerator, followed by /**< ... */ on its
# line. A function returning int also documents its return codes: its comment says "Returns"
# and names FRICREG_OK, unless it says that its int is "not a status" (a number or an id).
# These comments are what the Doxygen reference (cmake --build build --target docs) renders.
# Usage: doc_check.sh DIR. Lists every declaration that fails, and fails if there is one.
dir=$1
set -- "$dir"/*.h
[ -f "$1" ] || { echo "FAIL: no headers in $dir"; exit 1; }
awk '
function fail(what) { printf "FAIL: %s:%d: %s\n", FILENAME, FNR, what; fails++ }
function flush_decl() { decl = ""; decl_doc = "" }
# Checks a complete function declaration (joined lines) against the doc comment before it.
function check_function(text, doc,    name, type) {
    checked++
    name = text; sub(/\(.*/, "", name); sub(/.*[ *]/, "", name)
    type = text; sub(/^[ \t]*FRICREG_API[ \t]+/, "", type); sub(/[ \t*]*[A-Za-z_0-9]+\(.*/, "", type)
    if (doc == "") { fail("function " name " has no doc comment"); return }
    if (type == "int" && doc !~ /not a status/ && (doc !~ /Returns/ || doc !~ /FRICREG_OK/))
        fail("function " name " returns int but its comment does not list its return codes (\"Returns\" and FRICREG_OK)")
}
FNR == 1 { in_comment = 0; doc = ""; last_doc = ""; in_enum = 0; flush_decl() }
{
    line = $0
    # Inside a comment: collect it, and end it where it ends.
    if (in_comment) {
        doc = doc " " line
        if (line ~ /\*\//) { in_comment = 0; if (is_doc) last_doc = doc; else last_doc = "" }
        next
    }
    # A declaration that started on an earlier line goes on until its semicolon.
    if (decl != "") {
        decl = decl " " line
        if (line ~ /;/) { check_function(decl, decl_doc); flush_decl(); last_doc = "" }
        next
    }
    if (line ~ /^[ \t]*$/) { last_doc = ""; next }
    # A comment on a line of its own: a doc comment if it opens with /** (not /**<).
    if (line ~ /^[ \t]*\/\*/) {
        is_doc = (line ~ /^[ \t]*\/\*\*([^<]|$)/)
        doc = line
        if (line ~ /\*\/[ \t]*$/) { if (is_doc) last_doc = doc; else last_doc = "" }
        else in_comment = 1
        next
    }
    # Code.
    trailing = (line ~ /\/\*\*</)
    if (line ~ /\/\*/ && line !~ /\*\//) { in_comment = 1; is_doc = 0 } # comment continues
    if (line ~ /^[ \t]*FRICREG_API[ \t]/) {
        if (line ~ /;/) check_function(line, last_doc)
        else { decl = line; decl_doc = last_doc }
    } else if (line ~ /^[ \t]*typedef[ \t]/) {
        checked++
        if (last_doc == "") fail("typedef has no doc comment: " line)
    } else if (line ~ /^[ \t]*enum[ \t]+[A-Za-z_0-9]+[ \t]*\{/) {
        checked++
        if (last_doc == "") fail("enum has no doc comment: " line)
        in_enum = 1
    } else if (in_enum && line ~ /^[ \t]*\}/) {
        in_enum = 0
    } else if (in_enum && line ~ /^[ \t]*[A-Z_0-9]+[ \t]*(=|,|$)/) {
        checked++
        if (last_doc == "" && !trailing) {
            name = line; sub(/^[ \t]*/, "", name); sub(/[ \t=,].*/, "", name)
            fail("enumerator " name " has no doc comment")
        }
    }
    last_doc = ""
}
END {
    if (checked == 0) { print "FAIL: no declarations found"; exit 1 }
    printf "%d passed, %d failed\n", checked - fails, fails
    exit fails > 0
}' "$@"
