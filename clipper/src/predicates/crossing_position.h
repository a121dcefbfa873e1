// Where along a line its crossing with another line lies, as a certified interval: the filter in
// front of every exact order of crossings along an edge (phase 1 of the exact arithmetic, the OGC
// layout's noding). Most orders are decided by disjoint intervals; the rest by the exact
// predicate (crossing_order.h).
#pragma once

#include <cmath>
#include <limits>

#include "ghclip/region.h"
#include "predicates/difference_products.h"
#include "predicates/orientation.h"

namespace gh::detail {

// The parameter t = w1 / (w1 - w2) along an edge whose endpoints have the determinants w1, w2
// against the other edge's line (t is a crossing's position), with a certified bound on its
// error: infinite when the determinants' bounds do not apply. Only for lines that cross, where the
// exact denominator is not 0.
inline double certifiedRatio(FilteredDeterminant w1, FilteredDeterminant w2, double& err) {
  constexpr double u = 0x1p-53;
  const double d = w1.value - w2.value, inverse = 1 / d, t = w1.value * inverse;
  const double ed = w1.bound + w2.bound + u * std::abs(d);
  if (!(2 * ed <= std::abs(d)) || !std::isfinite(t)) {
    err = std::numeric_limits<double>::infinity();
    return t;
  }
  // |w1/d - t| <= (e1 + |t| ed) / (|d| - ed) <= 2 (e1 + |t| ed) / |d|, plus the roundings of 1/d
  // and of the product; the last factor covers the rounding of this bound itself. (Loose by at
  // most 2 against dividing by |d| - ed, and one division instead of three.)
  err = (2 * (w1.bound + std::abs(t) * ed) * std::abs(inverse) + 3 * u * std::abs(t)) * (1 + 0x1p-20);
  return t;
}

// The determinants of c and d against the line ab again, on the four points scaled towards 1
// together (difference_products.h): near 1e-300 or 1e150 the products fall outside the filter's
// range and the bounds are infinite, so every order along the edges would need the exact
// predicates. No sign changes, nor the ratio of the pair (a crossing's position); orientation()
// still falls back on the original points. Out of line: the usual path stays as it was.
[[gnu::noinline]] inline void determinantsTowardsUnit(Point a, Point b, Point c, Point d, FilteredDeterminant& dc,
                                                      FilteredDeterminant& dd) {
  scaleTowardsUnit(&a, &b, &c, &d);
  dc = orientationDeterminant(a, b, c), dd = orientationDeterminant(a, b, d);
}

// The position t along a1 -> a2 (0 at a1, 1 at a2) of its crossing with the line m1 m2, and a
// certified bound err on its error (infinite: none).
inline double crossingPosition(Point a1, Point a2, Point m1, Point m2, double& err) {
  FilteredDeterminant w1 = orientationDeterminant(m1, m2, a1), w2 = orientationDeterminant(m1, m2, a2);
  if (!(std::max(w1.bound, w2.bound) < std::numeric_limits<double>::infinity())) determinantsTowardsUnit(m1, m2, a1, a2, w1, w2);
  return certifiedRatio(w1, w2, err);
}

// The position t along a1 -> a2 of a point p on that line, and a certified bound on its error:
// along an axis on which a1 and a2 differ, (p - a1) / (a2 - a1) with three roundings.
inline double pointPosition(Point a1, Point a2, Point p, double& err) {
  const bool alongX = std::abs(a2.x - a1.x) >= std::abs(a2.y - a1.y);
  const double num = alongX ? p.x - a1.x : p.y - a1.y, den = alongX ? a2.x - a1.x : a2.y - a1.y;
  const double t = num / den;
  // Each rounding is relative (u) while nothing is subnormal: 3u |t|, and a margin for the bound's own.
  const bool normal = (num == 0 || std::abs(num) >= 0x1p-1000) && std::abs(den) >= 0x1p-1000 && std::isfinite(t);
  err = normal ? 0x1p-51 * std::abs(t) : std::numeric_limits<double>::infinity();
  return t;
}

}  // namespace gh::detail
