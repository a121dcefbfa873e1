// The answer of every predicate: a sign, never a raw value that would invite `< eps` downstream.
#pragma once

#include <optional>

namespace gh::detail {

enum class Sign { Negative = -1, Zero = 0, Positive = 1 };

inline Sign toSign(int s) { return s > 0 ? Sign::Positive : s < 0 ? Sign::Negative : Sign::Zero; }
inline Sign operator-(Sign s) { return toSign(-static_cast<int>(s)); }
inline Sign operator*(Sign a, Sign b) { return toSign(static_cast<int>(a) * static_cast<int>(b)); }

// Sign of a - b for doubles: exact (a comparison, no subtraction).
inline int signOfDifference(double a, double b) { return (a > b) - (a < b); }

// Sign of x (0 for a NaN).
inline Sign signOf(double x) { return toSign(signOfDifference(x, 0)); }

// The sign of a value known to within a certified bound, |exact - value| <= bound: empty when the
// bound does not decide it (it straddles zero, or is infinite or NaN). A zero bound decides even
// a zero sign: exact computations (small integers, dyadic grids) need no exact fallback.
// A nonzero bound was itself computed with a few roundings: the margin 2^-20 covers them.
inline std::optional<Sign> certainSign(double value, double bound) {
  if (bound == 0) return signOf(value);
  if (!(bound < __builtin_inf()) || value != value) return std::nullopt;
  if (value > bound * (1 + 0x1p-20)) return Sign::Positive;
  if (-value > bound * (1 + 0x1p-20)) return Sign::Negative;
  return std::nullopt;
}

}  // namespace gh::detail
