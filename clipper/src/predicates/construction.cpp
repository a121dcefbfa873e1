#include "predicates/construction.h"

#include <gmp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "predicates/error_free.h"
#include "predicates/exact_point.h"

namespace gh::detail {

namespace {

constexpr double kU2 = 0x1p-106;  // the square of double's unit roundoff u = 2^-53

// The double next to a finite nonzero d, away from zero (+1) or toward it (-1): adjacent doubles
// of one sign have adjacent bit patterns (nextafter without the library call).
double adjacent(double d, int away) {
  std::uint64_t bits;
  std::memcpy(&bits, &d, sizeof d);
  bits += static_cast<std::uint64_t>(static_cast<std::int64_t>(away));
  double out;
  std::memcpy(&out, &bits, sizeof out);
  return out;
}

// The two doubles next to a finite d.
void neighbours(double d, double& below, double& above) {
  if (d == 0) {
    below = -std::numeric_limits<double>::denorm_min(),
    above = std::numeric_limits<double>::denorm_min();
    return;
  }
  const double away = adjacent(d, +1), toward = adjacent(d, -1);
  if (d > 0)
    below = toward, above = away;
  else
    below = away, above = toward;
}

// The distance from a normal double d to its neighbour toward zero, the nearer of its two (they
// differ only at a power of two, where the one below is half as far). Exact: a power of two.
double gapAround(double d) {
  return std::abs(d - adjacent(d, -1));
}

// Is hi a faithful rounding of every value within `bound` of hi + lo? It is when that interval
// lies strictly between hi's two neighbours: |lo| + bound < gapAround(hi). The factor covers the
// rounding of the left side; the normal range keeps gapAround exact.
bool certify(TwoTerm v, double bound, double& out) {
  if (!(std::abs(v.hi) >= 0x1p-960 && std::abs(v.hi) <= 0x1p1000)) return false;  // also NaN
  if (!((std::abs(v.lo) + bound) * (1 + 0x1p-45) < gapAround(v.hi))) return false;
  out = v.hi;
  return true;
}

// The rationals of an exact construction, kept for the thread, as the integer stage keeps its
// integers: each fallback made and freed about 90 GMP blocks through temporaries of mpq_class,
// 63 % of the exact clip's allocations on the fuzz corpus (sampled stacks; there a crossing on an
// axis, at 0, or at an extreme magnitude cannot be certified in doubles), and under ASan each block
// costs more than the arithmetic. The same operations on the same values: the same exact results.
class Rationals {
 public:
  Rationals() {
    for (mpq_t* r : r_) mpq_init(*r);
    mpq_set_d(liftBelow_, 0x1p-1000);
  }
  ~Rationals() {
    for (mpq_t* r : r_) mpq_clear(*r);
  }
  Rationals(const Rationals&) = delete;
  Rationals& operator=(const Rationals&) = delete;

  // out = u - v for doubles (converted exactly).
  void difference(mpq_t out, double u, double v) {
    mpq_set_d(out, u);
    mpq_set_d(a_, v);
    mpq_sub(out, out, a_);
  }
  // out = ax * by - ay * bx for rationals ax, ay and differences of doubles by = b1 - b2, bx.
  void cross(mpq_t out, const mpq_t ax, const mpq_t ay, double by1, double by2, double bx1, double bx2) {
    difference(b_, by1, by2);
    mpq_mul(b_, ax, b_);
    difference(c_, bx1, bx2);
    mpq_mul(c_, ay, c_);
    mpq_sub(out, b_, c_);
  }
  // from + parameter (to - from), exactly.
  void along(mpq_t out, const mpq_t parameter, double from, double to) {
    difference(b_, to, from);
    mpq_mul(b_, parameter, b_);
    mpq_set_d(c_, from);
    mpq_add(out, c_, b_);
  }

