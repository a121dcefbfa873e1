#!/usr/bin/env bash
# ghclip from the outside: results, exit codes, one-line errors, and no output file on bad input.
#   cli_test.sh BIN_DIR EXAMPLES_DIR
set -uo pipefail
BIN="$1"
EX="$2"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
fails=0
passes=0
check() {  # check NAME CONDITION...
  local name="$1"
  shift
  if "$@"; then passes=$((passes + 1)); else echo "FAIL: $name"; fails=$((fails + 1)); fi
}

# Bad input: exit 2, exactly one line on stderr naming the file, no output file.
bad() {  # bad NAME SUBJECT_TEXT
  local name="$1" text="$2"
  printf '%s' "$text" >"$TMP/$name.wkt"
  "$BIN/ghclip" --op intersection "$TMP/$name.wkt" "$EX/half_square.wkt" -o "$TMP/$name.out" \
    --svg "$TMP/$name.svg" 2>"$TMP/$name.err" >/dev/null
  local code=$?
  check "$name: exit 2 (got $code)" test "$code" -eq 2
  check "$name: one stderr line" test "$(wc -l <"$TMP/$name.err")" -eq 1
  check "$name: message names the file" grep -q "$name.wkt" "$TMP/$name.err"
  check "$name: and not the valid operand's" test -z "$(grep half_square "$TMP/$name.err")"
  check "$name: no output file" test ! -e "$TMP/$name.out"
  check "$name: no svg file" test ! -e "$TMP/$name.svg"
  check "$name: no temporary file" test -z "$(ls "$TMP" | grep tmp)"
}
bad malformed 'POLYGON((0 0, 1 0, 1 1'
bad nan 'POLYGON((0 0, 1 0, nan 1, 0 0))'
bad twovertex 'POLYGON((0 0, 1 1, 0 0))'
bad notapolygon 'LINESTRING(0 0, 1 1)'
bad huge 'POLYGON((0 0, 1e300 0, 0 1, 0 0))'
bad badjson '{"type": "Polygon", "coordinates": [[[0, 0], [1]]]}'
# The same refusals of the clip operand name the clip's file.
for name in nan twovertex huge; do
  "$BIN/ghclip" --op union "$EX/half_square.wkt" "$TMP/$name.wkt" 2>"$TMP/$name-as-clip.err" >/dev/null
  check "$name as clip: exit 2" test $? -eq 2
  check "$name as clip: names its file only" test "$(grep -c "^ghclip: $TMP/$name.wkt: ring 1" "$TMP/$name-as-clip.err")" -eq 1
done

"$BIN/ghclip" --op intersection "$TMP/missing.wkt" "$EX/half_square.wkt" 2>"$TMP/missing.err"
check "missing file: exit 2" test $? -eq 2
check "missing file: named" grep -q missing.wkt "$TMP/missing.err"
"$BIN/ghclip" --op frobnicate "$EX/pentagram.wkt" "$EX/half_square.wkt" 2>"$TMP/op.err"
check "unknown op: exit 2" test $? -eq 2
check "unknown op: one line" test "$(wc -l <"$TMP/op.err")" -eq 1
"$BIN/ghclip" "$EX/pentagram.wkt" 2>/dev/null
check "missing arguments: exit 2" test $? -eq 2

# Good input: WKT and GeoJSON out, stdin in, statistics as JSON.
"$BIN/ghclip" --op intersection "$EX/pentagram.wkt" "$EX/half_square.wkt" -o "$TMP/r.wkt" \
  --svg "$TMP/r.svg" --stats >"$TMP/stats.json"
check "pentagram: exit 0" test $? -eq 0
check "pentagram: result is WKT" grep -q '^MULTIPOLYGON' "$TMP/r.wkt"
check "pentagram: svg uses even-odd" grep -q 'fill-rule="evenodd"' "$TMP/r.svg"
check "pentagram: stats count 4 intersections" grep -q '"intersections":4' "$TMP/stats.json"
"$BIN/ghclip" --op union --format geojson - "$EX/gate.geojson" <"$EX/square.geojson" >"$TMP/u.json"
check "stdin + geojson: exit 0" test $? -eq 0
check "geojson output" grep -q '"type":"MultiPolygon"' "$TMP/u.json"
"$BIN/ghclip" --op xor "$TMP/r.wkt" "$TMP/r.wkt" >/dev/null
check "result reads back" test $? -eq 0

