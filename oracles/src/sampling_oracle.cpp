#include "ghoracle/sampling_oracle.h"

#include <gmpxx.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <functional>
#include <random>
#include <vector>

#include "judging_scale.h"

namespace gh::oracle {
namespace {

struct Box {
  double minX = std::numeric_limits<double>::infinity(), minY = minX;
  double maxX = -std::numeric_limits<double>::infinity(), maxY = maxX;
  void grow(const Region& r) {
    for (const Ring& ring : r) {
      for (const Point& p : ring) {
        minX = std::min(minX, p.x), maxX = std::max(maxX, p.x);
        minY = std::min(minY, p.y), maxY = std::max(maxY, p.y);
      }
    }
  }
};

// Sign of (b - a) x (p - a), exactly: Shewchuk's filter in doubles, GMP when it cannot decide
// (or when a difference overflows or a product underflows).
int orientation(Point a, Point b, Point p) {
  const double l = (b.x - a.x) * (p.y - a.y), r = (b.y - a.y) * (p.x - a.x);
  const double det = l - r, magnitude = std::abs(l) + std::abs(r);
  if (std::isfinite(magnitude) && magnitude > 0x1p-900 && std::abs(det) > 0x1.0000000000002p-51 * magnitude) {
    return det > 0 ? 1 : -1;
  }
  const mpq_class bx(b.x), by(b.y), ax(a.x), ay(a.y), px(p.x), py(p.y);
  const mpq_class exact = (bx - ax) * (py - ay) - (by - ay) * (px - ax);
  return sgn(exact);
}

// Whether |(b - a) x (p - a)| <= bound, i.e. p is within bound / |b - a| of the line ab: in
// doubles when the rounding cannot matter, else in GMP (p near the origin and a, b at 1e144
// would cancel to noise).
bool lineDistanceAtMost(Point a, Point b, Point p, double bound) {
  const double l = (b.x - a.x) * (p.y - a.y), r = (b.y - a.y) * (p.x - a.x);
  const double det = std::abs(l - r), error = 0x1.0000000000002p-51 * (std::abs(l) + std::abs(r));
  if (std::isfinite(det) && std::isfinite(error) && std::abs(l) + std::abs(r) > 0x1p-900) {
    if (det + error <= bound) return true;
    if (det - error > bound) return false;
  }
  const mpq_class bx(b.x), by(b.y), ax(a.x), ay(a.y), px(p.x), py(p.y);
  const mpq_class exact = (bx - ax) * (py - ay) - (by - ay) * (px - ax);
  return abs(exact) <= mpq_class(bound);
}

// Even-odd parity of a rightward ray from p, exactly; nullopt when p lies on an edge (on the
// boundary, inside and outside are a convention, not an answer).
std::optional<bool> inside(const Region& region, Point p) {
  bool in = false;
  for (const Ring& ring : region) {
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      const Point& a = ring[i];
      const Point& b = ring[(i + 1) % n];
      if (p.y < std::min(a.y, b.y) || p.y > std::max(a.y, b.y)) continue;
      const bool crosses = (a.y > p.y) != (b.y > p.y);
      if (!crosses && (p.x < std::min(a.x, b.x) || p.x > std::max(a.x, b.x))) continue;
      const int o = orientation(a, b, p);
      if (o == 0 && p.x >= std::min(a.x, b.x) && p.x <= std::max(a.x, b.x)) return std::nullopt;
      // The edge crosses p's horizontal line to the right of p when p is on its left going
      // upward (on its right going downward).
      if (crosses && (b.y > a.y ? o > 0 : o < 0)) in = !in;
    }
  }
  return in;
}

// The edges of S and C, with what a point near one needs to know: how far from it a correct
// answer may legitimately disagree. The exact oracle's rounding zone along a line of S or C
// (exact_oracle.h) is the hull of the rounding boxes of every crossing on it, whether or not the
// exact answer has a boundary there (two rings of a candidate may run along an edge in opposite
// directions, one through a rounded crossing and one straight past it). So the delta near an
// edge is that of its largest crossing: a unit square crossed by a 1e15-long edge is judged at
// the unit square's resolution, unless that edge also crosses something at 1e15.
class OperandEdges {
 public:
  OperandEdges(const Region& s, const Region& c, int ulps, double ulpFloor) : ulps_(ulps), ulpFloor_(ulpFloor) {
    for (const Region* r : {&s, &c}) {
      for (const Ring& ring : *r) {
        for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
          if (ring[i] != ring[(i + 1) % n]) edges_.push_back({ring[i], ring[(i + 1) % n], -1});
        }
      }
    }
  }

