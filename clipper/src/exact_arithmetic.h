// The exact arithmetic policy: every decision of phase 1 (and of phase 2's starting status) is an
// exact predicate under Simulation of Simplicity (sos_predicates.h; why it is complete and what
// the output is in the limit: EXACT.md). No degeneracy exists for it, so nothing is perturbed and
// no input coordinate ever moves. Only intersection points are constructed, once each, from the
// original coordinates.
#pragma once

#include <cstdint>
#include <vector>

#include "operand.h"
#include "pair_test.h"

namespace gh::detail {

class ExactArithmetic {
 public:
  PairTest test(const Operand& subject, std::uint32_t subjectEdge, const Operand& clip,
                std::uint32_t clipEdge) const;

  bool lessAlongSubject(const Crossing& a, const Crossing& b, const Operand& subject,
                        const Operand& clip) const;
  bool lessAlongClip(const Crossing& a, const Crossing& b, const Operand& subject,
                     const Operand& clip) const;

  bool subjectVertexInsideClip(const Operand& subject, std::uint32_t v, const Operand& clip) const;
  bool clipVertexInsideSubject(const Operand& clip, std::uint32_t v, const Operand& subject) const;

  // Never called: test() reports no degeneracies.
  std::size_t perturb(Operand&, Operand&, const std::vector<std::uint32_t>&,
                      const std::vector<std::uint32_t>&, int) const {
    return 0;
  }
};

}  // namespace gh::detail
