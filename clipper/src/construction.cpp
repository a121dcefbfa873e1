#include "construction.h"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

namespace gh::detail {

std::uint64_t& exactConstructions() {
  thread_local std::uint64_t count = 0;
  return count;
}

namespace {

using Wide = long double;
constexpr Wide kU = std::numeric_limits<Wide>::epsilon() / 2;  // unit roundoff of Wide
// The bounds below assume no product of two doubles under- or overflows in Wide: true for the
// x87 extended format; elsewhere (long double = double) every point takes the exact path.
constexpr bool kWideHasRange =
    std::numeric_limits<Wide>::max_exponent >= 4096 && std::numeric_limits<Wide>::min_exponent <= -4096;

// The determinant O(b1, b2, a) = (b2 - b1) x (a - b1) with a stage-A style bound on its error in
// Wide (differences rounded, two products, one subtraction): (3 + 16u) u (|l| + |r|).
struct WideDeterminant {
  Wide value, bound;
};
WideDeterminant determinant(Point b1, Point b2, Point a) {
  const Wide l = (Wide(b2.x) - b1.x) * (Wide(a.y) - b1.y);
  const Wide r = (Wide(b2.y) - b1.y) * (Wide(a.x) - b1.x);
  return {l - r, (3 + 16 * kU) * kU * (std::abs(l) + std::abs(r))};
}

// A coordinate with a bound on its error: [value - bound, value + bound] holds the exact one.
struct Enclosure {
  Wide value, bound;
};

// Parameter t = w1 / (w1 - w2) along a segment whose endpoints lie on opposite sides of (or on)
// the other segment's line, and 1 - t = -w2 / (w1 - w2): bounds on both from those of w1, w2.
struct Parameter {
  Wide t, oneMinusT, errT, errOneMinusT;
  bool valid;
};
Parameter parameter(WideDeterminant w1, WideDeterminant w2) {
  const Wide d = w1.value - w2.value;
  const Wide ed = w1.bound + w2.bound + kU * std::abs(d);
  const Wide margin = std::abs(d) - ed;
  Parameter p{};
  if (!(margin > 0)) return p;
  const Wide inverse = 1 / d, inverseMargin = 1 / margin;
  p.t = w1.value * inverse;
  p.oneMinusT = -w2.value * inverse;
  // |w/d - W/D| <= (e_w + |w/d| e_d) / (|d| - e_d), plus the roundings of 1/d and the product.
  p.errT = ((w1.bound + std::abs(p.t) * ed) * inverseMargin + 2 * kU * std::abs(p.t)) * (1 + 8 * kU);
  p.errOneMinusT = ((w2.bound + std::abs(p.oneMinusT) * ed) * inverseMargin + 2 * kU * std::abs(p.oneMinusT)) * (1 + 8 * kU);
  p.valid = std::isfinite(p.errT) && std::isfinite(p.errOneMinusT);
  return p;
}

// from + s * (to - from) with |s - s_exact| <= errS: value and error bound.
Enclosure interpolate(double from, double to, Wide s, Wide errS) {
  const Wide delta = Wide(to) - from;  // rounded once
  const Wide step = s * delta;
  const Wide value = from + step;
  const Wide bound = (errS * std::abs(delta) + 2 * kU * std::abs(step) + kU * std::abs(value)) * (1 + 8 * kU);
  return {value, bound};
}

// The two doubles next to a finite d (nextafter without the library call: adjacent doubles of
// one sign have adjacent bit patterns).
void neighbours(double d, double& below, double& above) {
  if (d == 0) {
    below = -std::numeric_limits<double>::denorm_min(), above = std::numeric_limits<double>::denorm_min();
    return;
  }
  std::uint64_t bits;
  std::memcpy(&bits, &d, sizeof d);
  const std::uint64_t away = bits + 1, toward = bits - 1;  // away from zero / toward zero
  double a, t;
  std::memcpy(&a, &away, sizeof a);
  std::memcpy(&t, &toward, sizeof t);
  if (d > 0) below = t, above = a;
  else below = a, above = t;
}

// A double within one ulp of every value in the enclosure, if there is one: the enclosure then
// lies strictly between the two neighbours of its rounded centre.
bool certify(Enclosure e, double& out) {
  const double d = static_cast<double>(e.value);
  if (!std::isfinite(d) || !std::isfinite(e.bound)) return false;
  double below, above;
  neighbours(d, below, above);
  if (!(e.value - e.bound > below && e.value + e.bound < above)) return false;
  out = d;
  return true;
}

// The double nearest to v. mpq_class::get_d truncates and gives up below the normal range, so
// tiny values are lifted by an exact power of two first; the truncated result is then within one
// ulp, and the nearest of it and its two neighbours is chosen exactly.
double nearestDouble(const mpq_class& v) {
  constexpr int kLift = 1100;
  double d;
  if (abs(v) < mpq_class(0x1p-1000)) {
    mpq_class lifted;
    mpq_mul_2exp(lifted.get_mpq_t(), v.get_mpq_t(), kLift);
    d = std::ldexp(lifted.get_d(), -kLift);
  } else {
    d = v.get_d();
  }
  double best = d;
  mpq_class bestError = abs(v - mpq_class(d));
  for (double c : {std::nextafter(d, -std::numeric_limits<double>::infinity()),
                   std::nextafter(d, std::numeric_limits<double>::infinity())}) {
    if (!std::isfinite(c)) continue;
    const mpq_class error = abs(v - mpq_class(c));
    if (error < bestError) best = c, bestError = error;
  }
  return best;
}

Point exactCrossing(Point p1, Point p2, Point q1, Point q2) {
  ++exactConstructions();
  // t = O(q1, q2, p1) / (O(q1, q2, p1) - O(q1, q2, p2)) along p1p2; doubles convert exactly.
  const mpq_class qx = mpq_class(q2.x) - q1.x, qy = mpq_class(q2.y) - q1.y;
  const mpq_class w1 = qx * (mpq_class(p1.y) - q1.y) - qy * (mpq_class(p1.x) - q1.x);
  const mpq_class w2 = qx * (mpq_class(p2.y) - q1.y) - qy * (mpq_class(p2.x) - q1.x);
  const mpq_class t = w1 / (w1 - w2);
  const mpq_class x = mpq_class(p1.x) + t * (mpq_class(p2.x) - p1.x);
  const mpq_class y = mpq_class(p1.y) + t * (mpq_class(p2.y) - p1.y);
  return {nearestDouble(x), nearestDouble(y)};
}

}  // namespace

Point constructCrossing(Point p1, Point p2, Point q1, Point q2) {
  if (kWideHasRange) {
    const Parameter s = parameter(determinant(q1, q2, p1), determinant(q1, q2, p2));
    const Parameter c = parameter(determinant(p1, p2, q1), determinant(p1, p2, q2));
    if (s.valid && c.valid) {
      // Each coordinate along the segment with the smaller extent in it (exact along an
      // axis-parallel segment), from its endpoint nearer to the crossing.
      auto coordinate = [&](double Point::*axis) {
        const bool alongP = std::abs(p2.*axis - p1.*axis) <= std::abs(q2.*axis - q1.*axis);
        const Point a = alongP ? p1 : q1, b = alongP ? p2 : q2;
        const Parameter& t = alongP ? s : c;
        return t.t <= t.oneMinusT ? interpolate(a.*axis, b.*axis, t.t, t.errT)
                                  : interpolate(b.*axis, a.*axis, t.oneMinusT, t.errOneMinusT);
      };
      Point out;
      if (certify(coordinate(&Point::x), out.x) && certify(coordinate(&Point::y), out.y)) return out;
    }
  }
  return exactCrossing(p1, p2, q1, q2);
}

}  // namespace gh::detail
