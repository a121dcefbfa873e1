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
#include <optional>

#include "predicates/error_free.h"
#include "predicates/expansion.h"

namespace gh::detail {

// Smallest magnitude of a product made exact here (below it, the error may be lost).
inline constexpr double kLeastExactProduct = 0x1p-900;

// Multiplies every part of diffs[0, n) by one power of two, up, so that the largest leading part
// is in [1, 2); nothing when it is already at least 1 (or all are 0). Exact: no part overflows.
inline void scaleUpTogether(TwoTerm* diffs, std::size_t n) {
  double largest = 0;
  for (std::size_t i = 0; i < n; ++i) largest = std::max(largest, std::abs(diffs[i].hi));
  if (!(largest > 0) || largest >= 1) return;
  const int k = -std::ilogb(largest);
  for (std::size_t i = 0; i < n; ++i) diffs[i].hi = std::ldexp(diffs[i].hi, k), diffs[i].lo = std::ldexp(diffs[i].lo, k);
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
