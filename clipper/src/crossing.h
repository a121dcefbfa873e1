// A proper crossing of a subject edge with a clip edge, found in phase 1.
#pragma once

#include <cstdint>

#include "ghclip/region.h"

namespace gh::detail {

struct Crossing {
  std::uint32_t subjectEdge = 0;
  std::uint32_t clipEdge = 0;
  // Position along each edge in [0, 1] (the paper's alpha values). The naive policy orders
  // crossings along an edge by these; the exact policy orders them by exact predicates.
  double alphaSubject = 0;
  double alphaClip = 0;
  // Certified bounds |true alpha - alpha| <= err, used by the exact policy to order crossings
  // without its full predicate when the intervals are disjoint (infinite: no bound).
  double errSubject = 0;
  double errClip = 0;
  // The one constructed point shared by both copies of the intersection vertex.
  Point point;
};

}  // namespace gh::detail
