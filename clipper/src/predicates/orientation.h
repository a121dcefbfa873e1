// The orientation predicate everything else is built from, exact: Shewchuk's stage-A filter
// inline, then the filtered predicate (filtered_predicate.h), then GMP, counted.
#pragma once

#include <cmath>
#include <limits>

#include "ghclip/region.h"
#include "predicates/exact_counters.h"
#include "predicates/sign.h"

namespace gh::detail {

// u x v = ux vy - uy vx evaluated in doubles, each factor one rounded difference, with
// Shewchuk's stage-A bound on its error: |exact - value| <= bound, where bound = (3 + 16u) u
// (|left| + |right|) while nothing under- or overflows, and infinity otherwise. Callers that need
// the determinant itself as well as its sign (the exact policy's crossing parameters) evaluate
// it once.
struct FilteredDeterminant {
  double value;
  double bound;
};

inline FilteredDeterminant stageADeterminant(double ux, double uy, double vx, double vy) {
  constexpr double kBound = (3.0 + 16.0 * 0x1p-53) * 0x1p-53;
  const double left = ux * vy, right = uy * vx;
  const double sum = std::abs(left) + std::abs(right);
  const bool safe = sum > 0x1p-900 && sum < 0x1p900;
  return {left - right, safe ? kBound * sum : std::numeric_limits<double>::infinity()};
}

// (b - a) x (c - a), with its stage-A bound.
inline FilteredDeterminant orientationDeterminant(Point a, Point b, Point c) {
  return stageADeterminant(b.x - a.x, b.y - a.y, c.x - a.x, c.y - a.y);
}

// The sign when stage A cannot decide: the filtered predicate, GMP if it must.
Sign orientationExact(Point a, Point b, Point c, ExactCounters& counters);

// Sign of (b - a) x (c - a): Positive when a, b, c turn counter-clockwise. Stage A is inline: it
// decides almost every call.
inline Sign orientation(FilteredDeterminant d, Point a, Point b, Point c, ExactCounters& counters) {
  if (const auto s = certainSign(d.value, d.bound)) return *s;
  return orientationExact(a, b, c, counters);
}
inline Sign orientation(Point a, Point b, Point c, ExactCounters& counters) {
  return orientation(orientationDeterminant(a, b, c), a, b, c, counters);
}

// The sign of (b - a) x (d - c) when crossSign's inline stages cannot decide: points scaled
// towards 1, stage A again, the filtered predicate, the exact sum in doubles, GMP.
Sign crossSignBeyondStageA(Point a, Point b, Point c, Point d, ExactCounters& counters);

// Sign of (b - a) x (d - c), the cross product of two edge directions (the turn from one
// direction to the other). Inline: an exact zero when each product has a factor that is exactly
// zero (a difference of doubles is 0 only when they are equal: axis-parallel directions, the
// collinear points of the clean-up, need no rounding analysis), then stage A, which decides
// almost every other call.
inline Sign crossSign(Point a, Point b, Point c, Point d, ExactCounters& counters) {
  const double ux = b.x - a.x, uy = b.y - a.y, vx = d.x - c.x, vy = d.y - c.y;
  if ((ux == 0 || vy == 0) && (uy == 0 || vx == 0)) return Sign::Zero;
  const FilteredDeterminant det = stageADeterminant(ux, uy, vx, vy);
  if (const auto s = certainSign(det.value, det.bound)) return *s;
  return crossSignBeyondStageA(a, b, c, d, counters);
}

}  // namespace gh::detail
