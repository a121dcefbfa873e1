// Rings in one flat array, as phase 3 traces them and clean-up trims them: ring r is
// points[start[r] .. start[r + 1]). One growing array instead of one vector per ring while the
// answer is built; the answer's Region is made from it once, each ring at its final size.
#pragma once

#include <cstdint>
#include <vector>

#include "ghclip/region.h"

namespace gh::detail {

struct FlatRings {
  std::vector<Point> points;
  std::vector<std::uint32_t> start{0};

  std::size_t size() const { return start.size() - 1; }
  // Ends the ring begun after the previous one (an empty ring is allowed, and skipped by toRegion).
  void closeRing() { start.push_back(static_cast<std::uint32_t>(points.size())); }
  void append(const Ring& ring) {
    points.insert(points.end(), ring.begin(), ring.end());
    closeRing();
  }

  Region toRegion() const {
    Region out;
    out.reserve(size());
    for (std::size_t r = 0; r < size(); ++r) {
      if (start[r + 1] > start[r]) out.emplace_back(points.begin() + start[r], points.begin() + start[r + 1]);
    }
    return out;
  }
  static FlatRings from(const Region& region) {
    FlatRings f;
    for (const Ring& ring : region) f.append(ring);
    return f;
  }
};

}  // namespace gh::detail
