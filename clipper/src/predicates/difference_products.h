// Polynomials in differences of coordinates (cross products, and products of cross products),
// evaluated exactly in doubles: the stage of the exact predicates between the filter and GMP.
// Each difference is two terms (twoDiff), each product of terms two terms (Dekker's
// twoProductBySplitting), and the sum an expansion (expansion.h). A product is exact only while
// its rounding error stays above the subnormal range, so the differences are first scaled up by
// one power of two, exactly, when they are all small: a polynomial homogeneous in them changes by
// a positive factor only, so its sign stands. What still falls below 2^-900 is either bounded
// (crossSign) or sends the predicate on to GMP.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <limits>
#include <optional>

#include "ghclip/region.h"

#include "predicates/error_free.h"
#include "predicates/expansion.h"

namespace gh::detail {

// Smallest magnitude of a product made exact here (below it, the error may be lost).
inline constexpr double kLeastExactProduct = 0x1p-900;

// floor(log2 |x|) for finite nonzero x: from the exponent bits for normal numbers (no libm call:
// the pair test asks for every candidate pair of a problem near 1e-300).
inline int binaryExponent(double x) {
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  const int field = static_cast<int>((bits >> 52) & 0x7ff);
  return field != 0 ? field - 1023 : std::ilogb(x);
}

// The power of two k that brings a largest magnitude below 1 into [1, 2): 0 when it is 0 or
// already at least 1.
inline int scaleUpExponent(double largest) { return largest > 0 && largest < 1 ? -binaryExponent(largest) : 0; }

// x * 2^k for k in [-1022, 1074], exactly while the result neither overflows nor leaves the
// normal range (a multiplication by a power of two, in two steps when 2^k itself is beyond the
// largest double).
inline double timesPowerOfTwo(double x, int k) {
  const auto power = [](int e) {  // 2^e for e in [-1022, 1000], from its bits (no libm call)
    const std::uint64_t bits = static_cast<std::uint64_t>(e + 1023) << 52;
    double p;
    std::memcpy(&p, &bits, sizeof p);
    return p;
  };
  if (k <= 1000) return x * power(k);
  return x * 0x1p1000 * power(k - 1000);
}

// The power of two k that brings the largest of some magnitudes into [1, 2) without moving any
// nonzero one out of the normal range (scaling down would then round it): 0 when there is none.
inline int towardsUnitExponent(double largest, double smallestNonzero) {
  if (!(largest > 0) || (largest >= 1 && largest < 2)) return 0;
  const int k = -binaryExponent(largest);
  if (k < 0 && binaryExponent(smallestNonzero) + k < -1022) return 0;
  return k;
}

// Multiplies every part of diffs[0, n) by one power of two, up, so that the largest leading part
// is in [1, 2); nothing when it is already at least 1 (or all are 0). Exact: no part overflows.
inline void scaleUpTogether(TwoTerm* diffs, std::size_t n) {
  double largest = 0;
  for (std::size_t i = 0; i < n; ++i) largest = std::max(largest, std::abs(diffs[i].hi));
  const int k = scaleUpExponent(largest);
  if (k == 0) return;
  for (std::size_t i = 0; i < n; ++i) diffs[i] = {timesPowerOfTwo(diffs[i].hi, k), timesPowerOfTwo(diffs[i].lo, k)};
}

// Two rounded differences scaled together by one power of two, up or down, so that the larger
// is in [1, 2) (towardsUnitExponent): each keeps its relative rounding error, and the sign of a
// product of one and a difference of another pair stands.
inline void scaleTowardsUnit(double& x, double& y) {
  const double ax = std::abs(x), ay = std::abs(y);
  const int k = towardsUnitExponent(std::max(ax, ay), ax == 0 ? ay : ay == 0 ? ax : std::min(ax, ay));
  if (k != 0) x = timesPowerOfTwo(x, k), y = timesPowerOfTwo(y, k);
}

// Coordinates all below kFarBelow, or some beyond kFarAbove, are scaled before the filters
// (scaleTowardsUnit): near 1e-300 the filters' products fall below their range, near 1e150
// beyond it, and every predicate would go on to the slower exact stages.
inline constexpr double kFarBelow = 0x1p-200, kFarAbove = 0x1p200;

// The larger of m and the magnitudes of p's coordinates.
inline double largerMagnitude(double m, const Point& p) { return std::max(m, std::max(std::abs(p.x), std::abs(p.y))); }

// Scales the points together by one power of two, exactly, so that their largest coordinate is
// in [1, 2), when it is below 2^-200 or beyond 2^200 (and, scaling down, no nonzero coordinate
// would leave the normal range). The sign of a polynomial homogeneous in differences of the
// coordinates stands, and so does the ratio of two of the same degree (a crossing's position
// along an edge) and the order of two coordinates. A parameter pack, not a list: the test runs
// before every exact predicate, and a list's array on the stack cost a poisoned frame under ASan.
template <class... Points>
inline void scaleTowardsUnit(Points*... points) {
  double largest = 0;
  ((largest = largerMagnitude(largest, *points)), ...);
  if (!(largest < kFarBelow || largest > kFarAbove)) return;
  double smallest = std::numeric_limits<double>::infinity();
  for (const Point* p : {static_cast<const Point*>(points)...}) {
    for (const double c : {std::abs(p->x), std::abs(p->y)}) {
      if (c != 0) smallest = std::min(smallest, c);
    }
  }
  const int k = towardsUnitExponent(largest, smallest);
  if (k == 0) return;
  ((*points = {timesPowerOfTwo(points->x, k), timesPowerOfTwo(points->y, k)}), ...);
}

// Appends sign * x * y to terms as two terms, exactly; false, appending nothing, when the product
// is too small to be made exact (neither factor zero). Factors below 2^996 (Dekker's splitting).
inline bool appendProduct(double x, double y, double sign, double* terms, std::size_t& n) {
  if (x == 0 || y == 0) return true;
  if (!(std::abs(x * y) >= kLeastExactProduct)) return false;
  const TwoTerm t = twoProductBySplitting(x, y);
  terms[n++] = sign * t.hi, terms[n++] = sign * t.lo;
  return true;
}

// ux * vy - uy * vx exactly, as an expansion in out (room for 16); its number of components, or
// nothing when a product is too small to be made exact.
inline std::optional<std::size_t> crossExpansion(TwoTerm ux, TwoTerm uy, TwoTerm vx, TwoTerm vy, double* out) {
  const double a[2] = {ux.hi, ux.lo}, b[2] = {vy.hi, vy.lo}, c[2] = {uy.hi, uy.lo}, d[2] = {vx.hi, vx.lo};
  std::size_t n = 0;
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      if (!appendProduct(a[i], b[j], 1.0, out, n) || !appendProduct(c[i], d[j], -1.0, out, n)) return std::nullopt;
    }
  }
  return exactSum(out, n, out);
}

}  // namespace gh::detail
