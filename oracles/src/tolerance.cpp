#include "ghoracle/tolerance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <unordered_set>

#include "point_hash.h"
#include "ulp.h"

namespace gh::oracle {

double roundingAllowance(const Region& subject, const Region& clip, const Region& result, int ulps,
                         double ulpFloor) {
  std::unordered_set<Point, PointHash> inputVertices;
  for (const Region* r : {&subject, &clip}) {
    for (const Ring& ring : *r) inputVertices.insert(ring.begin(), ring.end());
  }
  double allowance = 0;
  for (const Ring& ring : result) {
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point& v = ring[i];
      if (inputVertices.count(v)) continue;
      const Point& a = ring[(i + n - 1) % n];
      const Point& b = ring[(i + 1) % n];
      const double displacement = ulps * ulpOf(std::max(std::abs(v.x), std::abs(v.y)), ulpFloor) * std::sqrt(2.0);
      // hypot avoids overflow at 1e150 scales.
      allowance += displacement * (std::hypot(v.x - a.x, v.y - a.y) + std::hypot(b.x - v.x, b.y - v.y)) / 2;
    }
  }
  return allowance;
}

}  // namespace gh::oracle
