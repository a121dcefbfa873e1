#!/usr/bin/env bash
# Compiles tests/fuzz/judge_heap_test.cpp with clang and ASan, as the fuzz build compiles the
# targets (GHCLIP_FUZZ_JUDGES_UNSANITIZED: the judges without the sanitizers) and with
# fuzz/judge_operator_new.cpp, as fuzz_clip_exact_oracle links it, and runs it: first the
# expectations on which heap each block is on, then one memory error per run outside any
# JudgeHeap, each of which must still be stopped with its report.
# Usage: judge_heap_test.sh <clang++> <scratch directory>
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
out="$2/judge_heap_test"
# -fsized-deallocation: clang 14 calls the sized delete only with it (libstdc++ calls it always).
"$1" -std=c++17 -O1 -g -fsanitize=address -fsized-deallocation -Wno-mismatched-new-delete -DGHCLIP_FUZZ_JUDGES_UNSANITIZED -I"$ROOT/fuzz" \
  "$ROOT/tests/fuzz/judge_heap_test.cpp" "$ROOT/fuzz/judge_operator_new.cpp" -lgmpxx -lgmp -o "$out"
ASAN_OPTIONS=detect_leaks=1 "$out"
for error in heap-buffer-overflow heap-use-after-free double-free alloc-dealloc-mismatch new-delete-type-mismatch; do
  # (stderr of the group dropped: bash's own "Aborted" line is not the report.)
  if { ASAN_OPTIONS=detect_leaks=0 "$out" "$error" > "$out.$error.log" 2>&1; } 2>/dev/null; then
    echo "FAILED: $error was not stopped" >&2
    cat "$out.$error.log" >&2
    exit 1
  fi
  if ! grep -q "ERROR: .*$error" "$out.$error.log"; then
    echo "FAILED: $error stopped without its report" >&2
    cat "$out.$error.log" >&2
    exit 1
  fi
  echo "$error: stopped ($(grep -m1 -o 'ERROR: .*' "$out.$error.log" | cut -c1-80))"
done
