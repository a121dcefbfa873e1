// Why the bound holds. The even-odd parity of a point off the segments is the parity of the
// number of segments a ray from it crosses: a sum, mod 2, over the segments. So the segments
// that a and b share (as undirected segments, counted with multiplicity) cancel in pairs, and the
// rest, L, has the parity of a XOR b; every vertex of L has even degree.
//
// Map each vertex v of L to a representative r(v) near it (itself, or a vertex of L found
// earlier within a small distance). Each segment pq of L closes into the path
// p -> q -> r(q) -> r(p) -> p. The parities of all these paths sum to L's, plus each rung v r(v)
// counted deg(v) times (even: they cancel), plus each contracted segment r(p) r(q) once per
// segment of L that maps to it; those counted an even number of times cancel too. What is
// left, L', is closed again (contraction keeps degrees even). So L's even-odd region lies in the
// union of the paths' regions and L''s. A path's region lies in its fan triangles from p,
// (p, q, r(q)) and (p, r(q), r(p)); each connected part of L' in its fan triangles from one of
// its vertices (the parity of a closed set is the sum of those triangles' parities). The bound
// is all these triangles' areas summed. Two answers whose constructed vertices differ by a few
// ulps give slivers only: the triangles are the slivers, and the bound is close to their area;
// an edge that one answer splits at a vertex (nearly) on it and the other does not leaves that
// thin triangle in L'. Any choice of representatives gives a true bound; a poor one, or answers
// that truly differ, give a large bound, and the caller builds the arrangement.
#include "difference_bound.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>
#include <vector>

#include "filtered_orientation.h"
#include "ghclip/validate.h"

namespace gh::oracle {
namespace {

struct Segment {
  Point a, b;  // a before b lexicographically
};

bool lexLess(const Point& p, const Point& q) { return std::tie(p.x, p.y) < std::tie(q.x, q.y); }

// A region's segments, without a normalized copy: a ring that normalized() would drop (fewer
// than 3 distinct vertices) runs along each of its segments an even number of times, and they
// cancel below anyway. Its coordinates are checked as normalized() checks them.
void addSegments(const Region& region, std::vector<Segment>& out) {
  for (std::size_t r = 0; r < region.size(); ++r) {
    const Ring& ring = region[r];
    detail::checkCoordinates(ring, r);
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      Point p = ring[i], q = ring[(i + 1) % n];
      if (p == q) continue;
      if (lexLess(q, p)) std::swap(p, q);
      out.push_back({p, q});
    }
  }
}

bool segmentLess(const Segment& s, const Segment& t) {
  return std::tie(s.a.x, s.a.y, s.b.x, s.b.y) < std::tie(t.a.x, t.a.y, t.b.x, t.b.y);
}
bool sameSegment(const Segment& s, const Segment& t) { return s.a == t.a && s.b == t.b; }

// Keeps the segments that occur an odd number of times, once each, sorted.
void keepOdd(std::vector<Segment>& segments) {
  std::sort(segments.begin(), segments.end(), segmentLess);
  std::size_t kept = 0;
  for (std::size_t i = 0; i < segments.size();) {
    std::size_t j = i + 1;
    while (j < segments.size() && sameSegment(segments[j], segments[i])) ++j;
    if ((j - i) % 2 == 1) segments[kept++] = segments[i];
    i = j;
  }
  segments.resize(kept);
}

// An upper bound on twice the area of triangle (p, q, s): |(q - p) x (s - p)| computed in
// doubles plus the judges' orientation filter's bound on its rounding error, with room for
// products below the normal range. Infinite or NaN when a product overflows.
double twiceTriangleBound(Point p, Point q, Point s) {
  const double l = (q.x - p.x) * (s.y - p.y), r = (q.y - p.y) * (s.x - p.x);
  return std::abs(l - r) + kOrientationErrorFactor * (std::abs(l) + std::abs(r)) + 0x1p-1070;
}

// The segments' ends, sorted, without repeats.
void listVertices(const std::vector<Segment>& segments, std::vector<Point>& vertices) {
  vertices.clear();
  for (const Segment& s : segments) vertices.push_back(s.a), vertices.push_back(s.b);
  std::sort(vertices.begin(), vertices.end(), lexLess);
  vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
}

// Scratch kept per thread: the differential fuzz target asks for five bounds per execution, and
// fresh vectors (from the sanitizers' allocator there) cost more than the bound's arithmetic.
struct Scratch {
  std::vector<Segment> odd, split, contracted;
  std::vector<Point> before, vertices, representative;
  std::vector<std::pair<double, Point>> on;  // (place along a segment, vertex)
  std::vector<std::size_t> part;

  std::size_t bytes() const {
    return (odd.capacity() + split.capacity() + contracted.capacity()) * sizeof(Segment) +
           (before.capacity() + vertices.capacity() + representative.capacity()) * sizeof(Point) +
           on.capacity() * sizeof(on[0]) + part.capacity() * sizeof(std::size_t);
  }
};

}  // namespace

