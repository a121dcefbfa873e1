#!/usr/bin/env bash
# Mutation testing of our own checks: does the test suite notice a plausible bug in the library?
#
#   experiments/mutants/run.sh BUILD_DIR [--only ID] [--fuzz-seconds N]
#
# The mutants are data: manifest.tsv lists each one (id, patch, what it breaks) and the patch
# beside it. In a scratch copy of the last commit (never this tree), each mutant is applied,
# built, tested with `ctest --stop-on-failure` (every unit, property, golden, CLI and fuzz-replay
# test), and reverted. A mutant is killed when the build of the tests or a test fails. With
# --fuzz-seconds N and clang present, survivors also face each libFuzzer target for N seconds
# (ASan + UBSan, seed corpora). A mutant listed in equivalent.tsv is one whose even-odd answers
# do not change; the test named there shows it, and it is left out of the score.
# Writes results/mutants.md. Not part of ./harness test (it takes about 5 minutes per mutant).
set -euo pipefail

ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)"
HERE="$ROOT/experiments/mutants"
MAIN_BUILD="${1:?usage: run.sh BUILD_DIR [--only ID] [--fuzz-seconds N]}"
shift
only="" fuzzSeconds=0
while (($#)); do
  case "$1" in
    --only) only="$2"; shift 2 ;;
    --fuzz-seconds) fuzzSeconds="$2"; shift 2 ;;
    *) echo "mutants: unknown option $1" >&2; exit 2 ;;
  esac
done
JOBS="${GHCLIP_JOBS:-$(nproc)}"
SCRATCH="${GHCLIP_MUTANTS_DIR:-${TMPDIR:-/tmp}/ghclip-mutants}"
log() { printf '[mutants] %s\n' "$*" >&2; }

# The scratch copy: the last commit (the report names it; uncommitted changes are not tested).
# A scratch copy whose unmutated build passed its tests at this commit is used again.
commit="$(git -C "$ROOT" rev-parse --short HEAD)"
SRC="$SCRATCH/src" B="$SCRATCH/build"
reuse=0
[[ "$(cat "$SCRATCH/baseline-passed" 2>/dev/null)" == "$commit" ]] && reuse=1
if ((!reuse)); then
  rm -rf "$SCRATCH"
  mkdir -p "$SCRATCH/src"
  git -C "$ROOT" archive --format=tar "$commit" | tar -xf - -C "$SCRATCH/src"
  cmake -S "$SRC" -B "$B" -G Ninja -DCMAKE_BUILD_TYPE=Release >/dev/null
fi

buildAll() { cmake --build "$B" --parallel "$JOBS" >"$SCRATCH/build.log" 2>&1; }
# Prints the failing tests (one line, up to three) and returns 1 when a test fails. The quick
# tests first, then the two slow ones (golden pins, the oracles' 400-case agreement): ctest would
# start with the slowest, and a mutant most tests kill would wait for them.
# A test that takes 3 minutes (the slowest takes under 2 unmutated) counts as hung: killed.
slow='Golden|AgreeOnTheRandomWorkload'
testAll() {
  rm -f "$B/Testing/Temporary/LastTestsFailed.log"
  if (cd "$B" && ctest --stop-on-failure --parallel "$JOBS" --timeout 180 -E "$slow" >"$SCRATCH/ctest.log" 2>&1 &&
      ctest --stop-on-failure --parallel "$JOBS" --timeout 300 -R "$slow" >>"$SCRATCH/ctest.log" 2>&1); then
    return 0
  fi
  local failed="$B/Testing/Temporary/LastTestsFailed.log"
  if [[ -s "$failed" ]]; then
    cut -d: -f2- "$failed" | sed 's/  *#.*//' | head -3 | paste -sd ',' -
  else
    echo "ctest"
  fi
  return 1
}

log "baseline: build and test the unmutated copy"
buildAll || { log "the unmutated copy does not build: $SCRATCH/build.log"; exit 1; }
if ((!reuse)); then
  if ! testAll >/dev/null; then
    log "the unmutated copy fails its tests: $SCRATCH/ctest.log"
    exit 1
  fi
  echo "$commit" >"$SCRATCH/baseline-passed"
fi

fuzzBuild=""
if ((fuzzSeconds > 0)); then
  command -v clang++ >/dev/null || { log "--fuzz-seconds needs clang"; exit 2; }
  fuzzBuild="$SCRATCH/build-fuzz"
  san="-fsanitize=address,undefined -fno-sanitize=vptr -fno-sanitize-recover=undefined -fsanitize=fuzzer-no-link -g -O1"
  CC=clang CXX=clang++ cmake -S "$SRC" -B "$fuzzBuild" -G Ninja -DGHCLIP_FUZZ=ON -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_C_FLAGS="$san" -DCMAKE_CXX_FLAGS="$san" >/dev/null
