#include "predicates/orientation.h"

#include <cmath>
#include <limits>
#include <optional>
#include <tuple>

#include "predicates/difference_products.h"
#include "predicates/expansion.h"
#include "predicates/filtered_predicate.h"
#include "predicates/integer_stage.h"

namespace gh::detail {

namespace {

// (b - a) x (d - c) exactly in doubles: the differences as two terms each (twoDiff), each pair
// scaled up together when it is small (the sign stands: difference_products.h), their products as
// two terms each, 16 terms summed exactly. A product too small to be made exact (the differences
// of one pair span hundreds of binades) is left out, and bounded: |x y| < 2^-899. The sum's
// largest component holds all but an ulp of it, so while it exceeds twice what was left out, its
// sign is the sign; empty when it does not.
std::optional<Sign> crossSignInDoubles(Point a, Point b, Point c, Point d) {
  TwoTerm left[2] = {twoDiff(b.x, a.x), twoDiff(b.y, a.y)}, right[2] = {twoDiff(d.y, c.y), twoDiff(d.x, c.x)};
  scaleUpTogether(left, 2), scaleUpTogether(right, 2);
  const double u[2] = {left[0].hi, left[0].lo}, w[2] = {left[1].hi, left[1].lo};
  const double v[2] = {right[0].hi, right[0].lo}, z[2] = {right[1].hi, right[1].lo};
  double terms[16];
  std::size_t n = 0;
  double leftOut = 0;  // a bound on the products left out
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      if (!appendProduct(u[i], v[j], 1.0, terms, n)) leftOut += 2 * kLeastExactProduct;
      if (!appendProduct(w[i], z[j], -1.0, terms, n)) leftOut += 2 * kLeastExactProduct;
    }
  }
  const std::size_t m = exactSum(terms, n, terms);
  const double leading = m == 0 ? 0 : terms[m - 1];
  if (leftOut > 0 && !(std::abs(leading) > 2 * leftOut)) return std::nullopt;
  return signOf(leading);
}

}  // namespace

Sign crossSignBeyondStageA(Point a, Point b, Point c, Point d, ExactCounters& counters) {
  // Points near 1e-300 or 1e150 are scaled towards 1 first (difference_products.h: the sign
  // stands), so that every stage below works there as at 1.
  scaleTowardsUnit(&a, &b, &c, &d);
  // Shewchuk's stage-A bound (each factor is one rounded difference, as in orientation()), then
  // the floating-point filter with a running error bound, then the exact sum in doubles, then GMP.
  // Stage A needs products in the normal range: when they are not, each pair of rounded
  // differences is scaled by a power of two first (exactly; each keeps its relative rounding
  // error, and the sign stands), so that coordinates near 1e-300 or 1e150 are decided here as at 1.
  {
    double ux = b.x - a.x, uy = b.y - a.y, vx = d.x - c.x, vy = d.y - c.y;
    FilteredDeterminant det = stageADeterminant(ux, uy, vx, vy);
    if (!(det.bound < std::numeric_limits<double>::infinity())) {  // products out of range
      scaleTowardsUnit(ux, uy), scaleTowardsUnit(vx, vy);
      det = stageADeterminant(ux, uy, vx, vy);
    }
    if (const auto s = certainSign(det.value, det.bound)) return *s;
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
  return integerCrossSign(a, b, c, d);
}

Sign orientationExact(Point a, Point b, Point c, ExactCounters& counters) {
  // Two equal points make the determinant exactly zero, but its factors are differences that the
  // filter carries with a rounding error, so it could not certify that: say it here.
  if (a == b || a == c || b == c) return Sign::Zero;
  return crossSign(a, b, a, c, counters);
}

}  // namespace gh::detail
