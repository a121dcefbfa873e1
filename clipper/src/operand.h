// One operand (subject or clip) flattened for phase 1: all vertices of all rings in one array.
// Edge e runs from vertices[e] to vertices[next[e]], so edges and vertices share indices.
#pragma once

#include <cstdint>
#include <vector>

#include "ghclip/region.h"
#include "ghclip/validate.h"

namespace gh::detail {

struct Operand {
  std::vector<Point> vertices;
  std::vector<std::uint32_t> next;       // next vertex in the same ring
  std::vector<std::uint32_t> ringStart;  // first vertex of each ring, plus one past the end

  // Copies the region as it is (callers that validated it already).
  explicit Operand(const Region& region);
  // Validates while copying, with normalized()'s rules: drops consecutive duplicates and the
  // closing vertex, throws InvalidInput (or drops the ring) like normalized() does.
  Operand(const Region& region, bool dropBadRings);
  // Rings already flat: ring k is points[ringStarts[k] .. ringStarts[k + 1]) (none empty).
  Operand(const std::vector<Point>& points, const std::vector<std::uint32_t>& ringStarts);

  std::size_t ringCount() const { return ringStart.size() - 1; }
  std::size_t size() const { return vertices.size(); }
  Point from(std::uint32_t edge) const { return vertices[edge]; }
  Point to(std::uint32_t edge) const { return vertices[next[edge]]; }

 private:
  void linkRings();  // next[] from ringStart: each ring's last vertex links back to its first
};

}  // namespace gh::detail
