#include "ghoracle/sampling_oracle.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <limits>
#include <functional>
#include <random>
#include <tuple>
#include <vector>

#include "even_odd_regions.h"
#include "ghoracle/exact_orientation.h"
#include "filtered_orientation.h"
#include "judging_scale.h"
#include "line_distance.h"
#include "ghoracle/mix_bits.h"
#include "point_hash.h"
#include "point_table.h"
#include "segment_grid.h"
#include "pooled_vector.h"
#include "ulp.h"
#include "uniform_bucket.h"
#include "uniform_double.h"
#include "uniform_grid.h"

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
  bool holds(Point p) const { return p.x >= minX && p.x <= maxX && p.y >= minY && p.y <= maxY; }
  bool holds(const Box& b) const { return b.minX >= minX && b.maxX <= maxX && b.minY >= minY && b.maxY <= maxY; }
};

// count points drawn uniformly over a box (x, then y, from one generator seeded so), the finite
// ones handed to f.
template <class F>
void forUniformPoints(const Box& box, std::uint64_t seed, std::size_t count, F&& f) {
  std::mt19937_64 rng(seed);
  for (std::size_t i = 0; i < count; ++i) {
    const double x = uniformIn(rng, box.minX, box.maxX);
    const Point p{x, uniformIn(rng, box.minY, box.maxY)};
    if (std::isfinite(p.x) && std::isfinite(p.y)) f(p);
  }
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
          const Point a = ring[i], b = ring[(i + 1) % n];
          if (a == b) continue;
          edges_.push_back({a, b, deltaAt(magnitude(a, b)), -1, 0, 0});
          largestCoarse_ = std::max(largestCoarse_, edges_.back().coarse);
        }
      }
    }
    index();
  }

  // Whether p is within the local delta of an edge.
  bool near(Point p) {
    return anyEdgeAround(p, [&](const Edge& e) {
      largest_ = std::max(largest_, e.delta);
      // Farther than delta from the edge's line is farther from every point of it: most
      // candidates end here, before the division that finds where p projects.
      if (!lineDistanceAtMost(e.a, e.b, p, e.delta * e.length)) return false;
      const double t = along(e, p);
      return (t > 0 && t < 1) || std::min(std::hypot(p.x - e.a.x, p.y - e.a.y), std::hypot(p.x - e.b.x, p.y - e.b.y)) <= e.delta;
    });
  }

  // The edges, in order (edges of zero length left out: they cut nothing).
  PooledVector<std::pair<Point, Point>> segments() const {
    PooledVector<std::pair<Point, Point>> out;
    for (const Edge& e : edges_) out.push_back({e.a, e.b});
    return out;
  }

  // Whether edge i's line passes within a quarter of its delta of q (d: q's distance from it in
  // doubles, for a cheap first look), and `rounding` (the error of a point computed near q) is
  // within another quarter. Then a point near q that lies on the other side of that line from a
  // point farther out in the same direction is within half the delta of it (the signed distance
  // is affine along the direction): skipped by near(), like the points beside an edge that runs
  // through q exactly.
  bool passesNear(std::size_t i, Point q, double d, double rounding) {
    Edge& e = edges_[i];
    if (!(d <= e.coarse)) return false;  // d is within a few ulps; delta / 4 <= coarse / 4
    settle(e);
    if (!(rounding <= e.delta / 4)) return false;
    return lineDistanceAtMost(e.a, e.b, q, e.delta / 4 * e.length);
  }

  // Whether an edge passes through q in the sense of passesNear (q projecting strictly inside
  // it), and the segment ab runs along it: a and b within an eighth of its delta of its line. Then
  // ab's line passes within 3/8 of the delta of q, and a point near q that lies on the other side
  // of ab from a point farther out in the same direction is within half the delta of that edge's
  // line, within 3/4 of it as computed: skipped by near(), like the points beside the edge.
  bool carries(Point q, Point a, Point b, double rounding) {
    return anyEdgeAround(q, [&](const Edge& e) {
      if (!(rounding <= e.delta / 4)) return false;
      const double t = along(e, q);
      return t > 0 && t < 1 && lineDistanceAtMost(e.a, e.b, q, e.delta / 4 * e.length) &&
             lineDistanceAtMost(e.a, e.b, a, e.delta / 8 * e.length) && lineDistanceAtMost(e.a, e.b, b, e.delta / 8 * e.length);
    });
  }

  double largestDelta() const { return largest_; }
  // The largest delta any edge can have: a bound on every delta met.
  double largestCoarseDelta() const { return largestCoarse_; }

 private:
  struct Box {
    double x0, x1, y0, y1;
  };
  struct Member : Box {
    std::uint32_t edge;
  };
  struct Edge {
    Point a, b;
    double coarse;   // the delta of its own magnitude: a bound on its delta
    double largest;  // a bound on max(|x|, |y|) of its crossings; -1 until first needed, then
    double delta;    // the delta of that and
    double length;   // its length
  };

  // Whether test(e) holds for an edge e (settled) whose box, widened by its coarse delta, holds p.
  template <class Test>
  bool anyEdgeAround(Point p, Test&& test) {
    if (edges_.empty()) return false;
    const std::size_t k = cell(p.x, p.y);
    for (std::size_t m = start_[k]; m < start_[k + 1]; ++m) {
      const Member& box = members_[m];
      if (p.x < box.x0 || p.x > box.x1 || p.y < box.y0 || p.y > box.y1) continue;
      Edge& e = edges_[box.edge];
      settle(e);
      if (test(static_cast<const Edge&>(e))) return true;
    }
    return false;
  }

  static double magnitude(Point a) { return std::max(std::abs(a.x), std::abs(a.y)); }
  static double magnitude(Point a, Point b) { return std::max(magnitude(a), magnitude(b)); }
  // Its delta and length, computed when first needed.
  void settle(Edge& e) const {
    if (e.largest >= 0) return;
    e.largest = largestCrossing(e);
    e.delta = deltaAt(e.largest);
    e.length = std::hypot(e.b.x - e.a.x, e.b.y - e.a.y);
  }
  double deltaAt(double m) const {
    return (2 * ulps_ + 6) * ulpOf(m, ulpFloor_);
  }

  // Where along e a point q projects (clamped to e).
  static double along(const Edge& e, Point q) {
    const double dx = e.b.x - e.a.x, dy = e.b.y - e.a.y;
    return std::clamp(((q.x - e.a.x) * dx + (q.y - e.a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  }

  // The largest proper crossing of e with another operand edge, decided exactly. A crossing
  // lies on both edges, so the smaller edge's coordinates bound its magnitude: nothing cancels
  // when a 1e144-long edge crosses a 1e-15 one. Meetings at input vertices need no rounding.
  // Edges whose boxes lie apart (strictly: a proper crossing is inside both) are passed over
  // before any orientation, and the walk ends once a crossing reaches e's own magnitude, which
  // no other can exceed.
  double largestCrossing(const Edge& e) const {
    double largest = 0;
    const double own = magnitude(e.a, e.b);
    auto apart = [](double u0, double u1, double v0, double v1) {  // false whenever one is NaN
      return (u0 < v0 && u0 < v1 && u1 < v0 && u1 < v1) || (v0 < u0 && v0 < u1 && v1 < u0 && v1 < u1);
    };
    for (const Edge& o : edges_) {
      if (&o == &e || apart(e.a.x, e.b.x, o.a.x, o.b.x) || apart(e.a.y, e.b.y, o.a.y, o.b.y)) continue;
      const int oa = filteredOrientation(e.a, e.b, o.a), ob = filteredOrientation(e.a, e.b, o.b);
      if (oa * ob >= 0) continue;
      const int ea = filteredOrientation(o.a, o.b, e.a), eb = filteredOrientation(o.a, o.b, e.b);
      if (ea * eb >= 0) continue;
      largest = std::max(largest, std::min(own, magnitude(o.a, o.b)));
      if (largest == own) break;
    }
    return largest;
  }

  // A uniform grid over the edges' boxes, each widened by its coarse delta: an edge is listed
  // in every cell that a point within its coarse delta of it can fall in, and a point's cell
  // (clamped to the grid, by the same monotone function) lists every edge it is that near. In
  // each row of cells its box meets, an edge is listed in the cells between its line's ends in
  // that row (the row widened by the delta and a margin for the rounding of the row's bounds and
  // of the ends, which is far above it), not in its box's whole width: the long diagonal edges
  // of a fuzz input's rings were listed in most cells, and near() read them for every point.
  std::size_t axis(double v, double lo, double hi) const { return bucket(v, lo, hi, side_); }
  std::size_t cell(double x, double y) const { return axis(y, y0_, y1_) * side_ + axis(x, x0_, x1_); }
  void index() {
    if (edges_.empty()) return;
    PooledVector<Box> boxes;
    x0_ = y0_ = std::numeric_limits<double>::infinity(), x1_ = y1_ = -x0_;
    for (const Edge& e : edges_) {
      boxes.push_back({std::min(e.a.x, e.b.x) - e.coarse, std::max(e.a.x, e.b.x) + e.coarse,
                       std::min(e.a.y, e.b.y) - e.coarse, std::max(e.a.y, e.b.y) + e.coarse});
      x0_ = std::min(x0_, boxes.back().x0), x1_ = std::max(x1_, boxes.back().x1);
      y0_ = std::min(y0_, boxes.back().y0), y1_ = std::max(y1_, boxes.back().y1);
    }
    // About eight cells per edge, fewer while the edges would be listed more than 32 times each
    // on average.
    side_ = listInCells(
        edges_.size(), std::min<std::size_t>(static_cast<std::size_t>(std::sqrt(edges_.size() * 8.0)), 1024),
        [&](std::size_t i, std::size_t side, auto&& f) {
          forEachCellNear(edges_[i].a, edges_[i].b, edges_[i].coarse, x0_, x1_, y0_, y1_, side, f);
        },
        [&](std::size_t i) { return Member{boxes[i], static_cast<std::uint32_t>(i)}; }, start_, members_);
  }

  int ulps_;
  double ulpFloor_;
  double largest_ = 0;
  double largestCoarse_ = 0;
  PooledVector<Edge> edges_;
  double x0_ = 0, x1_ = 0, y0_ = 0, y1_ = 0;
  std::size_t side_ = 1;
  PooledVector<std::size_t> start_;
  PooledVector<Member> members_;  // each cell's edges, with their widened boxes (read in order)
};

// The phase of the eight directions around a vertex: a function of the vertex and the seed
// alone (splitmix64 of its coordinates), so that a vertex met again (an input vertex on an answer,
// a crossing on the answers of several operations) is sampled at exactly the same points.
double phaseOf(Point q, std::uint64_t seed) {
  std::uint64_t h = seed;
  for (double v : {q.x + 0.0, q.y + 0.0}) {  // + 0.0: -0 and 0 are one vertex
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    h = mixBits(h + bits + 0x9E3779B97F4A7C15ull);
  }
  return static_cast<double>(h >> 11) * 0x1p-53 * 2 * std::acos(-1.0);
}

// Whether the segments pq and ab share a point (cross, touch or overlap), decided exactly.
bool touches(Point p, Point q, Point a, Point b) {
  if (std::max(p.x, q.x) < std::min(a.x, b.x) || std::max(a.x, b.x) < std::min(p.x, q.x) ||
      std::max(p.y, q.y) < std::min(a.y, b.y) || std::max(a.y, b.y) < std::min(p.y, q.y)) {
    return false;
  }
  const int op = filteredOrientation(a, b, p), oq = filteredOrientation(a, b, q);
  if (op == oq && op != 0) return false;  // p and q strictly on one side of ab's line
  const int oa = filteredOrientation(p, q, a), ob = filteredOrientation(p, q, b);
  return !(oa == ob && oa != 0);
}

// An answer's boundary near a point q, within a radius where it consists of rays from q (its
// edges that end at q or pass through it, each as far as its other end): there the answer's
// side changes across each ray and nowhere else, so one ray test at a reference point gives the
// side of every other point of the disk, from the parity of the rays between their directions
// (even in all, as every ring that meets q leaves it again; with an odd count, it is not used).
// Directions are ordered exactly: by half-plane, then by orientation.
class RaysFrom {
 public:
  void reset(Point q, double radius) {
    q_ = q, radius_ = radius, ends_.clear(), referenced_ = false;
  }
  void add(Point end) {
    if (end != q_) ends_.push_back({end, half(end)});
  }
  // Whether p (at `radius` from q, as sampled) gets its side here.
  bool holds(Point p, double radius) const {
    return radius <= radius_ && ends_.size() % 2 == 0 && p != q_;
  }
  // p's side: nullopt on a ray (on the answer's boundary); rayTest() gives it where no reference
  // is known yet.
  template <class RayTest>
  std::optional<bool> side(Point p, RayTest&& rayTest) {
    const int h = half(p);
    std::size_t before = 0;  // rays whose direction comes before p's
    for (const auto& [end, endHalf] : ends_) {
      if (endHalf != h) {
        before += endHalf < h;
        continue;
      }
      const int o = filteredOrientation(q_, end, p);
      if (o == 0) return std::nullopt;  // p's direction: p lies on that edge
      before += o > 0;
    }
    if (!referenced_) {
      const std::optional<bool> tested = rayTest();
      if (!tested) return tested;  // cannot happen (p is on no edge), and then no reference
      referenced_ = true, referenceSide_ = *tested, referenceBefore_ = before;
      return tested;
    }
    return referenceSide_ != (((before ^ referenceBefore_) & 1) != 0);
  }

 private:
  // 0 for a direction in [0, pi) from the positive x axis, 1 for [pi, 2 pi).
  int half(Point p) const { return p.y > q_.y || (p.y == q_.y && p.x > q_.x) ? 0 : 1; }

  Point q_{};
  double radius_ = -1;
  PooledVector<std::pair<Point, int>> ends_;
  bool referenced_ = false, referenceSide_ = false;
  std::size_t referenceBefore_ = 0;
};

// The points around a vertex q, in a fixed order: eight directions from the vertex's phase and
// both ways along each corner's bisector, at radii global (extent * 2^-8 .. 2^-26) and local (a
// corner's shorter edge * 2^-2 .. 2^-20, or a smaller corner's within a factor 2 of it).
// `corners` holds the distinct corners (the neighbours on a ring) of every ring of S, C and the
// answers through q: the vertex is visited once, with one clearance and one fan, and each corner
// gets the radii it would get alone at its (merged) scale (below), the union sampled once.
// (Visiting it once per corner cost 46 % more instructions on the clip targets' corpus and found
// 3 naive answers fewer wrong; one local scale for all corners, the shortest, lost 19 of 4,102
// naive findings there.)
//
// visit(p, r) gets each point p and its radius r, and says whether p was judged (not skipped).
// Points that add nothing are left out. clearanceBelow(cap), called once before the first visit,
// gives c: no edge of S, C or the answer comes within c of q except edges that end at q or cross
// there, and those reach at least c from q (or c = cap when that holds for cap). Inside the disk
// of radius c/2 only q's own edges cut, all as rays from q, so the points in one direction at two
// radii below c/2 lie in the same sector: the same side of S, C and the answer, and the outer one
// is no nearer an edge (the inner is skipped whenever the outer is, as long as c/2 exceeds every
// edge's delta, `delta`). Of the radii below c/2, only the largest is sampled; where a corner
// has one, of its radii above only the smallest (the larger reach the neighbourhoods of other
// vertices, sampled at those: on 1,644 seed, regression and grown fuzz inputs the naive answers
// they alone found wrong were none, while they cost 7 % of the exact target's instructions).
// widerClearance(cap), called at most once, after it, gives c': no edge comes within c' of q but
// the edges near q, those through q and a few others. Inside the disk of radius c'/2, a point is
// left out when the segment from the last point judged in its direction (farther out, inside that
// disk) to it meets none of those edges, decided exactly (separated(outer, p) is false): then
// both lie in one face of their arrangement, on the same side of S, C and the answer, and it
// would be judged as that point was, or skipped. This keeps a vertex an ulp from an edge (whose
// c lies below every radius) from costing 80 points. (Asked only where a corner's eight radii
// are to be sampled: on the fuzz corpora, asked wherever three or more were, finding c' cost
// more than the points it saved.) Of such a corner's radii beyond c'/2, the eight directions are
// sampled at the smallest only, as at the smallest radius above c/2 where c allows a kept
// radius; the larger ones get the corner's bisector both ways (which found one of the paper
// arithmetic's wrong answers the eight directions there did not: SamplingOracle tests).
//
// A bisector is sampled at its own corner's radii, not at every corner's: where several corners
// meet at q (S, C and five answers through a crossing), each alone would have been judged along
// its own bisector only. (On 1,101 seed, regression and grown clip inputs, these two rules judged
// 21 % fewer points, 12,132,590 instead of 15,318,329 for the three variants, with the same
// verdict for every answer.)
//
// At that largest radius below c/2 the points are one per sector of the disk: `fan` (filled by
// clearanceBelow) holds the far ends of the edges through q or counted so (the rays that alone
// cut the disk), and a point is judged in the middle of each sector between consecutive rays (so
// a thin sector the eight directions miss is judged too); a point of the eight directions and the
// bisector is judged only where no middle point was judged in its sector (decided exactly: the
// rays before its direction), as it lies in one face with that one, and not at all where every
// sector's middle was. At the smallest radius above c/2 the points lie in the sectors' middle
// directions and both ways along the corner's bisector (on those 1,644 inputs this found every
// naive answer the eight directions found wrong, and 26 more, with half the points); where the
// corners' smallest radii above c/2 differ, the middles at the least of them (a corner alone has
// two rays, whose sectors' middles are its bisector both ways) and each bisector at its own.
template <class Clearance, class WiderClearance, class Visit, class Separated>
void aroundVertex(Point q, const std::vector<std::pair<Point, Point>>& corners, double extent, std::uint64_t seed,
                  double delta, Clearance&& clearanceBelow, WiderClearance&& widerClearance, Visit&& visit,
                  Separated&& separated, const std::vector<Point>& fan) {
  const double pi = std::acos(-1.0);
  // Each corner's own scale: its shorter non-zero edge. Scales within a factor 2 of a smaller
  // one are sampled at that one's radii (at most 2 times nearer q than their own, never farther):
  // the corners of the answers' rings through a vertex often differ by a few per cent in length
  // (a crossing's neighbours on the five answers, a vertex the paper arithmetic moved), and each
  // distinct scale cost four radii of ten directions or more. On the clip targets' corpora (seed,
  // regression and grown: 1,479 naive and sweep inputs, 785 exact) this judged 12 % (naive,
  // sweep) to 21 % (exact) fewer points with the same verdict on every answer; merging within a
  // factor 8, one naive answer fewer was found wrong.
  // Each corner's two edges' halves (halves: no overflow near 2^1023), their lengths halved, and
  // its local scale (infinite when both edges have length 0).
  struct Legs {
    double ux, uy, wx, wy, lu, lw, local;
  };
  thread_local std::vector<Legs> legs;
  legs.clear();
  thread_local std::vector<double> locals;
  locals.clear();
  for (const auto& [prev, next] : corners) {
    const double ux = prev.x / 2 - q.x / 2, uy = prev.y / 2 - q.y / 2;
    const double wx = next.x / 2 - q.x / 2, wy = next.y / 2 - q.y / 2;
    const double lu = std::hypot(ux, uy), lw = std::hypot(wx, wy);
    double local = std::numeric_limits<double>::infinity();
    for (const double halfLength : {lu, lw}) {
      if (halfLength * 2 > 0) local = std::min(local, halfLength * 2);
    }
    legs.push_back({ux, uy, wx, wy, lu, lw, local});
    if (std::isfinite(local)) locals.push_back(local);
  }
  std::sort(locals.begin(), locals.end());
  std::size_t distinct = 0;
  for (double local : locals) {
    if (distinct == 0 || local > 2 * locals[distinct - 1]) locals[distinct++] = local;
  }
  locals.resize(distinct);
  const double phase = phaseOf(q, seed);
  // Both ways along the bisector of each corner too: a thin spike (a ring of a 1e-10 star tip)
  // lies between two of the eight rays, never across the bisector.
  thread_local std::vector<Point> bisectors;
  bisectors.clear();
  // Per corner, its bisector's place in bisectors (kNoBisector: an edge of length 0).
  constexpr std::size_t kNoBisector = std::numeric_limits<std::size_t>::max();
  thread_local std::vector<std::size_t> cornerBisector;
  cornerBisector.assign(corners.size(), kNoBisector);
  for (std::size_t c = 0; c < corners.size(); ++c) {
    const auto [ux, uy, wx, wy, lu, lw, local] = legs[c];
    if (!(lu > 0 && lw > 0)) continue;
    double bx = ux / lu + wx / lw, by = uy / lu + wy / lw;
    const double lb = std::hypot(bx, by);
    if (lb > 1e-9) {
      bx /= lb, by /= lb;
    } else {  // a straight corner: across the edge
      bx = -uy / lu, by = ux / lu;
    }
    const Point b{bx, by}, opposite{-bx, -by};
    auto it = std::find(bisectors.begin(), bisectors.end(), b);
    if (it == bisectors.end()) it = std::find(bisectors.begin(), bisectors.end(), opposite);
    cornerBisector[c] = static_cast<std::size_t>(it - bisectors.begin());
    if (it == bisectors.end()) bisectors.push_back(b);
  }
  double cosines[8], sines[8];  // the eight directions, the same at every radius
  for (int k = 0; k < 8; ++k) {
    const double a = phase + k * pi / 4;
    ::sincos(a, &sines[k], &cosines[k]);  // glibc's: the bits of std::sin and std::cos, in one call
  }
  // A corner's radii: the global ones and its local ones. Each corner is sampled as alone (below);
  // the union of what they need is sampled once.
  // (As products by powers of two, which are exact as ldexp is: the same doubles, without a
  // library call for each.)
  const double globalScales[] = {0x1p-8, 0x1p-14, 0x1p-20, 0x1p-26}, localScales[] = {0x1p-2, 0x1p-5, 0x1p-10, 0x1p-20};
  thread_local std::vector<double> radii;  // every corner's radii, outer first
  radii.clear();
  for (double scale : globalScales) radii.push_back(extent * scale);
  for (double local : locals) {
    for (double scale : localScales) radii.push_back(local * scale);
  }
  std::sort(radii.begin(), radii.end(), std::greater<>());
  radii.erase(std::unique(radii.begin(), radii.end()), radii.end());
  const double largest = radii[0];
  // 0.49 rather than 0.5: the clearance is computed in doubles.
  const double limit = 0.49 * clearanceBelow(2.5 * largest);
  const bool clear = limit > 2 * delta;
  // The largest radius below the limit: its sectors are every corner's (each radius below the
  // limit lies in the same sectors).
  double kept = -1;
  if (clear) {
    for (double r : radii) {
      if (r <= limit) kept = std::max(kept, r);
    }
  }
  // Per corner, as if alone: with a radius of its own below the limit, only the smallest radius
  // above it beside the kept radius (the larger ones reach the neighbourhoods of other vertices,
  // sampled at those); without, all its radii up to the smallest beyond the wider disk (where
  // only the edges near q cut: below), once that is known, and the larger ones along its bisector
  // alone. The radii sampled are the union of the corners'; a corner's bisector is sampled at its
  // own radii, not at every corner's (alone, it would have been sampled at its own only).
  enum Kind { kFull, kOutside, kAlongBisector };
  auto plan = [&](const double* own, std::size_t n, double wider, auto&& take) {
    double below = -1, above = -1;
    for (std::size_t i = 0; i < n; ++i) {
      if (clear && own[i] <= limit) below = std::max(below, own[i]);
      if (own[i] > limit && (above < 0 || own[i] < above)) above = own[i];
    }
    if (below >= 0) {
      if (above > 0) take(kOutside, above);
      return true;  // its sectors wanted
    }
    double beyond = -1;  // its smallest radius beyond the wider disk
    if (wider > 2 * delta) {
      for (std::size_t i = 0; i < n; ++i) {
        if (own[i] > wider && (beyond < 0 || own[i] < beyond)) beyond = own[i];
      }
    }
    for (std::size_t i = 0; i < n; ++i) take(beyond < 0 || own[i] <= beyond ? kFull : kAlongBisector, own[i]);
    return false;
  };
  // Each corner's own radii: the global ones, and those of its merged local scale.
  double own[8];
  for (int k = 0; k < 4; ++k) own[k] = extent * globalScales[k];
  auto withLocal = [&](double local) {
    for (int k = 0; k < 4; ++k) own[4 + k] = local * localScales[k];
  };
  thread_local std::vector<double> radiiOf[3];  // by Kind
  bool sectorsWanted = false;
  auto planRadii = [&](double wider) {
    for (auto& set : radiiOf) set.clear();
    sectorsWanted = false;
    auto take = [&](Kind kind, double r) { radiiOf[kind].push_back(r); };
    if (locals.empty()) sectorsWanted |= plan(own, 4, wider, take);
    for (double local : locals) withLocal(local), sectorsWanted |= plan(own, 8, wider, take);
  };
  planRadii(0.0);
  auto among = [](const std::vector<double>& set, double r) { return std::find(set.begin(), set.end(), r) != set.end(); };
  // Asked only where a corner with a local scale has all its radii sampled.
  bool localFull = false;
  for (double local : locals) localFull |= among(radiiOf[kFull], local * localScales[0]);
  const double wider = localFull ? 0.49 * widerClearance(2.5 * largest) : 0.0;
  if (wider > 2 * delta) planRadii(wider);
  // Each bisector's radii, by kind: those of the corners it bisects.
  thread_local std::vector<std::pair<double, std::size_t>> bisectorRadii[3];  // (radius, bisector)
  for (auto& set : bisectorRadii) set.clear();
  for (std::size_t c = 0; c < corners.size(); ++c) {
    if (cornerBisector[c] == kNoBisector) continue;
    double merged = locals[0];  // its local scale as merged above: the largest at most its own
    for (double local : locals) {
      if (local <= legs[c].local) merged = local;
    }
    withLocal(merged);
    plan(own, 8, wider, [&](Kind kind, double r) { bisectorRadii[kind].push_back({r, cornerBisector[c]}); });
  }
  // The bisectors wanted at a radius (of corners with that radius of that kind).
  thread_local std::vector<char> wanted;
  auto wantBisectors = [&](Kind kind, double r) {
    wanted.assign(bisectors.size(), 0);
    for (const auto& [radius, j] : bisectorRadii[kind]) {
      if (radius == r) wanted[j] = 1;
    }
  };
  // Per direction (the eight, then each bisector both ways), the last point judged inside the
  // wider disk.
  thread_local std::vector<Point> outer;
  thread_local std::vector<char> hasOuter;
  outer.assign(8 + 2 * bisectors.size(), Point{});
  hasOuter.assign(outer.size(), 0);
  auto at = [&](std::size_t k, Point p, double radius) {
    const bool inside = radius <= wider && wider > 2 * delta;
    if (inside && hasOuter[k] && !separated(outer[k], p)) return;
    if (visit(p, radius) && inside) outer[k] = p, hasOuter[k] = 1;
  };
  // Every direction's point at a radius, each as given to f(k, p).
  auto directions = [&](double radius, auto&& f) {
    for (std::size_t k = 0; k < 8; ++k) f(k, Point{q.x + radius * cosines[k], q.y + radius * sines[k]});
    for (std::size_t j = 0; j < bisectors.size(); ++j) {
      const Point b = bisectors[j];
      f(8 + 2 * j, Point{q.x + radius * b.x, q.y + radius * b.y});
      f(9 + 2 * j, Point{q.x - radius * b.x, q.y - radius * b.y});
    }
  };
  // At a radius all of some corner's are sampled at: the eight directions, and the bisectors of
  // those corners.
  auto around = [&](double radius) {
    wantBisectors(kFull, radius);
    directions(radius, [&](std::size_t k, Point p) {
      if (k < 8 || wanted[(k - 8) / 2]) at(k, p, radius);
    });
  };
  // Where a direction lies among the fan's rays: how many come before it (by half-plane from the
  // positive x axis, then by orientation), modulo their number; none on a ray. The fan's ends (each
  // once) with their half-planes, found once per vertex.
  auto half = [&](Point p) { return p.y > q.y || (p.y == q.y && p.x > q.x) ? 0 : 1; };
  thread_local std::vector<std::pair<Point, int>> ends;  // the fan's ends, with their halves
  auto takeEnds = [&] {
    ends.clear();
    for (const Point& end : fan) ends.push_back({end, half(end)});
  };
  auto sectorOf = [&](Point p) -> std::optional<std::size_t> {
    const int h = half(p);
    std::size_t before = 0;
    for (const auto& [end, endHalf] : ends) {
      if (endHalf != h) {
        before += endHalf < h;
        continue;
      }
      const int o = filteredOrientation(q, end, p);
      if (o == 0) return std::nullopt;
      before += o > 0;
    }
    return ends.empty() ? 0 : before % ends.size();
  };
  // The sectors' middle directions (unit vectors), once per vertex: the rays' directions in
  // angular order (by a pseudo-angle, in doubles), and between each two that differ the bisector
  // of the turn from one to the next. Returns how many; 0 when two distinct rays could not be
  // told apart so (then the sectors are not known to be all covered).
  thread_local std::vector<std::pair<double, Point>> rays;  // (pseudo-angle, unit direction)
  thread_local std::vector<Point> middles;
  auto sectorMiddles = [&]() -> std::size_t {
    rays.clear();
    middles.clear();
    for (const Point& end : fan) {
      const double dx = end.x / 2 - q.x / 2, dy = end.y / 2 - q.y / 2, l = length(dx, dy);
      // The "diamond angle": increasing with the angle from the positive x axis, in [0, 4).
      const double pseudo = dy >= 0 ? (dx >= 0 ? dy / (dx + dy) : 1 - dx / (dy - dx))
                                    : (dx < 0 ? 2 - dy / (-dx - dy) : 3 + dx / (dx - dy));
      rays.push_back({pseudo, Point{dx / l, dy / l}});
    }
    if (rays.empty()) {  // no edge through q: one sector, the whole disk
      middles.push_back({std::cos(phase), std::sin(phase)});
      return 1;
    }
    // Ties (ends in one direction, whose unit vectors may differ in the last bit) broken by the
    // vector: the ray kept for a direction does not depend on the order the ends were found in.
    std::sort(rays.begin(), rays.end(), [](const auto& u, const auto& v) {
      return u.first < v.first ||
             (u.first == v.first && (u.second.x < v.second.x || (u.second.x == v.second.x && u.second.y < v.second.y)));
    });
    bool merged = false;  // distinct ends in one pseudo-angle: perhaps two directions
    std::size_t k = 0;
    for (std::size_t i = 1; i < rays.size(); ++i) {
      if (rays[i].first == rays[k].first) {
        merged |= !(rays[i].second == rays[k].second);
        continue;
      }
      rays[++k] = rays[i];
    }
    rays.resize(k + 1);
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const Point a = rays[i].second, b = rays[(i + 1) % rays.size()].second;
      if (rays.size() == 1) {
        middles.push_back({-a.x, -a.y});  // the whole turn: straight back
        continue;
      }
      const double cross = a.x * b.y - a.y * b.x, sx = a.x + b.x, sy = a.y + b.y, l = length(sx, sy);
      if (!(l > 1e-9)) {
        middles.push_back({-a.y, a.x});  // a half turn: a quarter turn from a
      } else {
        const double side = cross >= 0 ? 1 : -1;  // the turn from a to b is less than half, or more
        middles.push_back({side * sx / l, side * sy / l});
      }
    }
    return merged ? 0 : middles.size();
  };
  std::size_t sectors = 0;
  if (sectorsWanted) sectors = sectorMiddles(), takeEnds();
  // At the kept radius: a point at each sector's middle; a direction's point only where its
  // sector's middle was not judged (all are where every sector's middle was).
  auto aroundSectors = [&](double radius) {
    std::size_t covered[64], judged = 0;
    for (const Point& u : middles) {
      const Point p{q.x + radius * u.x, q.y + radius * u.y};
      if (!visit(p, radius)) continue;
      const auto sector = sectorOf(p);
      if (sector && judged < 64 && std::find(covered, covered + judged, *sector) == covered + judged) covered[judged++] = *sector;
    }
    if (sectors > 0 && judged == sectors) return;
    directions(radius, [&](std::size_t k, Point p) {
      const auto sector = sectorOf(p);
      if (sector && std::find(covered, covered + judged, *sector) != covered + judged) return;
      at(k, p, radius);
    });
  };
  // At the smallest radius outside the clearance: the sectors' middle directions; at each
  // corner's, its bisector both ways. (A corner alone has two rays, whose sectors' middles are its
  // bisector both ways.)
  double smallestOutside = -1;
  for (double r : radiiOf[kOutside]) {
    if (smallestOutside < 0 || r < smallestOutside) smallestOutside = r;
  }
  auto alongBisectors = [&](Kind kind, double radius) {
    wantBisectors(kind, radius);
    for (std::size_t j = 0; j < bisectors.size(); ++j) {
      if (!wanted[j]) continue;
      const Point b = bisectors[j];
      visit(Point{q.x + radius * b.x, q.y + radius * b.y}, radius);
      visit(Point{q.x - radius * b.x, q.y - radius * b.y}, radius);
    }
  };
  for (double r : radii) {
    if (among(radiiOf[kFull], r)) {
      around(r);
    } else if (among(radiiOf[kOutside], r)) {
      if (r == smallestOutside) {
        for (const Point& u : middles) visit(Point{q.x + r * u.x, q.y + r * u.y}, r);
      }
      alongBisectors(kOutside, r);
    } else if (among(radiiOf[kAlongBisector], r)) {
      alongBisectors(kAlongBisector, r);
    }
    if (r == kept && sectorsWanted) aroundSectors(r);
  }
}

// One answer to judge, among several for the same S and C.
struct SampleAnswer {
  Op op;
  const Region& result;
};

// The edges of several answers, each distinct segment (in either direction) once in one grid,
// with the answers it is an edge of (an answer once per edge of it there): the exact variant's
// five answers share most of their edges.
class AnswerSegments {
  PooledVector<std::uint32_t> start_, answers_;  // answers_[start_[e] .. start_[e + 1]): segment e's;
                                                // made by distinct(), so declared before the grid

 public:
  explicit AnswerSegments(const std::vector<SampleAnswer>& answers) : grid(distinct(answers)) {}

  struct Answers {
    const std::uint32_t *first, *last;
    const std::uint32_t* begin() const { return first; }
    const std::uint32_t* end() const { return last; }
  };
  // The answers segment e of the grid is an edge of, one entry per edge.
  Answers answersOf(std::uint32_t e) const { return {answers_.data() + start_[e], answers_.data() + start_[e + 1]}; }

  const SegmentGrid grid;

 private:
  PooledVector<std::pair<Point, Point>> distinct(const std::vector<SampleAnswer>& answers) {
    struct Edge {
      Point a, b;  // a before b (by x, then y)
      std::uint32_t answer;
    };
    PooledVector<Edge> edges;
    for (std::uint32_t k = 0; k < answers.size(); ++k) {
      for (const Ring& ring : answers[k].result) {
        for (std::size_t i = 0, m = ring.size(); i < m; ++i) {
          Point a = ring[i], b = ring[(i + 1) % m];
          if (b.x < a.x || (b.x == a.x && b.y < a.y)) std::swap(a, b);
          edges.push_back({a, b, k});
        }
      }
    }
    auto key = [](const Edge& e) { return std::make_tuple(e.a.x, e.a.y, e.b.x, e.b.y); };
    std::sort(edges.begin(), edges.end(), [&](const Edge& e, const Edge& f) {
      return key(e) < key(f) || (key(e) == key(f) && e.answer < f.answer);
    });
    PooledVector<std::pair<Point, Point>> segments;
    start_.push_back(0);
    for (std::size_t i = 0; i < edges.size(); ++i) {
      if (i > 0 && key(edges[i]) == key(edges[i - 1])) {
        ++start_.back();
      } else {
        segments.push_back({edges[i].a, edges[i].b});
        start_.push_back(start_.back() + 1);
      }
      answers_.push_back(edges[i].answer);
    }
    return segments;
  }
};

// A bound on the error of a distance, or of a point's rounding, in a box.
double slackOf(const Box& box) {
  return 32 * ulpOf(std::max({std::abs(box.minX), std::abs(box.maxX), std::abs(box.minY), std::abs(box.maxY)}));
}

// The check proper, on a problem at a comfortable scale (ulpFloor is the original's smallest ulp
// at this scale), split so that several answers for the same S and C share the work that does
// not depend on the answer. What a point needs besides the answer (whether it is too near an
// edge of S or C to judge, and on which side of S and of C it lies) is computed once per point
// and kept: every vertex is sampled at the same points whenever it is met (phaseOf), around S
// and C for every answer, around an answer's vertices that are vertices of S or C or crossings
// shared by several answers. Each point is judged once per answer.
class Sampler {
 public:
  // box: S and C's joint bounding box, where every operation's answer lies (the answer's own box
  // when S and C are both empty).
  Sampler(const Region& subject, const Region& clip, const Box& box, const SampleOptions& options, double ulpFloor)
      : options_(options), box_(box), subject_(subject), clip_(clip),
        operandEdges_(subject, clip, options.constructionUlps, ulpFloor), operands_({&subject, &clip}),
        operandGrid_(operandEdges_.segments()) {
    std::size_t vertices = 0;
    for (const Region* r : {&subject, &clip}) {
      for (const Ring& ring : *r) vertices += ring.size();
    }
    operandClearance_.resize(vertices);
    if (!(box.minX <= box.maxX)) return;  // everything empty: nothing to check
    // Halves first: the extent of coordinates near 2^500 must not overflow.
    extent_ = std::max({(box.maxX / 2 - box.minX / 2) * 2, (box.maxY / 2 - box.minY / 2) * 2,
                        std::numeric_limits<double>::min()});
    forUniformPoints(box, options.seed, options.uniformPoints, [&](Point p) { uniform_.push_back({p, sides(p)}); });
  }

  bool empty() const { return !(box_.minX <= box_.maxX); }

  // Several answers judged at once, at the points of all of them: the uniform points, and the
  // points around every vertex of S, C and each answer. Around a vertex the radii sampled follow
  // its clearance from the edges of S, C and every answer, and each distinct corner (a vertex and
  // its two neighbours) is sampled once. So each answer is judged at every point a check of it
  // alone judges, or at a point of the same face of the arrangement of S, C and all the answers
  // (which has the same sides: aroundVertex), and at more; each point's sides of S and C are
  // decided once, and its side of each answer once per check.
  std::vector<SampleVerdict> check(const std::vector<SampleAnswer>& answers) {
    const auto start = std::chrono::steady_clock::now();
    const std::size_t n = answers.size();
    std::vector<SampleVerdict> verdicts(n);
    if (empty() || n == 0) return verdicts;
    ++epoch_;
    std::vector<Box> reach(n, box_);  // S, C and each answer
    std::vector<double> slack(n);
    for (std::size_t i = 0; i < n; ++i) {
      reach[i].grow(answers[i].result);
      slack[i] = slackOf(reach[i]);
    }
    // The answers' sides, by one ray per point for each group of up to 64 answers. Without
    // through edges: built for every check, their sorting cost more than they saved (on the exact
    // target's grown corpus, 4.9 % more instructions with them than without); S and C's bands,
    // built once per judge and asked for every fresh point, have them (even_odd_regions.h).
    std::vector<EvenOddRegions> inR;
    for (std::size_t first = 0; first < n; first += EvenOddRegions::kMost) {
      std::vector<const Region*> group;
      for (std::size_t i = first; i < n && i < first + EvenOddRegions::kMost; ++i) group.push_back(&answers[i].result);
      inR.emplace_back(group, false);
    }
    // A point's sides of every answer, each group's ray cast when first asked for (near a
    // vertex, most answers' sides follow from the rays there: RaysFrom).
    struct AnswerSides {
      std::vector<EvenOddRegions::Sides> groups;
      std::vector<char> known;
    } point;
    point.groups.resize(inR.size()), point.known.resize(inR.size());
    auto forget = [&] { std::fill(point.known.begin(), point.known.end(), 0); };
    auto sideIn = [&](std::size_t i, Point p) {
      const std::size_t g = i / EvenOddRegions::kMost;
      if (!point.known[g]) point.groups[g] = inR[g].inside(p), point.known[g] = 1;
      return point.groups[g].of(i % EvenOddRegions::kMost);
    };
    auto sideOf = [&](std::size_t i, Point p, std::uint8_t state) {
      return (state & kSkipped) ? std::nullopt : sideIn(i, p);
    };
    // With stopWhenAllFail, nothing more is judged once every answer has a mismatch, and an
    // answer that has one gets no points of its own beyond S and C's box (SampleOptions).
    const bool stopEarly = options_.stopWhenAllFail;
    auto allFail = [&] {
      return stopEarly && std::all_of(verdicts.begin(), verdicts.end(), [](const SampleVerdict& v) { return v.mismatched > 0; });
    };
    for (const auto& [p, state] : uniform_) {
      if (allFail()) break;
      forget();
      for (std::size_t i = 0; i < n; ++i) judge(verdicts[i], answers[i].op, p, state, sideOf(i, p, state));
    }
    // An answer reaching beyond S and C's box (a wrong one, or the paper arithmetic's, whose
    // perturbation moves vertices) is sampled there too: of as many points drawn uniformly over the
    // box of S, C and the answer, those that land outside S and C's box.
    for (std::size_t i = 0; i < n; ++i) {
      if (box_.holds(reach[i]) || (stopEarly && verdicts[i].mismatched > 0)) continue;
      forUniformPoints(reach[i], mixBits(options_.seed ^ 0xB0C5B0C5B0C5B0C5ull), options_.uniformPoints, [&](Point p) {
        if (box_.holds(p)) return;
        const std::uint8_t state = sides(p);
        forget();
        judge(verdicts[i], answers[i].op, p, state, sideOf(i, p, state));
      });
    }
    if (options_.nearVertices && !allFail()) {
      const AnswerSegments segments(answers);
      const SegmentGrid& answerGrid = segments.grid;
      rays_.resize(n);
      strictByAnswer_.resize(n);
      // Whether p was judged for every answer (not skipped), now or earlier in this check.
      auto probe = [&](Point p, double radius) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
        auto [known, fresh] = known_.findOrAdd(p);
        if (fresh) known.state = sides(p);  // sides() adds nothing to known_: the reference holds
        if (known.epoch == epoch_) return known.judged;  // judged in this check already
        known.epoch = epoch_;
        bool all = !(known.state & kSkipped);
        forget();
        for (std::size_t i = 0; i < n; ++i) {
          std::optional<bool> side;
          if (!(known.state & kSkipped)) {
            side = rays_[i].holds(p, radius) ? rays_[i].side(p, [&] { return sideIn(i, p); }) : sideIn(i, p);
          }
          all &= judge(verdicts[i], answers[i].op, p, known.state, side);
        }
        return known.judged = all;
      };
      // Whether one of the edges near the vertex sampled meets segment ft.
      auto separated = [&](Point f, Point t) {
        for (const auto& [a, b] : nearest_) {
          if (touches(f, t, a, b)) return true;
        }
        return false;
      };
      const double delta = operandEdges_.largestCoarseDelta();
      // Every vertex once, with the corners (its neighbours) of every ring of S, C and the
      // answers through it: one clearance and one fan of sectors, each corner at its own radii
      // and along its own bisector (aroundVertex).
      vertices_.clear(), cornersAt_.clear();
      vertexIndex_.clear();
      std::size_t operandVertex = 0;  // an S or C vertex's place in operandClearance_
      auto gather = [&](const Ring& ring, bool operand) {
        for (std::size_t i = 0, m = ring.size(); i < m; ++i, operandVertex += operand) {
          const Point q = ring[i];
          if (!std::isfinite(q.x) || !std::isfinite(q.y)) continue;  // no point around it is finite
          auto [index, fresh] = vertexIndex_.findOrAdd(q);
          if (fresh) index = static_cast<std::uint32_t>(vertices_.size()), vertices_.push_back({q, -1});
          if (operand && vertices_[index].operand < 0) vertices_[index].operand = static_cast<std::int64_t>(operandVertex);
          cornersAt_.push_back({index, ring[(i + m - 1) % m], ring[(i + 1) % m]});
        }
      };
      for (const Region* region : {&subject_, &clip_}) {
        for (const Ring& ring : *region) gather(ring, true);
      }
      for (const SampleAnswer& answer : answers) {
        for (const Ring& ring : answer.result) gather(ring, false);
      }
      // Grouped by vertex, in the order gathered within each: a counting sort (stable, as
      // stable_sort was, without the buffer it took for every check).
      {
        PooledVector<std::size_t> next(vertices_.size() + 1, 0);
        for (const Corner& c : cornersAt_) ++next[c.vertex + 1];
        for (std::size_t v = 0; v < vertices_.size(); ++v) next[v + 1] += next[v];
        PooledVector<Corner> grouped(cornersAt_.size());
        for (const Corner& c : cornersAt_) grouped[next[c.vertex]++] = c;
        cornersAt_.swap(grouped);
      }
      for (std::size_t first = 0, last; first < cornersAt_.size() && !allFail(); first = last) {
        for (last = first + 1; last < cornersAt_.size() && cornersAt_[last].vertex == cornersAt_[first].vertex; ++last) {
        }
        // This vertex's corners, each once (in either order).
        corners_.clear();
        for (std::size_t c = first; c < last; ++c) {
          const Point prev = cornersAt_[c].prev, next = cornersAt_[c].next;
          const bool seen = std::any_of(corners_.begin(), corners_.end(), [&](const auto& k) {
            return (k.first == prev && k.second == next) || (k.first == next && k.second == prev);
          });
          if (!seen) corners_.push_back({prev, next});
        }
        const VertexAt& vertex = vertices_[cornersAt_[first].vertex];
        const Point q = vertex.q;
        CachedClearance* cached = vertex.operand >= 0 ? &operandClearance_[static_cast<std::size_t>(vertex.operand)] : nullptr;
        for (RaysFrom& rays : rays_) rays.reset(q, -1);  // until the clearance below is known
        // An edge of S or C that passes within a rounding of q (q a rounded crossing of
        // it) counts as passing through q when the points computed near q are rounded far
        // less than its delta (OperandEdges::passesNear): within the clearance they differ
        // from the points farther out only where they are skipped. The answers' edges do
        // only where they run along such an edge: elsewhere the points are not skipped near them.
        // A point q + r * u (r < cap) is computed within half an ulp of m, plus 2^-53 r for
        // the product, of the exact point on its ray, per coordinate: within sqrt(2) times
        // that in all; this bound keeps another factor 1.4 in hand. (Twice as loose, it
        // failed passesNear at so many rounded crossings that the fuzz corpus's exact
        // answers had 42 % more points to judge.)
        auto roundingBelow = [&](double cap) { return ulpOf(std::max(std::abs(q.x), std::abs(q.y)) + cap) + 0x1p-51 * cap; };
        auto passesNear = [&](double rounding) {
          return [&, rounding](std::size_t e, double d) { return operandEdges_.passesNear(e, q, d, rounding); };
        };
        // An answer's edge that runs along such an edge of S or C (a ring of the answer
        // passing a rounded crossing that is a vertex of another ring) counts as passing
        // through q too (OperandEdges::carries), for the radii; not for the rays below.
        auto carried = [&](double rounding) {
          return [&, rounding](std::size_t e, double d) {
            return d <= delta && operandEdges_.carries(q, answerGrid.segment(e).first, answerGrid.segment(e).second, rounding);
          };
        };
        // Each end once: an edge through q is often met twice, as an edge of S or C and of an
        // answer (on the exact fuzz target's executions, 15 ends a vertex, 6.6 of them distinct).
        auto addToFan = [&](const std::pair<Point, Point>& segment) {
          for (const Point& end : {segment.first, segment.second}) {
            if (end != q && std::find(fan_.begin(), fan_.end(), end) == fan_.end()) fan_.push_back(end);
          }
        };
        auto clearance = [&](double cap) {
          const double rounding = roundingBelow(cap);
          fan_.clear();
          std::fill(strictByAnswer_.begin(), strictByAnswer_.end(), cap);
          const double answersClearance = answerGrid.clearance(q, cap, carried(rounding), &atQ_, nullptr, nullptr,
                                                               [&](std::uint32_t e, double d, bool through) {
                                                                 for (std::uint32_t a : segments.answersOf(e)) {
                                                                   strictByAnswer_[a] = std::min(strictByAnswer_[a], d);
                                                                 }
                                                                 if (through) addToFan(answerGrid.segment(e));
                                                               });
          // Within this radius each answer's edges are the rays from q: short of its clearance
          // (a segment the walk did not reach lies farther than answersClearance) by far more
          // than the error of a distance in doubles or of a point's rounding (a few ulps of the
          // box's magnitude).
          for (std::size_t a = 0; a < n; ++a) {
            rays_[a].reset(q, 0.49 * std::min(strictByAnswer_[a], answersClearance) - slack[a]);
          }
          for (std::uint32_t e : atQ_) {
            for (std::uint32_t a : segments.answersOf(e)) {
              rays_[a].add(answerGrid.segment(e).first);
              rays_[a].add(answerGrid.segment(e).second);
            }
          }
          // An S or C vertex's clearance from S and C (and the edges through it) is the same for
          // every answer.
          if (!cached) {
            return std::min(operandGrid_.clearance(q, cap, passesNear(rounding), nullptr, nullptr, nullptr,
                                                   [&](std::uint32_t e, double, bool through) {
                                                     if (through) addToFan(operandGrid_.segment(e));
                                                   }),
                            answersClearance);
          }
          if (cached->cap != cap) {
            cached->cap = cap, cached->throughFirst = throughs_.size();
            cached->value = operandGrid_.clearance(q, cap, passesNear(rounding), nullptr, nullptr, nullptr,
                                                   [&](std::uint32_t e, double, bool through) {
                                                     if (through) throughs_.push_back(e);
                                                   });
            cached->throughLast = throughs_.size();
          }
          for (std::size_t k = cached->throughFirst; k < cached->throughLast; ++k) addToFan(operandGrid_.segment(throughs_[k]));
          return std::min(cached->value, answersClearance);
        };
        // The clearance without the edges near q, which it gathers in nearest_.
        auto widerClearance = [&](double cap) {
          const double rounding = roundingBelow(cap);
          answerGrid.clearance(q, cap, carried(rounding), nullptr, nullptr, &nearScratch_);
          const double answersBeyond = nearScratch_.beyond;
          nearest_.clear();
          for (std::uint32_t e : nearScratch_.segments) nearest_.push_back(answerGrid.segment(e));
          NearOperands& operands = cached ? cached->wider : operandScratch_;
          if (!cached || operands.cap != cap) {
            operands.cap = cap;
            operandGrid_.clearance(q, cap, passesNear(rounding), nullptr, nullptr, &nearScratch_);
            operands.beyond = nearScratch_.beyond;
            operands.edges.clear();
            for (std::uint32_t e : nearScratch_.segments) operands.edges.push_back(operandGrid_.segment(e));
          }
          nearest_.insert(nearest_.end(), operands.edges.begin(), operands.edges.end());
          return std::min(operands.beyond, answersBeyond);
        };
        aroundVertex(q, corners_, extent_, options_.seed, delta, clearance, widerClearance, probe, separated, fan_);
      }
    }
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (SampleVerdict& v : verdicts) v.delta = operandEdges_.largestDelta(), v.seconds = seconds;
    return verdicts;
  }

 private:
  // Counts the point in v: skipped when it is within a delta of S or C (state) or on the answer's
  // boundary (no side); else checked, and a mismatch when the side is not op's. Whether judged.
  static bool judge(SampleVerdict& v, Op op, Point p, std::uint8_t state, const std::optional<bool>& side) {
    if ((state & kSkipped) || !side) {
      ++v.skipped;
      return false;
    }
    ++v.checked;
    if (*side != apply(op, (state & kInS) != 0, (state & kInC) != 0)) {
      if (!v.mismatched) v.firstMismatch = p;
      ++v.mismatched;
    }
    return true;
  }

  static constexpr std::uint8_t kInS = 1, kInC = 2, kSkipped = 4;
  struct Known {
    std::uint32_t epoch = 0;  // the last check it was judged in
    std::uint8_t state = 0;
    bool judged = false;      // for every answer of that check (not skipped)
  };

  // kSkipped when p is within the delta of an edge of S or C, or on one; else its sides.
  std::uint8_t sides(Point p) {
    if (operandEdges_.near(p)) return kSkipped;
    const EvenOddRegions::Sides both = operands_.inside(p);
    const auto a = both.of(0), b = both.of(1);
    if (!a || !b) return kSkipped;
    return static_cast<std::uint8_t>((*a ? kInS : 0) | (*b ? kInC : 0));
  }

  struct NearOperands {
    double cap = -1, beyond = 0;                 // the wider clearance below cap from S and C's edges
    std::vector<std::pair<Point, Point>> edges;  // the edges it leaves out (rarely asked: not pooled,
                                                 // as one per vertex would drain the pool)
  };
  struct CachedClearance {
    double cap = -1, value = 0;                     // clearanceBelow(cap) from S and C's edges
    std::size_t throughFirst = 0, throughLast = 0;  // throughs_[first, last): those through the
                                                    // vertex or counted so
    NearOperands wider;
  };

  SampleOptions options_;
  Box box_;
  const Region& subject_;
  const Region& clip_;
  OperandEdges operandEdges_;
  EvenOddRegions operands_;  // S (region 0) and C (region 1)
  SegmentGrid operandGrid_;
  double extent_ = 0;
  std::uint32_t epoch_ = 0;
  PooledVector<std::pair<Point, std::uint8_t>> uniform_;
  PointTable<Known> known_;
  std::vector<CachedClearance> operandClearance_;  // per vertex of S, then of C
  PooledVector<std::uint32_t> throughs_;           // their edges through the vertex, a run each
  PooledVector<std::uint32_t> atQ_;                // scratch: the answer's edges at a vertex
  PooledVector<std::pair<Point, Point>> nearest_;  // scratch: the edges near a vertex (S, C, answer)
  SegmentGrid::Nearest nearScratch_;               // scratch
  NearOperands operandScratch_;                    // scratch: an answer vertex's wider clearance from S and C
  std::vector<RaysFrom> rays_;                     // each answer's edges near the vertex sampled
  PooledVector<double> strictByAnswer_;            // scratch: each answer's clearance from the vertex
  struct VertexAt {
    Point q;
    std::int64_t operand;  // its place in operandClearance_ (an S or C vertex's), or -1
  };
  struct Corner {
    std::uint32_t vertex;  // its place in vertices_
    Point prev, next;      // its neighbours on its ring
  };
  PooledVector<VertexAt> vertices_;                // scratch: the vertices of S, C and the answers
  PointTable<std::uint32_t> vertexIndex_;          // scratch: their places in vertices_
  PooledVector<Corner> cornersAt_;                 // scratch: every corner of every ring
  PooledVector<std::pair<Point, Point>> corners_;  // scratch: one vertex's distinct corners
  PooledVector<Point> fan_;                        // scratch: the far ends of the edges through a vertex
};