  // The double nearest to v. mpq_get_d truncates and gives up below the normal range, so tiny
  // values are lifted by an exact power of two first; the truncated result is then within one
  // ulp, and the nearest of it and its two neighbours is chosen exactly (a tie keeps it).
  double nearest(const mpq_t v) {
    constexpr int kLift = 1100;
    double d;
    mpq_abs(a_, v);
    if (mpq_cmp(a_, liftBelow_) < 0) {
      mpq_mul_2exp(a_, v, kLift);
      d = std::ldexp(mpq_get_d(a_), -kLift);
    } else {
      d = mpq_get_d(v);
    }
    double best = d, below, above;
    distance(bestError_, v, d);
    neighbours(d, below, above);
    for (double c : {below, above}) {
      if (!std::isfinite(c)) continue;
      distance(b_, v, c);
      if (mpq_cmp(b_, bestError_) < 0) best = c, mpq_swap(bestError_, b_);
    }
    return best;
  }

  // The largest double at most v and the smallest at least v (one double when v is one).
  void bracket(const mpq_t v, double& below, double& above) {
    const double d = nearest(v);
    mpq_set_d(a_, d);
    const int c = mpq_cmp(v, a_);
    double down, up;
    neighbours(d, down, up);
    below = c < 0 ? down : d;
    above = c > 0 ? up : d;
  }

  mpq_t qx, qy, w1, w2, t, x, y;  // exactCrossing's named values