fi
fuzzTargets=(fuzz_clip_naive fuzz_clip_sweep fuzz_clip_exact fuzz_clip_exact_oracle fuzz_diff_vatti)
# Runs every fuzz target for fuzzSeconds on its seed corpus; prints the first that finds something.
fuzzAll() {
  cmake --build "$fuzzBuild" --parallel "$JOBS" --target "${fuzzTargets[@]}" >"$SCRATCH/fuzz-build.log" 2>&1 ||
    { echo "fuzz build"; return 1; }
  local t corpus
  for t in "${fuzzTargets[@]}"; do
    corpus="$SCRATCH/corpus-$t"
    rm -rf "$corpus" && mkdir -p "$corpus"
    cp -r "$SRC/fuzz/${t}_seed_corpus/." "$corpus/" 2>/dev/null || true
    if ! (cd "$SCRATCH" && "$fuzzBuild/bin/$t" -max_total_time="$fuzzSeconds" -print_final_stats=0 -len_control=100 \
            "$corpus" >"$SCRATCH/fuzz-$t.log" 2>&1); then
      echo "$t (fuzzing)"
      return 1
    fi
  done
  return 0
}

declare -A equivalent=()
if [[ -f "$HERE/equivalent.tsv" ]]; then
  while IFS=$'\t' read -r id test; do
    [[ -z "$id" || "$id" == \#* ]] && continue
    equivalent[$id]="$test"
  done <"$HERE/equivalent.tsv"
fi

rows=() killed=0 survived=0 counted=0
while IFS=$'\t' read -r id patchFile what; do
  [[ -z "$id" || "$id" == \#* ]] && continue
  [[ -n "$only" && "$id" != "$only" ]] && continue
  log "$id: $what"
  start=$SECONDS
  (cd "$SRC" && patch -s -p1 <"$HERE/$patchFile") || { log "$id: patch does not apply"; exit 1; }
  verdict="" by=""
  if ! buildAll; then
    verdict="killed" by="the build (a test no longer compiles)"
  elif by="$(testAll)"; then
    if [[ -n "$fuzzBuild" ]] && by="$(fuzzAll)"; then
      verdict="survived" by=""
    elif [[ -n "$fuzzBuild" ]]; then
      verdict="killed"
    else
      verdict="survived" by=""
    fi
  else
    verdict="killed"
  fi
  (cd "$SRC" && patch -s -R -p1 <"$HERE/$patchFile")
  seconds=$((SECONDS - start))
  if [[ -n "${equivalent[$id]:-}" ]]; then
    [[ "$verdict" == survived ]] && verdict="equivalent" by="${equivalent[$id]}"
  fi
  case "$verdict" in
    killed) killed=$((killed + 1)); counted=$((counted + 1)) ;;
    survived) survived=$((survived + 1)); counted=$((counted + 1)) ;;
  esac
  log "$id: $verdict${by:+ by $by} (${seconds} s)"
  rows+=("| \`$id\` | $what | **$verdict** | ${by:--} | $seconds |")
done <"$HERE/manifest.tsv"
buildAll || true  # leave the scratch build unmutated

if [[ -z "$only" ]]; then
  out="$ROOT/results/mutants.md"
  {
    echo "# Mutation score of our checks"
    echo
    command="./harness mutants"
    ((fuzzSeconds > 0)) && command+=" --fuzz-seconds $fuzzSeconds"
    echo "Written by \`$command\` on $(date -u +%Y-%m-%d) at commit $commit. Each mutant"
    echo "(experiments/mutants/*.patch, listed in manifest.tsv) is a plausible bug in the library, applied to"
    echo "a scratch copy, built, and run against every test of \`ctest\` (stopping at the first failure)$( ((fuzzSeconds > 0)) && echo ", then $fuzzSeconds s of each fuzz target")."
    echo "Killed: a test failed (or no longer compiled). Equivalent: the even-odd answers do not change, as the"
    echo "named test shows; left out of the score."
    echo
    echo "**Mutation score: $killed of $counted killed** ($survived survived)."
    echo
    echo "| mutant | what it breaks | verdict | first failing test | seconds |"
    echo "|---|---|---|---|---:|"
    printf '%s\n' "${rows[@]}"
  } >"$out"
  log "report: ${out#$ROOT/}"
fi
