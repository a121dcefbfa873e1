// The OGC layout of an even-odd region: polygons with holes that GIS tools read, with the same
// even-odd interior as the rings, decided exactly (docs/semantics.md, "The OGC layout").
//
//   std::vector<gh::PolygonWithHoles> p = gh::ogcLayout(rings);         // any even-odd rings
//   std::vector<gh::PolygonWithHoles> q = gh::Clipping(s, c).polygons(gh::Op::Union);  // a clip's
//
// How: the rings' edges are noded exactly at every point where they cross or touch (a new node is
// the crossing of two of the lines the edges lie on), overlapping pieces cancel in pairs (even-odd),
// what remains bounds the region; every node is rounded once to a faithful double, and where the
// rounded pieces would cross or touch where the exact ones do not, other faithful roundings of the
// nodes involved are tried. The faces of the rounded pieces, told inside from outside by a sweep,
// give the polygons: shells counter-clockwise, holes clockwise (RFC 7946), rings simple, touching
// only at points. Valid OGC polygons by construction (ogc_validity.h checks it exactly).
//
// Throws LayoutRefusal when no faithful rounding keeps the pieces apart (nodes an ulp from an edge
// in a way no choice of roundings resolves): the message names where. O((n + k) log n) for n
// vertices and k new nodes, plus the candidate pairs of edges whose boxes overlap.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <vector>

#include "ghclip/lined_rings.h"
#include "ghclip/polygons_with_holes.h"
#include "ghclip/region.h"

namespace gh {

class LayoutRefusal : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct LayoutStats {
  std::uint64_t nodes = 0;        // distinct exact points the pieces run between
  std::uint64_t newNodes = 0;     // of them, crossings of the rings' edges that were no vertex
  std::uint64_t pieces = 0;       // pieces of edges between nodes left after even-odd cancelling
  std::uint64_t merged = 0;       // nodes that rounded onto another node
  std::uint64_t rerounded = 0;    // nodes given another rounding to keep pieces apart
  bool snapRounded = false;       // no faithful rounding did: snap rounding (features below an ulp)
  std::uint64_t routed = 0;       // snap rounding: where a piece was bent through another node
  std::uint64_t polygons = 0, holes = 0;
  double seconds = 0;
};

std::vector<PolygonWithHoles> ogcLayout(const LinedRings& rings, LayoutStats* stats = nullptr);
std::vector<PolygonWithHoles> ogcLayout(const Region& rings, LayoutStats* stats = nullptr);

}  // namespace gh
