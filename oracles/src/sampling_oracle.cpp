#include "ghoracle/sampling_oracle.h"

#include <gmpxx.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <functional>
#include <random>
#include <vector>

#include "exact_orientation.h"
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

// Which of n equal buckets over [lo, hi] holds v, clamped to the ends: a monotone function of
// v, so that everything stored under the buckets of [a, b] is found from any v in [a, b]. A
// zero-width range (NaN) puts everything in bucket 0.
std::size_t bucket(double v, double lo, double hi, std::size_t n) {
  const double f = (v - lo) / (hi - lo) * static_cast<double>(n);
  if (!(f > 0)) return 0;
  return std::min(n - 1, static_cast<std::size_t>(f));
}

// A region's edges in horizontal bands, so that a ray test visits only the edges whose y-range
// can hold the point's y (every other edge lies wholly above or below it and cannot count). The
// band of a y is a monotone function of y, so an edge with ymin <= y <= ymax is always found.
class EvenOddRegion {
 public:
  explicit EvenOddRegion(const Region& region) {
    for (const Ring& ring : region) {
      for (std::size_t i = 0, n = ring.size(); i < n; ++i) edges_.push_back({ring[i], ring[(i + 1) % n]});
    }
    if (edges_.empty()) return;
    minY_ = maxY_ = edges_[0].a.y;
    for (const Edge& e : edges_) {
      minY_ = std::min({minY_, e.a.y, e.b.y}), maxY_ = std::max({maxY_, e.a.y, e.b.y});
    }
    // Bands: about one per 4 edges, fewer while long edges would be copied into too many.
    for (bands_ = std::clamp<std::size_t>(edges_.size() / 4, 1, 4096);; bands_ /= 2) {
      std::size_t copies = 0;
      for (const Edge& e : edges_) copies += band(std::max(e.a.y, e.b.y)) - band(std::min(e.a.y, e.b.y)) + 1;
      if (copies <= 16 * edges_.size() || bands_ == 1) break;
    }
    start_.assign(bands_ + 1, 0);
    for (const Edge& e : edges_) {
      for (std::size_t k = band(std::min(e.a.y, e.b.y)), last = band(std::max(e.a.y, e.b.y)); k <= last; ++k) ++start_[k + 1];
    }
    for (std::size_t k = 0; k < bands_; ++k) start_[k + 1] += start_[k];
    members_.resize(start_[bands_]);
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for (std::uint32_t i = 0; i < edges_.size(); ++i) {
      const Edge& e = edges_[i];
      for (std::size_t k = band(std::min(e.a.y, e.b.y)), last = band(std::max(e.a.y, e.b.y)); k <= last; ++k) members_[fill[k]++] = i;
    }
  }

  // Even-odd parity of a rightward ray from p, exactly; nullopt when p lies on an edge (on the
  // boundary, inside and outside are a convention, not an answer).
  std::optional<bool> inside(Point p) const {
    if (edges_.empty() || !(p.y >= minY_ && p.y <= maxY_)) return false;
    bool in = false;
    const std::size_t k = band(p.y);
    for (std::size_t m = start_[k]; m < start_[k + 1]; ++m) {
      const Point& a = edges_[members_[m]].a;
      const Point& b = edges_[members_[m]].b;
      if (p.y < std::min(a.y, b.y) || p.y > std::max(a.y, b.y)) continue;
      const bool crosses = (a.y > p.y) != (b.y > p.y);
      if (!crosses && (p.x < std::min(a.x, b.x) || p.x > std::max(a.x, b.x))) continue;
      if (crosses && p.x > std::max(a.x, b.x)) continue;  // crosses p's line left of p
      const int o = orientation(a, b, p);
      if (o == 0 && p.x >= std::min(a.x, b.x) && p.x <= std::max(a.x, b.x)) return std::nullopt;
      // The edge crosses p's horizontal line to the right of p when p is on its left going
      // upward (on its right going downward).
      if (crosses && (b.y > a.y ? o > 0 : o < 0)) in = !in;
    }
    return in;
  }

