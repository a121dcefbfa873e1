// Whether two regions have the same boundary taken mod 2, compared segment by segment: then their
// even-odd interiors are the same set, exactly (a point's side is the parity of the edges a ray
// from it crosses; docs/semantics.md, Regions). A cheap proof that a rewritten answer (the OGC
// layout of rings already judged) means what the rings meant, where the rewriting only reordered,
// reoriented or regrouped their edges. False proves nothing: the same boundary cut at other
// points, or different roundings, are compared by a judge instead.
#pragma once

#include "ghclip/region.h"

namespace gh::oracle {

bool sameBoundaryModTwo(const Region& a, const Region& b);

}  // namespace gh::oracle
