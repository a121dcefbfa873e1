// Floating point with a running error bound: the number type of the filter stage of every exact
// predicate (filtered_predicate.h).
//
// An Approx holds v and e with |true value - v| <= e. Subtraction and multiplication compute the
// rounding error of their own result exactly (error_free.h), so computations that happen to be
// exact (small integers, dyadic grids) carry e = 0 and decide even a zero sign without exact
// arithmetic. Magnitudes outside [2^-900, 2^900] make the bound unsafe (under- or overflow): e
// becomes infinite and the predicate falls back to exact arithmetic.
#pragma once

#include <cmath>
#include <limits>
#include <optional>

#include "predicates/error_free.h"
#include "predicates/sign.h"

namespace gh::detail {

struct Approx {
  double v = 0;
  double e = 0;

  Approx() = default;
  Approx(double value) : v(value) {}  // NOLINT: exact input
  Approx(double value, double error) : v(value), e(error) {}
};

namespace approx {

inline constexpr double kInf = std::numeric_limits<double>::infinity();

// Below it a product in the error bound may round with more than the relative error that
// certainSign's margin covers (subnormal results), or flush to 0.
inline constexpr double kLeastSafeErrorTerm = 0x1p-1000;

inline bool safeMagnitude(double x) {
  const double a = std::abs(x);
  return a == 0 || (a > 0x1p-900 && a < 0x1p900);
}

}  // namespace approx

inline Approx operator-(const Approx& a, const Approx& b) {
  const TwoTerm d = twoDiff(a.v, b.v);
  if (!approx::safeMagnitude(a.v) || !approx::safeMagnitude(b.v) || !approx::safeMagnitude(d.hi)) {
    return {d.hi, approx::kInf};
  }
  return {d.hi, a.e + b.e + std::abs(d.lo)};
}

inline Approx operator+(const Approx& a, const Approx& b) { return a - Approx{-b.v, b.e}; }

inline Approx operator*(const Approx& a, const Approx& b) {
  const double v = a.v * b.v;
  // A product of nonzero factors that underflowed to 0.0 is not an exact zero.
  const bool underflowed = v == 0 && a.v != 0 && b.v != 0;
  if (underflowed || !approx::safeMagnitude(a.v) || !approx::safeMagnitude(b.v) || !approx::safeMagnitude(v)) {
    return {v, approx::kInf};
  }
  // The bound's own products must not lose their value below the normal range: a value times an
  // error that flushed to 0 (2^-343 times 2^-898) made the bound 0, and a zero bound certifies.
  const double terms[3] = {std::abs(a.v) * b.e, std::abs(b.v) * a.e, a.e * b.e};
  const double factors[3][2] = {{a.v, b.e}, {b.v, a.e}, {a.e, b.e}};
  for (int i = 0; i < 3; ++i) {
    if (factors[i][0] != 0 && factors[i][1] != 0 && !(terms[i] >= approx::kLeastSafeErrorTerm)) return {v, approx::kInf};
  }
  return {v, terms[0] + terms[1] + terms[2] + std::abs(twoProductBySplitting(a.v, b.v).lo)};
}

// The sign of the true value if the bound decides it.
inline std::optional<Sign> certainSign(const Approx& a) { return certainSign(a.v, a.e); }

}  // namespace gh::detail
