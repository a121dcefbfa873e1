// Exact signs of the polynomial predicates everything else is built from: a floating-point filter
// (approx.h) with an exact GMP fallback, counted.
#pragma once

#include <cmath>
#include <cstdint>
#include <limits>

#include "ghclip/region.h"

namespace gh::detail {

enum class Sign { Negative = -1, Zero = 0, Positive = 1 };

inline Sign toSign(int s) { return s > 0 ? Sign::Positive : s < 0 ? Sign::Negative : Sign::Zero; }

// Sign of a - b for doubles: exact (a comparison, no subtraction).
inline int signOfDifference(double a, double b) { return (a > b) - (a < b); }

// (b - a) x (c - a) evaluated in doubles, with Shewchuk's stage-A bound on its error:
// |exact - value| <= bound, where bound = (3 + 16u) u (|left| + |right|) while nothing under- or
// overflows, and infinity otherwise. Callers that need the determinant itself as well as its
// sign (the exact policy's crossing parameters) evaluate it once.
struct FilteredDeterminant {
  double value;
  double bound;
};

inline FilteredDeterminant orientationDeterminant(Point a, Point b, Point c) {
  constexpr double kBound = (3.0 + 16.0 * 0x1p-53) * 0x1p-53;
  const double left = (b.x - a.x) * (c.y - a.y), right = (b.y - a.y) * (c.x - a.x);
  const double sum = std::abs(left) + std::abs(right);
  const bool safe = sum > 0x1p-900 && sum < 0x1p900;
  return {left - right, safe ? kBound * sum : std::numeric_limits<double>::infinity()};
}

// The exact sign when the filter cannot decide (counted in exactFallbacks()).
Sign orientationExact(Point a, Point b, Point c);

// Sign of (b - a) x (c - a): Positive when a, b, c turn counter-clockwise. The filter is inline:
// it decides almost every call.
inline Sign orientation(FilteredDeterminant d, Point a, Point b, Point c) {
  if (d.value > d.bound) return Sign::Positive;
  if (-d.value > d.bound) return Sign::Negative;
  return orientationExact(a, b, c);
}
inline Sign orientation(Point a, Point b, Point c) { return orientation(orientationDeterminant(a, b, c), a, b, c); }

// Sign of (b - a) x (d - c), the cross product of two edge directions.
Sign crossSign(Point a, Point b, Point c, Point d);

// Exact fallbacks taken by this thread so far (the filter could not decide).
std::uint64_t& exactFallbacks();

}  // namespace gh::detail
