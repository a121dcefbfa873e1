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
// The bounds below assume the x87 extended format: a 64-bit significand, and an exponent range in
// which no product of two doubles under- or overflows. Elsewhere (long double = double) every
// point takes the exact path.
constexpr bool kWideIsExtended = std::numeric_limits<Wide>::digits >= 64 &&
                                 std::numeric_limits<Wide>::max_exponent >= 4096 &&
                                 std::numeric_limits<Wide>::min_exponent <= -4096;
constexpr double kUW = 0x1p-64;  // unit roundoff of Wide (when kWideIsExtended)
// Error bounds are computed in doubles from double-rounded terms, beside the Wide chain. Each
// bound below is the Wide analysis' bound; this factor covers, with room to spare, what the
// doubles lose against it: a dozen roundings of at most 2^-53 each, and products that underflow
// (at most 2^-1075 each, negligible under the guard s >= 2^-900).
constexpr double kSlack = 1 + 0x1p-45;

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

// The distance from a normal double d to its neighbour toward zero, the nearer of its two (they
// differ only at a power of two, where the one below is half as far). Exact: a power of two.
double gapAround(double d) {
  std::uint64_t bits;
  std::memcpy(&bits, &d, sizeof d);
  const std::uint64_t toward = bits - 1;
  double t;
  std::memcpy(&t, &toward, sizeof t);
  return std::abs(d - t);
}

// Is d = double(v) a faithful rounding of every value in [v - bound, v + bound]? It is when the
// interval lies strictly between d's two neighbours: |v - d| + bound < gapAround(d). v - d is
// exact in Wide (the bits of v below d's last place) and in double (at most 11 bits, and no
// smaller than 2^-1023 when |d| >= 2^-960).
bool certify(Wide v, double bound, double& out) {
  const double d = static_cast<double>(v);
  const double r = static_cast<double>(v - Wide(d));
  if (!(std::abs(d) >= 0x1p-960 && std::abs(d) <= 0x1p1000)) return false;  // also NaN
  if (!((std::abs(r) + bound) * kSlack < gapAround(d))) return false;
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
// In Wide: the determinants w1, w2 of a1 and a2 against line b1b2 (opposite signs), d = w1 - w2,
// t = w1 / d, and a1 + t (a2 - a1). Their error bounds, in doubles:
//   |w - W| <= e = (3 + 16u) u S for both, S the sum of the four products' magnitudes
//     (Shewchuk's stage-A bound, u = 2^-64);
//   |d - D| <= ed = 2e + u |d|, and with ed <= |d| / 2,
//   |t - T| <= errT = 2 (e + |t| ed) / |d| + 2u |t|  (|w1/d - T| <= (e + |w1/d| ed) / (|d| - ed));
//   |x - X| <= (errT + 2u |t|) |a2 - a1| + u |x|    (the difference, product and sum rounded).
// The Wide chain has no branch and few operations (x87 instructions are the cost here); the
// bounds run beside it on the SSE units.
bool alongSegment(Point a1, Point a2, Point b1, Point b2, Point& out) {
  const double bxd = b2.x - b1.x, byd = b2.y - b1.y;
  const double s = std::abs(bxd * (a1.y - b1.y)) + std::abs(byd * (a1.x - b1.x)) +
                   std::abs(bxd * (a2.y - b1.y)) + std::abs(byd * (a2.x - b1.x));
  const double e = (3 + 0x1p-40) * kUW * s * kSlack;

  const Wide bx = Wide(b2.x) - b1.x, by = Wide(b2.y) - b1.y;
  const Wide w1 = bx * (Wide(a1.y) - b1.y) - by * (Wide(a1.x) - b1.x);
  const Wide w2 = bx * (Wide(a2.y) - b1.y) - by * (Wide(a2.x) - b1.x);
  const Wide d = w1 - w2;
  const Wide t = w1 / d;

  const double ad = std::abs(static_cast<double>(d)), at = std::abs(static_cast<double>(t));
  const double ed = (2 * e + kUW * ad) * kSlack;
  const double errT = (2 * (e + at * ed) / ad + 2 * kUW * at) * kSlack * kSlack;
  if (!(s >= 0x1p-900 && s <= 0x1p1010) || !(2 * ed * kSlack <= ad) || !(errT < 1)) return false;  // also NaN

  const Wide x = a1.x + t * (Wide(a2.x) - a1.x), y = a1.y + t * (Wide(a2.y) - a1.y);
  const double errStep = errT + 2 * kUW * at;
  const double boundX = (errStep * std::abs(a2.x - a1.x) * kSlack + kUW * std::abs(static_cast<double>(x))) * kSlack;
  const double boundY = (errStep * std::abs(a2.y - a1.y) * kSlack + kUW * std::abs(static_cast<double>(y))) * kSlack;
  return certify(x, boundX, out.x) & certify(y, boundY, out.y);
}

}  // namespace

Point constructCrossing(Point p1, Point p2, Point q1, Point q2) {
  Point out;
  // Along p first; along q when p cannot certify (a coordinate much nearer 0 than p's extent in
  // it, e.g. the crossing of a long slanted edge with an axis, is interpolated exactly along an
  // axis-parallel q).
  if (kWideIsExtended && (alongSegment(p1, p2, q1, q2, out) || alongSegment(q1, q2, p1, p2, out))) return out;
  return exactCrossing(p1, p2, q1, q2);
}

}  // namespace gh::detail
