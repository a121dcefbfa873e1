// Candidate search of the paper's phase 1: every subject edge against every clip edge.
#pragma once

#include <cstdint>

#include "operand.h"

namespace gh::detail {

struct AllPairsSearch {
  // Calls visit(subjectEdge, clipEdge) for all n*m pairs.
  template <class Visit>
  void forEachCandidate(const Operand& subject, const Operand& clip, Visit&& visit) const {
    const auto n = static_cast<std::uint32_t>(subject.size());
    const auto m = static_cast<std::uint32_t>(clip.size());
    for (std::uint32_t i = 0; i < n; ++i) {
      for (std::uint32_t j = 0; j < m; ++j) visit(i, j);
    }
  }
};

}  // namespace gh::detail
