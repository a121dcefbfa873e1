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
  // The one constructed point shared by both copies of the intersection vertex.
  Point point;
  // Position along each edge in [0, 1] (the paper's alpha values). The paper arithmetic orders
  // crossings along an edge by these; the exact arithmetic starts from them.
  double alphaSubject = 0;
  double alphaClip = 0;
};

struct Phase1Result {
  Operand subject;  // the vertices actually used (perturbed copies for the paper arithmetic)
  Operand clip;
  // In order along the subject: by edge, then along the edge. A crossing's index here is its
  // subject intersection vertex.
  std::vector<Crossing> crossings;
  // Crossing indices in order along the clip: by edge, then along the edge.
  std::vector<std::uint32_t> clipOrder;
};

}  // namespace gh::detail
