// An even-odd region as OGC polygons with holes that GEOS calls valid: what GIS tools read.
//
// Where the region's rings are simple and pairwise disjoint, the nesting is exact
// (gh::toPolygonsWithHoles). Where rings cross or touch (self-intersecting input, rings meeting
// at a vertex), GEOS nodes the rings' linework and polygonizes it; each face is kept when a point
// verified strictly inside it is inside the region by the even-odd rule (decided exactly), and
// the kept faces are merged by a coverage union (nothing moves); new nodes are rounded to
// doubles. Where that floating noding fails (slivers an ulp wide), the linework is snap-rounded
// instead (OverlayNG, fixed precision: valid by construction) to the finest power-of-two grid,
// from the largest coordinate's ulp up, that gives a valid result. The result is checked: valid
// by GEOSisValid, and of the region's even-odd area to within the boundary's length times twice
// the rounding (an ulp, or the grid); otherwise WriteError says why, rather than writing
// something invalid ("--layout rings" writes the raw rings).
// Shells counter-clockwise, holes clockwise (RFC 7946).
#pragma once

#include <vector>

#include "ghclip/polygons_with_holes.h"
#include "ghclip/region.h"

namespace gh::io {

std::vector<PolygonWithHoles> ogcPolygons(const Region& region);

}  // namespace gh::io
