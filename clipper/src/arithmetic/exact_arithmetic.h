// The exact arithmetic policy: every decision of phase 1 (and of phase 2's starting status) is an
// exact predicate under Simulation of Simplicity (predicates/sos_predicates.h; why it is complete
// and what the output is in the limit: EXACT.md). No degeneracy exists for it, so nothing is
// perturbed and no input coordinate ever moves. Only intersection points are constructed, once
// each, from the original coordinates. Every fallback to rational arithmetic is counted in the
// ExactCounters the policy is given.
#pragma once

#include <cstdint>

#include "arithmetic/pair_test.h"
#include "arithmetic/row_kernels.h"
#include "operand.h"
#include "phase1_buffers.h"
#include "phase1_result.h"
#include "predicates/exact_counters.h"

namespace gh::detail {

class ExactArithmetic {
 public:
  // Alpha is only an approximation of the order along an edge: it is decided exactly.
  static constexpr bool kAlphaOrderIsExact = false;
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
  ExactCounters& counters() const { return *counters_; }

  PairTest test(const Operand& subject, std::uint32_t subjectEdge, const Operand& clip, std::uint32_t clipEdge,
                Crossing& out, Extra& extra) const;
  void testPair(const Operand& subject, std::uint32_t se, const Operand& clip, std::uint32_t ce,
                CrossingBuffer<Extra>& into) const {
    ++into.pairs;
    Crossing c;
    Extra e;
    if (test(subject, se, clip, ce, c, e).kind == PairTest::Kind::Crossing) into.add(c, e);
  }
  // Subject edge se against every clip edge; the vectorized filter rejects most pairs first when
  // `clipArrays` is given (row_kernels.h), with the same answers.
  void testRow(const Operand& subject, std::uint32_t se, const Operand& clip, const EdgeArrays* clipArrays,
               CrossingBuffer<Extra>& into) const;

  // Exact order of two crossings on one edge: -1 (a first), +1, or 0 (one point in the limit,
  // only when the two other edges lie on one line). Most pairs are decided by their certified
  // position intervals (inline, for the sort); the rest by the exact predicate.
  double errorAlongSubject(const Extra& e) const { return e.errSubject; }
  double errorAlongClip(const Extra& e) const { return e.errClip; }
  template <class Item>
  int compareAlongSubject(const Item& a, const Item& b, const Crossing* cs, const Extra* extras,
                          const Operand& subject, const Operand& clip) const {
    if (const int quick = byIntervals(a.alpha, a.err, b.alpha, b.err)) return quick;
    return exactlyAlongSubject(cs[a.index], extras[a.index], cs[b.index], extras[b.index], subject, clip);
  }
  template <class Item>
  int compareAlongClip(const Item& a, const Item& b, const Crossing* cs, const Extra* extras, const Operand& subject,
                       const Operand& clip) const {
    if (const int quick = byIntervals(a.alpha, a.err, b.alpha, b.err)) return quick;
    return exactlyAlongClip(cs[a.index], extras[a.index], cs[b.index], extras[b.index], subject, clip);
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
