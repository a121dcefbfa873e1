#include "ghclip/polygons_with_holes.h"

#include <algorithm>
#include <sstream>

#include "ghclip/measure.h"
#include "ghclip/validate.h"
#include "operand.h"
#include "predicates/even_odd_ray.h"
#include "predicates/segment_meeting.h"
#include "search/sweep_search.h"

namespace gh {
namespace {

using detail::Sign;

// Exact orientation; the conversion's fallbacks are not reported anywhere.
Sign orientation(Point a, Point b, Point c) {
  detail::ExactCounters counters;
  return detail::orientation(a, b, c, counters);
}

// Exact even-odd test of p against one ring; p must not lie on the ring.
bool insideRing(const Ring& ring, Point p) {
  detail::ExactCounters counters;
  return detail::insideByRay(
      p,
      [&ring](auto&& visit) {
        for (std::size_t i = 0, n = ring.size(); i < n; ++i) visit(ring[i], ring[(i + 1) % n]);
      },
      counters);
}

// The orientation of a simple ring, exactly (its area in doubles underflows near 1e-300): the
// turn at its lexicographically smallest vertex, which is convex; Zero only when every vertex lies
// on one line (a simple ring cannot turn back on itself there).
Sign orientationOf(const Ring& ring) {
  const std::size_t n = ring.size();
  std::size_t m = 0;
  for (std::size_t i = 1; i < n; ++i) {
    if (ring[i].x < ring[m].x || (ring[i].x == ring[m].x && ring[i].y < ring[m].y)) m = i;
  }
  return orientation(ring[(m + n - 1) % n], ring[m], ring[(m + 1) % n]);
}

// For collinear p, q, r (q != p): does r lie back over q, towards p (or on q)? Decided by
// comparisons along an axis on which p and q differ, so nothing under- or overflows.
bool turnsBack(Point p, Point q, Point r) {
  const bool alongX = p.x != q.x;
  const int in = alongX ? detail::signOfDifference(q.x, p.x) : detail::signOfDifference(q.y, p.y);
  const int out = alongX ? detail::signOfDifference(r.x, q.x) : detail::signOfDifference(r.y, q.y);
  return in * out <= 0;
}

std::string at(Point p) {
  std::ostringstream s;
  s.precision(17);
  s << "(" << p.x << " " << p.y << ")";
  return s.str();
}

}  // namespace

PolygonsWithHoles toPolygonsWithHoles(const Region& input) {
  PolygonsWithHoles out;
  const Region region = normalized(input, OnBadRing::Throw);
  const detail::Operand op(region);
  std::vector<std::uint32_t> ringOf(op.size());
  for (std::size_t r = 0; r < op.ringCount(); ++r) {
    for (std::uint32_t v = op.ringStart[r]; v < op.ringStart[r + 1]; ++v) ringOf[v] = static_cast<std::uint32_t>(r);
  }
  // Every pair of edges with overlapping boxes: neighbours in a ring may only share their common
  // vertex (and must not fold back onto each other); all other pairs must not meet at all.
  std::optional<std::string> refusal;
  detail::SweepSearch{}.forEachCandidate(op, op, [&](std::uint32_t e, std::uint32_t f) {
    if (refusal || e >= f) return;
    const Point a = op.from(e), b = op.to(e), c = op.from(f), d = op.to(f);
    const bool eThenF = op.next[e] == f, fThenE = op.next[f] == e;
    if (eThenF || fThenE) {
      if (eThenF && fThenE) return;  // a 2-edge ring cannot pass normalisation
      // Consecutive edges p->q->r: only q is shared; collinear with r back over q is a spike.
      const Point p = eThenF ? a : c, q = eThenF ? b : d, r = eThenF ? d : b;
      if (orientation(p, q, r) == Sign::Zero && turnsBack(p, q, r)) {
        refusal = "ring " + std::to_string(ringOf[e] + 1) + " folds back on itself at " + at(q);
      }
      return;
    }
    detail::ExactCounters counters;
    if (detail::meeting(a, b, c, d, counters) != detail::Meeting::Disjoint) {
      refusal = ringOf[e] == ringOf[f]
                    ? "ring " + std::to_string(ringOf[e] + 1) + " touches or crosses itself near " + at(a)
                    : "rings " + std::to_string(ringOf[e] + 1) + " and " + std::to_string(ringOf[f] + 1) +
                          " touch or cross near " + at(a);
    }
  });
  if (refusal) {
    out.refusal = "not simple polygons with holes: " + *refusal;
    return out;
  }
  for (std::size_t r = 0; r < region.size(); ++r) {
    if (orientationOf(region[r]) == Sign::Zero) {
      out.refusal = "not simple polygons with holes: ring " + std::to_string(r + 1) + " has zero area";
      return out;
    }
  }
  // Nesting: rings are disjoint, so any vertex tells whether a ring lies inside another.
  const std::size_t n = region.size();
  std::vector<std::vector<std::size_t>> containers(n);
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = 0; j < n; ++j) {
      if (i != j && insideRing(region[j], region[i][0])) containers[i].push_back(j);
    }
  }
  std::vector<int> polygonOf(n, -1);
  auto oriented = [](Ring ring, bool ccw) {
    if ((orientationOf(ring) == Sign::Positive) != ccw) std::reverse(ring.begin(), ring.end());
    return ring;
  };
  for (std::size_t i = 0; i < n; ++i) {
    if (containers[i].size() % 2 == 0) {
      polygonOf[i] = static_cast<int>(out.polygons.size());
      out.polygons.push_back({oriented(region[i], true), {}});
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (containers[i].size() % 2 == 1) {
      // The direct container is the one that is itself inside all the others.
      std::size_t parent = containers[i][0];
      for (std::size_t j : containers[i]) {
        if (containers[j].size() > containers[parent].size()) parent = j;
      }
      out.polygons[static_cast<std::size_t>(polygonOf[parent])].holes.push_back(oriented(region[i], false));
    }
  }
  return out;
}

Region toRegion(const std::vector<PolygonWithHoles>& polygons) {
  Region out;
  for (const PolygonWithHoles& p : polygons) {
    out.push_back(p.shell);
    for (const Ring& h : p.holes) out.push_back(h);
  }
  return out;
}

}  // namespace gh
