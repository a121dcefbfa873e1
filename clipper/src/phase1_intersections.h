// Phase 1 of Greiner-Hormann (paper, Section 4.1): find every crossing of a subject edge with a
// clip edge and order the crossings along both operands' edges.
//
// Written once over two plug-ins:
//   Search     which edge pairs to test (search/: all pairs, or a sweep):
//              forEachCandidate(subject, clip, visit)
//   Arithmetic how a pair is decided and how crossings are ordered along an edge (arithmetic/:
//              the paper's doubles, or exact predicates under Simulation of Simplicity):
//                PairTest test(subject, se, clip, ce, Crossing& out, Extra& extra)
//                int compareAlongSubject(a, extraA, b, extraB, subject, clip), compareAlongClip
//              where Extra is whatever the policy's ordering needs beside the Crossing (nothing for
//              the paper's), kept only during phase 1.
// A policy that can meet degenerate contacts (Arithmetic::kReportsDegeneracies, the paper's only)
// reports them; phase 1 then lists the vertices concerned and stops before ordering. What to do
// about them is not phase 1's business: paper_perturbation.h wraps it.
//
// Ordering costs O(k + n + m) plus short sorts: crossings are bucketed by edge (counting sort,
// stable) and each edge's own few crossings are sorted along it. Ties (several crossings at one
// point) are broken by the other edge's index, so every search yields the same lists.
#pragma once

#include <algorithm>
#include <cstdint>
#include <type_traits>
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

// Indices 0..keys.size()-1 sorted by key (each below `buckets`), stable; offsets[b] is where
// bucket b starts, offsets[buckets] the end.
inline std::vector<std::uint32_t> countingSort(const std::vector<std::uint32_t>& keys, std::size_t buckets,
                                               std::vector<std::uint32_t>& offsets) {
  offsets.assign(buckets + 1, 0);
  for (std::uint32_t k : keys) ++offsets[k + 1];
  for (std::size_t b = 0; b < buckets; ++b) offsets[b + 1] += offsets[b];
  std::vector<std::uint32_t> order(keys.size()), at(offsets.begin(), offsets.end() - 1);
  for (std::uint32_t i = 0; i < keys.size(); ++i) order[at[keys[i]]++] = i;
  return order;
}

// Sorts each bucket [offsets[b], offsets[b+1]) of `order` with `less`.
template <class Less>
void sortBuckets(std::vector<std::uint32_t>& order, const std::vector<std::uint32_t>& offsets, Less less) {
  for (std::size_t b = 0; b + 1 < offsets.size(); ++b) {
    const auto first = order.begin() + offsets[b], last = order.begin() + offsets[b + 1];
    if (last - first > 1) std::sort(first, last, less);
  }
}

// Orders the crossings along the subject (moving them into that order) and along the clip.
template <class Arithmetic, class Extra>
void orderAlongEdges(Phase1Result& r, std::vector<Extra>& extras, const Arithmetic& arithmetic) {
  constexpr bool kHasExtra = !std::is_empty_v<Extra>;
  static const Extra kNoExtra{};
  auto extra = [&extras](std::uint32_t i) -> const Extra& {
    if constexpr (kHasExtra) return extras[i];
    return kNoExtra;
  };
  const auto& cs = r.crossings;
  std::vector<std::uint32_t> keys(cs.size()), offsets;
  for (std::size_t i = 0; i < cs.size(); ++i) keys[i] = cs[i].subjectEdge;
  std::vector<std::uint32_t> order = countingSort(keys, r.subject.size(), offsets);
  sortBuckets(order, offsets, [&](std::uint32_t a, std::uint32_t b) {
    if (const int c = arithmetic.compareAlongSubject(cs[a], extra(a), cs[b], extra(b), r.subject, r.clip)) return c < 0;
    return cs[a].clipEdge < cs[b].clipEdge;
  });
  std::vector<Crossing> sorted(cs.size());
  for (std::size_t i = 0; i < order.size(); ++i) sorted[i] = cs[order[i]];
  r.crossings.swap(sorted);
  if constexpr (kHasExtra) {
    std::vector<Extra> sortedExtras(extras.size());
    for (std::size_t i = 0; i < order.size(); ++i) sortedExtras[i] = extras[order[i]];
    extras.swap(sortedExtras);
  }

  for (std::size_t i = 0; i < cs.size(); ++i) keys[i] = cs[i].clipEdge;
  r.clipOrder = countingSort(keys, r.clip.size(), offsets);
  sortBuckets(r.clipOrder, offsets, [&](std::uint32_t a, std::uint32_t b) {
    if (const int c = arithmetic.compareAlongClip(cs[a], extra(a), cs[b], extra(b), r.subject, r.clip)) return c < 0;
    return cs[a].subjectEdge < cs[b].subjectEdge;
  });
}

template <class Search, class Arithmetic>
Phase1Result findIntersections(Operand subject, Operand clip, const Search& search, const Arithmetic& arithmetic,
                               Stats& stats, Degeneracies* degeneracies = nullptr) {
  using Extra = typename Arithmetic::Extra;
  Phase1Result r{std::move(subject), std::move(clip), {}, {}};
  std::vector<Extra> extras;
  Degeneracies found;
  search.forEachCandidate(r.subject, r.clip, [&](std::uint32_t se, std::uint32_t ce) {
    ++stats.candidatePairs;
    Crossing crossing;
    Extra extra;
    const PairTest t = arithmetic.test(r.subject, se, r.clip, ce, crossing, extra);
    if (t.kind == PairTest::Kind::Crossing) {
      r.crossings.push_back(crossing);
      if constexpr (!std::is_empty_v<Extra>) extras.push_back(extra);
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
  orderAlongEdges(r, extras, arithmetic);
  return r;
}

}  // namespace gh::detail
