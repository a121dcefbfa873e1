#include "ghclip/measure.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "ghclip/errors.h"
#include "predicates/even_odd_ray.h"
#include "predicates/segment_meeting.h"

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
  std::vector<Segment> segs;
  std::vector<double> xs;
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

  double area = 0;
  std::vector<const Segment*> active;
  std::vector<std::pair<double, const Segment*>> spanning;
  std::size_t nextSeg = 0;
  for (std::size_t k = 0; k + 1 < xs.size(); ++k) {
    const double x0 = xs[k], x1 = xs[k + 1], xm = (x0 + x1) / 2;
    while (nextSeg < segs.size() && segs[nextSeg].a.x <= x0) active.push_back(&segs[nextSeg++]);
    active.erase(std::remove_if(active.begin(), active.end(),
                                [x0](const Segment* s) { return s->b.x <= x0; }),
                 active.end());
    spanning.clear();
    for (const Segment* s : active) spanning.emplace_back(s->yAt(xm), s);
    std::sort(spanning.begin(), spanning.end(),
              [](const auto& u, const auto& v) { return u.first < v.first; });
    for (std::size_t i = 0; i + 1 < spanning.size(); i += 2) {
      const Segment& lo = *spanning[i].second;
      const Segment& hi = *spanning[i + 1].second;
      const double h0 = hi.yAt(x0) - lo.yAt(x0), h1 = hi.yAt(x1) - lo.yAt(x1);
      area += (h0 + h1) / 2 * (x1 - x0);
    }
  }
  return area;
}

}  // namespace gh
