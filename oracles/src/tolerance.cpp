#include "ghoracle/tolerance.h"

#include <cmath>
#include <limits>
#include <unordered_set>

#include "judging_scale.h"

namespace gh::oracle {
namespace {

struct PointHash {
  std::size_t operator()(const Point& p) const {
    return std::hash<double>()(p.x) * 31 + std::hash<double>()(p.y);
  }
};

double ulpOf(double m) {
  if (m == 0) return std::numeric_limits<double>::denorm_min();
  return std::nextafter(m, std::numeric_limits<double>::infinity()) - m;
}

}  // namespace

double constructionDisplacement(const Region& subject, const Region& clip, const Region& result) {
  return kConstructionUlps * ulpOf(largestMagnitude(subject, clip, result)) * std::sqrt(2.0);
}

double roundingTolerance(const Region& subject, const Region& clip, const Region& result, double displacement) {
  std::unordered_set<Point, PointHash> inputVertices;
  for (const Region* r : {&subject, &clip}) {
    for (const Ring& ring : *r) inputVertices.insert(ring.begin(), ring.end());
  }
  double tolerance = 0;
  for (const Ring& ring : result) {
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point& v = ring[i];
      if (inputVertices.count(v)) continue;
      const Point& a = ring[(i + n - 1) % n];
      const Point& b = ring[(i + 1) % n];
      // hypot avoids overflow at 1e150 scales.
      tolerance += displacement * (std::hypot(v.x - a.x, v.y - a.y) + std::hypot(b.x - v.x, b.y - v.y)) / 2;
    }
  }
  return tolerance;
}

double roundingTolerance(const Region& subject, const Region& clip, const Region& result) {
  return roundingTolerance(subject, clip, result, constructionDisplacement(subject, clip, result));
}

}  // namespace gh::oracle
