// The predicates of the exact variant under Simulation of Simplicity (see EXACT.md): the clip
// operand is translated by the infinitesimal vector (eps, eps^2); every sign is the sign of the
// leading non-zero term of its expansion in eps. None of them ever returns zero.
#pragma once

#include "ghclip/region.h"
#include "orientation.h"

namespace gh::detail::sos {

// orient(q1 + d, q2 + d, p) for a clip edge q1q2 and a subject point p:
//   O(q1, q2, p) + (q2.y - q1.y) eps - (q2.x - q1.x) eps^2
Sign clipEdgeSide(Point q1, Point q2, Point p);

// orient(p1, p2, q + d) for a subject edge p1p2 and a clip point q:
//   O(p1, p2, q) - (p2.y - p1.y) eps + (p2.x - p1.x) eps^2
Sign subjectEdgeSide(Point p1, Point p2, Point q);

// The same two expansions for a caller that already has the exact O (its eps-free term); inline,
// as phase 1 asks them for every pair of edges whose boxes overlap.
inline Sign clipEdgeSide(Sign o, Point q1, Point q2) {
  if (o != Sign::Zero) return o;
  const int dy = signOfDifference(q2.y, q1.y);
  if (dy != 0) return toSign(dy);
  return toSign(-signOfDifference(q2.x, q1.x));
}
inline Sign subjectEdgeSide(Sign o, Point p1, Point p2) {
  if (o != Sign::Zero) return o;
  const int ey = signOfDifference(p2.y, p1.y);
  if (ey != 0) return toSign(-ey);
  return toSign(signOfDifference(p2.x, p1.x));
}

// Do subject edge p1p2 and the translated clip edge q1q2 cross? (Never touch: SoS.)
bool cross(Point p1, Point p2, Point q1, Point q2);

// Order along subject edge p1p2 of its crossings with clip edges q and r (both crossing it):
// true when q's crossing comes first. Equal in every eps term only when q and r lie on one line.
// Returns -1 (q first), +1 (r first) or 0 (same point for every eps).
int compareAlongSubject(Point p1, Point p2, Point q1, Point q2, Point r1, Point r2);

// Order along clip edge q1q2 of its crossings with subject edges p and s: -1, +1 or 0.
int compareAlongClip(Point q1, Point q2, Point p1, Point p2, Point s1, Point s2);

// Even-odd point-in-region with the clip translated: a subject point against the clip rings,
// and a clip point against the subject rings. Rings are given as (vertices, next) arrays.
bool subjectPointInsideClip(Point p, const Point* clipVertices, const std::uint32_t* clipNext, std::size_t n);
bool clipPointInsideSubject(Point q, const Point* subjectVertices, const std::uint32_t* subjectNext, std::size_t n);

}  // namespace gh::detail::sos
