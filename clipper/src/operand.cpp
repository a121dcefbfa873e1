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

}  // namespace gh::detail
