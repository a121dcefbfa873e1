// The library's one test of how two closed segments meet, exact (four orientations).
#pragma once

#include <algorithm>

#include "ghclip/region.h"
#include "predicates/orientation.h"

namespace gh::detail {

enum class Meeting {
  Disjoint,  // no common point
  Crossing,  // one common point, interior to both, where they cross (no three endpoints collinear)
  Touching,  // any other contact: an endpoint on the other segment, or a collinear overlap
};

inline Meeting meeting(Point a, Point b, Point c, Point d, ExactCounters& counters) {
  const Sign o1 = orientation(a, b, c, counters), o2 = orientation(a, b, d, counters);
  const Sign o3 = orientation(c, d, a, counters), o4 = orientation(c, d, b, counters);
  if (o1 != Sign::Zero && o2 != Sign::Zero && o3 != Sign::Zero && o4 != Sign::Zero) {
    return o1 != o2 && o3 != o4 ? Meeting::Crossing : Meeting::Disjoint;
  }
  auto within = [](Point p, Point q, Point r) {  // r on line pq: inside the box of pq?
    return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y &&
           r.y <= std::max(p.y, q.y);
  };
  const bool touch = (o1 == Sign::Zero && within(a, b, c)) || (o2 == Sign::Zero && within(a, b, d)) ||
                     (o3 == Sign::Zero && within(c, d, a)) || (o4 == Sign::Zero && within(c, d, b));
  return touch ? Meeting::Touching : Meeting::Disjoint;
}

}  // namespace gh::detail
