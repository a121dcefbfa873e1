// The predicates of the exact arithmetic under Simulation of Simplicity (see EXACT.md): the clip
// operand is translated by the infinitesimal vector (eps, eps^2); every sign is the sign of the
// leading non-zero term of its expansion in eps. None of them ever returns zero.
#pragma once

#include <cstddef>
#include <cstdint>

#include "ghclip/region.h"
#include "predicates/exact_counters.h"
#include "predicates/sign.h"

namespace gh::detail::sos {

// orient(q1 + d, q2 + d, p) for a clip edge q1q2 and a subject point p, given the exact
// O = orient(q1, q2, p), its eps-free term:
//   O + (q2.y - q1.y) eps - (q2.x - q1.x) eps^2
// Inline: phase 1 asks it for every pair of edges whose boxes overlap.
inline Sign clipEdgeSide(Sign o, Point q1, Point q2) {
  if (o != Sign::Zero) return o;
  const int dy = signOfDifference(q2.y, q1.y);
  if (dy != 0) return toSign(dy);
  return toSign(-signOfDifference(q2.x, q1.x));
}

// orient(p1, p2, q + d) for a subject edge p1p2 and a clip point q, given O = orient(p1, p2, q):
//   O - (p2.y - p1.y) eps + (p2.x - p1.x) eps^2
inline Sign subjectEdgeSide(Sign o, Point p1, Point p2) {
  if (o != Sign::Zero) return o;
  const int ey = signOfDifference(p2.y, p1.y);
  if (ey != 0) return toSign(-ey);
  return toSign(signOfDifference(p2.x, p1.x));
}

// Order along subject edge p1p2 of its crossings with clip edges q and r (both crossing it):
// -1 (q first), +1 (r first) or 0 (the same point for every eps: only when q and r lie on one
// line). With sameLimit the caller knows that both crossings tend to one point as eps -> 0 (the
// eps-free term is 0): only the eps terms, polynomials of lower degree, are decided.
int compareAlongSubject(Point p1, Point p2, Point q1, Point q2, Point r1, Point r2, ExactCounters& counters,
                        bool sameLimit = false);

// Order along clip edge q1q2 of its crossings with subject edges p and s: -1, +1 or 0.
int compareAlongClip(Point q1, Point q2, Point p1, Point p2, Point s1, Point s2, ExactCounters& counters,
                     bool sameLimit = false);

// Even-odd point-in-region with the clip translated (the one ray test, even_odd_ray.h): a subject
// point against the clip's edges, and a clip point against the subject's edges. Edges are given
// as (vertices, next) arrays, edge e from vertices[e] to vertices[next[e]]: the `count` edges
// listed in `edges`, or all `count` edges when `edges` is null. The list must hold every edge
// whose y-range holds the point's y (search/edge_slabs.h).
bool subjectPointInsideClip(Point p, const Point* clipVertices, const std::uint32_t* clipNext,
                            const std::uint32_t* edges, std::size_t count, ExactCounters& counters);
bool clipPointInsideSubject(Point q, const Point* subjectVertices, const std::uint32_t* subjectNext,
                            const std::uint32_t* edges, std::size_t count, ExactCounters& counters);

}  // namespace gh::detail::sos
