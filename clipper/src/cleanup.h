// Output clean-up shared by both arithmetics: the result has no zero-length edges, no zero-width
// spikes and no zero-area rings (DESIGN.md section 1). None of them changes the even-odd interior;
// the exact arithmetic needs all three to return S for S n S exactly (the limit of its symbolic
// perturbation leaves slivers of zero width).
#pragma once

#include "flat_rings.h"
#include "ghclip/region.h"
#include "predicates/exact_counters.h"

namespace gh::detail {

// Drops repeated points and spike tips (a -> b -> a' folding back on one line), then rings left
// with fewer than 3 points (a ring on one line folds back at its ends, so it is one of them);
// all decided exactly, fallbacks to rational arithmetic counted in `counters`. With dissolveSeams
// (for an arithmetic whose answers are a limit that leaves zero-width parts:
// Arithmetic::kLeavesZeroWidthParts), zero-width seams between rings that share a vertex are
// dissolved too: coincident pieces cancel in pairs, opposite or (even-odd) the same way.
// `rings` is trimmed in place on the way.
Region cleanedUp(FlatRings& rings, bool dissolveSeams, ExactCounters& counters);
Region cleanedUp(const Region& region, bool dissolveSeams, ExactCounters& counters);

}  // namespace gh::detail
