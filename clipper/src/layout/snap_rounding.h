// The OGC layout's last resort (node_rounding.h): snap rounding on the doubles (Hobby 1999,
// "Practical segment intersection with finite precision output"; Guibas and Marimont 1998), around
// the nodes the faithful roundings could not keep apart.
//
// Where features are finer than the doubles (subnormal coordinates, where the grid is 5e-324
// wide), no choice of faithful roundings may keep the rounded pieces apart. Around such trouble
// nodes the cells of the doubles become hot: each trouble node goes to its nearest double, the
// centre of its cell (the points that round to it), so does every node whose exact point lies in a
// hot cell, and every piece that passes through a hot cell is bent through its centre, in order
// along the piece. Paths then meet only at cell centres. Where the result still meets itself
// wrongly, the nodes there join the trouble and it runs again (at worst every node: snap rounding
// of the whole answer). Every vertex is still a rounding of a node within one ulp, and every path
// stays within half an ulp of its piece; but a piece bent through another node's cell no longer
// lies on its line (the price of a valid layout at that scale, kept to where it is needed).
// Exact: cells and pieces are compared in rationals (GMP), slow, and only here.
#pragma once

#include <vector>

#include "ghclip/lined_rings.h"
#include "layout/exact_noding.h"
#include "layout/node_rounding.h"

namespace gh::detail {

// positions: every node's rounding so far; trouble: nodes at the ends of pieces that still meet
// wrongly there. Throws LayoutRefusal when the snapped paths still meet wrongly with every node
// in trouble (cells of different sizes either side of a power of two can do that in principle).
PlaneGraph snapRoundAround(const NodedBoundary& noded, const LinedRings& rings, const std::vector<Point>& positions,
                           const std::vector<std::uint32_t>& trouble, ExactCounters& counters, RoundingStats& stats);

}  // namespace gh::detail
