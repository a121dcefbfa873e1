// The paper's arithmetic policy: doubles and alpha values (Greiner & Hormann 1998, Figure 11).
//
// intersect() is Figure 11: window-edge coordinates (WEC) of each endpoint against the other edge,
// a crossing when both pairs change sign, alpha = WEC ratio. A WEC of exactly zero on a touching
// pair is the paper's degeneracy ("P1 lies on Q1Q2 iff alphaP = 0 and 0 <= alphaQ <= 1"): the
// vertex that lies on the other operand's edge is reported, and paper_perturbation.h moves it and
// runs phase 1 again (Section 5, Figure 12).
//
// Every decision of phase 1 here is a floating-point sign: near-degenerate inputs can be decided
// inconsistently. That is the paper as written; the exact arithmetic exists to do better. Only
// phase 2's starting status uses the library's one ray test (exact orientations): the paper leaves
// that test open, and a vertex on an edge has been perturbed away by then.
#pragma once

#include <cstdint>

#include "arithmetic/pair_test.h"
#include "operand.h"
#include "phase1_result.h"
#include "predicates/exact_counters.h"
#include "predicates/sign.h"

namespace gh::detail {

class PaperArithmetic {
 public:
  static constexpr bool kReportsDegeneracies = true;
  // Perturbed answers have no zero-width parts to dissolve (cleanup.h).
  static constexpr bool kLeavesZeroWidthParts = false;

  // The ordering needs nothing beside the alpha values.
  struct Extra {};

  explicit PaperArithmetic(ExactCounters& counters) : counters_(&counters) {}

  // The paper's intersect(): a crossing is written to `out`.
  PairTest test(const Operand& subject, std::uint32_t subjectEdge, const Operand& clip, std::uint32_t clipEdge,
                Crossing& out, Extra&) const;

  // Order of two crossings on the same subject (clip) edge: by alpha, as in the paper.
  // -1: a first, +1: b first, 0: tied.
  int compareAlongSubject(const Crossing& a, const Extra&, const Crossing& b, const Extra&, const Operand&,
                          const Operand&) const {
    return signOfDifference(a.alphaSubject, b.alphaSubject);
  }
  int compareAlongClip(const Crossing& a, const Extra&, const Crossing& b, const Extra&, const Operand&,
                       const Operand&) const {
    return signOfDifference(a.alphaClip, b.alphaClip);
  }

  // Even-odd test of a vertex of one operand against the other operand (phase 2's start).
  bool subjectVertexInsideClip(const Operand& subject, std::uint32_t v, const Operand& clip) const;
  bool clipVertexInsideSubject(const Operand& clip, std::uint32_t v, const Operand& subject) const;

 private:
  ExactCounters* counters_;
};

}  // namespace gh::detail
