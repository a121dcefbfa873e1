#include "orientation.h"

#include <gmpxx.h>

#include <cmath>

#include "approx.h"

namespace gh::detail {

std::uint64_t& exactFallbacks() {
  thread_local std::uint64_t count = 0;
  return count;
}

namespace {

template <class N>
N cross(Point a, Point b, Point c, Point d) {
  return (N(b.x) - N(a.x)) * (N(d.y) - N(c.y)) - (N(b.y) - N(a.y)) * (N(d.x) - N(c.x));
}

Sign decide(Point a, Point b, Point c, Point d) {
  const int s = certainSign(cross<Approx>(a, b, c, d));
  if (s != 2) return toSign(s);
  ++exactFallbacks();
  return toSign(sgn(cross<mpq_class>(a, b, c, d)));  // doubles convert to rationals exactly
}

}  // namespace

Sign orientation(Point a, Point b, Point c) {
  // Stage A of Shewchuk's orient2d: a plain double evaluation decides almost every call;
  // |error| <= (3 + 16 eps) eps (|left| + |right|) while nothing under- or overflows.
  constexpr double kBound = (3.0 + 16.0 * 0x1p-53) * 0x1p-53;
  const double left = (b.x - a.x) * (c.y - a.y), right = (b.y - a.y) * (c.x - a.x);
  const double det = left - right, sum = std::abs(left) + std::abs(right);
  if (sum > 0x1p-900 && sum < 0x1p900) {
    if (det > kBound * sum) return Sign::Positive;
    if (-det > kBound * sum) return Sign::Negative;
  }
  return decide(a, b, a, c);
}

Sign crossSign(Point a, Point b, Point c, Point d) { return decide(a, b, c, d); }

}  // namespace gh::detail