Box boxOf(std::initializer_list<const Region*> regions) {
  Box box;
  for (const Region* r : regions) box.grow(*r);
  return box;
}

// What a Sampler samples uniformly: S and C's box, or the answer's when S and C are both empty.
Box operandBox(const Region& subject, const Region& clip, const Region& result) {
  const Box box = boxOf({&subject, &clip});
  return box.minX <= box.maxX ? box : boxOf({&result});
}

}  // namespace

SampleVerdict sampleCheck(const Region& subject, const Region& clip, Op op, const Region& result,
                          const SampleOptions& options) {
  const double denormMin = std::numeric_limits<double>::denorm_min();
  const int k = judgingExponent(subject, clip, result);
  if (k == 0) return Sampler(subject, clip, operandBox(subject, clip, result), options, denormMin).check({{op, result}})[0];
  // Scaled from subnormal coordinates, the original's rounding grid becomes coarse there: its
  // smallest ulp, denorm_min, is 2^k * denorm_min at this scale.
  const Region s = scaledBy(subject, k), c = scaledBy(clip, k), r = scaledBy(result, k);
  SampleVerdict v = Sampler(s, c, operandBox(s, c, r), options, std::ldexp(denormMin, std::max(k, 0))).check({{op, r}})[0];
  v.delta = std::ldexp(v.delta, -k);
  if (v.firstMismatch) v.firstMismatch = scaledBy(*v.firstMismatch, -k);
  return v;
}

