// Step 2 of the OGC layout (ogc_layout.h): every node rounded to a double, so that the rounded
// pieces still form a plane graph (they meet only at their common ends).
//
// Each node starts at its faithful rounding; nodes that round to one double become one vertex,
// pieces of no length vanish, and pieces that become one segment cancel in pairs (even-odd). Where
// two rounded pieces cross, touch or overlap although the exact ones do not (a node within an ulp
// of a piece), the crossing nodes at their ends are given other faithful roundings (each
// coordinate either double around the exact one: up to four points), fewest changes first, until
// nothing near them meets wrongly. Input vertices never move. Every vertex of the result is
// therefore an input vertex or a faithful rounding of a crossing of two input lines, as the
// answer's own vertices are: what the judges allow (docs/semantics.md).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "ghclip/region.h"
#include "layout/exact_noding.h"
#include "predicates/exact_counters.h"

namespace gh::detail {

// Straight edges between distinct vertices, no two the same, meeting only at common ends, every
// vertex at an even number of them: the boundary of an even-odd region.
struct PlaneGraph {
  std::vector<Point> vertices;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
};

struct RoundingStats {
  std::uint64_t merged = 0;     // nodes that share their double with another node
  std::uint64_t rerounded = 0;  // nodes given another rounding than their first
  bool snapRounded = false;     // the faithful roundings could not do it: snap_rounding.h did
  std::uint64_t routed = 0;     // snap rounding: vertices where a piece was bent through a node's cell
};

// Where no choice of faithful roundings keeps the pieces apart, snap rounding does
// (snap_rounding.h). Throws LayoutRefusal when that fails too.
PlaneGraph roundNodes(const NodedBoundary& noded, const LinedRings& rings, ExactCounters& counters,
                      RoundingStats& stats);

// Do the segments ab and cd meet where a plane graph's edges may not? Segments of no length vanish
// and two copies of one segment cancel or stay one edge, so neither is wrong; segments with one
// common end may only share that end; others may not meet at all. Exact.
bool meetWrongly(Point a, Point b, Point c, Point d, ExactCounters& counters);

// The plane graph of segments, if they form one: distinct points as vertices, segments of
// non-zero length counted modulo 2 (two copies bound nothing).
PlaneGraph planeGraph(const std::vector<std::pair<Point, Point>>& segments);
// The pairs of the graph's edges that meet wrongly (meetWrongly), in order.
std::vector<std::pair<std::uint32_t, std::uint32_t>> wrongEdges(const PlaneGraph& graph, ExactCounters& counters);
// How many of the positions repeat an earlier one.
std::uint64_t mergedNodes(const std::vector<Point>& positions);

// "(x y)" with every digit a double needs, for messages.
std::string pointText(Point p);

}  // namespace gh::detail
