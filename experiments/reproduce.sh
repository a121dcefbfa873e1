#!/usr/bin/env bash
# Regenerates everything in results/ from a built tree. Called by `./harness reproduce`;
# GHCLIP_FULL=1 selects the large runs. Paths are relative to the repository root so that the
# provenance of each file reads the same on every machine.
#   experiments/reproduce.sh BUILD_DIR
set -euo pipefail
ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$ROOT"
BUILD="$(realpath --relative-to="$ROOT" "$1")"
BIN="$BUILD/bin"
export GHCLIP_COMMIT="${GHCLIP_COMMIT:-$(git rev-parse --short HEAD 2>/dev/null || echo unknown)}"
if [[ -n "$(git status --porcelain -- clipper io oracles workloads tools experiments 2>/dev/null)" ]]; then
  GHCLIP_COMMIT+="-dirty"
fi

step() { printf '[reproduce] %s\n' "$*" >&2; }

step "examples -> results/examples/"
rm -rf results/examples
"$BIN/run_examples" experiments/examples results/examples

step "naive variant judged by the exact oracle -> results/oracle-first-look.md"
rm -rf results/oracle-first-look results/oracle-first-look.md
"$BIN/oracle_first_look" results 1000

step "one picture per workload -> results/workloads/"
rm -rf results/workloads
mkdir -p results/workloads
{
  echo "# Workloads"
  echo
  echo "One example of every workload, written by \`ghgen NAME --n N --seed 1\` (commit $GHCLIP_COMMIT)."
  echo "Subject in blue, clip in red; both filled with the even-odd rule."
  echo
} >results/workloads/README.md
while read -r name n; do
  "$BIN/ghgen" "$name" --n "$n" --seed 1 -o "results/workloads/$name.wkt" --svg "results/workloads/$name.svg"
  printf '## %s (n = %s)\n\n![%s](%s.svg)\n\n' "$name" "$n" "$name" "$name" >>results/workloads/README.md
done <<'LIST'
random 20
simple 30
grid 10
identical 10
shared-edge 4
touching-vertex 4
nested-touching 4
sliver 4
sub-boundary 8
bitset-grid 50
circles 400
coastline 4000
holes 60
simple+ulp 30
grid+tiny 10
grid+huge 10
simple+far 30
LIST

step "property suite with a fixed seed; shrunk counterexamples -> results/counterexamples/"
rm -rf results/counterexamples
# Known violations are expected failures (tests/properties/expected_failures.txt); anything
# else failing here fails the reproduction.
GHCLIP_COUNTEREXAMPLES=results/counterexamples RC_PARAMS="max_success=100 seed=20261122 verbose_progress=0" \
  "$BIN/property_tests" >results/properties.log 2>&1 || { tail -40 results/properties.log; exit 1; }
grep -E '^\[ +(OK|FAILED) +\]|expected failure' results/properties.log | sed 's/ (.*//' >results/properties-summary.txt

step "every method on simple, holes, grid and random inputs, judged exactly -> results/peers-first-look.md"
rm -rf results/peers-first-look results/peers-first-look.md
"$BIN/peers_first_look" results 200

step "robustness study: every method x input class x operation, judged exactly -> results/robustness.md, .svg, .json (about 2 minutes; --full about 15)"
rm -f results/counterexamples/*/robustness-*
ROBUSTNESS_ARGS=()
[[ "${GHCLIP_FULL:-0}" == 1 ]] && ROBUSTNESS_ARGS+=(--full)
"$BIN/robustness" results "${ROBUSTNESS_ARGS[@]}"

step "exact vs naive on 10^5 degenerate cases over 12 families -> results/exact-degenerate.md (about 11 minutes on one core)"
"$BIN/exact_degenerate" results 100000

step "what exactness costs: exact vs naive on the paper's workload -> results/exact-speed.md (under a minute)"
"$BIN/exact_speed" results/exact-speed.md >results/exact-speed.log 2>&1 || { tail -20 results/exact-speed.log; exit 1; }

step "I/O speed against GEOS's readers and writers, 10^6 vertices -> results/io.md (about a minute)"
"$BIN/io_speed" results/io.md >results/io-speed.log 2>&1 || { tail -20 results/io-speed.log; exit 1; }

step "the clip fuzz targets' clip against their judges, on the pinned fuzz inputs -> results/judge-cost.md (about a minute)"
"$BIN/judge_cost" results/judge-cost.md >results/judge-cost.log 2>&1 || { tail -20 results/judge-cost.log; exit 1; }

step "peak memory of a clip per crossing -> results/memory.md (under a minute)"
"$BIN/clip_memory" results/memory.md

step "sweep benchmark (circles, archipelagos, pie and flower, random) -> results/sweep.md, sweep.json, sweep.svg"
SWEEP_ARGS=()
[[ "${GHCLIP_FULL:-0}" == 1 ]] && SWEEP_ARGS+=(--full)
"$BIN/sweep_benchmark" "${SWEEP_ARGS[@]}" --benchmark_repetitions=3 --benchmark_enable_random_interleaving=true \
  --benchmark_out=results/sweep.json --benchmark_out_format=json >results/sweep-benchmark.log 2>&1 \
  || { tail -20 results/sweep-benchmark.log; exit 1; }
"$BIN/report_sweep" results/sweep.json results/sweep.md results/sweep
rm -f results/sweep.gp results/sweep.dat

step "Table 1 (the paper's evaluation) and Table 2 -> results/table1.md, table2.md, table1.svg, tables.json"
TABLE_ARGS=()
[[ "${GHCLIP_FULL:-0}" == 1 ]] && TABLE_ARGS+=(--full)
"$BIN/table_benchmark" "${TABLE_ARGS[@]}" --benchmark_repetitions=3 --benchmark_enable_random_interleaving=true \
  --benchmark_out=results/tables.json --benchmark_out_format=json >results/table-benchmark.log 2>&1 \
  || { tail -20 results/table-benchmark.log; exit 1; }
"$BIN/report_tables" results/tables.json results
