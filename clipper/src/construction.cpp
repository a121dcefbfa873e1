#include "construction.h"

#include <gmpxx.h>

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

// A coordinate with a bound on its error: [value - bound, value + bound] holds the exact one.
struct Enclosure {
  Wide value, bound;
};

// from + t * (to - from) with |t - t_exact| <= errT: value and error bound. The product and the
// difference are rounded once each, the sum once: |error| <= errT |delta| + 2u t |delta| + u |value|
// (to first order; the last factor covers the rest).
Enclosure interpolate(double from, double to, Wide t, Wide errT) {
  const Wide delta = Wide(to) - from;
  const Wide value = from + t * delta;
  return {value, ((errT + 2 * kU * std::abs(t)) * std::abs(delta) + kU * std::abs(value)) * (1 + 8 * kU)};
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
  if (!std::isfinite(d)) return false;
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
  double best = d, below, above;
  mpq_class bestError = abs(v - mpq_class(d));
  neighbours(d, below, above);
  for (double c : {below, above}) {
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

// The crossing interpolated along a1a2 (b1b2 the other segment), if both coordinates certify.
// The determinants w1, w2 of a1 and a2 against line b1b2 (opposite signs) share one stage-A
// bound e in Wide, (3 + 16u) u (|l1| + |r1| + |l2| + |r2|); t = w1 / (w1 - w2) with
// |t - T| <= (e + t e_d) / (|d| - e_d), where 1 / (|d| - e_d) is taken as 2 / |d| (loose by at
// most 2, which the 11 extra bits of Wide absorb; it saves a division). No branch depends on the
// data until the certificate: they would be mispredicted half the time.
bool alongSegment(Point a1, Point a2, Point b1, Point b2, Point& out) {
  constexpr Wide kDet = (3 + 16 * kU) * kU;
  const Wide bx = Wide(b2.x) - b1.x, by = Wide(b2.y) - b1.y;
  const Wide l1 = bx * (Wide(a1.y) - b1.y), r1 = by * (Wide(a1.x) - b1.x);
  const Wide l2 = bx * (Wide(a2.y) - b1.y), r2 = by * (Wide(a2.x) - b1.x);
  const Wide w1 = l1 - r1, w2 = l2 - r2;
  const Wide e = kDet * (std::abs(l1) + std::abs(r1) + std::abs(l2) + std::abs(r2));
  const Wide d = w1 - w2, ad = std::abs(d);
  const Wide ed = 2 * e + kU * ad;
  const Wide inverse = 1 / d;
  const Wide t = w1 * inverse;
  const Wide err = ((e + std::abs(t) * ed) * 2 * std::abs(inverse) + 2 * kU * std::abs(t)) * (1 + 8 * kU);
  if (!(2 * ed <= ad) || !(err < 1)) return false;  // also NaN
  return certify(interpolate(a1.x, a2.x, t, err), out.x) && certify(interpolate(a1.y, a2.y, t, err), out.y);
}

}  // namespace

Point constructCrossing(Point p1, Point p2, Point q1, Point q2) {
  Point out;
  // Along p first; along q when p cannot certify (a coordinate much nearer 0 than p's extent in
  // it, e.g. the crossing of a long slanted edge with an axis, is interpolated exactly along an
  // axis-parallel q).
  if (kWideHasRange && (alongSegment(p1, p2, q1, q2, out) || alongSegment(q1, q2, p1, p2, out))) return out;
  return exactCrossing(p1, p2, q1, q2);
}

}  // namespace gh::detail
