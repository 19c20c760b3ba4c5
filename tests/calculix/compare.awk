# SPDX-License-Identifier: GPL-3.0-or-later
# Compares a ccx output of the patched build (second file) with the stock build's (first
# file), line by line: the two must have the same lines, and on each line the same words but
# for the real numbers. A real number may differ from the stock one by
#
#     tol * range + one unit in the last printed digit of the larger of the two
#
# where range = max - min of the stock's numbers in that column of that block (a block: the
# numeric lines under one heading, one output at one time: "displacements ... and time 0.1",
# or one .frd record set; a block of one line, a total force, is one vector, and its range is
# over its components), and the unit is what the printed digits can resolve (two numbers
# rounded to 7 digits differ by a unit when the true ones differ by far less). Integers (node
# and element numbers) must be equal.
# The .frd format runs its fields together (" -1" node, then 6 numbers of 12 characters); its
# " -1" records are cut at those widths, all other lines compared as words but the header's
# date and time.
# Usage: awk -v tol=1e-6 -v name=LABEL -f compare.awk STOCK PATCHED
# Prints the largest difference as a fraction of its range, how many numbers passed only by the
# printed digit's unit, and "N passed, M failed".
function isreal(w) { return w ~ /^[-+]?[0-9]*\.[0-9]*([EeDd][-+]?[0-9]+)?$/ && w ~ /[0-9]/ }
function isint(w) { return w ~ /^[-+]?[0-9]+$/ }
# the words of a line: .frd records cut at their fixed widths
function words(line, w,    n, k) {
    if (frd && substr(line, 1, 3) == " -1") {
        w[1] = "-1"; w[2] = substr(line, 4, 10) + 0; n = 2
        for (k = 14; k <= length(line); k += 12) w[++n] = substr(line, k, 12)
        for (k = 3; k <= n; k++) gsub(/ /, "", w[k])
        return n
    }
    return split(line, w)
}
# one unit in the last printed digit of the number w
function unit(w,    m, e, d) {
    m = w; e = 0
    if (match(w, /[EeDd][-+]?[0-9]+$/)) { e = substr(w, RSTART + 1) + 0; m = substr(w, 1, RSTART - 1) }
    d = index(m, ".") ? length(m) - index(m, ".") : 0
    return 10 ^ (e - d)
}
function abs(x) { return x < 0 ? -x : x }
function span(key, v) {
    if (!(key in lo) || v < lo[key]) lo[key] = v
    if (!(key in hi) || v > hi[key]) hi[key] = v
}
FNR == 1 { file++; block = 0; frd = FILENAME ~ /\.frd$/ }
frd && /^ +1U(DATE|TIME) / { next } # the run's own date and time
{
    n = words($0, w)
    numeric = n > 0
    for (k = 1; k <= n; k++) if (!isreal(w[k]) && !isint(w[k])) numeric = 0
    if (!numeric) { if (n > 0) block++ }
    if (file == 1) {
        line1[FNR] = $0; lines1 = FNR; blk[FNR] = block
        if (numeric) {
            rows[block]++
            for (k = 1; k <= n; k++) if (isreal(w[k])) {
                v = w[k] + 0
                span(block SUBSEP k, v)
                span(block, v)
            }
        }
        next
    }
    lines2 = FNR
    if (FNR > lines1) next
    m = words(line1[FNR], s)
    if (m != n) { fail("line " FNR ": " m " words in the stock output, " n " here"); next }
    for (k = 1; k <= n; k++) {
        if (isreal(s[k]) && isreal(w[k])) {
            # a column's range; a block of one line (a total) is one vector: its components'
            key = rows[blk[FNR]] > 1 ? blk[FNR] SUBSEP k : blk[FNR]
            range = hi[key] - lo[key]
            diff = abs(w[k] - s[k])
            u = unit(abs(s[k] + 0) > abs(w[k] + 0) ? s[k] : w[k])
            compared++
            if (range > 0 && diff / range > worst) { worst = diff / range; where = FNR ": " s[k] " / " w[k] }
            if (diff > tol * range && diff <= tol * range + u * 1.000001) digit++
            if (diff > tol * range + u * 1.000001) {
                fail("line " FNR ", word " k ": " s[k] " (stock) and " w[k] ": differ by " diff ", range " range)
            }
        } else if (s[k] != w[k]) {
            fail("line " FNR ", word " k ": \"" s[k] "\" (stock) and \"" w[k] "\"")
        }
    }
}
function fail(msg) { if (++fails <= 10) print "FAIL: " name ": " msg }
END {
    if (lines1 != lines2) fail(lines1 " lines in the stock output, " lines2 " here")
    printf "%s: %d numbers compared, the largest difference %.3g of its range (line %s)",
           name, compared, worst, where == "" ? "-" : where
    printf "; %d within the last printed digit only\n", digit
    printf "%d passed, %d failed\n", fails ? 0 : 1, fails ? 1 : 0
    exit fails > 0
}
