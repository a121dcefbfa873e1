// Output clean-up shared by every variant: the result has no zero-length edges and no
// zero-area rings (DESIGN.md section 1). Neither changes the even-odd interior.
#pragma once

#include "ghclip/region.h"

namespace gh::detail {

// Drops consecutive duplicate points (and a closing point equal to the first), then drops rings
// left with fewer than 3 points or with all points on one line (decided exactly).
Region cleanedUp(Region region);

}  // namespace gh::detail
