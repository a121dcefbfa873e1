#include "ghclip/ogc_validity.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <unordered_map>
#include <unordered_set>

#include "operand.h"
#include "point_hash.h"
#include "predicates/orientation.h"
#include "predicates/segment_meeting.h"
#include "search/box_overlaps.h"
#include "search/edge_slabs.h"

namespace gh {
namespace {

using detail::ExactCounters;
using detail::Sign;

std::string at(Point p) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << p.x << " " << p.y << ")";
  return s.str();
}

bool lexLess(Point a, Point b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

// For collinear directions w -> a and w -> b: do they point the same way?
bool sameWay(Point w, Point a, Point b) {
  if (w.x != a.x) return detail::signOfDifference(a.x, w.x) == detail::signOfDifference(b.x, w.x);
  return detail::signOfDifference(a.y, w.y) == detail::signOfDifference(b.y, w.y);
}

// Upper half-plane (with +x) before the lower one, then counter-clockwise: the order of
// directions from o, for telling whether two rings cross where they touch.
struct AroundPoint {
  Point o;
  ExactCounters* counters;
  int half(Point t) const { return t.y > o.y || (t.y == o.y && t.x > o.x) ? 0 : 1; }
  bool operator()(Point a, Point b) const {
    const int ha = half(a), hb = half(b);
    if (ha != hb) return ha < hb;
    return detail::orientation(o, a, b, *counters) == Sign::Positive;
  }
};

class Validity {
 public:
  Validity(const std::vector<PolygonWithHoles>& polygons, RingOrientation orientation)
      : polygons_(polygons), orientation_(orientation) {}

  std::optional<std::string> run() {
    if (auto why = flatten()) return why;
    if (auto why = orientations()) return why;
    if (auto why = meetings()) return why;
    if (auto why = touches()) return why;
    return containment();
  }

 private:
  // "polygon 2 hole 1" (shell when ring 0).
  std::string name(std::uint32_t ring) const {
    const std::uint32_t p = polygonOf_[ring], k = ring - firstRing_[p];
    return "polygon " + std::to_string(p + 1) + (k == 0 ? " shell" : " hole " + std::to_string(k));
  }
  bool isShell(std::uint32_t ring) const { return ring == firstRing_[polygonOf_[ring]]; }

  // Every ring's vertices in one array, repeated consecutive points dropped.
  std::optional<std::string> flatten() {
    std::vector<std::uint32_t> starts{0};
    for (std::uint32_t p = 0; p < polygons_.size(); ++p) {
      firstRing_.push_back(static_cast<std::uint32_t>(starts.size() - 1));
      std::vector<const Ring*> rings{&polygons_[p].shell};
      for (const Ring& h : polygons_[p].holes) rings.push_back(&h);
      for (const Ring* ring : rings) {
        const std::uint32_t id = static_cast<std::uint32_t>(starts.size() - 1);
        const std::size_t first = points_.size();
        for (const Point& q : *ring) {
          if (!std::isfinite(q.x) || !std::isfinite(q.y)) return name(id, p) + " has a non-finite coordinate";
          if (points_.size() == first || !(points_.back() == q)) points_.push_back(q);
        }
        while (points_.size() > first + 1 && points_.back() == points_[first]) points_.pop_back();
        std::unordered_set<Point, detail::PointHash> distinct(points_.begin() + static_cast<long>(first), points_.end());
        if (distinct.size() < 3) return name(id, p) + " has fewer than 3 distinct points";
        polygonOf_.push_back(p);
        starts.push_back(static_cast<std::uint32_t>(points_.size()));
      }
    }
    firstRing_.push_back(static_cast<std::uint32_t>(starts.size() - 1));
    ops_.emplace(points_, starts);
    ringOf_.resize(points_.size());
    for (std::uint32_t r = 0; r + 1 < starts.size(); ++r) {
      for (std::uint32_t v = starts[r]; v < starts[r + 1]; ++v) ringOf_[v] = r;
    }
    return std::nullopt;
  }
  std::string name(std::uint32_t ring, std::uint32_t polygon) const {
    const std::uint32_t k = ring - firstRing_[polygon];
    return "polygon " + std::to_string(polygon + 1) + (k == 0 ? " shell" : " hole " + std::to_string(k));
  }

  std::optional<std::string> orientations() {
    if (orientation_ == RingOrientation::Any) return std::nullopt;
    const detail::Operand& op = *ops_;
    for (std::uint32_t r = 0; r < op.ringCount(); ++r) {
      const std::uint32_t first = op.ringStart[r], end = op.ringStart[r + 1];
      std::uint32_t m = first;
      for (std::uint32_t v = first + 1; v < end; ++v) {
        if (lexLess(points_[v], points_[m])) m = v;
      }
      const Point a = points_[m == first ? end - 1 : m - 1], b = points_[m], c = points_[m + 1 == end ? first : m + 1];
      const Sign turn = detail::orientation(a, b, c, counters_);
      // A zero turn at the lexicographically smallest vertex: the ring folds back there (found below).
      if (turn == Sign::Zero) continue;
      if ((turn == Sign::Positive) != isShell(r)) {
        return name(r) + (isShell(r) ? " is clockwise" : " is counter-clockwise") +
               " (RFC 7946: shells counter-clockwise, holes clockwise)";
      }
    }
    return std::nullopt;
  }

  // Every pair of edges whose boxes overlap: within a ring only neighbours meet, at their common
  // vertex; rings meet at isolated points only (kept in touches_ for the next checks).
  std::optional<std::string> meetings() {
    const detail::Operand& op = *ops_;
    std::vector<detail::Box> boxes(op.size());
    for (std::uint32_t e = 0; e < op.size(); ++e) {
      const Point a = op.from(e), b = op.to(e);
      boxes[e] = {std::min(a.x, b.x), std::max(a.x, b.x), std::min(a.y, b.y), std::max(a.y, b.y), e};
    }
    std::optional<std::string> why;
    detail::forEachOverlappingPair(boxes, [&](std::uint32_t e, std::uint32_t f) {
      if (!why) why = meet(std::min(e, f), std::max(e, f));
    });
    return why;
  }

  std::optional<std::string> meet(std::uint32_t e, std::uint32_t f) {
    const detail::Operand& op = *ops_;
    const Point a = op.from(e), b = op.to(e), c = op.from(f), d = op.to(f);
    const std::uint32_t re = ringOf_[e], rf = ringOf_[f];
    if (re == rf && (op.next[e] == f || op.next[f] == e)) {
      if (op.next[e] == f && op.next[f] == e) return std::nullopt;  // a ring of 2 edges was refused
      const Point w = op.next[e] == f ? b : a, x = op.next[e] == f ? a : b, y = op.next[e] == f ? d : c;
      if (detail::orientation(w, x, y, counters_) == Sign::Zero && sameWay(w, x, y)) {
        return name(re) + " folds back on itself at " + at(w);
      }
      return std::nullopt;
    }
    const detail::Meeting m = detail::meeting(a, b, c, d, counters_);
    if (m == detail::Meeting::Disjoint) return std::nullopt;
    if (m == detail::Meeting::Crossing) {
      return re == rf ? name(re) + " crosses itself near " + at(a) : name(re) + " and " + name(rf) + " cross near " + at(a);
    }
    // Touching: at one point, unless collinear and overlapping.
    const Sign oc = detail::orientation(a, b, c, counters_), od = detail::orientation(a, b, d, counters_);
    if (oc == Sign::Zero && od == Sign::Zero) {
      // One line: an overlap of positive length unless the segments only share an end.
      const bool axisX = a.x != b.x;
      auto key = [axisX](Point p) { return axisX ? p.x : p.y; };
      const double lo = std::max(std::min(key(a), key(b)), std::min(key(c), key(d)));
      const double hi = std::min(std::max(key(a), key(b)), std::max(key(c), key(d)));
      if (lo < hi) {
        return (re == rf ? name(re) + " runs along itself near " : name(re) + " and " + name(rf) + " share an edge near ") +
               at(a);
      }
    }
    Point p = a;
    if (oc == Sign::Zero && within(a, b, c)) {
      p = c;
    } else if (od == Sign::Zero && within(a, b, d)) {
      p = d;
    } else if (detail::orientation(c, d, a, counters_) == Sign::Zero && within(c, d, a)) {
      p = a;
    } else {
      p = b;
    }
    if (re == rf) return name(re) + " touches itself at " + at(p);
    touches_.push_back({p, e, f});
    return std::nullopt;
  }
  static bool within(Point p, Point q, Point r) {
    return std::min(p.x, q.x) <= r.x && r.x <= std::max(p.x, q.x) && std::min(p.y, q.y) <= r.y && r.y <= std::max(p.y, q.y);
  }

  // Where rings touch: they may not cross there, and a polygon's rings and the points where they
  // touch may form no cycle (its interior would fall apart).
  std::optional<std::string> touches() {
    const detail::Operand& op = *ops_;
    std::stable_sort(touches_.begin(), touches_.end(), [](const Touch& s, const Touch& t) { return lexLess(s.at, t.at); });
    std::vector<std::uint32_t> parent(op.ringCount());
    std::iota(parent.begin(), parent.end(), 0u);
    auto find = [&](std::uint32_t r) {
      while (parent[r] != r) r = parent[r] = parent[parent[r]];
      return r;
    };
    for (std::size_t i = 0, j; i < touches_.size(); i = j) {
      const Point p = touches_[i].at;
      for (j = i + 1; j < touches_.size() && touches_[j].at == p; ++j) {
      }
      // Each ring's two directions out of p: to the far ends of its edges there.
      std::unordered_map<std::uint32_t, std::vector<Point>> directions;
      std::unordered_set<std::uint32_t> edges;
      for (std::size_t k = i; k < j; ++k) edges.insert(touches_[k].e), edges.insert(touches_[k].f);
      for (const std::uint32_t e : edges) {
        std::vector<Point>& d = directions[ringOf_[e]];
        for (const Point q : {op.from(e), op.to(e)}) {
          if (!(q == p) && std::find(d.begin(), d.end(), q) == d.end()) d.push_back(q);
        }
      }
      std::vector<std::uint32_t> rings;
      for (const auto& [ring, d] : directions) rings.push_back(ring);
      std::sort(rings.begin(), rings.end());
      const AroundPoint order{p, &counters_};
      for (std::size_t x = 0; x < rings.size(); ++x) {
        std::vector<Point> a = directions[rings[x]];
        if (a.size() != 2) continue;  // its edges at p were not all seen: only its own neighbours meet it there
        if (order(a[1], a[0])) std::swap(a[0], a[1]);
        // Strictly between a[0] and a[1] counter-clockwise (no direction is shared: that overlap
        // was refused).
        auto inside = [&](Point q) { return order(a[0], q) && order(q, a[1]); };
        for (std::size_t y = x + 1; y < rings.size(); ++y) {
          const std::vector<Point>& b = directions[rings[y]];
          if (b.size() == 2 && inside(b[0]) != inside(b[1])) {
            return name(rings[x]) + " and " + name(rings[y]) + " cross at " + at(p);
          }
        }
      }
      // The touch graph of each polygon: rings and points; an edge per ring at p.
      std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> byPolygon;
      for (const std::uint32_t r : rings) byPolygon[polygonOf_[r]].push_back(r);
      for (const auto& [polygon, at_p] : byPolygon) {
        if (at_p.size() < 2) continue;
        // Joining the rings at p: a cycle when two of them are joined already.
        for (std::size_t k = 1; k < at_p.size(); ++k) {
          const std::uint32_t u = find(at_p[0]), v = find(at_p[k]);
          if (u == v) return "the interior of polygon " + std::to_string(polygon + 1) + " is disconnected at " + at(p);
          parent[v] = u;
        }
      }
    }
    return std::nullopt;
  }

  // Holes inside their shell and not inside one another, polygons not inside one another: decided
  // by rays from a vertex of each ring that no other ring touches.
  std::optional<std::string> containment() {
    const detail::Operand& op = *ops_;
    std::unordered_set<Point, detail::PointHash> touched;
    for (const Touch& t : touches_) touched.insert(t.at);
    const detail::EdgeSlabs slabs(op);
    for (std::uint32_t r = 0; r < op.ringCount(); ++r) {
      std::optional<Point> free;
      for (std::uint32_t v = op.ringStart[r]; v < op.ringStart[r + 1] && !free; ++v) {
        if (!touched.count(points_[v])) free = points_[v];
      }
      if (!free) continue;  // every vertex touches another ring: its neighbours decide around it
      const std::unordered_set<std::uint32_t> around = ringsAround(*free, r, slabs);
      const std::uint32_t p = polygonOf_[r], shell = firstRing_[p];
      if (!isShell(r)) {
        if (!around.count(shell)) return name(r) + " lies outside its shell (at " + at(*free) + ")";
        for (std::uint32_t h = shell + 1; h < firstRing_[p + 1]; ++h) {
          if (h != r && around.count(h)) return name(r) + " lies inside " + name(h);
        }
        continue;
      }
      for (const std::uint32_t q : around) {
        if (!isShell(q) || polygonOf_[q] == p) continue;
        bool inHole = false;
        for (std::uint32_t h = q + 1; h < firstRing_[polygonOf_[q] + 1]; ++h) inHole |= around.count(h) > 0;
        if (!inHole) return "polygon " + std::to_string(p + 1) + " lies inside polygon " + std::to_string(polygonOf_[q] + 1);
      }
    }
    return std::nullopt;
  }

  // The rings other than `own` around point p (on none of them): the ray from p towards +x crosses
  // each an odd number of times.
  std::unordered_set<std::uint32_t> ringsAround(Point p, std::uint32_t own, const detail::EdgeSlabs& slabs) {
    const detail::Operand& op = *ops_;
    std::unordered_set<std::uint32_t> odd;
    for (auto [it, end] = slabs.near(p.y); it != end; ++it) {
      const std::uint32_t e = *it;
      if (ringOf_[e] == own) continue;
      const Point a = op.from(e), b = op.to(e);
      const bool aAbove = a.y > p.y, bAbove = b.y > p.y;
      if (aAbove == bAbove) continue;
      const Sign s = detail::orientation(a, b, p, counters_);
      if (bAbove ? s == Sign::Positive : s == Sign::Negative) {
        if (!odd.erase(ringOf_[e])) odd.insert(ringOf_[e]);
      }
    }
    return odd;
  }

  struct Touch {
    Point at;
    std::uint32_t e, f;
  };

  const std::vector<PolygonWithHoles>& polygons_;
  RingOrientation orientation_;
  ExactCounters counters_;
  std::vector<Point> points_;
  std::optional<detail::Operand> ops_;
  std::vector<std::uint32_t> ringOf_, polygonOf_, firstRing_;
  std::vector<Touch> touches_;
};

}  // namespace

std::optional<std::string> ogcInvalidity(const std::vector<PolygonWithHoles>& polygons, RingOrientation orientation) {
  return Validity(polygons, orientation).run();
}

}  // namespace gh
