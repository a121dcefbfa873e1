// The paper's arithmetic policy: doubles, alpha values, and perturbation of degenerate vertices.
//
// intersect() is Figure 11 of Greiner & Hormann (1998): window-edge coordinates (WEC) of each
// endpoint against the other edge, a crossing when both pairs change sign, alpha = WEC ratio.
// A WEC of exactly zero on a touching pair is the paper's degeneracy ("P1 lies on Q1Q2 iff
// alphaP = 0 and 0 <= alphaQ <= 1"): the vertex that lies on the other operand's edge is
// reported, phase 1 perturbs it and searches again (Section 5, Figure 12).
//
// Every decision here is a floating-point sign: near-degenerate inputs can be decided
// inconsistently. That is the paper as written; the exact policy exists to do better.
#pragma once

#include <cstdint>
#include <vector>

#include "operand.h"
#include "orientation.h"
#include "pair_test.h"

namespace gh::detail {

class NaiveArithmetic {
 public:
  // Relative size of a perturbation: |move| = kPerturbationScale * max |coordinate| of both
  // operands. About 2^10 ulps of the largest coordinate, so the moved vertex is clearly off the
  // line in double arithmetic, and still far below a pixel at any sensible scale.
  static constexpr double kPerturbationScale = 0x1p-42;

  PairTest test(const Operand& subject, std::uint32_t subjectEdge, const Operand& clip,
                std::uint32_t clipEdge) const;

  // Order of two crossings on the same subject (clip) edge: by alpha, as in the paper.
  // -1: a first, +1: b first, 0: tied.
  int compareAlongSubject(const Crossing& a, const Crossing& b, const Operand&, const Operand&) const {
    return signOfDifference(a.alphaSubject, b.alphaSubject);
  }
  int compareAlongClip(const Crossing& a, const Crossing& b, const Operand&, const Operand&) const {
    return signOfDifference(a.alphaClip, b.alphaClip);
  }

  // Even-odd test of a vertex of one operand against the other operand (phase 2's start).
  bool subjectVertexInsideClip(const Operand& subject, std::uint32_t v, const Operand& clip) const;
  bool clipVertexInsideSubject(const Operand& clip, std::uint32_t v, const Operand& subject) const;

  // Moves the flagged vertices of one operand (the clip's when any are flagged, else the
  // subject's) by one common vector of length kPerturbationScale * scale; the direction turns by
  // the golden angle each round so that a vertex moved twice does not walk back onto a line.
  // Returns how many vertices moved.
  std::size_t perturb(Operand& subject, Operand& clip, const std::vector<std::uint32_t>& subjectVs,
                      const std::vector<std::uint32_t>& clipVs, int round) const;
};

}  // namespace gh::detail