struct SamplingJudge::Shared {
  Region subject, clip;  // as given
  int k = 0;             // the judging exponent of S and C alone
  Region scaledSubject, scaledClip;
  std::optional<Sampler> sampler;
};

SamplingJudge::SamplingJudge(const Region& subject, const Region& clip, const SampleOptions& options)
    : options_(options), shared_(std::make_unique<Shared>()) {
  Shared& sh = *shared_;
  sh.subject = subject, sh.clip = clip;
  sh.k = judgingExponent(subject, clip, {});
  sh.scaledSubject = sh.k == 0 ? subject : scaledBy(subject, sh.k);
  sh.scaledClip = sh.k == 0 ? clip : scaledBy(clip, sh.k);
  const double denormMin = std::numeric_limits<double>::denorm_min();
  sh.sampler.emplace(sh.scaledSubject, sh.scaledClip, boxOf({&sh.scaledSubject, &sh.scaledClip}), options,
                     sh.k == 0 ? denormMin : std::ldexp(denormMin, std::max(sh.k, 0)));
}

SamplingJudge::~SamplingJudge() = default;

SampleVerdict SamplingJudge::check(Op op, const Region& result) { return check({{op, &result}})[0]; }

std::vector<SampleVerdict> SamplingJudge::check(const std::vector<std::pair<Op, const Region*>>& answers) {
  Shared& sh = *shared_;
  std::vector<SampleVerdict> verdicts(answers.size());
  // An answer that changes the judging scale (only a wrong one can), or one beside empty S and C
  // (sampled over its own box), is judged on its own; the others together, at S and C's scale.
  std::vector<std::size_t> together;
  std::vector<Region> scaled;
  scaled.reserve(answers.size());  // SampleAnswer holds references into it
  std::vector<SampleAnswer> joint;
  for (std::size_t i = 0; i < answers.size(); ++i) {
    const auto& [op, result] = answers[i];
    if (judgingExponent(sh.subject, sh.clip, *result) != sh.k || (sh.sampler->empty() && !result->empty())) {
      verdicts[i] = sampleCheck(sh.subject, sh.clip, op, *result, options_);
      continue;
    }
    together.push_back(i);
    if (sh.k == 0) {
      joint.push_back({op, *result});
    } else {
      scaled.push_back(scaledBy(*result, sh.k));
      joint.push_back({op, scaled.back()});
    }
  }
  std::vector<SampleVerdict> judged = sh.sampler->check(joint);
  for (std::size_t j = 0; j < together.size(); ++j) {
    SampleVerdict& v = verdicts[together[j]];
    v = judged[j];
    v.delta = std::ldexp(v.delta, -sh.k);
    if (v.firstMismatch) v.firstMismatch = scaledBy(*v.firstMismatch, -sh.k);
  }
  return verdicts;
}

}  // namespace gh::oracle
