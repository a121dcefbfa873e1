// Exact sums of doubles, computed in doubles: the terms are accumulated into a nonoverlapping
// expansion (Shewchuk, "Adaptive precision floating-point arithmetic and fast robust geometric
// predicates", 1997, GROW-EXPANSION with zero elimination), whose largest component carries the
// sign and all but an ulp of the sum. Sums and differences are error-free at every magnitude, so
// this is exact whenever the terms are (no term overflowed; products made exact by twoProduct*).
#pragma once

#include <cstddef>

#include "predicates/error_free.h"
#include "predicates/sign.h"

namespace gh::detail {

// The exact sum of terms[0, count) as a nonoverlapping expansion in out (components in increasing
// magnitude, none zero; out has room for count); returns the number of components, 0 for a zero
// sum. out may be terms itself.
inline std::size_t exactSum(const double* terms, std::size_t count, double* out) {
  std::size_t m = 0;
  for (std::size_t i = 0; i < count; ++i) {
    double q = terms[i];
    std::size_t kept = 0;
    for (std::size_t j = 0; j < m; ++j) {
      const TwoTerm s = twoSum(q, out[j]);
      q = s.hi;
      if (s.lo != 0) out[kept++] = s.lo;
    }
    if (q != 0) out[kept++] = q;
    m = kept;
  }
  return m;
}

template <std::size_t N>
Sign signOfExactSum(const double (&terms)[N]) {
  double e[N];
  const std::size_t m = exactSum(terms, N, e);
  return m == 0 ? Sign::Zero : signOf(e[m - 1]);
}

}  // namespace gh::detail
