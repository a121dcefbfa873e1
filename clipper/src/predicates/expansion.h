// The exact sign of a sum of doubles, computed in doubles: the terms are accumulated into a
// nonoverlapping expansion (Shewchuk, "Adaptive precision floating-point arithmetic and fast
// robust geometric predicates", 1997, GROW-EXPANSION with zero elimination), whose largest
// component carries the sign. Sums and differences are error-free at every magnitude, so this is
// exact whenever the terms are (no term overflowed; products made exact by twoProduct*).
#pragma once

#include <cstddef>

#include "predicates/error_free.h"
#include "predicates/sign.h"

namespace gh::detail {

template <std::size_t N>
Sign signOfExactSum(const double (&terms)[N]) {
  double e[N];
  std::size_t m = 0;
  for (const double t : terms) {
    double q = t;
    std::size_t kept = 0;
    for (std::size_t j = 0; j < m; ++j) {
      const TwoTerm s = twoSum(q, e[j]);
      q = s.hi;
      if (s.lo != 0) e[kept++] = s.lo;
    }
    if (q != 0) e[kept++] = q;
    m = kept;
  }
  return m == 0 ? Sign::Zero : toSign((e[m - 1] > 0) - (e[m - 1] < 0));
}

}  // namespace gh::detail
