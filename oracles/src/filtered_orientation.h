// The judges' orientation (ghoracle/exact_orientation.h) with its filter inline, for the oracles'
// own translation units: the sampling oracle's ray tests and sector orders call it some fifteen
// million times on a hundred fuzz inputs. Private: the filter's error bound holds only without
// floating-point contraction (no fused l - r), which the oracles' target turns off
// (-ffp-contract=off, oracles/CMakeLists.txt) and another target's flags might not.
#pragma once

#include <cmath>

#include "ghclip/region.h"

namespace gh::oracle {

// The filter's error factor: |(computed l - r) - exact| <= kOrientationErrorFactor (|l| + |r|)
// for l = (b.x - a.x) (p.y - a.y), r = (b.y - a.y) (p.x - a.x) in doubles while nothing under-
// or overflows (Shewchuk's (3 + 16u) u, rounded up to the next power of two and an ulp).
inline constexpr double kOrientationErrorFactor = 0x1.0000000000002p-51;

// The stages beyond the filter (exact_orientation.cpp): exact doubles, exact expansions of
// doubles, then GMP integers.
int orientationBeyondFilter(Point a, Point b, Point p);

// Sign of (b - a) x (p - a), exactly: Shewchuk's filter in doubles, then the stages beyond it.
inline int filteredOrientation(Point a, Point b, Point p) {
  const double l = (b.x - a.x) * (p.y - a.y), r = (b.y - a.y) * (p.x - a.x);
  const double det = l - r, magnitude = std::abs(l) + std::abs(r);
  if (std::isfinite(magnitude) && magnitude > 0x1p-900 && std::abs(det) > kOrientationErrorFactor * magnitude) {
    return det > 0 ? 1 : -1;
  }
  return orientationBeyondFilter(a, b, p);
}

}  // namespace gh::oracle
