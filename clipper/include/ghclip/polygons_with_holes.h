// Turning an even-odd region into OGC polygons with holes, only where that is exact.
//
// GEOS, Boost.Geometry and CGAL take valid simple polygons with holes. An even-odd region is
// exactly such a set when its rings are simple and pairwise disjoint (no ring touches or
// crosses itself or another ring, decided with exact predicates): then a ring nested inside an
// even number of other rings is a shell, one nested in an odd number is a hole of the ring
// directly around it. Anything else (self-intersections, touching or shared edges, zero-area
// rings) is refused with the reason; the conversion never guesses.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ghclip/region.h"

namespace gh {

struct PolygonWithHoles {
  Ring shell;               // counter-clockwise
  std::vector<Ring> holes;  // clockwise
};

struct PolygonsWithHoles {
  std::vector<PolygonWithHoles> polygons;
  std::optional<std::string> refusal;  // why the region has no exact OGC form
};

// O(N log N + P) for N vertices and P pairs of edges with overlapping boxes, plus
// O(R * N) for the nesting of R rings.
PolygonsWithHoles toPolygonsWithHoles(const Region& region);

// Back to an even-odd region: shells and holes are all rings.
Region toRegion(const std::vector<PolygonWithHoles>& polygons);

}  // namespace gh
