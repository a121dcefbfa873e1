#!/usr/bin/env bash
# fuzz_findings groups a campaign's findings by target, cause and degeneracy, one row each, with
# the operations and the kinds of coordinates as counts: every finding counted once, distinct
# inputs apart, the figures in parentheses not splitting a cause; a malformed line is refused.
#   fuzz_findings_test.sh BIN_DIR
set -euo pipefail
BIN="$1"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
T=$'\t'
shared="MULTIPOLYGON(((0 3,3 6,1 0,0 3)))${T}MULTIPOLYGON(((0 3,6 1,7 3,0 3)))"  # one shared vertex
# Decided exactly where doubles cannot: C's first vertex lies 3e-17 off S's first edge, whose
# cross product rounds to 0 in doubles (a vertex inside the edge, were doubles trusted); and C's
# first vertex lies exactly on an edge of S whose differences overflow a double.
near="MULTIPOLYGON(((0 0,3.415680154384778 3.502881216432216,0 4,0 0)))${T}MULTIPOLYGON(((0.8174314053038976 0.8383001293856664,5 0,5 -1,0.8174314053038976 0.8383001293856664)))"
onHuge="MULTIPOLYGON(((-1e308 -1e308,1e308 1e308,-1e308 1e308,-1e308 -1e308)))${T}MULTIPOLYGON(((0.5 0.5,3 0,3 -2,0.5 0.5)))"
# A coordinate no target would judge (they refuse non-finite input) is named, never tested: the
# orientation takes finite coordinates only (unguarded, its GMP stage stops the tool with SIGFPE).
nonFinite="MULTIPOLYGON(((0 0,nan 1,1 1,0 0)))${T}MULTIPOLYGON(((0 0,2 1,inf 1,0 0)))"
general="MULTIPOLYGON(((0.5 0.5,3.5 0.5,2 3.25,0.5 0.5)))${T}MULTIPOLYGON(((1.25 1,4.75 1.5,3 4.5,1.25 1)))"
{
  echo "fuzz_clip_naive${T}sampling oracle disagrees${T}union${T}${shared}${T}input-1"
  echo "fuzz_clip_naive${T}sampling oracle disagrees${T}xor${T}${shared}${T}input-1"
  echo "fuzz_clip_naive${T}sampling oracle disagrees${T}xor${T}${shared}${T}input-2"
  echo "fuzz_clip_naive${T}invariant: union smaller than an operand (area S 1, C 2, result 0.5)${T}union${T}${shared}${T}input-1"
  echo "fuzz_clip_naive${T}invariant: union smaller than an operand (area S 3, C 4, result 1)${T}union${T}${shared}${T}input-3"
  echo "fuzz_clip_sweep${T}sampling oracle disagrees${T}intersection${T}${general}${T}input-4"
  echo "fuzz_clip_sweep${T}sampling oracle disagrees${T}difference${T}${near}${T}input-5"
  echo "fuzz_clip_sweep${T}sampling oracle disagrees${T}xor${T}${onHuge}${T}input-6"
  echo "fuzz_clip_sweep${T}sampling oracle disagrees${T}union${T}${nonFinite}${T}input-7"
} >"$TMP/f.tsv"
"$BIN/fuzz_findings" "$TMP/f.tsv" >"$TMP/table.md"
expect() {
  grep -qF -- "$1" "$TMP/table.md" || { echo "FAIL: no row $1"; cat "$TMP/table.md"; exit 1; }
}
expect "| target | finding | degeneracy of the operands | intersection | union | difference | reverse-difference | xor | integers / off the grid / subnormal or huge | findings | distinct inputs |"
expect "| fuzz_clip_naive | sampling oracle disagrees | shared vertex | 0 | 1 | 0 | 0 | 2 | 3 / 0 / 0 | 3 | 2 |"
expect "| fuzz_clip_naive | invariant: an area bound | shared vertex | 0 | 2 | 0 | 0 | 0 | 2 / 0 / 0 | 2 | 2 |"
expect "| fuzz_clip_sweep | sampling oracle disagrees | general position | 1 | 0 | 0 | 0 | 0 | 0 / 1 / 0 | 1 | 1 |"
expect "| fuzz_clip_sweep | sampling oracle disagrees | near-degenerate (a vertex within 2^-40 of an edge) | 0 | 0 | 1 | 0 | 0 | 0 / 1 / 0 | 1 | 1 |"
expect "| fuzz_clip_sweep | sampling oracle disagrees | vertex inside another edge | 0 | 0 | 0 | 0 | 1 | 0 / 0 / 1 | 1 | 1 |"
expect "| fuzz_clip_sweep | sampling oracle disagrees | non-finite coordinates | 0 | 1 | 0 | 0 | 0 | 0 / 0 / 1 | 1 | 1 |"
test "$(grep -c '^| fuzz_clip' "$TMP/table.md")" -eq 6 || { echo "FAIL: not 6 rows"; cat "$TMP/table.md"; exit 1; }
printf 'fuzz_clip_naive\tonly three fields\tunion\n' >"$TMP/bad.tsv"
set +e
"$BIN/fuzz_findings" "$TMP/bad.tsv" >/dev/null 2>"$TMP/err"
code=$?
set -e
test "$code" -eq 2 || { echo "FAIL: a malformed line gave exit $code, not 2"; exit 1; }
test "$(wc -l <"$TMP/err")" -eq 1 || { echo "FAIL: not one line on stderr"; cat "$TMP/err"; exit 1; }
echo "findings grouped: 6 rows"
