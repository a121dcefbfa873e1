// Whether a point lies within a distance of a line, exactly: the sampling oracle's skipped zones
// and the boundary certificate's roundings are both measured so. Private to the oracles (the
// filter's bound needs their -ffp-contract=off: filtered_orientation.h).
#pragma once

#include <cmath>

#include "filtered_orientation.h"
#include "ghoracle/exact_orientation.h"
#include "ghclip/region.h"

namespace gh::oracle {

// Whether |(b - a) x (p - a)| <= bound, i.e. p is within bound / |b - a| of the line ab: in
// doubles when the rounding cannot matter, else exactly (p near the origin and a, b at 1e144
// would cancel to noise): crossAtMost, whose integer stage allocates nothing (the rationals it
// replaced took 12,000 instructions a call, 8 % of fuzz_clip_exact's, for 0.6 % of the calls).
inline bool lineDistanceAtMost(Point a, Point b, Point p, double bound) {
  const double l = (b.x - a.x) * (p.y - a.y), r = (b.y - a.y) * (p.x - a.x);
  const double det = std::abs(l - r), error = kOrientationErrorFactor * (std::abs(l) + std::abs(r));
  if (std::isfinite(det) && std::isfinite(error) && std::abs(l) + std::abs(r) > 0x1p-900) {
    if (det + error <= bound) return true;
    if (det - error > bound) return false;
  }
  return crossAtMost(a, b, p, bound);
}

}  // namespace gh::oracle
