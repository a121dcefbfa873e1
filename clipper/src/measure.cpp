#include "ghclip/measure.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "ghclip/errors.h"
#include "predicates/even_odd_ray.h"
#include "predicates/segment_meeting.h"
#include "recycled.h"

namespace gh {
namespace {

struct Segment {
  Point a, b;  // a.x < b.x
  double yAt(double x) const {
    if (x <= a.x) return a.y;
    if (x >= b.x) return b.y;
    return a.y + (b.y - a.y) * ((x - a.x) / (b.x - a.x));
  }
};

// x of the proper crossing of two segments, if they cross at an interior point.
bool properCrossingX(const Segment& s, const Segment& t, double& x) {
  detail::ExactCounters counters;  // measurement, not a clip: its fallbacks are not reported
  if (detail::meeting(s.a, s.b, t.a, t.b, counters) != detail::Meeting::Crossing) return false;
  const double d1 = (s.b.x - s.a.x) * (t.a.y - s.a.y) - (s.b.y - s.a.y) * (t.a.x - s.a.x);
  const double d2 = (s.b.x - s.a.x) * (t.b.y - s.a.y) - (s.b.y - s.a.y) * (t.b.x - s.a.x);
  const double alpha = d1 / (d1 - d2);  // along t
  x = t.a.x + alpha * (t.b.x - t.a.x);
  // The crossing lies in both segments' x-ranges. Nearly parallel segments can cancel d1 - d2
  // to 0 in doubles although they cross (0/0), or round x just outside: clamp into the range.
  const double lo = std::max(s.a.x, t.a.x), hi = std::min(s.b.x, t.b.x);
  if (!(x >= lo)) x = std::isnan(x) ? (lo + hi) / 2 : lo;
  if (x > hi) x = hi;
  return true;
}

// The exact predicates below fall back to GMP, which cannot hold NaN or infinity (it raises
// SIGFPE): a non-finite coordinate is refused first.
void requireFinite(Point p, const char* what) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw InvalidInput(std::string(what) + " has a non-finite coordinate");
}
void requireFinite(const Region& region, const char* what) {
  for (const Ring& ring : region) {
    for (const Point& p : ring) requireFinite(p, what);
  }
}

}  // namespace

double signedArea(const Ring& ring) {
  double twice = 0;
  for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
    const Point& p = ring[i];
    const Point& q = ring[(i + 1) % n];
    twice += (p.x - q.x) * (p.y + q.y);
  }
  return twice / 2;
}

std::size_t vertexCount(const Region& region) {
  std::size_t n = 0;
  for (const Ring& r : region) n += r.size();
  return n;
}

bool insideEvenOdd(const Region& region, Point p) {
  requireFinite(p, "the point");
  requireFinite(region, "the region");
  detail::ExactCounters counters;
  return detail::insideByRay(
      p,
      [&region](auto&& visit) {
        for (const Ring& ring : region) {
          for (std::size_t i = 0, n = ring.size(); i < n; ++i) visit(ring[i], ring[(i + 1) % n]);
        }
      },
      counters);
}

