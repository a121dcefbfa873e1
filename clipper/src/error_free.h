// Error-free transformations of double arithmetic (Knuth, Dekker; see Ogita, Rump and Oishi,
// "Accurate sum and dot product", SIAM J. Sci. Comput. 2005): each returns a rounded result and
// the exact error of that rounding, so that hi + lo equals the exact value. Round to nearest, no
// overflow; sums and differences are exact at every magnitude, subnormal included.
#pragma once

#include <cmath>

namespace gh::detail {

// hi + lo, exactly.
struct TwoTerm {
  double hi, lo;
};

// a + b = hi + lo exactly (Knuth's TwoSum: no condition on the magnitudes).
inline TwoTerm twoSum(double a, double b) {
  const double s = a + b, bv = s - a, av = s - bv;
  return {s, (a - av) + (b - bv)};
}

// a - b = hi + lo exactly.
inline TwoTerm twoDiff(double a, double b) {
  const double s = a - b, bv = s - a, av = s - bv;
  return {s, (a - av) - (b + bv)};
}

// a * b = hi + lo exactly unless the product's error falls below the subnormal range (then lo is
// within 2^-1075 of it). Fast only where fma is an instruction: call it from code compiled for it.
inline TwoTerm twoProduct(double a, double b) {
  const double p = a * b;
  return {p, std::fma(a, b, -p)};
}

}  // namespace gh::detail
