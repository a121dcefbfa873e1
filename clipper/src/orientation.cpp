#include "orientation.h"

#include <gmpxx.h>

#include <cmath>
#include <limits>

namespace gh::detail {
namespace {

Sign signOf(int s) { return s > 0 ? Sign::Positive : s < 0 ? Sign::Negative : Sign::Zero; }

Sign exactOrientation(Point a, Point b, Point c) {
  // Doubles convert to rationals exactly, so this is the true sign.
  const mpq_class ax(a.x), ay(a.y), bx(b.x), by(b.y), cx(c.x), cy(c.y);
  const mpq_class det = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
  return signOf(sgn(det));
}

}  // namespace

Sign orientation(Point a, Point b, Point c) {
  // Shewchuk's orient2d stage A: |error| <= (3 + 16 eps) eps * (|left| + |right|), valid when no
  // intermediate result under- or overflows; outside that range go straight to exact arithmetic.
  constexpr double eps = std::numeric_limits<double>::epsilon() / 2;
  constexpr double errBound = (3.0 + 16.0 * eps) * eps;
  const double left = (b.x - a.x) * (c.y - a.y);
  const double right = (b.y - a.y) * (c.x - a.x);
  const double det = left - right;
  const double sum = std::abs(left) + std::abs(right);
  if (sum > 1e-280 && sum < 1e280 && std::isfinite(det)) {
    if (det > errBound * sum) return Sign::Positive;
    if (-det > errBound * sum) return Sign::Negative;
  }
  return exactOrientation(a, b, c);
}

}  // namespace gh::detail