  // Whether p is within the local delta of an edge.
  bool near(Point p) {
    for (Edge& e : edges_) {
      const double coarse = deltaAt(magnitude(e.a, e.b));  // a bound on e's delta
      if (p.x < std::min(e.a.x, e.b.x) - coarse || p.x > std::max(e.a.x, e.b.x) + coarse ||
          p.y < std::min(e.a.y, e.b.y) - coarse || p.y > std::max(e.a.y, e.b.y) + coarse) {
        continue;
      }
      if (e.largest < 0) e.largest = largestCrossing(e);
      const double delta = deltaAt(e.largest);
      largest_ = std::max(largest_, delta);
      const double dx = e.b.x - e.a.x, dy = e.b.y - e.a.y, length = std::hypot(dx, dy);
      const double t = along(e, p);
      const bool within = t > 0 && t < 1 ? lineDistanceAtMost(e.a, e.b, p, delta * length)
                                         : std::min(std::hypot(p.x - e.a.x, p.y - e.a.y),
                                                    std::hypot(p.x - e.b.x, p.y - e.b.y)) <= delta;
      if (within) return true;
    }
    return false;
  }

  double largestDelta() const { return largest_; }

 private:
  struct Edge {
    Point a, b;
    double largest;  // a bound on max(|x|, |y|) of its crossings; -1 until first needed
  };

  static double magnitude(Point a) { return std::max(std::abs(a.x), std::abs(a.y)); }
  static double magnitude(Point a, Point b) { return std::max(magnitude(a), magnitude(b)); }
  double deltaAt(double m) const {
    const double ulp = std::nextafter(m, std::numeric_limits<double>::infinity()) - m;
    return (2 * ulps_ + 6) * std::max(ulp, ulpFloor_);
  }

