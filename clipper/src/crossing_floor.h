// The floor under phase 1, for benchmarks (experiments/table_benchmark, Table 1's "crossings
// only" column): the paper's all-pairs loop that tests every subject edge against every clip edge
// with the paper arithmetic's pair test and constructs every crossing point, and nothing else: no
// ordering, no graph, no tracing, no degeneracy handling. A clip cannot cost less than this.
#pragma once

#include <cstddef>
#include <vector>

#include "ghclip/region.h"
#include "phase1_result.h"

namespace gh::detail {

// How many crossings the validated operands have; the plain pair-by-pair loop puts them in `out`
// in its order. `vectorized`: the rows through the vectorized pair test (row_kernels.h) where the
// processor has it, into phase 1's own buffer instead.
std::size_t crossingFloor(const Region& subject, const Region& clip, std::vector<Crossing>& out, bool vectorized);

}  // namespace gh::detail
