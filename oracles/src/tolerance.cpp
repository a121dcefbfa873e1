#include "ghoracle/tolerance.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "ulp.h"

namespace gh::oracle {

double roundingAllowance(const Region& subject, const Region& clip, const Region& result, int ulps,
                         double ulpFloor) {
  // The input vertices, sorted, in scratch kept per thread (the invariant judges ask this of every
  // answer of every fuzz execution; a node per vertex in a hash set cost more than the sum).
  // NaN left out: it equals nothing (the hash set found no vertex with one), and would break the order.
  thread_local std::vector<Point> inputVertices;
  inputVertices.clear();
  for (const Region* r : {&subject, &clip}) {
    for (const Ring& ring : *r) {
      for (const Point& p : ring) {
        if (!std::isnan(p.x) && !std::isnan(p.y)) inputVertices.push_back(p);
      }
    }
  }
  const auto less = [](const Point& a, const Point& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); };
  std::sort(inputVertices.begin(), inputVertices.end(), less);
  auto isInputVertex = [&](const Point& v) {
    return !std::isnan(v.x) && !std::isnan(v.y) && std::binary_search(inputVertices.begin(), inputVertices.end(), v, less);
  };
  double allowance = 0;
  for (const Ring& ring : result) {
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i < n; ++i) {
      const Point& v = ring[i];
      if (isInputVertex(v)) continue;
      const Point& a = ring[(i + n - 1) % n];
      const Point& b = ring[(i + 1) % n];
      const double displacement = ulps * ulpOf(std::max(std::abs(v.x), std::abs(v.y)), ulpFloor) * std::sqrt(2.0);
      // hypot avoids overflow at 1e150 scales.
      allowance += displacement * (std::hypot(v.x - a.x, v.y - a.y) + std::hypot(b.x - v.x, b.y - v.y)) / 2;
    }
  }
  // A huge problem's vertices are not kept for good.
  if (inputVertices.capacity() > (std::size_t{64} << 20) / sizeof(Point)) std::vector<Point>().swap(inputVertices);
  return allowance;
}

}  // namespace gh::oracle
