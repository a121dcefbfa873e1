#include "operand.h"

#include <limits>
#include <stdexcept>

namespace gh::detail {

Operand::Operand(const Region& region) {
  std::size_t total = 0;
  for (const Ring& ring : region) total += ring.size();
  // Vertex ids are 32-bit (half the memory of the linked lists); the graph also needs room for
  // intersection nodes, so stay well clear of the limit.
  if (total >= std::numeric_limits<std::uint32_t>::max() / 4) {
    throw std::length_error("ghclip: operand has too many vertices");
  }
  vertices.reserve(total);
  next.reserve(total);
  ringStart.reserve(region.size() + 1);
  for (const Ring& ring : region) {
    const auto first = static_cast<std::uint32_t>(vertices.size());
    ringStart.push_back(first);
    for (std::size_t i = 0; i < ring.size(); ++i) {
      vertices.push_back(ring[i]);
      next.push_back(i + 1 < ring.size() ? static_cast<std::uint32_t>(first + i + 1) : first);
    }
  }
  ringStart.push_back(static_cast<std::uint32_t>(vertices.size()));
}

void Operand::linkRings() {
  next.resize(vertices.size());
  for (std::size_t k = 0; k + 1 < ringStart.size(); ++k) {
    for (std::uint32_t v = ringStart[k]; v < ringStart[k + 1]; ++v) next[v] = v + 1 < ringStart[k + 1] ? v + 1 : ringStart[k];
  }
}

Operand::Operand(const std::vector<Point>& points, const std::vector<std::uint32_t>& ringStarts)
    : vertices(points), ringStart(ringStarts) {
  linkRings();
}

Operand::Operand(const Region& region, bool dropBadRings) {
  std::size_t total = 0;
  for (const Ring& ring : region) total += ring.size();
  if (total >= std::numeric_limits<std::uint32_t>::max() / 4) {
    throw std::length_error("ghclip: operand has too many vertices");
  }
  vertices.reserve(total);
  ringStart.reserve(region.size() + 1);
  for (std::size_t r = 0; r < region.size(); ++r) {
    const Ring& ring = region[r];
    checkCoordinates(ring, r);
    const std::size_t first = vertices.size();
    for (const Point& p : ring) {
      if (vertices.size() == first || vertices.back() != p) vertices.push_back(p);
    }
    while (vertices.size() > first + 1 && vertices.back() == vertices[first]) vertices.pop_back();
    if (!hasThreeDistinct(vertices.data() + first, vertices.data() + vertices.size())) {
      if (!dropBadRings) throwTooFewVertices(r);
      vertices.resize(first);
      continue;
    }
    ringStart.push_back(static_cast<std::uint32_t>(first));
  }
  ringStart.push_back(static_cast<std::uint32_t>(vertices.size()));
  linkRings();
}

}  // namespace gh::detail
