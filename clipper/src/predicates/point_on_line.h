// Points on a line as the OGC layout knows them (layout/exact_noding.h): an answer's vertex is an
// input vertex or the crossing of two input edges' lines, so a point on the line of an edge is a
// double lying on it, or that line's crossing with another line. Their order along the line is
// decided exactly from the doubles that define them; no point is ever rounded to decide it.
#pragma once

#include "ghclip/region.h"
#include "predicates/crossing_order.h"
#include "predicates/crossing_position.h"
#include "predicates/exact_counters.h"
#include "predicates/orientation.h"

namespace gh::detail {

struct PointOnLine {
  bool crossing = false;
  Point at;      // the point itself (crossing false)
  Point m1, m2;  // the other line, not parallel to this one (crossing true)

  static PointOnLine exact(Point p) { return {false, p, {}, {}}; }
  static PointOnLine crossingWith(Point m1, Point m2) { return {true, {}, m1, m2}; }
};

// The order of u and v along the line from a1 to a2 (a1 != a2), both on it: -1 when u comes first,
// +1 when v does, 0 when they are one point.
inline int compareOnLine(Point a1, Point a2, const PointOnLine& u, const PointOnLine& v, ExactCounters& counters) {
  // Certified positions along the line first (crossing_position.h): disjoint intervals decide.
  if (u.crossing || v.crossing) {
    double eu, ev;
    const double tu = u.crossing ? crossingPosition(a1, a2, u.m1, u.m2, eu) : pointPosition(a1, a2, u.at, eu);
    const double tv = v.crossing ? crossingPosition(a1, a2, v.m1, v.m2, ev) : pointPosition(a1, a2, v.at, ev);
    if (tu + eu < tv - ev) return -1;
    if (tv + ev < tu - eu) return 1;
  }
  // A double p against the crossing with M: orient(M, a(t)) is affine in t and vanishes at t_M, so
  // sign(t_p - t_M) = orient(m1, m2, p) * sign((m2 - m1) x (a2 - a1)).
  auto doubleAgainstCrossing = [&](Point p, Point m1, Point m2) {
    return static_cast<int>(orientation(m1, m2, p, counters)) * static_cast<int>(crossSign(m1, m2, a1, a2, counters));
  };
  if (!u.crossing && !v.crossing) {
    if (u.at == v.at) return 0;
    // Comparisons along an axis on which a1 and a2 differ: nothing is computed.
    if (a1.x != a2.x) return signOfDifference(u.at.x, v.at.x) * signOfDifference(a2.x, a1.x);
    return signOfDifference(u.at.y, v.at.y) * signOfDifference(a2.y, a1.y);
  }
  if (!u.crossing) return doubleAgainstCrossing(u.at, v.m1, v.m2);
  if (!v.crossing) return -doubleAgainstCrossing(v.at, u.m1, u.m2);
  if (u.m1 == v.m1 && u.m2 == v.m2) return 0;
  return orderOfCrossings(a1, a2, u.m1, u.m2, v.m1, v.m2, counters);
}

}  // namespace gh::detail
