// Floating point with a running error bound: the filter of every exact predicate.
//
// An Approx holds v and e with |true value - v| <= e. Subtraction and multiplication compute the
// rounding error of their own result exactly (Knuth's TwoSum, Dekker's TwoProduct), so
// computations that happen to be exact (small integers, dyadic grids) carry e = 0 and decide even
// a zero sign without exact arithmetic. Magnitudes outside [2^-900, 2^900] make the bound unsafe
// (under- or overflow): e becomes infinite and the caller falls back to exact arithmetic.
#pragma once

#include <cmath>
#include <limits>

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

inline bool safeMagnitude(double x) {
  const double a = std::abs(x);
  return a == 0 || (a > 0x1p-900 && a < 0x1p900);
}

// Exact rounding error of a - b (Knuth's TwoSum on a + (-b)).
inline double subtractionError(double a, double b, double s) {
  const double bb = s - a;
  const double aa = s - bb;
  return (a - aa) + (-b - bb);
}

// Exact rounding error of a * b (Dekker's TwoProduct with Veltkamp splitting; valid while
// |a|, |b| < 2^996, which safeMagnitude guarantees).
inline void split(double a, double& hi, double& lo) {
  const double c = 134217729.0 * a;  // 2^27 + 1
  hi = c - (c - a);
  lo = a - hi;
}
inline double productError(double a, double b, double p) {
  double ah, al, bh, bl;
  split(a, ah, al);
  split(b, bh, bl);
  return ((ah * bh - p) + ah * bl + al * bh) + al * bl;
}

}  // namespace approx

inline Approx operator-(const Approx& a, const Approx& b) {
  const double v = a.v - b.v;
  if (!approx::safeMagnitude(a.v) || !approx::safeMagnitude(b.v) || !approx::safeMagnitude(v)) {
    return {v, approx::kInf};
  }
  return {v, a.e + b.e + std::abs(approx::subtractionError(a.v, b.v, v))};
}

inline Approx operator+(const Approx& a, const Approx& b) { return a - Approx{-b.v, b.e}; }

inline Approx operator*(const Approx& a, const Approx& b) {
  const double v = a.v * b.v;
  // A product of nonzero factors that underflowed to 0.0 is not an exact zero.
  const bool underflowed = v == 0 && a.v != 0 && b.v != 0;
  if (underflowed || !approx::safeMagnitude(a.v) || !approx::safeMagnitude(b.v) || !approx::safeMagnitude(v)) {
    return {v, approx::kInf};
  }
  return {v, std::abs(a.v) * b.e + std::abs(b.v) * a.e + a.e * b.e +
                 std::abs(approx::productError(a.v, b.v, v))};
}

// The sign of the true value if the bound decides it: +1, -1, 0; or 2 when it cannot.
// A nonzero e was itself computed with a few roundings: the margin 2^-20 covers them.
inline int certainSign(const Approx& a) {
  if (a.e == 0) return (a.v > 0) - (a.v < 0);
  if (!(a.e < approx::kInf) || std::isnan(a.v)) return 2;
  if (std::abs(a.v) > a.e * (1 + 0x1p-20)) return a.v > 0 ? 1 : -1;
  return 2;
}

}  // namespace gh::detail
