// The one filtered-predicate helper of the library, as CGAL's Filtered_predicate: a predicate is
// written once, generically over a number policy, and run first with floating-point values that
// carry a certified error bound (Approx), then, only if some sign it needed was not certain, with
// exact rationals (GMP), counted as a filter failure; optionally with a stage exact in doubles
// between the two.
//
//   Sign s = filteredPredicate([&](auto numbers) -> std::optional<Sign> {
//     using N = typename decltype(numbers)::Number;
//     const N d = (N(b.x) - N(a.x)) * (N(c.y) - N(a.y)) - ...;
//     return numbers.sign(d);   // empty: not certain at this stage
//   }, counters);
//
// A predicate that needs several signs asks for them one at a time and returns empty as soon as
// one is uncertain, so terms that are never needed are never decided.
// Include only from .cpp files: it brings in gmpxx.
#pragma once

#include <gmpxx.h>

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

// Exact rationals (doubles convert exactly): every sign is certain.
struct ExactNumbers {
  using Number = mpq_class;
  static std::optional<Sign> sign(const mpq_class& q) { return toSign(sgn(q)); }
};

template <class Predicate>
auto filteredPredicate(Predicate&& predicate, ExactCounters& counters) {
  if (auto quick = predicate(FilterNumbers{})) return *quick;
  ++counters.filterFailures;
  return *predicate(ExactNumbers{});
}

// The same with a stage between the filter and GMP: inDoubles() gives the sign exactly in doubles
// where it can (difference_products.h), counted as an expansion decision, or nothing.
template <class Predicate, class InDoubles>
auto filteredPredicate(Predicate&& predicate, InDoubles&& inDoubles, ExactCounters& counters) {
  if (auto quick = predicate(FilterNumbers{})) return *quick;
  if (auto exact = inDoubles()) {
    ++counters.expansionDecisions;
    return *exact;
  }
  ++counters.filterFailures;
  return *predicate(ExactNumbers{});
}

}  // namespace gh::detail
