#include "ghclip/validate.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "ghclip/errors.h"

namespace gh {
namespace {

std::string where(std::size_t ring, std::size_t vertex) {
  std::ostringstream s;
  s << "ring " << ring + 1 << ", vertex " << vertex + 1;
  return s.str();
}

void checkCoordinates(const Ring& ring, std::size_t r) {
  for (std::size_t v = 0; v < ring.size(); ++v) {
    for (double c : {ring[v].x, ring[v].y}) {
      if (!std::isfinite(c)) {
        throw InvalidInput(where(r, v) + ": coordinate is not finite (" + std::to_string(c) + ")");
      }
      if (std::abs(c) > kMaxCoordinate) {
        std::ostringstream s;
        s << where(r, v) << ": |coordinate| " << c << " exceeds the limit 2^500 (~3.3e150)";
        throw InvalidInput(s.str());
      }
    }
  }
}

std::size_t distinctCount(const Ring& ring) {
  std::vector<std::pair<double, double>> pts;
  pts.reserve(ring.size());
  for (const Point& p : ring) pts.emplace_back(p.x, p.y);
  std::sort(pts.begin(), pts.end());
  return static_cast<std::size_t>(std::unique(pts.begin(), pts.end()) - pts.begin());
}

}  // namespace

Region normalized(const Region& region, OnBadRing onBadRing) {
  Region out;
  out.reserve(region.size());
  for (std::size_t r = 0; r < region.size(); ++r) {
    const Ring& in = region[r];
    checkCoordinates(in, r);
    Ring ring;
    ring.reserve(in.size());
    for (const Point& p : in) {
      if (ring.empty() || ring.back() != p) ring.push_back(p);
    }
    while (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
    if (ring.size() < 3 || distinctCount(ring) < 3) {
      if (onBadRing == OnBadRing::Drop) continue;
      throw InvalidInput("ring " + std::to_string(r + 1) + " has fewer than 3 distinct vertices");
    }
    out.push_back(std::move(ring));
  }
  return out;
}

}  // namespace gh