# Exact by default: a region minus itself is empty, exactly, with no --variant; the paper's
# arithmetic (named) leaves a sliver. The two axes can be given on their own, not with --variant.
"$BIN/ghclip" --op difference "$EX/square.geojson" "$EX/square.geojson" -o "$TMP/self.wkt" --stats >"$TMP/self.json"
check "A \\ A by default: exit 0" test $? -eq 0
check "A \\ A by default: no coordinates" test -z "$(grep '[0-9]' "$TMP/self.wkt")"
check "A \\ A by default: stats say exact" grep -q '"variant":"exact"' "$TMP/self.json"
"$BIN/ghclip" --op difference --variant naive "$EX/square.geojson" "$EX/square.geojson" -o "$TMP/self-naive.wkt"
check "A \\ A with --variant naive: a sliver" grep -q '[0-9]' "$TMP/self-naive.wkt"
"$BIN/ghclip" --op union --arithmetic paper --search sweep "$EX/square.geojson" "$EX/gate.geojson" -o "$TMP/ps.wkt" \
  --stats >"$TMP/ps.json"
check "--arithmetic paper --search sweep is the sweep variant" grep -q '"variant":"sweep"' "$TMP/ps.json"
"$BIN/ghclip" --op union --variant naive --arithmetic exact "$EX/square.geojson" "$EX/gate.geojson" 2>"$TMP/both.err" >/dev/null
check "--variant with --arithmetic: exit 2" test $? -eq 2
check "--variant with --arithmetic: one line" test "$(wc -l <"$TMP/both.err")" -eq 1
"$BIN/ghclip" --op union --search diagonal "$EX/square.geojson" "$EX/gate.geojson" 2>/dev/null >/dev/null
check "unknown --search: exit 2" test $? -eq 2

# Threads do not change the answer: byte for byte the same file.
"$BIN/ghgen" circles --n 30000 --seed 2 -o "$TMP/circles.wkt"
sed -n 1p "$TMP/circles.wkt" >"$TMP/cs.wkt"
sed -n 2p "$TMP/circles.wkt" >"$TMP/cc.wkt"
"$BIN/ghclip" --op union --threads 1 "$TMP/cs.wkt" "$TMP/cc.wkt" -o "$TMP/t1.wkt"
"$BIN/ghclip" --op union --threads 2 "$TMP/cs.wkt" "$TMP/cc.wkt" -o "$TMP/t2.wkt"
check "--threads 1 and 2: the same answer" cmp -s "$TMP/t1.wkt" "$TMP/t2.wkt"
"$BIN/ghclip" --op union --threads many "$TMP/cs.wkt" "$TMP/cc.wkt" 2>/dev/null >/dev/null
check "--threads many: exit 2" test $? -eq 2

# ghcheck: pass (0), fail (1), bad input (2); --expected writes the exact answer. The pentagram's
# answer crosses itself: its OGC layout adds nodes rounded by GEOS (up to an ulp beyond a
# faithful rounding: --ulps 2), its raw rings add nothing.
"$BIN/ghcheck" --op intersection --ulps 2 "$EX/pentagram.wkt" "$EX/half_square.wkt" "$TMP/r.wkt" >"$TMP/v.txt"
check "ghcheck passes ghclip's answer" test $? -eq 0
check "ghcheck prints the verdict" grep -q '^verdict: pass' "$TMP/v.txt"
"$BIN/ghclip" --op intersection --layout rings "$EX/pentagram.wkt" "$EX/half_square.wkt" -o "$TMP/raw.wkt"
"$BIN/ghcheck" --op intersection "$EX/pentagram.wkt" "$EX/half_square.wkt" "$TMP/raw.wkt" >/dev/null
check "ghcheck passes the raw rings at one ulp" test $? -eq 0
"$BIN/ghcheck" --op union "$EX/pentagram.wkt" "$EX/half_square.wkt" "$TMP/r.wkt" --json \
  --svg "$TMP/wrong.svg" >"$TMP/v.json"