static std::optional<double> boundUsing(const Region& a, const Region& b, Scratch& scratch) {
  std::vector<Segment>& odd = scratch.odd;
  odd.clear();
  addSegments(a, odd);
  addSegments(b, odd);
  keepOdd(odd);
  if (odd.empty()) return 0.0;

  // `near`: far above the few ulps by which two answers' constructed vertices differ, far below
  // the distances between the features of a problem of a few dozen vertices. It decides which
  // splits and representatives are tried, never whether the bound holds (see above).
  double largest = 0;
  for (const Segment& s : odd) {
    largest = std::max({largest, std::abs(s.a.x), std::abs(s.a.y), std::abs(s.b.x), std::abs(s.b.y)});
  }
  const double near = std::max(largest * 0x1p-30, 0x1p-1000);
  double twice = 0;

  // A segment pq with vertices x1 .. xk of L (nearly) on it, in order from p, is p x1 and x1 q
  // and the closed path p x1 q p, whose region is the triangle (p, x1, q); then x1 q likewise:
  // an edge that one answer splits (at a vertex of its own, or where the other answer's ring
  // crosses itself) and the other does not.
  std::vector<Point>& before = scratch.before;
  listVertices(odd, before);
  std::vector<Segment>& split = scratch.split;
  split.clear();
  std::vector<std::pair<double, Point>>& on = scratch.on;
  for (const Segment& s : odd) {
    const double dx = s.b.x - s.a.x, dy = s.b.y - s.a.y, length2 = dx * dx + dy * dy;
    on.clear();
    // Only vertices within `near` of the segment's x-range can be near it (s.a.x <= s.b.x).
    const auto first = std::lower_bound(before.begin(), before.end(), s.a.x - near,
                                        [](const Point& v, double x) { return v.x < x; });
    for (auto it = first; it != before.end() && it->x <= s.b.x + near; ++it) {
      const Point& v = *it;
      if (v == s.a || v == s.b) continue;
      const double t = ((v.x - s.a.x) * dx + (v.y - s.a.y) * dy) / length2;
      const double cross = (v.y - s.a.y) * dx - (v.x - s.a.x) * dy;
      if (t > 0 && t < 1 && cross * cross <= near * near * length2) on.emplace_back(t, v);
    }
    if (on.empty()) {
      split.push_back(s);
      continue;
    }
    std::sort(on.begin(), on.end(), [](const auto& l, const auto& r) { return l.first < r.first; });
    Point from = s.a;
    for (const auto& [t, v] : on) {
      if (v == from) continue;
      split.push_back(lexLess(from, v) ? Segment{from, v} : Segment{v, from});
      twice += twiceTriangleBound(from, v, s.b);  // from b is from v b, v b and the triangle's path
      from = v;
    }
    split.push_back(lexLess(from, s.b) ? Segment{from, s.b} : Segment{s.b, from});
  }
  keepOdd(split);
  odd.swap(split);

  // Representatives: a vertex's is the first vertex before it (lexicographically) within `near`
  // in both coordinates that is its own, else itself.
  std::vector<Point>& vertices = scratch.vertices;
  listVertices(odd, vertices);
  std::vector<Point>& representative = scratch.representative;
  representative.resize(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    representative[i] = vertices[i];
    for (std::size_t j = i; j-- > 0 && vertices[i].x - vertices[j].x <= near;) {
      if (representative[j] == vertices[j] && std::abs(vertices[i].y - vertices[j].y) <= near) {
        representative[i] = vertices[j];
      }
    }
  }
  auto indexOf = [&](const Point& v) {
    return static_cast<std::size_t>(std::lower_bound(vertices.begin(), vertices.end(), v, lexLess) - vertices.begin());
  };
  std::vector<Segment>& contracted = scratch.contracted;
  contracted.clear();
  for (const Segment& s : odd) {
    const Point rp = representative[indexOf(s.a)], rq = representative[indexOf(s.b)];
    if (rp != rq) contracted.push_back(lexLess(rp, rq) ? Segment{rp, rq} : Segment{rq, rp});
    twice += twiceTriangleBound(s.a, s.b, rq) + twiceTriangleBound(s.a, rq, rp);
  }

  // What the contracted segments leave (answers that truly differ): a closed set again, each of
  // its connected parts bounded by its fan triangles from one of its vertices.
  keepOdd(contracted);
  const std::vector<Segment>& left = contracted;
  std::vector<std::size_t>& part = scratch.part;
  part.resize(vertices.size());
  for (std::size_t i = 0; i < part.size(); ++i) part[i] = i;
  auto root = [&](std::size_t i) {
    while (part[i] != i) i = part[i] = part[part[i]];
    return i;
  };
  for (const Segment& s : left) part[root(indexOf(s.a))] = root(indexOf(s.b));
  for (const Segment& s : left) twice += twiceTriangleBound(vertices[root(indexOf(s.a))], s.a, s.b);
  if (!std::isfinite(twice)) return std::nullopt;
  // The sum of n non-negative doubles is within (1 + n u) of the true sum, n far below 2^20; the
  // last term covers halving a subnormal.
  return twice / 2 * (1 + 0x1p-30) + 0x1p-1074;
}

std::optional<double> symmetricDifferenceBound(const Region& a, const Region& b) {
  thread_local Scratch scratch;
  std::optional<double> bound = boundUsing(a, b, scratch);
  if (scratch.bytes() > (std::size_t{64} << 20)) scratch = Scratch();  // a huge pair's is not kept
  return bound;
}

}  // namespace gh::oracle
