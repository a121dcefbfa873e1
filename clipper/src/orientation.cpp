#include "orientation.h"

#include <gmpxx.h>

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

Sign orientationExact(Point a, Point b, Point c) { return decide(a, b, a, c); }

Sign crossSign(Point a, Point b, Point c, Point d) { return decide(a, b, c, d); }

}  // namespace gh::detail
