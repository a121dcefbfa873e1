// Every pair of boxes, among one list of them, whose closed boxes overlap: the candidate pairs
// of the OGC layout's noding and of its check that rounded pieces stay apart (layout/). A sweep
// over the boxes sorted by xmin with an active list, as sweepOverlaps (sweep_search.h) runs it for
// two operands, here within one list: each pair reported once.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

namespace gh::detail {

struct Box {
  double minX, maxX, minY, maxY;
  std::uint32_t id;
};

inline bool overlap(const Box& a, const Box& b) {
  return a.minX <= b.maxX && b.minX <= a.maxX && a.minY <= b.maxY && b.minY <= a.maxY;
}

// Calls visit(a.id, b.id) once for every pair of overlapping boxes; sorts `boxes` by minX.
template <class Visit>
void forEachOverlappingPair(std::vector<Box>& boxes, Visit&& visit) {
  std::stable_sort(boxes.begin(), boxes.end(), [](const Box& a, const Box& b) {
    return a.minX < b.minX || (a.minX == b.minX && a.id < b.id);
  });
  std::vector<const Box*> active;
  for (const Box& entering : boxes) {
    std::size_t kept = 0;
    for (std::size_t k = 0; k < active.size(); ++k) {
      const Box* other = active[k];
      if (other->maxX < entering.minX) continue;  // ended: dropped
      active[kept++] = other;
      if (other->minY <= entering.maxY && entering.minY <= other->maxY) visit(other->id, entering.id);
    }
    active.resize(kept);
    active.push_back(&entering);
  }
}

}  // namespace gh::detail
