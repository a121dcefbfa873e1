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

Sign orientationExact(Point a, Point b, Point c, ExactCounters& counters) { return crossSign(a, b, a, c, counters); }

}  // namespace gh::detail