check "ghcheck fails a confused operation" test $? -eq 1
check "ghcheck json has a witness" grep -q '"witness":\[' "$TMP/v.json"
check "ghcheck svg marks wrong faces" grep -q 'wrong faces' "$TMP/wrong.svg"
"$BIN/ghcheck" --op union --oracle sample "$EX/pentagram.wkt" "$EX/half_square.wkt" "$TMP/r.wkt" >/dev/null
check "sampling oracle fails it too" test $? -eq 1
"$BIN/ghcheck" --op intersection "$EX/pentagram.wkt" "$EX/half_square.wkt" "$TMP/nan.wkt" 2>/dev/null
check "ghcheck bad input: exit 2" test $? -eq 2
"$BIN/ghcheck" --op intersection --expected "$EX/pentagram.wkt" "$EX/half_square.wkt" -o "$TMP/e.wkt"
check "ghcheck --expected writes the answer" grep -q '^MULTIPOLYGON' "$TMP/e.wkt"
"$BIN/ghcheck" --op intersection "$EX/pentagram.wkt" "$EX/half_square.wkt" "$TMP/e.wkt" >/dev/null
check "the exact answer passes" test $? -eq 0
"$BIN/ghclip" --op intersection "$EX/pentagram.wkt" "$EX/half_square.wkt" --check exact >/dev/null 2>"$TMP/chk.err"
check "ghclip --check exact passes" test $? -eq 0

# The report generators refuse JSON that is not Google Benchmark's: exit 2, one line, no table.
printf '{"context": {}, "benchmarks": [' >"$TMP/cut.json"
mkdir -p "$TMP/tables"
"$BIN/report_tables" "$TMP/cut.json" "$TMP/tables" 2>"$TMP/rt.err"
check "report_tables on cut JSON: exit 2" test $? -eq 2
check "report_tables on cut JSON: one line naming the file" \
  test "$(wc -l <"$TMP/rt.err")" -eq 1 -a -n "$(grep cut.json "$TMP/rt.err")"
check "report_tables on cut JSON: no table" test ! -e "$TMP/tables/table1.md"

# --help prints the usage and exits 0, in every tool that parses its command line with CLI11.
for tool in ghclip ghcheck ghgen robustness; do
  "$BIN/$tool" --help >"$TMP/help.out" 2>"$TMP/help.err"
  check "$tool --help: exit 0" test $? -eq 0
  check "$tool --help: prints the options" grep -q -- "--help" "$TMP/help.out"
done

# exact_speed with a filter that matches nothing: exit 2 and one line, not an abort.
"$BIN/exact_speed" "$TMP/speed.md" --benchmark_filter=matches-nothing >/dev/null 2>"$TMP/es.err"
check "exact_speed, empty filter: exit 2" test $? -eq 2
check "exact_speed, empty filter: the reason on stderr" grep -q "matched" "$TMP/es.err"
check "exact_speed, empty filter: no report" test ! -e "$TMP/speed.md"

# Output files as users expect (issue 18): FIFOs, devices and links written, never replaced;
# every write error exit 2 with one line naming the path, and no file left behind.
S="$EX/pentagram.wkt"
C="$EX/half_square.wkt"
mkfifo "$TMP/fifo"
cat "$TMP/fifo" >"$TMP/from-fifo" &
reader=$!
"$BIN/ghclip" --op intersection "$S" "$C" -o "$TMP/fifo"
check "fifo: exit 0" test $? -eq 0
wait "$reader"
check "fifo: still a FIFO" test -p "$TMP/fifo"
check "fifo: the answer came through" grep -q '^MULTIPOLYGON' "$TMP/from-fifo"
echo old >"$TMP/target.wkt"
ln -s "$TMP/target.wkt" "$TMP/link.wkt"
"$BIN/ghclip" --op intersection "$S" "$C" -o "$TMP/link.wkt"
check "symlink: still a link" test -L "$TMP/link.wkt"
check "symlink: its target replaced" grep -q '^MULTIPOLYGON' "$TMP/target.wkt"
"$BIN/ghclip" --op intersection "$S" "$C" -o /dev/full 2>"$TMP/full.err"
check "-o /dev/full: exit 2" test $? -eq 2
check "-o /dev/full: one line naming it" test "$(grep -c /dev/full "$TMP/full.err")" -eq 1
check "-o /dev/full: still a device" test -c /dev/full
"$BIN/ghclip" --op intersection "$S" "$C" >/dev/full 2>"$TMP/stdout-full.err"
check "stdout full: exit 2" test $? -eq 2
"$BIN/ghclip" --op intersection "$S" "$C" -o "$TMP/answer.wkt" --svg "$TMP/no/such/dir/pic.svg" 2>"$TMP/svg.err"
check "failing --svg: exit 2" test $? -eq 2
check "failing --svg: names the path" grep -q "no/such/dir/pic.svg" "$TMP/svg.err"
check "failing --svg: no -o file left" test ! -e "$TMP/answer.wkt"
check "failing --svg: no temporary left" test -z "$(ls -A "$TMP" | grep ghclip-)"
mkdir "$TMP/readonly" && chmod 555 "$TMP/readonly"
if [[ $(id -u) -ne 0 ]]; then  # root writes anywhere
  "$BIN/ghclip" --op intersection "$S" "$C" -o "$TMP/readonly/a.wkt" 2>/dev/null
  check "unwritable directory: exit 2" test $? -eq 2
