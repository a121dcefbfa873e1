// Step 1 of the OGC layout (ogc_layout.h): the rings' edges noded exactly, and what is left of
// them once overlapping pieces cancel in pairs.
//
// Every edge lies on a known line (LinedRings), and every point where two edges meet is either an
// endpoint of one of them or the crossing of their two lines: a node is an input double or the
// crossing of two lines, never a rounded value. Nodes are placed and ordered along each edge with
// exact predicates on the doubles that define them (predicates/point_on_line.h); nodes that are
// one exact point are one node. Pieces between consecutive nodes of an edge are counted modulo 2:
// under the even-odd rule two copies of a piece bound nothing (a seam, a spike, a ring traced
// twice), so every piece left separates the inside from the outside. A node where the pieces left
// go straight on along one line is no vertex of the answer: its two pieces become one.
#pragma once

#include <cstdint>
#include <vector>

#include "ghclip/lined_rings.h"
#include "predicates/exact_counters.h"

namespace gh::detail {

inline constexpr std::uint32_t kNoLine = 0xffffffffu;

struct NodedBoundary {
  // Node n is an exact point: rounded[n] itself when lineA[n] == kNoLine, else the crossing of lines
  // lineA[n] and lineB[n] (of the LinedRings), of which rounded[n] is a faithful rounding.
  std::vector<Point> rounded;
  std::vector<std::uint32_t> lineA, lineB;
  // Piece i runs straight from node pieceFrom[i] to node pieceTo[i] (distinct), along line
  // pieceLine[i]. Every node ends an even number of pieces, and no two pieces are the same.
  std::vector<std::uint32_t> pieceFrom, pieceTo, pieceLine;
  std::uint64_t newNodes = 0;  // nodes that are no vertex of the rings (crossings found here)

  bool isExact(std::uint32_t n) const { return lineA[n] == kNoLine; }
};

// Throws InvalidInput when the rings break LinedRings' rules (a line of one point, a
// vertex off its edges' lines, a crossing vertex of parallel lines, a line index out of range).
NodedBoundary nodeExactly(const LinedRings& rings, ExactCounters& counters);

}  // namespace gh::detail
