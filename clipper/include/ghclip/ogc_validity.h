// Whether polygons with holes are valid OGC polygons (OGC Simple Features, ISO 19125-1, 6.1.11),
// decided exactly: the check behind "every written answer is valid", independent of the layout
// that wrote it (ogc_layout.h) and of GEOS, whose isValid underflows near 1e-300.
//
// The rules, as GEOS's IsValidOp applies them:
//   - every coordinate finite; every ring at least 3 distinct points (repeated points are allowed);
//   - every ring simple: no edge meets another edge of its ring but its neighbours at their common
//     vertex, and none folds back onto its neighbour;
//   - rings meet each other only at isolated points, where they touch without crossing;
//   - every hole lies inside its shell, and no hole inside another hole of its polygon;
//   - the interior of every polygon is connected (its rings and the points where they touch form no
//     cycle);
//   - the interiors of the polygons are disjoint (none lies inside another's interior).
// With `orientation`, also RFC 7946's: shells counter-clockwise, holes clockwise.
// O((n + k) log n + P) for n vertices, k touching points and P pairs of edges whose boxes overlap.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "ghclip/polygons_with_holes.h"

namespace gh {

enum class RingOrientation { Any, Rfc7946 };

// Empty when valid; otherwise why not, naming the polygon and ring (1-based) and a point.
std::optional<std::string> ogcInvalidity(const std::vector<PolygonWithHoles>& polygons,
                                         RingOrientation orientation = RingOrientation::Rfc7946);

}  // namespace gh