  // Where along e a point q projects (clamped to e).
  static double along(const Edge& e, Point q) {
    const double dx = e.b.x - e.a.x, dy = e.b.y - e.a.y;
    return std::clamp(((q.x - e.a.x) * dx + (q.y - e.a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  }

  // The largest proper crossing of e with another operand edge, decided exactly. A crossing
  // lies on both edges, so the smaller edge's coordinates bound its magnitude: nothing cancels
  // when a 1e144-long edge crosses a 1e-15 one. Meetings at input vertices need no rounding.
  double largestCrossing(const Edge& e) const {
    double largest = 0;
    for (const Edge& o : edges_) {
      if (&o == &e) continue;
      const int oa = orientation(e.a, e.b, o.a), ob = orientation(e.a, e.b, o.b);
      if (oa * ob >= 0) continue;
      const int ea = orientation(o.a, o.b, e.a), eb = orientation(o.a, o.b, e.b);
      if (ea * eb >= 0) continue;
      largest = std::max(largest, std::min(magnitude(e.a, e.b), magnitude(o.a, o.b)));
    }
    return largest;
  }

  int ulps_;
  double ulpFloor_;
  double largest_ = 0;
  std::vector<Edge> edges_;
};

// The check proper, on a problem at a comfortable scale; ulpFloor is the original's smallest
// ulp at this scale.
SampleVerdict sample(const Region& subject, const Region& clip, Op op, const Region& result,
                     const SampleOptions& options, double ulpFloor) {
  const auto start = std::chrono::steady_clock::now();
  SampleVerdict v;
  Box box;
  box.grow(subject), box.grow(clip), box.grow(result);
  if (!(box.minX <= box.maxX)) return v;  // everything empty: nothing to check
  // Halves first: the extent of coordinates near 2^500 must not overflow.
  const double extent = std::max({(box.maxX / 2 - box.minX / 2) * 2, (box.maxY / 2 - box.minY / 2) * 2,
                                  std::numeric_limits<double>::min()});

  OperandEdges operandEdges(subject, clip, options.constructionUlps, ulpFloor);
  auto check = [&](Point p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
    if (operandEdges.near(p)) {
      ++v.skipped;
      return;
    }
    const auto r = inside(result, p), a = inside(subject, p), b = inside(clip, p);
    if (!r || !a || !b) {
      ++v.skipped;
      return;
    }
    ++v.checked;
    if (*r != apply(op, *a, *b)) {
      if (!v.mismatched) v.firstMismatch = p;
      ++v.mismatched;
    }
  };

  std::mt19937_64 rng(options.seed);
  std::uniform_real_distribution<double> ux(box.minX, box.maxX), uy(box.minY, box.maxY);
  for (std::size_t i = 0; i < options.uniformPoints; ++i) check({ux(rng), uy(rng)});
  if (options.nearVertices) {
    const double pi = std::acos(-1.0);
    std::uniform_real_distribution<double> turn(0, 2 * pi);
    for (const Region* region : {&subject, &clip, &result}) {
      for (const Ring& ring : *region) {
        for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
          const Point& q = ring[i];
          const Point& prev = ring[(i + n - 1) % n];
          const Point& next = ring[(i + 1) % n];
          // The vertex's own scale: its shorter non-zero edge.
          double local = std::numeric_limits<double>::infinity();
          for (const Point& o : {prev, next}) {
            const double length = std::hypot(o.x / 2 - q.x / 2, o.y / 2 - q.y / 2) * 2;
            if (length > 0) local = std::min(local, length);
          }
          const double phase = turn(rng);
          // Both ways along the bisector of the vertex's corner too: a thin spike (a ring of a
          // 1e-10 star tip) lies between two of the eight rays, never across the bisector.
          const double ux = prev.x / 2 - q.x / 2, uy = prev.y / 2 - q.y / 2;
          const double wx = next.x / 2 - q.x / 2, wy = next.y / 2 - q.y / 2;
          const double lu = std::hypot(ux, uy), lw = std::hypot(wx, wy);
          double bx = 0, by = 0;
          if (lu > 0 && lw > 0) {
            bx = ux / lu + wx / lw, by = uy / lu + wy / lw;
            const double lb = std::hypot(bx, by);
            if (lb > 1e-9) {
              bx /= lb, by /= lb;
            } else {  // a straight corner: across the edge
              bx = -uy / lu, by = ux / lu;
            }
          }
          auto around = [&](double radius) {
            for (int k = 0; k < 8; ++k) {
              const double a = phase + k * pi / 4;
              check({q.x + radius * std::cos(a), q.y + radius * std::sin(a)});
            }
            if (bx != 0 || by != 0) {
              check({q.x + radius * bx, q.y + radius * by});
              check({q.x - radius * bx, q.y - radius * by});
            }
          };
          for (int e : {8, 14, 20, 26}) around(std::ldexp(extent, -e));
          if (std::isfinite(local)) {
            for (int e : {2, 5, 10, 20}) around(std::ldexp(local, -e));
          }
        }
      }
    }
  }
  v.delta = operandEdges.largestDelta();
  v.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return v;
}

}  // namespace

SampleVerdict sampleCheck(const Region& subject, const Region& clip, Op op, const Region& result,
                          const SampleOptions& options) {
  const double denormMin = std::numeric_limits<double>::denorm_min();
  const int k = judgingExponent(subject, clip, result);
  if (k == 0) return sample(subject, clip, op, result, options, denormMin);
  // Scaled from subnormal coordinates, the original's rounding grid becomes coarse there: its
  // smallest ulp, denorm_min, is 2^k * denorm_min at this scale.
  SampleVerdict v = sample(scaledBy(subject, k), scaledBy(clip, k), op, scaledBy(result, k), options,
                           std::ldexp(denormMin, std::max(k, 0)));
  v.delta = std::ldexp(v.delta, -k);
  if (v.firstMismatch) v.firstMismatch = scaledBy(*v.firstMismatch, -k);
  return v;
}

}  // namespace gh::oracle
