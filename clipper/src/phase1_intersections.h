// Phase 1 of Greiner-Hormann (paper, Section 4.1): find every crossing of a subject edge with a
// clip edge and order the crossings along both operands' edges.
//
// Written once over two plug-ins:
//   Search     which edge pairs to test (search/: all pairs, or a sweep):
//              forEachCandidate(subject, clip, visit)
//   Arithmetic how a pair is decided and how crossings are ordered along an edge (arithmetic/:
//              the paper's doubles, or exact predicates under Simulation of Simplicity)
// A policy that can meet degenerate contacts (Arithmetic::kReportsDegeneracies, the paper's only)
// reports them; phase 1 then lists the vertices concerned and stops before ordering. What to do
// about them is not phase 1's business: paper_perturbation.h wraps it.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include "arithmetic/pair_test.h"
#include "ghclip/stats.h"
#include "phase1_result.h"

namespace gh::detail {

// Vertices found on the other operand's edges (sorted, unique).
struct Degeneracies {
  std::vector<std::uint32_t> subject, clip;
  bool empty() const { return subject.empty() && clip.empty(); }
};

template <class Search, class Arithmetic>
Phase1Result findIntersections(Operand subject, Operand clip, const Search& search, const Arithmetic& arithmetic,
                               Stats& stats, Degeneracies* degeneracies = nullptr) {
  Phase1Result r{std::move(subject), std::move(clip), {}, {}, {}};
  Degeneracies found;
  search.forEachCandidate(r.subject, r.clip, [&](std::uint32_t se, std::uint32_t ce) {
    ++stats.candidatePairs;
    const PairTest t = arithmetic.test(r.subject, se, r.clip, ce);
    if (t.kind == PairTest::Kind::Crossing) {
      r.crossings.push_back(t.crossing);
    } else if constexpr (Arithmetic::kReportsDegeneracies) {
      if (t.kind == PairTest::Kind::Degenerate) {
        if (t.onOtherEdge & PairTest::kSubjectFrom) found.subject.push_back(se);
        if (t.onOtherEdge & PairTest::kSubjectTo) found.subject.push_back(r.subject.next[se]);
        if (t.onOtherEdge & PairTest::kClipFrom) found.clip.push_back(ce);
        if (t.onOtherEdge & PairTest::kClipTo) found.clip.push_back(r.clip.next[ce]);
      }
    }
  });
  if constexpr (Arithmetic::kReportsDegeneracies) {
    if (!found.empty()) {
      for (auto* vs : {&found.subject, &found.clip}) {
        std::sort(vs->begin(), vs->end());
        vs->erase(std::unique(vs->begin(), vs->end()), vs->end());
      }
      if (degeneracies) *degeneracies = std::move(found);
      return r;  // unordered: the caller must resolve the degeneracies first
    }
  }
  stats.intersections = r.crossings.size();

  // Order along edges; ties (several crossings at one point) broken by the other edge's index
  // so that every candidate search yields the same lists.
  const auto& cs = r.crossings;
  r.subjectOrder.resize(cs.size());
  r.clipOrder.resize(cs.size());
  for (std::uint32_t i = 0; i < cs.size(); ++i) r.subjectOrder[i] = r.clipOrder[i] = i;
  std::sort(r.subjectOrder.begin(), r.subjectOrder.end(), [&](std::uint32_t a, std::uint32_t b) {
    if (cs[a].subjectEdge != cs[b].subjectEdge) return cs[a].subjectEdge < cs[b].subjectEdge;
    if (a == b) return false;
    if (const int c = arithmetic.compareAlongSubject(cs[a], cs[b], r.subject, r.clip)) return c < 0;
    return cs[a].clipEdge < cs[b].clipEdge;
  });
  std::sort(r.clipOrder.begin(), r.clipOrder.end(), [&](std::uint32_t a, std::uint32_t b) {
    if (cs[a].clipEdge != cs[b].clipEdge) return cs[a].clipEdge < cs[b].clipEdge;
    if (a == b) return false;
    if (const int c = arithmetic.compareAlongClip(cs[a], cs[b], r.subject, r.clip)) return c < 0;
    return cs[a].subjectEdge < cs[b].subjectEdge;
  });
  return r;
}

}  // namespace gh::detail
