// The one filtered-predicate helper of the library, as CGAL's Filtered_predicate: a predicate is
// written generically over a number policy and run first with floating-point values that carry a
// certified error bound (Approx); only if some sign it needed was not certain, a stage exact in
// doubles (counted as an expansion decision), and where that cannot decide, the exact stage in
// integers (integer_stage.h), counted as a filter failure.
//
//   Sign s = filteredPredicate([&](auto numbers) -> std::optional<Sign> {
//     using N = typename decltype(numbers)::Number;
//     const N d = (N(b.x) - N(a.x)) * (N(c.y) - N(a.y)) - ...;
//     return numbers.sign(d);   // empty: not certain at this stage
//   }, inDoubles, exact, counters);
//
// A predicate that needs several signs asks for them one at a time and returns empty as soon as
// one is uncertain, so terms that are never needed are never decided.
#pragma once

#include <optional>

#include "predicates/approx.h"
#include "predicates/exact_counters.h"
#include "predicates/sign.h"

namespace gh::detail {

// Floating point with a running error bound: certain signs only.
struct FilterNumbers {
  using Number = Approx;
  static std::optional<Sign> sign(const Approx& a) { return certainSign(a); }
};

// inDoubles() gives the sign exactly in doubles where it can (difference_products.h), or nothing;
// exact() always gives it.
template <class Predicate, class InDoubles, class Exact>
auto filteredPredicate(Predicate&& predicate, InDoubles&& inDoubles, Exact&& exact, ExactCounters& counters) {
  if (auto quick = predicate(FilterNumbers{})) return *quick;
  if (auto decided = inDoubles()) {
    ++counters.expansionDecisions;
    return *decided;
  }
  ++counters.filterFailures;
  return exact();
}

}  // namespace gh::detail
