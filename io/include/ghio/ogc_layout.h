// An even-odd region as OGC polygons with holes that GEOS calls valid: what GIS tools read.
//
// Where the region's rings are simple and pairwise disjoint, the nesting is exact
// (gh::toPolygonsWithHoles). Where rings cross or touch (self-intersecting input, rings meeting
// at a vertex), the rings are noded and the even-odd faces built by GEOS (MakeValid, linework
// method: the faces of the noded rings, alternately in and out, i.e. the even-odd rule); new
// nodes are rounded to doubles by GEOS. The result is checked: valid by GEOSisValid and of the
// region's even-odd area (to the rounding of the added nodes); otherwise WriteError says why,
// rather than writing something invalid ("--layout rings" writes the raw rings).
// Shells counter-clockwise, holes clockwise (RFC 7946).
#pragma once

#include <vector>

#include "ghclip/polygons_with_holes.h"
#include "ghclip/region.h"

namespace gh::io {

std::vector<PolygonWithHoles> ogcPolygons(const Region& region);

}  // namespace gh::io
