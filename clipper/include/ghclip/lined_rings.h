// Rings that know the line each of their edges lies on: what an exact clip knows of its answer.
//
// Every edge of an answer of gh::clip lies on an edge of the subject or the clip, and every vertex
// is an input vertex or the crossing of the lines of its two edges, rounded faithfully (each
// coordinate one of the two doubles around the exact one). The OGC layout (ogc_layout.h) uses that
// knowledge: it nodes the rings at the exact crossings of those lines, so that the polygons it
// writes have only input vertices and faithfully rounded crossings of input edges as vertices, as
// the answer's rings do (docs/semantics.md, "What is written is what is judged").
#pragma once

#include <cstdint>
#include <vector>

#include "ghclip/region.h"

namespace gh {

struct LinedRings {
  struct Line {
    Point from, to;  // two distinct doubles
  };
  std::vector<Line> lines;
  std::vector<Point> points;                  // every ring's vertices, ring after ring
  std::vector<std::uint32_t> ringStart{0};    // ring r is points[ringStart[r] .. ringStart[r + 1])
  std::vector<std::uint32_t> line;            // per vertex: the line of the edge to the next vertex
  // Per vertex: 1 when points[k] is the vertex itself; 0 when the vertex is the crossing of the
  // lines of its two edges (which must not be parallel) and points[k] a faithful rounding of it.
  std::vector<std::uint8_t> exact;

  std::size_t ringCount() const { return ringStart.size() - 1; }
};

// Rings that know nothing more than their vertices: every vertex exact, each edge on its own line.
// Repeated consecutive vertices are dropped (an edge needs two distinct points).
LinedRings linedRings(const Region& region);

}  // namespace gh
