#include "predicates/orientation.h"

#include <cmath>
#include <optional>
#include <tuple>

#include "predicates/expansion.h"
#include "predicates/filtered_predicate.h"

namespace gh::detail {

namespace {

// (b - a) x (d - c) exactly in doubles, where that is exact: the differences as two terms each
// (twoDiff), their products as two terms each (Dekker's splitting: every factor below 2^996), 16
// terms summed exactly. Empty when a product's rounding error could fall below the subnormal
// range (then twoProduct would not be exact).
std::optional<Sign> crossSignInDoubles(Point a, Point b, Point c, Point d) {
  const TwoTerm u = twoDiff(b.x, a.x), v = twoDiff(d.y, c.y), w = twoDiff(b.y, a.y), z = twoDiff(d.x, c.x);
  const double left[2] = {u.hi, u.lo}, right[2] = {v.hi, v.lo}, left2[2] = {w.hi, w.lo}, right2[2] = {z.hi, z.lo};
  double terms[16];
  int n = 0;
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      for (const auto& [x, y, sign] : {std::tuple{left[i], right[j], 1.0}, std::tuple{left2[i], right2[j], -1.0}}) {
        // A product of nonzero factors that is tiny (or underflowed to 0) may have lost bits.
        if (x != 0 && y != 0 && !(std::abs(x * y) >= 0x1p-900)) return std::nullopt;
        const TwoTerm t = twoProductBySplitting(x, y);
        terms[n++] = sign * t.hi, terms[n++] = sign * t.lo;
      }
    }
  }
  return signOfExactSum(terms);
}

}  // namespace

Sign crossSign(Point a, Point b, Point c, Point d, ExactCounters& counters) {
  // Shewchuk's stage-A bound (each factor is one rounded difference, as in orientation()), then
  // the floating-point filter with a running error bound, then the exact sum in doubles, then GMP.
  {
    const double left = (b.x - a.x) * (d.y - c.y), right = (b.y - a.y) * (d.x - c.x);
    const double sum = std::abs(left) + std::abs(right);
    if (sum > 0x1p-900 && sum < 0x1p900) {
      if (const auto s = certainSign(left - right, (3.0 + 16.0 * 0x1p-53) * 0x1p-53 * sum)) return *s;
    }
  }
  const auto approximate = [&](auto numbers) {
    using N = typename decltype(numbers)::Number;
    const N value = (N(b.x) - N(a.x)) * (N(d.y) - N(c.y)) - (N(b.y) - N(a.y)) * (N(d.x) - N(c.x));
    return numbers.sign(value);
  };
  if (const auto s = approximate(FilterNumbers{})) return *s;
  if (const auto s = crossSignInDoubles(a, b, c, d)) {
    ++counters.expansionDecisions;
    return *s;
  }
  ++counters.filterFailures;
  return *approximate(ExactNumbers{});
}

Sign orientationExact(Point a, Point b, Point c, ExactCounters& counters) {
  // Two equal points make the determinant exactly zero, but its factors are differences that the
  // filter carries with a rounding error, so it could not certify that: say it here.
  if (a == b || a == c || b == c) return Sign::Zero;
  return crossSign(a, b, a, c, counters);
}

}  // namespace gh::detail
