#include "ghclip/validate.h"

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

}  // namespace

namespace detail {

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

// At least 3 distinct vertices? One pass: the first vertex, one different from it, and one
// different from both (no sort: this runs on every input of every clip).
bool hasThreeDistinct(const Point* begin, const Point* end) {
  if (end - begin < 3) return false;
  const Point a = *begin;
  const Point* i = begin + 1;
  while (i != end && *i == a) ++i;
  if (i == end) return false;
  const Point b = *i;
  for (; i != end; ++i) {
    if (*i != a && *i != b) return true;
  }
  return false;
}

void throwTooFewVertices(std::size_t r) {
  throw InvalidInput("ring " + std::to_string(r + 1) + " has fewer than 3 distinct vertices");
}

}  // namespace detail

Region normalized(const Region& region, OnBadRing onBadRing) {
  Region out;
  out.reserve(region.size());
  for (std::size_t r = 0; r < region.size(); ++r) {
    const Ring& in = region[r];
    detail::checkCoordinates(in, r);
    Ring ring;
    ring.reserve(in.size());
    for (const Point& p : in) {
      if (ring.empty() || ring.back() != p) ring.push_back(p);
    }
    while (ring.size() > 1 && ring.back() == ring.front()) ring.pop_back();
    if (!detail::hasThreeDistinct(ring.data(), ring.data() + ring.size())) {
      if (onBadRing == OnBadRing::Drop) continue;
      detail::throwTooFewVertices(r);
    }
    out.push_back(std::move(ring));
  }
  return out;
}

}  // namespace gh