 private:
  struct Edge {
    Point a, b;
  };
  std::size_t band(double y) const { return bucket(y, minY_, maxY_, bands_); }
  std::vector<Edge> edges_;
  double minY_ = 0, maxY_ = 0;
  std::size_t bands_ = 1;
  std::vector<std::size_t> start_;
  std::vector<std::uint32_t> members_;
};

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
    index();
  }

  // Whether p is within the local delta of an edge.
  bool near(Point p) {
    if (edges_.empty()) return false;
    const std::size_t k = cell(p.x, p.y);
    for (std::size_t m = start_[k]; m < start_[k + 1]; ++m) {
      Edge& e = edges_[members_[m]];
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

  // A uniform grid over the edges' boxes, each widened by its coarse delta: an edge is listed
  // in every cell its widened box meets, and a point's cell (clamped to the grid, by the same
  // monotone function) lists every edge whose widened box holds it.
  std::size_t axis(double v, double lo, double hi) const { return bucket(v, lo, hi, side_); }
  std::size_t cell(double x, double y) const { return axis(y, y0_, y1_) * side_ + axis(x, x0_, x1_); }
  void index() {
    if (edges_.empty()) return;
    struct Box {
      double x0, x1, y0, y1;
    };
    std::vector<Box> boxes;
    x0_ = y0_ = std::numeric_limits<double>::infinity(), x1_ = y1_ = -x0_;
    for (const Edge& e : edges_) {
      const double coarse = deltaAt(magnitude(e.a, e.b));
      boxes.push_back({std::min(e.a.x, e.b.x) - coarse, std::max(e.a.x, e.b.x) + coarse,
                       std::min(e.a.y, e.b.y) - coarse, std::max(e.a.y, e.b.y) + coarse});
      x0_ = std::min(x0_, boxes.back().x0), x1_ = std::max(x1_, boxes.back().x1);
      y0_ = std::min(y0_, boxes.back().y0), y1_ = std::max(y1_, boxes.back().y1);
    }
    auto copies = [&] {
      std::size_t n = 0;
      for (const Box& b : boxes) n += (axis(b.x1, x0_, x1_) - axis(b.x0, x0_, x1_) + 1) * (axis(b.y1, y0_, y1_) - axis(b.y0, y0_, y1_) + 1);
      return n;
    };
    // About one cell per 2 edges, fewer while long edges would be copied into too many cells.
    for (side_ = std::clamp<std::size_t>(static_cast<std::size_t>(std::sqrt(edges_.size() / 2.0)), 1, 1024);
         side_ > 1 && copies() > 16 * edges_.size(); side_ /= 2) {
    }
    start_.assign(side_ * side_ + 1, 0);
    auto forCells = [&](const Box& b, auto&& f) {
      for (std::size_t cy = axis(b.y0, y0_, y1_), ly = axis(b.y1, y0_, y1_); cy <= ly; ++cy) {
        for (std::size_t cx = axis(b.x0, x0_, x1_), lx = axis(b.x1, x0_, x1_); cx <= lx; ++cx) f(cy * side_ + cx);
      }
    };
    for (const Box& b : boxes) forCells(b, [&](std::size_t k) { ++start_[k + 1]; });
    for (std::size_t k = 0; k + 1 < start_.size(); ++k) start_[k + 1] += start_[k];
    members_.resize(start_.back());
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for (std::uint32_t i = 0; i < boxes.size(); ++i) forCells(boxes[i], [&](std::size_t k) { members_[fill[k]++] = i; });
  }

  int ulps_;
  double ulpFloor_;
  double largest_ = 0;
  std::vector<Edge> edges_;
  double x0_ = 0, x1_ = 0, y0_ = 0, y1_ = 0;
  std::size_t side_ = 1;
  std::vector<std::size_t> start_;
  std::vector<std::uint32_t> members_;
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
  const EvenOddRegion inS(subject), inC(clip), inR(result);
  auto check = [&](Point p) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return;
    if (operandEdges.near(p)) {
      ++v.skipped;
      return;
    }
    const auto r = inR.inside(p), a = inS.inside(p), b = inC.inside(p);
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
