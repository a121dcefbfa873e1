// Candidate search of the paper's phase 1: every subject edge against every clip edge.
#pragma once

#include <cstddef>
#include <cstdint>

#include "operand.h"

namespace gh::detail {

struct AllPairsSearch {
  // The work as units that can be visited in pieces, in any order, each piece's pairs in a fixed
  // order: here a unit is one subject edge, and a row of it against every clip edge.
  struct Plan {
    std::size_t units;
    std::size_t pairsPerUnit;  // for splitting the work: a row tests every clip edge
    static constexpr bool rows = true;  // units are visited as rows (onRow)
    // onRow(subjectEdge) for every unit in [begin, end); onPair is for searches that find pairs
    // one at a time.
    template <class OnRow, class OnPair>
    void visit(std::size_t begin, std::size_t end, OnRow&& onRow, OnPair&&) const {
      for (std::size_t i = begin; i < end; ++i) onRow(static_cast<std::uint32_t>(i));
    }
  };
  Plan plan(const Operand& subject, const Operand& clip) const { return {subject.size(), clip.size()}; }

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
