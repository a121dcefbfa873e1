#include "predicates/orientation.h"

#include "predicates/filtered_predicate.h"

namespace gh::detail {

Sign crossSign(Point a, Point b, Point c, Point d, ExactCounters& counters) {
  return filteredPredicate(
      [&](auto numbers) {
        using N = typename decltype(numbers)::Number;
        const N value = (N(b.x) - N(a.x)) * (N(d.y) - N(c.y)) - (N(b.y) - N(a.y)) * (N(d.x) - N(c.x));
        return numbers.sign(value);
      },
      counters);
}

Sign orientationExact(Point a, Point b, Point c, ExactCounters& counters) {
  // Two equal points make the determinant exactly zero, but its factors are differences that the
  // filter carries with a rounding error, so it could not certify that: say it here.
  if (a == b || a == c || b == c) return Sign::Zero;
  return crossSign(a, b, a, c, counters);
}

}  // namespace gh::detail