fi
"$BIN/ghclip" --op intersection "$S" "$C" -o "$TMP" 2>/dev/null
check "a directory as -o: exit 2" test $? -eq 2
# The layouts and empty answers: MULTIPOLYGON EMPTY, read back by our own readers too.
printf 'POLYGON((10 10,11 10,11 11,10 10))' >"$TMP/far.wkt"
"$BIN/ghclip" --op intersection "$S" "$TMP/far.wkt" -o "$TMP/empty.wkt"
check "empty answer: MULTIPOLYGON EMPTY" grep -qx 'MULTIPOLYGON EMPTY' "$TMP/empty.wkt"
"$BIN/ghclip" --op union "$TMP/empty.wkt" "$TMP/far.wkt" >/dev/null
check "MULTIPOLYGON EMPTY reads back" test $? -eq 0
"$BIN/ghclip" --op intersection "$S" "$C" --layout nonsense 2>/dev/null
check "--layout nonsense: exit 2" test $? -eq 2
# Z and M: tagged, read (x and y used); untagged 3-number points refused.
printf 'POLYGON Z((0 0 5,1 0 5,1 1 5,0 0 5))' >"$TMP/z.wkt"
"$BIN/ghclip" --op union "$TMP/z.wkt" "$TMP/far.wkt" -o "$TMP/z.out"
check "POLYGON Z: read" grep -q '0 0,1 0,1 1' "$TMP/z.out"
printf 'POLYGON((0 0 5,1 0 5,1 1 5,0 0 5))' >"$TMP/xyz.wkt"
"$BIN/ghclip" --op union "$TMP/xyz.wkt" "$TMP/far.wkt" 2>"$TMP/xyz.err" >/dev/null
check "untagged XYZ: exit 2" test $? -eq 2
check "untagged XYZ: says why" grep -q "3 coordinates" "$TMP/xyz.err"
# Every tool refuses what the clip refuses; peers do not crash on what it accepts.
printf 'POLYGON((0 0,1e308 0,0 1,0 0))' >"$TMP/e308.wkt"
"$BIN/ghcheck" --op union "$TMP/e308.wkt" "$C" "$C" 2>/dev/null >/dev/null
check "ghcheck refuses 1e308: exit 2" test $? -eq 2
"$BIN/ghclip" --peer clipper6 --op union "$TMP/e308.wkt" "$C" 2>/dev/null >/dev/null
check "clipper6 peer refuses 1e308: exit 2" test $? -eq 2
printf 'MULTIPOLYGON EMPTY' >"$TMP/none.wkt"
"$BIN/ghclip" --peer clipper6 --op union "$TMP/none.wkt" "$TMP/none.wkt" -o "$TMP/none.out"
check "clipper6 peer, both empty: exit 0" test $? -eq 0
printf 'POLYGON((1e150 1e150,2e150 1e150,2e150 3e150,1e150 1e150))' >"$TMP/big.wkt"
"$BIN/ghclip" --peer cgal --op union "$TMP/big.wkt" "$C" 2>"$TMP/cgal.err" >/dev/null
check "cgal peer at 1e150: refused, exit 2 (not a crash)" test $? -eq 2
for tool in ghclip ghcheck ghgen; do
  "$BIN/$tool" --version >"$TMP/version.out"
  check "$tool --version" grep -q "$tool [0-9]" "$TMP/version.out"
done

# No arguments: the usage on stderr, exit 2. ghgen writes the two operands as ghclip reads them.
for tool in ghclip ghcheck ghgen; do
  "$BIN/$tool" >/dev/null 2>"$TMP/noargs.err"
  check "$tool with no arguments: exit 2" test $? -eq 2
  check "$tool with no arguments: prints the usage" grep -q -- "--help" "$TMP/noargs.err"
done
"$BIN/ghgen" simple --n 12 --seed 3 -o /dev/null --subject "$TMP/gs.wkt" --clip "$TMP/gc.wkt"
"$BIN/ghclip" --op union "$TMP/gs.wkt" "$TMP/gc.wkt" -o "$TMP/gu.wkt"
check "ghgen --subject/--clip feed ghclip" grep -q '^MULTIPOLYGON' "$TMP/gu.wkt"

echo "$passes passed, $fails failed"
test "$fails" -eq 0
