// Error-free transformations of double arithmetic (Knuth, Dekker; see Ogita, Rump and Oishi,
// "Accurate sum and dot product", SIAM J. Sci. Comput. 2005): each returns a rounded result and
// the exact error of that rounding, so that hi + lo equals the exact value. Round to nearest, no
// overflow; sums and differences are exact at every magnitude, subnormal included. The library's
// only copy: the filter (approx.h) and the construction of crossing points build on these.
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

// The same without fma (Dekker's TwoProduct with Veltkamp's splitting into 26-bit halves), for
// code compiled for the base instruction set: exact while |a|, |b| < 2^996 and the error does not
// fall below the subnormal range.
inline TwoTerm twoProductBySplitting(double a, double b) {
  auto split = [](double v, double& hi, double& lo) {
    const double c = 134217729.0 * v;  // 2^27 + 1
    hi = c - (c - v);
    lo = v - hi;
  };
  const double p = a * b;
  double ah, al, bh, bl;
  split(a, ah, al);
  split(b, bh, bl);
  return {p, ((ah * bh - p) + ah * bl + al * bh) + al * bl};
}

}  // namespace gh::detail