double evenOddArea(const Region& region) {
  requireFinite(region, "the region");
  // Scratch kept per thread: the invariant judges measure every answer of every fuzz execution,
  // and a dozen growing vectors per call cost more than the sweep on their small regions.
  struct Active {
    const Segment* segment;
    double y0, y1;  // its heights at the slab's boundaries (y0: computed as the last slab's y1)
  };
  struct Scratch {
    std::vector<Segment> segs;
    std::vector<double> xs;
    std::vector<Active> active;
    std::vector<std::pair<double, std::size_t>> spanning;  // (its boundary heights summed, place in active)
  };
  thread_local Scratch scratch;
  std::vector<Segment>& segs = scratch.segs;
  std::vector<double>& xs = scratch.xs;
  segs.clear(), xs.clear();
  for (const Ring& ring : region) {
    for (std::size_t i = 0, n = ring.size(); i < n; ++i) {
      Point a = ring[i], b = ring[(i + 1) % n];
      xs.push_back(a.x);
      if (a.x == b.x) continue;  // vertical edges bound no slab
      if (b.x < a.x) std::swap(a, b);
      segs.push_back({a, b});
    }
  }
  std::sort(segs.begin(), segs.end(), [](const Segment& s, const Segment& t) { return s.a.x < t.a.x; });
  bool huge = false;  // a height whose double would overflow in a sum of two
  for (const Segment& s : segs) huge = huge || std::max(std::abs(s.a.y), std::abs(s.b.y)) >= 0x1p1022;
  // A proper crossing lies strictly inside both segments' x- and y-ranges (neither is vertical):
  // pairs whose ranges only touch or miss are passed over before the four orientations.
  for (std::size_t i = 0; i < segs.size(); ++i) {
    const Segment& s = segs[i];
    const double sy0 = std::min(s.a.y, s.b.y), sy1 = std::max(s.a.y, s.b.y);
    for (std::size_t j = i + 1; j < segs.size() && segs[j].a.x < s.b.x; ++j) {
      const Segment& t = segs[j];
      if (std::max(t.a.y, t.b.y) <= sy0 || std::min(t.a.y, t.b.y) >= sy1) continue;
      double x;
      if (properCrossingX(s, t, x)) xs.push_back(x);
    }
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());

  // Slab by slab, the segments spanning it ordered by the sum of their heights at its two
  // boundaries and paired off. No two of them cross inside the slab (their crossings bound
  // slabs), so one lying below another is lower at both boundaries, and its rounded sum is never
  // the larger. (Their height at the slab's middle was the key before, but between two adjacent
  // doubles the middle rounds to one of them, where segments meeting there tie: a triangle one ulp
  // wide was measured as 0.) Halves are summed where a height is near the top of the range.
  // A segment's height at a boundary is computed once, at the slab it closes, and reused as the
  // next slab's left one (the same division: the same bits).
  double area = 0;
  std::vector<Active>& active = scratch.active;
  std::vector<std::pair<double, std::size_t>>& spanning = scratch.spanning;
  active.clear();
  std::size_t nextSeg = 0;
  for (std::size_t k = 0; k + 1 < xs.size(); ++k) {
    const double x0 = xs[k], x1 = xs[k + 1];
    active.erase(std::remove_if(active.begin(), active.end(), [x0](const Active& s) { return s.segment->b.x <= x0; }),
                 active.end());
    // Entering segments go after the ones still active, in the order they were sorted in. (The
    // sort below is not stable: segments with equal keys coincide across the slab, or nearly,
    // their sums rounding alike, and pairing them either way differs by that rounding at most.)
    while (nextSeg < segs.size() && segs[nextSeg].a.x <= x0) {
      const Segment& s = segs[nextSeg++];
      if (s.b.x > x0) active.push_back({&s, s.yAt(x0), 0});
    }
    spanning.clear();
    for (std::size_t i = 0; i < active.size(); ++i) {
      active[i].y1 = active[i].segment->yAt(x1);
      const double y0 = active[i].y0, y1 = active[i].y1;
      spanning.emplace_back(huge ? y0 / 2 + y1 / 2 : y0 + y1, i);
    }
    std::sort(spanning.begin(), spanning.end(), [](const auto& u, const auto& v) { return u.first < v.first; });
    for (std::size_t i = 0; i + 1 < spanning.size(); i += 2) {
      const Active& lo = active[spanning[i].second];
      const Active& hi = active[spanning[i + 1].second];
      const double h0 = hi.y0 - lo.y0, h1 = hi.y1 - lo.y1;
      area += (h0 + h1) / 2 * (x1 - x0);
    }
    for (Active& s : active) s.y0 = s.y1;
  }
  // A huge region's scratch is not kept for good (recycled.h's limit, as for the clip's spares).
  const std::size_t bytes = segs.capacity() * sizeof(Segment) + xs.capacity() * sizeof(double) +
                            active.capacity() * sizeof(Active) + spanning.capacity() * sizeof(spanning[0]);
  if (bytes > detail::kKeepBytes) scratch = Scratch();
  return area;
}

}  // namespace gh
