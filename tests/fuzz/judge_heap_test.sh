#!/usr/bin/env bash
# Compiles tests/fuzz/judge_heap_test.cpp with clang and ASan, as the fuzz build compiles the
# targets (GHCLIP_FUZZ_JUDGES_UNSANITIZED: the judges without the sanitizers), and runs it.
# Usage: judge_heap_test.sh <clang++> <scratch directory>
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
out="$2/judge_heap_test"
"$1" -std=c++17 -O1 -g -fsanitize=address -DGHCLIP_FUZZ_JUDGES_UNSANITIZED -I"$ROOT/fuzz" \
  "$ROOT/tests/fuzz/judge_heap_test.cpp" -lgmpxx -lgmp -o "$out"
ASAN_OPTIONS=detect_leaks=1 "$out"
