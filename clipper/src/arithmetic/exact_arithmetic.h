// The exact arithmetic policy: every decision of phase 1 (and of phase 2's starting status) is an
// exact predicate under Simulation of Simplicity (predicates/sos_predicates.h; why it is complete
// and what the output is in the limit: EXACT.md). No degeneracy exists for it, so nothing is
// perturbed and no input coordinate ever moves. Only intersection points are constructed, once
// each, from the original coordinates. Every fallback to rational arithmetic is counted in the
// ExactCounters the policy is given.
#pragma once

#include <cstdint>

#include "arithmetic/pair_test.h"
#include "operand.h"
#include "phase1_result.h"
#include "predicates/exact_counters.h"

namespace gh::detail {

class ExactArithmetic {
 public:
  static constexpr bool kReportsDegeneracies = false;
  // The limit eps -> 0 leaves zero-width parts (slivers, spikes, seams) for clean-up to remove.
  static constexpr bool kLeavesZeroWidthParts = true;

  // What the ordering needs beside the Crossing: certified bounds |true alpha - alpha| <= err on
  // its positions (infinite: no bound), and whether the crossing's point is exactly an input
  // vertex (the limit of the crossing is that vertex, so its position is known exactly).
  struct Extra {
    double errSubject = 0;
    double errClip = 0;
    bool atInputVertex = false;
  };

  explicit ExactArithmetic(ExactCounters& counters) : counters_(&counters) {}

  PairTest test(const Operand& subject, std::uint32_t subjectEdge, const Operand& clip, std::uint32_t clipEdge,
                Crossing& out, Extra& extra) const;

  // Exact order of two crossings on one edge: -1 (a first), +1, or 0 (one point in the limit,
  // only when the two other edges lie on one line).
  // Most pairs are decided by their certified position intervals (inline, for the sort); the
  // rest by the exact predicate.
  int compareAlongSubject(const Crossing& a, const Extra& ea, const Crossing& b, const Extra& eb,
                          const Operand& subject, const Operand& clip) const {
    if (const int quick = byIntervals(a.alphaSubject, ea.errSubject, b.alphaSubject, eb.errSubject)) return quick;
    return exactlyAlongSubject(a, ea, b, eb, subject, clip);
  }
  int compareAlongClip(const Crossing& a, const Extra& ea, const Crossing& b, const Extra& eb,
                       const Operand& subject, const Operand& clip) const {
    if (const int quick = byIntervals(a.alphaClip, ea.errClip, b.alphaClip, eb.errClip)) return quick;
    return exactlyAlongClip(a, ea, b, eb, subject, clip);
  }

  bool subjectVertexInsideClip(const Operand& subject, std::uint32_t v, const Operand& clip) const;
  bool clipVertexInsideSubject(const Operand& clip, std::uint32_t v, const Operand& subject) const;

 private:
  // a < b from certified intervals a +- ea, b +- eb when they are disjoint: -1 (a first), +1, or
  // 0 (undecided).
  static int byIntervals(double a, double ea, double b, double eb) {
    if (a + ea < b - eb) return -1;
    if (b + eb < a - ea) return 1;
    return 0;
  }
  int exactlyAlongSubject(const Crossing& a, const Extra& ea, const Crossing& b, const Extra& eb,
                          const Operand& subject, const Operand& clip) const;
  int exactlyAlongClip(const Crossing& a, const Extra& ea, const Crossing& b, const Extra& eb,
                       const Operand& subject, const Operand& clip) const;

  ExactCounters* counters_;
};

}  // namespace gh::detail
