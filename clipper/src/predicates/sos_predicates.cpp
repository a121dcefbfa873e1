#include "predicates/sos_predicates.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "predicates/crossing_order.h"
#include "predicates/difference_products.h"
#include "predicates/even_odd_ray.h"
#include "predicates/orientation.h"

namespace gh::detail::sos {
namespace {

// Order of the crossings of line L (a1 -> a2) with lines M (m1, m2) and N (n1, n2) along L. The
// parameter along L at the crossing with M expands as
//   t_M = (A_M + bSign * my * eps + cSign * mx * eps^2) / D_M,
//   A_M = cross(m2 - m1, a1 - m1), D_M = cross(m2 - m1, a1 - a2), (mx, my) = m2 - m1,
// so (t_M - t_N) D_M D_N = F0 + bSign F1 eps + cSign F2 eps^2 with
//   F0 = A_M D_N - A_N D_M,  F1 = my D_N - ny D_M,  F2 = mx D_N - nx D_M.
// Expanding D_M and D_N, the eps terms factor into signs that are each cheap to decide exactly:
//   F1 = -(a1.y - a2.y) X,  F2 = -(a1.x - a2.x) X,  X = cross(m2 - m1, n2 - n1),
// so only F0 (degree 4, crossing_order.h) is a polynomial the filter may fail on; with sameLimit it
// is known to be 0.
int compare(Point a1, Point a2, Point m1, Point m2, Point n1, Point n2, int bSign, int cSign,
            ExactCounters& counters, bool sameLimit) {
  // Every sign below is of a polynomial homogeneous in differences of the coordinates, or compares
  // two coordinates: points near 1e-300 or 1e150 are scaled first (difference_products.h).
  scaleTowardsUnit(&a1, &a2, &m1, &m2, &n1, &n2);
  // D_M = cross(m2 - m1, a1 - a2), D_N likewise.
  const int denominator =
      static_cast<int>(crossSign(m1, m2, a2, a1, counters)) * static_cast<int>(crossSign(n1, n2, a2, a1, counters));
  if (!sameLimit) {
    const Sign f0 = crossingOrderTerm(a1, a2, m1, m2, n1, n2, counters);
    if (f0 != Sign::Zero) return static_cast<int>(f0) * denominator;
  }
  const int x = static_cast<int>(crossSign(m1, m2, n1, n2, counters));
  if (x == 0) return 0;  // M and N parallel (on one line, as they share the limit): a tie in every term
  const int ay = signOfDifference(a1.y, a2.y);
  if (ay != 0) return bSign * -ay * x * denominator;
  return cSign * -signOfDifference(a1.x, a2.x) * x * denominator;
}

}  // namespace

int compareAlongSubject(Point p1, Point p2, Point q1, Point q2, Point r1, Point r2, ExactCounters& counters,
                        bool sameLimit) {
  // Parameter along p of the crossing with clip edge q: (O(q1,q2,p1) + dy_q eps - dx_q eps^2) / D_q
  // with D_q = O(q1,q2,p1) - O(q1,q2,p2) = cross(q2 - q1, p1 - p2): B = +dy, C = -dx.
  return compare(p1, p2, q1, q2, r1, r2, +1, -1, counters, sameLimit);
}

int compareAlongClip(Point q1, Point q2, Point p1, Point p2, Point s1, Point s2, ExactCounters& counters,
                     bool sameLimit) {
  // Parameter along q of the crossing with subject edge p: (O(p1,p2,q1) - dy_p eps + dx_p eps^2)
  // / D_p with D_p = cross(p2 - p1, q1 - q2). O(p1,p2,q1) = cross(p2 - p1, q1 - p1) is the same
  // cross product shape as along the subject edge, with the roles of the lines swapped: B = -dy,
  // C = +dx.
  return compare(q1, q2, p1, p2, s1, s2, -1, +1, counters, sameLimit);
}

namespace {

auto edgesOf(const Point* v, const std::uint32_t* next, const std::uint32_t* edges, std::size_t n) {
  return [v, next, edges, n](auto&& visit) {
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t e = edges ? edges[i] : static_cast<std::uint32_t>(i);
      visit(v[e], v[next[e]]);
    }
  };
}

}  // namespace

bool subjectPointInsideClip(Point p, const Point* v, const std::uint32_t* next, const std::uint32_t* edges,
                            std::size_t n, ExactCounters& counters) {
  // The clip is translated: a clip vertex q is above p's line iff q.y + eps^2 > p.y, i.e. q.y >= p.y.
  return insideByRay(
      edgesOf(v, next, edges, n), [p](Point q) { return q.y >= p.y; },
      [p, &counters](Point a, Point b) { return clipEdgeSide(orientation(a, b, p, counters), a, b); });
}

bool clipPointInsideSubject(Point q, const Point* v, const std::uint32_t* next, const std::uint32_t* edges,
                            std::size_t n, ExactCounters& counters) {
  // The point is translated: a subject vertex s is above iff s.y > q.y + eps^2, i.e. s.y > q.y.
  return insideByRay(
      edgesOf(v, next, edges, n), [q](Point s) { return s.y > q.y; },
      [q, &counters](Point a, Point b) { return subjectEdgeSide(orientation(a, b, q, counters), a, b); });
}

}  // namespace gh::detail::sos
