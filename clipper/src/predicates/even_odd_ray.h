// The library's one even-odd ray test (DESIGN.md section 1): a point p is inside a region iff the
// ray from p towards +x crosses an odd number of its edges.
//
// An edge ab crosses the ray iff exactly one of a, b lies above p's horizontal line and p lies on
// the left of the edge directed upward. The caller says what "above" and "left" mean: a half-open
// rule for vertices on the line (so that a ray through a vertex counts it once), and the side of p
// as an exact orientation (measure.h, the OGC conversion) or under Simulation of Simplicity (the
// exact policy: p or the edge translated by an infinitesimal vector, so p is never on an edge).
// The sampling oracle keeps its own independent copy on purpose: a judge must not share the
// code it judges.
#pragma once

#include "ghclip/region.h"
#include "predicates/orientation.h"

namespace gh::detail {

// forEachEdge(visit) calls visit(a, b) for every edge; above(v) says whether vertex v is above the
// ray's line; side(a, b) is the sign of orientation(a, b, p) as the caller decides it.
template <class ForEachEdge, class Above, class Side>
bool insideByRay(ForEachEdge&& forEachEdge, Above&& above, Side&& side) {
  bool inside = false;
  forEachEdge([&](Point a, Point b) {
    const bool aAbove = above(a), bAbove = above(b);
    if (aAbove == bAbove) return;
    const Sign s = side(a, b);
    if (bAbove ? s == Sign::Positive : s == Sign::Negative) inside = !inside;
  });
  return inside;
}

// The plain exact test: a vertex is above when its y is greater than p's, sides are exact
// orientations. A point on an edge gets an arbitrary (but deterministic) answer.
template <class ForEachEdge>
bool insideByRay(Point p, ForEachEdge&& forEachEdge, ExactCounters& counters) {
  return insideByRay(
      std::forward<ForEachEdge>(forEachEdge), [p](Point v) { return v.y > p.y; },
      [p, &counters](Point a, Point b) { return orientation(a, b, p, counters); });
}

}  // namespace gh::detail
