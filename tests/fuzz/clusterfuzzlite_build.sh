#!/usr/bin/env bash
# Checks .clusterfuzzlite/build.sh the way ClusterFuzzLite runs it: with the engine's environment
# variables (CC, CXX, CFLAGS, CXXFLAGS, LIB_FUZZING_ENGINE, SRC, OUT, WORK) set for libFuzzer +
# ASan, then runs every built target briefly on its seed corpus. Needs clang and zip (./harness
# installs both). Slow (a full clang build with CGAL): run by hand, not under ctest.
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
TMP="$(mktemp -d)"
trap 'rm -rf "$TMP"' EXIT
mkdir -p "$TMP/src" "$TMP/out" "$TMP/work"
ln -s "$ROOT" "$TMP/src/ghclip"
export CC=clang CXX=clang++
export CFLAGS="-O1 -fno-omit-frame-pointer -gline-tables-only -fsanitize=address -fsanitize-address-use-after-scope -fsanitize=fuzzer-no-link"
export CXXFLAGS="$CFLAGS"
export LIB_FUZZING_ENGINE="-fsanitize=fuzzer"
export SRC="$TMP/src" OUT="$TMP/out" WORK="$TMP/work"
bash "$ROOT/.clusterfuzzlite/build.sh"
passed=0 failed=0
for t in fuzz_clip_naive fuzz_clip_sweep fuzz_clip_exact fuzz_clip_exact_oracle fuzz_diff_vatti fuzz_read; do
  mkdir -p "$TMP/seeds-$t"
  (cd "$TMP/seeds-$t" && unzip -q "$OUT/${t}_seed_corpus.zip")
  if [[ -x "$OUT/$t" && -f "$OUT/$t.dict" && -f "$OUT/$t.options" ]] && "$OUT/$t" -runs=200 -dict="$OUT/$t.dict" "$TMP/seeds-$t" >/dev/null 2>&1; then
    passed=$((passed + 1))
  else
    echo "FAIL: $t"
    failed=$((failed + 1))
  fi
done
echo "$passed passed, $failed failed"
test "$failed" -eq 0
