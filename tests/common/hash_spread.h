// How well a point hash spreads the points that degenerate inputs are made of over the slots of
// an open-addressing table (indexed by the hash's low bits): small integers and dyadic fractions,
// whose doubles have their low bits all zero. A hash that does not mix the high bits down puts
// them all in a few slots, and every lookup then walks all of them.
#pragma once

#include <cmath>
#include <cstdint>
#include <set>
#include <vector>

#include "ghclip/region.h"

namespace gh::test {

// Grid points: the 9 x 9 integer grid of the fuzz targets' mode 0, a 64 x 64 grid of multiples
// of 8 and of -4 (coarser, negative coordinates too), and a 64 x 64 integer grid moved by 2^-20.
inline std::vector<std::vector<Point>> gridPointSets() {
  std::vector<Point> small, halves, moved;
  for (int i = 0; i <= 8; ++i) for (int j = 0; j <= 8; ++j) small.push_back({double(i), double(j)});
  for (int i = 0; i < 64; ++i) {
    for (int j = 0; j < 64; ++j) {
      halves.push_back({16.0 * i * 0.5, -8.0 * j * 0.5});
      moved.push_back({i + std::ldexp(1.0, -20), j - std::ldexp(1.0, -20)});
    }
  }
  return {small, halves, moved};
}

// The distinct slots that `points` occupy in a table of `slots` (a power of two) as a fraction of
// what a uniformly random hash would be expected to fill: slots * (1 - (1 - 1/slots)^n).
template <class Hash>
double spreadOverSlots(const std::vector<Point>& points, std::uint64_t slots, Hash hash) {
  std::set<std::uint64_t> used;
  for (const Point& p : points) used.insert(static_cast<std::uint64_t>(hash(p)) & (slots - 1));
  const double expected = slots * (1 - std::pow(1 - 1.0 / slots, static_cast<double>(points.size())));
  return used.size() / expected;
}

}  // namespace gh::test
