// Phase 1 of Greiner-Hormann: find every crossing of a subject edge with a clip edge.
//
// Written once over two plug-ins:
//   Search     which edge pairs to test (all pairs, or a sweep): forEachCandidate(s, c, visit)
//   Arithmetic how a pair is decided, how crossings are ordered along an edge, and whether a
//              vertex lies inside the other operand (doubles + perturbation, or exact + SoS)
// A policy that reports degenerate contacts gets them perturbed and the search run again,
// until no degeneracy is left or kMaxPerturbationRounds is reached.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "construction.h"
#include "crossing.h"
#include "ghclip/errors.h"
#include "ghclip/stats.h"
#include "operand.h"
#include "orientation.h"
#include "pair_test.h"

namespace gh::detail {

inline constexpr int kMaxPerturbationRounds = 32;

// What phases 2 and 3 need from phase 1, whatever the policy.
struct Phase1Result {
  Operand subject;  // the vertices actually used (perturbed copies for the naive policy)
  Operand clip;
  std::vector<Crossing> crossings;
  // Crossing ids sorted by (edge, position along the edge) for each operand.
  std::vector<std::uint32_t> subjectOrder;
  std::vector<std::uint32_t> clipOrder;
  // Is the first vertex of each ring inside the other operand (even-odd)?
  std::vector<char> subjectRingInside;
  std::vector<char> clipRingInside;
};

template <class Search, class Arithmetic>
Phase1Result findIntersections(Operand subject, Operand clip, const Search& search,
                               const Arithmetic& arithmetic, Stats& stats) {
  Phase1Result r{std::move(subject), std::move(clip), {}, {}, {}, {}, {}};
  const std::uint64_t fallbacksBefore = exactFallbacks(), constructionsBefore = exactConstructions();
  for (int round = 0;; ++round) {
    r.crossings.clear();
    std::vector<std::uint32_t> degenerateSubject, degenerateClip;
    search.forEachCandidate(r.subject, r.clip, [&](std::uint32_t se, std::uint32_t ce) {
      ++stats.candidatePairs;
      const PairTest t = arithmetic.test(r.subject, se, r.clip, ce);
      if (t.kind == PairTest::Kind::Crossing) {
        r.crossings.push_back(t.crossing);
      } else if (t.kind == PairTest::Kind::Degenerate) {
        if (t.onOtherEdge & PairTest::kSubjectFrom) degenerateSubject.push_back(se);
        if (t.onOtherEdge & PairTest::kSubjectTo) degenerateSubject.push_back(r.subject.next[se]);
        if (t.onOtherEdge & PairTest::kClipFrom) degenerateClip.push_back(ce);
        if (t.onOtherEdge & PairTest::kClipTo) degenerateClip.push_back(r.clip.next[ce]);
      }
    });
    if (degenerateSubject.empty() && degenerateClip.empty()) break;
    if (round + 1 >= kMaxPerturbationRounds) {
      throw ClipFailure("degeneracies remain after " + std::to_string(kMaxPerturbationRounds) +
                        " rounds of perturbation");
    }
    for (auto* vs : {&degenerateSubject, &degenerateClip}) {
      std::sort(vs->begin(), vs->end());
      vs->erase(std::unique(vs->begin(), vs->end()), vs->end());
    }
    stats.perturbations += arithmetic.perturb(r.subject, r.clip, degenerateSubject,
                                              degenerateClip, round);
    ++stats.perturbationRounds;
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

  r.subjectRingInside.resize(r.subject.ringCount());
  for (std::size_t k = 0; k < r.subject.ringCount(); ++k) {
    r.subjectRingInside[k] =
        arithmetic.subjectVertexInsideClip(r.subject, r.subject.ringStart[k], r.clip);
  }
  r.clipRingInside.resize(r.clip.ringCount());
  for (std::size_t k = 0; k < r.clip.ringCount(); ++k) {
    r.clipRingInside[k] = arithmetic.clipVertexInsideSubject(r.clip, r.clip.ringStart[k], r.subject);
  }
  stats.filterFailures = exactFallbacks() - fallbacksBefore;
  stats.exactConstructions = exactConstructions() - constructionsBefore;
  return r;
}

}  // namespace gh::detail
