// The OGC layout's orchestrator (ghclip/ogc_layout.h): the rings noded exactly, the nodes
// rounded so that the pieces stay apart, the faces of what is left. Each step is its own file.
#include "ghclip/ogc_layout.h"

#include <chrono>
#include <cmath>

#include "ghclip/errors.h"
#include "layout/exact_noding.h"
#include "layout/node_rounding.h"
#include "layout/plane_faces.h"

namespace gh {

std::vector<PolygonWithHoles> ogcLayout(const LinedRings& rings, LayoutStats* stats) {
  const auto start = std::chrono::steady_clock::now();
  detail::ExactCounters counters;
  const detail::NodedBoundary noded = detail::nodeExactly(rings, counters);
  detail::RoundingStats rounding;
  const detail::PlaneGraph graph = detail::roundNodes(noded, rings, counters, rounding);
  std::vector<PolygonWithHoles> polygons = detail::planeFaces(graph, counters);
  if (stats) {
    stats->nodes = noded.rounded.size();
    stats->newNodes = noded.newNodes;
    stats->pieces = noded.pieceFrom.size();
    stats->merged = rounding.merged;
    stats->rerounded = rounding.rerounded;
    stats->snapRounded = rounding.snapRounded;
    stats->routed = rounding.routed;
    stats->polygons = polygons.size();
    stats->holes = 0;
    for (const PolygonWithHoles& p : polygons) stats->holes += p.holes.size();
    stats->seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return polygons;
}

std::vector<PolygonWithHoles> ogcLayout(const Region& rings, LayoutStats* stats) { return ogcLayout(linedRings(rings), stats); }

LinedRings linedRings(const Region& region) {
  LinedRings out;
  for (std::size_t r = 0; r < region.size(); ++r) {
    const Ring& ring = region[r];
    for (const Point& p : ring) {
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) {
        throw InvalidInput("ring " + std::to_string(r + 1) + ": a non-finite coordinate");
      }
    }
    // Consecutive repeats (and the closing point) dropped: an edge runs between two points.
    const std::size_t first = out.points.size();
    for (const Point& p : ring) {
      if (out.points.size() == first || !(out.points.back() == p)) out.points.push_back(p);
    }
    while (out.points.size() > first + 1 && out.points.back() == out.points[first]) out.points.pop_back();
    if (out.points.size() - first < 3) {  // fewer than 3 distinct points bound nothing
      out.points.resize(first);
      continue;
    }
    for (std::size_t k = first; k < out.points.size(); ++k) {
      const Point to = k + 1 < out.points.size() ? out.points[k + 1] : out.points[first];
      out.line.push_back(static_cast<std::uint32_t>(out.lines.size()));
      out.lines.push_back({out.points[k], to});
      out.exact.push_back(1);
    }
    out.ringStart.push_back(static_cast<std::uint32_t>(out.points.size()));
  }
  return out;
}

}  // namespace gh
