#!/usr/bin/env bash
# Every mutant of experiments/mutants/manifest.tsv still applies to the source it mutates:
# ./harness mutants stops at the first patch that does not, so a refactor that moves the mutated
# line must carry the mutant along (orientation-filter-bound-third.patch stopped applying when
# stage A moved to orientation.h, and nothing noticed). Checked with `git apply --check`, which
# changes nothing and needs no repository.
#   mutant_patches_apply_test.sh SOURCE_DIR
set -euo pipefail
ROOT="$1"
cd "$ROOT"
failed=0 count=0
while IFS=$'\t' read -r id patchFile _what; do
  [[ -z "$id" || "$id" == \#* ]] && continue
  count=$((count + 1))
  if ! git apply --check "experiments/mutants/$patchFile" 2>/dev/null; then
    echo "mutant $id: $patchFile does not apply" >&2
    failed=1
  fi
done <experiments/mutants/manifest.tsv
((count > 0)) || { echo "no mutants read from manifest.tsv" >&2; exit 1; }
((failed == 0)) && echo "$count mutant patches apply"
exit "$failed"