 private:
  // out = |v - c|.
  void distance(mpq_t out, const mpq_t v, double c) {
    mpq_set_d(out, c);
    mpq_sub(out, v, out);
    mpq_abs(out, out);
  }
  mpq_t a_, b_, c_, bestError_, liftBelow_;  // scratch, and the bound below which to lift
  // Every number above, for construction and destruction.
  mpq_t* const r_[12] = {&qx, &qy, &w1, &w2, &t, &x, &y, &a_, &b_, &c_, &bestError_, &liftBelow_};
};

// The exact crossing into r.x and r.y: t = O(q1, q2, p1) / (O(q1, q2, p1) - O(q1, q2, p2)) along
// p1p2; doubles convert exactly.
void exactCrossingRationals(Point p1, Point p2, Point q1, Point q2, Rationals& r) {
  r.difference(r.qx, q2.x, q1.x);
  r.difference(r.qy, q2.y, q1.y);
  r.cross(r.w1, r.qx, r.qy, p1.y, q1.y, p1.x, q1.x);  // qx (p1.y - q1.y) - qy (p1.x - q1.x)
  r.cross(r.w2, r.qx, r.qy, p2.y, q1.y, p2.x, q1.x);
  mpq_sub(r.t, r.w1, r.w2);
  mpq_div(r.t, r.w1, r.t);
  r.along(r.x, r.t, p1.x, p2.x);
  r.along(r.y, r.t, p1.y, p2.y);
}

Rationals& threadRationals() {
  thread_local Rationals r;
  return r;
}

Point exactCrossing(Point p1, Point p2, Point q1, Point q2, ExactCounters& counters) {
  ++counters.exactConstructions;
  Rationals& r = threadRationals();
  exactCrossingRationals(p1, p2, q1, q2, r);
  return {r.nearest(r.x), r.nearest(r.y)};
}

// A determinant L - R of two products of exact differences, as s + lo, and |L| + |R| rounded.
struct Determinant {
  double s, lo, magnitude;
};

// bx * ay - by * ax for differences given exactly as two terms each. Each product is hi * hi
// exactly (twoProduct) plus the cross terms rounded once; lo * lo is dropped (< u^2 |hi * hi|).
// |L - R - (s + lo)| <= 16 u^2 (|L| + |R|) and |lo| <= 4.3 u (|L| + |R|).
inline Determinant determinant(TwoTerm bx, TwoTerm by, TwoTerm ay, TwoTerm ax) {
  const TwoTerm l = twoProduct(bx.hi, ay.hi), r = twoProduct(by.hi, ax.hi);
  const double lc = std::fma(bx.hi, ay.lo, bx.lo * ay.hi),
               rc = std::fma(by.hi, ax.lo, by.lo * ax.hi);
  const TwoTerm s = twoSum(l.hi, -r.hi);
  return {s.hi, s.lo + ((l.lo - r.lo) + (lc - rc)), std::abs(l.hi) + std::abs(r.hi)};
}

// The crossing interpolated along a1a2 (b1b2 the other segment), if both coordinates certify.
// Double-double arithmetic: the differences exactly (twoDiff), the determinants w1 = s1 + lo1
// and w2 of a1 and a2 against line b1b2 (opposite signs), their difference d = ds + dl, the
// parameter t = th + tl = w1 / d (one division and a correction), and a1 + t (a2 - a1) as
// hi + lo. With S = the four products' magnitudes and k = S / |ds| (the condition: k is large
// for nearly parallel segments), while 2^-800 <= S <= 2^1010 and k <= 2^40 (nothing under- or
// overflows to matter; |d| >= |ds| / 2):
//   |w - W| <= 16 u^2 S,  |d - D| <= u^2 (25 S + |ds|),
//   |t - T| <= errT = 2^12 u^2 (1 + |th|) (1 + k)^2   (2^8 suffices: the rest covers the
//                                                         roundings of the bounds themselves),
//   |x - X| <= 3 errT |a2 - a1| + 2 u^2 |a1 + th (a2 - a1)|.
// These are about 2^-90 relative on ordinary input, far below the half ulp that certification
// needs. Compiled twice below: for fma, and for the base instruction set.
[[gnu::always_inline]] inline bool alongSegment(Point a1, Point a2, Point b1, Point b2,
                                                Point& out) {
  const TwoTerm bx = twoDiff(b2.x, b1.x), by = twoDiff(b2.y, b1.y);
  const Determinant w1 = determinant(bx, by, twoDiff(a1.y, b1.y), twoDiff(a1.x, b1.x));
  const Determinant w2 = determinant(bx, by, twoDiff(a2.y, b1.y), twoDiff(a2.x, b1.x));
  const TwoTerm d = twoSum(w1.s, -w2.s);
  const double ds = d.hi, dl = d.lo + (w1.lo - w2.lo);
  const double th = w1.s / ds;
  const double tl = (std::fma(-th, ds, w1.s) + (w1.lo - th * dl)) / ds;

  const double size = w1.magnitude + w2.magnitude, k = size / std::abs(ds);
  if (!(size >= 0x1p-800 && size <= 0x1p1010) || !(k <= 0x1p40)) return false;  // also NaN
  const double errT = 0x1p12 * kU2 * (1 + std::abs(th)) * (1 + k) * (1 + k);

  auto along = [&](double from, double to, double& coordinate) {
    const TwoTerm delta = twoDiff(to, from), p = twoProduct(th, delta.hi);
    const double pe = p.lo + std::fma(th, delta.lo, tl * delta.hi);
    const TwoTerm s = twoSum(from, p.hi);
    const TwoTerm x = twoSum(s.hi, s.lo + pe);
    return certify(x, 3 * errT * std::abs(delta.hi) + 2 * kU2 * std::abs(s.hi), coordinate);
  };
  const bool xCertified = along(a1.x, a2.x, out.x), yCertified = along(a1.y, a2.y, out.y);
  return xCertified && yCertified;
}

// alongSegment where fma is an instruction, and where it is a library call (the C library's fma
// is correctly rounded: the same bounds hold, slower).
using AlongSegment = bool (*)(Point, Point, Point, Point, Point&);
#if defined(__x86_64__) || defined(__i386__)
[[gnu::target("fma")]] bool alongSegmentFma(Point a1, Point a2, Point b1, Point b2, Point& out) {
  return alongSegment(a1, a2, b1, b2, out);
}
#endif
bool alongSegmentBase(Point a1, Point a2, Point b1, Point b2, Point& out) {
  return alongSegment(a1, a2, b1, b2, out);
}

AlongSegment fastestAlongSegment() {
#if defined(__x86_64__) || defined(__i386__)
  if (__builtin_cpu_supports("fma")) return alongSegmentFma;
#endif
  return alongSegmentBase;  // elsewhere fma is in the base instruction set, or a library call
}

// Along p first; along q when p cannot certify (a coordinate much nearer 0 than p's extent in it,
// e.g. the crossing of a long slanted edge with an axis, is interpolated exactly along an
// axis-parallel q).
bool certifiedCrossing(AlongSegment along, Point p1, Point p2, Point q1, Point q2, Point& out) {
  return along(p1, p2, q1, q2, out) || along(q1, q2, p1, p2, out);
}

// The same at a power-of-two scale 2^e for segments near the origin whose products underflow
// (every coordinate below 2^-300), if the result scales back exactly.
bool certifiedCrossingOfTinySegments(AlongSegment along, Point p1, Point p2, Point q1, Point q2,
                                     Point& out) {
  double largest = 0;
  for (const Point& v : {p1, p2, q1, q2})
    largest = std::max({largest, std::abs(v.x), std::abs(v.y)});
  if (!(largest > 0 && largest < 0x1p-300)) return false;
  // The largest coordinate to [1, 2): every scaled coordinate is exact.
  const int e = -std::ilogb(largest);
  auto up = [e](Point v) { return Point{std::ldexp(v.x, e), std::ldexp(v.y, e)}; };
  Point scaled;
  if (!certifiedCrossing(along, up(p1), up(p2), up(q1), up(q2), scaled)) return false;
  out = {std::ldexp(scaled.x, -e), std::ldexp(scaled.y, -e)};
  return std::ldexp(out.x, e) == scaled.x && std::ldexp(out.y, e) == scaled.y;
}

Point construct(AlongSegment along, Point p1, Point p2, Point q1, Point q2, ExactCounters& counters) {
  Point out;
  if (certifiedCrossing(along, p1, p2, q1, q2, out) ||
      certifiedCrossingOfTinySegments(along, p1, p2, q1, q2, out)) {
    return out;
  }
  return exactCrossing(p1, p2, q1, q2, counters);
}

}  // namespace

Point constructCrossing(Point p1, Point p2, Point q1, Point q2, ExactCounters& counters) {
  static const AlongSegment along = fastestAlongSegment();
  return construct(along, p1, p2, q1, q2, counters);
}

CrossingRoundings crossingRoundings(Point p1, Point p2, Point q1, Point q2) {
  Rationals& r = threadRationals();
  exactCrossingRationals(p1, p2, q1, q2, r);
  CrossingRoundings out;
  r.bracket(r.x, out.x0, out.x1);
  r.bracket(r.y, out.y0, out.y1);
  return out;
}

Point constructCrossingWithoutFmaInstruction(Point p1, Point p2, Point q1, Point q2, ExactCounters& counters) {
  return construct(alongSegmentBase, p1, p2, q1, q2, counters);
}

}  // namespace gh::detail

namespace gh::detail {

ExactPoint exactCrossingPoint(Point p1, Point p2, Point q1, Point q2) {
  const mpq_class qx = mpq_class(q2.x) - q1.x, qy = mpq_class(q2.y) - q1.y;
  const mpq_class w1 = qx * (mpq_class(p1.y) - q1.y) - qy * (mpq_class(p1.x) - q1.x);
  const mpq_class w2 = qx * (mpq_class(p2.y) - q1.y) - qy * (mpq_class(p2.x) - q1.x);
  const mpq_class t = w1 / (w1 - w2);
  return {p1.x + t * (mpq_class(p2.x) - p1.x), p1.y + t * (mpq_class(p2.y) - p1.y)};
}

double nearestDouble(const mpq_class& v) {
  double below, above;
  threadRationals().bracket(v.get_mpq_t(), below, above);
  if (below == above) return below;
  const mpq_class toBelow = v - below, toAbove = mpq_class(above) - v;
  if (toBelow != toAbove) return toBelow < toAbove ? below : above;
  std::uint64_t bits;
  std::memcpy(&bits, &below, sizeof bits);
  return bits % 2 == 0 ? below : above;  // a tie: the even significand
}

}  // namespace gh::detail
