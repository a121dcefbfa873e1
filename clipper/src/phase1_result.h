// What phase 1 hands to phases 2 and 3, whatever the search and arithmetic: data only, so that
// the vertex graph does not depend on how the crossings were found.
#pragma once

#include <cstdint>
#include <vector>

#include "ghclip/region.h"
#include "operand.h"

namespace gh::detail {

// A proper crossing of a subject edge with a clip edge.
struct Crossing {
  std::uint32_t subjectEdge = 0;
  std::uint32_t clipEdge = 0;
  // Position along each edge in [0, 1] (the paper's alpha values). The paper arithmetic orders
  // crossings along an edge by these; the exact arithmetic by exact predicates.
  double alphaSubject = 0;
  double alphaClip = 0;
  // Certified bounds |true alpha - alpha| <= err, used by the exact arithmetic to order crossings
  // without its full predicate when the intervals are disjoint (infinite: no bound).
  double errSubject = 0;
  double errClip = 0;
  // The one constructed point shared by both copies of the intersection vertex.
  Point point;
};

struct Phase1Result {
  Operand subject;  // the vertices actually used (perturbed copies for the paper arithmetic)
  Operand clip;
  std::vector<Crossing> crossings;
  // Crossing ids sorted by (edge, position along the edge) for each operand.
  std::vector<std::uint32_t> subjectOrder;
  std::vector<std::uint32_t> clipOrder;
};

}  // namespace gh::detail
