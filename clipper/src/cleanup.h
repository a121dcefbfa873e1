// Output clean-up shared by every variant: the result has no zero-length edges, no zero-width
// spikes and no zero-area rings (DESIGN.md section 1). None of them changes the even-odd interior;
// the exact variant needs all three to return S for S n S exactly (the limit of its symbolic
// perturbation leaves slivers of zero width).
#pragma once

#include "ghclip/region.h"

namespace gh::detail {

// Drops repeated points and spike tips (a -> b -> a' folding back on one line), then rings left
// with fewer than 3 points or with all points on one line; all decided exactly.
// With dissolveSeams (the exact variant), zero-width seams between rings are dissolved too.
Region cleanedUp(Region region, bool dissolveSeams);

}  // namespace gh::detail
